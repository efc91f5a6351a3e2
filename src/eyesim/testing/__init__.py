"""Testing and grading robot programs from Python: `Simulation` (docs/testing.md), the pytest
plugin (`pytest_plugin`), and the checks both use (`assertions`)."""

from eyesim.testing.simulation import CompileError, RunEnd, Simulation, SimulationError, compile_program

__all__ = ["Simulation", "SimulationError", "CompileError", "RunEnd", "compile_program"]
