"""Reading the JSON body of a request to an HTTP route, checked against its definition in
interface/viewer.schema.json (`routes`, docs/viewer-channel.md) before the route acts on it.

A body the schema refuses is answered 400 with one sentence naming the field (413 when it is too
large); what needs the world to check (does robot 7 exist, is the file under a root) is left to
the route."""

from __future__ import annotations

import json

from aiohttp import web

from eyesim.protocol.channel_schema import route_request_problem


class BadBody(Exception):
    """A request body the route does not take: the reason and the HTTP status to answer."""

    def __init__(self, message: str, status: int = 400):
        super().__init__(message)
        self.status = status


def route_of(request: web.Request) -> str:
    """The route as the schema names it: "POST /scenes/open"."""
    resource = request.match_info.route.resource
    return f"{request.method} {resource.canonical if resource is not None else request.path}"


async def checked_body(request: web.Request, limit: int) -> dict:
    """The request's JSON body (no body: {}), checked against the route's request definition."""
    if request.content_length is not None and request.content_length > limit:
        raise BadBody(f"the request is larger than {limit} bytes", 413)
    raw = b""
    while len(raw) <= limit:  # read(n) gives what has come so far, up to n: a large body comes in parts
        part = await request.content.read(limit + 1 - len(raw))
        if not part:
            break
        raw += part
    if len(raw) > limit:
        raise BadBody(f"the request is larger than {limit} bytes", 413)
    try:
        body = json.loads(raw, parse_constant=_not_json) if raw.strip() else {}
    except (ValueError, RecursionError) as error:
        raise BadBody(f"not valid JSON: {error}") from None
    problem = route_request_problem(route_of(request), body)
    if problem is not None:
        raise BadBody(problem)
    return body


def _not_json(name: str):
    raise ValueError(f"{name} is not a JSON number")
