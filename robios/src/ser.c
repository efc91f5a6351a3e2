/* ser.c: the RoBIOS serial functions that send or receive bytes through a buffer (the others only pass
 * values through: api_gen.c). Interfaces: 0 = serial port, 1..20 = USB. */
#include <stdio.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

#define SER_ERROR 1

static int ser_call(const char *function, uint16_t op, const es_value *args)
{
    es_value result[1];
    return es_call(function, op, args, result) ? SER_ERROR : (int)result[0].i;
}

static int send_bytes(const char *function, int interface, const void *bytes, size_t count)
{
    es_value data = {0};
    data.p = bytes;
    data.n = (uint32_t)count;
    es_value args[2] = {es_int(interface), data};
    return ser_call(function, ES_OP_SER_SEND, args);
}

int SERSendChar(int interface, char ch)
{
    return send_bytes("SERSendChar", interface, &ch, 1);
}

int SERSend(int interface, const char *buf)
{
    if (!buf) {
        fprintf(stderr, "eyesim: SERSend: the text is NULL\n");
        return SER_ERROR;
    }
    return send_bytes("SERSend", interface, buf, strlen(buf));
}

int SERReceive(int interface, char *buf, int size)
{
    if (!buf || size < 0) {
        fprintf(stderr, "eyesim: SERReceive: %s\n", buf ? "the size is negative" : "the buffer is NULL");
        return -1;
    }
    es_value args[2] = {es_int(interface), es_int(size)}, result[1];
    if (es_call("SERReceive", ES_OP_SER_RECEIVE, args, result))
        return -1;
    uint32_t count = result[0].n <= (uint32_t)size ? result[0].n : (uint32_t)size;
    memcpy(buf, result[0].p, count);
    if (count < (uint32_t)size)
        buf[count] = '\0'; /* text can be used as a string when there is room */
    return (int)count;
}

