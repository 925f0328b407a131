"""Shared set-up of the Python module's tests: where the repository, the vct binary and
the built module are. ctest sets VCT_SOURCE_DIR, VCT_BINARY and PYTHONPATH; run by hand,
the defaults are this checkout and its build/ directory."""
import os
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.get("VCT_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
BINARY = os.environ.get("VCT_BINARY", os.path.join(SOURCE_DIR, "build", "vct"))
if "PYTHONPATH" not in os.environ:
    sys.path.insert(0, os.path.join(SOURCE_DIR, "build", "python"))


def scene(name):
    return os.path.join(SOURCE_DIR, "scenes", name)


def run_cli(*args):
    """Runs the vct binary; returns (exit code, stderr)."""
    p = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stderr


def cli_error(*args):
    """The message the command line prints for a failing command, without "vct: error: "."""
    code, err = run_cli(*args)
    assert code != 0, err
    lines = [l for l in err.splitlines() if l.startswith("vct: error: ")]
    assert lines, err
    return code, lines[-1][len("vct: error: "):]


@pytest.fixture(scope="module")
def cornell():
    import vct
    return vct.Session(scene("cornell_box.gltf"))
