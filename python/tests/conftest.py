"""Shared by hlrdraw's tests: where the sources and the hlr program are, and running hlr.

ctest sets HLR_SOURCE_DIR, HLRDRAW_HLR (the build's hlr) and PYTHONPATH (the build's hlrdraw); run
by hand, the tests take the checkout this file is in and its build/ folder.
"""
import os
import subprocess
import sys

import pytest

SOURCE_DIR = os.environ.get("HLR_SOURCE_DIR") or os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HLR = os.environ.get("HLRDRAW_HLR") or os.path.join(SOURCE_DIR, "build", "app", "hlr")
if "HLRDRAW_HLR" not in os.environ:
    # By hand: this checkout's build, for this process and the ones it starts (hlrdraw.batch).
    os.environ["HLRDRAW_HLR"] = HLR
    module = os.path.join(SOURCE_DIR, "build", "python")
    sys.path.insert(0, module)
    os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, [module, os.environ.get("PYTHONPATH")]))

SCENES = os.path.join(SOURCE_DIR, "fixtures", "scenes")
PARTS = os.path.join(SOURCE_DIR, "fixtures", "parts")
CLIP = os.path.join(SOURCE_DIR, "fixtures", "clip")
CLI_PARTS = os.path.join(SOURCE_DIR, "tests", "cli", "parts")


class Run:
    def __init__(self, completed):
        self.code = completed.returncode
        self.out = completed.stdout
        self.err = completed.stderr

    @property
    def error(self):
        """The one-line error without its "hlr: " (what hlrdraw.Error says)."""
        lines = self.err.strip().splitlines()
        assert len(lines) == 1, self.err
        assert lines[0].startswith("hlr: "), self.err
        return lines[0][len("hlr: "):]


def run_hlr(*args, cwd=None):
    return Run(subprocess.run([HLR, *map(str, args)], capture_output=True, text=True, cwd=cwd))


@pytest.fixture
def hlr():
    return run_hlr
