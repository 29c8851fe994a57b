"""Bad input raises swingsim.InputError with the command line's file:line message."""
import subprocess

import pytest

import swingsim


def test_input_error_is_a_value_error():
    assert issubclass(swingsim.InputError, ValueError)
    assert issubclass(swingsim.RunError, RuntimeError)


def test_bad_yaml_names_file_and_line(repo, cli, tmp_path):
    lines = (repo / "participants" / "p1.yaml").read_text().splitlines()
    bad_line = next(i for i, line in enumerate(lines) if line.startswith("height_m:"))
    lines[bad_line] = "height_m: tall"
    bad = tmp_path / "bad.yaml"
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(swingsim.InputError) as error:
        swingsim.load_participant(bad)
    message = str(error.value)
    assert message.startswith(f"{bad}:{bad_line + 1}:")
    assert "height_m" in message
    # the same message as the command line prints
    cli_run = subprocess.run([cli, "simulate", str(bad), "--out", str(tmp_path / "out")], capture_output=True, text=True)
    assert cli_run.returncode != 0
    assert message in cli_run.stderr
    with pytest.raises(swingsim.InputError, match=f"{bad}:{bad_line + 1}:"):
        swingsim.simulate(bad)


def test_bad_edit_names_the_key(repo):
    participant = swingsim.load_participant(repo / "participants" / "p1.yaml")
    participant.segments.shank.mass_kg = -1.0
    with pytest.raises(swingsim.InputError, match=r"edited in Python.*mass_kg"):
        swingsim.simulate(participant)


def test_missing_file(tmp_path):
    with pytest.raises(swingsim.InputError, match="missing.yaml"):
        swingsim.simulate(tmp_path / "missing.yaml")
