/* lcd.c: the RoBIOS LCD functions that do more than pass values through (api_gen.c has those): printf
 * formatting, and images of the size the program chose. */
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
    es_value result[1];
    return es_call(function, ES_OP_LCD_IMAGE, args, result) ? LCD_ERROR : (int)result[0].i;
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
