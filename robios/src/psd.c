/* psd.c: RoBIOS PSD distance sensors. */
#include "eyebot.h"
#include "transport.h"

int PSDGet(int psd)
{
    es_value args[1] = {es_int(psd)}, result[1];
    return es_call("PSDGet", ES_OP_PSD_GET, args, result) ? -1 : (int)result[0].i;
}

int PSDGetRaw(int psd)
{
    es_value args[1] = {es_int(psd)}, result[1];
    return es_call("PSDGetRaw", ES_OP_PSD_GET_RAW, args, result) ? -1 : (int)result[0].i;
}
