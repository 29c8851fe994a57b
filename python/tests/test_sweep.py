"""swingsim.sweep against the command line's `sweep --json` for a small study."""
import json
import subprocess

import pytest

import swingsim



@pytest.fixture(scope="module")
def small_study(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("study")
    study = folder / "small.yaml"
    study.write_text(f"""kind: knee-axis-sweep
name: small
participants:
  - {repo / 'participants' / 'p1.yaml'}
  - {repo / 'participants' / 'p3.yaml'}
lowering:
  step_m: 0.05
  max_m: 0.10
""")
    return study


def test_sweep_equals_cli(cli, small_study, tmp_path):
    out = tmp_path / "sweep.json"
    subprocess.run([cli, "sweep", str(small_study), "--json", str(out), "--out", str(tmp_path / "report")],
                   check=True, capture_output=True)
    expected = json.loads(out.read_text())
    result = swingsim.sweep(small_study)
    fastest = {p["name"]: p["best_lowering_m"] for p in result["participants"]}
    assert fastest == {p["name"]: p["best_lowering_m"] for p in expected["participants"]}
    assert len(fastest) == 2
    assert all(lowering is not None for lowering in fastest.values())  # each swept to an optimum
    # Everything else too: the same JSON document, number for number (None for null).
    assert result == expected

def test_sweep_rejects_negative_uncertainty(small_study):
    with pytest.raises(swingsim.InputError, match="uncertainty"):
        swingsim.sweep(small_study, uncertainty=-1)
