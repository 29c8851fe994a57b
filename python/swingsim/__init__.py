"""swingsim from Python: the swing phase of an above-knee prosthetic leg (docs/python.md).

Participants, knee models and diagnosis studies load from their YAML files into editable
objects whose fields are the file's keys, in the file's units (``p.segments.shank.mass_kg``,
kg); they validate with the C++ loaders' checks and save back to YAML. `simulate` runs one
swing, `sweep` a knee-axis sweep study, `tune` a knee-tuning study, `fit` a cylinder-fit
study, `compare` and `diagnose` a diagnosis study (a file or a `DiagnosisStudy` built here),
`swings` lists the swings of an OpenSim IK file, `import_osim` makes a participant from an
OpenSim model and `export_osim` writes one, all through the same C++ functions as the
command line, with the GIL released while they run. Bad input raises `InputError` (a
ValueError) with the command line's ``file:line: key: ...`` message; an argument of the
wrong type raises TypeError and one out of the command line's range InputError, naming it;
a failed run raises `RunError`; a warning about the data is issued with `warnings.warn` as
a `SwingsimWarning`.
"""
import copy as _copy
import math as _math
import numbers as _numbers
import os as _os
import tempfile as _tempfile
import warnings as _warnings

from swingsim import _swingsim
from swingsim._swingsim import InputError, RunError

InputError.__module__ = RunError.__module__ = "swingsim"  # shown as swingsim.InputError
InputError.__doc__ = ("Bad input (a ValueError): a file, an edited field or an argument the command line would refuse; "
                      "the message is the command line's `file:line: key: what was expected (got VALUE)`.")
RunError.__doc__ = ("A run that failed (a RuntimeError): a swing that cannot be simulated, as the command line "
                    "reports it.")

__all__ = ["InputError", "RunError", "SwingsimWarning", "Record", "Result", "Participant", "KneeModel",
           "DiagnosisStudy", "SwingRecord", "SwingResult", "SwingList", "DiagnosisResult", "RecordSeries",
           "load_participant", "load_knee", "load_study", "simulate", "sweep", "tune", "fit", "compare",
           "diagnose", "swings", "import_osim", "export_osim"]


class SwingsimWarning(UserWarning):
    """A warning about the data a swingsim call read (a flipped sign, a column read without
    the pelvis tilt, a force file left to the kinematics, ...): the same text the command
    line prints on stderr and the JSON keeps under "warnings"."""


def _argument_problem(where, expected, value):
    shown = repr(value)
    return f"{where}: {expected}, got {type(value).__name__} {shown[:80]}"


class Record:
    """A mapping of a YAML file, read and edited by attribute (``r.initial.knee_flexion_deg``)
    or by key (``r["initial"]["knee_flexion_deg"]``), nested maps as Records. Setting an
    attribute that the file does not have is an AttributeError (a misspelt key); set a new
    optional key by item instead. ``del r.key`` / ``del r["key"]`` removes an optional key
    (its default applies when loaded); removing a key the file must have raises InputError
    naming it, and the key stays."""

    def __init__(self, values, root=None):
        object.__setattr__(self, "_values", values)
        object.__setattr__(self, "_root", root)

    def __getattr__(self, key):
        values = object.__getattribute__(self, "_values")
        if key not in values:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(values)}")
        value = values[key]
        return Record(value, self._root_record()) if isinstance(value, dict) else value

    def _root_record(self):
        root = object.__getattribute__(self, "_root")
        return self if root is None else root

    def __setattr__(self, key, value):
        if key not in self._values:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(self._values)} "
                                 f"(an optional key the file may have: r[{key!r}] = ...)")
        self._values[key] = value.to_dict() if isinstance(value, Record) else value

    def __getitem__(self, key):
        return self.__getattr__(key) if key in self._values else self._values[key]

    def __setitem__(self, key, value):
        self._values[key] = value.to_dict() if isinstance(value, Record) else value

    def __delitem__(self, key):
        if key not in self._values:
            raise KeyError(key)
        keys = list(self._values)
        value = self._values.pop(key)
        try:
            self._root_record()._check_deletion()
        except InputError:
            # Put it back where it was, so that the record is as before.
            self._values[key] = value
            for k in keys[keys.index(key) + 1:]:
                self._values[k] = self._values.pop(k)
            raise

    def __delattr__(self, key):
        if key not in self._values:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(self._values)}")
        self.__delitem__(key)

    def _check_deletion(self):
        """A plain Record has no loader to ask: any key may go."""

    def __contains__(self, key):
        return key in self._values

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)

    def __eq__(self, other):
        if isinstance(other, Record):
            return self._values == other._values
        return self._values == other if isinstance(other, dict) else NotImplemented

    def __dir__(self):
        return list(self._values)

    def keys(self):
        """The keys, in the file's order."""
        return self._values.keys()

    def to_dict(self):
        """A deep copy of the fields as plain dicts and lists."""
        return _copy.deepcopy(self._values)

    def __repr__(self):
        return f"{type(self).__name__}({self._values!r})"


def _write_text(path, text):
    """`text` to `path` through a temporary file in the same folder and a rename: a reader
    never sees half a file, and a failed write leaves the old one."""
    folder = _os.path.dirname(_os.path.abspath(path))
    fd, tmp = _tempfile.mkstemp(dir=folder, prefix=".swingsim-", suffix=".yaml")
    try:
        with _os.fdopen(fd, "w") as f:
            f.write(text)
        _os.replace(tmp, path)
    except BaseException:
        if _os.path.exists(tmp):
            _os.unlink(tmp)
        raise


class _FileRecord(Record):
    """A Record of a file: `origin` is its absolute path (relative paths in it resolve against
    the origin's folder, wherever the current folder goes later; messages about edited values
    name it)."""

    _loader = None  # the module function that loads one into a dict

    def __init__(self, values, origin):
        super().__init__(values)
        # Absolute at once: after os.chdir an object loaded by a relative path resolved its
        # knee_model against the new folder.
        object.__setattr__(self, "origin", _os.path.abspath(_os.fspath(origin)))

    def resolve(self, path):
        """A path written in the file (``p.knee_model``) as a path from the current folder:
        relative paths in a file are relative to the file's folder."""
        return _os.path.join(_os.path.dirname(self.origin), _os.fspath(path))

    def copy(self):
        """An independent copy to edit."""
        return type(self)(self.to_dict(), self.origin)

    def _as_file(self):
        """The object the C++ loader reads (a study replaces its in-memory parts)."""
        return self

    def _check_deletion(self):
        self.validate()

    def _named_files(self, value=None, key=""):
        """(key, path) of every text value that names an existing file, resolved as the loader
        resolves it (relative to the origin's folder)."""
        value = self._values if value is None else value
        if isinstance(value, Record):
            value = value._values
        if isinstance(value, dict):
            for k, v in value.items():
                yield from self._named_files(v, f"{key}.{k}" if key else str(k))
        elif isinstance(value, (list, tuple)):
            for i, v in enumerate(value):
                yield from self._named_files(v, f"{key}[{i}]")
        elif isinstance(value, str) and value:
            candidate = self.resolve(value)
            if _os.path.isfile(candidate):
                yield key, candidate

    def _refuse_overwriting_an_input(self, path):
        """save() may replace the object's own file, never a file it names (its knee model,
        its records): that input would be lost."""
        if not _os.path.exists(path):
            return
        for key, named in self._named_files():
            if _os.path.samefile(named, path):
                raise InputError(f"save(): path: expected a file other than the {key} this object names "
                                 f"(got {path!r}, which is {key}: writing it would replace that input)")

    def validate(self):
        """Checks every field as the C++ loader checks the file (`swingsim simulate` reads a
        participant so); raises InputError naming the key, the value and the origin with
        ``(edited in Python)``. Returns None."""
        _swingsim.format_record(self._as_file(), _os.path.dirname(self.origin) or ".")

    def save(self, path):
        """Writes the object as a YAML file at `path` (validated first: nothing is written if
        a check fails) and makes `path` its origin. The file is the project's own writer's
        (the loader's canonical form: every key, defaults filled in, comments not kept).
        Relative paths in it (a participant's ``knee_model``, a study's records) are rewritten
        relative to the new file's folder, so they point at the same files. Returns `path`."""
        path = _os.fspath(path)
        if not isinstance(path, str):
            raise TypeError(_argument_problem("save(): path", "expected a path (str or os.PathLike)", path))
        self._refuse_overwriting_an_input(path)
        text = _swingsim.format_record(self._as_file(), _os.path.dirname(path) or ".")
        _write_text(path, text)
        object.__setattr__(self, "_values", type(self)._loader(path))
        object.__setattr__(self, "origin", _os.path.abspath(path))
        return path

    def __repr__(self):
        return f"{type(self).__name__}(origin={self.origin!r}, {self._values!r})"


_SEGMENTS = ("thigh", "shank", "foot")
_KEEPS = ("radius_of_gyration", "inertia")


class Participant(_FileRecord):
    """A participant file (participants/*.yaml, docs/formats.md), every key as in the file:
    lengths m, masses kg, inertias kg m^2 about the COM, angles deg, moments N m, times s."""

    _loader = staticmethod(_swingsim.load_participant_dict)

    def set_mass(self, segment, kg, keep="radius_of_gyration"):
        """Sets segment `segment`'s ("thigh", "shank" or "foot") mass to `kg` (kg > 0), its
        COM kept. keep="radius_of_gyration" (default) scales ``inertia_kgm2`` (kg m^2, about
        the COM) by the same factor (I = m k^2 with k kept: the same shape, denser), as
        ``swingsim import-osim --shank-mass-kg`` does; keep="inertia" leaves it (a mass
        added at the COM). Setting ``segments.<segment>.mass_kg`` directly is keep="inertia".
        Raises TypeError / ValueError naming the argument."""
        if not isinstance(segment, str):
            raise TypeError(_argument_problem("set_mass(): segment", "expected one of 'thigh', 'shank', 'foot'", segment))
        if segment not in _SEGMENTS:
            raise InputError(_argument_problem("set_mass(): segment", "expected one of 'thigh', 'shank', 'foot'", segment))
        if isinstance(kg, bool) or not isinstance(kg, _numbers.Real):
            raise TypeError(_argument_problem("set_mass(): kg", "expected a number", kg))
        if not (_math.isfinite(kg) and kg > 0):
            raise InputError(_argument_problem("set_mass(): kg", "expected a positive value", kg))
        if not isinstance(keep, str):
            raise TypeError(_argument_problem("set_mass(): keep", "expected 'radius_of_gyration' or 'inertia'", keep))
        if keep not in _KEEPS:
            raise InputError(_argument_problem("set_mass(): keep", "expected 'radius_of_gyration' or 'inertia'", keep))
        values = self._values["segments"][segment]
        if keep == "radius_of_gyration":
            old = values["mass_kg"]
            if not (isinstance(old, _numbers.Real) and _math.isfinite(old) and old > 0):
                # No radius of gyration to keep from a massless segment (was ZeroDivisionError).
                raise InputError(_argument_problem(
                    "set_mass(): keep", "expected 'inertia' (the segment's mass is " + repr(old) +
                    " kg, so it has no radius of gyration to keep; set inertia_kgm2 too)", keep))
            values["inertia_kgm2"] = values["inertia_kgm2"] * float(kg) / old
        values["mass_kg"] = float(kg)


class KneeModel(_FileRecord):
    """A knee model file (models/*.yaml), every key as in the file (moments N m, angles deg,
    rates deg/s)."""

    _loader = staticmethod(_swingsim.load_knee_dict)


class SwingRecord:
    """One measured swing given in memory, for a `DiagnosisStudy`'s train or validate list:
    the columns of a swing record CSV (docs/formats.md) as 1-D arrays of one length, toe-off
    first. name: the record's name in the study (unique); time_s: s; hip_flexion_deg,
    knee_flexion_deg: deg (flexion positive); hip_moment_Nm, knee_moment_Nm: N m, flexion
    positive (optional; drive: hip_moment needs the hip moment). Checked as a CSV file is
    when the study runs (at least 10 rows, time increasing, plausible ranges)."""

    _COLUMNS = ("time_s", "hip_flexion_deg", "knee_flexion_deg", "hip_moment_Nm", "knee_moment_Nm")

    def __init__(self, name, time_s, hip_flexion_deg, knee_flexion_deg, hip_moment_Nm=None, knee_moment_Nm=None):
        import numpy
        if not isinstance(name, str):
            raise TypeError(_argument_problem("SwingRecord(): name", "expected text (str)", name))
        # The name stands in the study for a file name: a path (../../etc/passwd) is refused.
        if not name or name.startswith(".") or any(c in name for c in "/\\\0"):
            raise InputError(_argument_problem("SwingRecord(): name", "expected a plain name (no folder, no leading dot)", name))
        self.name = name
        given = dict(zip(self._COLUMNS, (time_s, hip_flexion_deg, knee_flexion_deg, hip_moment_Nm, knee_moment_Nm)))
        for key, values in given.items():
            if values is None:
                setattr(self, key, None)
                continue
            array = numpy.asarray(values)
            if array.ndim != 1 or array.dtype.kind not in "iuf":
                raise TypeError(_argument_problem(f"SwingRecord(): {key}", "expected a 1-D array of numbers", values))
            if len(array) != len(given["time_s"]):
                raise InputError(f"SwingRecord(): {key}: expected {len(given['time_s'])} values (as time_s), "
                                 f"got {len(array)}")
            setattr(self, key, array.astype(float))

    @classmethod
    def from_csv(cls, path, name=None):
        """A swing record CSV file's columns (time_s, hip_flexion_deg, knee_flexion_deg,
        optional hip_moment_Nm, knee_moment_Nm) read with numpy; name: default the file's stem."""
        import numpy
        table = numpy.genfromtxt(_os.fspath(path), delimiter=",", names=True)
        stem = _os.path.splitext(_os.path.basename(_os.fspath(path)))[0]
        columns = {k: table[k] for k in cls._COLUMNS if k in table.dtype.names}
        return cls(name or stem, **columns)

    def to_csv(self):
        """The record as swing record CSV text (each number in its shortest exact form)."""
        keys = [k for k in self._COLUMNS if getattr(self, k) is not None]
        rows = [",".join(keys)]
        for i in range(len(self.time_s)):
            rows.append(",".join(repr(float(getattr(self, k)[i])) for k in keys))
        return "\n".join(rows) + "\n"

    def __repr__(self):
        return (f"SwingRecord(name={self.name!r}, {len(self.time_s)} rows, "
                f"{self.time_s[0]:g}..{self.time_s[-1]:g} s)")


def _placeholder(record):
    """A study entry for a record in memory: its name and a file name that is never read."""
    return {"name": record.name, "file": f"{record.name}.in-memory.csv"}


class DiagnosisStudy(_FileRecord):
    """A diagnosis study (studies/*.yaml, kind: cylinder-diagnosis | swing-diagnosis |
    sweep-diagnosis; docs/diagnosis.md), every key as in the file. Built in Python with
    ``DiagnosisStudy(dict, origin="study.yaml")`` (relative paths resolve against origin's
    folder): for a swing-diagnosis study, `participant` may be a Participant, `base_model` a
    KneeModel, and a train/validate entry a SwingRecord (numpy arrays) besides a file name
    or a {name, file, toe_off_s, heel_contact_s | swing, inverse_dynamics} map."""

    _loader = staticmethod(_swingsim.load_study_dict)

    def __init__(self, values, origin="study.yaml"):
        if not isinstance(values, dict):
            raise TypeError(_argument_problem("DiagnosisStudy(): values", "expected a dict", values))
        super().__init__(values, origin)

    def to_dict(self):
        """A deep copy of the fields (objects in it copied too)."""
        return _copy.deepcopy(self._values)

    def _objects(self):
        """(participant, knee, records, file study): the parts held as objects, and a study
        whose YAML names files in their place (the placeholders are never read)."""
        values = dict(self._values)
        participant = values.get("participant")
        knee = values.get("base_model")
        participant = participant if isinstance(participant, Participant) else None
        knee = knee if isinstance(knee, KneeModel) else None
        if participant is not None:
            values["participant"] = participant.origin
        if knee is not None:
            values["base_model"] = knee.origin
        records = {}
        for key in ("train", "validate"):
            if isinstance(values.get(key), list):
                values[key] = [_placeholder(r) if isinstance(r, SwingRecord) else r for r in values[key]]
                records.update({r.name: r.to_csv() for r in self._values[key] if isinstance(r, SwingRecord)})
        return participant, knee, records, DiagnosisStudy(values, self.origin)

    def _as_file(self):
        return self._objects()[3]

    def save(self, path):
        """As Record.save; a study holding objects (a Participant, KneeModel or SwingRecord)
        is refused naming the key: save those as files first and name the files."""
        for key in ("participant", "base_model"):
            if isinstance(self._values.get(key), (Participant, KneeModel)):
                raise InputError(f"{self.origin}: {key}: a {type(self._values[key]).__name__} object; save it "
                                 f"(obj.save(path)) and set {key} to that path before saving the study")
        for key in ("train", "validate"):
            for r in self._values.get(key) or []:
                if isinstance(r, SwingRecord):
                    raise InputError(f"{self.origin}: {key}: record {r.name!r} is in memory; write it as a CSV "
                                     f"(r.to_csv()) and name the file before saving the study")
        return super().save(path)


def load_participant(path):
    """The participant file at `path` as a Participant. Raises InputError as `swingsim
    simulate` would."""
    return Participant(_swingsim.load_participant_dict(path), _os.fspath(path))


def load_knee(path):
    """The knee model file at `path` as a KneeModel. Raises InputError as `swingsim simulate
    --knee` would."""
    return KneeModel(_swingsim.load_knee_dict(path), _os.fspath(path))


def load_study(path):
    """The diagnosis study file at `path` as a DiagnosisStudy. Raises InputError as `swingsim
    diagnose` would."""
    return DiagnosisStudy(_swingsim.load_study_dict(path), _os.fspath(path))


class Result(dict):
    """A result: the dict the command's --json writes (== compares with it), every key also
    an attribute (``r.swings``), nested dicts as Results; to_dict() gives plain dicts."""

    def __getattr__(self, key):
        if key not in self:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(self)}")
        return _as_result(self[key])

    def __dir__(self):
        return list(self) + ["to_dict"]

    def to_dict(self):
        """A deep copy as plain dicts and lists."""
        return _copy.deepcopy(dict(self))

    def _summary(self):
        return ", ".join(f"{k}={v!r}" for k, v in self.items() if not isinstance(v, (dict, list)))

    def __repr__(self):
        return f"{type(self).__name__}({self._summary()})"


def _as_result(value):
    if isinstance(value, dict) and not isinstance(value, Result):
        return Result(value)
    if isinstance(value, list):
        return [_as_result(v) for v in value]
    return value


class SwingResult:
    """One swing: every key of `swingsim simulate --json` as an attribute (swing_time_s,
    peak_knee_flexion_deg, bounce, bounces, bounce_height_deg, stop_impacts,
    min_toe_clearance_m, events, drive, ...), `events_by_name` (name -> time_s), `knee_model`,
    and `trajectory`: the trajectory CSV's columns (time_s, hip_flexion_deg, ...) as numpy
    arrays. `json` is the dict `--json` writes."""

    def __init__(self, values):
        self.trajectory = Record(values.pop("trajectory"))
        self.knee_model = values.pop("knee_model")
        self.json = values
        for key, value in values.items():
            setattr(self, key, value)
        self.events_by_name = {e["name"]: e["time_s"] for e in values["events"]}

    def to_dict(self):
        """The dict `swingsim simulate --json` writes (a copy)."""
        return _copy.deepcopy(self.json)

    def __repr__(self):
        return (f"SwingResult(participant={self.participant!r}, lowering_m={self.lowering_m}, "
                f"swing_time_s={self.swing_time_s})")


def simulate(participant, lowering_m=0.0, knee=None, added_mass_kg=None, added_mass_below_knee_m=None,
             integrator=None, accuracy=None):
    """One swing, as `swingsim simulate PARTICIPANT --lowering M [--knee MODEL] [--add-mass
    KG@M] [--integrator METHOD] [--accuracy A]`.

    participant: a path or a Participant; lowering_m: knee-axis lowering below the standard
    location, m; knee: None (the participant's knee_model), a path or a KneeModel;
    added_mass_kg and added_mass_below_knee_m: a mass on the shank, kg, at m below the knee
    (both or neither); integrator: None (the default) or one of the command line's
    --integrator names, at its converged accuracy unless accuracy (relative, 1e-14 to 0.01)
    is given. Returns a SwingResult (times s, angles deg, moments N m)."""
    return SwingResult(_swingsim.simulate(participant, lowering_m, knee, added_mass_kg, added_mass_below_knee_m,
                                          integrator, accuracy))


def sweep(study_path, uncertainty=0, seed=None, jobs=0, out=None):
    """A knee-axis sweep study, as `swingsim sweep STUDY --json FILE [--uncertainty N]
    [--seed S] [--out DIR]`: returns what the JSON file holds, as dicts and lists (swing
    times s, lowerings m). jobs: worker threads, 0 = all cores. With out (a folder), the
    command's files are written there too (report.md, report.html, sweep.csv and the
    figures, as one staged set; refused if one would replace an input); without it nothing
    is written. Ctrl-C stops it between swings."""
    return _swingsim.sweep(study_path, uncertainty, seed, jobs, out)


def tune(study_path, jobs=0, out=None):
    """A knee-tuning study, as `swingsim tune STUDY --json FILE [--jobs N]`: returns what the
    JSON file holds, as dicts and lists, plus the tuned knee model file's text under
    "tuned_knee_yaml". jobs: worker threads, 0 = all cores. With out (a folder), the command's
    files are written there too (tuned-knee.yaml, tuning.md, tuning.json, tradeoff.svg).
    Ctrl-C stops it between swings and raises KeyboardInterrupt."""
    return _swingsim.tune(study_path, jobs, out)


def _warn_about(result):
    for message in result.get("warnings", []) if isinstance(result, dict) else []:
        _warnings.warn(message, SwingsimWarning, stacklevel=3)
    return result


def fit(study_path):
    """The Mauch cylinder fit of a cylinder-fit study, as `swingsim fit STUDY --json FILE`:
    returns what the JSON file holds (each model's coefficients and ME / RMSE / R^2 per bench
    file, force in N). No report written."""
    return _warn_about(_swingsim.fit(study_path))


def compare(study_path):
    """Model against measurement for a cylinder-diagnosis or swing-diagnosis study, as
    `swingsim compare STUDY --json FILE`: returns what the JSON file holds (errors in the
    compared quantity's unit: N for a cylinder, deg for a swing). No plots written."""
    return _warn_about(_swingsim.compare(study_path))


class RecordSeries:
    """One record of a diagnosis, model against measurement: name, training (True for a
    training record), quantity and unit ("knee flexion", "deg"; "force", "N"), and numpy
    arrays of one length: time_s (s), measured, baseline (the base model refitted) and
    diagnosed (the final model), in `unit`."""

    def __init__(self, values):
        self.__dict__.update(values)

    def to_dict(self):
        """The fields, arrays as lists."""
        return {k: v.tolist() if hasattr(v, "tolist") else v for k, v in self.__dict__.items()}

    def __repr__(self):
        return (f"RecordSeries(name={self.name!r}, training={self.training}, {self.quantity} in {self.unit}, "
                f"{len(self.time_s)} samples)")


class DiagnosisResult(Result):
    """A diagnosis: what `swingsim diagnose STUDY --json FILE` writes, as a Result (==
    compares with that dict; keys as attributes: candidates, accepted, before, after, ...),
    plus `series`: a RecordSeries per record (measured and model, numpy arrays)."""

    def __init__(self, values, series):
        super().__init__(values)
        self.__dict__["series"] = [RecordSeries(s) for s in series]

    def __getattr__(self, key):
        if key == "series":
            return self.__dict__["series"]
        return Result.__getattr__(self, key)

    def __repr__(self):
        def rmse(side):
            fit = self.get(side) or {}
            train = (fit.get("train") or {}).get("rmse")
            return "-" if train is None else f"{train:.3g}"
        return (f"DiagnosisResult(plant={self.get('plant')!r}, accepted={self.get('accepted')!r}, "
                f"train RMSE {rmse('baseline')} -> {rmse('final')} {self.get('unit', '')}, "
                f"explained={self.get('explained')!r}, {len(self.series)} records; keys: {', '.join(self)})")


def diagnose(study=None, max_rows=None, *, study_path=None):
    """The diagnosis of a cylinder-diagnosis, swing-diagnosis or sweep-diagnosis study, as
    `swingsim diagnose STUDY --json FILE`. study: a path, or a DiagnosisStudy (loaded and
    edited, or built in Python with a Participant, a KneeModel and SwingRecords from numpy
    arrays). Returns a DiagnosisResult (errors in deg for a swing, N for a cylinder); each
    warning about the data is issued as a SwingsimWarning. No report or model is written.
    Its size (rows of measured data) and a time estimate are printed on stderr first; above
    `max_rows` (default: the command line's --max-rows default for the study's kind) it is
    refused with ValueError before any fit. `study_path=` is the argument's name before
    objects were accepted, still read (not both)."""
    if study_path is not None:
        if study is not None:
            raise TypeError("diagnose(): give study or study_path, not both")
        study = study_path
    if study is None:
        raise TypeError("diagnose(): missing the study: a path or a swingsim.DiagnosisStudy")
    if isinstance(study, DiagnosisStudy):
        participant, knee, records, file_study = study._objects()
        values = _swingsim.diagnose(file_study, max_rows, participant, knee, records)
    else:
        values = _swingsim.diagnose(study, max_rows)
    series = values.pop("series")
    return _warn_about(DiagnosisResult(values, series))


class SwingList(Result):
    """The swings of one leg in an OpenSim IK file: what `swingsim swings --json` writes
    (file, side, hip, knee, knee_sign, gait, notes, swings: each with swing (1-based),
    toe_off_s, heel_contact_s, duration_s (s), their sources and the force-minus-kinematics
    disagreements, ms)."""

    def __repr__(self):
        spans = ", ".join(f"{s['swing']}: {s['toe_off_s']:.3f}-{s['heel_contact_s']:.3f} s" for s in self["swings"])
        return f"SwingList(file={self['file']!r}, side={self['side']!r}, gait={self['gait']!r}, swings=[{spans}])"


def swings(motion_path, side="r", grf=None, vertical_force=None, threshold_N=20.0, fallback_to_kinematics=False,
           gait=None, knee_sign=-1.0):
    """The complete swings of one leg in an OpenSim IK .mot, as `swingsim swings FILE.mot
    [--side S] [--grf GRF.mot] [--vertical-force LABEL] [--threshold-N N]
    [--fallback-to-kinematics] [--gait G] [--knee-sign S] --json FILE` (docs/swing-events.md).

    side: "r" or "l" (hip_flexion_<side>, knee_angle_<side>); grf: the ground reaction force
    .mot on the same clock (None: events from the kinematics); vertical_force: its column
    (default ground_force_vy for r, 1_ground_force_vy for l), N; threshold_N: force below
    which the foot is in the air, N (> 0); gait: "walking", "running" or None (detected);
    knee_sign: +1 or -1 (knee flexion = sign * knee_angle). Returns a SwingList; its `notes`
    are what the command line prints as "note:" lines."""
    return SwingList(_swingsim.swings(motion_path, side, grf, vertical_force, threshold_N, fallback_to_kinematics,
                                      gait, knee_sign))


def import_osim(osim_path, side="r", name=None, knee=None, knee_friction_Nm=0.0, shank_mass_kg=None,
                foot_mass_kg=None, foot_length_m=None, height_m=None):
    """A Participant from one leg of a scaled OpenSim 4 model, as `swingsim import-osim
    MODEL.osim` (docs/import-osim.md): thigh, shank and foot from femur_<side>, tibia_<side>,
    talus + calcn + toes, every other field the project's default.

    side: "r" or "l"; name: the participant's (default <model name>_<side>); knee: the knee
    model path written as knee_model (default models/damping-table-default.yaml);
    knee_friction_Nm: N m (>= 0); shank_mass_kg, foot_mass_kg: the prosthesis's parts, kg
    (inertia scales with the mass, as set_mass(keep="radius_of_gyration")); foot_length_m:
    ankle to toe, m; height_m: standing height, m. The Participant's origin is
    "<name>.yaml" in the current folder (save(path) writes it; the file's provenance
    comments are the command line's only)."""
    values, participant_name = _swingsim.import_osim(osim_path, side, name, knee, knee_friction_Nm, shank_mass_kg,
                                                     foot_mass_kg, foot_length_m, height_m)
    return Participant(values, f"{participant_name}.yaml")


def export_osim(participant, path, lowering_m=0.0, side="r", added_mass_kg=None, added_mass_below_knee_m=None):
    """The simulated leg as an OpenSim 4 model written to `path` (a .osim file), as
    `swingsim export-osim PARTICIPANT --side S --lowering M [--add-mass KG@M]`
    (docs/export-osim.md). participant: a path or a Participant; lowering_m: knee-axis
    lowering, m; side: "r" or "l", naming bodies, joints and coordinates as OpenSim's gait
    models (femur_r, hip_flexion_r, knee_angle_r negative in flexion); added_mass_kg (kg) and
    added_mass_below_knee_m (m below the knee, along the shank): a point mass welded to the
    tibia, both or neither. Refuses to write over the participant or its knee model.
    Returns `path`."""
    return _swingsim.export_osim(participant, path, lowering_m, side, added_mass_kg, added_mass_below_knee_m)
