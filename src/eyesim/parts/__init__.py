"""Part kinds that live in one folder each: `parts/<kind>/` holds the part's declaration (what a
robot file says about it: keywords, spec, schema; `declaration.py`, on the scene's layer) and its
component (what it does in the simulation: `component.py`, on the robot's layer). The folder is
registered with one line in `scene/parts/__init__.py`; the declaration names its component."""
