"""Who may use the viewer: only its own page, on the names the server really has.

Three checks, in this order, on every HTTP request and WebSocket upgrade:

- **Host.** The `Host` header must name this server (a loopback name when it listens on loopback,
  else the address it listens on or this machine's name). A page on another site whose name was
  made to resolve to 127.0.0.1 (DNS rebinding) sends its own name and is refused.
- **Origin.** When a browser sends `Origin` (it always does for WebSockets and for cross-site
  requests), it must be this server's own `http://host:port`. Another site's page open in the same
  browser cannot drive the simulation or read the LCDs.
- **Token.** A random token is required, as Jupyter does: `?token=...` in the URL printed at
  start, after which a cookie carries it. On a shared lab machine every local user can reach a
  loopback port, so loopback needs it too, unless the server was started without one
  (`--no-token`, refused for any other address, where other machines can reach the server).

Refusals answer 403 with the reason, and are logged."""

from __future__ import annotations

import ipaddress
import logging
import secrets
import socket

from aiohttp import web

log = logging.getLogger("eyesim.web")
TOKEN_COOKIE = "eyesim_token"
LOOPBACK_NAMES = {"localhost", "127.0.0.1", "::1", "[::1]"}


def is_loopback(host: str) -> bool:
    if host.lower() in LOOPBACK_NAMES or host.lower().endswith(".localhost"):
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


class NoTokenRefused(ValueError):
    """--no-token with an address other machines can reach."""


class AccessPolicy:
    def __init__(self, host: str, token: str | None = None, require_token: bool = True):
        self.host = host
        self.loopback = is_loopback(host)
        if not require_token and not self.loopback:
            raise NoTokenRefused(
                f"--no-token: {host} can be reached from other machines; "
                f"a server without a token may only listen on loopback (127.0.0.1)"
            )
        self.token = (token or secrets.token_urlsafe(18)) if require_token else None
        self._names = self._allowed_names(host)

    def _allowed_names(self, host: str) -> set[str] | None:
        """Host names a request may use; None = any (a token guards a server on every address)."""
        if self.loopback:
            return set(LOOPBACK_NAMES) | {host.lower()}
        if host in ("0.0.0.0", "::", ""):
            return None
        return {host.lower(), f"[{host.lower()}]", socket.gethostname().lower(), socket.getfqdn().lower()}

    def url_suffix(self) -> str:
        return f"?token={self.token}" if self.token else ""

    def refusal(self, request: web.Request) -> str | None:
        """Why this request is refused, or None when it may go on."""
        host_header = request.headers.get("Host", "")
        name = _host_name(host_header)
        if not name:
            return "no Host header"
        if self._names is not None and name not in self._names and not (self.loopback and is_loopback(name)):
            return f"unknown Host {host_header!r}"
        origin = request.headers.get("Origin")
        if origin is not None and origin.lower() != f"{request.scheme}://{host_header}".lower():
            return f"foreign Origin {origin!r}"
        if self.token is not None:
            given = request.query.get("token") or request.cookies.get(TOKEN_COOKIE) or ""
            if not secrets.compare_digest(given.encode(), self.token.encode()):
                return "missing or wrong access token (use the URL the simulator printed)"
        return None

    @web.middleware
    async def middleware(self, request: web.Request, handler):
        reason = self.refusal(request)
        if reason is not None:
            log.warning("viewer: refused %s %s from %s: %s", request.method, request.path, request.remote, reason)
            raise web.HTTPForbidden(text=f"EyeSim viewer: {reason}\n")
        response = await handler(request)
        if self.token is not None and request.query.get("token") == self.token:
            # the page's own requests (assets, WebSocket) then carry it without the query
            response.set_cookie(TOKEN_COOKIE, self.token, httponly=True, samesite="Strict")
        return response


def _host_name(host_header: str) -> str:
    """The name part of a Host header, lower case: 'localhost:8080' -> 'localhost', '[::1]:80' -> '::1'."""
    header = host_header.strip().lower()
    if header.startswith("["):
        return header[1 : header.find("]")] if "]" in header else ""
    return header.rsplit(":", 1)[0] if header.count(":") == 1 else header
