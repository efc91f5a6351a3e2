"""Where the shared corpus of real EyeSim files is: ../shared/corpus beside the checkout (CI puts
shared/ there; the files are never copied into the project)."""

from pathlib import Path

CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
