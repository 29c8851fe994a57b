#!/usr/bin/env python3
"""Checks that the tree agrees with itself (stdlib only; run from any folder).

  python3 scripts/check-tree.py

Three checks, one line per problem, exit 1 if any (else one summary line, exit 0):

- mirror: every src/<layer>/<unit>.cpp has tests/<layer>/<unit>_test.cpp, or a line
  `<layer>/<unit>: <reason>` in tests/mirror-allowlist.txt saying where it is tested instead
  (or "UNTESTED: ..." where nothing runs it). An allowlist line is stale once the unit has its
  own test or no longer exists, and every tests/ path a reason names must exist.
- doc pointers: every path to a docs file or the README named in src/ and python/ (comments
  and strings: `docs/foo.md`, `docs/foo.md#anchor`, `docs/foo.md, "Section"`, `README`,
  `README ("Section")`, `README, Section)`) exists, and a section it names is there: an
  anchor is one of the file's headings by GitHub's rule (lowercase; punctuation other than
  -, _ and spaces dropped; spaces to -; -1, -2 for repeats); a quoted or capitalised title is a
  heading (`#`..`######`) or a bold paragraph lead (`**Title**`, as docs/robustness.md and
  docs/assumptions.md are laid out), compared case-insensitively, a trailing " (...)" of the
  heading ignored.
- architecture: docs/architecture.md names every folder of src/ (`src/<name>/` anywhere, or
  `<name>/` in a list item or a table row).
- YAML in io/: no file of src/ outside src/io/, and none of python/src/, names yaml-cpp
  (`YAML::` or its header); they read and edit YAML through io/ (io/yaml_tree.h).
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ALLOWLIST = "tests/mirror-allowlist.txt"
ARCHITECTURE = "docs/architecture.md"
POINTER_ROOTS = ("src", "python")


def rel(path):
    return os.path.relpath(path, ROOT)


def read_text(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except (UnicodeDecodeError, OSError):
        return None


# --- mirror ---------------------------------------------------------------------------

def list_units():
    """(layer, unit) of every src/<layer>/<unit>.cpp."""
    units = []
    src = os.path.join(ROOT, "src")
    for layer in sorted(os.listdir(src)):
        folder = os.path.join(src, layer)
        if not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if name.endswith(".cpp") and os.path.isfile(os.path.join(folder, name)):
                units.append((layer, name[: -len(".cpp")]))
    return units


def read_allowlist(problems):
    """{"layer/unit": (line number, reason)}; malformed and repeated lines are problems."""
    entries = {}
    text = read_text(os.path.join(ROOT, ALLOWLIST))
    if text is None:
        problems.append(f"mirror: {ALLOWLIST}: missing")
        return entries
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        m = re.match(r"^([a-z0-9_]+/[A-Za-z0-9_]+):\s*(.*)$", stripped)
        if not m:
            problems.append(f"mirror: {ALLOWLIST}:{number}: expected `<layer>/<unit>: <reason>` (got {stripped!r})")
            continue
        unit, reason = m.group(1), m.group(2).strip()
        if not reason:
            problems.append(f"mirror: {ALLOWLIST}:{number}: {unit}: no reason given")
        if unit in entries:
            problems.append(f"mirror: {ALLOWLIST}:{number}: {unit}: listed again (first on line {entries[unit][0]})")
            continue
        entries[unit] = (number, reason)
    return entries


def check_mirror(problems):
    units = list_units()
    entries = read_allowlist(problems)
    existing = {f"{layer}/{unit}" for layer, unit in units}
    with_test = 0
    for layer, unit in units:
        key = f"{layer}/{unit}"
        test = f"tests/{layer}/{unit}_test.cpp"
        has_test = os.path.isfile(os.path.join(ROOT, test))
        with_test += has_test
        if has_test and key in entries:
            problems.append(f"mirror: {ALLOWLIST}:{entries[key][0]}: {key}: stale, {test} exists now; remove the line")
        elif not has_test and key not in entries:
            problems.append(f"mirror: src/{key}.cpp: no {test}, and no line `{key}: <where it is tested>` in {ALLOWLIST}")
    for key, (number, reason) in sorted(entries.items(), key=lambda e: e[1][0]):
        if key not in existing:
            problems.append(f"mirror: {ALLOWLIST}:{number}: {key}: stale, src/{key}.cpp no longer exists; remove the line")
        for path in re.findall(r"\btests/[A-Za-z0-9_./-]*[A-Za-z0-9_]", reason):
            if not os.path.exists(os.path.join(ROOT, path)):
                problems.append(f"mirror: {ALLOWLIST}:{number}: {key}: the reason names {path}, which does not exist")
    return len(units), with_test, len(entries)


# --- doc pointers -----------------------------------------------------------------------

def strip_markup(text):
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # [text](link) -> text
    return text.replace("`", "").replace("**", "").replace("*", "")


def normalise(title):
    title = strip_markup(title).lower()
    title = re.sub(r"\s+", " ", title).strip()
    return title.rstrip(".:").strip()


def github_anchor(heading):
    anchor = strip_markup(heading).strip().lower()
    anchor = re.sub(r"[^\w\- ]", "", anchor)
    return anchor.replace(" ", "-")


_sections = {}


def sections_of(path):
    """(titles, anchors) of a Markdown file: its headings and bold paragraph leads."""
    if path in _sections:
        return _sections[path]
    titles, anchors, seen = set(), set(), {}
    fence = None
    for line in (read_text(path) or "").splitlines():
        m = re.match(r"^\s*(```+|~~~+)", line)
        if m:
            mark = m.group(1)[:3]
            fence = None if fence == mark else (fence or mark)
            continue
        if fence:
            continue
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m:
            heading = m.group(1)
            titles.add(normalise(heading))
            anchor = github_anchor(heading)
            count = seen.get(anchor, 0)
            seen[anchor] = count + 1
            anchors.add(anchor if count == 0 else f"{anchor}-{count}")
            continue
        m = re.match(r"^\s*(?:[-*]\s+)?\*\*(.+?)\*\*", line)
        if m:
            # A bold lead is a paragraph's opening phrase: its name is the whole of it, or its
            # first clause ("**The search is local, and a miss means ...**").
            titles.add(normalise(m.group(1)))
            titles.add(normalise(re.split(r"[,;:.]\s| \(", m.group(1) + " ", maxsplit=1)[0]))
    _sections[path] = (titles, anchors)
    return _sections[path]


def title_found(title, titles):
    want = normalise(title)
    for have in titles:
        if have == want or have.startswith(want + " ("):
            return True
    return False


# A docs path or the README, not inside a longer path.
POINTER = re.compile(r"(?<![A-Za-z0-9_./-])(docs/[A-Za-z0-9_./-]*[A-Za-z0-9_/-]|README(?:\.md)?(?![A-Za-z0-9_.-]))")
# What may follow it: an anchor, a quoted title (", "T"", " ("T")", " \"T\"", " 'T'"), or an
# unquoted capitalised title closed by ")" or the end of the comment (", Convergence study)").
ANCHOR = re.compile(r"^#([A-Za-z0-9_-]+)")
QUOTED = re.compile(r"^(?:,\s*|\s*\(\s*|\s+)(?:section\s+)?(\\\"|\"|')(.+?)\1")
UNQUOTED = re.compile(r"^,\s+([A-Z][A-Za-z0-9' -]{1,60}?)\s*(?:[):;]|$)")
UNQUOTED_WRAPPED = re.compile(r"^,\s+([A-Z][A-Za-z0-9' -]{1,60}?)\s*\)")
COMMENT_LEAD = re.compile(r"^\s*(?://+!?|#+|\*+|/\*+)\s?")


def continuation(lines, index):
    """The next line as text that continues a comment (its comment marker dropped)."""
    if index + 1 >= len(lines):
        return ""
    nxt = lines[index + 1]
    if not COMMENT_LEAD.match(nxt):
        return ""
    return COMMENT_LEAD.sub("", nxt, count=1).strip()


def pointer_files():
    for top in POINTER_ROOTS:
        for folder, dirs, files in os.walk(os.path.join(ROOT, top)):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "__pycache__")
            for name in sorted(files):
                yield os.path.join(folder, name)


def check_doc_pointers(problems):
    count = 0
    for path in pointer_files():
        text = read_text(path)
        if text is None:
            continue
        lines = text.splitlines()
        for index, line in enumerate(lines):
            for m in POINTER.finditer(line):
                count += 1
                target = m.group(1).rstrip(".")
                if target.startswith("README"):
                    target = "README.md"
                where = f"{rel(path)}:{index + 1}"
                full = os.path.join(ROOT, target)
                if not os.path.exists(full):
                    problems.append(f"doc pointer: {where}: {m.group(1).rstrip('.')}: no such file")
                    continue
                if not target.endswith(".md") or os.path.isdir(full):
                    continue
                rest = line[m.end():]
                joined = rest.rstrip() + " " + continuation(lines, index)  # a title may wrap
                titles, anchors = sections_of(full)
                a = ANCHOR.match(line[m.end():])
                if a:
                    if a.group(1) not in anchors:
                        problems.append(f"doc pointer: {where}: {target}#{a.group(1)}: no such heading in {target}")
                    continue
                q = QUOTED.match(joined) or UNQUOTED_WRAPPED.match(joined) or UNQUOTED.match(rest)
                if q:
                    title = q.group(q.lastindex)
                    title = re.sub(r"\s+", " ", title.replace('\\"', "")).strip()
                    if not title_found(title, titles):
                        problems.append(f"doc pointer: {where}: {target}, \"{title}\": no such section in {target}")
    return count


# --- architecture -----------------------------------------------------------------------

def check_architecture(problems):
    src = os.path.join(ROOT, "src")
    folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    text = read_text(os.path.join(ROOT, ARCHITECTURE))
    if text is None:
        problems.append(f"architecture: {ARCHITECTURE}: missing")
        return len(folders)
    listed = [l for l in text.splitlines() if re.match(r"^\s*([-*+]|\d+\.|\|)\s", l)]
    for name in folders:
        anywhere = re.search(rf"(?<![A-Za-z0-9_./-])src/{re.escape(name)}/", text)
        in_list = any(re.search(rf"(?<![A-Za-z0-9_.-]){re.escape(name)}/", l) for l in listed)
        if not (anywhere or in_list):
            problems.append(f"architecture: {ARCHITECTURE}: does not name src/{name}/ (as `src/{name}/`, "
                            f"or `{name}/` in a list or table)")
    return len(folders)


def check_yaml_in_io(problems):
    checked = 0
    for top in ("src", os.path.join("python", "src")):
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            if rel(folder).split(os.sep)[:2] == ["src", "io"]:
                continue
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.join(folder, name)
                checked += 1
                for number, line in enumerate((read_text(path) or "").splitlines(), 1):
                    if "YAML::" in line or "yaml-cpp/" in line:
                        problems.append(f"yaml: {rel(path)}:{number}: uses yaml-cpp outside src/io/ "
                                        f"(read or edit YAML through io/, e.g. io/yaml_tree.h)")
    return checked


def main():
    problems = []
    units, with_test, allowed = check_mirror(problems)
    pointers = check_doc_pointers(problems)
    folders = check_architecture(problems)
    yaml_free = check_yaml_in_io(problems)
    for p in problems:
        print(p)
    if problems:
        print(f"check-tree: {len(problems)} problem(s)", file=sys.stderr)
        return 1
    print(f"check-tree: OK: {units} units in src/ ({with_test} with their own test, {allowed} in {ALLOWLIST}), "
          f"{pointers} doc pointers in src/ and python/, {folders} folders of src/ in {ARCHITECTURE}, "
          f"{yaml_free} files outside src/io/ without yaml-cpp")
    return 0


if __name__ == "__main__":
    sys.exit(main())
