"""swingsim.sweep: the symmetry lowering beside the fastest, for a participant with a
sound-limb swing time (P1) and not for one without (Winter's)."""
import pytest

import swingsim


@pytest.fixture(scope="module")
def result(repo, tmp_path_factory):
    study = tmp_path_factory.mktemp("symmetry") / "small.yaml"
    study.write_text(f"""kind: knee-axis-sweep
name: small
participants:
  - {repo / 'participants' / 'p1.yaml'}
  - {repo / 'participants' / 'winter.yaml'}
lowering:
  step_m: 0.05
  max_m: 0.10
""")
    return swingsim.sweep(study)


def test_symmetry_beside_the_fastest_for_the_participant_with_a_sound_limb_time(result):
    p1 = next(p for p in result["participants"] if p["name"] == "P1")
    symmetry = p1["symmetry"]
    assert symmetry["sound_limb_swing_time_s"] == pytest.approx(0.499)  # Burkett Table 4, 0 m
    assert 0.0 <= symmetry["lowering_m"] <= 0.10
    # The gap and the ratio say the same thing about the swing time at that lowering.
    prosthetic = symmetry["prosthetic_swing_time_s"]
    assert symmetry["gap_s"] == pytest.approx(prosthetic - 0.499)
    assert symmetry["ratio"] == pytest.approx(prosthetic / 0.499)
    if symmetry["reached"]:
        assert symmetry["gap_s"] == 0
    else:
        # Not reached: the closest swing time of the grid (0, 0.05, 0.10 m; Table 4's 0.15 m
        # is an extra point off the grid), so no grid point is closer.
        times = [t for d, t in zip(p1["lowering_m"], p1["swing_time_s"]) if d <= 0.10 + 1e-9 and t is not None]
        assert len(times) == 3
        assert all(abs(t - 0.499) >= abs(symmetry["gap_s"]) - 1e-12 for t in times)


def test_no_symmetry_without_a_sound_limb_time(result):
    winter = next(p for p in result["participants"] if p["name"] != "P1")
    assert "symmetry" not in winter
    assert winter["best_lowering_m"] is not None
