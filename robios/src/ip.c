/* ip.c: RoBIOS image processing, computed here in the library on images of the IP size (no simulator call). */
#include <ctype.h>
#include <errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eyebot.h"
#include "ip_size.h"

#define IP_MAX_SIDE 8192   /* keeps IP_SIZE far inside an int */
#define PNM_MAX_SIDE 65535 /* larger PNM files are refused rather than risking huge allocations */

/* Published for programs (the hardware types.h has them); the IP functions use the private copy
 * below, so a program writing to these cannot make them overrun a buffer. */
int IP_WIDTH = QVGA_X, IP_HEIGHT = QVGA_Y, IP_PIXELS = QVGA_PIXELS, IP_SIZE = QVGA_SIZE;

static pthread_mutex_t size_lock = PTHREAD_MUTEX_INITIALIZER;
static int ip_width = QVGA_X, ip_height = QVGA_Y;

static void ip_error(const char *function, const char *format, ...)
{
    char message[512];
    va_list ap;
    va_start(ap, format);
    vsnprintf(message, sizeof message, format, ap);
    va_end(ap);
    fprintf(stderr, "eyesim: %s: %s\n", function, message); /* one call: lines of threads do not mix */
}

/* ---- The IP size ----------------------------------------------------------------------------- */

int es_ip_set_size(int width, int height)
{
    if (width < 1 || height < 1 || width > IP_MAX_SIDE || height > IP_MAX_SIDE)
        return 1;
    pthread_mutex_lock(&size_lock);
    ip_width = width;
    ip_height = height;
    IP_WIDTH = width;
    IP_HEIGHT = height;
    IP_PIXELS = width * height;
    IP_SIZE = 3 * width * height;
    pthread_mutex_unlock(&size_lock);
    return 0;
}

void es_ip_get_size(int *width, int *height)
{
    pthread_mutex_lock(&size_lock);
    *width = ip_width;
    *height = ip_height;
    pthread_mutex_unlock(&size_lock);
}

static size_t ip_pixels(void)
{
    int width, height;
    es_ip_get_size(&width, &height);
    return (size_t)width * (size_t)height;
}

int IPSetSize(int resolution)
{
    static const int sizes[][2] = {
        [QQVGA] = {QQVGA_X, QQVGA_Y}, [QVGA] = {QVGA_X, QVGA_Y},     [VGA] = {VGA_X, VGA_Y},
        [CAM1MP] = {CAM1MP_X, CAM1MP_Y}, [CAMHD] = {CAMHD_X, CAMHD_Y}, [CAM5MP] = {CAM5MP_X, CAM5MP_Y},
    };
    if (resolution < QQVGA || resolution > CAM5MP) {
        ip_error("IPSetSize", "resolution %d has no fixed size; use QQVGA, QVGA, VGA, CAM1MP, CAMHD or CAM5MP",
                 resolution);
        return 1;
    }
    return es_ip_set_size(sizes[resolution][0], sizes[resolution][1]);
}

/* ---- Single pixels and colours -------------------------------------------------------------- */

COLOR IPPRGB2Col(BYTE r, BYTE g, BYTE b)
{
    return (r << 16) | (g << 8) | b;
}

void IPPCol2RGB(COLOR col, BYTE *r, BYTE *g, BYTE *b)
{
    if (r)
        *r = (BYTE)((col >> 16) & 0xFF);
    if (g)
        *g = (BYTE)((col >> 8) & 0xFF);
    if (b)
        *b = (BYTE)(col & 0xFF);
}

/* Hue on a circle of 252 steps, three sectors of 84 centred on red (42), green (126) and blue
 * (210); 0 means no hue (gray). The circle closes at red, so 0 there is written as 252. */
BYTE IPPRGB2Hue(BYTE r, BYTE g, BYTE b)
{
    int max = r > g ? (r > b ? r : b) : (g > b ? g : b);
    int min = r < g ? (r < b ? r : b) : (g < b ? g : b);
    int delta = max - min, hue;
    if (delta == 0)
        return 0;
    if (r == max)
        hue = 42 + 42 * (g - b) / delta;
    else if (g == max)
        hue = 126 + 42 * (b - r) / delta;
    else
        hue = 210 + 42 * (r - g) / delta;
    return (BYTE)(hue <= 0 ? hue + 252 : hue);
}

/* HSI: hue as IPPRGB2Hue; saturation 255 * (1 - min / mean); intensity = mean of r, g, b. */
void IPPRGB2HSI(BYTE r, BYTE g, BYTE b, BYTE *h, BYTE *s, BYTE *i)
{
    int min = r < g ? (r < b ? r : b) : (g < b ? g : b);
    int sum = r + g + b;
    if (h)
        *h = IPPRGB2Hue(r, g, b);
    if (s)
        *s = (BYTE)(sum == 0 ? 0 : 255 - 765 * min / sum);
    if (i)
        *i = (BYTE)(sum / 3);
}

void IPPCol2HSI(COLOR c, BYTE *h, BYTE *s, BYTE *i)
{
    BYTE r, g, b;
    IPPCol2RGB(c, &r, &g, &b);
    IPPRGB2HSI(r, g, b, h, s, i);
}

/* ---- Whole images ---------------------------------------------------------------------------- */

/* True when none of the `count` buffers is NULL; otherwise reports it. */
static int buffers_given(const char *function, int count, ...)
{
    va_list ap;
    int ok = 1;
    va_start(ap, count);
    for (int k = 0; k < count; k++)
        if (va_arg(ap, const void *) == NULL)
            ok = 0;
    va_end(ap);
    if (!ok)
        ip_error(function, "an image buffer is NULL");
    return ok;
}

/* Applies a 3x3 operator to every inner pixel; the one-pixel frame becomes 0, having no neighbours
 * all round. The output may be the input buffer. */
static void edge_filter(const char *function, const BYTE *in, BYTE *out, int (*at)(const BYTE *, int))
{
    int width, height;
    if (!buffers_given(function, 2, in, out))
        return;
    es_ip_get_size(&width, &height);
    size_t pixels = (size_t)width * (size_t)height;
    BYTE *copy = NULL;
    if (in == out) {
        copy = malloc(pixels);
        if (!copy) {
            ip_error(function, "out of memory");
            return;
        }
        memcpy(copy, in, pixels);
        in = copy;
    }
    for (int y = 0; y < height; y++) {
        BYTE *row = out + (size_t)y * (size_t)width;
        const BYTE *source = in + (size_t)y * (size_t)width;
        if (y == 0 || y == height - 1) {
            memset(row, 0, (size_t)width);
            continue;
        }
        row[0] = row[width - 1] = 0;
        for (int x = 1; x < width - 1; x++)
            row[x] = (BYTE)at(source + x, width);
    }
    free(copy);
}

static int clip(int value)
{
    return value > 255 ? 255 : value;
}

static int laplace_at(const BYTE *p, int w)
{
    return clip(abs(4 * p[0] - p[-1] - p[1] - p[-w] - p[w]));
}

/* |gx| + |gy| of the Sobel kernels, divided by 3 (the usual RoBIOS scaling) and clipped. */
static int sobel_at(const BYTE *p, int w)
{
    int gx = (p[-w + 1] + 2 * p[1] + p[w + 1]) - (p[-w - 1] + 2 * p[-1] + p[w - 1]);
    int gy = (p[-w - 1] + 2 * p[-w] + p[-w + 1]) - (p[w - 1] + 2 * p[w] + p[w + 1]);
    return clip((abs(gx) + abs(gy)) / 3);
}

void IPLaplace(const BYTE *grayIn, BYTE *grayOut)
{
    edge_filter("IPLaplace", grayIn, grayOut, laplace_at);
}

void IPSobel(const BYTE *grayIn, BYTE *grayOut)
{
    edge_filter("IPSobel", grayIn, grayOut, sobel_at);
}

/* Gray = mean of r, g, b. Going forwards, grayOut may be imgIn itself. */
void IPCol2Gray(const BYTE *imgIn, BYTE *grayOut)
{
    if (!buffers_given("IPCol2Gray", 2, imgIn, grayOut))
        return;
    size_t pixels = ip_pixels();
    for (size_t k = 0; k < pixels; k++)
        grayOut[k] = (BYTE)((imgIn[3 * k] + imgIn[3 * k + 1] + imgIn[3 * k + 2]) / 3);
}

/* r = g = b = gray. Going backwards, colOut may be imgIn itself. */
void IPGray2Col(const BYTE *imgIn, BYTE *colOut)
{
    if (!buffers_given("IPGray2Col", 2, imgIn, colOut))
        return;
    for (size_t k = ip_pixels(); k-- > 0;) {
        BYTE gray = imgIn[k];
        colOut[3 * k] = colOut[3 * k + 1] = colOut[3 * k + 2] = gray;
    }
}

void IPRGB2Col(const BYTE *r, const BYTE *g, const BYTE *b, BYTE *imgOut)
{
    if (!buffers_given("IPRGB2Col", 4, r, g, b, imgOut))
        return;
    size_t pixels = ip_pixels();
    for (size_t k = 0; k < pixels; k++) {
        imgOut[3 * k] = r[k];
        imgOut[3 * k + 1] = g[k];
        imgOut[3 * k + 2] = b[k];
    }
}

void IPCol2HSI(const BYTE *img, BYTE *h, BYTE *s, BYTE *i)
{
    if (!buffers_given("IPCol2HSI", 4, img, h, s, i))
        return;
    size_t pixels = ip_pixels();
    for (size_t k = 0; k < pixels; k++)
        IPPRGB2HSI(img[3 * k], img[3 * k + 1], img[3 * k + 2], &h[k], &s[k], &i[k]);
}

/* Pixels of c2 that are not black replace those of c1. cOut may be c1 or c2. */
void IPOverlay(const BYTE *c1, const BYTE *c2, BYTE *cOut)
{
    if (!buffers_given("IPOverlay", 3, c1, c2, cOut))
        return;
    size_t bytes = 3 * ip_pixels();
    for (size_t k = 0; k < bytes; k += 3) {
        const BYTE *from = (c2[k] | c2[k + 1] | c2[k + 2]) ? c2 : c1;
        cOut[k] = from[k];
        cOut[k + 1] = from[k + 1];
        cOut[k + 2] = from[k + 2];
    }
}

/* The gray image g1 in colour, with the pixels where g2 is not 0 painted in col. */
void IPOverlayGray(const BYTE *g1, const BYTE *g2, COLOR col, BYTE *cOut)
{
    BYTE r, g, b;
    if (!buffers_given("IPOverlayGray", 3, g1, g2, cOut))
        return;
    IPPCol2RGB(col, &r, &g, &b);
    for (size_t k = ip_pixels(); k-- > 0;) { /* backwards: cOut may be g1 */
        BYTE gray = g1[k];
        int marked = g2[k] != 0;
        cOut[3 * k] = marked ? r : gray;
        cOut[3 * k + 1] = marked ? g : gray;
        cOut[3 * k + 2] = marked ? b : gray;
    }
}

/* ---- PNM files ------------------------------------------------------------------------------- */

typedef struct {
    FILE *file;
    const char *name;
    int format; /* 1..6 as in P1..P6 */
    int width, height, maxval;
} pnm_reader;

static int is_pnm_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* Skips whitespace and '#' comments; returns the next other character (or EOF). */
static int skip_space(FILE *file)
{
    int c = getc(file);
    while (c == '#' || is_pnm_space(c)) {
        if (c == '#')
            while (c != '\n' && c != '\r' && c != EOF)
                c = getc(file);
        c = getc(file);
    }
    return c;
}

/* Reads an unsigned decimal number after whitespace/comments; -1 if there is none. The one
 * character after it is consumed when it is whitespace (as the header's last field requires). */
static long read_number(FILE *file)
{
    int c = skip_space(file);
    long value = 0;
    if (!isdigit(c))
        return -1;
    for (; isdigit(c); c = getc(file))
        if (value <= 10000000)
            value = value * 10 + (c - '0'); /* larger values are invalid anyway; stop growing */
    if (c != EOF && !is_pnm_space(c))
        ungetc(c, file);
    return value;
}

static int read_header(pnm_reader *pnm)
{
    FILE *file = pnm->file;
    int p = getc(file), digit = getc(file);
    if (p != 'P' || digit < '1' || digit > '6') {
        ip_error("IPReadFile", "'%s' is not a PNM file (it does not start with P1 to P6)", pnm->name);
        return -1;
    }
    pnm->format = digit - '0';
    int has_maxval = pnm->format != 1 && pnm->format != 4;
    long width = read_number(file), height = read_number(file);
    long maxval = has_maxval ? read_number(file) : 1;
    if (width < 1 || height < 1 || width > PNM_MAX_SIDE || height > PNM_MAX_SIDE) {
        ip_error("IPReadFile", "'%s': bad width and height in the header (1 to %d each)", pnm->name, PNM_MAX_SIDE);
        return -1;
    }
    if (maxval < 1 || maxval > 65535) {
        ip_error("IPReadFile", "'%s': bad maxval in the header (1 to 65535)", pnm->name);
        return -1;
    }
    pnm->width = (int)width;
    pnm->height = (int)height;
    pnm->maxval = (int)maxval;
    return 0;
}

static int truncated(const pnm_reader *pnm)
{
    ip_error("IPReadFile", "'%s' ends before all of its %d x %d pixels", pnm->name, pnm->width, pnm->height);
    return -1;
}

/* One plain (ASCII) sample: a decimal number, or for P1 a single 0 or 1. -1 after an error. */
static long plain_sample(const pnm_reader *pnm)
{
    if (pnm->format == 1) {
        int c = skip_space(pnm->file);
        if (c == EOF)
            return truncated(pnm);
        if (c != '0' && c != '1') {
            ip_error("IPReadFile", "'%s': a plain PBM holds only 0 and 1, found '%c'", pnm->name, c);
            return -1;
        }
        return c - '0';
    }
    long value = read_number(pnm->file);
    if (value < 0) {
        if (feof(pnm->file))
            return truncated(pnm);
        ip_error("IPReadFile", "'%s': expected a number among the pixels", pnm->name);
        return -1;
    }
    return value;
}

/* Reads one row of samples (channels per pixel) into `samples`; 0, or -1 after an error. */
static int read_row(const pnm_reader *pnm, int channels, long *samples, BYTE *raw)
{
    size_t count = (size_t)pnm->width * (size_t)channels;
    if (pnm->format <= 3) {
        for (size_t k = 0; k < count; k++)
            if ((samples[k] = plain_sample(pnm)) < 0)
                return -1;
    } else if (pnm->format == 4) {
        size_t bytes = ((size_t)pnm->width + 7) / 8; /* rows are padded to whole bytes, first pixel in the high bit */
        if (fread(raw, 1, bytes, pnm->file) != bytes)
            return truncated(pnm);
        for (size_t k = 0; k < count; k++)
            samples[k] = (raw[k / 8] >> (7 - k % 8)) & 1;
    } else {
        size_t width = pnm->maxval > 255 ? 2 : 1; /* 16-bit samples are big-endian */
        if (fread(raw, width, count, pnm->file) != count)
            return truncated(pnm);
        for (size_t k = 0; k < count; k++)
            samples[k] = width == 2 ? (raw[2 * k] << 8) | raw[2 * k + 1] : raw[k];
    }
    for (size_t k = 0; k < count; k++)
        if (samples[k] > pnm->maxval) {
            ip_error("IPReadFile", "'%s': a sample (%ld) is larger than the maxval (%d)", pnm->name, samples[k],
                     pnm->maxval);
            return -1;
        }
    return 0;
}

/* Reads every pixel into `image` (IP size, `channels` bytes per pixel, zero-filled), cropping
 * what lies outside it. Samples are scaled to 0..255; in a PBM 1 is black (0) and 0 white (255). */
static int read_pixels(const pnm_reader *pnm, int channels, BYTE *image, int ip_w, int ip_h)
{
    size_t count = (size_t)pnm->width * (size_t)channels;
    long *samples = malloc(count * sizeof *samples);
    BYTE *raw = malloc(count * 2);
    int rc = 0;
    if (!samples || !raw) {
        ip_error("IPReadFile", "out of memory for '%s'", pnm->name);
        rc = -1;
    }
    int bitmap = pnm->format == 1 || pnm->format == 4;
    for (int y = 0; rc == 0 && y < pnm->height; y++) {
        rc = read_row(pnm, channels, samples, raw);
        if (rc || y >= ip_h)
            continue;
        int columns = pnm->width < ip_w ? pnm->width : ip_w;
        BYTE *row = image + (size_t)y * (size_t)ip_w * (size_t)channels;
        for (size_t k = 0; k < (size_t)columns * (size_t)channels; k++) {
            long v = samples[k];
            row[k] = (BYTE)(bitmap ? (v ? 0 : 255) : (v * 255 + pnm->maxval / 2) / pnm->maxval);
        }
    }
    free(samples);
    free(raw);
    return rc;
}

int IPReadFile(const char *filename, BYTE *img)
{
    if (!filename || !img) {
        ip_error("IPReadFile", filename ? "the image buffer is NULL" : "the file name is NULL");
        return -1;
    }
    pnm_reader pnm = {.file = fopen(filename, "rb"), .name = filename};
    if (!pnm.file) {
        ip_error("IPReadFile", "cannot open '%s': %s", filename, strerror(errno));
        return -1;
    }
    int ip_w, ip_h, rc = read_header(&pnm);
    es_ip_get_size(&ip_w, &ip_h);
    int channels = pnm.format == 3 || pnm.format == 6 ? 3 : 1;
    size_t bytes = (size_t)ip_w * (size_t)ip_h * (size_t)channels;
    BYTE *image = rc ? NULL : calloc(bytes, 1); /* filled with black where the file has no pixels */
    if (rc == 0 && !image) {
        ip_error("IPReadFile", "out of memory for '%s'", filename);
        rc = -1;
    }
    if (rc == 0)
        rc = read_pixels(&pnm, channels, image, ip_w, ip_h);
    fclose(pnm.file);
    if (rc == 0)
        memcpy(img, image, bytes); /* only a complete image reaches the caller's buffer */
    free(image);
    if (rc)
        return -1;
    return pnm.format == 3 || pnm.format == 6 ? 3 : pnm.format == 2 || pnm.format == 5 ? 2 : 1;
}

static int write_pnm(const char *function, const char *filename, const BYTE *img, int channels)
{
    int width, height;
    if (!filename || !img) {
        ip_error(function, filename ? "the image buffer is NULL" : "the file name is NULL");
        return 1;
    }
    es_ip_get_size(&width, &height);
    FILE *file = fopen(filename, "wb");
    if (!file) {
        ip_error(function, "cannot create '%s': %s", filename, strerror(errno));
        return 1;
    }
    size_t pixels = (size_t)width * (size_t)height;
    fprintf(file, "P%d\n%d %d\n255\n", channels == 3 ? 6 : 5, width, height);
    int failed = fwrite(img, (size_t)channels, pixels, file) != pixels;
    if (fclose(file) != 0 || failed) {
        ip_error(function, "cannot write '%s': %s", filename, strerror(errno));
        return 1;
    }
    return 0;
}

int IPWriteFile(const char *filename, const BYTE *img)
{
    return write_pnm("IPWriteFile", filename, img, 3);
}

int IPWriteFileGray(const char *filename, const BYTE *gray)
{
    return write_pnm("IPWriteFileGray", filename, gray, 1);
}
