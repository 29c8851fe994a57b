"""`pip install --no-build-isolation .` (pyproject.toml, setup.py) into a fresh venv: the
installed package imports outside the source tree and swings P1 exactly as the build's module
does, and the install leaves the source tree unchanged. It reuses the build folder CTest runs
from (SWINGSIM_BINARY's folder), so it compiles nothing new."""
import os
import pathlib
import subprocess
import sys

import swingsim


def git_status(repo):
    return subprocess.run(["git", "status", "--porcelain", "--ignored=no"], cwd=repo, capture_output=True,
                          text=True).stdout


def test_pip_install_into_a_venv_gives_the_same_swing(tmp_path, repo, cli):
    build = pathlib.Path(cli).resolve().parent
    venv = tmp_path / "venv"
    subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)], check=True)
    python = venv / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["SWINGSIM_BUILD_DIR"] = str(build)
    before = git_status(repo)
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index",
                              "--quiet", str(repo)], env=env, capture_output=True, text=True)
    assert install.returncode == 0, install.stdout + install.stderr
    assert git_status(repo) == before, "pip install wrote into the source tree"

    # From another folder, with no PYTHONPATH: the venv's own copy, not the build's.
    p1 = str(repo / "participants" / "p1.yaml")
    probe = ("import swingsim, sys; r = swingsim.simulate(sys.argv[1]); "
             "print(swingsim.__file__); print(repr(r.swing_time_s))")
    out = subprocess.run([str(python), "-c", probe, p1], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    where, swing_time = out.stdout.split("\n")[:2]
    assert pathlib.Path(where).resolve().is_relative_to(venv.resolve()), where
    assert float(swing_time) == swingsim.simulate(p1).swing_time_s
    # The stub is installed beside the package, for editors.
    assert (pathlib.Path(where).parent / "__init__.pyi").exists()
