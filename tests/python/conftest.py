"""Shared fixtures of the Python tests: where the scenarios and the tumble program are.

ctest runs these with PYTHONPATH at the build tree's python/ folder (the freshly built module),
TUMBLE_EXE at the built `tumble` program and TUMBLE_SCENARIO_DIR at scenarios/ (tests/python/
CMakeLists.txt); tests that compare with the CLI are skipped when it was not built.
"""

import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def scenarios():
    return pathlib.Path(os.environ.get("TUMBLE_SCENARIO_DIR", REPO / "scenarios"))


@pytest.fixture(scope="session")
def tumble_cli():
    """Runs the tumble program: cli(*args) -> CompletedProcess (text, not checked)."""
    exe = os.environ.get("TUMBLE_EXE")
    if not exe:
        pytest.skip("TUMBLE_EXE is not set (the tumble program was not built)")

    def run(*args, cwd=None):
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, cwd=cwd)

    return run
