/* io.c: ANALOGTransfer, which copies the recording into the caller's buffer (the other DIGITAL and ANALOG
 * functions only pass values through: api_gen.c). */
#include <stdio.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

int ANALOGTransfer(BYTE *buffer)
{
    if (!buffer) {
        fprintf(stderr, "eyesim: ANALOGTransfer: the buffer is NULL\n");
        return -1;
    }
    es_value result[1];
    if (es_call("ANALOGTransfer", ES_OP_ANALOG_TRANSFER, NULL, result))
        return -1;
    memcpy(buffer, result[0].p, result[0].n);
    return (int)result[0].n;
}
