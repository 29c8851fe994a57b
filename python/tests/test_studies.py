"""swingsim.fit, swingsim.compare and swingsim.diagnose against the command line's --json."""
import json
import subprocess

import pytest

import swingsim


@pytest.mark.parametrize("command", ["compare", "diagnose"])
def test_equals_cli(repo, cli, tmp_path, command):
    study = repo / "studies" / "diagnose-demo-cylinder.yaml"
    out = tmp_path / "cli.json"
    subprocess.run([cli, command, str(study), "--json", str(out), "--out", str(tmp_path / "report")],
                   check=True, capture_output=True)
    expected = json.loads(out.read_text())
    result = getattr(swingsim, command)(study)
    assert result == expected


def test_fit_equals_cli(repo, cli, tmp_path):
    study = repo / "studies" / "mauch2014.yaml"
    out = tmp_path / "cli.json"
    subprocess.run([cli, "fit", str(study), "--json", str(out), "--out", str(tmp_path / "report")],
                   check=True, capture_output=True)
    result = swingsim.fit(study)
    assert result == json.loads(out.read_text())
    assert [m["model"] for m in result["models"]] == ["mauch-2phase", "mauch-4phase"]


def test_fit_of_a_study_of_another_kind_names_the_key(repo):
    with pytest.raises(swingsim.InputError, match="kind"):
        swingsim.fit(repo / "studies" / "diagnose-demo-cylinder.yaml")


def test_a_warning_about_the_data_is_a_python_warning(repo, cli, tmp_path):
    # The hip read without the pelvis tilt the file has: compare warns, as the command line
    # does on stderr and in its JSON, with a category of the module's own.
    ik = repo / "tests" / "data" / "opensim-gait10dof" / "subject01_walk_IK.mot"
    study = tmp_path / "study.yaml"
    study.write_text(
        "kind: swing-diagnosis\n"
        f"participant: {repo / 'participants' / 'winter.yaml'}\n"
        f"base_model: {repo / 'models' / 'passive-knee.yaml'}\n"
        "drive: thigh_kinematics\n"
        "motion_columns: {hip: hip_flexion_r, knee: knee_angle_r, knee_sign: -1}\n"
        f"train:\n  - {{name: right1, file: {ik}, toe_off_s: 0.25, heel_contact_s: 0.7}}\n"
        f"validate:\n  - {{name: right2, file: {ik}, toe_off_s: 1.35, heel_contact_s: 1.8}}\n")
    with pytest.warns(swingsim.SwingsimWarning, match="read without the pelvis tilt") as caught:
        result = swingsim.compare(study)
    assert [str(w.message) for w in caught] == result["warnings"]
    out = tmp_path / "cli.json"
    run = subprocess.run([cli, "compare", str(study), "--json", str(out), "--out", str(tmp_path / "report")],
                         capture_output=True, text=True, check=True)
    assert json.loads(out.read_text())["warnings"] == result["warnings"]
    assert result["warnings"][0] in run.stderr
