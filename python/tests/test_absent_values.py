"""A quantity a swing did not have is None, never a marker number; a knee folded past 180 deg
is a failed run (swingsim.RunError), as on the command line."""
import subprocess

import pytest

import swingsim


def winter_without_a_knee_peak(repo):
    # A zone of stability above anything the walking knee reaches: it never peaks above it.
    participant = swingsim.load_participant(repo / "participants" / "winter.yaml")
    participant.swing_end.zone_of_stability_deg = 150.0
    return participant


def test_no_knee_peak_is_none(repo):
    result = swingsim.simulate(winter_without_a_knee_peak(repo))
    assert result.trial_end["unmet"] == "knee_peak"
    assert result.swing_time_s is None
    assert result.peak_knee_flexion_deg is None
    assert result.peak_knee_flexion_time_s is None
    assert result.bounce_height_deg is None
    assert result.min_toe_clearance_m is None
    assert result.trial_end["settle_dwell_done_s"] is None
    assert result.json["peak_knee_flexion_deg"] is None


def test_ended_swing_has_its_numbers(repo):
    result = swingsim.simulate(repo / "participants" / "p1.yaml")
    assert result.peak_knee_flexion_deg > 0
    assert 0 < result.peak_knee_flexion_time_s < result.swing_time_s
    assert result.min_toe_clearance_m is not None


def test_knee_past_180_deg_is_a_run_error(repo, cli, tmp_path):
    participant = swingsim.load_participant(repo / "participants" / "winter.yaml")
    participant.initial.knee_flexion_rate_deg_s = 3000.0  # far faster than any swing's
    participant.initial["knee_start"] = "initial"  # from these values, not the record's knee at toe-off
    with pytest.raises(swingsim.RunError, match=r"the knee flexion passed 180 deg at \d+(\.\d+)? s") as error:
        swingsim.simulate(participant)
    # the same message as the command line prints, with a non-zero exit
    cli_run = subprocess.run([cli, "simulate", str(repo / "participants" / "winter.yaml"), "--knee-start", "initial", "--knee-rate-deg-s", "3000",
                              "--out", str(tmp_path / "out")], capture_output=True, text=True)
    assert cli_run.returncode != 0
    assert str(error.value) in cli_run.stderr
