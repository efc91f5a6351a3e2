/* key.c: RoBIOS key functions (the robot's four soft keys and touches on its LCD). */
#include "eyebot.h"
#include "transport.h"

int KEYGet(void)
{
    es_value result[1];
    return es_call("KEYGet", ES_OP_KEY_GET, NULL, result) ? NOKEY : (int)result[0].i;
}

int KEYRead(void)
{
    es_value result[1];
    return es_call("KEYRead", ES_OP_KEY_READ, NULL, result) ? NOKEY : (int)result[0].i;
}

int KEYWait(int key)
{
    es_value args[1] = {es_int(key)}, result[1];
    return es_call("KEYWait", ES_OP_KEY_WAIT, args, result) ? NOKEY : (int)result[0].i;
}

int KEYGetXY(int *x, int *y)
{
    es_value result[3] = {{0}};
    int rc = es_call("KEYGetXY", ES_OP_KEY_GET_XY, NULL, result);
    es_out(x, result[1].i);
    es_out(y, result[2].i);
    return rc ? 1 : (int)result[0].i;
}

int KEYReadXY(int *x, int *y)
{
    es_value result[3] = {{0}};
    if (es_call("KEYReadXY", ES_OP_KEY_READ_XY, NULL, result))
        return 1;
    if (result[0].i == 0) { /* a touch: otherwise x and y keep what they held */
        es_out(x, result[1].i);
        es_out(y, result[2].i);
    }
    return (int)result[0].i;
}
