"""EyeSim: a robot simulator for teaching, running RoBIOS-7 programs against a MuJoCo world.

`eyesim.Simulation` is the Python API for tests and grading (eyesim/testing, docs/testing.md);
the engine inside it is `eyesim.core.engine.Simulation`."""

__version__ = "0.1.0"


def __getattr__(name: str):
    # Imported on first use, so `eyesim run` and `eyesim cc` do not load the testing layer.
    if name in ("Simulation", "SimulationError", "CompileError"):
        import eyesim.testing

        return getattr(eyesim.testing, name)
    raise AttributeError(f"module 'eyesim' has no attribute {name!r}")
