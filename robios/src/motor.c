/* motor.c: RoBIOS motors and encoders (numbers per drive type: docs/api/motor.md). */
#include "eyebot.h"
#include "transport.h"

#define MOTOR_ERROR 1
#define ENCODER_ERROR 1 /* as the RoBIOS header says; the message on stderr tells it from a count */

static int motor_call(const char *function, uint16_t op, const es_value *args)
{
    es_value result[1];
    return es_call(function, op, args, result) ? MOTOR_ERROR : (int)result[0].i;
}

int MOTORDrive(int motor, int speed)
{
    es_value args[2] = {es_int(motor), es_int(speed)};
    return motor_call("MOTORDrive", ES_OP_MOTOR_DRIVE, args);
}

int MOTORDriveRaw(int motor, int speed)
{
    es_value args[2] = {es_int(motor), es_int(speed)};
    return motor_call("MOTORDriveRaw", ES_OP_MOTOR_DRIVE_RAW, args);
}

int MOTORPID(int motor, int p, int i, int d)
{
    es_value args[4] = {es_int(motor), es_int(p), es_int(i), es_int(d)};
    return motor_call("MOTORPID", ES_OP_MOTOR_PID, args);
}

int MOTORPIDOff(int motor)
{
    es_value args[1] = {es_int(motor)};
    return motor_call("MOTORPIDOff", ES_OP_MOTOR_PID_OFF, args);
}

int MOTORSpeed(int motor, int ticks)
{
    es_value args[2] = {es_int(motor), es_int(ticks)};
    return motor_call("MOTORSpeed", ES_OP_MOTOR_SPEED, args);
}

int ENCODERRead(int quad)
{
    es_value args[1] = {es_int(quad)}, result[1];
    return es_call("ENCODERRead", ES_OP_ENCODER_READ, args, result) ? ENCODER_ERROR : (int)result[0].i;
}

int ENCODERReset(int quad)
{
    es_value args[1] = {es_int(quad)};
    return motor_call("ENCODERReset", ES_OP_ENCODER_RESET, args);
}
