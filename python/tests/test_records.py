"""Participant, KneeModel and DiagnosisStudy objects: edit, delete optional keys, validate
with the loaders' checks, save back to YAML (round trip; the saved file runs in the CLI)."""
import json
import shutil
import subprocess

import pytest

import swingsim


def test_delete_an_optional_key_by_item_and_by_attribute(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    assert "sound_limb_swing_time_s" in p
    del p["sound_limb_swing_time_s"]
    assert "sound_limb_swing_time_s" not in p
    q = swingsim.load_participant(repo / "participants" / "p1.yaml")
    del q.sound_limb_swing_time_s
    assert p == q
    p.validate()


def test_switch_to_the_thigh_drive_by_deleting_the_hip_moment(repo):
    # hip_moment is required with the hip-moment drive and refused with the thigh drive:
    # set the drive, then delete it (as the user wanted).
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    with pytest.raises(swingsim.InputError, match="hip_moment: required key is missing"):
        del p.hip_moment
    assert "hip_moment" in p
    p["drive"] = "thigh_kinematics"
    p["thigh_kinematics"] = "../studies/data/winter-swing/swing1.csv"
    del p["hip_moment"]
    assert "hip_moment" not in p
    assert swingsim.simulate(p).drive == "thigh_kinematics"


def test_delete_a_required_key_raises_naming_it_and_keeps_it(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    before = p.to_dict()
    with pytest.raises(swingsim.InputError, match="mass_kg"):
        del p.segments.shank.mass_kg
    assert p.to_dict() == before
    assert list(p.segments.shank.keys()) == list(before["segments"]["shank"].keys())  # order kept too
    with pytest.raises(swingsim.InputError, match="height_m"):
        del p["height_m"]
    assert p.height_m == before["height_m"]


def test_delete_a_missing_key_is_a_key_error(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    with pytest.raises(KeyError):
        del p["no_such_key"]
    with pytest.raises(AttributeError, match="no_such_key"):
        del p.no_such_key


def test_validate_names_the_key_and_value(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.validate()  # as loaded: no error
    p.segments.shank.mass_kg = -1
    with pytest.raises(swingsim.InputError, match=r"p1.yaml \(edited in Python\):\d+: segments.shank.mass_kg.*-1"):
        p.validate()
    k = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    k.validate()


def test_participant_round_trip_and_the_cli_runs_the_saved_file(repo, cli, tmp_path):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.segments.shank.mass_kg = 1.1
    saved = tmp_path / "p1-heavy.yaml"
    assert p.save(saved) == str(saved)
    assert p.origin == str(saved)
    again = swingsim.load_participant(saved)
    assert again.to_dict() == p.to_dict()
    assert again.segments.shank.mass_kg == 1.1
    # Saved elsewhere, the relative knee_model is rewritten to point at the same file.
    assert again.resolve(again.knee_model) != str(saved)
    assert (tmp_path / again.knee_model).resolve() == (repo / "models" / "damping-table-default.yaml").resolve()
    out = tmp_path / "swing.json"
    subprocess.run([cli, "simulate", str(saved), "--json", str(out), "--out", str(tmp_path / "sim")],
                   check=True, capture_output=True)
    assert json.loads(out.read_text())["swing_time_s"] == pytest.approx(swingsim.simulate(p).swing_time_s, rel=0, abs=0)


def test_save_beside_the_original_keeps_the_dict(repo, tmp_path):
    (tmp_path / "participants").mkdir()
    shutil.copy(repo / "participants" / "p1.yaml", tmp_path / "participants" / "p1.yaml")
    (tmp_path / "models").mkdir()
    shutil.copy(repo / "models" / "damping-table-default.yaml", tmp_path / "models")
    p = swingsim.load_participant(tmp_path / "participants" / "p1.yaml")
    before = p.to_dict()
    p.save(tmp_path / "participants" / "copy.yaml")
    assert swingsim.load_participant(tmp_path / "participants" / "copy.yaml").to_dict() == before


def test_a_refused_save_writes_nothing(repo, tmp_path):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.height_m = "tall"
    with pytest.raises(swingsim.InputError, match="height_m"):
        p.save(tmp_path / "bad.yaml")
    assert list(tmp_path.iterdir()) == []


def test_knee_model_round_trip(repo, tmp_path):
    k = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    k.damping_table.moment_Nm = [2 * m for m in k.damping_table.moment_Nm]
    k.save(tmp_path / "knee.yaml")
    assert swingsim.load_knee(tmp_path / "knee.yaml").to_dict() == k.to_dict()


def test_study_round_trip_rewrites_its_paths(repo, tmp_path):
    s = swingsim.load_study(repo / "studies" / "diagnose-demo-swing.yaml")
    assert s.kind == "swing-diagnosis"
    s.acceptance.max_effects = 2
    s.save(tmp_path / "study.yaml")
    again = swingsim.load_study(tmp_path / "study.yaml")
    assert again.to_dict() == s.to_dict()
    assert again.acceptance.max_effects == 2
    assert (tmp_path / again.participant).resolve() == (repo / "participants" / "p1.yaml").resolve()


def test_save_refuses_to_replace_a_file_it_names(repo, tmp_path):
    """save() over the object's knee model (a file it names) is refused and the knee file is
    left as it was; over its own file it is an edit in place."""
    (tmp_path / "participants").mkdir()
    (tmp_path / "models").mkdir()
    shutil.copy(repo / "participants" / "p1.yaml", tmp_path / "participants" / "p1.yaml")
    knee = tmp_path / "models" / "damping-table-default.yaml"
    shutil.copy(repo / "models" / "damping-table-default.yaml", knee)
    before = knee.read_text()
    p = swingsim.load_participant(tmp_path / "participants" / "p1.yaml")
    with pytest.raises(swingsim.InputError, match=r"save\(\): path: expected a file other than the knee_model"):
        p.save(knee)
    assert knee.read_text() == before
    p.segments.shank.mass_kg = 1.2
    p.save(tmp_path / "participants" / "p1.yaml")
    assert swingsim.load_participant(tmp_path / "participants" / "p1.yaml").segments.shank.mass_kg == 1.2


def test_an_object_loaded_by_a_relative_path_keeps_its_folder_after_chdir(repo, tmp_path, monkeypatch):
    # Issue 57: after os.chdir an object loaded by a relative path swung with another folder's knee.
    monkeypatch.chdir(repo)
    p = swingsim.load_participant("participants/p1.yaml")
    expected = swingsim.simulate(p).swing_time_s
    monkeypatch.chdir(tmp_path)
    assert p.origin == str(repo / "participants" / "p1.yaml")
    assert swingsim.simulate(p).swing_time_s == expected
