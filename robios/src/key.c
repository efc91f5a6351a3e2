/* key.c: RoBIOS key functions (the robot's four soft keys). */
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
