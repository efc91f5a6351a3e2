/* io.c: RoBIOS digital and analog I/O: 16 digital lines, 8 analog channels, the battery voltage. */
#include <stdio.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

#define IO_ERROR 1

int DIGITALSetup(int io, char direction)
{
    es_value args[2] = {es_int(io), es_int((unsigned char)direction)}, result[1];
    return es_call("DIGITALSetup", ES_OP_DIGITAL_SETUP, args, result) ? IO_ERROR : (int)result[0].i;
}

int DIGITALRead(int io)
{
    es_value args[1] = {es_int(io)}, result[1];
    return es_call("DIGITALRead", ES_OP_DIGITAL_READ, args, result) ? -1 : (int)result[0].i;
}

int DIGITALReadAll(void)
{
    es_value result[1];
    return es_call("DIGITALReadAll", ES_OP_DIGITAL_READ_ALL, NULL, result) ? -1 : (int)result[0].i;
}

int DIGITALWrite(int io, int state)
{
    es_value args[2] = {es_int(io), es_int(state)}, result[1];
    return es_call("DIGITALWrite", ES_OP_DIGITAL_WRITE, args, result) ? IO_ERROR : (int)result[0].i;
}

int ANALOGRead(int channel)
{
    es_value args[1] = {es_int(channel)}, result[1];
    return es_call("ANALOGRead", ES_OP_ANALOG_READ, args, result) ? -1 : (int)result[0].i;
}

int ANALOGVoltage(void)
{
    es_value result[1];
    return es_call("ANALOGVoltage", ES_OP_ANALOG_VOLTAGE, NULL, result) ? -1 : (int)result[0].i;
}

int ANALOGRecord(int channel, int iterations)
{
    es_value args[2] = {es_int(channel), es_int(iterations)}, result[1];
    return es_call("ANALOGRecord", ES_OP_ANALOG_RECORD, args, result) ? IO_ERROR : (int)result[0].i;
}

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
