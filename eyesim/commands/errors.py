"""The error a handler raises for a request it cannot serve; it becomes an error reply."""

from eyesim.protocol import generated


class CommandError(Exception):
    def __init__(self, message: str, code: int = generated.ERR_BAD_ARGUMENT):
        super().__init__(message)
        self.code = code


def require(component, robot, what: str):
    """The component, or a NOT_SUPPORTED error naming what the robot lacks."""
    if component is None:
        raise CommandError(f"robot {robot.id} ({robot.name}) has no {what}", generated.ERR_NOT_SUPPORTED)
    return component
