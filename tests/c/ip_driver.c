/* ip_driver.c: runs one RoBIOS image-processing function on raw images in files, for tests/c/test_ip.py.
 *
 * ip_driver SIZE OP FILES...   SIZE is a resolution name (IPSetSize) or, when built together with
 * ip.c and -DIP_DIRECT, WIDTHxHEIGHT (any size, through the library-internal es_ip_set_size). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eyebot.h"
#ifdef IP_DIRECT
#include "ip_size.h"
#endif

static BYTE *load(const char *path)
{
    FILE *file = fopen(path, "rb");
    if (!file) {
        perror(path);
        exit(2);
    }
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    BYTE *data = malloc((size_t)size + 1);
    if (!data || fread(data, 1, (size_t)size, file) != (size_t)size)
        exit(2);
    fclose(file);
    return data;
}

static void save(const char *path, const void *data, size_t size)
{
    FILE *file = fopen(path, "wb");
    if (!file || fwrite(data, 1, size, file) != size || fclose(file) != 0) {
        perror(path);
        exit(2);
    }
}

static void set_size(const char *size)
{
    static const char *names[] = {"QQVGA", "QVGA", "VGA", "CAM1MP", "CAMHD", "CAM5MP"};
    for (int k = 0; k < 6; k++)
        if (strcmp(size, names[k]) == 0) {
            if (IPSetSize(k) != 0)
                exit(3);
            return;
        }
#ifdef IP_DIRECT
    int width, height;
    if (sscanf(size, "%dx%d", &width, &height) == 2 && es_ip_set_size(width, height) == 0)
        return;
#endif
    fprintf(stderr, "ip_driver: bad size %s\n", size);
    exit(2);
}

/* One record per r, g, b triple of the input, in the layout test_ip.py reads back. */
typedef struct {
    BYTE hue, h, s, i, h2, s2, i2, r, g, b;
    int col;
} pixel_record;

static void pixels(const char *in, const char *out, long triples)
{
    BYTE *rgb = load(in);
    pixel_record *records = calloc((size_t)triples, sizeof *records);
    for (long k = 0; k < triples; k++) {
        pixel_record *p = &records[k];
        BYTE r = rgb[3 * k], g = rgb[3 * k + 1], b = rgb[3 * k + 2];
        p->hue = IPPRGB2Hue(r, g, b);
        IPPRGB2HSI(r, g, b, &p->h, &p->s, &p->i);
        p->col = IPPRGB2Col(r, g, b);
        IPPCol2HSI(p->col, &p->h2, &p->s2, &p->i2);
        IPPCol2RGB(p->col, &p->r, &p->g, &p->b);
    }
    save(out, records, (size_t)triples * sizeof *records);
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return 2;
    const char *op = argv[2];
    char **f = argv + 3;
    if (strcmp(op, "record-size") == 0) {
        printf("%zu\n", sizeof(pixel_record));
        return 0;
    }
    set_size(argv[1]);
    size_t pixels_n = (size_t)IP_PIXELS, colour_n = (size_t)IP_SIZE;
    BYTE *out = malloc(colour_n), *out2 = malloc(pixels_n), *out3 = malloc(pixels_n);

    if (strcmp(op, "size") == 0) {
        printf("%d %d %d %d\n", IP_WIDTH, IP_HEIGHT, IP_PIXELS, IP_SIZE);
    } else if (strcmp(op, "laplace") == 0 || strcmp(op, "sobel") == 0) {
        void (*filter)(const BYTE *, BYTE *) = op[0] == 'l' ? IPLaplace : IPSobel;
        BYTE *in = load(f[0]);
        filter(in, out);
        save(f[1], out, pixels_n);
        filter(in, in); /* in place: the same result */
        save(f[2], in, pixels_n);
    } else if (strcmp(op, "col2gray") == 0) {
        IPCol2Gray(load(f[0]), out);
        save(f[1], out, pixels_n);
    } else if (strcmp(op, "gray2col") == 0) {
        IPGray2Col(load(f[0]), out);
        save(f[1], out, colour_n);
    } else if (strcmp(op, "rgb2col") == 0) {
        IPRGB2Col(load(f[0]), load(f[1]), load(f[2]), out);
        save(f[3], out, colour_n);
    } else if (strcmp(op, "col2hsi") == 0) {
        IPCol2HSI(load(f[0]), out, out2, out3);
        save(f[1], out, pixels_n);
        save(f[2], out2, pixels_n);
        save(f[3], out3, pixels_n);
    } else if (strcmp(op, "overlay") == 0) {
        IPOverlay(load(f[0]), load(f[1]), out);
        save(f[2], out, colour_n);
    } else if (strcmp(op, "overlaygray") == 0) {
        IPOverlayGray(load(f[0]), load(f[1]), (COLOR)strtol(f[2], NULL, 0), out);
        save(f[3], out, colour_n);
    } else if (strcmp(op, "pixels") == 0) {
        pixels(f[0], f[1], strtol(f[2], NULL, 10));
    } else if (strcmp(op, "read") == 0) {
        memset(out, 0xAB, colour_n); /* shows what the call wrote and what it left alone */
        printf("%d\n", IPReadFile(f[0], out));
        save(f[1], out, colour_n);
    } else if (strcmp(op, "write") == 0 || strcmp(op, "writegray") == 0) {
        BYTE *in = load(f[0]);
        printf("%d\n", op[5] ? IPWriteFileGray(f[1], in) : IPWriteFile(f[1], in));
    } else if (strcmp(op, "nulls") == 0) {
        /* Every image function given NULL buffers: a message each, never a crash. */
        IPLaplace(NULL, out);
        IPSobel(out, NULL);
        IPCol2Gray(NULL, NULL);
        IPGray2Col(NULL, out);
        IPRGB2Col(out, NULL, out, out);
        IPCol2HSI(out, out, NULL, out);
        IPOverlay(NULL, out, out);
        IPOverlayGray(out, NULL, RED, out);
        IPPCol2RGB(RED, NULL, NULL, NULL);
        IPPRGB2HSI(1, 2, 3, NULL, NULL, NULL);
        IPPCol2HSI(RED, NULL, NULL, NULL);
        printf("%d %d %d %d %d %d\n", IPReadFile(NULL, out), IPReadFile("x", NULL), IPWriteFile(NULL, out),
               IPWriteFileGray("x", NULL), IPSetSize(CUSTOM), IPSetSize(-1));
    } else {
        fprintf(stderr, "ip_driver: unknown op %s\n", op);
        return 2;
    }
    return 0;
}
