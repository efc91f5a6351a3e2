/* radio.c: the RoBIOS radio functions that check or fill the caller's buffers (the others only pass values
 * through: api_gen.c). Messages go between the robots of a scene; ids are robot ids. */
#include "eyebot.h"
#include "transport.h"

#include <stdio.h>
#include <string.h>

int RADIOSend(int id, const char *buf)
{
    if (!buf) {
        fprintf(stderr, "eyesim: RADIOSend: the message is NULL\n");
        return 1;
    }
    es_value args[2] = {es_int(id), es_text(buf)}, result[1];
    return es_call("RADIOSend", ES_OP_RADIO_SEND, args, result) ? 1 : (int)result[0].i;
}

int RADIOReceive(int *id_no, char *buf, int size)
{
    if (!buf || size < 1) {
        fprintf(stderr, "eyesim: RADIOReceive: the buffer is NULL or has no room (size %d)\n", size);
        return -1;
    }
    es_value result[2] = {{0}};
    if (es_call("RADIOReceive", ES_OP_RADIO_RECEIVE, NULL, result)) {
        buf[0] = '\0';
        es_out(id_no, 0);
        return -1;
    }
    /* A message longer than the buffer is cut to fit, always NUL-terminated. */
    uint32_t length = result[1].n < (uint32_t)size - 1 ? result[1].n : (uint32_t)size - 1;
    memcpy(buf, result[1].p, length);
    buf[length] = '\0';
    es_out(id_no, result[0].i);
    return (int)length;
}

int RADIOStatus(int IDlist[])
{
    es_value result[1] = {{0}};
    if (es_call("RADIOStatus", ES_OP_RADIO_STATUS, NULL, result))
        return -1;
    if (IDlist)
        for (uint32_t k = 0; k < result[0].n; k++)
            IDlist[k] = es_i32s_at(&result[0], k);
    return (int)result[0].n;
}

