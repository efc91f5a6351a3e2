"""eyebot.h: warning-free as C11 and C++17, the spec's constant values; no RoBIOS call, no connection."""

from __future__ import annotations

import subprocess

import pytest

from eyesim import toolchain

PROGRAM = r"""
#include "eyebot.h"
#include <stdio.h>
#include <string.h>

static int failures;
#define EXPECT(cond) do { if (!(cond)) { printf("FAIL: %s\n", #cond); failures++; } } while (0)

/* Never called: type-checks every declaration, and that key comparisons draw no warnings. */
void use_every_function(void);
void use_every_function(void)
{
    int a, b, c, d;
    if (KEYGet() == ANYKEY || KEYRead() == KEY_ESCAPE || KEYRead() == KEY_INVALID) {}
    switch (KEYGet()) { case KEY1: case KEY4: case ANYKEY: case KEY_ESCAPE: case KEY_LIST8: break; default: break; }
    LCDPrintf("%d %s\n", 1, "x");
    LCDSetPrintf(1, 2, "%5.1f", 1.5);
    LCDClear();
    LCDMenu("GO", "", " ", "END");
    OSWait(10);
    (void)OSGetCount();
    (void)PSDGet(PSD_FRONT);
    VWSetSpeed(100, -30);
    VWGetSpeed(&a, &b);
    VWSetPosition(1, 2, 3);
    VWGetPosition(&a, &b, &c);
    VWStraight(-1000, 300);
    VWTurn(180, 60);
    while (!VWDone()) {}
    VWWait();
    (void)VWDriveDone();
    VWDriveWait();
    SIMGetRobot(0, &a, &b, &c, &d);
    SIMSetRobot(0, 500, 500, 0, 180);
}

int main(void)
{
    COLOR colour = ORANGE;
    BYTE pixel = 255;
    TIMER timer = 0;
    (void)timer;
    EXPECT(colour == 0xFFA500 && pixel == 255 && sizeof(BYTE) == 1);
    EXPECT(NOKEY == 0 && KEY1 == 1 && KEY2 == 2 && KEY3 == 4 && KEY4 == 8);
    EXPECT(ANYKEY == -1 && (unsigned)ANYKEY == 0xFFFFFFFFu && (unsigned)KEY_INVALID == 0xFFFFFFFFu);
    EXPECT((unsigned)KEY_ESCAPE == 0x80000000u && KEY_LISTTL == 0x40000000 && KEY_LIST1 == 0x10 && KEY_LIST8 == 0x800);
    EXPECT(KEYTM_CLASSIC == 1 && KEYTM_LISTMENU == 4);
    EXPECT(RED == 0xFF0000 && GREEN == 0x00FF00 && BLUE == 0x0000FF && WHITE == 0xFFFFFF && BLACK == 0);
    EXPECT(GRAY == 0x808080 && SILVER == 0xC0C0C0 && LIGHTGRAY == 0xD3D3D3 && DARKGRAY == 0xA9A9A9);
    EXPECT(NAVY == 0x000080 && CYAN == 0x00EEEE && TEAL == 0x008080 && MAGENTA == 0xFF00FF);
    EXPECT(PURPLE == 0x800080 && MAROON == 0x800000 && YELLOW == 0xFFFF00 && OLIVE == 0x9ACD32);
    EXPECT(QQVGA == 0 && QVGA == 1 && VGA == 2 && CAM1MP == 3 && CAMHD == 4 && CAM5MP == 5 && CUSTOM == 10);
    EXPECT(QQVGA_X == 160 && QQVGA_Y == 120 && QQVGA_PIXELS == 19200 && QQVGA_SIZE == 57600);
    EXPECT(QVGA_PIXELS == 76800 && QVGA_SIZE == 230400 && VGA_PIXELS == 307200 && VGA_SIZE == 921600);
    EXPECT(CAM1MP_X == 1296 && CAM1MP_Y == 730 && CAM1MP_PIXELS == 946080 && CAM1MP_SIZE == 2838240);
    EXPECT(CAMHD_PIXELS == 2073600 && CAMHD_SIZE == 6220800 && CAM5MP_PIXELS == 5038848 && CAM5MP_SIZE == 15116544);
    EXPECT(sizeof(QQVGAcol) == 57600 && sizeof(QQVGAgray) == 19200 && sizeof(QVGAcol) == 230400);
    EXPECT(sizeof(VGAgray) == 307200 && sizeof(CAM1MPcol) == 2838240 && sizeof(CAMHDgray) == 2073600);
    EXPECT(sizeof(CAM5MPcol) == 15116544 && sizeof(CAM5MPgray) == 5038848 && sizeof(VGAcol) == 921600);
    EXPECT(HELVETICA == 0 && TIMES == 1 && COURIER == 2 && NORMAL == 0 && BOLD == 1 && ITALICS == 2);
    EXPECT(LCD_BGCOL_TRANSPARENT == 0x01 && LCD_BGCOL_NOTRANSPARENT == 0x10 && LCD_FGCOL_NOINVERSE == 0x40);
    EXPECT(LCD_AUTOREFRESH == 1 && LCD_NOAUTOREFRESH == 0x100 && LCD_CLASSICMENU == 0x1000);
    EXPECT(LCD_FB_ROTATE == 0x80 && LCD_FB_NOROTATION == 0x8000 && LCD_HIDEMENU == 0x800);
    EXPECT(PSD_FRONT == 1 && PSD_LEFT == 2 && PSD_RIGHT == 3 && PSD_BACK == 4);
    EXPECT(VEHICLE == 1 && PLATFORM == 2 && WALKER == 3 && MACHINE_SPEED == 700000000 && MACHINE_ID == 1);
    EXPECT(strcmp(MACHINE_NAME, "EyeBot") == 0 && strcmp(VERSION, "1.0") == 0);
    EXPECT(MENU_HEIGHT == 38 && LCD_MENU_STRLENGTH == 32 && LCD_LIST_STRLENGTH == 64);
    EXPECT(CAM_SUCCESS == 0 && CAM_FAILURE == 1 && IOBOARD == 1 && True == 1 && False == 0);
    EXPECT(IRTV_0 == '0' && IRTV_9 == '9' && IRTV_RIGHT == '>' && IRTV_POWER == 'P');
    printf("ok\n");
    return failures != 0;
}
"""


@pytest.mark.parametrize("language,standard", [("cc", "-std=c11"), ("c++", "-std=c++17")])
def test_header_compiles_cleanly_and_has_the_spec_values(compiler, free_port_env, language, standard):
    exe = compiler.build(PROGRAM, name="header_check", language=language, flags=(standard, "-Wpedantic"))
    # No RoBIOS call is made, so nothing connects, even with no simulator anywhere.
    ran = subprocess.run([str(exe)], capture_output=True, text=True, timeout=10, env=free_port_env)
    assert ran.returncode == 0, ran.stdout + ran.stderr
    assert ran.stdout == "ok\n"
    assert ran.stderr == ""


@pytest.mark.parametrize("language", ["cc", "c++"])
def test_header_compiles_on_its_own(robios_prefix, tmp_path, language):
    source = tmp_path / ("only.c" if language == "cc" else "only.cpp")
    source.write_text('#include "eyebot.h"\n')
    standard = "-std=c11" if language == "cc" else "-std=c++17"
    command = toolchain.compiler_command(
        language, [standard, "-Wall", "-Wextra", "-Werror", "-c", str(source), "-o", str(tmp_path / "only.o")],
        robios_prefix)
    done = subprocess.run(command, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
