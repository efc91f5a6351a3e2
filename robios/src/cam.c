/* cam.c: RoBIOS camera: CAMInit chooses the resolution, CAMGet/CAMGetGray fetch rendered frames. */
#include "eyebot.h"
#include "transport.h"

#include <stdio.h>
#include <string.h>

int CAMWIDTH, CAMHEIGHT, CAMPIXELS, CAMSIZE; /* 0 until CAMInit */

int CAMInit(int resolution)
{
    es_value args[1] = {es_int(resolution)}, result[3];
    if (es_call("CAMInit", ES_OP_CAM_INIT, args, result))
        return CAM_FAILURE;
    CAMWIDTH = (int)result[1].i;
    CAMHEIGHT = (int)result[2].i;
    CAMPIXELS = CAMWIDTH * CAMHEIGHT;
    CAMSIZE = CAMPIXELS * 3;
    /* The image processing and LCD image functions work on camera-sized images from now on. */
    IPSetSize(resolution);
    LCDImageSize(resolution);
    return (int)result[0].i;
}

int CAMRelease(void)
{
    es_value result[1];
    if (es_call("CAMRelease", ES_OP_CAM_RELEASE, NULL, result))
        return CAM_FAILURE;
    CAMWIDTH = CAMHEIGHT = CAMPIXELS = CAMSIZE = 0;
    return (int)result[0].i;
}

/* One frame of `bytes_per_pixel` into buf, which holds at least width * height of them. */
static int get_frame(const char *function, uint16_t op, BYTE *buf, int bytes_per_pixel)
{
    if (!buf) {
        fprintf(stderr, "eyesim: %s: the image buffer is NULL\n", function);
        return CAM_FAILURE;
    }
    es_value result[4] = {{0}};
    if (es_call(function, op, NULL, result))
        return CAM_FAILURE;
    uint32_t expected = (uint32_t)(result[1].i * result[2].i * bytes_per_pixel);
    if (result[3].n != expected) {
        fprintf(stderr, "eyesim: %s: the simulator sent %u bytes for a %d x %d image\n", function,
                (unsigned)result[3].n, (int)result[1].i, (int)result[2].i);
        return CAM_FAILURE;
    }
    memcpy(buf, result[3].p, result[3].n);
    return (int)result[0].i;
}

int CAMGet(BYTE *buf)
{
    return get_frame("CAMGet", ES_OP_CAM_GET, buf, 3);
}

int CAMGetGray(BYTE *buf)
{
    return get_frame("CAMGetGray", ES_OP_CAM_GET_GRAY, buf, 1);
}
