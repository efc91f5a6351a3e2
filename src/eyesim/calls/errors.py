"""The error a handler raises for a request it cannot serve; it becomes an error reply."""

from contextlib import contextmanager

from eyesim.protocol import generated


class CallError(Exception):
    def __init__(self, message: str, code: int = generated.ERR_BAD_ARGUMENT):
        super().__init__(message)
        self.code = code


def require(component, robot, what: str):
    """The component, or a NOT_SUPPORTED error naming what the robot lacks."""
    if component is None:
        raise CallError(f"robot {robot.id} ({robot.name}) has no {what}", generated.ERR_NOT_SUPPORTED)
    return component


def numbered(robot, table: dict, number: int, what: str):
    """The robot's `what` (motor, encoder, servo) by its number; none: an error naming the numbers it has
    (NOT_SUPPORTED when it has none at all)."""
    device = table.get(number)
    if device is None:
        numbers = ", ".join(str(n) for n in sorted(table)) or "none"
        raise CallError(
            f"robot {robot.id} ({robot.name}) has no {what} {number} (its {what}s: {numbers})",
            generated.ERR_BAD_ARGUMENT if table else generated.ERR_NOT_SUPPORTED,
        )
    return device


def component_of(robot, cls):
    """The robot's component of that class, or a NOT_SUPPORTED error naming it by its noun."""
    return require(robot.component(cls), robot, cls.noun)


@contextmanager
def checked_arguments():
    """Turns a component's ValueError about a bad argument into an error reply with its message."""
    try:
        yield
    except ValueError as error:
        raise CallError(str(error)) from None
