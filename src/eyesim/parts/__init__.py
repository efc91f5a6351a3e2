"""Part kinds that live in one folder each: `parts/<kind>/` holds the part's declaration (what a
robot file says about it: keywords, spec, schema; `declaration.py`, on the scene's layer), its
component (what it does in the simulation: `component.py`, on the robot's layer) and, when it has
a RoBIOS group of its own, that group's handlers (`calls.py`, on the handlers' layer). The folder
is registered with one line in `scene/parts/__init__.py`; the declaration names its component and
the handlers are found by the RoBIOS registry (`eyesim.calls`). `part.py` is what every
declaration declares.

The scene package is imported first: its registry imports every declaration, so a declaration
imported before it would be asked for its PART while it is still being read."""

import eyesim.scene  # noqa: F401
