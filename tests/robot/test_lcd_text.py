"""The LCD's text layer: what text it shows where, as tests and graders read it (no OCR)."""

from eyesim.robot.components.lcd import AUTOREFRESH, Lcd


def test_printed_text_is_read_back_by_row_and_column():
    lcd = Lcd()
    lcd.print("Hello\n")
    lcd.set_position(2, 4)
    lcd.print("x=12")
    assert lcd.text_rows() == ["Hello", "", "    x=12"]


def test_overwriting_replaces_text_and_blanks_erase_it():
    lcd = Lcd()
    lcd.set_position(0, 0)
    lcd.print("front 1234 mm")
    lcd.set_position(0, 0)
    lcd.print("front   12   ")
    assert lcd.text_rows() == ["front   12"]


def test_clear_and_filled_areas_remove_text_but_lines_leave_it():
    lcd = Lcd()
    lcd.print("one\ntwo\nthree")
    lcd.line(0, 0, 100, 40, 0xFF0000)
    assert lcd.text_rows() == ["one", "two", "three"]
    lcd.area(0, 13, 479, 25, 0x00FF00, True)  # covers the second row
    assert lcd.text_rows() == ["one", "", "three"]
    lcd.clear()
    assert lcd.text_rows() == []


def test_scrolling_moves_the_text_up():
    lcd = Lcd()
    for n in range(lcd.rows + 2):
        lcd.print(f"line {n}\n")
    rows = lcd.text_rows()
    assert rows[0] == "line 3" and rows[lcd.rows - 2] == f"line {lcd.rows + 1}"


def test_a_larger_font_uses_its_own_grid():
    lcd = Lcd()
    lcd.set_font_size(20)
    lcd.set_position(1, 0)
    lcd.print("BIG")
    lcd.set_font_size(10)
    lcd.set_position(0, 0)
    lcd.print("small")
    assert lcd.text_rows() == ["small", "BIG"]


def test_without_auto_refresh_the_text_shown_waits_for_refresh():
    lcd = Lcd()
    lcd.print("before")
    lcd.set_mode(AUTOREFRESH << 8)
    lcd.print(" after")
    assert lcd.text_rows() == ["before"]
    lcd.refresh()
    assert lcd.text_rows() == ["before after"]
