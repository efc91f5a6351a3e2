"""Registry of RoBIOS operations: handler modules by RoBIOS group, looked up by op code.

The groups are protocol.json's. A part kind's folder holds its group's handlers
(`eyesim/parts/psd/calls.py` serves group `psd`: its GROUP names the group, its HANDLERS table the
operations); a group of the robot's computer has its module here, named after it
(`eyesim.calls.lcd`). Both are found without a registry line (the session group, the
handshake, is the engine's own). An operation that only calls one method of the robot's
component declares it in protocol.json (`"calls": "Lcd.set_position"`) and has no handler
function: `calling` makes its handler.

A handler is `handler(sim, robot, request) -> reply values | Pending`; it raises CallError for
requests it cannot serve. The network layer never knows what an operation means."""

from __future__ import annotations

import importlib
import importlib.util
import pkgutil
from types import ModuleType

import eyesim.parts
import eyesim.robot.components  # noqa: F401  (the computer's component classes, for "calls" to name)
from eyesim.calls.errors import CallError, checked_arguments, component_of
from eyesim.protocol import generated
from eyesim.protocol.ops import OpSpec
from eyesim.robot.component import Component, named
from eyesim.scene.parts import PARTS

ENGINE_GROUP = "session"  # HELLO and THREADS: answered by the engine itself


def component_class(name: str) -> type[Component]:
    """The component class of that name (a "calls" declaration names it so)."""
    seen, waiting = set(), [Component]
    while waiting:
        cls = waiting.pop()
        seen.add(cls)
        waiting += [sub for sub in cls.__subclasses__() if sub not in seen]
    found = [cls for cls in seen if cls.__name__ == name]
    if len(found) != 1:
        raise RuntimeError(f"protocol.json's calls names {name!r}: {len(found)} component classes have that name")
    return found[0]


def calling(op: OpSpec):
    """The handler of an op declared as `"calls": "Component.method"`: the robot's component of that
    class (none: NOT_SUPPORTED, naming its noun) is called with the request's values; a ValueError
    it raises is a BAD_ARGUMENT with its message. The reply is what the method returns, after a 0
    for the op's "result" field (a method returning None fills just that)."""
    class_name, method_name = op.calls.split(".")
    cls = component_class(class_name)
    method = getattr(cls, method_name, None)
    if not callable(method) or not cls.noun:
        raise RuntimeError(f"{op.name} calls {op.calls}: {class_name} needs the method and a noun")
    result_first = op.reply[0][0] == "result"
    if len(op.reply) > 2 or len(op.reply) == 2 and not result_first:
        raise RuntimeError(f"{op.name} calls {op.calls}: a call's reply is a result, a value, or both")
    # The reply's shape, chosen once: the method's value, after a 0 for a "result" field.
    shape = (
        (lambda value: (0, value))
        if len(op.reply) == 2
        else (lambda value: (0,))
        if result_first
        else (lambda value: (value,))
    )

    def handler(sim, robot, request):
        component = component_of(robot, cls)
        with checked_arguments():
            return shape(method(component, *request.args))

    return handler


def handler_modules() -> dict[str, ModuleType]:
    """The handler module of each group that has one: the `calls` module of a part kind's folder
    (the group its GROUP names), else `eyesim.calls.<group>`."""
    modules: dict[str, ModuleType] = {}
    for folder in pkgutil.iter_modules(eyesim.parts.__path__):
        name = f"{eyesim.parts.__name__}.{folder.name}.calls"
        if folder.ispkg and importlib.util.find_spec(name):
            module = importlib.import_module(name)
            if module.GROUP in modules:
                raise RuntimeError(f"{name} and {modules[module.GROUP].__name__} both handle group {module.GROUP}")
            modules[module.GROUP] = module
    for group in sorted({op.group for op in generated.OPS.values()} - {ENGINE_GROUP}):
        name = f"{__name__}.{group}"
        if importlib.util.find_spec(name):
            if group in modules:
                raise RuntimeError(f"{name} and {modules[group].__name__} both handle group {group}")
            modules[group] = importlib.import_module(name)
    return modules


def _build_registry() -> dict:
    for part in PARTS:  # the part kinds' component classes, for "calls" to name
        for factory in part.components:
            named(factory)
    registry = {}
    for group, module in handler_modules().items():
        for name, handler in module.HANDLERS.items():
            op = generated.OPS_BY_NAME[name]
            if op.group != group:
                raise RuntimeError(f"{module.__name__} handles {name}, an operation of group {op.group}")
            if op.calls:
                raise RuntimeError(f"{module.__name__} handles {name}, which protocol.json says calls {op.calls}")
            registry[op.code] = handler
    for op in generated.OPS.values():
        if op.calls:
            registry[op.code] = calling(op)
    return registry


def __getattr__(name: str) -> dict:
    """HANDLERS (op code -> handler), built at its first use: a part folder's `calls` imports this
    package (its errors) before the registry imports it, so it cannot be built while importing."""
    if name != "HANDLERS":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    registry = globals()["HANDLERS"] = _build_registry()
    return registry


__all__ = ["HANDLERS", "CallError"]
