"""Framing survives any split or coalescing of the byte stream; bad frames give our own error."""

import struct

import pytest
from hypothesis import given, settings, strategies as st

from eyesim.protocol import (
    FrameDecoder,
    ProtocolError,
    decode_payload,
    encode_frame,
    encode_message,
    encode_payload,
    generated as g,
)

FRAMES = [
    encode_message(g.OP_HELLO, g.KIND_REQUEST, 1, (g.VERSION, "S4", "prog", 7, "token")),
    encode_message(g.OP_PSD_GET, g.KIND_REQUEST, 2, (1,)),
    encode_message(g.OP_LCD_PRINTF, g.KIND_REQUEST, 3, ("x" * 5000,)),
    encode_message(g.OP_LCD_CLEAR, g.KIND_REQUEST, 4, ()),
    encode_message(g.OP_SIM_SET_ROBOT, g.KIND_REQUEST, 5, (0, 1, 2, 3, -4)),
]


@settings(max_examples=300, deadline=None)
@given(
    order=st.lists(st.integers(0, len(FRAMES) - 1), min_size=1, max_size=12),
    cuts=st.lists(st.integers(0, 40000), max_size=30),
)
def test_any_split_of_the_stream_gives_the_same_messages(order, cuts):
    stream = b"".join(FRAMES[i] for i in order)
    points = sorted({c % (len(stream) + 1) for c in cuts} | {0, len(stream)})
    decoder = FrameDecoder()
    messages = []
    for start, end in zip(points, points[1:]):
        messages += decoder.feed(stream[start:end])
    assert [m.request_id for m in messages] == [i + 1 for i in order]
    assert decoder.pending_bytes == 0


def test_an_oversized_frame_is_refused_before_its_body_arrives():
    decoder = FrameDecoder()
    with pytest.raises(ProtocolError) as error:
        decoder.feed((g.MAX_FRAME + 1).to_bytes(4, "little"))
    assert error.value.code == g.ERR_BAD_FRAME


def test_a_frame_shorter_than_its_header_is_refused():
    with pytest.raises(ProtocolError):
        FrameDecoder().feed((3).to_bytes(4, "little") + b"abc")


@pytest.mark.parametrize(
    "payload, reason",
    [
        (b"\x01\x00", "too short"),
        (b"\x01\x00\x00\x00\x02", "unexpected bytes"),
    ],
)
def test_payload_errors_say_what_is_wrong(payload, reason):
    with pytest.raises(ProtocolError, match=reason) as error:
        decode_payload(g.OPS[g.OP_PSD_GET].request, payload)
    assert error.value.code == g.ERR_BAD_PAYLOAD


def test_a_string_longer_than_the_payload_is_refused():
    payload = (100).to_bytes(4, "little") + b"abc"
    with pytest.raises(ProtocolError, match="runs past"):
        decode_payload(g.OPS[g.OP_LCD_PRINTF].request, payload)


def test_invalid_utf8_is_refused():
    payload = (2).to_bytes(4, "little") + b"\xff\xfe"
    with pytest.raises(ProtocolError, match="UTF-8"):
        decode_payload(g.OPS[g.OP_LCD_PRINTF].request, payload)


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=64))
def test_random_payloads_raise_only_protocol_errors(payload):
    for op in g.OPS.values():
        try:
            decode_payload(op.request, payload)
        except ProtocolError:
            pass


def test_frame_header_layout():
    assert encode_frame(0x1234, 2, 0x01020304, b"") == bytes.fromhex("080000003412020004030201")


def test_a_large_bytes_field_is_a_read_only_view_of_the_frame_and_a_small_one_a_copy():
    from eyesim.protocol.codec import VIEW_FIELDS_FROM

    image = bytes(range(256)) * (VIEW_FIELDS_FROM // 256)
    for data, kept_as in ((image, memoryview), (b"\x01\x02\x03", bytes)):
        frame = encode_message(g.OP_LCD_IMAGE, g.KIND_REQUEST, 5, (0, 0, 1, len(data), 1, 1, 1, data))
        (message,) = FrameDecoder().feed(frame)
        values = decode_payload(g.OPS[g.OP_LCD_IMAGE].request, message.payload)
        assert type(values[-1]) is kept_as and values[-1] == data
    with pytest.raises(TypeError):
        values = decode_payload(
            g.OPS[g.OP_LCD_IMAGE].request,
            FrameDecoder()
            .feed(encode_message(g.OP_LCD_IMAGE, g.KIND_REQUEST, 5, (0, 0, 1, len(image), 1, 1, 1, image)))[0]
            .payload,
        )
        values[-1][0] = 0  # nobody can change the frame it came from


def test_messages_of_fixed_size_fields_pack_in_one_go_as_field_by_field():
    """Layouts of i32/u32/f64 fields only are packed and unpacked with one Struct: the bytes, the
    values and the errors are those of the general field-by-field code."""
    from eyesim.protocol.codec import _scalar_structs

    samples = {"i32": -123456, "u32": 4000000000, "f64": -2.5}
    checked = 0
    for op in g.OPS.values():
        for kind, layout in ((g.KIND_REQUEST, op.request), (g.KIND_REPLY, op.reply)):
            if _scalar_structs(layout)[0] is None:
                continue
            values = tuple(samples[typ] for _, typ in layout)
            general = encode_frame(op.code, kind, 77, encode_payload(layout, values))
            assert encode_message(op.code, kind, 77, values) == general
            assert decode_payload(layout, general[4 + 8 :]) == values
            with pytest.raises(ValueError, match="expected"):
                encode_message(op.code, kind, 77, values + (1,))
            checked += 1
    assert checked > 100  # most calls: PSDGet, VWGetPosition, OSGetCount ...
    with pytest.raises(struct.error):
        encode_message(g.OP_PSD_GET, g.KIND_REQUEST, 1, (2**31,))


def test_a_lone_frame_is_still_held_to_the_decoders_limit():
    frame = encode_message(g.OP_SIM_SET_ROBOT, g.KIND_REQUEST, 5, (0, 1, 2, 3, -4))
    with pytest.raises(ProtocolError) as error:
        FrameDecoder(max_frame=16).feed(frame)
    assert error.value.code == g.ERR_BAD_FRAME
    assert FrameDecoder().feed(frame, limit=0) == []
