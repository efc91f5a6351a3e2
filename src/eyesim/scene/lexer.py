"""Reading keyword-style scene files: text decoding, lines, comments, quoted tokens, numbers."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from eyesim.scene.diagnostics import Location
from eyesim.scene.diagnostics import Diagnostics, quoted

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
_WHITESPACE = " \t\f\v"


@dataclass(frozen=True)
class Token:
    text: str
    column: int  # 1-based column of the token's first character (its quote, if quoted)
    quoted: bool = False


@dataclass(frozen=True)
class Line:
    """One statement: its 1-based line number and tokens (comments already removed)."""

    number: int
    tokens: tuple[Token, ...]

    @property
    def keyword(self) -> str:
        return self.tokens[0].text

    @property
    def args(self) -> tuple[Token, ...]:
        return self.tokens[1:]


class TextFileError(Exception):
    """The bytes are not a text file; the message says why."""


def decode(data: bytes) -> str:
    """File bytes as text: UTF-8 (a BOM is dropped), else Windows-1252/Latin-1 as old editors
    wrote them. Line endings become '\\n'."""
    if b"\x00" in data:
        raise TextFileError("not a text file: it contains NUL bytes")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    return text.replace("\r\n", "\n").replace("\r", "\n")


def read_text(path: Path) -> str:
    return decode(path.read_bytes())


def split_lines(
    text: str, file: str, diagnostics: Diagnostics, comment_chars: str = "", strict: bool = True
) -> list[Line]:
    """The statements of a keyword file. Lines whose first non-blank character is '#' or ';' are
    comments in every format; `comment_chars` also start a comment after data (.wld uses ';').
    Double or single quotes group a token with spaces. An unterminated quote runs to the end of
    the line and is reported (an error when `strict`, else a warning)."""
    lines = []
    for number, raw in enumerate(text.split("\n"), start=1):
        stripped = raw.lstrip(_WHITESPACE)
        if not stripped or stripped[0] in "#;":
            continue
        tokens = _tokens(raw, number, file, diagnostics, comment_chars, strict)
        if tokens:
            lines.append(Line(number, tuple(tokens)))
    return lines


_PLAIN_TOKEN = re.compile(r"[^ \t\f\v]+")


def _tokens(
    raw: str, number: int, file: str, diagnostics: Diagnostics, comment_chars: str, strict: bool
) -> list[Token]:
    if '"' not in raw and "'" not in raw and not any(c in raw for c in comment_chars):
        # most lines: no quotes, no comment; the regular expression is much faster
        return [Token(m.group(), m.start() + 1) for m in _PLAIN_TOKEN.finditer(raw)]
    tokens = []
    i, n = 0, len(raw)
    while i < n:
        c = raw[i]
        if c in _WHITESPACE:
            i += 1
            continue
        if c in comment_chars:
            break
        start = i
        if c in "\"'":
            end = raw.find(c, i + 1)
            if end < 0:
                message = (
                    f"unterminated quote: expected a closing {c} before the end of the line, found {quoted(raw[i:])}"
                )
                where = Location(file, number, start + 1)
                (diagnostics.error if strict else diagnostics.warning)(where, message)
                tokens.append(Token(raw[i + 1 :].rstrip(_WHITESPACE), start + 1, True))
                break
            tokens.append(Token(raw[i + 1 : end], start + 1, True))
            i = end + 1
            continue
        while i < n and raw[i] not in _WHITESPACE and raw[i] not in comment_chars:
            i += 1
        tokens.append(Token(raw[start:i], start + 1))
    return tokens


LARGEST = 1e9  # mm, degrees or kg: anything larger is a typo and would overflow the geometry


def number(text: str) -> float | None:
    """A decimal number with optional sign and exponent, at most LARGEST in size (no 'nan',
    'inf' or '1_000'), else None."""
    if _NUMBER.fullmatch(text):
        value = float(text)
        if not -LARGEST <= value <= LARGEST:
            return None
        return value + 0.0  # no negative zero
    return None


def integer(text: str) -> int | None:
    if _INTEGER.fullmatch(text) and len(text) <= 10:
        return int(text)
    return None


def format_number(value: float) -> str:
    """The shortest text that reads back as exactly `value` ('90', '22.7', '-0.025')."""
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return repr(float(value))


def quote_token(text: str) -> str:
    """A token for writing: quoted when it is empty or has spaces, quotes or comment characters."""
    if text and not any(c in text for c in _WHITESPACE + ";#'\""):
        return text
    return "'" + text + "'" if '"' in text else '"' + text + '"'
