# A menu-driven robot program (the Python version of menu_demo.c), as students write them: the soft
# keys choose what the robot does, and the LCD shows a title, the sensors, a small drawing and a log
# of what happened. From the examples folder (the default arena; open the printed viewer address):
#   eyesim run --program 1=programs/menu_demo.py
from eye import *

LOG_ROW = 12  # the log starts on this text row
log_lines = 0


def show_title():
    LCDSetFont(HELVETICA, BOLD)
    LCDSetFontSize(18)
    LCDSetColor(YELLOW, BLACK)
    LCDSetPrintf(0, 0, "EyeSim menu demo")
    LCDSetFontSize(10)
    LCDSetFont(COURIER, NORMAL)
    LCDSetColor(WHITE, BLACK)


def show_sensors():
    """Sensor readings as text, and the three PSD beams as bars on the right."""
    front, left, right = PSDGet(PSD_FRONT), PSDGet(PSD_LEFT), PSDGet(PSD_RIGHT)
    x, y, phi = VWGetPosition()
    LCDSetPrintf(4, 0, "PSD front %4d  left %4d  right %4d", front, left, right)
    LCDSetPrintf(5, 0, "Position x %5d  y %5d  phi %4d", x, y, phi)
    LCDSetPrintf(
        6, 0, "Battery %d.%02d V   time %6.1f s", ANALOGVoltage() // 100, ANALOGVoltage() % 100, OSGetCount() / 1000.0
    )
    for k, (value, colour) in enumerate([(left, GREEN), (front, ORANGE), (right, CYAN)]):
        length = 100 if value > 2000 else value // 20
        LCDArea(340, 95 + 22 * k, 440, 110 + 22 * k, DARKGRAY, 1)
        LCDArea(340, 95 + 22 * k, 340 + length, 110 + 22 * k, colour, 1)
        LCDArea(340, 95 + 22 * k, 440, 110 + 22 * k, WHITE, 0)


def draw_robot(phi):
    """A little picture: the robot (a circle with its heading) in a frame."""
    cx, cy = 400, 200
    LCDArea(355, 165, 445, 240, BLACK, 1)
    LCDArea(355, 165, 445, 240, GRAY, 0)
    LCDCircle(cx, cy, 25, BLUE, 1)
    LCDCircle(cx, cy, 25, WHITE, 0)
    dx = [25, 18, 0, -18, -25, -18, 0, 18]
    dy = [0, -18, -25, -18, 0, 18, 25, 18]
    octant = (phi % 360 + 22) // 45 % 8  # counter-clockwise; screen y points down
    LCDLine(cx, cy, cx + dx[octant], cy + dy[octant], RED)


def log_line(text):
    global log_lines
    if log_lines == 7:  # the log area is full: start again from the top
        LCDArea(0, LOG_ROW * 13, 330, LOG_ROW * 13 + 7 * 13 - 1, BLACK, 1)
        log_lines = 0
    LCDSetPrintf(LOG_ROW + log_lines, 0, "%.40s", text)
    log_lines += 1


def main():
    LCDClear()
    show_title()
    LCDSetPrintf(2, 0, "Robot %s (id %d). Choose with the keys below.", OSMachineName(), OSMachineID())
    LCDMenu("DRIVE", "TURN", "BEEP", "END")
    LCDMenuI(3, "END", WHITE, MAROON)  # positions count from 0: 3 is KEY4
    LCDSetColor(LIGHTGRAY, BLACK)
    LCDSetPrintf(LOG_ROW - 1, 0, "Log:")
    LCDSetColor(WHITE, BLACK)

    key = 0
    while key != KEY4:
        show_sensors()
        x, y, phi = VWGetPosition()
        draw_robot(phi)
        key = KEYGet()
        if key == KEY1:
            if PSDGet(PSD_FRONT) < 300:
                log_line("DRIVE: a wall is too close")
                AUBeep()
            else:
                VWStraight(200, 300)
                VWWait()
                log_line("DRIVE: 200 mm forward")
        elif key == KEY2:
            VWTurn(90, 90)
            VWWait()
            log_line("TURN: 90 degrees to the left")
        elif key == KEY3:
            AUBeep()
            log_line("BEEP!")

    LCDSetColor(BLACK, YELLOW)
    LCDSetPrintf(9, 0, " Goodbye! ")
    LCDMenu("", "", "", "")


main()
