"""Python callables as robot programs, for in-process tests: the callable runs in a thread of the
test process and drives its robot through a `RobotClient`, a small blocking client of the
simulator's program port speaking the same protocol as libeyesim.

    def drive(robot):
        robot.VWSetSpeed(200, 0)
        robot.OSWait(1000)
        return robot.PSDGet(2)

RoBIOS functions are called by their C names (`VWSetSpeed`) or by protocol op names
(`robot.call("VW_SET_SPEED", 200, 0)`); arguments and replies follow interface/protocol.json
(one value comes back as itself, several as a tuple). `token`: the run's program token
(the engine's `program_token`), sent in the HELLO."""

from __future__ import annotations

import threading
import traceback
from dataclasses import dataclass, field

from eyesim.protocol import generated as g
from eyesim.protocol.client import ProtocolClient, RemoteError

_BY_FOLDED_NAME = {name.replace("_", ""): name for name in g.OPS_BY_NAME}


class RoBIOSError(Exception):
    """The simulator refused a call (the error libeyesim would report)."""

    def __init__(self, op: str, code: int, message: str):
        super().__init__(f"{op}: {message} (error {code})")
        self.code = code


class RobotClient:
    """A program's connection, called like the API: `client.vw_set_speed(100, 0)` or
    `client.call("VW_SET_SPEED", 100, 0)`; a reply of one value is that value."""

    def __init__(
        self, host: str, port: int, robot: int | str, program: str = "python-callable", token: str | None = None
    ):
        self._connection = ProtocolClient(port, host)
        self._lock = threading.Lock()
        _, self.robot_id, self.robot_name = self.call("HELLO", g.VERSION, str(robot), program, 0, token or "")

    def call(self, op_name: str, *args):
        with self._lock:
            try:
                values = self._connection.call(op_name, *args)
            except RemoteError as error:
                raise RoBIOSError(op_name, error.code, error.message) from None
        return values[0] if len(values) == 1 else values

    def __getattr__(self, name: str):
        op_name = _BY_FOLDED_NAME.get(name.upper().replace("_", ""))
        if op_name is None:
            raise AttributeError(f"no RoBIOS function {name!r}")
        return lambda *args: self.call(op_name, *args)

    def close(self) -> None:
        self._connection.close()


@dataclass
class CallableRun:
    """A Python callable driving a robot; shaped like launcher.ProgramRun so results read alike.
    `value` is what the callable returned; an exception it raised is `error` (traceback in stderr)."""

    robot_id: int
    function: object
    exit_code: int | None = None
    error: str | None = None
    value: object = None
    stopped_by_us: bool = False
    truncated: bool = False
    output: dict = field(default_factory=lambda: {"stdout": [], "stderr": []})
    thread: threading.Thread | None = None
    client: RobotClient | None = None

    @property
    def name(self) -> str:
        return getattr(self.function, "__name__", "callable")

    @property
    def crash(self) -> None:
        return None  # a callable's failure is its `error`

    @property
    def failed(self) -> bool:
        return self.error is not None

    def text(self, stream: str = "stdout") -> str:
        return "".join(self.output[stream])


def start_callable(sim, host: str, port: int, robot_id: int, function) -> CallableRun:
    """Run `function(robot_client)` in a thread; the simulation waits for it like a program."""
    run = CallableRun(robot_id, function)
    sim.call(lambda s: s.expected_programs.add(robot_id))

    def body():
        try:
            run.client = RobotClient(host, port, robot_id, run.name, sim.program_token)
            run.value = function(run.client)
            run.exit_code = 0
        except Exception as error:  # the program's failure, reported like a crash
            if run.stopped_by_us and isinstance(error, (ConnectionError, OSError)):
                run.exit_code = None
            else:
                run.error = f"{type(error).__name__}: {error}"
                run.output["stderr"].append(traceback.format_exc())
                run.exit_code = 1
        finally:
            if run.client is not None:
                run.client.close()
            sim.call(lambda s: s.program_gone(robot_id))

    run.thread = threading.Thread(target=body, name=f"robot {robot_id} {run.name}", daemon=True)
    run.thread.start()
    return run


def stop_callable(run: CallableRun, timeout: float = 5.0) -> None:
    """End a callable still running: its next call fails and the thread unwinds."""
    if run.thread is not None and run.thread.is_alive():
        run.stopped_by_us = True
        if run.client is not None:
            run.client.close()
        run.thread.join(timeout)
