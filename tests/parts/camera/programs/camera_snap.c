/* Test program: camera errors, then one colour and one gray QVGA frame saved as camera.ppm and
 * camera.pgm in the program's directory, once the robot has settled. */
#include <stdio.h>
#include "eyebot.h"

static BYTE colour[QVGA_SIZE];
static BYTE gray[QVGA_PIXELS];

static int save(const char *name, const char *magic, const BYTE *data, size_t size)
{
    FILE *file = fopen(name, "wb");
    if (!file)
        return 1;
    fprintf(file, "%s\n%d %d\n255\n", magic, CAMWIDTH, CAMHEIGHT);
    fwrite(data, 1, size, file);
    return fclose(file);
}

int main(void)
{
    printf("before %d\n", CAMGet(colour));
    printf("custom %d\n", CAMInit(CUSTOM));
    OSWait(500);
    int rc = CAMInit(QVGA);
    printf("init %d %d %d %d %d\n", rc, CAMWIDTH, CAMHEIGHT, CAMPIXELS, CAMSIZE);
    int got_colour = CAMGet(colour);
    int got_gray = CAMGetGray(gray);
    printf("get %d %d\n", got_colour, got_gray);
    int saved_colour = save("camera.ppm", "P6", colour, QVGA_SIZE);
    printf("saved %d %d\n", saved_colour, save("camera.pgm", "P5", gray, QVGA_PIXELS));
    int released = CAMRelease();
    printf("release %d %d\n", released, CAMGet(colour));
    return 0;
}
