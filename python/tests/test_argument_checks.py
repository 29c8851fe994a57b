"""Python's arguments are checked as the command line's are, against the same ranges
(src/study/run_arguments.h): a wrong type is a TypeError and a wrong value a ValueError
(swingsim.InputError), each naming the function and the argument, before any work."""
import os
import signal
import subprocess
import sys
import threading

import numpy as np
import pytest

import swingsim

MAX_SAMPLES = 100000  # kMaxUncertaintySamples


@pytest.fixture(scope="module")
def small_study(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    study = folder / "small.yaml"
    study.write_text(f"""kind: knee-axis-sweep
name: small
participants:
  - {repo / 'participants' / 'p1.yaml'}
lowering:
  step_m: 0.05
  max_m: 0.05
""")
    return study


# --- sweep(): counts, seeds and jobs --------------------------------------------------------

def test_huge_sample_count_is_refused_before_any_work(small_study):
    # Was: every sample's draws allocated up front (15 GB), Ctrl-C ignored.
    with pytest.raises(swingsim.InputError) as error:
        swingsim.sweep(small_study, uncertainty=10**9)
    assert str(error.value) == ("sweep(): uncertainty: expected 0 (none) or a whole number of samples "
                                f"from 1 to {MAX_SAMPLES}, got 1000000000")


def test_sample_count_beyond_a_long_long_is_a_value_error(small_study):
    with pytest.raises(swingsim.InputError, match=r"sweep\(\): uncertainty: .*, got 1" + "0" * 30):
        swingsim.sweep(small_study, uncertainty=10**30)


def test_negative_seed_is_refused_not_wrapped(small_study):
    # Was: -1 became the seed 18446744073709551615.
    with pytest.raises(swingsim.InputError) as error:
        swingsim.sweep(small_study, uncertainty=2, seed=-1)
    assert str(error.value) == "sweep(): seed: expected a seed from 0 to 1000000000, got -1"
    assert isinstance(error.value, ValueError)


@pytest.mark.parametrize("keyword, value, shown", [
    ("uncertainty", 2.5, "float 2.5"),   # was: 2 samples
    ("uncertainty", 2.0, "float 2.0"),
    ("uncertainty", True, "bool True"),  # bool is not an int
    ("uncertainty", "5", "str '5'"),
    ("seed", 2.5, "float 2.5"),
    ("seed", np.bool_(True), "numpy.bool_ True"),
    ("jobs", 1.0, "float 1.0"),
    ("jobs", None, "None"),
    ("jobs", np.array([1, 2]), "numpy.ndarray of shape (2,)"),
])
def test_non_integers_are_type_errors_naming_the_argument(small_study, keyword, value, shown):
    with pytest.raises(TypeError) as error:
        swingsim.sweep(small_study, **{keyword: value})
    assert str(error.value) == f"sweep(): {keyword}: expected an integer, got {shown}"


def test_seed_with_nothing_to_seed_is_refused_as_on_the_command_line(small_study):
    # Was: ignored.
    with pytest.raises(swingsim.InputError) as error:
        swingsim.sweep(small_study, seed=3)
    assert str(error.value) == ("sweep(): seed: sets the seed of the uncertainty analysis, which needs uncertainty=N "
                                f"or an `uncertainty:` map in {small_study} (got seed=3 alone)")


def test_negative_jobs_are_refused(small_study):
    # Was: run.
    with pytest.raises(swingsim.InputError) as error:
        swingsim.sweep(small_study, jobs=-3)
    assert str(error.value) == "sweep(): jobs: expected 0 (all cores) or a positive whole number, got -3"


def test_numpy_integer_scalars_are_integers(small_study):
    plain = swingsim.sweep(small_study, jobs=1)
    assert swingsim.sweep(small_study, jobs=np.int64(1), uncertainty=np.int32(0)) == plain


@pytest.mark.parametrize("function", ["sweep", "fit", "compare"])  # diagnose: test_diagnose_objects.py
def test_study_path_of_another_type_is_named(function):
    with pytest.raises(TypeError) as error:
        getattr(swingsim, function)(3)
    assert str(error.value) == f"{function}(): study_path: expected a path (str or os.PathLike), got int 3"


# --- simulate(): participant, knee, lowering -----------------------------------------------

@pytest.mark.parametrize("value, shown", [(3, "int 3"), (None, "None"), ({"name": "P1"}, "dict {'name': 'P1'}")])
def test_participant_that_is_not_one_is_a_type_error(value, shown):
    # Was: AttributeError: ... has no attribute 'origin'.
    with pytest.raises(TypeError) as error:
        swingsim.simulate(value)
    assert str(error.value) == f"simulate(): participant: expected a path or a swingsim.Participant, got {shown}"


def test_knee_model_given_as_participant_is_a_type_error(repo):
    knee = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    with pytest.raises(TypeError, match=r"^simulate\(\): participant: expected a path or a swingsim.Participant, "
                                        r"got swingsim.KneeModel"):
        swingsim.simulate(knee)


def test_knee_of_another_type_is_named(repo):
    with pytest.raises(TypeError) as error:
        swingsim.simulate(repo / "participants" / "p1.yaml", knee=7)
    assert str(error.value) == ("simulate(): knee: expected None (the participant's), a path or a swingsim.KneeModel, "
                                "got int 7")


@pytest.mark.parametrize("value, shown", [
    (np.array([0.0, 0.05]), "numpy.ndarray of shape (2,)"),  # was: a TypeError naming no argument
    ("0.05", "str '0.05'"),
    (True, "bool True"),
    (None, "None"),
])
def test_lowering_of_another_type_is_named(repo, value, shown):
    with pytest.raises(TypeError) as error:
        swingsim.simulate(repo / "participants" / "p1.yaml", lowering_m=value)
    assert str(error.value) == f"simulate(): lowering_m: expected a number, got {shown}"


def test_non_finite_lowering_is_a_value_error(repo):
    with pytest.raises(swingsim.InputError) as error:
        swingsim.simulate(repo / "participants" / "p1.yaml", lowering_m=float("nan"))
    assert str(error.value) == "simulate(): lowering_m: expected a number, got nan"


def test_numpy_number_scalars_are_numbers(repo):
    p1 = repo / "participants" / "p1.yaml"
    plain = swingsim.simulate(p1, lowering_m=0.05)
    assert swingsim.simulate(p1, lowering_m=np.float64(0.05)).json == plain.json
    assert swingsim.simulate(p1, lowering_m=np.float32(0.0)).json == swingsim.simulate(p1, lowering_m=0).json


def test_one_dimensional_numpy_arrays_are_lists(repo):
    p1 = repo / "participants" / "p1.yaml"
    knee = swingsim.load_knee(repo / "models" / "damping-table-default.yaml")
    plain = swingsim.simulate(p1, knee=knee)
    knee.damping_table.moment_Nm = np.array(knee.damping_table.moment_Nm)
    assert swingsim.simulate(p1, knee=knee).json == plain.json
    knee.damping_table.moment_Nm = np.ones((2, 4))
    with pytest.raises(swingsim.InputError, match=r"knee model\.damping_table\.moment_Nm: expected a number or a "
                                                   r"1-D array of numbers, found a numpy.ndarray of shape \(2, 4\)"):
        swingsim.simulate(p1, knee=knee)


def test_load_path_of_another_type_is_named():
    with pytest.raises(TypeError, match=r"^load_participant\(\): path: expected a path"):
        swingsim.load_participant(None)
    with pytest.raises(TypeError, match=r"^load_knee\(\): path: expected a path"):
        swingsim.load_knee(1.5)


# --- the same limit as the command line -----------------------------------------------------

def test_cli_and_python_refuse_the_same_sample_count_with_the_same_limit(cli, small_study, tmp_path):
    limit = f"a whole number of samples from 1 to {MAX_SAMPLES}"
    run = subprocess.run([cli, "sweep", str(small_study), "--uncertainty", str(MAX_SAMPLES + 1),
                          "--out", str(tmp_path / "out")], capture_output=True, text=True)
    assert run.returncode != 0
    assert f"--uncertainty: expected {limit} (got '{MAX_SAMPLES + 1}')" in run.stderr
    with pytest.raises(swingsim.InputError, match=f"sweep\\(\\): uncertainty: .*{limit}, got {MAX_SAMPLES + 1}"):
        swingsim.sweep(small_study, uncertainty=MAX_SAMPLES + 1)
    # The limit itself passes both checks: the error is then the study file's, not the count's.
    missing = tmp_path / "missing.yaml"
    run = subprocess.run([cli, "sweep", str(missing), "--uncertainty", str(MAX_SAMPLES)], capture_output=True, text=True)
    assert "--uncertainty" not in run.stderr and str(missing) in run.stderr
    with pytest.raises(swingsim.InputError) as error:
        swingsim.sweep(missing, uncertainty=MAX_SAMPLES)
    assert "uncertainty" not in str(error.value) and str(missing) in str(error.value)


def test_cli_and_python_refuse_the_same_seed(cli, small_study, tmp_path):
    run = subprocess.run([cli, "sweep", str(small_study), "--uncertainty", "2", "--seed", "1000000001",
                          "--out", str(tmp_path / "out")], capture_output=True, text=True)
    assert "--seed: expected a seed from 0 to 1000000000 (got '1000000001')" in run.stderr
    with pytest.raises(swingsim.InputError, match=r"sweep\(\): seed: expected a seed from 0 to 1000000000, got 1000000001"):
        swingsim.sweep(small_study, uncertainty=2, seed=1000000001)


# --- Ctrl-C ---------------------------------------------------------------------------------

def interrupted_inside(call):
    """Runs call() with SIGINT sent once it runs in C++: the helper thread cannot take the GIL
    before the call releases it (the switch interval is made longer than any test), so the
    signal arrives inside the call and only its own poll can raise KeyboardInterrupt.
    Returns whether it raised KeyboardInterrupt."""
    go = threading.Event()

    def interrupt():
        go.wait()
        os.kill(os.getpid(), signal.SIGINT)

    helper = threading.Thread(target=interrupt)
    interval = sys.getswitchinterval()
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    helper.start()
    sys.setswitchinterval(1000.0)
    try:
        go.set()
        call()
    except KeyboardInterrupt:
        return True
    finally:
        sys.setswitchinterval(interval)
        helper.join()
        signal.signal(signal.SIGINT, previous)
    return False


def test_ctrl_c_during_an_uncertainty_sweep_raises_keyboard_interrupt(small_study, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # 5000 samples would run for hours if the poll missed the signal.
    assert interrupted_inside(lambda: swingsim.sweep(small_study, uncertainty=5000, jobs=1))
    assert list(tmp_path.iterdir()) == []  # nothing written, half or whole


def test_ctrl_c_during_a_diagnosis_raises_keyboard_interrupt(repo, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert interrupted_inside(lambda: swingsim.diagnose(repo / "studies" / "diagnose-demo-cylinder.yaml"))
    assert list(tmp_path.iterdir()) == []


def test_diagnose_is_held_to_a_row_limit_as_on_the_command_line(repo):
    # The swing demo has 828 rows of measured data: refused below that, before any fit.
    with pytest.raises(swingsim.InputError, match="--max-rows|max_rows|rows"):
        swingsim.diagnose(repo / "studies" / "diagnose-demo-swing.yaml", max_rows=100)
    with pytest.raises(TypeError, match=r"diagnose\(\): max_rows"):
        swingsim.diagnose(repo / "studies" / "diagnose-demo-swing.yaml", max_rows=2.5)
    with pytest.raises(swingsim.InputError, match=r"diagnose\(\): max_rows"):
        swingsim.diagnose(repo / "studies" / "diagnose-demo-swing.yaml", max_rows=0)


def test_a_list_that_contains_itself_is_refused_not_a_crash(repo):
    # Issue 57: the YAML emitter recursed without bound and crashed the interpreter.
    p = swingsim.load_participant(repo / "participants" / "p1.yaml")
    loop = [1.0]
    loop.append(loop)
    p["notes"] = loop
    with pytest.raises(ValueError, match="levels of lists and mappings"):
        swingsim.simulate(p)
