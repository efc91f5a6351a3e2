/* Counts calls instead of time, as lab programs do: how many loop iterations (OSGetCount + KEYRead)
 * fit into 1 s of simulation time, then how much simulation time 100 KEYRead calls take. */
#include <stdio.h>
#include "eyebot.h"

int main(void)
{
    int start = OSGetCount(), iterations = 0;
    while (OSGetCount() - start < 1000) {
        KEYRead();
        iterations++;
    }
    printf("iterations %d\n", iterations);
    start = OSGetCount();
    for (int k = 0; k < 100; k++)
        KEYRead();
    printf("100 calls took %d ms\n", OSGetCount() - start);
    return 0;
}
