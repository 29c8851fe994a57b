"""swingsim.compare and swingsim.diagnose against the command line's --json."""
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
