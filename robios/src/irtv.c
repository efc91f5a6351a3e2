/* irtv.c: RoBIOS IR remote control: codes from the viewer's remote, the keyboard or a script. */
#include "eyebot.h"
#include "transport.h"

int IRTVGet(void)
{
    es_value result[1];
    return es_call("IRTVGet", ES_OP_IRTV_GET, NULL, result) ? 0 : (int)result[0].i;
}

int IRTVRead(void)
{
    es_value result[1];
    return es_call("IRTVRead", ES_OP_IRTV_READ, NULL, result) ? 0 : (int)result[0].i;
}

int IRTVFlush(void)
{
    es_value result[1];
    return es_call("IRTVFlush", ES_OP_IRTV_FLUSH, NULL, result) ? 1 : (int)result[0].i;
}

int IRTVGetStatus(void)
{
    es_value result[1];
    return es_call("IRTVGetStatus", ES_OP_IRTV_GET_STATUS, NULL, result) ? 0 : (int)result[0].i;
}
