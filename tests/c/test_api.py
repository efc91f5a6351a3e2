"""Each RoBIOS function of libeyesim sends its operation with the right values and returns the reply's."""

from __future__ import annotations

import subprocess

PROGRAM = r"""
#include "eyebot.h"
#include <stdio.h>
#include <string.h>

int main(void)
{
    int a = -7, b = -7, c = -7, d = -7, r;
    char long_text[1001];
    memset(long_text, 'a', 1000);
    long_text[1000] = 0;
    printf("LCDPrintf %d\n", LCDPrintf("x=%d %s\n", 5, "\xc3\xa9"));
    printf("LCDPrintf %d\n", LCDPrintf("%s", long_text));
    printf("LCDSetPrintf %d\n", LCDSetPrintf(20, 3, "%05.1f|", 2.5));
    printf("LCDClear %d\n", LCDClear());
    printf("LCDMenu %d\n", LCDMenu("GO", "", NULL, "END"));
    printf("KEYGet %d\n", KEYGet());
    printf("KEYRead %d\n", KEYRead());
    printf("OSWait %d\n", OSWait(250));
    printf("OSGetCount %d\n", OSGetCount());
    r = PSDGet(PSD_FRONT);
    printf("PSDGet %d %d\n", r, PSDGet(PSD_BACK));
    printf("VWSetSpeed %d\n", VWSetSpeed(300, -45));
    r = VWGetSpeed(&a, &b);
    printf("VWGetSpeed %d %d %d\n", r, a, b);
    VWGetSpeed(NULL, NULL);
    printf("VWSetPosition %d\n", VWSetPosition(100, -200, 90));
    r = VWGetPosition(&a, &b, &c);
    printf("VWGetPosition %d %d %d %d\n", r, a, b, c);
    printf("VWStraight %d\n", VWStraight(-1000, 300));
    printf("VWTurn %d\n", VWTurn(180, 60));
    printf("VWDone %d\n", VWDone());
    printf("VWWait %d\n", VWWait());
    printf("VWDriveDone %d\n", VWDriveDone());
    printf("VWDriveWait %d\n", VWDriveWait());
    r = SIMGetRobot(2, &a, &b, &c, &d);
    printf("SIMGetRobot %d %d %d %d %d\n", r, a, b, c, d);
    printf("SIMSetRobot %d\n", SIMSetRobot(0, 500, 600, 10, -90));
    return 0;
}
"""

# What the fake simulator answers (op -> reply values, or a function of the request's values).
SCRIPT = {
    "LCD_PRINTF": (0,),
    "LCD_SET_PRINTF": (0,),
    "LCD_CLEAR": (0,),
    "LCD_MENU": (0,),
    "KEY_GET": (2,),
    "KEY_READ": (8,),
    "OS_WAIT": (0,),
    "OS_GET_COUNT": (123456,),
    "PSD_GET": lambda values: (values[0] * 100 + 7,),
    "VW_SET_SPEED": (0,),
    "VW_GET_SPEED": (0, 298, -44),
    "VW_SET_POSITION": (0,),
    "VW_GET_POSITION": (0, -250, 1000, -90),
    "VW_STRAIGHT": (0,),
    "VW_TURN": (1,),  # a failure result is the function's return value, no message
    "VW_DONE": (1,),
    "VW_WAIT": (0,),
    "SIM_GET_ROBOT": (0, 1500, 2500, 30, 45),
    "SIM_SET_ROBOT": (0,),
}

EXPECTED_REQUESTS = [
    ("LCD_PRINTF", ("x=5 \u00e9\n",)),
    ("LCD_PRINTF", ("a" * 1000,)),
    ("LCD_SET_PRINTF", (20, 3, "002.5|")),
    ("LCD_CLEAR", ()),
    ("LCD_MENU", ("GO", "", "", "END")),
    ("KEY_GET", ()),
    ("KEY_READ", ()),
    ("OS_WAIT", (250,)),
    ("OS_GET_COUNT", ()),
    ("PSD_GET", (1,)),
    ("PSD_GET", (4,)),
    ("VW_SET_SPEED", (300, -45)),
    ("VW_GET_SPEED", ()),
    ("VW_GET_SPEED", ()),
    ("VW_SET_POSITION", (100, -200, 90)),
    ("VW_GET_POSITION", ()),
    ("VW_STRAIGHT", (-1000, 300)),
    ("VW_TURN", (180, 60)),
    ("VW_DONE", ()),
    ("VW_WAIT", ()),
    ("VW_DONE", ()),
    ("VW_WAIT", ()),
    ("SIM_GET_ROBOT", (2,)),
    ("SIM_SET_ROBOT", (0, 500, 600, 10, -90)),
]

EXPECTED_OUTPUT = """\
LCDPrintf 0
LCDPrintf 0
LCDSetPrintf 0
LCDClear 0
LCDMenu 0
KEYGet 2
KEYRead 8
OSWait 0
OSGetCount 123456
PSDGet 107 407
VWSetSpeed 0
VWGetSpeed 0 298 -44
VWSetPosition 0
VWGetPosition 0 -250 1000 -90
VWStraight 0
VWTurn 1
VWDone 1
VWWait 0
VWDriveDone 1
VWDriveWait 0
SIMGetRobot 0 1500 2500 30 45
SIMSetRobot 0
"""


def test_every_function_sends_its_op_and_returns_the_reply(compiler, fake_sim):
    exe = compiler.build(PROGRAM, name="api_calls")
    fake_sim.script.update(SCRIPT)
    ran = subprocess.run([str(exe)], capture_output=True, text=True, timeout=30, env=fake_sim.env())
    assert ran.stderr == ""
    assert ran.returncode == 0
    assert [(r.op, r.values) for r in fake_sim.requests] == EXPECTED_REQUESTS
    assert ran.stdout == EXPECTED_OUTPUT
    ids = [r.request_id for r in fake_sim.requests]
    assert len(set(ids)) == len(ids) and 0 not in ids
