/* lcd.c: RoBIOS LCD functions: text, colours, fonts, modes, the soft-key menu, graphics, images. */
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "eyebot.h"
#include "transport.h"

#define LCD_ERROR 1

/* printf-style formatting: into `local` when it fits, else into a malloc'd string. */
static char *format_text(char *local, size_t size, const char *format, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(local, size, format ? format : "", ap);
    char *text = local;
    if (n < 0) {
        local[0] = '\0';
    } else if ((size_t)n >= size) {
        text = malloc((size_t)n + 1);
        if (text)
            vsnprintf(text, (size_t)n + 1, format, again);
        else
            text = local; /* out of memory: print what fitted */
    }
    va_end(again);
    return text;
}

/* Sends the formatted text as the last argument of `op` (after `row`, `column` for LCD_SET_PRINTF). */
static int print_text(const char *function, uint16_t op, int row, int column, const char *format, va_list ap)
{
    char local[256];
    char *text = format_text(local, sizeof local, format, ap);
    es_value args[3], result[1];
    if (op == ES_OP_LCD_SET_PRINTF) {
        args[0] = es_int(row);
        args[1] = es_int(column);
        args[2] = es_text(text);
    } else {
        args[0] = es_text(text);
    }
    int rc = es_call(function, op, args, result);
    if (text != local)
        free(text);
    return rc ? LCD_ERROR : (int)result[0].i;
}

int LCDPrintf(const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int rc = print_text("LCDPrintf", ES_OP_LCD_PRINTF, 0, 0, format, ap);
    va_end(ap);
    return rc;
}

int LCDSetPrintf(int row, int column, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    int rc = print_text("LCDSetPrintf", ES_OP_LCD_SET_PRINTF, row, column, format, ap);
    va_end(ap);
    return rc;
}

int LCDClear(void)
{
    es_value result[1];
    return es_call("LCDClear", ES_OP_LCD_CLEAR, NULL, result) ? LCD_ERROR : (int)result[0].i;
}

int LCDMenu(const char *key1, const char *key2, const char *key3, const char *key4)
{
    es_value args[4] = {es_text(key1), es_text(key2), es_text(key3), es_text(key4)}, result[1];
    return es_call("LCDMenu", ES_OP_LCD_MENU, args, result) ? LCD_ERROR : (int)result[0].i;
}

/* ---- Cursor, colours, fonts, modes ------------------------------------------------------------ */

/* Calls an op whose reply is just a result code. */
static int lcd_call(const char *function, uint16_t op, const es_value *args)
{
    es_value result[1];
    return es_call(function, op, args, result) ? LCD_ERROR : (int)result[0].i;
}

int LCDSetPos(int row, int column)
{
    es_value args[2] = {es_int(row), es_int(column)};
    return lcd_call("LCDSetPos", ES_OP_LCD_SET_POS, args);
}

int LCDGetPos(int *row, int *column)
{
    es_value result[3] = {{0}};
    int rc = es_call("LCDGetPos", ES_OP_LCD_GET_POS, NULL, result);
    es_out(row, result[1].i);
    es_out(column, result[2].i);
    return rc ? LCD_ERROR : (int)result[0].i;
}

int LCDSetColor(COLOR fg, COLOR bg)
{
    es_value args[2] = {es_int(fg), es_int(bg)};
    return lcd_call("LCDSetColor", ES_OP_LCD_SET_COLOR, args);
}

int LCDSetFont(int font, int variation)
{
    es_value args[2] = {es_int(font), es_int(variation)};
    return lcd_call("LCDSetFont", ES_OP_LCD_SET_FONT, args);
}

int LCDSetFontSize(int fontsize)
{
    es_value args[1] = {es_int(fontsize)};
    return lcd_call("LCDSetFontSize", ES_OP_LCD_SET_FONT_SIZE, args);
}

int LCDSetMode(int mode)
{
    es_value args[1] = {es_int(mode)};
    return lcd_call("LCDSetMode", ES_OP_LCD_SET_MODE, args);
}

int LCDMenuI(int pos, const char *string, COLOR fg, COLOR bg)
{
    es_value args[4] = {es_int(pos), es_text(string), es_int(fg), es_int(bg)};
    return lcd_call("LCDMenuI", ES_OP_LCD_MENU_I, args);
}

int LCDRefresh(void)
{
    return lcd_call("LCDRefresh", ES_OP_LCD_REFRESH, NULL);
}

/* ---- Graphics --------------------------------------------------------------------------------- */

int LCDGetSize(int *x, int *y)
{
    es_value result[3] = {{0}};
    int rc = es_call("LCDGetSize", ES_OP_LCD_GET_SIZE, NULL, result);
    es_out(x, result[1].i);
    es_out(y, result[2].i);
    return rc ? LCD_ERROR : (int)result[0].i;
}

int LCDPixel(int x, int y, COLOR col)
{
    es_value args[3] = {es_int(x), es_int(y), es_int(col)};
    return lcd_call("LCDPixel", ES_OP_LCD_PIXEL, args);
}

COLOR LCDGetPixel(int x, int y)
{
    es_value args[2] = {es_int(x), es_int(y)}, result[1];
    return es_call("LCDGetPixel", ES_OP_LCD_GET_PIXEL, args, result) ? -1 : (COLOR)result[0].i;
}

int LCDLine(int x1, int y1, int x2, int y2, COLOR col)
{
    es_value args[5] = {es_int(x1), es_int(y1), es_int(x2), es_int(y2), es_int(col)};
    return lcd_call("LCDLine", ES_OP_LCD_LINE, args);
}

int LCDArea(int x1, int y1, int x2, int y2, COLOR col, int fill)
{
    es_value args[6] = {es_int(x1), es_int(y1), es_int(x2), es_int(y2), es_int(col), es_int(fill)};
    return lcd_call("LCDArea", ES_OP_LCD_AREA, args);
}

int LCDCircle(int x1, int y1, int size, COLOR col, int fill)
{
    es_value args[5] = {es_int(x1), es_int(y1), es_int(size), es_int(col), es_int(fill)};
    return lcd_call("LCDCircle", ES_OP_LCD_CIRCLE, args);
}

/* ---- Images: their size and where they show are kept here, in the program ------------------ */

enum { IMAGE_COLOR = 0, IMAGE_GRAY = 1, IMAGE_BINARY = 2 }; /* LCD_IMAGE's format */

/* As in EyeSim, LCDImageStart sets both where images show and how many pixels their data has (a
 * 128 x 128 map after LCDImageStart(0, 0, 128, 128)); LCDImageSize and CAMInit set the size of
 * the images of programs that never call it. Images show 1:1. */
static pthread_mutex_t image_lock = PTHREAD_MUTEX_INITIALIZER;
static int image_width = QVGA_X, image_height = QVGA_Y; /* pixels of the images the program passes */
static int image_x, image_y;                            /* where their top-left corner shows */

int LCDImageSize(int t)
{
    static const int sizes[][2] = {{QQVGA_X, QQVGA_Y}, {QVGA_X, QVGA_Y},     {VGA_X, VGA_Y},
                                   {CAM1MP_X, CAM1MP_Y}, {CAMHD_X, CAMHD_Y}, {CAM5MP_X, CAM5MP_Y}};
    if (t == CUSTOM) /* the size LCDImageStart gives (or the last resolution) stays */
        return 0;
    if (t < QQVGA || t > CAM5MP) {
        fprintf(stderr, "eyesim: LCDImageSize: %d is not a resolution (QQVGA 0 .. CAM5MP 5, CUSTOM 10)\n", t);
        return LCD_ERROR;
    }
    pthread_mutex_lock(&image_lock);
    image_width = sizes[t][0];
    image_height = sizes[t][1];
    pthread_mutex_unlock(&image_lock);
    return 0;
}

int LCDImageStart(int x, int y, int xs, int ys)
{
    if (xs <= 0 || ys <= 0) {
        fprintf(stderr, "eyesim: LCDImageStart: the image size %d x %d is not positive\n", xs, ys);
        return LCD_ERROR;
    }
    pthread_mutex_lock(&image_lock);
    image_x = x;
    image_y = y;
    image_width = xs;
    image_height = ys;
    pthread_mutex_unlock(&image_lock);
    return 0;
}

static int draw_image(const char *function, const BYTE *pixels, int format)
{
    if (!pixels) {
        fprintf(stderr, "eyesim: %s: the image is NULL\n", function);
        return LCD_ERROR;
    }
    pthread_mutex_lock(&image_lock);
    int width = image_width, height = image_height, x = image_x, y = image_y;
    pthread_mutex_unlock(&image_lock);
    es_value data = {0};
    data.p = pixels;
    data.n = (uint32_t)width * (uint32_t)height * (format == IMAGE_COLOR ? 3u : 1u);
    es_value args[8] = {es_int(x), es_int(y), es_int(width), es_int(height), es_int(width), es_int(height),
                        es_int(format), data};
    return lcd_call(function, ES_OP_LCD_IMAGE, args);
}

int LCDImage(const BYTE *img)
{
    return draw_image("LCDImage", img, IMAGE_COLOR);
}

int LCDImageGray(const BYTE *g)
{
    return draw_image("LCDImageGray", g, IMAGE_GRAY);
}

int LCDImageBinary(const BYTE *b)
{
    return draw_image("LCDImageBinary", b, IMAGE_BINARY);
}
