"""The shared test vectors (interface/vectors.json): Python encodes and decodes them exactly.

robios/tests/test_protocol.c checks the same vectors with the C codec."""

import json
from pathlib import Path

import pytest

from eyesim.protocol import FrameDecoder, decode_payload, encode_error, encode_message, generated as g

VECTORS = json.loads((Path(__file__).resolve().parents[2] / "interface" / "vectors.json").read_text())["vectors"]


def layout_of(vector):
    if vector["kind"] == "error":
        return g.ERROR_PAYLOAD
    op = g.OPS_BY_NAME[vector["op"]]
    return op.request if vector["kind"] == "request" else op.reply


@pytest.mark.parametrize("vector", VECTORS, ids=[v["name"] for v in VECTORS])
def test_encoding_gives_the_vector_bytes(vector):
    op = g.OPS_BY_NAME[vector["op"]].code
    if vector["kind"] == "error":
        frame = encode_error(op, vector["request_id"], *vector["values"])
    else:
        kind = g.KIND_REQUEST if vector["kind"] == "request" else g.KIND_REPLY
        frame = encode_message(op, kind, vector["request_id"], vector["values"])
    assert frame.hex() == vector["hex"]


@pytest.mark.parametrize("vector", VECTORS, ids=[v["name"] for v in VECTORS])
def test_decoding_the_vector_bytes_gives_the_values(vector):
    (message,) = FrameDecoder().feed(bytes.fromhex(vector["hex"]))
    assert message.op == g.OPS_BY_NAME[vector["op"]].code
    assert message.request_id == vector["request_id"]
    assert list(decode_payload(layout_of(vector), message.payload)) == vector["values"]


def test_a_hand_checked_vector():
    # VW_STRAIGHT request id 0xFFFFFFFF, dist -1000, speed 300: length 16, op 3077 (group vw = 12), kind 0.
    vector = next(v for v in VECTORS if v["name"] == "vw straight negative")
    assert vector["hex"] == "10000000050c0000ffffffff18fcffff2c010000"
