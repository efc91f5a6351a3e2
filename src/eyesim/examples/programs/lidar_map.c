/* Lidar mapping: the robot wanders, turning away from what its lidar sees ahead, and enters every
 * scan into an occupancy grid around its start (poses from odometry). The map grows on the LCD;
 * at the end it is saved as map.pgm (black = seen as occupied, 1 pixel = CELL mm, start at the
 * centre, x to the right, y up), beside this program. KEY4 ends it early.
 * From the examples folder (eyesim compiles it):
 *   eyesim run scenes/lidar_map.sim --program 1=programs/lidar_map.c
 */
#include <math.h>
#include <stdio.h>
#include "eyebot.h"

#define CELL 20           /* mm per map cell */
#define SIZE 300          /* cells per side: a 6 m square around the start */
#define RUN_SECONDS 40
#define CLEARANCE 380     /* mm: turn when something is this close ahead */
#define SCALE 1           /* map cells per LCD pixel */

static unsigned char hits[SIZE][SIZE];
static int scan[3600];

/* Smallest distance of the beams within `half` degrees of `centre` (360-point scan, 180 = ahead). */
static int nearest(int centre, int half)
{
    int best = 99999;
    for (int i = centre - half; i <= centre + half; i++)
        if (scan[(i + 360) % 360] < best)
            best = scan[(i + 360) % 360];
    return best;
}

static void enter_scan(int x, int y, int phi)
{
    for (int i = 0; i < LIDAR_RESOLUTION; i++) {
        if (scan[i] >= 9999)
            continue; /* nothing in range */
        double angle = (phi - (i - LIDAR_RESOLUTION / 2) * 360.0 / LIDAR_RESOLUTION) * M_PI / 180.0;
        int cx = (int)floor((x + scan[i] * cos(angle)) / CELL) + SIZE / 2;
        int cy = (int)floor((y + scan[i] * sin(angle)) / CELL) + SIZE / 2;
        if (cx < 0 || cy < 0 || cx >= SIZE || cy >= SIZE || hits[cy][cx] == 255)
            continue;
        if (++hits[cy][cx] == 2) /* seen twice: occupied */
            LCDPixel(240 + (cx - SIZE / 2) / SCALE, 140 - (cy - SIZE / 2) / SCALE, WHITE);
    }
}

static void save_map(const char *name)
{
    FILE *file = fopen(name, "wb");
    if (!file)
        return;
    fprintf(file, "P5\n%d %d\n255\n", SIZE, SIZE);
    for (int row = SIZE - 1; row >= 0; row--) /* the top row is the map's largest y */
        for (int col = 0; col < SIZE; col++)
            fputc(hits[row][col] >= 2 ? 0 : 255, file);
    fclose(file);
}

int main(void)
{
    LCDMenu("", "", "", "END");
    LCDSetPrintf(0, 0, "Lidar map (1 pixel = %d mm)", CELL * SCALE);
    LIDARSet(360, 0, 360);
    int start = OSGetCount(), scans = 0;
    while (KEYRead() != KEY4 && OSGetCount() - start < RUN_SECONDS * 1000) {
        int x, y, phi;
        LIDARGet(scan);
        VWGetPosition(&x, &y, &phi);
        enter_scan(x, y, phi);
        scans++;
        if (nearest(180, 25) < CLEARANCE) {
            /* blocked: turn towards the side with more room until the way ahead is clear */
            int left = nearest(90, 40), right = nearest(270, 40);
            VWSetSpeed(0, left > right ? 60 : -60);
        } else {
            VWSetSpeed(250, 0);
        }
        OSWait(50);
    }
    VWSetSpeed(0, 0);
    save_map("map.pgm");
    printf("mapped %d scans\n", scans);
    return 0;
}
