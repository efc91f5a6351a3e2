"""The LCD group against a running simulator: text grid, modes, fonts, graphics, images, menu, errors.

Pixels are read back with LCD_GET_PIXEL (what the program drew) and from the LCD's screen (what
the viewer shows)."""

import numpy as np
import pytest
from support.client import RemoteError
from support.connected import connected_program

from eyesim.robot.components.lcd import (
    CELL_HEIGHT,
    CELL_WIDTH,
    COLUMNS,
    HEIGHT,
    MENU_HEIGHT,
    ROWS,
    WIDTH,
    Lcd,
)

RED, GREEN, BLUE, WHITE, BLACK, YELLOW = 0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF, 0x000000, 0xFFFF00
LCD_AUTOREFRESH, LCD_NOAUTOREFRESH = 0x0001, 0x0100
LCD_NOSCROLLING, LCD_NOLINEFEED = 0x0200, 0x0400
LCD_SHOWMENU, LCD_HIDEMENU, LCD_FB_ROTATE = 0x0008, 0x0800, 0x0080


@pytest.fixture
def program():
    with connected_program() as (sim, client):
        yield sim, client


def screen(sim) -> np.ndarray:
    return sim.robots[0].component(Lcd).screen().copy()


def pixel(client, x, y) -> int:
    return client.call("LCD_GET_PIXEL", x, y)[0]


def ink_rows(image: np.ndarray) -> set[int]:
    """Text rows (of the default grid) with any lit pixel."""
    return {y // CELL_HEIGHT for y in np.flatnonzero(image[: ROWS * CELL_HEIGHT].any(axis=(1, 2)))}


def test_the_default_grid_is_eyesims_80_columns_by_21_rows_above_the_menu_bar(program):
    """EyeSim's default font is X11's 6x13: 480 / 6 = 80 columns, (320 - 38) / 13 = 21 rows."""
    sim, client = program
    assert (CELL_WIDTH, CELL_HEIGHT, COLUMNS, ROWS, MENU_HEIGHT) == (6, 13, 80, 21, 38)
    assert client.call("LCD_GET_SIZE") == (0, 480, 320)
    client.call("LCD_PRINTF", "x" * 80)
    assert client.call("LCD_GET_POS") == (0, 0, 80)  # the line is full; the next character wraps
    client.call("LCD_PRINTF", "y")
    assert client.call("LCD_GET_POS") == (0, 1, 1)
    assert sim.robots[0].component(Lcd).text_rows() == ["x" * 80, "y"]
    client.call("LCD_SET_PRINTF", 20, 79, "z")  # the last cell exists
    with pytest.raises(RemoteError, match="row 21 is outside the text rows 0..20"):
        client.call("LCD_SET_POS", 21, 0)
    with pytest.raises(RemoteError, match="column 80 is outside the text columns 0..79"):
        client.call("LCD_SET_POS", 0, 80)
    with pytest.raises(RemoteError, match="column 80 is outside"):
        client.call("LCD_SET_PRINTF", 0, 80, "a")


def test_newlines_tabs_and_carriage_returns_move_the_cursor_like_a_terminal(program):
    sim, client = program
    client.call("LCD_PRINTF", "ab\ncd\tX")
    assert client.call("LCD_GET_POS") == (0, 1, 5)
    client.call("LCD_PRINTF", "\rQ")
    assert client.call("LCD_GET_POS") == (0, 1, 1)
    client.call("LCD_CLEAR")
    assert client.call("LCD_GET_POS") == (0, 0, 0)
    assert not screen(sim).any()


def test_printing_past_the_last_row_scrolls_the_text_up(program):
    sim, client = program
    client.call("LCD_PRINTF", "top\n" + "\n" * (ROWS - 2) + "bottom")
    before = screen(sim)
    assert ink_rows(before) == {0, ROWS - 1}
    client.call("LCD_PRINTF", "\n")
    after = screen(sim)
    assert ink_rows(after) == {ROWS - 2}  # "top" scrolled away, "bottom" moved up one row
    bottom = slice((ROWS - 1) * CELL_HEIGHT, ROWS * CELL_HEIGHT)
    above = slice((ROWS - 2) * CELL_HEIGHT, (ROWS - 1) * CELL_HEIGHT)
    assert np.array_equal(after[above], before[bottom])
    assert client.call("LCD_GET_POS") == (0, ROWS - 1, 0)


def test_without_scrolling_the_text_continues_at_the_top(program):
    sim, client = program
    client.call("LCD_SET_MODE", LCD_NOSCROLLING)
    client.call("LCD_PRINTF", "\n" * (ROWS - 1) + "last\nfirst again")
    assert client.call("LCD_GET_POS") == (0, 0, 11)
    assert ink_rows(screen(sim)) == {0, ROWS - 1}


def test_without_line_feed_text_beyond_the_last_column_is_cut_off(program):
    sim, client = program
    client.call("LCD_SET_MODE", LCD_NOLINEFEED)
    client.call("LCD_PRINTF", "x" * 90)
    assert client.call("LCD_GET_POS") == (0, 0, 80)
    assert ink_rows(screen(sim)) == {0}
    client.call("LCD_PRINTF", "\nnext")
    assert client.call("LCD_GET_POS") == (0, 1, 4)


def test_text_is_drawn_in_its_colours_and_getpixel_returns_exactly_that(program):
    sim, client = program
    client.call("LCD_SET_COLOR", RED, BLUE)
    client.call("LCD_PRINTF", "#")
    cell = screen(sim)[:CELL_HEIGHT, :CELL_WIDTH].reshape(-1, 3)
    colours = {tuple(int(v) for v in p) for p in cell}
    assert (255, 0, 0) in colours and (0, 0, 255) in colours  # glyph and background
    assert all(g == 0 and r + b in range(254, 257) for r, g, b in colours)  # only blends of the two
    for y in range(CELL_HEIGHT):
        for x in range(CELL_WIDTH):
            r, g, b = (int(v) for v in screen(sim)[y, x])
            assert pixel(client, x, y) == (r << 16) | (g << 8) | b


def test_fonts_and_variations_look_different_and_sizes_change_the_grid(program):
    sim, client = program
    shapes = set()
    for font in (0, 1, 2):
        for variation in (0, 1, 2, 3):
            client.call("LCD_CLEAR")
            client.call("LCD_SET_FONT", font, variation)
            client.call("LCD_PRINTF", "Agy")
            shapes.add(screen(sim)[:CELL_HEIGHT, : 3 * CELL_WIDTH].tobytes())
    assert len(shapes) == 12
    client.call("LCD_CLEAR")
    client.call("LCD_SET_FONT_SIZE", 24)  # 15 x 32 pixel cells: 32 columns, 8 rows
    client.call("LCD_PRINTF", "M" * 33)
    assert client.call("LCD_GET_POS") == (0, 1, 1)
    lit = np.flatnonzero(screen(sim).any(axis=(1, 2)))
    assert lit.max() > 32 and lit.max() < 64
    with pytest.raises(RemoteError, match="font size 7 is outside 8..24"):
        client.call("LCD_SET_FONT_SIZE", 7)
    with pytest.raises(RemoteError, match="font 3 is not"):
        client.call("LCD_SET_FONT", 3, 0)
    with pytest.raises(RemoteError, match="variation 4 is not"):
        client.call("LCD_SET_FONT", 0, 4)


def test_pixels_lines_areas_and_circles_read_back_exactly(program):
    sim, client = program
    client.call("LCD_PIXEL", 5, 7, 0x123456)
    assert pixel(client, 5, 7) == 0x123456
    client.call("LCD_PIXEL", 480, 0, RED)  # off the screen: clipped, no error
    client.call("LCD_LINE", 10, 100, 60, 100, GREEN)
    assert all(pixel(client, x, 100) == GREEN for x in (10, 35, 60))
    assert pixel(client, 61, 100) == BLACK and pixel(client, 9, 100) == BLACK
    client.call("LCD_LINE", 100, 100, 120, 120, WHITE)  # 45 degrees: every pixel of the diagonal
    assert all(pixel(client, 100 + k, 100 + k) == WHITE for k in range(21))
    client.call("LCD_AREA", 200, 50, 210, 60, BLUE, 1)
    assert pixel(client, 205, 55) == BLUE and pixel(client, 210, 60) == BLUE and pixel(client, 211, 60) == BLACK
    client.call("LCD_AREA", 230, 60, 220, 50, RED, 0)  # corners in any order; an outline
    assert pixel(client, 220, 50) == RED and pixel(client, 230, 55) == RED and pixel(client, 225, 55) == BLACK
    client.call("LCD_CIRCLE", 300, 200, 20, YELLOW, 1)
    assert pixel(client, 300, 200) == YELLOW and pixel(client, 320, 200) == YELLOW
    assert pixel(client, 321, 200) == BLACK and pixel(client, 315, 215) == BLACK  # outside the radius
    client.call("LCD_CIRCLE", 400, 200, 20, WHITE, 0)
    for x, y in ((420, 200), (380, 200), (400, 180), (400, 220)):
        assert pixel(client, x, y) == WHITE
    assert pixel(client, 400, 200) == BLACK
    drawn = screen(sim)
    assert ((drawn == 255).all(axis=2)).sum() > 100  # the outline and the diagonal are visible


def test_images_in_colour_gray_and_binary_are_placed_and_scaled(program):
    _sim, client = program
    colour = bytes([255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255])  # 2 x 2: red green / blue white
    client.call("LCD_IMAGE", 10, 20, 2, 2, 2, 2, 0, colour)
    assert [pixel(client, x, y) for y in (20, 21) for x in (10, 11)] == [RED, GREEN, BLUE, WHITE]
    client.call("LCD_IMAGE", 100, 100, 2, 2, 40, 20, 0, colour)  # each pixel becomes 20 x 10
    assert pixel(client, 100, 100) == RED and pixel(client, 119, 109) == RED and pixel(client, 120, 109) == GREEN
    assert pixel(client, 139, 119) == WHITE and pixel(client, 140, 119) == BLACK
    client.call("LCD_IMAGE", 0, 200, 3, 1, 3, 1, 1, bytes([0, 128, 255]))
    assert [pixel(client, x, 200) for x in range(3)] == [0, 0x808080, WHITE]
    client.call("LCD_IMAGE", 0, 210, 3, 1, 3, 1, 2, bytes([1, 0, 1]))  # 1 = black, 0 = white
    assert [pixel(client, x, 210) for x in range(3)] == [BLACK, WHITE, BLACK]
    client.call("LCD_IMAGE", 470, 310, 2, 2, 20, 20, 0, colour)  # partly off the screen: clipped
    assert pixel(client, 479, 319) == RED
    with pytest.raises(RemoteError, match="a 2x2 image needs 12 bytes, got 3"):
        client.call("LCD_IMAGE", 0, 0, 2, 2, 2, 2, 0, b"abc")
    with pytest.raises(RemoteError, match="image format 5"):
        client.call("LCD_IMAGE", 0, 0, 1, 1, 1, 1, 5, b"a")


def test_menu_entries_have_their_colours_and_hiding_the_menu_frees_its_rows(program):
    sim, client = program
    client.call("LCD_MENU", "A", "B", "C", "D")
    client.call("LCD_MENU_I", 1, "GO", BLACK, GREEN)  # positions count from 0, as on EyeSim: 1 is KEY2
    bar_top = HEIGHT - MENU_HEIGHT
    assert pixel(client, 125, bar_top + 4) == GREEN  # inside KEY2's button
    assert pixel(client, 5, bar_top + 4) != GREEN
    assert sim.robots[0].component(Lcd).menu == ["A", "GO", "C", "D"]
    client.call("LCD_SET_MODE", LCD_HIDEMENU)
    assert not screen(sim)[bar_top:].any()
    client.call("LCD_SET_POS", 23, 0)  # 320 // 13 = 24 rows without the menu
    client.call("LCD_SET_MODE", LCD_SHOWMENU)
    assert pixel(client, 125, bar_top + 4) == GREEN
    assert client.call("LCD_GET_POS")[1] == ROWS - 1  # the cursor stays on the screen's text rows
    for position in (-1, 4):
        with pytest.raises(RemoteError, match=rf"menu position {position} is not 0\.\.3 \(0 is KEY1"):
            client.call("LCD_MENU_I", position, "x", WHITE, BLACK)


def test_menu_entries_count_from_0_as_on_eyesim(program):
    """EyeSim's graphics example labels the four keys with LCDMenuI(0..3): each lands on its key."""
    sim, client = program
    colours = (BLUE, WHITE, RED, GREEN)
    for position, (label, colour) in enumerate(zip(("One", "Two", "Three", "Four"), colours)):
        assert client.call("LCD_MENU_I", position, label, BLACK, colour) == (0,)
    assert sim.robots[0].component(Lcd).menu == ["One", "Two", "Three", "Four"]
    bar_top = HEIGHT - MENU_HEIGHT
    assert [pixel(client, 120 * key + 5, bar_top + 4) for key in range(4)] == list(colours)


def test_without_auto_refresh_the_screen_changes_only_on_refresh(program):
    sim, client = program
    client.call("LCD_SET_MODE", LCD_NOAUTOREFRESH)
    client.call("LCD_AREA", 0, 0, 99, 99, RED, 1)
    assert pixel(client, 50, 50) == RED  # drawn ...
    assert not screen(sim)[50, 50].any()  # ... but not shown yet
    client.call("LCD_REFRESH")
    assert tuple(screen(sim)[50, 50]) == (255, 0, 0)
    client.call("LCD_SET_MODE", LCD_AUTOREFRESH)
    client.call("LCD_PIXEL", 200, 200, GREEN)
    assert tuple(screen(sim)[200, 200]) == (0, 255, 0)


def test_a_rotated_lcd_shows_its_image_turned_while_getpixel_keeps_program_coordinates(program):
    sim, client = program
    client.call("LCD_PIXEL", 0, 0, RED)
    client.call("LCD_SET_MODE", LCD_FB_ROTATE)
    assert tuple(screen(sim)[HEIGHT - 1, WIDTH - 1]) == (255, 0, 0)
    assert pixel(client, 0, 0) == RED


def test_bad_arguments_get_clear_errors(program):
    _sim, client = program
    for op, args, message in [
        ("LCD_SET_COLOR", (-1, 0), "foreground -1 is not a 0xRRGGBB colour"),
        ("LCD_PIXEL", (0, 0, 0x1000000), "colour 0x1000000 is not a 0xRRGGBB colour"),
        ("LCD_GET_PIXEL", (480, 0), r"pixel \(480, 0\) is outside the 480x320 screen"),
        ("LCD_SET_MODE", (0x0202,), "turns one setting both on"),
        ("LCD_SET_MODE", (0x0020,), "unknown flag bits 0x20"),
        ("LCD_CIRCLE", (10, 10, -1, 0, 1), "radius -1 is negative"),
        ("LCD_SET_PRINTF", (-1, 0, "x"), "row -1 is outside"),
    ]:
        with pytest.raises(RemoteError, match=message):
            client.call(op, *args)
    assert client.call("LCD_GET_POS") == (0, 0, 0)
