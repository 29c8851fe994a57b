"""The package's records (re-exported by swingsim/__init__.py as swingsim.Record, ...):
Record, a YAML file's mapping read and edited by attribute or by key; the file objects
Participant, KneeModel and DiagnosisStudy, loaded, validated and saved by the C++ loaders
(a DiagnosisStudy may hold the other objects in memory); and SwingRecord, a measured swing
given as numpy arrays (docs/python.md)."""
import copy as _copy
import math as _math
import numbers as _numbers
import os as _os
import tempfile as _tempfile

from swingsim import _swingsim
from swingsim._errors import InputError, _argument_problem


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
