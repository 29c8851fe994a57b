"""swingsim.sweep(..., out=DIR) writes the command's report, CSV and figures, as
`swingsim sweep --out DIR` does, and refuses to write over an input."""
import json
import subprocess

import pytest

import swingsim

STUDY = """kind: knee-axis-sweep
name: small
participants:
  - {participant}
lowering:
  step_m: 0.05
  max_m: 0.10
"""


def test_out_writes_the_report_the_cli_writes(repo, cli, tmp_path):
    study = tmp_path / "small.yaml"
    study.write_text(STUDY.format(participant=repo / "participants" / "p1.yaml"))
    result = swingsim.sweep(study, out=tmp_path / "py")
    subprocess.run([cli, "sweep", str(study), "--out", str(tmp_path / "cli"), "--json", str(tmp_path / "cli.json")],
                   check=True, capture_output=True)
    assert result == json.loads((tmp_path / "cli.json").read_text())
    written = sorted(p.relative_to(tmp_path / "py").as_posix() for p in (tmp_path / "py").rglob("*"))
    expected = sorted(p.relative_to(tmp_path / "cli").as_posix() for p in (tmp_path / "cli").rglob("*"))
    assert written == expected
    assert "report.md" in written and any(name.endswith(".svg") for name in written)
    assert (tmp_path / "py" / "sweep.csv").read_text() == (tmp_path / "cli" / "sweep.csv").read_text()


def test_out_refuses_to_replace_an_input(repo, tmp_path):
    study = tmp_path / "report.md"  # the study file where the report would go
    study.write_text(STUDY.format(participant=repo / "participants" / "p1.yaml"))
    with pytest.raises(swingsim.InputError, match="report.md"):
        swingsim.sweep(study, out=tmp_path)
    assert study.read_text().startswith("kind: knee-axis-sweep")


def test_out_type_is_checked(repo):
    with pytest.raises(TypeError, match="sweep\\(\\): out"):
        swingsim.sweep(repo / "studies" / "burkett2004.yaml", out=3)
