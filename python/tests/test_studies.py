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
