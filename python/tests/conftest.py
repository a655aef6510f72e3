"""Shared set-up: where the program, the scenes and the built package are.

CTest runs this suite with PYTHONPATH=<build>/python, RATTLEBACK_BIN (the command-line program
to compare against) and RATTLEBACK_SOURCE_DIR set (tests/CMakeLists.txt).
"""

import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("RATTLEBACK_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BIN = os.environ.get("RATTLEBACK_BIN", str(SOURCE / "build" / "app" / "rattleback"))


def scene_path(name: str) -> str:
    return str(SOURCE / "scenes" / name)


def cli(*args: str, cwd=None, check=True) -> subprocess.CompletedProcess:
    """Runs the command-line program; its output as text."""
    result = subprocess.run([BIN, *args], capture_output=True, text=True, cwd=cwd)
    if check and result.returncode != 0:
        raise AssertionError(f"rattleback {' '.join(args)} exited {result.returncode}: " f"{result.stderr}")
    return result


@pytest.fixture
def default_scene() -> str:
    return scene_path("rattleback.yaml")
