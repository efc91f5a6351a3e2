"""EyeSim: a robot simulator for teaching, running RoBIOS-7 programs against a MuJoCo world."""

__version__ = "0.1.0"
