"""swingsim.diagnose on a study object: loaded and unedited, edited, and built in Python
from a Participant, a KneeModel and SwingRecords of numpy arrays; its result object."""
import json
import subprocess

import numpy
import pytest

import swingsim

DATA = "studies/data/diagnose-demo-swing"


@pytest.fixture(scope="module")
def study_file(repo, tmp_path_factory):
    """studies/diagnose-demo-swing.yaml with one candidate effect (the one it accepts), so
    that each diagnosis here takes seconds."""
    path = tmp_path_factory.mktemp("study") / "demo-swing.yaml"
    data = repo / DATA
    path.write_text(f"""kind: swing-diagnosis
name: diagnose-demo-swing
participant: {repo / 'participants' / 'p1.yaml'}
base_model: {repo / 'models' / 'damping-table-default.yaml'}
train: [{data / 'normal.csv'}]
validate: [{data / 'slow.csv'}, {data / 'fast.csv'}]
candidates: [extension_assist_spring]
acceptance: {{alpha: 0.01, min_validation_improvement: 0.02, max_effects: 1}}
""")
    return path


@pytest.fixture(scope="module")
def from_path(study_file):
    return swingsim.diagnose(study_file)


def test_result_is_the_cli_json_with_series(repo, cli, tmp_path, study_file, from_path):
    out = tmp_path / "cli.json"
    subprocess.run([cli, "diagnose", str(study_file), "--json", str(out), "--out", str(tmp_path / "report")], cwd=repo,
                   check=True, capture_output=True)
    assert from_path == json.loads(out.read_text())
    assert isinstance(from_path, swingsim.DiagnosisResult)
    assert from_path.to_dict() == json.loads(out.read_text())
    assert [s.name for s in from_path.series] == ["normal", "slow", "fast"]
    first = from_path.series[0]
    assert first.training and not from_path.series[1].training
    assert first.unit == "deg"
    assert isinstance(first.measured, numpy.ndarray)
    assert len(first.time_s) == len(first.measured) == len(first.baseline) == len(first.diagnosed) > 10
    assert from_path.accepted == ["extension_assist_spring"]
    assert "DiagnosisResult(" in repr(from_path) and "3 records" in repr(from_path)
    assert "accepted=['extension_assist_spring']" in repr(from_path)


def test_an_unedited_study_object_gives_the_same(study_file, from_path):
    assert swingsim.diagnose(swingsim.load_study(study_file)) == from_path


def test_a_study_built_in_python_from_arrays(repo, from_path):
    # The same study with every part an object: participant and knee loaded, the records read
    # into numpy arrays. Same records, same settings: the same diagnosis.
    records = [swingsim.SwingRecord.from_csv(repo / DATA / f"{n}.csv") for n in ("normal", "slow", "fast")]
    assert isinstance(records[0].time_s, numpy.ndarray)
    study = swingsim.DiagnosisStudy({
        "kind": "swing-diagnosis",
        "name": "diagnose-demo-swing",
        "participant": swingsim.load_participant(repo / "participants" / "p1.yaml"),
        "base_model": swingsim.load_knee(repo / "models" / "damping-table-default.yaml"),
        "train": records[:1],
        "validate": records[1:],
        "candidates": ["extension_assist_spring"],
        "acceptance": {"alpha": 0.01, "min_validation_improvement": 0.02, "max_effects": 1},
    }, origin=repo / "studies" / "python-study.yaml")
    result = swingsim.diagnose(study)
    strip = lambda d: {k: v for k, v in d.items() if k not in ("study",)}  # noqa: E731
    assert strip(result.to_dict()) == strip(from_path.to_dict())
    assert numpy.array_equal(result.series[2].measured, from_path.series[2].measured)


def test_an_edited_record_changes_the_diagnosis(repo, study_file, from_path):
    s = swingsim.load_study(study_file)
    record = swingsim.SwingRecord.from_csv(repo / DATA / "normal.csv")
    record.knee_flexion_deg = record.knee_flexion_deg + 2.0  # a 2 deg offset in the measurement
    s["train"] = [record]
    result = swingsim.diagnose(s)
    assert not numpy.array_equal(result.series[0].measured, from_path.series[0].measured)
    assert result.series[0].measured == pytest.approx(from_path.series[0].measured + 2.0)


def test_a_bad_record_in_memory_is_named(study_file):
    s = swingsim.load_study(study_file)
    t = numpy.linspace(0, 0.5, 20)
    s["train"] = [swingsim.SwingRecord("flat", t, numpy.zeros(20), numpy.linspace(0, 1, 20), numpy.zeros(20))]
    with pytest.raises(swingsim.InputError, match="record flat.*knee_flexion_deg.*radians"):
        swingsim.diagnose(s)


def test_study_checks_name_the_key(study_file):
    s = swingsim.load_study(study_file)
    s.acceptance.alpha = 2
    with pytest.raises(swingsim.InputError, match=r"\(edited in Python\):\d+: acceptance.alpha"):
        swingsim.diagnose(s)
    with pytest.raises(TypeError) as error:
        swingsim.diagnose(42)
    assert str(error.value) == "diagnose(): study: expected a path or a swingsim.DiagnosisStudy, got int 42"


def test_a_record_timed_in_ms_is_refused_at_once(study_file):
    # Issue 57: a record timed in ms sent the diagnosis integrating past 60 s.
    s = swingsim.load_study(study_file)
    t = numpy.linspace(0, 500.0, 20)  # ms
    s["train"] = [swingsim.SwingRecord("ms", t, numpy.zeros(20), numpy.linspace(0, 60, 20), numpy.zeros(20))]
    with pytest.raises(swingsim.InputError, match="record ms.*time_s: expected one swing in seconds.*in ms\\?"):
        swingsim.diagnose(s)


def test_swing_record_arguments():
    # Issue 57: a record's name stands for a file name in the study: no path.
    for bad in ("../../../etc/passwd", "a/b", "", ".hidden"):
        with pytest.raises(swingsim.InputError, match="SwingRecord\\(\\): name: expected a plain name"):
            swingsim.SwingRecord(bad, [0, 1, 2], [0, 1, 2], [0, 1, 2])
    with pytest.raises(swingsim.InputError, match="SwingRecord\\(\\): knee_flexion_deg: expected 3 values"):
        swingsim.SwingRecord("r", [0, 1, 2], [0, 1, 2], [0, 1])
    with pytest.raises(TypeError, match="SwingRecord\\(\\): hip_flexion_deg"):
        swingsim.SwingRecord("r", [0, 1, 2], ["a", "b", "c"], [0, 1, 2])


def test_a_study_with_objects_is_not_saved(repo, tmp_path):
    s = swingsim.load_study(repo / "studies" / "diagnose-demo-swing.yaml")
    s["participant"] = swingsim.load_participant(repo / "participants" / "p1.yaml")
    with pytest.raises(swingsim.InputError, match="participant"):
        s.save(tmp_path / "s.yaml")
    assert not (tmp_path / "s.yaml").exists()


def test_warnings_of_a_study_object(repo):
    # The hip read without the pelvis tilt: a SwingsimWarning, as for a study file.
    ik = repo / "tests" / "data" / "opensim-gait10dof" / "subject01_walk_IK.mot"
    study = swingsim.DiagnosisStudy({
        "kind": "swing-diagnosis",
        "participant": str(repo / "participants" / "winter.yaml"),
        "base_model": str(repo / "models" / "passive-knee.yaml"),
        "drive": "thigh_kinematics",
        "motion_columns": {"hip": "hip_flexion_r", "knee": "knee_angle_r", "knee_sign": -1},
        "train": [{"name": "right1", "file": str(ik), "toe_off_s": 0.25, "heel_contact_s": 0.7}],
        "validate": [{"name": "right2", "file": str(ik), "toe_off_s": 1.35, "heel_contact_s": 1.8}],
        "acceptance": {"max_effects": 1},
    })
    with pytest.warns(swingsim.SwingsimWarning, match="read without the pelvis tilt"):
        swingsim.diagnose(study)


def test_diagnose_still_reads_the_old_argument_name(study_file, from_path):
    assert swingsim.diagnose(study_path=study_file) == from_path
    with pytest.raises(TypeError, match="not both"):
        swingsim.diagnose("a.yaml", study_path="b.yaml")
    with pytest.raises(TypeError, match="missing the study"):
        swingsim.diagnose()
