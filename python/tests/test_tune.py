"""swingsim.tune against the command line's `tune --json` on the shipped example, and its
argument checks."""
import json
import subprocess

import pytest

import swingsim


def test_tune_equals_cli(cli, repo, tmp_path):
    study = repo / "studies" / "tune-p1-damping.yaml"
    out = tmp_path / "tune.json"
    subprocess.run([cli, "tune", str(study), "--json", str(out), "--out", str(tmp_path / "report")],
                   check=True, capture_output=True)
    expected = json.loads(out.read_text())
    result = swingsim.tune(study, out=tmp_path / "py")
    # The same tuning, number for number; only the wall time and the files' folder differ.
    for key in ("knobs", "targets", "swing", "identifiable", "feasible", "iterations"):
        assert result[key] == expected[key], key
    assert [p["knobs"] for p in result["points"]] == [p["knobs"] for p in expected["points"]]
    assert all(t["met"] for t in result["targets"] if t["hard"])
    assert "kind: damping_table" in result["tuned_knee_yaml"]
    assert "model_scale" in result["tuned_knee_yaml"]  # a knob the file did not have, now written
    assert (tmp_path / "py" / "tradeoff.svg").exists()


def test_tune_checks_its_arguments(repo):
    study = repo / "studies" / "tune-p1-damping.yaml"
    with pytest.raises(swingsim.InputError, match=r"tune\(\): jobs"):
        swingsim.tune(study, jobs=-1)
    with pytest.raises(TypeError, match=r"tune\(\): study_path"):
        swingsim.tune(3)


def test_tune_refuses_a_bad_study_with_file_line_key(tmp_path, repo):
    study = tmp_path / "bad.yaml"
    study.write_text(f"kind: knee-tuning\nparticipant: {repo / 'participants' / 'p1.yaml'}\n"
                     "knobs:\n  - key: damping_table.speed_rule\n    range: [0, 1]\n"
                     "targets:\n  swing_time_s: {value: 0.5}\n")
    with pytest.raises(swingsim.InputError, match=r"bad\.yaml:4: knobs\[0\]\.key: .*not a number"):
        swingsim.tune(study)


def test_tune_writes_only_into_out(repo, tmp_path, monkeypatch):
    # A tune from Python once wrote outside its out folder: here every file it writes is in
    # out, and nothing beside the study, its participant or its knee model changes. Run from
    # another working folder with a relative out, as a notebook would.
    def files(folder):
        return {p: p.stat().st_mtime_ns for p in folder.rglob("*") if p.is_file()}

    watched = [repo / "studies", repo / "models", repo / "participants"]
    before = [files(f) for f in watched]
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    swingsim.tune(repo / "studies" / "tune-p1-damping.yaml", out="rel-out")
    assert sorted(p.name for p in work.rglob("*") if p.is_file()) == \
        ["tradeoff.svg", "tuned-knee.yaml", "tuning.json", "tuning.md"]
    assert all(p.parent == work / "rel-out" for p in work.rglob("*") if p.is_file())
    assert [files(f) for f in watched] == before
