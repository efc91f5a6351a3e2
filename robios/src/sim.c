/* sim.c: simulation-only functions: the true poses of robots. */
#include "eyebot.h"
#include "transport.h"

int SIMGetRobot(int id, int *x, int *y, int *z, int *phi)
{
    es_value args[1] = {es_int(id)}, result[5] = {{0}};
    int rc = es_call("SIMGetRobot", ES_OP_SIM_GET_ROBOT, args, result);
    es_out(x, result[1].i); /* zeros after an error, never garbage */
    es_out(y, result[2].i);
    es_out(z, result[3].i);
    es_out(phi, result[4].i);
    return rc ? 1 : (int)result[0].i;
}

int SIMSetRobot(int id, int x, int y, int z, int phi)
{
    es_value args[5] = {es_int(id), es_int(x), es_int(y), es_int(z), es_int(phi)}, result[1];
    return es_call("SIMSetRobot", ES_OP_SIM_SET_ROBOT, args, result) ? 1 : (int)result[0].i;
}
