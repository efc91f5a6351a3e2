/* sim.c: simulation-only functions: the true poses of robots and objects, and how many there are. */
#include "eyebot.h"
#include "transport.h"

static int get_pose(const char *function, uint16_t op, int id, int *x, int *y, int *z, int *phi)
{
    es_value args[1] = {es_int(id)}, result[5] = {{0}};
    int rc = es_call(function, op, args, result);
    es_out(x, result[1].i); /* zeros after an error, never garbage */
    es_out(y, result[2].i);
    es_out(z, result[3].i);
    es_out(phi, result[4].i);
    return rc ? 1 : (int)result[0].i;
}

static int set_pose(const char *function, uint16_t op, int id, int x, int y, int z, int phi)
{
    es_value args[5] = {es_int(id), es_int(x), es_int(y), es_int(z), es_int(phi)}, result[1];
    return es_call(function, op, args, result) ? 1 : (int)result[0].i;
}

static int count(const char *function, uint16_t op)
{
    es_value result[1];
    return es_call(function, op, NULL, result) ? -1 : (int)result[0].i;
}

int SIMGetRobot(int id, int *x, int *y, int *z, int *phi)
{
    return get_pose("SIMGetRobot", ES_OP_SIM_GET_ROBOT, id, x, y, z, phi);
}

int SIMSetRobot(int id, int x, int y, int z, int phi)
{
    return set_pose("SIMSetRobot", ES_OP_SIM_SET_ROBOT, id, x, y, z, phi);
}

int SIMGetObject(int id, int *x, int *y, int *z, int *phi)
{
    return get_pose("SIMGetObject", ES_OP_SIM_GET_OBJECT, id, x, y, z, phi);
}

int SIMSetObject(int id, int x, int y, int z, int phi)
{
    return set_pose("SIMSetObject", ES_OP_SIM_SET_OBJECT, id, x, y, z, phi);
}

int SIMGetRobotCount(void)
{
    return count("SIMGetRobotCount", ES_OP_SIM_GET_ROBOT_COUNT);
}

int SIMGetObjectCount(void)
{
    return count("SIMGetObjectCount", ES_OP_SIM_GET_OBJECT_COUNT);
}
