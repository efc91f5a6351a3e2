"""The image-processing wrappers: eye.py's conventions (new buffers back, [code, image] from IPReadFile,
lists from the pixel functions), every kind of buffer a program may pass, and clear errors.
(The C results themselves are checked against numpy in tests/c/test_ip.py.)"""

from __future__ import annotations

import ctypes

import numpy as np
import pytest
from PIL import Image


@pytest.fixture
def ip(eye):
    eye.IPSetSize(eye.QQVGA)
    return eye


def as_array(buffer, shape) -> np.ndarray:
    return np.frombuffer(bytes(buffer), np.uint8).reshape(shape)


def step_image() -> np.ndarray:
    gray = np.zeros((120, 160), np.uint8)
    gray[:, 80:] = 200
    return gray


def test_filters_return_new_buffers_of_the_ip_size(ip):
    gray = step_image()
    edges = ip.IPLaplace(gray)
    assert isinstance(edges, ctypes.Array) and len(edges) == 160 * 120
    expected = np.zeros((120, 160), np.uint8)
    expected[1:-1, 79:81] = 200
    np.testing.assert_array_equal(as_array(edges, (120, 160)), expected)
    assert as_array(ip.IPSobel(gray), (120, 160))[60, 80] == 255  # 4 * 200 / 3, clipped
    assert max(edges) == 200 and min(edges) == 0  # unsigned values, not eye.py's negative c_bytes


def test_every_kind_of_buffer_is_accepted(ip):
    gray = step_image()
    expected = bytes(ip.IPLaplace(gray))
    signed = (ctypes.c_byte * gray.size)(*[v - 256 if v > 127 else v for v in gray.flatten().tolist()])
    for kind in (
        gray,
        gray.tobytes(),
        bytearray(gray.tobytes()),
        memoryview(gray.tobytes()),
        signed,
        gray.flatten().tolist(),
        (ctypes.c_ubyte * gray.size).from_buffer_copy(gray.tobytes()),
    ):
        assert bytes(ip.IPLaplace(kind)) == expected, type(kind)


def test_an_output_buffer_is_filled_in_place(ip):
    out = np.zeros((120, 160), np.uint8)
    result = ip.IPLaplace(step_image(), out)
    assert out[60, 79] == 200 and bytes(result) == out.tobytes()
    colour = np.zeros((120, 160, 3), np.uint8)
    ip.IPGray2Col(step_image(), colour)
    assert (colour[:, 80:] == 200).all() and (colour[:, :80] == 0).all()


def test_colour_conversions(ip):
    rng = np.random.default_rng(4)
    rgb = rng.integers(0, 256, (120, 160, 3), dtype=np.uint8)
    gray = as_array(ip.IPCol2Gray(rgb), (120, 160))
    np.testing.assert_array_equal(gray, (rgb.astype(int).sum(axis=2) // 3).astype(np.uint8))
    planes = [rgb[..., k].copy() for k in range(3)]
    np.testing.assert_array_equal(as_array(ip.IPRGB2Col(*planes), (120, 160, 3)), rgb)
    h, s, i = ip.IPCol2HSI(rgb)
    assert len(h) == len(s) == len(i) == 160 * 120
    assert [h[0], s[0], i[0]] == ip.IPPRGB2HSI(*rgb[0, 0].tolist())
    top = np.zeros_like(rgb)
    top[:60] = 255
    np.testing.assert_array_equal(as_array(ip.IPOverlay(rgb, top), (120, 160, 3)), np.concatenate([top[:60], rgb[60:]]))
    marked = as_array(ip.IPOverlayGray(step_image(), step_image(), ip.RED), (120, 160, 3))
    assert tuple(marked[0, 100]) == (255, 0, 0) and tuple(marked[0, 10]) == (0, 0, 0)


def test_pixel_functions_return_ints_and_lists(ip):
    assert ip.IPPRGB2Col(0x12, 0x34, 0x56) == 0x123456
    assert ip.IPPCol2RGB(0x123456) == [0x12, 0x34, 0x56]
    assert ip.IPPRGB2Hue(0, 0, 255) == 210 and ip.IPPRGB2Hue(9, 9, 9) == 0
    assert ip.IPPCol2HSI(ip.GREEN) == [126, 255, 85]
    assert ip.IPPRGB2HSI(255, 255, 255) == [0, 0, 255]
    assert ip.IPPRGB2Col(-1, 0, -128) == 0xFF0080  # eye.py's signed pixel values
    with pytest.raises(ValueError, match=r"IPPRGB2Hue: g = 256 is not a byte value \(0 .. 255\)"):
        ip.IPPRGB2Hue(0, 256, 0)


def test_files(ip, tmp_path):
    rgb = np.random.default_rng(5).integers(0, 256, (120, 160, 3), dtype=np.uint8)
    assert ip.IPWriteFile(tmp_path / "c.ppm", rgb) == 0
    np.testing.assert_array_equal(np.asarray(Image.open(tmp_path / "c.ppm")), rgb)
    code, image = ip.IPReadFile(str(tmp_path / "c.ppm"))
    assert code == 3 and bytes(image) == rgb.tobytes()

    Image.fromarray(rgb[:50, :70, 0]).save(tmp_path / "g.pgm")  # smaller: filled with black
    code, gray = ip.IPReadFile(tmp_path / "g.pgm")
    assert code == 2 and len(gray) == 160 * 120
    expected = np.zeros((120, 160), np.uint8)
    expected[:50, :70] = rgb[:50, :70, 0]
    np.testing.assert_array_equal(as_array(gray, (120, 160)), expected)
    assert ip.IPWriteFileGray(tmp_path / "g2.pgm", gray) == 0
    np.testing.assert_array_equal(np.asarray(Image.open(tmp_path / "g2.pgm")), expected)

    buffer = bytearray(160 * 120 * 3)  # C style: the caller's buffer, the code back
    assert ip.IPReadFile(tmp_path / "c.ppm", buffer) == 3 and bytes(buffer) == rgb.tobytes()
    assert ip.IPReadFile(tmp_path / "missing.ppm") == [-1, None]


def test_the_ip_size_decides_the_buffer_sizes(ip):
    assert ip.IPSetSize(ip.CUSTOM) == 1  # no size of its own: refused, the size stays
    assert len(ip.IPCol2Gray(bytes(160 * 120 * 3))) == 160 * 120
    assert ip.IPSetSize(ip.QVGA) == 0
    assert len(ip.IPGray2Col(bytes(320 * 240))) == 320 * 240 * 3
    with pytest.raises(
        ValueError,
        match=r"IPGray2Col: the gray image has 19200 bytes, but 76800 are needed "
        r"\(the IP size is 320 x 240\)",
    ):
        ip.IPGray2Col(bytes(160 * 120))


@pytest.mark.parametrize(
    "call,error,message",
    [
        (lambda ip: ip.IPLaplace("image"), TypeError, "IPLaplace: the gray image must be an image buffer"),
        (lambda ip: ip.IPLaplace(None), TypeError, "IPLaplace: the gray image must be an image buffer"),
        (lambda ip: ip.IPLaplace(bytes(19200), bytes(19200)), TypeError, "the output image must be a writable"),
        (lambda ip: ip.IPLaplace(bytes(19200), bytearray(10)), ValueError, "the output image has 10 bytes"),
        (lambda ip: ip.IPCol2Gray([1, 2, 3]), ValueError, "the colour image has 3 bytes, but 57600"),
    ],
)
def test_bad_buffers_raise_clear_errors(ip, call, error, message):
    with pytest.raises(error, match=message):
        call(ip)
