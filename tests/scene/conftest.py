"""Shared paths for the scene tests; makes the helper module scene_testing importable."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
