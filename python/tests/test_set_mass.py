"""Participant.set_mass: the radius of gyration kept (as import-osim --shank-mass-kg) or the
inertia kept."""
import pytest

import swingsim

OSIM = "studies/data/opensim-subject01/gait2354_subject01_simbody.osim"


def test_keep_radius_of_gyration_scales_inertia_with_mass(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    shank = p.segments.shank
    k2 = shank.inertia_kgm2 / shank.mass_kg  # squared radius of gyration, m^2
    p.set_mass("shank", 1.5)
    assert p.segments.shank.mass_kg == 1.5
    assert p.segments.shank.inertia_kgm2 / 1.5 == pytest.approx(k2, rel=1e-15)
    assert p.segments.shank.com_from_distal_m == 0.260  # COM kept


def test_keep_inertia_leaves_it(repo):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.set_mass("foot", 2.0, keep="inertia")
    assert p.segments.foot.mass_kg == 2.0
    assert p.segments.foot.inertia_kgm2 == 0.0059


def test_matches_import_osim_shank_mass(repo):
    # import-osim --shank-mass-kg keeps the radius of gyration: the same numbers as
    # importing the tibia's mass and setting it afterwards.
    plain = swingsim.import_osim(repo / OSIM, name="s01")
    plain.set_mass("shank", 1.2)
    direct = swingsim.import_osim(repo / OSIM, name="s01", shank_mass_kg=1.2)
    assert plain.segments.shank.mass_kg == direct.segments.shank.mass_kg
    assert plain.segments.shank.inertia_kgm2 == pytest.approx(direct.segments.shank.inertia_kgm2, rel=1e-12)


def test_the_heavier_shank_swings_differently_by_keep(repo):
    # keep decides the physics: the same mass with the inertia kept or scaled gives two swings.
    rog = swingsim.load_participant(repo / "participants" / "p1.yaml")
    rog.set_mass("shank", 2.0)
    inertia = swingsim.load_participant(repo / "participants" / "p1.yaml")
    inertia.set_mass("shank", 2.0, keep="inertia")
    assert swingsim.simulate(rog).swing_time_s != swingsim.simulate(inertia).swing_time_s


@pytest.mark.parametrize("args, error, match", [
    (("calf", 1.0), ValueError, "set_mass\\(\\): segment: expected one of"),
    ((1, 1.0), TypeError, "set_mass\\(\\): segment"),
    (("shank", "1"), TypeError, "set_mass\\(\\): kg: expected a number"),
    (("shank", True), TypeError, "set_mass\\(\\): kg"),
    (("shank", -1.0), ValueError, "set_mass\\(\\): kg: expected a positive value"),
    (("shank", float("nan")), ValueError, "set_mass\\(\\): kg"),
    (("shank", 1.0, "mass"), ValueError, "set_mass\\(\\): keep"),
])
def test_arguments_are_checked(repo, args, error, match):
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    before = p.to_dict()
    with pytest.raises(error, match=match):
        p.set_mass(*args)
    assert p.to_dict() == before


def test_a_massless_segment_needs_keep_inertia(repo):
    # Issue 57: set_mass on a 0 kg segment raised ZeroDivisionError.
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    p.segments.foot.mass_kg = 0.0
    with pytest.raises(ValueError, match="set_mass\\(\\): keep: expected 'inertia' \\(the segment's mass is 0.0 kg"):
        p.set_mass("foot", 1.0)
    p.set_mass("foot", 1.0, keep="inertia")
    assert p.segments.foot.mass_kg == 1.0
