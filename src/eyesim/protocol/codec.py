"""Encoding and decoding of protocol frames: length prefix, header, typed payload fields."""

from __future__ import annotations

import struct
from typing import NamedTuple, Sequence

import numpy as np

from eyesim.protocol import generated as g

_LEN = struct.Struct("<I")
_HEADER = struct.Struct("<HHI")  # op, kind, request id
_I32 = struct.Struct("<i")
_U32 = struct.Struct("<I")
_F64 = struct.Struct("<d")
SHARE_BUFFER_FROM = 64 * 1024  # frame bytes from which the decoder hands its buffer over rather than copy
# A bytes field from this size on (an LCDImage picture, an AUPlay sound: megabytes) is passed on as a
# read-only view of the received frame, not copied: every frame body is a buffer of its own.
VIEW_FIELDS_FROM = 1 << 20


class ProtocolError(Exception):
    """A frame or payload that does not follow the protocol; `code` is one of the ERR_* values."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code = code


class Message(NamedTuple):
    op: int
    kind: int
    request_id: int
    payload: bytes | memoryview  # a view into the received frame: decode_payload copies what it keeps


_SCALAR_CODES = {"i32": "i", "u32": "I", "f64": "d"}
_scalar_layouts: dict[int, tuple] = {}  # id(layout) -> (layout, payload Struct, frame Struct) or (layout, None, None)


def _scalar_structs(layout: Sequence[tuple[str, str]]) -> tuple[struct.Struct | None, struct.Struct | None]:
    """For a layout of fixed-size fields only (most calls' requests and replies): one Struct for
    the payload and one for the whole frame (length, header, payload), so a message is packed or
    unpacked in one go; (None, None) for a layout with a text, bytes or array field."""
    known = _scalar_layouts.get(id(layout))
    if known is None or known[0] is not layout:  # layouts are long-lived constants: keyed by identity
        codes = [_SCALAR_CODES.get(typ) for _, typ in layout]
        if None in codes:
            known = (layout, None, None)
        else:
            fields = "".join(code for code in codes if code)
            known = (layout, struct.Struct("<" + fields), struct.Struct("<IHHI" + fields))
        _scalar_layouts[id(layout)] = known
    return known[1], known[2]


def _encode_field(out: list[bytes], typ: str, value) -> None:
    if typ == "i32":
        out.append(_I32.pack(value))
    elif typ == "u32":
        out.append(_U32.pack(value))
    elif typ == "f64":
        out.append(_F64.pack(value))
    elif typ == "str":
        raw = value.encode("utf-8")
        out.append(_U32.pack(len(raw)))
        out.append(raw)
    elif typ == "bytes":
        raw = bytes(value)
        out.append(_U32.pack(len(raw)))
        out.append(raw)
    elif typ == "i32s":
        out.append(_U32.pack(len(value)))
        if isinstance(value, np.ndarray):  # a lidar scan: 30x faster than packing a list
            out.append(value.astype("<i4", casting="same_kind", copy=False).tobytes())
        else:
            out.append(struct.pack(f"<{len(value)}i", *value))
    else:
        raise ValueError(f"unknown field type {typ!r}")


def _check_count(layout: Sequence, values: Sequence) -> None:
    if len(values) != len(layout):
        raise ValueError(f"expected {len(layout)} values, got {len(values)}")


def _payload_size_error(end: int, used: int) -> ProtocolError:
    """A payload of `end` bytes whose fields took `used` (or ran past its end: `used` > `end`)."""
    if used > end:
        return ProtocolError(g.ERR_BAD_PAYLOAD, f"payload too short ({end} bytes) for its fields")
    return ProtocolError(g.ERR_BAD_PAYLOAD, f"{end - used} unexpected bytes after the last field")


def encode_payload(layout: Sequence[tuple[str, str]], values: Sequence) -> bytes:
    _check_count(layout, values)
    out: list[bytes] = []
    for (_, typ), value in zip(layout, values):
        _encode_field(out, typ, value)
    return b"".join(out)


def decode_payload(
    layout: Sequence[tuple[str, str]], payload: bytes | memoryview, lengths: Sequence[tuple[int, int]] = ()
) -> tuple:
    """Decode `payload` by `layout`; raises ProtocolError(BAD_PAYLOAD) on any mismatch, and
    ProtocolError(BAD_ARGUMENT) for a field longer than `lengths` allows (an OpSpec's: (field
    index, most bytes)), before it is decoded. Text is decoded straight from the payload (a
    memoryview is not copied first); bytes are copied once, or not at all when they are large
    (VIEW_FIELDS_FROM: a read-only memoryview)."""
    end = len(payload)
    scalars, _ = _scalar_structs(layout)
    if scalars is not None:
        if end != scalars.size:
            raise _payload_size_error(end, scalars.size)
        return scalars.unpack_from(payload)
    most = dict(lengths)
    values = []
    pos = 0
    try:
        for index, (name, typ) in enumerate(layout):
            if typ == "i32":
                values.append(_I32.unpack_from(payload, pos)[0])
                pos += 4
            elif typ == "u32":
                values.append(_U32.unpack_from(payload, pos)[0])
                pos += 4
            elif typ == "f64":
                values.append(_F64.unpack_from(payload, pos)[0])
                pos += 8
            else:
                (n,) = _U32.unpack_from(payload, pos)
                pos += 4
                if n > most.get(index, n):
                    raise ProtocolError(g.ERR_BAD_ARGUMENT, f"{name}: {n} bytes is too large (at most {most[index]})")
                size = n * 4 if typ == "i32s" else n
                if pos + size > end:
                    raise ProtocolError(g.ERR_BAD_PAYLOAD, f"field {name!r}: length {n} runs past the payload")
                raw = payload[pos : pos + size]
                pos += size
                if typ == "str":
                    values.append(str(raw, "utf-8"))
                elif typ == "bytes":
                    values.append(memoryview(raw).toreadonly() if size >= VIEW_FIELDS_FROM else bytes(raw))
                else:
                    values.append(list(struct.unpack(f"<{n}i", raw)))
    except struct.error:
        raise _payload_size_error(end, end + 1) from None
    except UnicodeDecodeError:
        raise ProtocolError(g.ERR_BAD_PAYLOAD, "a text field is not valid UTF-8") from None
    if pos != end:
        raise _payload_size_error(end, pos)
    return tuple(values)


def encode_frame(op: int, kind: int, request_id: int, payload: bytes) -> bytes:
    body_len = _HEADER.size + len(payload)
    return _LEN.pack(body_len) + _HEADER.pack(op, kind, request_id) + payload


def encode_message(op: int, kind: int, request_id: int, values: Sequence) -> bytes:
    """Encode a request or reply of operation `op` with its fields' values."""
    spec = g.OPS[op]
    layout = spec.request if kind == g.KIND_REQUEST else spec.reply
    _, frame = _scalar_structs(layout)
    if frame is None:
        return encode_frame(op, kind, request_id, encode_payload(layout, values))
    _check_count(layout, values)
    return frame.pack(frame.size - _LEN.size, op, kind, request_id, *values)


def encode_error(op: int, request_id: int, code: int, message: str) -> bytes:
    return encode_frame(op, g.KIND_ERROR, request_id, encode_payload(g.ERROR_PAYLOAD, (code, message)))


def decode_body(body: bytes | memoryview) -> Message:
    if len(body) < _HEADER.size:
        raise ProtocolError(g.ERR_BAD_FRAME, f"frame of {len(body)} bytes is shorter than its header")
    op, kind, request_id = _HEADER.unpack_from(body)
    return Message(op, kind, request_id, memoryview(body)[_HEADER.size :])


class FrameDecoder:
    """Reassembles frames from a byte stream split or coalesced in any way."""

    def __init__(self, max_frame: int = g.MAX_FRAME):
        self._buffer = bytearray()
        self._max_frame = max_frame

    def feed(self, data: bytes, limit: int | None = None) -> list[Message]:
        """Add received bytes; return the complete messages they finish, in order, at most `limit`
        of them (the rest stay buffered: feed b"" later to take them).

        Raises ProtocolError(BAD_FRAME) when a frame announces a size beyond the limit."""
        if not self._buffer and type(data) is bytes and len(data) >= 4 and (limit is None or limit > 0):
            (length,) = _LEN.unpack_from(data)
            if len(data) == 4 + length and _HEADER.size <= length <= min(self._max_frame, SHARE_BUFFER_FROM):
                # Exactly one small frame and nothing buffered (a call's request, as a rule): the
                # received bytes are the frame, and they never change, so nothing is copied.
                return [decode_body(memoryview(data)[4:])]
        self._buffer += data
        messages: list[Message] = []
        buf = self._buffer
        pos = 0
        while len(buf) - pos >= 4 and (limit is None or len(messages) < limit):
            (length,) = _LEN.unpack_from(buf, pos)
            if length > self._max_frame or length < _HEADER.size:
                raise ProtocolError(g.ERR_BAD_FRAME, f"frame length {length} outside {_HEADER.size}..{self._max_frame}")
            if len(buf) - pos - 4 < length:
                break
            if pos == 0 and len(buf) == 4 + length and length > SHARE_BUFFER_FROM:
                # A large frame alone in the buffer (as a 16 MiB one always is): hand the buffer
                # itself over instead of copying it; the next frame starts a new one.
                self._buffer = bytearray()
                messages.append(decode_body(memoryview(buf)[4:]))
                return messages
            messages.append(decode_body(bytes(buf[pos + 4 : pos + 4 + length])))
            pos += 4 + length
        if pos:
            del buf[:pos]
        return messages

    @property
    def pending_bytes(self) -> int:
        return len(self._buffer)


def encode_image_reply(op: int, request_id: int, values: Sequence, image: np.ndarray) -> memoryview:
    """The reply of `op` whose last field (bytes) holds `image`'s uint8 values, row by row, after the
    other `values`: the same bytes as encode_message, with the image copied once, straight into the
    frame, by numpy, which lets other threads run meanwhile (bytes() of a 15 MB image would not)."""
    if g.OPS[op].reply[-1][1] != "bytes":
        raise ValueError(f"the reply of {g.OPS[op].name} does not end in a bytes field")
    head = encode_message(op, g.KIND_REPLY, request_id, (*values, b""))
    frame = np.empty(len(head) + image.nbytes, dtype=np.uint8)
    frame[: len(head)] = np.frombuffer(head, dtype=np.uint8)
    _LEN.pack_into(frame.data, 0, len(frame) - _LEN.size)
    _U32.pack_into(frame.data, len(head) - _U32.size, image.nbytes)
    np.copyto(frame[len(head) :].reshape(image.shape), image)
    return frame.data
