"""swingsim.simulate against the command line's `simulate --json`, and edits of a loaded
participant changing the swing."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import swingsim

# The module and the CLI call the same functions on the same inputs: results agree to the
# last bit; this allows only for the JSON's shortest round-trip printing of doubles.
EXACT = 1e-12
# A change must exceed the converged integrator's 0.1 ms of swing time (docs/speed.md,
# "Convergence study") tenfold to count as measurable; angles likewise, far above its error.
MEASURABLE_S = 1e-3
MEASURABLE_DEG = 1.0


def run_cli_simulate(cli, tmp_path, participant, *args):
    out = tmp_path / "cli.json"
    subprocess.run([cli, "simulate", str(participant), "--json", str(out), "--out", str(tmp_path / "traj"), *args],
                   check=True, capture_output=True)
    return json.loads(out.read_text())


@pytest.mark.parametrize("lowering", [0.0, 0.05])
def test_simulate_equals_cli(repo, cli, tmp_path, lowering):
    participant = repo / "participants" / "p1.yaml"
    expected = run_cli_simulate(cli, tmp_path, participant, "--lowering", str(lowering))
    result = swingsim.simulate(participant, lowering_m=lowering)
    assert result.swing_time_s == pytest.approx(expected["swing_time_s"], abs=EXACT)
    assert [e["name"] for e in result.events] == [e["name"] for e in expected["events"]]
    for got, want in zip(result.events, expected["events"]):
        assert got["time_s"] == pytest.approx(want["time_s"], abs=EXACT)
    assert result.bounce == expected["bounce"]
    assert result.bounces == expected["bounces"]
    assert result.peak_knee_flexion_deg == pytest.approx(expected["peak_knee_flexion_deg"], abs=EXACT)
    assert result.drive == expected["drive"]


def test_trajectory_equals_cli_csv(repo, cli, tmp_path):
    participant = repo / "participants" / "p2.yaml"
    run_cli_simulate(cli, tmp_path, participant)
    csv = next((tmp_path / "traj").glob("*.csv"))
    table = np.genfromtxt(csv, delimiter=",", names=True)
    result = swingsim.simulate(participant)
    assert isinstance(result.trajectory.time_s, np.ndarray)
    for name in table.dtype.names:
        np.testing.assert_allclose(result.trajectory[name], table[name], rtol=1e-6, atol=1e-9, err_msg=name)


def test_loaded_object_equals_its_file(repo):
    path = repo / "participants" / "p1.yaml"
    participant = swingsim.load_participant(path)
    knee = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    from_path = swingsim.simulate(path)
    from_objects = swingsim.simulate(participant, knee=knee)
    assert from_objects.swing_time_s == from_path.swing_time_s
    assert from_objects.events == from_path.events


def test_fields_read_in_file_units(repo):
    participant = swingsim.load_participant(repo / "participants" / "p1.yaml")
    assert participant.name == "P1"
    assert participant.segments.shank.mass_kg == pytest.approx(0.785)
    assert participant.initial.knee_flexion_deg == pytest.approx(10)
    with pytest.raises(AttributeError, match="mass_kgg"):
        participant.segments.shank.mass_kgg = 1.0


def test_heavier_shank_slows_the_thigh_and_lowers_the_peak(repo):
    # The same hip moment drives a heavier leg: the thigh reaches its target later, and the
    # heavier shank (more inertia about the knee) flexes less.
    participant = swingsim.load_participant(repo / "participants" / "p1.yaml")
    base = swingsim.simulate(participant)
    heavier = participant.copy()
    heavier.segments.shank.mass_kg = 1.5 * participant.segments.shank.mass_kg
    heavier.segments.shank.inertia_kgm2 = 1.5 * participant.segments.shank.inertia_kgm2
    slower = swingsim.simulate(heavier)
    assert participant.segments.shank.mass_kg == pytest.approx(0.785)  # the copy was edited, not the original
    thigh = "thigh_at_target"
    assert slower.events_by_name[thigh] > base.events_by_name[thigh] + MEASURABLE_S
    assert slower.peak_knee_flexion_deg < base.peak_knee_flexion_deg - MEASURABLE_DEG


def test_more_knee_damping_lowers_the_peak_flexion(repo):
    participant = repo / "participants" / "p1.yaml"
    knee = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    base = swingsim.simulate(participant, knee=knee)
    damped = knee.copy()
    damped.damping_table.moment_Nm = [2 * m for m in knee.damping_table.moment_Nm]
    stiffer = swingsim.simulate(participant, knee=damped)
    assert stiffer.peak_knee_flexion_deg < base.peak_knee_flexion_deg - MEASURABLE_DEG


# The child of test_simulate_releases_the_gil: the participant file is a FIFO that only a
# second Python thread writes, and only once the swing's call has opened it. Were the GIL held
# through the call, that thread could never write and the call would wait forever.
GIL_CHILD = r"""
import sys, threading
sys.path[:0] = [sys.argv[3]]
import swingsim
fifo, text = sys.argv[1], open(sys.argv[2]).read()
def feed():
    with open(fifo, "w") as f:  # returns once the call has opened the FIFO to read it
        f.write(text)           # needs the GIL while the call is still in progress
threading.Thread(target=feed).start()
print(swingsim._swingsim.simulate(fifo, 0.0, None)["swing_time_s"])
"""


def test_simulate_releases_the_gil(repo, tmp_path):
    # Scheduler-independent: the call can only finish if another Python thread runs while it
    # is in progress. A hang (the GIL held) is caught by a timeout far above the second the
    # child needs on a loaded machine; no duration is asserted.
    participant = repo / "participants" / "p1.yaml"
    text = participant.read_text().replace("../models/", str(repo / "models") + "/")
    source = tmp_path / "p1.yaml"
    source.write_text(text)
    fifo = tmp_path / "p1-fifo.yaml"
    os.mkfifo(fifo)
    try:
        child = subprocess.run([sys.executable, "-c", GIL_CHILD, str(fifo), str(source), os.path.dirname(swingsim.__path__[0])],
                               capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        pytest.fail("simulate held the GIL: the thread that feeds its participant file never ran (5 min)")
    assert child.returncode == 0, child.stderr
    assert float(child.stdout) == pytest.approx(swingsim.simulate(str(source)).swing_time_s, abs=EXACT)


@pytest.mark.parametrize("options,cli_args", [
    ({"added_mass_kg": 0.5, "added_mass_below_knee_m": 0.2}, ["--add-mass", "0.5@0.2"]),
    ({"integrator": "runge-kutta-merson", "accuracy": 1e-6}, ["--integrator", "runge-kutta-merson", "--accuracy", "1e-6"]),
    ({"integrator": "runge-kutta-feldberg"}, ["--integrator", "runge-kutta-feldberg"]),
])
def test_simulate_options_equal_cli(repo, cli, tmp_path, options, cli_args):
    """simulate's added mass, integrator and accuracy arguments as the command line's options."""
    participant = repo / "participants" / "p1.yaml"
    expected = run_cli_simulate(cli, tmp_path, participant, "--lowering", "0.05", *cli_args)
    plain = swingsim.simulate(participant, lowering_m=0.05)
    result = swingsim.simulate(participant, lowering_m=0.05, **options)
    assert result.swing_time_s == pytest.approx(expected["swing_time_s"], abs=EXACT)
    assert result.peak_knee_flexion_deg == pytest.approx(expected["peak_knee_flexion_deg"], abs=EXACT)
    if "added_mass_kg" in options:  # the mass is felt, far above the integrator's error
        assert abs(result.swing_time_s - plain.swing_time_s) > MEASURABLE_S


def test_simulate_option_errors_name_the_argument(repo):
    participant = repo / "participants" / "p1.yaml"
    with pytest.raises(TypeError, match="added_mass_kg and added_mass_below_knee_m: give both or neither"):
        swingsim.simulate(participant, added_mass_kg=0.5)
    with pytest.raises(swingsim.InputError, match=r"simulate\(\): added_mass_kg"):
        swingsim.simulate(participant, added_mass_kg=-1, added_mass_below_knee_m=0.2)
    with pytest.raises(swingsim.InputError, match=r"simulate\(\): integrator"):
        swingsim.simulate(participant, integrator="euler")
    with pytest.raises(swingsim.InputError, match=r"simulate\(\): accuracy"):
        swingsim.simulate(participant, accuracy=0.5)
