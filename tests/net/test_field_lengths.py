"""protocol.json's lengths: a str or bytes field longer than its operation takes is refused while
the frame is decoded, with the limit named, and the program carries on."""

import pytest
from support.client import RemoteError
from support.connected import connected_program

from eyesim.protocol import generated as g


def _args(op, index: int, size: int) -> tuple:
    """Arguments for `op` whose field `index` has `size` bytes and every other field is small."""
    args = []
    for k, (_, typ) in enumerate(op.request):
        small = {"i32": 0, "u32": 0, "f64": 0.0, "str": "a", "bytes": b"a", "i32s": []}[typ]
        args.append(small if k != index else ("x" * size if typ == "str" else bytes(size)))
    return tuple(args)


def test_every_limited_field_is_refused_one_byte_over_its_limit():
    limited = [(op, index, most) for op in g.OPS.values() for index, most in op.lengths]
    assert {op.name for op, _, _ in limited} >= {"LCD_PRINTF", "LCD_MENU", "SER_SEND", "AU_PLAY", "RADIO_SEND"}
    with connected_program() as (sim, client):
        for op, index, most in limited:
            name = op.request[index][0]
            with pytest.raises(
                RemoteError, match=rf"{name}: {most + 1} bytes is too large \(at most {most}\)"
            ) as refused:
                client.call(op.name, *_args(op, index, most + 1))
            assert refused.value.code == g.ERR_BAD_ARGUMENT
        assert client.call("LCD_PRINTF", "x" * g.OPS[g.OP_LCD_PRINTF].lengths[0][1]) == (0,)  # the limit itself
        assert client.call("OS_GET_COUNT")[0] >= 0
