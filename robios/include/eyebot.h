/* eyebot.h: the RoBIOS-7 API for EyeSim programs (types, constants, and the functions libeyesim implements). */
#ifndef EYEBOT_H
#define EYEBOT_H

#ifndef __cplusplus
#include <stdbool.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define EYEBOT_PRINTF(fmt, first) __attribute__((format(printf, fmt, first)))
#else
#define EYEBOT_PRINTF(fmt, first)
#endif

/* ---- Basic types ---------------------------------------------------------------------------- */

typedef unsigned char BYTE;  /* pixel channel, buffer element */
typedef int COLOR;           /* 0xRRGGBB */
typedef int TIMER;           /* handle returned by OSAttachTimer */

#ifndef True
#define True 1
#endif
#ifndef False
#define False 0
#endif

/* ---- Key codes: single bits, so a mask like ANYKEY covers several. The high codes are written
 * as int so that comparing them with KEYGet()'s int result draws no sign warnings. ---------- */

#define NOKEY 0x00000000
#define KEY1 0x00000001
#define KEY2 0x00000002
#define KEY3 0x00000004
#define KEY4 0x00000008
#define ANYKEY ((int)0xFFFFFFFFu)
#define KEY_INVALID ((int)0xFFFFFFFFu)
#define KEY_ESCAPE ((int)0x80000000u)
#define KEY_LISTTL 0x40000000
#define KEY_LISTUP 0x20000000
#define KEY_LISTDN 0x10000000
#define KEY_LIST1 0x00000010
#define KEY_LIST2 0x00000020
#define KEY_LIST3 0x00000040
#define KEY_LIST4 0x00000080
#define KEY_LIST5 0x00000100
#define KEY_LIST6 0x00000200
#define KEY_LIST7 0x00000400
#define KEY_LIST8 0x00000800

#define KEYTM_UNKNOWN 0x00
#define KEYTM_CLASSIC 0x01
#define KEYTM_STANDARD 0x02
#define KEYTM_REGIONS 0x03
#define KEYTM_LISTMENU 0x04

/* ---- Colours (EyeSim values; CYAN and OLIVE differ from the web colour names) ---------------- */

#define RED 0xFF0000
#define GREEN 0x00FF00
#define BLUE 0x0000FF
#define WHITE 0xFFFFFF
#define GRAY 0x808080
#define BLACK 0x000000
#define SILVER 0xC0C0C0
#define LIGHTGRAY 0xD3D3D3
#define DARKGRAY 0xA9A9A9
#define NAVY 0x000080
#define CYAN 0x00EEEE
#define TEAL 0x008080
#define MAGENTA 0xFF00FF
#define PURPLE 0x800080
#define MAROON 0x800000
#define YELLOW 0xFFFF00
#define OLIVE 0x9ACD32
#define ORANGE 0xFFA500

/* ---- Camera and image resolutions; colour images have 3 bytes per pixel ---------------------- */

#define QQVGA 0
#define QVGA 1
#define VGA 2
#define CAM1MP 3
#define CAMHD 4
#define CAM5MP 5
#define CUSTOM 10

#define QQVGA_X 160
#define QQVGA_Y 120
#define QVGA_X 320
#define QVGA_Y 240
#define VGA_X 640
#define VGA_Y 480
#define CAM1MP_X 1296
#define CAM1MP_Y 730
#define CAMHD_X 1920
#define CAMHD_Y 1080
#define CAM5MP_X 2592
#define CAM5MP_Y 1944

#define QQVGA_PIXELS (QQVGA_X * QQVGA_Y)
#define QVGA_PIXELS (QVGA_X * QVGA_Y)
#define VGA_PIXELS (VGA_X * VGA_Y)
#define CAM1MP_PIXELS (CAM1MP_X * CAM1MP_Y)
#define CAMHD_PIXELS (CAMHD_X * CAMHD_Y)
#define CAM5MP_PIXELS (CAM5MP_X * CAM5MP_Y)

#define QQVGA_SIZE (QQVGA_PIXELS * 3)
#define QVGA_SIZE (QVGA_PIXELS * 3)
#define VGA_SIZE (VGA_PIXELS * 3)
#define CAM1MP_SIZE (CAM1MP_PIXELS * 3)
#define CAMHD_SIZE (CAMHD_PIXELS * 3)
#define CAM5MP_SIZE (CAM5MP_PIXELS * 3)

typedef BYTE QQVGAcol[QQVGA_SIZE];
typedef BYTE QQVGAgray[QQVGA_PIXELS];
typedef BYTE QVGAcol[QVGA_SIZE];
typedef BYTE QVGAgray[QVGA_PIXELS];
typedef BYTE VGAcol[VGA_SIZE];
typedef BYTE VGAgray[VGA_PIXELS];
typedef BYTE CAM1MPcol[CAM1MP_SIZE];
typedef BYTE CAM1MPgray[CAM1MP_PIXELS];
typedef BYTE CAMHDcol[CAMHD_SIZE];
typedef BYTE CAMHDgray[CAMHD_PIXELS];
typedef BYTE CAM5MPcol[CAM5MP_SIZE];
typedef BYTE CAM5MPgray[CAM5MP_PIXELS];

/* ---- Fonts ----------------------------------------------------------------------------------- */

#define HELVETICA 0
#define TIMES 1
#define COURIER 2
#define NORMAL 0
#define BOLD 1
#define ITALICS 2

/* ---- LCD colour flags and mode flags (for LCDSetMode); each "off" flag is 8 bits above its "on" */

#define LCD_BGCOL_TRANSPARENT 0x01
#define LCD_BGCOL_NOTRANSPARENT 0x10
#define LCD_BGCOL_INVERSE 0x02
#define LCD_BGCOL_NOINVERSE 0x20
#define LCD_FGCOL_INVERSE 0x04
#define LCD_FGCOL_NOINVERSE 0x40

#define LCD_AUTOREFRESH 0x0001
#define LCD_NOAUTOREFRESH 0x0100
#define LCD_SCROLLING 0x0002
#define LCD_NOSCROLLING 0x0200
#define LCD_LINEFEED 0x0004
#define LCD_NOLINEFEED 0x0400
#define LCD_SHOWMENU 0x0008
#define LCD_HIDEMENU 0x0800
#define LCD_LISTMENU 0x0010
#define LCD_CLASSICMENU 0x1000
#define LCD_FB_ROTATE 0x0080
#define LCD_FB_NOROTATION 0x8000

/* ---- Machine and system constants ------------------------------------------------------------ */

#define VEHICLE 1
#define PLATFORM 2
#define WALKER 3
#define MACHINE_SPEED 700000000 /* Hz */
#define MACHINE_NAME "EyeBot"
#define MACHINE_ID 1
#ifndef VERSION /* build systems often define their own VERSION */
#define VERSION "1.0"
#endif
#define MENU_HEIGHT 38 /* pixel height of the soft-key menu bar */
#define LCD_MENU_STRLENGTH 32
#define LCD_LIST_STRLENGTH 64
#define CAM_SUCCESS 0
#define CAM_FAILURE 1
#define IOBOARD 1

/* ---- PSD positions (EyeSim numbering; the robot definition maps them to sensors) -------------- */

#define PSD_FRONT 1
#define PSD_LEFT 2
#define PSD_RIGHT 3
#define PSD_BACK 4

/* ---- IR remote codes, as returned by IRTVGet/IRTVRead ----------------------------------------- */

#define IRTV_0 '0'
#define IRTV_1 '1'
#define IRTV_2 '2'
#define IRTV_3 '3'
#define IRTV_4 '4'
#define IRTV_5 '5'
#define IRTV_6 '6'
#define IRTV_7 '7'
#define IRTV_8 '8'
#define IRTV_9 '9'
#define IRTV_RED 'R'
#define IRTV_GREEN 'G'
#define IRTV_YELLOW 'Y'
#define IRTV_BLUE 'B'
#define IRTV_LEFT 'L'
#define IRTV_RIGHT '>'
#define IRTV_UP 'U'
#define IRTV_DOWN 'D'
#define IRTV_OK 'O'
#define IRTV_POWER 'P'

/* ==== Functions =================================================================================
 * Unless a function says otherwise it returns 0 for OK and 1 for an error. When the simulator
 * answers a call with an error, the library prints "eyesim: <function>: <reason>" to stderr and
 * returns the error value given below. Units: mm, mm/s, degrees, degrees/s, milliseconds. */

/* ---- LCD: a 480 x 320 screen; text cells are addressed by row and column ---------------------- */

int LCDPrintf(const char *format, ...) EYEBOT_PRINTF(1, 2);               /* print at the cursor */
int LCDSetPrintf(int row, int column, const char *format, ...) EYEBOT_PRINTF(3, 4);
int LCDClear(void);                                                      /* clear to black */
int LCDMenu(const char *key1, const char *key2, const char *key3, const char *key4); /* soft-key labels */

/* ---- Keys ------------------------------------------------------------------------------------ */

int KEYGet(void);  /* blocks until a soft key is pressed; KEY1..KEY4 (NOKEY on error) */
int KEYRead(void); /* the key pressed now, or NOKEY; never blocks */

/* ---- Time (the simulator's clock) ------------------------------------------------------------- */

int OSWait(int ms);     /* blocks for ms milliseconds of simulation time */
int OSGetCount(void);   /* milliseconds since the program started (-1 on error) */

/* ---- Distance sensors ------------------------------------------------------------------------- */

int PSDGet(int psd);    /* distance in mm measured by PSD_FRONT/LEFT/RIGHT/BACK or 1..6 (-1 on error) */

/* ---- V-omega driving: mm, mm/s, degrees (counter-clockwise positive), degrees/s --------------- */

int VWSetSpeed(int linSpeed, int angSpeed);      /* drive on until changed; (0, 0) stops */
int VWGetSpeed(int *linSpeed, int *angSpeed);    /* measured speeds */
int VWSetPosition(int x, int y, int phi);        /* overwrite the odometry pose; the robot stays */
int VWGetPosition(int *x, int *y, int *phi);     /* odometry pose */
int VWStraight(int dist, int lin_speed);         /* start driving dist mm (negative = backwards) */
int VWTurn(int angle, int ang_speed);            /* start turning on the spot */
int VWDone(void);                                /* 1 manoeuvre finished, 0 still driving, -1 error */
int VWWait(void);                                /* blocks until the manoeuvre ends */
int VWDriveDone(void);                           /* older name of VWDone */
int VWDriveWait(void);                           /* older name of VWWait */

/* ---- Simulation only: true poses; id 0 = this program's robot, 1.. = robots in scene order ---- */

int SIMGetRobot(int id, int *x, int *y, int *z, int *phi); /* non-zero for an unknown id */
int SIMSetRobot(int id, int x, int y, int z, int phi);     /* moves the robot at once */

#ifdef __cplusplus
}
#endif

#endif /* EYEBOT_H */
