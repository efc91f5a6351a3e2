"""Checking viewer-channel messages against interface/viewer.schema.json (docs/viewer-channel.md).

Every command from a browser, and every JSON body sent to an HTTP route, is checked here before
anything acts on it, and answered with one short sentence naming the field and what it must be;
tests check what the server sends with `server_message_problems` and `route_answer_problems`.
The schema itself is package data, viewer.schema.json: `make protocol` writes it from
interface/viewer.schema.json, with the RoBIOS constants the source names filled in from
protocol.json, so that the installed package carries it."""

from __future__ import annotations

import functools
import json
import reprlib
from importlib import resources
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from jsonschema import Draft202012Validator

_short = reprlib.Repr()
_short.maxstring = _short.maxother = 40
_short.maxlong = 40

SCHEMA = json.loads(resources.files(__package__).joinpath("viewer.schema.json").read_text(encoding="utf-8"))


ROUTES = SCHEMA["routes"]  # "METHOD /path" -> {"request": {"$ref"}, "response": {"$ref"}}


@functools.cache
def _validator(name: str) -> "Draft202012Validator":
    from jsonschema import Draft202012Validator  # on first use: a headless run never needs it (start-up time)

    return Draft202012Validator({**SCHEMA, "$ref": f"#/$defs/{name}"})


@functools.cache
def _by_tag(union: str) -> dict[str | None, "Draft202012Validator"]:
    """The union's members by the constant of its `x-discriminator` property (None: the member
    taken when the property is absent)."""
    key = SCHEMA["$defs"][union]["x-discriminator"]
    names = [entry["$ref"].rsplit("/", 1)[1] for entry in SCHEMA["$defs"][union]["oneOf"]]
    return {SCHEMA["$defs"][name]["properties"].get(key, {}).get("const"): _validator(name) for name in names}


def command_validators() -> dict[str | None, "Draft202012Validator"]:
    """The browser commands' validators by their `type`."""
    return _by_tag("BrowserCommand")


def mesh_body_validator() -> "Draft202012Validator":
    """The schema of a mesh route's body (made on first use, as every validator here)."""
    return _validator("MeshBody")


def command_problem(data) -> str | None:
    """Why `data` (parsed JSON) is not a browser command of the schema, or None when it is one."""
    if not isinstance(data, dict):
        return "expected a JSON object with a 'type'"
    kind = data.get("type")
    validator = command_validators().get(kind) if isinstance(kind, str) else None
    if validator is None:
        return f"unknown message type {_short.repr(kind)}"
    return _problem(validator, data, kind)


def server_message_problems(message: dict) -> list[str]:
    """Everything wrong with a message the server sends (for tests), [] when it follows the schema."""
    validator = _by_tag("ServerMessage").get(message.get("type"))
    if validator is None:
        return [f"unknown message type {_short.repr(message.get('type'))}"]
    problems = [_describe(error, message["type"]) for error in validator.iter_errors(message)]
    return list(dict.fromkeys(problems))  # several fields missing say so once


def route_request_problem(route: str, body) -> str | None:
    """Why `body` (parsed JSON) is not the request `route` ("POST /scenes/open") takes, or None."""
    name = _definition(ROUTES[route]["request"])
    definition = SCHEMA["$defs"][name]
    if definition.get("type") == "object" or "x-discriminator" in definition:
        if not isinstance(body, dict):
            return "expected a JSON object"
    if "x-discriminator" not in definition:
        return _problem(_validator(name), body, None)
    key, members = definition["x-discriminator"], _by_tag(name)
    if key not in body:
        return _problem(members[None], body, None) if None in members else f"field {key!r} is missing"
    tag = body[key]
    if not isinstance(tag, str) or tag not in members:
        choices = ", ".join(_short.repr(t) for t in members if t is not None)
        return f"{key} must be one of {choices}, not {_short.repr(tag)}"
    return _problem(members[tag], body, tag)


def route_answer_problems(route: str, status: int, body) -> list[str]:
    """Everything wrong with what `route` answered (for tests), [] when it follows the schema: its
    response, or a RouteError for a refusal."""
    name = _definition(ROUTES[route]["response"]) if status < 400 else "RouteError"
    problems = [_describe(error, f"{route} ({status})") for error in _validator(name).iter_errors(body)]
    return list(dict.fromkeys(problems))


def _definition(reference: dict) -> str:
    return reference["$ref"].removeprefix("#/$defs/")


def _problem(validator: "Draft202012Validator", data: dict, kind: str | None) -> str | None:
    # The shallowest error says most: a missing field before what is wrong inside another.
    error = min(validator.iter_errors(data), key=lambda e: len(e.absolute_path), default=None)
    return None if error is None else _describe(error, kind)


def _where(error) -> str:
    path = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in error.absolute_path)
    return path.lstrip(".") or "the message"


def _describe(error, kind: str | None) -> str:
    where, got, limit = _where(error), _short.repr(error.instance), error.validator_value
    check = error.validator
    if check == "type":
        text = f"{where} must be {_kinds(limit)}, not {got}"
    elif check in ("minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "enum", "const"):
        text = f"{where} must be {_alternative(error.schema)}, not {got}"
    elif check == "required":
        missing = [repr(name) for name in limit if name not in error.instance]  # one error per name: say all
        text = (
            f"field {missing[0]} is missing"
            if len(missing) == 1
            else f"fields {', '.join(missing[:-1])} and {missing[-1]} are missing"
        )
    elif check == "additionalProperties":
        known = error.schema.get("properties", {})
        extra = [name for name in error.instance if name not in known]
        text = f"unknown field {_short.repr(extra[0])} (fields: {', '.join(known) or 'none'})"
    elif check in ("maxLength", "minLength"):
        text = f"{where} must have {'at most' if check == 'maxLength' else 'at least'} {limit} characters"
    elif check in ("maxItems", "minItems"):
        text = f"{where} must have {'at most' if check == 'maxItems' else 'at least'} {limit} items"
    elif check == "pattern":
        text = f"{where} must be {error.schema.get('description', f'text matching {limit}')}"
    elif check == "oneOf" and "x-oneOf-message" in error.schema:
        text = error.schema["x-oneOf-message"]
    elif check == "oneOf":
        text = f"{where} must be {' or '.join(_alternative(option) for option in limit)}, not {got}"
    else:
        text = f"{where}: {error.message[:200]}"
    return text if kind is None else f"{kind}: {text}"


def _kinds(types) -> str:
    words = {
        "integer": "a whole number",
        "number": "a number",
        "string": "text",
        "boolean": "true or false",
        "array": "a list",
        "object": "an object",
        "null": "null",
    }
    return " or ".join(words.get(t, t) for t in ([types] if isinstance(types, str) else types))


def _alternative(schema: dict) -> str:
    """What a schema allows, in words: 'a number from 0.01 to 1000', 'one of 1, 2, 4, 8', ..."""
    if "const" in schema:
        return _short.repr(schema["const"])
    if "enum" in schema:
        return "one of " + ", ".join("null" if v is None else _short.repr(v) for v in schema["enum"])
    low = schema.get("minimum", schema.get("exclusiveMinimum"))
    high = schema.get("maximum", schema.get("exclusiveMaximum"))
    what = _kinds(schema.get("type", "number"))
    if low is not None and high is not None:
        return f"{what} from {low:g} to {high:g}"
    if low is not None:
        return f"{what} {'above' if 'exclusiveMinimum' in schema else 'at least'} {low:g}"
    if high is not None:
        return f"{what} {'below' if 'exclusiveMaximum' in schema else 'at most'} {high:g}"
    return what
