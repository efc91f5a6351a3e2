/* os.c: RoBIOS time functions; time is the simulator's clock, not the host's. */
#include "eyebot.h"
#include "transport.h"

int OSWait(int ms)
{
    es_value args[1] = {es_int(ms)}, result[1];
    return es_call("OSWait", ES_OP_OS_WAIT, args, result) ? 1 : (int)result[0].i;
}

int OSGetCount(void)
{
    es_value result[1];
    return es_call("OSGetCount", ES_OP_OS_GET_COUNT, NULL, result) ? -1 : (int)result[0].i;
}
