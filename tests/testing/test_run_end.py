"""A deterministic run that ends because the last program left ends at the same step however
the threads are scheduled (grading the same case twice, anywhere, must give the same result)."""

from support.scenes import arena

from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation as Engine
from eyesim.net.session import Session


class NoConnection:
    def send(self, data: bytes) -> None:
        pass

    def close(self) -> None:
        pass

    def resume(self) -> None:
        pass


def test_no_step_is_taken_after_the_last_program_leaves():
    engine = Engine(arena(), Clock(DETERMINISTIC))
    session = Session(NoConnection(), robot=engine.robots[0])
    engine.sessions.append(session)
    engine.stop_when_programs_done = True
    # The end is already known when the round starts (the program left while the simulation
    # thread was busy): the run must stop where it is, as when the end arrives while the loop
    # waits for the program.
    engine.call(lambda sim: sim.drop_session(session))
    engine.run(until=1.0)
    assert engine.time_us == 0
