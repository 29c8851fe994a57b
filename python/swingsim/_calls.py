"""The package's calls around the C++ extension swingsim._swingsim (re-exported by
swingsim/__init__.py as swingsim.simulate, ...): the loaders and the commands, each as the
command line's, with the GIL released while the C++ runs; a warning about the data is issued
as a SwingsimWarning."""
import os as _os
import warnings as _warnings

from swingsim import _swingsim
from swingsim._errors import SwingsimWarning
from swingsim._records import DiagnosisStudy, KneeModel, Participant
from swingsim._results import DiagnosisResult, SwingList, SwingResult


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
                foot_mass_kg=None, foot_length_m=None, height_m=None, knee_part=None, pylon_part=None,
                ankle_part=None, foot_part=None, parts_catalogue=None):
    """A Participant from one leg of a scaled OpenSim 4 model, as `swingsim import-osim
    MODEL.osim` (docs/import-osim.md): thigh, shank and foot from femur_<side>, tibia_<side>,
    talus + calcn + toes, every other field the project's default.

    side: "r" or "l"; name: the participant's (default <model name>_<side>); knee: the knee
    model path written as knee_model (default models/damping-table-default.yaml);
    knee_friction_Nm: N m (>= 0); shank_mass_kg, foot_mass_kg: the prosthesis's parts, kg
    (inertia scales with the mass, as set_mass(keep="radius_of_gyration")); foot_length_m:
    ankle to toe, m; height_m: standing height, m. knee_part, pylon_part, ankle_part,
    foot_part: catalogue ids (`swingsim parts`; docs/parts.md) whose masses make the shank and
    foot instead; parts_catalogue: their catalogue (default the shipped one). The Participant's origin is
    "<name>.yaml" in the current folder (save(path) writes it; the file's provenance
    comments are the command line's only)."""
    values, participant_name = _swingsim.import_osim(osim_path, side, name, knee, knee_friction_Nm, shank_mass_kg,
                                                     foot_mass_kg, foot_length_m, height_m, knee_part, pylon_part,
                                                     ankle_part, foot_part, parts_catalogue)
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
