"""The wire protocol between RoBIOS programs and the simulator (see interface/protocol.json)."""

from eyesim.protocol import generated
from eyesim.protocol.codec import (
    FrameDecoder,
    Message,
    ProtocolError,
    decode_body,
    decode_payload,
    encode_error,
    encode_frame,
    encode_image_reply,
    encode_message,
    encode_payload,
)

__all__ = [
    "generated",
    "FrameDecoder",
    "Message",
    "ProtocolError",
    "decode_body",
    "decode_payload",
    "encode_error",
    "encode_frame",
    "encode_image_reply",
    "encode_message",
    "encode_payload",
]
