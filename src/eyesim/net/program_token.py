"""The program token: a random secret of each run that programs send in their HELLO.

Without it anyone who can reach the program port could connect as a program and drive (or teleport)
robots: anyone on the network with `--host 0.0.0.0`, any local user on a shared lab machine. So the
simulator makes a new token for every run and refuses a HELLO without it (ERR_BAD_TOKEN, the
connection closed). Programs get it without a step of their own (docs/running.md#the-program-token):

- programs the simulator starts, in their environment (EYESIM_TOKEN, programs/launcher.py);
- programs started by hand in another terminal, from a file the run writes for its port,
  `<state dir>/program-token-<port>`, readable by its user only and removed when the run ends
  (libeyesim reads it when EYESIM_TOKEN is not set; robios/src/transport.c).

`eyesim run --no-token` turns the token off, on loopback only."""

from __future__ import annotations

import ipaddress
import logging
import os
import secrets
from pathlib import Path

from eyesim import paths

log = logging.getLogger("eyesim.net")
ENV_NAME = "EYESIM_TOKEN"
LOOPBACK_NAMES = {"localhost", "127.0.0.1", "::1", "[::1]"}


class NoTokenRefused(ValueError):
    """--no-token with an address other machines can reach."""


def new_token() -> str:
    return secrets.token_urlsafe(24)  # 32 characters, 192 random bits


def is_loopback(host: str) -> bool:
    """True when only this machine can reach an address."""
    name = host.lower()
    if name in LOOPBACK_NAMES or name.endswith(".localhost"):
        return True
    try:
        return ipaddress.ip_address(name.strip("[]")).is_loopback
    except ValueError:
        return False


def check_no_token(host: str) -> None:
    """Raise NoTokenRefused unless a server without a token may listen on `host`."""
    if not is_loopback(host):
        raise NoTokenRefused(
            f"--no-token: {host} can be reached from other machines; programs may only "
            f"connect without a token on loopback (127.0.0.1)"
        )


def token_file_path(port: int) -> Path:
    """Where a run on `port` keeps its token for programs started by hand (as libeyesim looks for it)."""
    return paths.state_dir() / f"program-token-{port}"


class TokenFile:
    """The token written for programs started by hand: created readable by its user only (0600, in
    a folder made 0700), replaced atomically, removed again by remove() if it still holds this
    run's token."""

    def __init__(self, token: str, port: int):
        self.token = token
        self.path = token_file_path(port)
        self.written = False

    def write(self) -> None:
        """Raises OSError when the file cannot be written."""
        folder = self.path.parent
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        temporary = folder / f".{self.path.name}.{os.getpid()}.{secrets.token_hex(4)}"
        flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0) | getattr(os, "O_NOFOLLOW", 0)
        descriptor = os.open(temporary, flags, 0o600)
        try:
            with os.fdopen(descriptor, "w", encoding="ascii") as file:
                file.write(self.token + "\n")
            os.replace(temporary, self.path)
        except BaseException:
            temporary.unlink(missing_ok=True)
            raise
        self.written = True

    def remove(self) -> None:
        if not self.written:
            return
        self.written = False
        try:
            if self.path.read_text(encoding="ascii").strip() == self.token:  # not a later run's
                self.path.unlink()
        except (OSError, UnicodeDecodeError):
            pass


def refusal(given: str, token_file: Path | None) -> str:
    """The message of a HELLO refused for its token (missing: `given` is empty)."""
    problem = (
        "this simulator wants its program token, and this program sent none"
        if not given
        else "this program sent a wrong program token (one of an earlier run or another simulator?)"
    )
    where = (
        f"a program started by hand, as the same user, reads it from {token_file} while the run lasts"
        if token_file is not None
        else "set it for a program started by hand"
    )
    return (
        f"{problem}. A program the simulator starts gets it in {ENV_NAME}; {where}; or set {ENV_NAME} "
        f"to this run's token (`eyesim run --no-token` turns it off, on loopback only; docs/running.md)"
    )
