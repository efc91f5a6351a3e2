/* menu_demo.c: a menu-driven robot program as students write them: the soft keys choose what the
 * robot does, and the LCD shows a title, the sensors, a small drawing and a log of what happened.
 * From the examples folder (the default arena; eyesim compiles it; open the printed viewer address):
 *   eyesim run --program 1=programs/menu_demo.c
 */
#include <stdio.h>
#include "eyebot.h"

#define LOG_ROW 12 /* the log starts on this text row */

static int log_lines;

static void show_title(void)
{
    LCDSetFont(HELVETICA, BOLD);
    LCDSetFontSize(18);
    LCDSetColor(YELLOW, BLACK);
    LCDSetPrintf(0, 0, "EyeSim menu demo");
    LCDSetFontSize(10);
    LCDSetFont(COURIER, NORMAL);
    LCDSetColor(WHITE, BLACK);
}

/* Sensor readings as text, and the three PSD beams as bars on the right. */
static void show_sensors(void)
{
    int front = PSDGet(PSD_FRONT), left = PSDGet(PSD_LEFT), right = PSDGet(PSD_RIGHT);
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    LCDSetPrintf(4, 0, "PSD front %4d  left %4d  right %4d", front, left, right);
    LCDSetPrintf(5, 0, "Position x %5d  y %5d  phi %4d", x, y, phi);
    LCDSetPrintf(6, 0, "Battery %d.%02d V   time %6.1f s", ANALOGVoltage() / 100, ANALOGVoltage() % 100,
                 OSGetCount() / 1000.0);

    const int values[3] = {left, front, right};
    const COLOR colours[3] = {GREEN, ORANGE, CYAN};
    for (int k = 0; k < 3; k++) {
        int length = values[k] > 2000 ? 100 : values[k] / 20;
        LCDArea(340, 95 + 22 * k, 440, 110 + 22 * k, DARKGRAY, 1);
        LCDArea(340, 95 + 22 * k, 340 + length, 110 + 22 * k, colours[k], 1);
        LCDArea(340, 95 + 22 * k, 440, 110 + 22 * k, WHITE, 0);
    }
}

/* A little picture: the robot (a circle with its heading) in a frame. */
static void draw_robot(int phi)
{
    const int cx = 400, cy = 200, r = 25;
    LCDArea(355, 165, 445, 240, BLACK, 1);
    LCDArea(355, 165, 445, 240, GRAY, 0);
    LCDCircle(cx, cy, r, BLUE, 1);
    LCDCircle(cx, cy, r, WHITE, 0);
    static const int dx[8] = {25, 18, 0, -18, -25, -18, 0, 18}, dy[8] = {0, -18, -25, -18, 0, 18, 25, 18};
    int octant = ((phi % 360 + 360 + 22) / 45) % 8; /* counter-clockwise; screen y points down */
    LCDLine(cx, cy, cx + dx[octant], cy + dy[octant], RED);
}

static void log_line(const char *text)
{
    if (log_lines == 7) { /* the log area is full: start again from the top */
        LCDArea(0, LOG_ROW * 13, 330, LOG_ROW * 13 + 7 * 13 - 1, BLACK, 1);
        log_lines = 0;
    }
    LCDSetPrintf(LOG_ROW + log_lines++, 0, "%.40s", text);
}

int main(void)
{
    char name[64];
    OSMachineName(name);
    LCDClear();
    show_title();
    LCDSetPrintf(2, 0, "Robot %s (id %d). Choose with the keys below.", name, OSMachineID());
    LCDMenu("DRIVE", "TURN", "BEEP", "END");
    LCDMenuI(3, "END", WHITE, MAROON); /* positions count from 0: 3 is KEY4 */
    LCDSetColor(LIGHTGRAY, BLACK);
    LCDSetPrintf(LOG_ROW - 1, 0, "Log:");
    LCDSetColor(WHITE, BLACK);

    int key;
    do {
        int x, y, phi;
        show_sensors();
        VWGetPosition(&x, &y, &phi);
        draw_robot(phi);
        key = KEYGet();
        char text[64];
        switch (key) {
        case KEY1:
            if (PSDGet(PSD_FRONT) < 300) {
                log_line("DRIVE: a wall is too close");
                AUBeep();
                break;
            }
            VWStraight(200, 300);
            VWWait();
            snprintf(text, sizeof text, "DRIVE: 200 mm forward");
            log_line(text);
            break;
        case KEY2:
            VWTurn(90, 90);
            VWWait();
            log_line("TURN: 90 degrees to the left");
            break;
        case KEY3:
            AUBeep();
            log_line("BEEP!");
            break;
        default:
            break;
        }
    } while (key != KEY4);

    LCDSetColor(BLACK, YELLOW);
    LCDSetPrintf(9, 0, " Goodbye! ");
    LCDMenu("", "", "", "");
    return 0;
}
