/* audio.c: AUPlay, which reads the WAV or MP3 file and sends its contents (the other AU functions only
 * pass values through: api_gen.c). Sounds play in the simulator, and aloud in the viewer. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eyebot.h"
#include "transport.h"

#define AU_ERROR 1
#define MAX_SOUND_BYTES (8u * 1024u * 1024u) /* fits into one protocol frame */

/* The whole file in a malloc'd buffer, or NULL (reported). A relative name is relative to the
 * program's working directory. */
static unsigned char *read_sound(const char *filename, size_t *size)
{
    FILE *file = fopen(filename, "rb");
    if (!file) {
        fprintf(stderr, "eyesim: AUPlay: cannot open %s (%s)\n", filename, strerror(errno));
        return NULL;
    }
    size_t length = 0, capacity = 1u << 16;
    unsigned char *data = malloc(capacity);
    while (data) {
        length += fread(data + length, 1, capacity - length, file);
        if (length < capacity || ferror(file))
            break; /* the end of the file, or an error */
        unsigned char *bigger = capacity < MAX_SOUND_BYTES ? realloc(data, capacity * 2) : NULL;
        if (!bigger) {
            if (capacity < MAX_SOUND_BYTES)
                fprintf(stderr, "eyesim: AUPlay: out of memory reading %s\n", filename);
            else
                fprintf(stderr, "eyesim: AUPlay: %s is too large (at most %u MB)\n", filename, MAX_SOUND_BYTES >> 20);
            free(data);
        }
        data = bigger;
        capacity *= 2;
    }
    if (data && ferror(file)) {
        fprintf(stderr, "eyesim: AUPlay: cannot read %s (%s)\n", filename, strerror(errno));
        free(data);
        data = NULL;
    }
    fclose(file);
    *size = length;
    return data;
}

int AUPlay(const char *filename)
{
    if (!filename) {
        fprintf(stderr, "eyesim: AUPlay: the file name is NULL\n");
        return AU_ERROR;
    }
    size_t size = 0;
    unsigned char *data = read_sound(filename, &size);
    if (!data)
        return AU_ERROR;
    es_value sound = {0};
    sound.p = data;
    sound.n = (uint32_t)size;
    es_value args[2] = {es_text(filename), sound}, result[1];
    int rc = es_call("AUPlay", ES_OP_AU_PLAY, args, result) ? AU_ERROR : (int)result[0].i;
    free(data);
    return rc;
}

