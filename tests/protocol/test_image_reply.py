"""A camera reply written straight from the image is the same frame encode_message makes."""

import numpy as np
import pytest

from eyesim.protocol import encode_image_reply, encode_message, generated as g


@pytest.mark.parametrize("op", [g.OP_CAM_GET, g.OP_CAM_GET_GRAY])
def test_an_image_reply_is_the_same_frame_as_encode_message(op):
    shape = (3, 5, 3) if op == g.OP_CAM_GET else (3, 5)
    image = np.arange(np.prod(shape), dtype=np.uint8).reshape(shape)[::-1]  # not contiguous, as GL's flipped rows
    frame = encode_image_reply(op, 77, (0, 5, 3), image)
    assert bytes(frame) == encode_message(op, g.KIND_REPLY, 77, (0, 5, 3, image.tobytes()))


def test_an_op_whose_reply_has_no_trailing_bytes_is_refused():
    with pytest.raises(ValueError, match="does not end in a bytes field"):
        encode_image_reply(g.OP_OS_GET_COUNT, 1, (), np.zeros(4, dtype=np.uint8))
