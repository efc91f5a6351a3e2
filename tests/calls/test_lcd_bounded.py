"""LCD drawing costs the same for any coordinates: only what can land on the 480x320 screen is
computed, and it draws exactly the pixels the full algorithms would (references below draw every
point of the shape and keep the visible ones)."""

import math
import time
import tracemalloc

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from eyesim.robot.components.lcd import HEIGHT, MAX_PRINT, WIDTH, Lcd

WHITE = 0xFFFFFF
coordinate = st.integers(-700, 1200)


def _fresh() -> Lcd:
    lcd = Lcd()
    lcd.reset()
    return lcd


def _lit(lcd: Lcd) -> set:
    ys, xs = np.nonzero(lcd.screen().any(axis=2)) if hasattr(lcd, "screen") else np.nonzero(lcd.pixels.any(axis=2))
    return set(zip(xs.tolist(), ys.tolist()))


def _visible(points) -> set:
    return {(x, y) for x, y in points if 0 <= x < WIDTH and 0 <= y < HEIGHT}


def _reference_line(x1, y1, x2, y2) -> set:
    steps = max(abs(x2 - x1), abs(y2 - y1))
    if steps == 0:
        return _visible([(x1, y1)])
    return _visible(
        (x1 + (2 * (x2 - x1) * t + steps) // (2 * steps), y1 + (2 * (y2 - y1) * t + steps) // (2 * steps))
        for t in range(steps + 1)
    )


def _reference_circle(cx, cy, r) -> set:
    points, x, y, error = [], r, 0, 1 - r
    while x >= y:
        points += [(x, y), (y, x), (-y, x), (-x, y), (-x, -y), (-y, -x), (y, -x), (x, -y)]
        y += 1
        if error < 0:
            error += 2 * y + 1
        else:
            x -= 1
            error += 2 * (y - x) + 1
    return _visible((cx + dx, cy + dy) for dx, dy in points)


@settings(max_examples=150, deadline=None)
@given(coordinate, coordinate, coordinate, coordinate)
def test_clipped_lines_draw_the_same_pixels(x1, y1, x2, y2):
    lcd = _fresh()
    lcd.line(x1, y1, x2, y2, WHITE)
    assert _lit(lcd) == _reference_line(x1, y1, x2, y2)


@settings(max_examples=150, deadline=None)
@given(coordinate, coordinate, st.integers(0, 900), st.booleans())
def test_clipped_circles_draw_the_same_pixels(cx, cy, radius, fill):
    lcd = _fresh()
    lcd.circle(cx, cy, radius, WHITE, fill)
    if fill:
        expected = _visible(
            (cx + dx, cy + dy)
            for dx in range(-radius, radius + 1)
            for dy in range(-radius, radius + 1)
            if dx * dx + dy * dy <= radius * radius + radius
        )
    else:
        expected = _reference_circle(cx, cy, radius)
    assert _lit(lcd) == expected


@settings(max_examples=100, deadline=None)
@given(coordinate, coordinate, coordinate, coordinate, st.booleans())
def test_clipped_areas_draw_the_same_pixels(x1, y1, x2, y2, fill):
    lcd = _fresh()
    lcd.area(x1, y1, x2, y2, WHITE, fill)
    left, right, top, bottom = min(x1, x2), max(x1, x2), min(y1, y2), max(y1, y2)
    if fill:
        expected = _visible((x, y) for x in range(left, right + 1) for y in range(top, bottom + 1))
    else:
        expected = _visible(
            [(x, y) for x in range(left, right + 1) for y in (top, bottom)]
            + [(x, y) for y in range(top, bottom + 1) for x in (left, right)]
        )
    assert _lit(lcd) == expected


def test_shapes_at_the_int32_limits_use_little_memory_and_still_draw():
    big, small = 2**31 - 1, -(2**31)
    tracemalloc.start()
    lcd = _fresh()
    lcd.line(0, 0, 100_000_000, 0, WHITE)  # once 4 s and 2.5 GB
    lcd.line(small, small, big, big, WHITE)
    lcd.line(big, 5, small, 5, WHITE)
    lcd.area(small, small, big, big, 0x00FF00, False)  # outline all off screen
    lcd.area(small, 100, big, 101, 0x0000FF, True)
    lcd.circle(240, 160 + big, big, 0xFF0000, False)  # an arc through the screen
    lcd.circle(240, 160, big, 0xFF00FF, True)  # covers everything... drawn last below
    lcd.image(0, 0, 2, 2, big, big, 1, bytes([0, 80, 160, 255]))
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 20 * 2**20, f"peak {peak / 2**20:.1f} MB"
    pixels = lcd.pixels
    # the image scaled to 2**31 pixels: its top-left source pixel (0 = black) fills the screen
    assert (pixels == 0).all()


def test_huge_lines_and_arcs_land_where_they_should():
    lcd = _fresh()
    lcd.line(0, 0, 100_000_000, 0, WHITE)
    assert (lcd.pixels[0] == 255).all() and not lcd.pixels[1:].any()
    lcd = _fresh()
    radius = 10**9
    lcd.circle(240, 10 + radius, radius, WHITE, False)  # the top of a huge circle: a flat row at y=10
    lit = _lit(lcd)
    assert {(x, 10) for x in range(WIDTH)} <= lit and all(y in (10, 11) for _, y in lit)
    assert math.isclose(len(lit), WIDTH, rel_tol=0.05)


def _print_each(lcd: Lcd, text: str) -> None:
    for char in text:  # one character per call: never cut, the reference
        lcd.print(char)


@settings(max_examples=100, deadline=None)
@given(
    st.lists(st.text(st.sampled_from("Ab é\t\r\x01"), max_size=70), max_size=120),
    st.sampled_from([0, 0x0800, 0x0200, 0x0400]),
    st.integers(0, 20),
    st.sampled_from([8, 10, 17]),
)
@example(["Ab\t\ré" * (i % 19) for i in range(110)], 0, 3, 10)  # the cut at 42 line feeds, wrapped lines
@example(["x" * 70] * 100, 0x0800, 20, 8)
@example(["ab"] * 43, 0, 0, 10)  # 2 x 21 line feeds from the top row: 21 scrolls, the old screen is gone
@example(["ab"] * 41, 0, 0, 10)  # 40 from the top row: 20 scrolls, a line of the old screen stays
def test_printing_only_what_reaches_the_screen_gives_the_same_screen(lines, mode, start_row, size):
    """Menu hidden (0x0800), no scrolling (0x0200), no line feed (0x0400)."""
    text = "\n".join(lines)
    fast, reference = _fresh(), _fresh()
    for lcd in (fast, reference):
        lcd.set_font_size(size)
        lcd.set_mode(mode)
        lcd.print("X" * 2000)  # text on the screen already, the cursor anywhere on it
        lcd.set_position(start_row % lcd.rows, 0)
    fast.print(text)
    _print_each(reference, text)
    assert (fast.row, fast.column) == (reference.row, reference.column)
    assert (fast.pixels == reference.pixels).all()


def test_a_16_mib_print_costs_milliseconds_and_shows_its_end():
    lcd = _fresh()
    start = time.perf_counter()
    lcd.print("\t\n" * (8 << 20) + "the end")  # once 8 minutes of the simulation thread
    lcd.print("A" * (16 << 20))  # long lines: the last MAX_PRINT characters are drawn
    assert time.perf_counter() - start < 1.0  # generous (about 40 ms); minutes before
    reference = _fresh()
    _print_each(reference, "\n" * 30 + "the end" + "A" * MAX_PRINT)
    assert (lcd.row, lcd.column) == (reference.row, reference.column)
    assert (lcd.pixels == reference.pixels).all()
