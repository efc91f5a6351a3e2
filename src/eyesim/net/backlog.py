"""A connection's reply bytes that the kernel has not taken yet."""

from __future__ import annotations

from collections import deque

LARGE = 1 << 16  # bytes: a reply this large is kept as it is, not copied


class Backlog:
    """Replies waiting to be sent, in order. Small ones are gathered in one buffer; a large one (a
    camera image) is kept as the reply itself: copying a 15 MB image into a fresh buffer cost the
    simulation thread about 10 ms, mostly the new memory's page faults."""

    def __init__(self):
        self._chunks: deque = deque()  # bytearray (gathered small replies) or memoryview (one large reply)
        self.size = 0  # bytes waiting: an attribute, as the connection asks for it several times a call

    def __len__(self) -> int:
        return self.size

    def __iadd__(self, data) -> "Backlog":
        if len(data) >= LARGE:
            self._chunks.append(memoryview(data).cast("B"))
        else:
            if not self._chunks or not isinstance(self._chunks[-1], bytearray):
                self._chunks.append(bytearray())
            self._chunks[-1] += data
        self.size += len(data)
        return self

    def first(self):
        """The bytes to send next (part of the backlog: send, then `consume` what went)."""
        return self._chunks[0]

    def chunks(self) -> list:
        return list(self._chunks)

    def consume(self, count: int) -> None:
        """`count` bytes from the front were sent."""
        self.size -= count
        while count:
            chunk = self._chunks[0]
            if count >= len(chunk):
                self._chunks.popleft()
                count -= len(chunk)
            elif isinstance(chunk, bytearray):
                del chunk[:count]
                count = 0
            else:
                self._chunks[0] = chunk[count:]
                count = 0
