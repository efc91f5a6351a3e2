"""The viewer's robot I/O in headless Chromium against the fake simulator: touches on the LCD (also
with the menu hidden or the LCD rotated), the IR remote by click and keyboard, serial in and out,
digital and analog controls, battery and sounds."""

from __future__ import annotations

import pytest
from browser import lcd_image, robot_panel, wait_for_lcd
from fake_viewer_server import MENU_LABELS, ROBOT_ID

pytestmark = pytest.mark.browser


def of_type(kind: str):
    return lambda command: isinstance(command, dict) and command.get("type") == kind


def commands(server, kind: str) -> list[dict]:
    return [c for c in server.commands if of_type(kind)(c)]


def test_clicks_above_the_menu_bar_are_touches_in_lcd_pixels(viewer, fake_server):
    wait_for_lcd(viewer.page, ROBOT_ID)
    image = lcd_image(viewer.page, ROBOT_ID)
    box = image.bounding_box()
    scale = box["width"] / 480
    image.click(position={"x": 100.5 * scale, "y": 50.5 * scale})
    assert fake_server.wait_for_command(of_type("touch")) == {"type": "touch", "robot": ROBOT_ID, "x": 100, "y": 50}
    image.click(position={"x": 10 * scale, "y": 310 * scale})  # on the menu bar: KEY1, no touch
    fake_server.wait_for_command(lambda c: of_type("key")(c) and c["key"] == 1)
    assert len(commands(fake_server, "touch")) == 1

    # The program hides the menu and turns the LCD: every click is a touch, mapped back.
    fake_server.send({"type": "menu", "robot": ROBOT_ID, "labels": MENU_LABELS, "visible": False, "rotated": True})
    viewer.page.wait_for_function("() => document.querySelector('.lcd-image.rotated') !== null")
    image.click(position={"x": 10.5 * scale, "y": 310.5 * scale})
    fake_server.wait_for_command(lambda c: of_type("touch")(c) and c["x"] == 469)
    assert commands(fake_server, "touch")[-1] == {"type": "touch", "robot": ROBOT_ID, "x": 469, "y": 9}
    assert len(commands(fake_server, "key")) == 1


def test_the_remote_the_serial_terminal_and_the_io_controls_send_commands(viewer, fake_server):
    page = viewer.page
    panel = robot_panel(page, ROBOT_ID)
    panel.locator("details.robot-io summary").click()
    panel.locator('.ir-button[data-code="OK"]').click()
    fake_server.wait_for_command(lambda c: of_type("irtv")(c) and c["code"] == "OK")
    panel.locator(".ir-remote").focus()
    page.keyboard.press("7")
    page.keyboard.press("ArrowRight")
    fake_server.wait_for_command(lambda c: of_type("irtv")(c) and c["code"] == "RIGHT")
    assert [c["code"] for c in commands(fake_server, "irtv")] == ["OK", "7", "RIGHT"]

    panel.locator(".serial-interface").select_option("2")
    panel.locator(".serial-input").fill("hi")
    panel.locator(".serial-input").press("Enter")
    assert fake_server.wait_for_command(of_type("serial")) == {
        "type": "serial",
        "robot": ROBOT_ID,
        "interface": 2,
        "text": "hi\n",
    }

    lines = [{"direction": "i", "level": 0, "driven": None} for _ in range(16)]
    lines[15] = {"direction": "o", "level": 1, "driven": None}
    fake_server.send({"type": "io", "robot": ROBOT_ID, "digital": lines, "analog": [0] * 7 + [512]})
    page.wait_for_function("r => window.eyesimViewer.ioState(r)?.analog[7] === 512", arg=ROBOT_ID)
    panel.locator(".digital-line").nth(2).click()  # an undriven input: drive it to 1
    assert fake_server.wait_for_command(of_type("digital")) == {
        "type": "digital",
        "robot": ROBOT_ID,
        "line": 3,
        "level": 1,
    }
    panel.locator(".digital-line").nth(15).click()  # an output: the program's, no command
    panel.locator(".analog-channel input").nth(3).fill("700")
    panel.locator(".analog-channel input").nth(3).press("Enter")
    assert fake_server.wait_for_command(of_type("analog")) == {
        "type": "analog",
        "robot": ROBOT_ID,
        "channel": 4,
        "value": 700,
    }
    assert len(commands(fake_server, "digital")) == 1
    assert panel.locator(".digital-line").nth(15).get_attribute("data-level") == "1"


def test_serial_output_battery_and_sounds_show_up(viewer, fake_server):
    page = viewer.page
    fake_server.send({"type": "serial", "robot": ROBOT_ID, "interface": 0, "text": "hello \xff\n"})
    fake_server.send({"type": "serial", "robot": ROBOT_ID, "interface": 5, "text": "usb"})
    fake_server.send({"type": "audio", "robot": ROBOT_ID, "sound": "beep", "duration": 0.2, "frequency": 1000})
    page.wait_for_function("r => window.eyesimViewer.soundsPlayed(r) === 1", arg=ROBOT_ID)
    assert viewer.state("serialText", ROBOT_ID, 0) == "hello \xff\n"
    assert viewer.state("serialText", ROBOT_ID, 5) == "usb"
    panel = robot_panel(page, ROBOT_ID)
    panel.locator("details.robot-io summary").click()
    assert panel.locator(".serial-output").text_content() == "hello \xff\n"
    fake_server.send(
        {
            "type": "snapshot",
            "time": 0.0,
            "objects": [],
            "robots": [{"id": ROBOT_ID, "pos": [1, 1, 0], "quat": [1, 0, 0, 0], "battery": 8.123}],
        }
    )
    page.wait_for_function("() => document.querySelector('.robot-io .battery').textContent === 'battery 8.12 V'")
    assert viewer.errors == []
