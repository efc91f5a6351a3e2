"""Every module of a part kind's folder can be the first one a program imports: the registries
that import the folders (the scene's declarations, the robot builder's factories, the RoBIOS
handlers) never ask a module for what it has not defined yet."""

import subprocess
import sys
from pathlib import Path

import pytest

import eyesim.parts

FOLDERS = Path(eyesim.parts.__file__).parent
MODULES = sorted(
    f"eyesim.parts.{path.parent.name}.{path.stem}" for path in FOLDERS.glob("*/*.py") if path.stem != "__init__"
)


def test_the_folders_have_their_modules():
    assert {"eyesim.parts.psd.declaration", "eyesim.parts.psd.component", "eyesim.parts.psd.calls"} <= set(MODULES)


@pytest.mark.parametrize("module", MODULES)
def test_a_module_of_a_part_folder_imports_first(module):
    result = subprocess.run([sys.executable, "-c", f"import {module}"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
