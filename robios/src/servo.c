/* servo.c: RoBIOS servos, positions 0..255 (steering, arm joints, grippers: docs/api/servo.md). */
#include "eyebot.h"
#include "transport.h"

#define SERVO_ERROR 1

static int servo_call(const char *function, uint16_t op, const es_value *args)
{
    es_value result[1];
    return es_call(function, op, args, result) ? SERVO_ERROR : (int)result[0].i;
}

int SERVOSet(int servo, int angle)
{
    es_value args[2] = {es_int(servo), es_int(angle)};
    return servo_call("SERVOSet", ES_OP_SERVO_SET, args);
}

int SERVOSetRaw(int servo, int angle)
{
    es_value args[2] = {es_int(servo), es_int(angle)};
    return servo_call("SERVOSetRaw", ES_OP_SERVO_SET_RAW, args);
}

int SERVORange(int servo, int low, int high)
{
    es_value args[3] = {es_int(servo), es_int(low), es_int(high)};
    return servo_call("SERVORange", ES_OP_SERVO_RANGE, args);
}
