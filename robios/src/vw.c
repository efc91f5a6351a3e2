/* vw.c: RoBIOS v-omega driving (mm, mm/s, degrees, degrees/s). */
#include "eyebot.h"
#include "transport.h"

#define VW_ERROR 1

int VWSetSpeed(int linSpeed, int angSpeed)
{
    es_value args[2] = {es_int(linSpeed), es_int(angSpeed)}, result[1];
    return es_call("VWSetSpeed", ES_OP_VW_SET_SPEED, args, result) ? VW_ERROR : (int)result[0].i;
}

int VWGetSpeed(int *linSpeed, int *angSpeed)
{
    es_value result[3] = {{0}};
    int rc = es_call("VWGetSpeed", ES_OP_VW_GET_SPEED, NULL, result);
    es_out(linSpeed, result[1].i); /* zeros after an error, never garbage */
    es_out(angSpeed, result[2].i);
    return rc ? VW_ERROR : (int)result[0].i;
}

int VWSetPosition(int x, int y, int phi)
{
    es_value args[3] = {es_int(x), es_int(y), es_int(phi)}, result[1];
    return es_call("VWSetPosition", ES_OP_VW_SET_POSITION, args, result) ? VW_ERROR : (int)result[0].i;
}

int VWGetPosition(int *x, int *y, int *phi)
{
    es_value result[4] = {{0}};
    int rc = es_call("VWGetPosition", ES_OP_VW_GET_POSITION, NULL, result);
    es_out(x, result[1].i);
    es_out(y, result[2].i);
    es_out(phi, result[3].i);
    return rc ? VW_ERROR : (int)result[0].i;
}

int VWStraight(int dist, int lin_speed)
{
    es_value args[2] = {es_int(dist), es_int(lin_speed)}, result[1];
    return es_call("VWStraight", ES_OP_VW_STRAIGHT, args, result) ? VW_ERROR : (int)result[0].i;
}

int VWTurn(int angle, int ang_speed)
{
    es_value args[2] = {es_int(angle), es_int(ang_speed)}, result[1];
    return es_call("VWTurn", ES_OP_VW_TURN, args, result) ? VW_ERROR : (int)result[0].i;
}

int VWCurve(int dist, int angle, int lin_speed)
{
    es_value args[3] = {es_int(dist), es_int(angle), es_int(lin_speed)}, result[1];
    return es_call("VWCurve", ES_OP_VW_CURVE, args, result) ? VW_ERROR : (int)result[0].i;
}

int VWDrive(int dx, int dy, int lin_speed)
{
    es_value args[3] = {es_int(dx), es_int(dy), es_int(lin_speed)}, result[1];
    return es_call("VWDrive", ES_OP_VW_DRIVE, args, result) ? VW_ERROR : (int)result[0].i;
}

static int vw_remain(const char *function)
{
    es_value result[1];
    return es_call(function, ES_OP_VW_REMAIN, NULL, result) ? -1 : (int)result[0].i;
}

int VWRemain(void)
{
    return vw_remain("VWRemain");
}

int VWDriveRemain(void)
{
    return vw_remain("VWDriveRemain");
}

int VWStalled(void)
{
    es_value result[1];
    return es_call("VWStalled", ES_OP_VW_STALLED, NULL, result) ? -1 : (int)result[0].i;
}

static int vw_done(const char *function)
{
    es_value result[1];
    return es_call(function, ES_OP_VW_DONE, NULL, result) ? -1 : (int)result[0].i;
}

static int vw_wait(const char *function)
{
    es_value result[1];
    return es_call(function, ES_OP_VW_WAIT, NULL, result) ? VW_ERROR : (int)result[0].i;
}

int VWDone(void)
{
    return vw_done("VWDone");
}

int VWWait(void)
{
    return vw_wait("VWWait");
}

int VWDriveDone(void)
{
    return vw_done("VWDriveDone");
}

int VWDriveWait(void)
{
    return vw_wait("VWDriveWait");
}
