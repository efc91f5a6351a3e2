/* ip_size.h: the image size the IP functions work on, for the parts of libeyesim that set it (CAMInit). */
#ifndef EYESIM_IP_SIZE_H
#define EYESIM_IP_SIZE_H

#if defined(__GNUC__)
#pragma GCC visibility push(hidden) /* internal to libeyesim, not part of the API */
#endif

/* Makes width x height pixels the IP size (what IPSetSize does for a resolution constant); also
 * updates IP_WIDTH, IP_HEIGHT, IP_PIXELS and IP_SIZE. Returns 0, or 1 (and changes nothing) when a
 * dimension is below 1 or the image would be too large. */
int es_ip_set_size(int width, int height);

/* The current IP size in pixels. */
void es_ip_get_size(int *width, int *height);

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif
