/* eyebot.h: the RoBIOS-7 API for EyeSim programs (types, constants, and the functions libeyesim implements). */
#ifndef EYEBOT_H
#define EYEBOT_H

/* EyeSim's eyebot.h (through its types.h) gave programs the C standard library and POSIX basics,
 * and programs call rand, strtok, sqrt, M_PI, usleep, printf without including anything else.
 * usleep and M_PI are outside strict ISO C (-std=c99/c11): ask for glibc's default set of names
 * unless the program chose a feature set itself. This only helps when eyebot.h comes first;
 * `eyesim cc` passes -D_DEFAULT_SOURCE, which works whatever the include order. */
#if !defined(_DEFAULT_SOURCE) && !defined(_GNU_SOURCE) && !defined(_POSIX_C_SOURCE) && \
    !defined(_XOPEN_SOURCE) && !defined(_POSIX_SOURCE) && !defined(_FEATURES_H)
#define _DEFAULT_SOURCE 1
#endif

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
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

/* ==== Generated constants ==== */
/* From the "constants" groups of interface/protocol.json down to "End of the generated constants": change
 * them there and run `make protocol`. */

/* ---- Truth values (C only: Python has its own) ----------------------------------------------- */

#ifndef True
#define True 1
#endif
#ifndef False
#define False 0
#endif

/* ---- Key codes: single bits, so a mask like ANYKEY covers several -------------------------------
 * In C the high codes are written as int, so that comparing them with KEYGet()'s int result draws
 * no sign warnings; in Python they are unsigned 32-bit numbers (ANYKEY = 4294967295), as in
 * EyeSim's eye.py, and so are the codes the key functions return. */

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

/* ---- Touch modes of the keys (KEYTM_*) ------------------------------------------------------- */

#define KEYTM_UNKNOWN 0x00
#define KEYTM_CLASSIC 0x01
#define KEYTM_STANDARD 0x02
#define KEYTM_REGIONS 0x03
#define KEYTM_LISTMENU 0x04

/* ---- Colours, 0xRRGGBB (EyeSim values; CYAN and OLIVE differ from the web colour names) ------ */

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

/* ---- Camera and image resolutions ------------------------------------------------------------ */

#define QQVGA 0
#define QVGA 1
#define VGA 2
#define CAM1MP 3
#define CAMHD 4
#define CAM5MP 5
#define CUSTOM 10

/* ---- Width and height of each resolution, in pixels ------------------------------------------ */

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

/* ---- Pixels of an image, and its bytes in colour (3 bytes per pixel) ------------------------- */

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

/* ---- Fonts ----------------------------------------------------------------------------------- */

#define HELVETICA 0
#define TIMES 1
#define COURIER 2
#define NORMAL 0
#define BOLD 1
#define ITALICS 2

/* ---- LCD colour and mode flags (for LCDSetMode) -------------------------------------------------
 * Each "off" flag is 8 bits above its "on" flag. */

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
#ifndef VERSION                 /* build systems often define their own VERSION */
#define VERSION "1.0"
#endif
#define MENU_HEIGHT 38          /* pixel height of the soft-key menu bar */
#define LCD_MENU_STRLENGTH 32
#define LCD_LIST_STRLENGTH 64
#define CAM_SUCCESS 0
#define CAM_FAILURE 1
#define IOBOARD 1

/* ---- Serial handshake (SERInit) -------------------------------------------------------------- */

#define RTSCTS 1 /* SERInit handshake; 0 = none */

/* ---- PSD positions (EyeSim numbering; the robot definition maps them to sensors) ------------- */

#define PSD_FRONT 1
#define PSD_LEFT 2
#define PSD_RIGHT 3
#define PSD_BACK 4

/* ---- IR remote codes, as returned by IRTVGet/IRTVRead ---------------------------------------- */

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

/* ==== End of the generated constants ==== */

/* ---- Image buffers of each resolution (the sizes above) -------------------------------------- */

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

/* ==== Functions =================================================================================
 * Unless a function says otherwise it returns 0 for OK and 1 for an error. When the simulator
 * answers a call with an error, the library prints "eyesim: <function>: <reason>" to stderr and
 * returns the error value given below. Units: mm, mm/s, degrees, degrees/s, milliseconds. */

/* <windows.h> (through rpc.h) defines `interface` as `struct` for COM; the serial functions below
 * name a parameter so. Undone for the declarations only. */
#if defined(_WIN32)
#pragma push_macro("interface")
#undef interface
#endif
/* Building eyesim.dll with clang (Zig, llvm-mingw): the functions and variables declared from here
 * to the end of the generated declarations, and the sleeps at the end of this file, are the DLL's
 * exports; nothing else is (without any dllexport, MinGW's linker would export every global symbol,
 * the start-up code's atexit among them, and programs calling atexit would then not link). */
#if defined(_WIN32) && defined(EYESIM_BUILDING_LIBRARY) && defined(__clang__)
#define EYESIM_EXPORTS_MARKED 1
#pragma clang attribute push(__declspec(dllexport), apply_to = any(function, variable(is_global)))
#endif

/* ==== Generated from the "api" groups of interface/protocol.json down to "End of the generated
 * declarations": change them there and run `make protocol`. ==== */

/* ---- LCD: a 480 x 320 screen; text cells are addressed by row and column --------------------- */

int LCDPrintf(const char *format, ...) EYEBOT_PRINTF(1, 2); /* print at the cursor */
int LCDSetPrintf(int row, int column, const char *format, ...) EYEBOT_PRINTF(3, 4);
                                                        /* move the text cursor to row, column, then print
                                                           as LCDPrintf */
int LCDClear(void);                                     /* clear to black */
int LCDMenu(const char *st1, const char *st2, const char *st3, const char *st4); /* soft-key labels */
int LCDMenuI(int pos, const char *string, COLOR fg, COLOR bg);
                                                        /* one soft-key label in its own colours; pos 0..3
                                                           is KEY1..KEY4, counted from 0 as EyeSim did; 1
                                                           if outside */
int LCDSetPos(int row, int column);                     /* move the text cursor; 1 if outside the text grid */
int LCDGetPos(int *row, int *column);                   /* the text cursor */
int LCDSetColor(COLOR fg, COLOR bg);                    /* text colours (default WHITE on BLACK) */
int LCDSetFont(int font, int variation);                /* HELVETICA/TIMES/COURIER, NORMAL/BOLD/ITALICS (or
                                                           BOLD|ITALICS) */
int LCDSetFontSize(int fontsize);                       /* 8..24 (default 10: 80 x 21 cells of 6 x 13
                                                           pixels, as EyeSim); 1 if invalid */
int LCDSetMode(int mode);                               /* OR of LCD_* mode flags, e.g. LCD_NOSCROLLING |
                                                           LCD_HIDEMENU */
int LCDRefresh(void);                                   /* show what was drawn (needed with
                                                           LCD_NOAUTOREFRESH) */
int LCDGetSize(int *x, int *y);                         /* 480 x 320 pixels */
int LCDPixel(int x, int y, COLOR col);                  /* drawing is clipped to the screen */
COLOR LCDGetPixel(int x, int y);                        /* the colour drawn there (-1 outside the screen) */
int LCDLine(int x1, int y1, int x2, int y2, COLOR col); /* a line between two points, both included */
int LCDArea(int x1, int y1, int x2, int y2, COLOR col, int fill); /* corners included; fill 1 or outline 0 */
int LCDCircle(int x1, int y1, int size, COLOR col, int fill); /* centre, radius; fill 1 or outline 0 */
int LCDImageSize(int t);                                /* size of the images LCDImage* get: QQVGA..CAM5MP
                                                           (QVGA); CUSTOM keeps LCDImageStart's size */
int LCDImageStart(int x, int y, int xs, int ys);        /* where images show, and their size: the next
                                                           images have xs x ys pixels, shown 1:1 */
int LCDImage(const BYTE *img);                          /* colour image: 3 bytes (R, G, B) per pixel */
int LCDImageGray(const BYTE *g);                        /* gray image: 1 byte per pixel, 0 black .. 255
                                                           white */
int LCDImageBinary(const BYTE *b);                      /* 1 byte per pixel: non-zero black, 0 white */

/* ---- Keys ------------------------------------------------------------------------------------ */

int KEYGet(void);              /* blocks until a soft key is pressed; KEY1..KEY4 (NOKEY on error) */
int KEYRead(void);             /* the key pressed now, or NOKEY; never blocks */
int KEYWait(int key);          /* blocks until a key in the mask (KEY1..KEY4, ANYKEY) is pressed; returns
                                  it */
int KEYGetXY(int *x, int *y);  /* blocks until the LCD is touched above the menu bar; pixel coordinates */
int KEYReadXY(int *x, int *y); /* 0 and the touch's coordinates, or 1 if there was none; never blocks */

/* ---- Time (the simulator's clock) and system ------------------------------------------------- */

int OSWait(int n);                    /* blocks for n milliseconds of simulation time */
int OSGetCount(void);                 /* milliseconds of simulation time (-1 on error) */
int OSGetTime(int *hrs, int *mins, int *secs, int *ticks); /* simulation time; ticks in ms */
char *OSExecute(const char *command); /* runs a shell command, returns its output (free() it) or NULL */
int OSVersion(char *buf);             /* the library's version text */
int OSVersionIO(char *buf);           /* the simulated I/O board's version text */
int OSMachineSpeed(void);             /* MACHINE_SPEED (Hz) */
int OSMachineType(void);              /* VEHICLE, or PLATFORM for a manipulator arm */
int OSMachineName(char *buf);         /* the robot's name from the scene */
int OSMachineID(void);                /* the robot's id (1.. in scene order) */

/* ---- Timers: functions the library calls every so many ms of simulation time ----------------- */

TIMER OSAttachTimer(int scale, void (*fct)(void)); /* call fct every scale ms of simulation time; 0 on
                                                      error */
int OSDetachTimer(TIMER t);                        /* fct is not called again once this returns */

/* ---- Serial interfaces: 0 = serial port, 1..20 = USB; byte streams the simulator carries ----- */

int SERInit(int interface, int baud, int handshake); /* baud 50..230400 */
int SERSendChar(int interface, char ch);             /* one byte */
int SERSend(int interface, const char *buf);         /* a NUL-terminated string */
char SERReceiveChar(int interface);                  /* blocks until a byte arrives */
int SERReceive(int interface, char *buf, int size);  /* up to size bytes already there (NUL added if room);
                                                        never blocks; -1 on error */
bool SERCheck(int interface);                        /* true when a byte is waiting */
int SERFlush(int interface);                         /* drops the bytes waiting */
int SERClose(int interface);                         /* close the interface */

/* ---- Audio ----------------------------------------------------------------------------------- */

int AUBeep(void);                 /* a short beep (0.2 s) */
int AUPlay(const char *filename); /* plays a WAV or MP3 file in the background */
int AUDone(void);                 /* 1 when nothing plays any more, 0 while playing */
int AUMicrophone(void);           /* one microphone sample, 0..1023 (silence 512) */

/* ---- Digital and analog I/O ------------------------------------------------------------------ */

int DIGITALSetup(int io, char direction);      /* line 1..16: 'i' in, 'o' out, 'I' in pull-up, 'J' in
                                                  pull-down */
int DIGITALRead(int io);                       /* 0 or 1 (-1 on error) */
int DIGITALReadAll(void);                      /* bit k-1 = line k */
int DIGITALWrite(int io, int state);           /* an output line: 0 or 1 */
int ANALOGRead(int channel);                   /* channel 1..8 (8 = microphone): 0..1023 (-1 on error) */
int ANALOGVoltage(void);                       /* battery voltage in 0.01 V */
int ANALOGRecord(int channel, int iterations); /* starts sampling at 1 kHz; never blocks */
int ANALOGTransfer(BYTE *buffer);              /* waits for the recording: 2 bytes per sample
                                                  (little-endian); returns the number of bytes (-1 on
                                                  error) */

/* ---- IR remote control ----------------------------------------------------------------------- */

int IRTVGet(void);       /* blocks until a code (IRTV_*) arrives */
int IRTVRead(void);      /* the next code, or 0 if none; never blocks */
int IRTVFlush(void);     /* drops the codes waiting */
int IRTVGetStatus(void); /* 1: the receiver is on */

/* ---- PSD distance sensors -------------------------------------------------------------------- */

int PSDGet(int psd);    /* distance in mm measured by PSD_FRONT/LEFT/RIGHT/BACK or 1..6 (-1 on error) */
int PSDGetRaw(int psd); /* raw 10-bit reading, 102300 / (mm + 100): 1023 at 0 mm, 93 at 1 m (-1 on error) */

/* ---- LIDAR --------------------------------------------------------------------------------------
 * index LIDAR_RESOLUTION/2 looks straight ahead, indices grow clockwise seen from above (360 points
 * over 360 degrees: 0 behind, 90 left, 180 ahead, 270 right); 9999 = nothing in range. */

extern int LIDAR_RESOLUTION;                   /* points per scan: 360 until LIDARSet changes it; LIDARGet
                                                  never writes more */
int LIDARSet(int range, int tilt, int points); /* field 1..360 deg centred ahead, tilt deg (front down
                                                  positive), points 1..3600 */
int LIDARGet(int distance[]);                  /* one scan in mm into LIDAR_RESOLUTION ints */
int SIMLaserScan(int scan[360]);               /* EyeSim 6's scan: 360 level beams in mm, one per degree,
                                                  index 0 ahead, counter-clockwise (a wall point is at x +
                                                  d*cos(phi + i)); the LIDARSet settings and
                                                  LIDAR_RESOLUTION stay */

/* ---- Camera: frames are rendered from the camera's pose on the robot ------------------------- */

extern int CAMWIDTH, CAMHEIGHT, CAMPIXELS, CAMSIZE; /* the size CAMInit chose (0 before) */
int CAMInit(int resolution);                        /* QQVGA .. CAM5MP (not CUSTOM); also sets the IP and
                                                       LCD image size; 0 = OK, CAM_FAILURE on error */
int CAMRelease(void);                               /* 0 = OK */
int CAMGet(BYTE *buf);                              /* CAMSIZE bytes: R, G, B per pixel, row by row from
                                                       the top left */
int CAMGetGray(BYTE *buf);                          /* CAMPIXELS bytes: (R + G + B) / 3 per pixel */

/* ---- Radio: messages between the robots of the scene; ids are robot ids (1.. in scene order) - */

int RADIOInit(void);                               /* switch the radio on; 0 = OK */
int RADIOGetID(void);                              /* this robot's id */
int RADIOSend(int id, const char *buf);            /* queue a text of at most 1024 bytes for robot id; 1
                                                      for an unknown id or before RADIOInit */
int RADIOReceive(int *id_no, char *buf, int size); /* blocks for the oldest message; its sender and text
                                                      (cut to size - 1 bytes, NUL added); returns the
                                                      number of bytes stored, -1 on error */
int RADIOCheck(void);                              /* 1 if a message waits, 0 if not, -1 on error */
int RADIOStatus(int IDlist[]);                     /* ids of all robots with the radio on (this one too);
                                                      returns their number */
int RADIORelease(void);                            /* switch the radio off */

/* ---- Servos; numbers per robot in docs/api/servo.md ------------------------------------------ */

int SERVOSet(int servo, int angle);           /* position 0..255 within the servo's SERVORange */
int SERVOSetRaw(int servo, int angle);        /* raw position 0..255, ignoring SERVORange */
int SERVORange(int servo, int low, int high); /* the raw positions SERVOSet 0 and 255 stand for */

/* ---- Motors and encoders; numbers per drive type in docs/api/motor.md ------------------------ */

int MOTORDrive(int motor, int speed);         /* open loop, -100..100 percent */
int MOTORDriveRaw(int motor, int speed);      /* the same (the simulator has no HDT table) */
int MOTORPID(int motor, int p, int i, int d); /* closed-loop gains 0..255; holds the set speed */
int MOTORPIDOff(int motor);                   /* back to open loop, unpowered */
int MOTORSpeed(int motor, int ticks);         /* closed-loop speed in encoder ticks per second */
int ENCODERRead(int quad);                    /* ticks since the last reset (1 on error) */
int ENCODERReset(int quad);                   /* set the count to 0 */

/* ---- V-omega driving: mm, mm/s, degrees (counter-clockwise positive), degrees/s -------------- */

int VWSetSpeed(int linSpeed, int angSpeed);      /* drive on until changed; (0, 0) stops */
int VWGetSpeed(int *linSpeed, int *angSpeed);    /* measured speeds */
int VWSetPosition(int x, int y, int phi);        /* overwrite the odometry pose; the robot stays */
int VWGetPosition(int *x, int *y, int *phi);     /* odometry pose */
int VWStraight(int dist, int lin_speed);         /* start driving dist mm (negative = backwards) */
int VWTurn(int angle, int ang_speed);            /* start turning on the spot */
int VWCurve(int dist, int angle, int lin_speed); /* start an arc of dist mm changing the heading by angle */
int VWDrive(int dx, int dy, int lin_speed);      /* start an arc to dx ahead, dy left; needs dx > |dy| */
int VWRemain(void);                              /* mm left of the manoeuvre (-1 on error) */
int VWStalled(void);                             /* 0 none, 1 left, 2 right, 3 both wheels stalled */
int VWDone(void);                                /* 1 manoeuvre finished, 0 still driving, -1 error */
int VWWait(void);                                /* blocks until the manoeuvre ends */
int VWDriveDone(void);                           /* older name of VWDone */
int VWDriveWait(void);                           /* older name of VWWait */
int VWDriveRemain(void);                         /* older name of VWRemain */

/* ---- Image processing, done in this library without the simulator -------------------------------
 * Every function works on images of the current IP size: IPSetSize, or CAMInit; QVGA at the start.
 * Colour images have 3 bytes per pixel (R, G, B), gray images 1, row by row from the top left. Bad
 * arguments (NULL buffers, unknown files) are reported on stderr as "eyesim: <function>: ...". */

extern int IP_WIDTH, IP_HEIGHT, IP_PIXELS, IP_SIZE;     /* the IP size: width, height, pixels, colour bytes */
int IPSetSize(int resolution);                          /* QQVGA .. CAM5MP; 1 for anything else (CUSTOM) */
int IPReadFile(const char *filename, BYTE *img);        /* PNM P1-P6, cropped or filled with black to the
                                                           IP size: 3 colour (P3/P6), 2 gray (P2/P5), 1
                                                           black and white (P1/P4, as gray 0/255), -1 error */
int IPWriteFile(const char *filename, const BYTE *img); /* binary PPM (P6); 1 on error */
int IPWriteFileGray(const char *filename, const BYTE *gray); /* binary PGM (P5); 1 on error */
void IPLaplace(const BYTE *grayIn, BYTE *grayOut);      /* |4c - 4 neighbours|, clipped; border 0; in-place
                                                           ok */
void IPSobel(const BYTE *grayIn, BYTE *grayOut);        /* (|gx| + |gy|) / 3, clipped; border 0; in-place
                                                           ok */
void IPCol2Gray(const BYTE *imgIn, BYTE *grayOut);      /* gray = (r + g + b) / 3 */
void IPGray2Col(const BYTE *imgIn, BYTE *colOut);       /* r = g = b = gray */
void IPRGB2Col(const BYTE *r, const BYTE *g, const BYTE *b, BYTE *imgOut); /* three planes -> colour */
void IPCol2HSI(const BYTE *img, BYTE *h, BYTE *s, BYTE *i); /* colour -> three planes */
void IPOverlay(const BYTE *c1, const BYTE *c2, BYTE *cOut); /* non-black pixels of c2 over c1 */
void IPOverlayGray(const BYTE *g1, const BYTE *g2, COLOR col, BYTE *cOut);
                                                        /* g1 in colour, col where g2 != 0 */
COLOR IPPRGB2Col(BYTE r, BYTE g, BYTE b);               /* 0xRRGGBB */
void IPPCol2RGB(COLOR col, BYTE *r, BYTE *g, BYTE *b);  /* 0xRRGGBB -> r, g, b */
void IPPCol2HSI(COLOR c, BYTE *h, BYTE *s, BYTE *i);    /* 0xRRGGBB -> hue, saturation, intensity (as
                                                           IPPRGB2HSI) */
BYTE IPPRGB2Hue(BYTE r, BYTE g, BYTE b);                /* 1..252: red 42, green 126, blue 210; 0 = gray
                                                           (no hue) */
void IPPRGB2HSI(BYTE r, BYTE g, BYTE b, BYTE *h, BYTE *s, BYTE *i); /* s = 255 (1 - min/mean), i = mean */

/* ---- Simulation only: true poses; id 0 = this program's robot, 1.. = robots in scene order --- */

int SIMGetRobot(int id, int *x, int *y, int *z, int *phi); /* non-zero for an unknown id */
int SIMSetRobot(int id, int x, int y, int z, int phi);  /* moves the robot at once */
int SIMGetObject(int id, int *x, int *y, int *z, int *phi); /* objects 1.. in scene order */
int SIMSetObject(int id, int x, int y, int z, int phi); /* non-zero for a fixed object */
int SIMGetRobotCount(void);                             /* robots in the scene */
int SIMGetObjectCount(void);                            /* objects (not robots) in the scene */

/* ==== End of the generated declarations ==== */

#if defined(EYESIM_EXPORTS_MARKED)
#pragma clang attribute pop
#endif
#if defined(_WIN32)
#pragma pop_macro("interface")
#endif

/* ---- Older programs (docs/api/compatibility.md): names that still work ------------------------ */

/* The LCD needs no set-up: LCDInit does nothing and returns 0. */
static inline int LCDInit(void)
{
    return 0;
}

/* X11-era EyeSim programs call XInitThreads before starting threads; nothing needs it now. With
 * <X11/Xlib.h> included first, Xlib's own function is used instead. */
#ifndef _X11_XLIB_H_
static inline int XInitThreads(void)
{
    return 1;
}
#endif

/* ---- Windows and macOS: sleeping in simulation time ------------------------------------------
 * On Linux libeyesim's own sleep, usleep, nanosleep and clock_nanosleep take the program's calls.
 * Windows cannot reroute a function so, and on macOS whether it does depends on the linker: there
 * these macros send the calls in code that includes eyebot.h to libeyesim, which waits in
 * simulation time once the program is connected and in wall time (the system's function) before.
 * On Windows also Sleep (milliseconds), when <windows.h> came before eyebot.h. See
 * docs/c-library.md, "Sleeping". */
#if defined(_WIN32) || defined(__APPLE__)
#if defined(EYESIM_EXPORTS_MARKED)
#pragma clang attribute push(__declspec(dllexport), apply_to = function)
#endif
unsigned es_sleep(unsigned seconds);
int es_usleep(useconds_t microseconds);
int es_nanosleep(const struct timespec *request, struct timespec *remaining);
#if defined(_WIN32)
int es_clock_nanosleep(clockid_t clock, int flags, const struct timespec *request, struct timespec *remaining);
void __stdcall es_Sleep(unsigned long milliseconds);
#endif
#if defined(EYESIM_EXPORTS_MARKED)
#pragma clang attribute pop
#endif
#ifndef EYESIM_BUILDING_LIBRARY
#undef sleep
#undef usleep
#undef nanosleep
#define sleep(seconds) es_sleep(seconds)
#define usleep(microseconds) es_usleep(microseconds)
#define nanosleep(request, remaining) es_nanosleep(request, remaining)
#if defined(_WIN32)
#undef clock_nanosleep
#define clock_nanosleep(clock, flags, request, remaining) es_clock_nanosleep(clock, flags, request, remaining)
#if defined(_SYNCHAPI_H_)
#undef Sleep
#define Sleep(milliseconds) es_Sleep(milliseconds)
#endif
#endif
#endif
#endif

#ifdef __cplusplus
}
#endif

#endif /* EYEBOT_H */
