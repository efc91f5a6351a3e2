/* key.c: KEYReadXY, which leaves x and y alone when there was no touch (the other KEY functions only pass
 * values through: api_gen.c). */
#include "eyebot.h"
#include "transport.h"

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
