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
import importlib as _importlib
import sys as _sys

# The package is in parts, each a private module: _errors (InputError, RunError,
# SwingsimWarning), _records (Record, Participant, KneeModel, SwingRecord, DiagnosisStudy),
# _results (Result, SwingResult, RecordSeries, DiagnosisResult, SwingList) and _calls (the
# load_* functions and the commands around the C++ extension swingsim._swingsim). They are
# loaded in the order they import each other, and importlib.reload(swingsim) (a notebook's
# autoreload) reloads each, so that a reload picks up an edited part as it did when all was
# in this file.
for _part in ("_errors", "_records", "_results", "_calls"):
    if f"{__name__}.{_part}" in _sys.modules:
        _importlib.reload(_sys.modules[f"{__name__}.{_part}"])
    else:
        _importlib.import_module(f"{__name__}.{_part}")
del _part

from swingsim import _swingsim
from swingsim._calls import (compare, diagnose, export_osim, fit, import_osim, load_knee, load_participant,
                             load_study, simulate, sweep, swings, tune)
from swingsim._errors import InputError, RunError, SwingsimWarning
from swingsim._records import DiagnosisStudy, KneeModel, Participant, Record, SwingRecord, _FileRecord
from swingsim._results import DiagnosisResult, RecordSeries, Result, SwingList, SwingResult

__all__ = ["InputError", "RunError", "SwingsimWarning", "Record", "Result", "Participant", "KneeModel",
           "DiagnosisStudy", "SwingRecord", "SwingResult", "SwingList", "DiagnosisResult", "RecordSeries",
           "load_participant", "load_knee", "load_study", "simulate", "sweep", "tune", "fit", "compare",
           "diagnose", "swings", "import_osim", "export_osim"]

# Every class and function is shown as the package's (swingsim.Participant, in repr(), help()
# and messages), as when they were defined here. The C++ side relies on it: an object made
# before importlib.reload(swingsim) is an instance of the class as it was, and is accepted by
# its module ("swingsim") and name (isPackageObject, python/src/python_objects.cpp).
for _name in __all__ + ["_FileRecord"]:
    globals()[_name].__module__ = __name__
del _name
