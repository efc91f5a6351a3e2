"""The SER functions that do more than pass values through (eye/ser.py has the rest): bytes and text both
ways, one byte per character (Latin-1)."""

from __future__ import annotations

import ctypes

from eye._library import C

__all__ = ["SERSendChar", "SERSend", "SERReceiveChar", "SERReceive"]

RECEIVE_SIZE = 1024  # what SERReceive takes at most per call unless told otherwise


def _bytes(data: str | bytes | bytearray, function: str) -> bytes:
    """Data to send: bytes as they are, text one byte per character (Latin-1, as SERReceive returns it)."""
    if isinstance(data, (bytes, bytearray)):
        return bytes(data)
    try:
        return str(data).encode("latin-1")
    except UnicodeEncodeError:
        raise ValueError(f"{function}: characters above \\xff cannot be sent; send bytes "
                         f"(e.g. text.encode('utf-8'))") from None


def SERSendChar(interface: int, ch: str | bytes | int) -> int:
    """Sends one character (a 1-character string, a byte, or a number 0 .. 255). Returns 0 (1 on error)."""
    if isinstance(ch, int):
        ch = bytes([ch & 0xFF])
    data = _bytes(ch, "SERSendChar")
    if len(data) != 1:
        raise ValueError(f"SERSendChar: send one character, not {len(data)}")
    return C.SERSendChar(interface, data)


def SERSend(interface: int, buf: str | bytes) -> int:
    """Sends a string (up to a NUL character, as in C). Returns 0 (1 on error)."""
    return C.SERSend(interface, _bytes(buf, "SERSend"))


def SERReceiveChar(interface: int) -> str:
    """Waits for the next character and returns it (one character, Latin-1: byte n is chr(n))."""
    return C.SERReceiveChar(interface).decode("latin-1")


def SERReceive(interface: int, size: int = RECEIVE_SIZE) -> str:
    """The characters received so far, at most `size` (possibly ""); never waits. Byte n is chr(n)."""
    buffer = ctypes.create_string_buffer(size + 1)
    count = C.SERReceive(interface, buffer, size)
    return buffer.raw[:max(count, 0)].decode("latin-1")
