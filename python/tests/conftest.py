"""Shared set-up of the swingsim pytest suite: run from the repository root (CTest does),
with PYTHONPATH=build/python and SWINGSIM_BINARY the built command line."""
import os
import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def cli():
    """The built `swingsim` command line, to compare the module with."""
    binary = os.environ.get("SWINGSIM_BINARY", str(REPO / "build" / "swingsim"))
    if not os.path.exists(binary):
        pytest.fail(f"SWINGSIM_BINARY: no swingsim command line at {binary} (build the swingsim target)")
    return binary
