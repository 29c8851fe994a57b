"""The package's results (re-exported by swingsim/__init__.py as swingsim.Result, ...): what
the calls return, each the dict the command line's --json writes with its keys as attributes
(Result, DiagnosisResult, SwingList), one swing with its trajectory (SwingResult), and one
record of a diagnosis as numpy arrays (RecordSeries)."""
import copy as _copy

from swingsim._records import Record


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
        # Scalars in full; a nested dict or list by its size, so a result of nested parts
        # (a sweep's participants, a diagnosis's records) does not print as empty.
        def brief(v):
            if isinstance(v, dict):
                return f"{{{len(v)} keys}}"
            if isinstance(v, list):
                return f"[{len(v)} items]"
            return repr(v)
        return ", ".join(f"{k}={brief(v)}" for k, v in self.items())

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


class SwingList(Result):
    """The swings of one leg in an OpenSim IK file: what `swingsim swings --json` writes
    (file, side, hip, knee, knee_sign, gait, notes, swings: each with swing (1-based),
    toe_off_s, heel_contact_s, duration_s (s), their sources and the force-minus-kinematics
    disagreements, ms)."""

    def __repr__(self):
        spans = ", ".join(f"{s['swing']}: {s['toe_off_s']:.3f}-{s['heel_contact_s']:.3f} s" for s in self["swings"])
        return f"SwingList(file={self['file']!r}, side={self['side']!r}, gait={self['gait']!r}, swings=[{spans}])"
