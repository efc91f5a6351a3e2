"""Image processing in libeyesim (robios/src/ip.c) against references computed here with numpy.

The driver (tests/c/ip_driver.c) runs one function on raw images in files. It is built twice: with
`eyesim cc` against libeyesim (the public API, resolutions set by IPSetSize) and together with ip.c
(any size, odd ones included, set through the library-internal es_ip_set_size)."""

from __future__ import annotations

import colorsys
import subprocess
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from support.programs import run_headless

from eyesim.programs import toolchain

ROOT = Path(__file__).resolve().parents[2]
DRIVER = Path(__file__).resolve().parent / "ip_driver.c"
ODD_SIZES = [(1, 1), (2, 2), (3, 3), (7, 5), (1, 9), (13, 1), (31, 17)]
RESOLUTIONS = {"QQVGA": (160, 120), "VGA": (640, 480)}


@pytest.fixture(scope="session")
def drivers(robios_prefix, tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("ip_driver")
    public, direct = out / "ip_public", out / "ip_direct"
    commands = [
        toolchain.compiler_command(
            "cc", ["-std=c11", "-Wall", "-Wextra", "-Werror", str(DRIVER), "-o", str(public)], robios_prefix
        ),
        [
            "cc",
            "-std=c11",
            "-D_GNU_SOURCE",
            "-DIP_DIRECT",
            "-Wall",
            "-Wextra",
            "-Werror",
            f"-I{ROOT / 'robios' / 'include'}",
            f"-I{ROOT / 'robios' / 'src'}",
            str(DRIVER),
            str(ROOT / "robios" / "src" / "ip.c"),
            "-o",
            str(direct),
            "-lpthread",
        ],
    ]
    for command in commands:
        done = subprocess.run(command, capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
    return {"public": public, "direct": direct}


class Driver:
    """Runs the driver at one IP size; images go in and come out as numpy arrays."""

    def __init__(self, exe: Path, size: str, width: int, height: int, work: Path):
        self.exe, self.size, self.width, self.height, self.work = exe, size, width, height, work
        self.count = 0

    def file(self, data: np.ndarray | None = None) -> Path:
        self.count += 1
        path = self.work / f"{self.size}-{self.count}.raw"
        if data is not None:
            path.write_bytes(np.ascontiguousarray(data, dtype=np.uint8).tobytes())
        return path

    def run(self, op: str, *args) -> subprocess.CompletedProcess:
        done = subprocess.run(
            [str(self.exe), self.size, op, *map(str, args)], capture_output=True, text=True, timeout=30
        )
        assert done.returncode == 0, done.stderr
        return done

    def gray(self, path: Path) -> np.ndarray:
        return np.frombuffer(path.read_bytes(), np.uint8).reshape(self.height, self.width)

    def colour(self, path: Path) -> np.ndarray:
        return np.frombuffer(path.read_bytes(), np.uint8).reshape(self.height, self.width, 3)


def driver_cases():
    for size, (w, h) in RESOLUTIONS.items():
        yield pytest.param(("public", size, w, h), id=size)
    for w, h in ODD_SIZES:
        yield pytest.param(("direct", f"{w}x{h}", w, h), id=f"{w}x{h}")


@pytest.fixture(params=list(driver_cases()))
def driver(request, drivers, tmp_path) -> Driver:
    kind, size, w, h = request.param
    return Driver(drivers[kind], size, w, h, tmp_path)


@pytest.fixture
def qqvga(drivers, tmp_path) -> Driver:
    return Driver(drivers["public"], "QQVGA", 160, 120, tmp_path)


def random_image(shape, seed: int) -> np.ndarray:
    """Random pixels with extremes mixed in, so that clipping and the borders are exercised."""
    rng = np.random.default_rng(seed)
    image = rng.integers(0, 256, shape, dtype=np.uint8)
    image[rng.random(shape) < 0.2] = 255
    image[rng.random(shape) < 0.2] = 0
    return image


# ---- numpy references -----------------------------------------------------------------------------


def laplace_reference(gray: np.ndarray) -> np.ndarray:
    c = gray.astype(np.int64)
    out = np.zeros_like(gray)
    inner = 4 * c[1:-1, 1:-1] - c[:-2, 1:-1] - c[2:, 1:-1] - c[1:-1, :-2] - c[1:-1, 2:]
    out[1:-1, 1:-1] = np.minimum(np.abs(inner), 255)
    return out


def sobel_reference(gray: np.ndarray) -> np.ndarray:
    c = gray.astype(np.int64)
    out = np.zeros_like(gray)
    gx = (c[:-2, 2:] + 2 * c[1:-1, 2:] + c[2:, 2:]) - (c[:-2, :-2] + 2 * c[1:-1, :-2] + c[2:, :-2])
    gy = (c[:-2, :-2] + 2 * c[:-2, 1:-1] + c[:-2, 2:]) - (c[2:, :-2] + 2 * c[2:, 1:-1] + c[2:, 2:])
    out[1:-1, 1:-1] = np.minimum((np.abs(gx) + np.abs(gy)) // 3, 255)
    return out


def hsi_reference(rgb: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    r, g, b = (rgb[..., k].astype(np.int64) for k in range(3))
    high, low = np.maximum(np.maximum(r, g), b), np.minimum(np.minimum(r, g), b)
    delta = np.where(high == low, 1, high - low)

    def towards_zero(a):  # C integer division of 42 * a by delta
        return np.sign(a) * (np.abs(42 * a) // delta)

    hue = np.where(
        r == high, 42 + towards_zero(g - b), np.where(g == high, 126 + towards_zero(b - r), 210 + towards_zero(r - g))
    )
    hue = np.where(hue <= 0, hue + 252, hue)
    hue = np.where(high == low, 0, hue)
    total = r + g + b
    saturation = np.where(total == 0, 0, 255 - (765 * low) // np.where(total == 0, 1, total))
    return hue.astype(np.uint8), saturation.astype(np.uint8), (total // 3).astype(np.uint8)


# ---- whole images ---------------------------------------------------------------------------------


def test_the_ip_size_is_published(driver):
    w, h = driver.width, driver.height
    assert driver.run("size").stdout.split() == [str(w), str(h), str(w * h), str(3 * w * h)]


def test_laplace_and_sobel(driver):
    gray = random_image((driver.height, driver.width), seed=driver.width * 1000 + driver.height)
    for op, reference in (("laplace", laplace_reference), ("sobel", sobel_reference)):
        out, in_place = driver.file(), driver.file()
        driver.run(op, driver.file(gray), out, in_place)
        np.testing.assert_array_equal(driver.gray(out), reference(gray), err_msg=op)
        np.testing.assert_array_equal(driver.gray(in_place), reference(gray), err_msg=f"{op} in place")


def test_edges_are_clipped_at_white(qqvga):
    # A vertical step from black to white at column 80: worked out by hand, Laplace gives 255 on
    # both sides of it and Sobel 4 * 255 / 3 = 340, clipped to 255; the border rows stay 0.
    gray = np.zeros((120, 160), np.uint8)
    gray[:, 80:] = 255
    expected = np.zeros_like(gray)
    expected[1:-1, 79:81] = 255
    for op in ("laplace", "sobel"):
        out, in_place = qqvga.file(), qqvga.file()
        qqvga.run(op, qqvga.file(gray), out, in_place)
        np.testing.assert_array_equal(qqvga.gray(out), expected, err_msg=op)


def test_colour_and_gray_conversions(driver):
    rgb = random_image((driver.height, driver.width, 3), seed=driver.width + 7)
    gray = random_image((driver.height, driver.width), seed=driver.height + 11)

    out = driver.file()
    driver.run("col2gray", driver.file(rgb), out)
    np.testing.assert_array_equal(driver.gray(out), (rgb.astype(int).sum(axis=2) // 3).astype(np.uint8))

    out = driver.file()
    driver.run("gray2col", driver.file(gray), out)
    np.testing.assert_array_equal(driver.colour(out), np.repeat(gray[..., None], 3, axis=2))

    out = driver.file()
    driver.run("rgb2col", *(driver.file(rgb[..., k]) for k in range(3)), out)
    np.testing.assert_array_equal(driver.colour(out), rgb)

    h, s, i = driver.file(), driver.file(), driver.file()
    driver.run("col2hsi", driver.file(rgb), h, s, i)
    for got, want, name in zip((h, s, i), hsi_reference(rgb), "HSI"):
        np.testing.assert_array_equal(driver.gray(got), want, err_msg=name)


def test_overlays(driver):
    shape = (driver.height, driver.width)
    base = random_image((*shape, 3), seed=3)
    top = random_image((*shape, 3), seed=4)
    top[np.random.default_rng(5).random(shape) < 0.5] = 0  # half of it black: transparent
    out = driver.file()
    driver.run("overlay", driver.file(base), driver.file(top), out)
    np.testing.assert_array_equal(driver.colour(out), np.where(top.any(axis=2)[..., None], top, base))

    g1 = random_image(shape, seed=6)
    g2 = np.where(np.random.default_rng(7).random(shape) < 0.3, 200, 0).astype(np.uint8)
    out = driver.file()
    driver.run("overlaygray", driver.file(g1), driver.file(g2), "0x12AB34", out)
    expected = np.repeat(g1[..., None], 3, axis=2)
    expected[g2 != 0] = (0x12, 0xAB, 0x34)
    np.testing.assert_array_equal(driver.colour(out), expected)


# ---- single pixels --------------------------------------------------------------------------------


def pixel_records(drivers, tmp_path, rgb: np.ndarray) -> np.ndarray:
    size = int(subprocess.run([str(drivers["public"]), "QQVGA", "record-size"], capture_output=True, text=True).stdout)
    fields = [(name, np.uint8) for name in ("hue", "h", "s", "i", "h2", "s2", "i2", "r", "g", "b")]
    dtype = np.dtype(
        {
            "names": [n for n, _ in fields] + ["col"],
            "formats": [t for _, t in fields] + ["<i4"],
            "offsets": list(range(10)) + [12],
            "itemsize": size,
        }
    )
    (tmp_path / "rgb.raw").write_bytes(rgb.astype(np.uint8).tobytes())
    subprocess.run(
        [
            str(drivers["public"]),
            "QQVGA",
            "pixels",
            str(tmp_path / "rgb.raw"),
            str(tmp_path / "out.raw"),
            str(len(rgb)),
        ],
        check=True,
    )
    return np.frombuffer((tmp_path / "out.raw").read_bytes(), dtype)


def test_pixel_functions(drivers, tmp_path):
    steps = np.arange(0, 256, 5)
    grid = np.stack(np.meshgrid(steps, steps, steps, indexing="ij"), axis=-1).reshape(-1, 3)
    rgb = np.concatenate(
        [
            grid,
            np.random.default_rng(1).integers(0, 256, (20000, 3)),
            [[0, 0, 0], [255, 255, 255], [7, 7, 7], [255, 0, 255], [255, 0, 1], [1, 0, 0]],
        ]
    )
    records = pixel_records(drivers, tmp_path, rgb)
    r, g, b = (rgb[:, k] for k in range(3))
    np.testing.assert_array_equal(records["col"], (r << 16) | (g << 8) | b)
    for field, channel in zip("rgb", (r, g, b)):
        np.testing.assert_array_equal(records[field], channel)
    hue, saturation, intensity = hsi_reference(rgb)
    for name, want in (
        ("hue", hue),
        ("h", hue),
        ("h2", hue),
        ("s", saturation),
        ("s2", saturation),
        ("i", intensity),
        ("i2", intensity),
    ):
        np.testing.assert_array_equal(records[name], want, err_msg=name)


def test_hue_follows_the_colour_circle(drivers, tmp_path):
    """Independently of the integer formula: hue = HSV hue on 252 steps, turned so that red is 42."""
    rgb = np.random.default_rng(2).integers(0, 256, (5000, 3))
    rgb = rgb[rgb.max(axis=1) != rgb.min(axis=1)]
    records = pixel_records(drivers, tmp_path, rgb)
    expected = np.array([colorsys.rgb_to_hsv(*(c / 255))[0] * 252 + 42 for c in rgb]) % 252
    distance = np.abs(records["hue"] - expected)
    assert (np.minimum(distance, 252 - distance) <= 1).all()
    assert records["hue"].min() >= 1 and records["hue"].max() <= 252
    named = pixel_records(
        drivers,
        tmp_path,
        np.array([[255, 0, 0], [255, 255, 0], [0, 255, 0], [0, 255, 255], [0, 0, 255], [255, 0, 255], [9, 9, 9]]),
    )
    assert list(named["hue"]) == [42, 84, 126, 168, 210, 252, 0]
    assert list(named["s"]) == [255] * 6 + [0]


def test_bad_buffers_are_reported_not_crashed_on(drivers):
    done = subprocess.run([str(drivers["public"]), "QVGA", "nulls"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["-1", "-1", "1", "1", "1", "1"]
    for function in (
        "IPLaplace",
        "IPSobel",
        "IPCol2Gray",
        "IPGray2Col",
        "IPRGB2Col",
        "IPCol2HSI",
        "IPOverlay",
        "IPOverlayGray",
        "IPReadFile",
        "IPWriteFile",
        "IPWriteFileGray",
    ):
        assert f"eyesim: {function}: " in done.stderr
    assert "eyesim: IPSetSize: resolution 10 has no fixed size" in done.stderr


# ---- PNM files ------------------------------------------------------------------------------------


def pnm_bytes(magic: str, pixels: np.ndarray, maxval: int = 255, comment: str = "") -> bytes:
    """A PNM file written here, independently of the library: pixels HxW (P1/P2/P4/P5) or HxWx3."""
    h, w = pixels.shape[:2]
    header = f"{magic}\n{comment}{w} {h}\n" + ("" if magic in ("P1", "P4") else f"{maxval}\n")
    if magic in ("P1", "P2", "P3"):
        flat = pixels.reshape(h, -1)
        joiner = "" if magic == "P1" else " "  # plain PBM digits need no spaces between them
        return (header + "\n".join(joiner.join(str(v) for v in row) for row in flat) + "\n").encode()
    if magic == "P4":
        return header.encode() + np.packbits(pixels.astype(np.uint8), axis=1).tobytes()
    dtype = ">u2" if maxval > 255 else np.uint8
    return header.encode() + pixels.astype(dtype).tobytes()


def scaled(values: np.ndarray, maxval: int) -> np.ndarray:
    return ((values.astype(np.int64) * 255 + maxval // 2) // maxval).astype(np.uint8)


def read_file(driver: Driver, content: bytes) -> tuple[int, np.ndarray, str]:
    path, out = driver.file(), driver.file()
    path.write_bytes(content)
    done = driver.run("read", path, out)
    return int(done.stdout), np.frombuffer(out.read_bytes(), np.uint8), done.stderr


def place(image: np.ndarray, width: int, height: int) -> np.ndarray:
    """The image cropped or filled with black to width x height."""
    out = np.zeros((height, width) + image.shape[2:], np.uint8)
    h, w = min(height, image.shape[0]), min(width, image.shape[1])
    out[:h, :w] = image[:h, :w]
    return out


@pytest.mark.parametrize(
    "magic,shape,maxval",
    [
        ("P6", (120, 160, 3), 255),  # exactly the IP size
        ("P3", (150, 200, 3), 255),  # larger: cropped
        ("P6", (23, 37, 3), 15),  # smaller, odd: filled with black; scaled up
        ("P6", (121, 161, 3), 65535),  # 16-bit samples
        ("P5", (120, 160), 255),
        ("P2", (131, 77), 1000),
        ("P5", (45, 301), 65535),
    ],
)
def test_read_colour_and_gray_files(qqvga, magic, shape, maxval):
    values = np.random.default_rng(maxval).integers(0, maxval + 1, shape)
    values.flat[0], values.flat[-1] = maxval, 0
    code, out, stderr = read_file(qqvga, pnm_bytes(magic, values, maxval, comment="# made by test_ip\n"))
    assert stderr == ""
    expected = place(scaled(values, maxval), 160, 120)
    if len(shape) == 3:
        assert code == 3
        np.testing.assert_array_equal(out.reshape(120, 160, 3), expected)
    else:
        assert code == 2
        np.testing.assert_array_equal(out[: 160 * 120].reshape(120, 160), expected)
        assert (out[160 * 120 :] == 0xAB).all()  # a gray image fills only IP_PIXELS bytes


@pytest.mark.parametrize("magic,shape", [("P1", (9, 13)), ("P4", (130, 171)), ("P4", (120, 160))])
def test_read_black_and_white_files(qqvga, magic, shape):
    bits = np.random.default_rng(shape[1]).integers(0, 2, shape)
    code, out, _ = read_file(qqvga, pnm_bytes(magic, bits))
    assert code == 1
    gray = np.where(bits == 1, 0, 255).astype(np.uint8)  # 1 is black in a PBM
    np.testing.assert_array_equal(out[: 160 * 120].reshape(120, 160), place(gray, 160, 120))


def test_read_accepts_comments_and_odd_whitespace(qqvga):
    content = b"P2 # gray\n# another comment\n3\t2 #size\n 9\n0 3\n6 9 # row end\n9 0\n"
    code, out, _ = read_file(qqvga, content)
    assert code == 2
    assert list(out[:3]) == [0, 85, 170] and list(out[160:163]) == [255, 255, 0]


@pytest.mark.parametrize(
    "content,message",
    [
        (None, "cannot open"),
        (b"GIF89a", "is not a PNM file"),
        (b"P6\n0 5\n255\n", "bad width and height"),
        (b"P5\n4 4\n70000\n", "bad maxval"),
        (b"P6\n4 4\n255\n" + bytes(40), "ends before all of its 4 x 4 pixels"),
        (b"P2\n2 1\n100\n5 101\n", "larger than the maxval"),
        (b"P1\n2 1\n0 7\n", "holds only 0 and 1"),
        (b"P3\n2 1\n255\n1 2 3 4 x", "expected a number"),
    ],
)
def test_bad_files_are_reported_and_leave_the_buffer_alone(qqvga, content, message):
    path, out = qqvga.file(), qqvga.file()
    if content is not None:
        path.write_bytes(content)
    done = qqvga.run("read", path, out)
    assert done.stdout.strip() == "-1"
    assert "eyesim: IPReadFile: " in done.stderr and message in done.stderr
    assert set(out.read_bytes()) == {0xAB}


def test_write_files_that_other_programs_read(qqvga, tmp_path):
    rgb = random_image((120, 160, 3), seed=9)
    gray = random_image((120, 160), seed=10)
    done = qqvga.run("write", qqvga.file(rgb), tmp_path / "c.ppm")
    assert done.stdout.strip() == "0"
    done = qqvga.run("writegray", qqvga.file(gray), tmp_path / "g.pgm")
    assert done.stdout.strip() == "0"
    assert (tmp_path / "c.ppm").read_bytes().startswith(b"P6\n160 120\n255\n")
    assert (tmp_path / "g.pgm").read_bytes().startswith(b"P5\n160 120\n255\n")
    np.testing.assert_array_equal(np.asarray(Image.open(tmp_path / "c.ppm")), rgb)
    np.testing.assert_array_equal(np.asarray(Image.open(tmp_path / "g.pgm")), gray)
    # ... and read them back unchanged.
    code, out, _ = read_file(qqvga, (tmp_path / "c.ppm").read_bytes())
    assert code == 3 and (out.reshape(120, 160, 3) == rgb).all()


def test_write_failures_are_reported(qqvga, tmp_path):
    done = qqvga.run("write", qqvga.file(np.zeros(160 * 120 * 3)), tmp_path / "no-such-dir" / "x.ppm")
    assert done.stdout.strip() == "1"
    assert "eyesim: IPWriteFile: cannot create" in done.stderr and "No such file" in done.stderr


CAMERA_PROGRAM = r"""
#include "eyebot.h"

int main(void)
{
    static QQVGAcol frame;
    static QQVGAgray gray, edges;
    if (CAMInit(QQVGA) != 0 || IP_WIDTH != QQVGA_X || IP_HEIGHT != QQVGA_Y) /* CAMInit sets the IP size */
        return 3;
    CAMGet(frame);
    IPCol2Gray(frame, gray);
    IPLaplace(gray, edges);
    LCDImageGray(edges); /* CAMInit set the LCD image size too */
    return IPWriteFile("frame.ppm", frame) || IPWriteFileGray("edges.pgm", edges);
}
"""


def test_a_camera_frame_goes_through_ip_to_the_lcd(robios_prefix, tmp_path):
    """A C program against a running simulator: CAMInit sets the IP size; the results match numpy."""
    (tmp_path / "camera.c").write_text(CAMERA_PROGRAM)
    command = toolchain.compiler_command(
        "cc",
        ["-std=c11", "-Wall", "-Wextra", "-Werror", str(tmp_path / "camera.c"), "-o", str(tmp_path / "camera")],
        robios_prefix,
    )
    subprocess.run(command, check=True)
    result = run_headless("--program", f"1={tmp_path / 'camera'}", "--save-lcd", "lcd", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    frame = np.asarray(Image.open(tmp_path / "frame.ppm")).astype(int)
    assert frame.shape == (120, 160, 3) and frame.max() > 0
    expected = laplace_reference((frame.sum(axis=2) // 3).astype(np.uint8))
    edges = np.asarray(Image.open(tmp_path / "edges.pgm"))
    np.testing.assert_array_equal(edges, expected)
    lcd = np.asarray(Image.open(tmp_path / "lcd" / "robot1-lcd.png").convert("RGB"))
    np.testing.assert_array_equal(lcd[:120, :160], np.repeat(expected[..., None], 3, axis=2))
