/* Serial, IR remote, digital and analog I/O and audio from C, against scripted input (see
 * tests/e2e/test_robot_io_program.py). Prints "ok/FAIL what value" lines. */
#include <stdio.h>
#include <string.h>
#include "eyebot.h"

static void check(const char *what, int value, int expected)
{
    printf("%s %s %d\n", value == expected ? "ok" : "FAIL", what, value);
}

int main(void)
{
    char text[64] = {0};

    /* Serial: interface 1 has a loopback plug, interface 0 goes out; "hello\n" arrives on 0. */
    check("ser init", SERInit(1, 115200, 0), 0);
    SERSend(1, "ping");
    check("loopback char", SERReceiveChar(1), 'p');
    check("loopback rest", SERReceive(1, text, sizeof text), 3);
    check("loopback text", strcmp(text, "ing"), 0);
    check("not open", SERSend(2, "x"), 1);
    check("bad baud", SERInit(0, 10, 0), 1);
    SERInit(0, 9600, RTSCTS);
    SERSend(0, "hello from the robot\n");
    SERSendChar(0, '!');
    SERSendChar(0, '\n');
    int n = 0;
    char c;
    while ((c = SERReceiveChar(0)) != '\n' && n < 60)
        text[n++] = c;
    text[n] = '\0';
    check("serial input", strcmp(text, "hello"), 0);
    check("nothing more", SERCheck(0), 0);

    /* IR remote: OK then 7 arrive at 0.3 s. */
    check("irtv status", IRTVGetStatus(), 1);
    check("irtv get", IRTVGet(), IRTV_OK);
    check("irtv read", IRTVRead(), IRTV_7);
    check("irtv none", IRTVRead(), 0);

    /* Digital lines: 3 is driven to 1 from outside, 5 has its pull-up, 9 is an output. */
    DIGITALSetup(5, 'I');
    DIGITALSetup(9, 'o');
    check("digital write", DIGITALWrite(9, 1), 0);
    check("digital read 3", DIGITALRead(3), 1);
    check("digital read all", DIGITALReadAll(), (1 << 2) | (1 << 4) | (1 << 8));
    check("write an input", DIGITALWrite(4, 1), 1);

    /* Analog: channel 2 was set to 700; record 100 samples at 1 kHz. */
    check("analog read", ANALOGRead(2), 700);
    int volts = ANALOGVoltage();
    check("battery in range", volts >= 830 && volts <= 840, 1);
    int start = OSGetCount(); /* before the recording starts: every call takes simulation time */
    check("record", ANALOGRecord(2, 100), 0);
    BYTE samples[200];
    check("transfer bytes", ANALOGTransfer(samples), 200);
    check("transfer took 100 ms", OSGetCount() - start >= 99, 1);
    check("first sample", samples[0] | samples[1] << 8, 700);
    check("last sample", samples[198] | samples[199] << 8, 700);

    /* Audio: a beep plays 0.2 s, the WAV file next to the program 0.3 s. */
    AUBeep();
    check("beep playing", AUDone(), 0);
    OSWait(250);
    check("beep done", AUDone(), 1);
    check("play", AUPlay("sound.wav"), 0);
    OSWait(250);
    check("file playing", AUDone(), 0);
    OSWait(100);
    check("file done", AUDone(), 1);
    check("missing file", AUPlay("no-such-sound.wav"), 1);
    check("microphone", AUMicrophone(), 512);
    printf("done\n");
    return 0;
}
