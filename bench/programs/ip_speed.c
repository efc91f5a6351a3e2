/* Benchmark: microseconds per call of each image-processing function on one image size, beside
 * copying a colour image of that size (memcpy, the baseline). Prints "name microseconds" lines. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "eyebot.h"

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

/* Best of 5 runs of `repeats` calls: the least disturbed by other work on the machine. */
#define TIME(name, call)                                                                          \
    do {                                                                                          \
        double best = 1e30;                                                                       \
        for (int run = 0; run < 5; run++) {                                                       \
            double start = now_us();                                                              \
            for (int k = 0; k < repeats; k++) {                                                   \
                call;                                                                             \
            }                                                                                     \
            double each = (now_us() - start) / repeats;                                           \
            best = each < best ? each : best;                                                     \
        }                                                                                         \
        printf("%s %.2f\n", name, best);                                                          \
    } while (0)

int main(int argc, char **argv)
{
    int resolution = argc > 1 ? atoi(argv[1]) : QVGA, repeats = argc > 2 ? atoi(argv[2]) : 50;
    if (IPSetSize(resolution))
        return 2;
    size_t pixels = (size_t)IP_PIXELS, bytes = (size_t)IP_SIZE;
    BYTE *col = malloc(bytes), *col2 = malloc(bytes), *out = malloc(bytes);
    BYTE *gray = malloc(pixels), *h = malloc(pixels), *s = malloc(pixels), *i = malloc(pixels);
    srand(1);
    for (size_t k = 0; k < bytes; k++)
        col[k] = col2[k] = (BYTE)rand();
    for (size_t k = 0; k < pixels; k++)
        gray[k] = (BYTE)rand();

    TIME("memcpy", memcpy(out, col, bytes); col[k % bytes] ^= out[0] & 1);
    TIME("IPLaplace", IPLaplace(gray, out));
    TIME("IPSobel", IPSobel(gray, out));
    TIME("IPCol2Gray", IPCol2Gray(col, out));
    TIME("IPGray2Col", IPGray2Col(gray, out));
    TIME("IPRGB2Col", IPRGB2Col(h, s, i, out));
    TIME("IPCol2HSI", IPCol2HSI(col, h, s, i));
    TIME("IPOverlay", IPOverlay(col, col2, out));
    TIME("IPOverlayGray", IPOverlayGray(gray, gray, RED, out));
    return 0;
}
