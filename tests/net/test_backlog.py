"""A connection's backlog keeps its replies in order, however they are sent off in pieces, and keeps a
large reply without copying it."""

import numpy as np

from eyesim.net.backlog import LARGE, Backlog


def drain(backlog: Backlog, piece: int) -> bytes:
    """Send everything `piece` bytes at a time, as a socket taking that much would."""
    out = bytearray()
    while backlog:
        chunk = bytes(backlog.first()[:piece])
        out += chunk
        backlog.consume(len(chunk))
    return bytes(out)


def test_replies_come_out_in_order_in_any_pieces():
    image = np.arange(3 * LARGE, dtype=np.uint32).view(np.uint8)
    replies = [b"small one", bytes(range(200)), memoryview(image), b"after the image", b"x" * (LARGE + 1)]
    for piece in (1, 7, 1000, LARGE, 10 * LARGE):
        backlog = Backlog()
        for reply in replies:
            backlog += reply
        assert len(backlog) == sum(len(r) for r in replies)
        assert drain(backlog, piece) == b"".join(bytes(r) for r in replies)
        assert len(backlog) == 0 and not backlog


def test_a_large_reply_is_kept_not_copied():
    image = np.zeros(LARGE * 4, dtype=np.uint8)
    backlog = Backlog()
    backlog += b"header"
    backlog += memoryview(image)
    backlog.consume(6)
    assert np.shares_memory(np.asarray(backlog.first()), image)
    image[0] = 7  # the backlog shows the reply itself
    assert backlog.first()[0] == 7
