"""swingsim from Python: the swing phase of an above-knee prosthetic leg (docs/python.md).

Participants and knee models load from their YAML files into editable objects whose fields
are the file's keys, in the file's units (``p.segments.shank.mass_kg``); `simulate` runs one
swing, `sweep` a knee-axis sweep study, `tune` a knee-tuning study, `fit` a cylinder-fit study, `compare` and `diagnose` a
diagnosis study, through the same C++ functions as the command
line, with the GIL released while they run. Bad input raises `InputError` (a ValueError)
with the command line's ``file:line: key: ...`` message; an argument of the wrong type raises
TypeError and one out of the command line's range InputError, naming it; a failed run raises `RunError`; a
warning about the data is issued with `warnings.warn` as a `SwingsimWarning`.
"""
import copy as _copy
import os as _os
import warnings as _warnings

from swingsim import _swingsim
from swingsim._swingsim import InputError, RunError

InputError.__module__ = RunError.__module__ = "swingsim"  # shown as swingsim.InputError

__all__ = ["InputError", "RunError", "SwingsimWarning", "Record", "Participant", "KneeModel", "SwingResult",
           "load_participant", "load_knee", "simulate", "sweep", "tune", "fit", "compare", "diagnose"]


class Record:
    """A mapping of a YAML file, read and edited by attribute (``r.initial.knee_flexion_deg``)
    or by key (``r["initial"]["knee_flexion_deg"]``). Setting an attribute that the file does
    not have is an AttributeError (a misspelt key); set a new optional key by item instead."""

    def __init__(self, values):
        object.__setattr__(self, "_values", values)

    def __getattr__(self, key):
        values = object.__getattribute__(self, "_values")
        if key not in values:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(values)}")
        value = values[key]
        return Record(value) if isinstance(value, dict) else value

    def __setattr__(self, key, value):
        if key not in self._values:
            raise AttributeError(f"no key {key!r}; keys: {', '.join(self._values)} "
                                 f"(an optional key the file may have: r[{key!r}] = ...)")
        self._values[key] = value.to_dict() if isinstance(value, Record) else value

    def __getitem__(self, key):
        return self.__getattr__(key) if key in self._values else self._values[key]

    def __setitem__(self, key, value):
        self._values[key] = value.to_dict() if isinstance(value, Record) else value

    def __contains__(self, key):
        return key in self._values

    def __dir__(self):
        return list(self._values)

    def keys(self):
        return self._values.keys()

    def to_dict(self):
        """A deep copy of the fields as plain dicts and lists."""
        return _copy.deepcopy(self._values)

    def __repr__(self):
        return f"{type(self).__name__}({self._values!r})"


class _FileRecord(Record):
    """A Record loaded from a file: `origin` is its path (relative paths in it resolve
    against the origin's folder; messages about edited values name it)."""

    def __init__(self, values, origin):
        super().__init__(values)
        object.__setattr__(self, "origin", str(origin))

    def resolve(self, path):
        """A path written in the file (``p.knee_model``) as a path from the current folder:
        relative paths in a file are relative to the file's folder."""
        return _os.path.join(_os.path.dirname(self.origin), _os.fspath(path))

    def copy(self):
        """An independent copy to edit."""
        return type(self)(self.to_dict(), self.origin)

    def __repr__(self):
        return f"{type(self).__name__}(origin={self.origin!r}, {self._values!r})"


class Participant(_FileRecord):
    """A participant file (participants/*.yaml), every key as in the file."""


class KneeModel(_FileRecord):
    """A knee model file (models/*.yaml), every key as in the file."""


def load_participant(path):
    """The participant file at `path`. Raises InputError as `swingsim simulate` would."""
    return Participant(_swingsim.load_participant_dict(path), _os.fspath(path))


def load_knee(path):
    """The knee model file at `path`. Raises InputError as `swingsim simulate --knee` would."""
    return KneeModel(_swingsim.load_knee_dict(path), _os.fspath(path))


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

    def __repr__(self):
        return (f"SwingResult(participant={self.participant!r}, lowering_m={self.lowering_m}, "
                f"swing_time_s={self.swing_time_s})")


def simulate(participant, lowering_m=0.0, knee=None):
    """One swing, as `swingsim simulate PARTICIPANT --lowering M [--knee MODEL]`.

    participant: a path or a Participant; lowering_m: knee-axis lowering, m; knee: None (the
    participant's knee_model), a path or a KneeModel. Returns a SwingResult."""
    return SwingResult(_swingsim.simulate(participant, lowering_m, knee))


def sweep(study_path, uncertainty=0, seed=None, jobs=0):
    """A knee-axis sweep study, as `swingsim sweep STUDY --json FILE [--uncertainty N]
    [--seed S]`: returns what the JSON file holds, as dicts and lists. jobs: worker threads,
    0 = all cores. No report or CSV is written. Ctrl-C stops it between swings."""
    return _swingsim.sweep(study_path, uncertainty, seed, jobs)


def tune(study_path, jobs=0, out=None):
    """A knee-tuning study, as `swingsim tune STUDY --json FILE [--jobs N]`: returns what the
    JSON file holds, as dicts and lists, plus the tuned knee model file's text under
    "tuned_knee_yaml". jobs: worker threads, 0 = all cores. With out (a folder), the command's
    files are written there too (tuned-knee.yaml, tuning.md, tuning.json, tradeoff.svg).
    Ctrl-C stops it between swings and raises KeyboardInterrupt."""
    return _swingsim.tune(study_path, jobs, out)


class SwingsimWarning(UserWarning):
    """A warning about the data a swingsim call read (a flipped sign, a column read without
    the pelvis tilt, a force file left to the kinematics, ...): the same text the command
    line prints on stderr and the JSON keeps under "warnings"."""


def _warn_about(result):
    for message in result.get("warnings", []) if isinstance(result, dict) else []:
        _warnings.warn(message, SwingsimWarning, stacklevel=3)
    return result


def fit(study_path):
    """The Mauch cylinder fit of a cylinder-fit study, as `swingsim fit STUDY --json FILE`:
    returns what the JSON file holds (each model's coefficients and ME / RMSE / R^2 per bench
    file). No report written."""
    return _warn_about(_swingsim.fit(study_path))


def compare(study_path):
    """Model against measurement for a cylinder-diagnosis or swing-diagnosis study, as
    `swingsim compare STUDY --json FILE`: returns what the JSON file holds. No plots written."""
    return _warn_about(_swingsim.compare(study_path))


def diagnose(study_path, max_rows=None):
    """The diagnosis of a cylinder-diagnosis or swing-diagnosis study, as `swingsim diagnose
    STUDY --json FILE`: returns what the JSON file holds. No report or model is written.
    Its size (rows of measured data) and a time estimate are printed on stderr first; above
    `max_rows` (default: the command line's --max-rows default for the study's kind) it is
    refused with ValueError before any fit."""
    return _warn_about(_swingsim.diagnose(study_path, max_rows))
