"""swingsim.swings, import_osim and export_osim against their commands' output, and their
argument checks."""
import json
import pathlib
import subprocess

import pytest

import swingsim

IK = "studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot"
GRF = "studies/data/opensim-subject01/subject01_walk1_grf.mot"
OSIM = "studies/data/opensim-subject01/gait2354_subject01_simbody.osim"


def test_swings_equals_cli(repo, cli, tmp_path):
    out = tmp_path / "swings.json"
    subprocess.run([cli, "swings", IK, "--grf", GRF, "--json", str(out)], cwd=repo, check=True, capture_output=True)
    result = swingsim.swings(IK, grf=GRF)
    assert result == json.loads(out.read_text())
    assert [s.swing for s in result.swings] == [1, 2]
    assert result.swings[0].toe_off_source == "grf"
    assert "SwingList(" in repr(result) and "1: 1.409-1.852 s" in repr(result)


def test_swings_without_force_file_and_left_side(repo, cli, tmp_path):
    out = tmp_path / "swings.json"
    subprocess.run([cli, "swings", IK, "--side", "l", "--gait", "walking", "--json", str(out)], cwd=repo, check=True,
                   capture_output=True)
    assert swingsim.swings(IK, side="l", gait="walking") == json.loads(out.read_text())


@pytest.mark.parametrize("kwargs, error, match", [
    ({"side": "x"}, ValueError, "swings\\(\\): side: expected one of 'r', 'l', got 'x'"),
    ({"side": 1}, TypeError, "swings\\(\\): side"),
    ({"threshold_N": -5}, ValueError, "swings\\(\\): threshold_N: expected a positive force"),
    ({"threshold_N": "20"}, TypeError, "swings\\(\\): threshold_N: expected a number"),
    ({"knee_sign": 2}, ValueError, "swings\\(\\): knee_sign: expected \\+1 or -1"),
    ({"fallback_to_kinematics": 1}, TypeError, "swings\\(\\): fallback_to_kinematics: expected True or False"),
    ({"gait": "jogging"}, ValueError, "swings\\(\\): gait"),
    ({"grf": 3}, TypeError, "swings\\(\\): grf"),
])
def test_swings_arguments(repo, kwargs, error, match):
    with pytest.raises(error, match=match):
        swingsim.swings(repo / IK, **kwargs)


def test_swings_bad_file_is_an_input_error(tmp_path):
    bad = tmp_path / "bad.mot"
    bad.write_text("not a motion file\n")
    with pytest.raises(swingsim.InputError, match="bad.mot"):
        swingsim.swings(bad)


def test_import_osim_equals_cli(repo, cli, tmp_path):
    out = tmp_path / "s01.yaml"
    subprocess.run([cli, "import-osim", OSIM, "--name", "s01", "--shank-mass-kg", "1.5", "--out", str(out)], cwd=repo,
                   check=True, capture_output=True)
    p = swingsim.import_osim(repo / OSIM, name="s01", shank_mass_kg=1.5)
    assert isinstance(p, swingsim.Participant)
    cli_p = swingsim.load_participant(out)
    expected = cli_p.to_dict()
    got = p.to_dict()
    # knee_model is written relative to each file's folder: compare the file it names.
    assert (tmp_path / expected.pop("knee_model")).resolve() == pathlib.Path(p.resolve(got.pop("knee_model"))).resolve()
    assert got == expected
    assert p.segments.shank.mass_kg == 1.5


def test_import_osim_with_catalogue_parts_equals_cli(repo, cli, tmp_path):
    out = tmp_path / "s01.yaml"
    subprocess.run([cli, "import-osim", OSIM, "--name", "s01", "--knee-part", "ottobock-3r15", "--foot-part",
                    "proteor-kinterra-26", "--out", str(out)], cwd=repo, check=True, capture_output=True)
    p = swingsim.import_osim(repo / OSIM, name="s01", knee_part="ottobock-3r15", foot_part="proteor-kinterra-26")
    expected = swingsim.load_participant(out).to_dict()
    got = p.to_dict()
    assert (tmp_path / expected.pop("knee_model")).resolve() == pathlib.Path(p.resolve(got.pop("knee_model"))).resolve()
    assert got == expected
    assert got["prosthesis_parts"] == {"knee": "ottobock-3r15", "foot": "proteor-kinterra-26"}


@pytest.mark.parametrize("kwargs, error, match", [
    ({"knee_part": "c-leg"}, swingsim.InputError, "import_osim\\(\\): knee_part: expected a knee"),
    ({"side": "left"}, ValueError, "import_osim\\(\\): side"),
    ({"shank_mass_kg": 0}, ValueError, "import_osim\\(\\): shank_mass_kg: expected a positive value"),
    ({"height_m": "1.8"}, TypeError, "import_osim\\(\\): height_m"),
    ({"knee_friction_Nm": -1}, ValueError, "import_osim\\(\\): knee_friction_Nm: expected a moment >= 0 N m"),
    ({"name": 5}, TypeError, "import_osim\\(\\): name"),
])
def test_import_osim_arguments(repo, kwargs, error, match):
    with pytest.raises(error, match=match):
        swingsim.import_osim(repo / OSIM, **kwargs)


def test_export_osim_equals_cli(repo, cli, tmp_path):
    subprocess.run([cli, "export-osim", "participants/p1.yaml", "--lowering", "0.02", "--out", str(tmp_path)], cwd=repo,
                   check=True, capture_output=True)
    (written,) = tmp_path.glob("*.osim")
    mine = tmp_path / "mine.osim"
    assert swingsim.export_osim(repo / "participants" / "p1.yaml", mine, lowering_m=0.02) == str(mine)
    assert mine.read_text() == written.read_text()


def test_export_osim_left_leg_with_an_added_mass_equals_cli(repo, cli, tmp_path):
    subprocess.run([cli, "export-osim", "participants/p1.yaml", "--side", "l", "--add-mass", "0.5@0.2", "--out",
                    str(tmp_path)], cwd=repo, check=True, capture_output=True)
    (written,) = tmp_path.glob("*.osim")
    mine = tmp_path / "mine.osim"
    swingsim.export_osim(repo / "participants" / "p1.yaml", mine, side="l", added_mass_kg=0.5,
                         added_mass_below_knee_m=0.2)
    assert mine.read_text() == written.read_text()
    assert 'name="knee_angle_l"' in mine.read_text() and 'name="added_mass_l"' in mine.read_text()


def test_export_osim_of_an_edited_participant(repo, tmp_path):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.segments.shank.mass_kg = 1.25
    swingsim.export_osim(p, tmp_path / "edited.osim")
    assert '<mass>1.25</mass>' in (tmp_path / "edited.osim").read_text()


def test_export_osim_refuses_to_write_over_its_input(repo, tmp_path):
    (tmp_path / "p1.yaml").write_text((repo / "participants" / "p1.yaml").read_text().replace(
        "../models/", str(repo / "models") + "/"))
    with pytest.raises(swingsim.InputError, match="p1.yaml"):
        swingsim.export_osim(tmp_path / "p1.yaml", tmp_path / "p1.yaml")
    assert "name: P1" in (tmp_path / "p1.yaml").read_text()
    edited = swingsim.load_participant(tmp_path / "p1.yaml")
    edited.segments.shank.mass_kg = 1.0
    with pytest.raises(swingsim.InputError, match="p1.yaml"):
        swingsim.export_osim(edited, tmp_path / "p1.yaml")  # an object's origin is an input too
    assert "name: P1" in (tmp_path / "p1.yaml").read_text()


@pytest.mark.parametrize("kwargs, error, match", [
    ({"lowering_m": "0"}, TypeError, "export_osim\\(\\): lowering_m"),
    ({"lowering_m": float("inf")}, ValueError, "export_osim\\(\\): lowering_m"),
    ({"participant": 3}, TypeError, "export_osim\\(\\): participant"),
    ({"path": None}, TypeError, "export_osim\\(\\): path"),
    ({"side": "x"}, ValueError, "export_osim\\(\\): side"),
    ({"added_mass_kg": 0.5}, TypeError, "both or neither"),
    ({"added_mass_kg": -0.5, "added_mass_below_knee_m": 0.2}, ValueError, "export_osim\\(\\): added_mass_kg"),
    ({"added_mass_kg": 0.5, "added_mass_below_knee_m": 2.0}, swingsim.InputError, ""),
])
def test_export_osim_arguments(repo, tmp_path, kwargs, error, match):
    args = {"participant": repo / "participants" / "p1.yaml", "path": tmp_path / "x.osim"}
    args.update(kwargs)
    with pytest.raises(error, match=match):
        swingsim.export_osim(**args)
    assert not (tmp_path / "x.osim").exists()
