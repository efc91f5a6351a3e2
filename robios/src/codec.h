/* codec.h: encoding and decoding of protocol frames, driven by the generated layout tables. */
#ifndef EYESIM_CODEC_H
#define EYESIM_CODEC_H

#include <stddef.h>
#include <stdint.h>

#include "protocol_gen.h"

#if defined(__GNUC__)
#pragma GCC visibility push(hidden) /* internal to libeyesim, not part of the API */
#endif

/* One field value. Which member counts depends on the field's es_type. */
typedef struct {
    int64_t i;     /* ES_T_I32, ES_T_U32 */
    double f;      /* ES_T_F64 */
    const void *p; /* ES_T_STR, ES_T_BYTES: the bytes (a decoded string has no NUL);
                      ES_T_I32S: int32_t[] when encoding, raw little-endian words when decoded
                      (read them with es_i32s_at) */
    uint32_t n;    /* byte count (STR, BYTES) or element count (I32S) */
} es_value;

/* Results of the codec functions. */
enum {
    ES_CODEC_OK = 0,
    ES_CODEC_UNKNOWN_OP,  /* the op is not in ES_OP_LAYOUTS */
    ES_CODEC_BAD_KIND,    /* kind is not request, reply or error */
    ES_CODEC_TOO_SHORT,   /* frame or payload ends before its fields do */
    ES_CODEC_TRAILING,    /* bytes left after the last field */
    ES_CODEC_BAD_UTF8,    /* a decoded str field is not UTF-8 */
    ES_CODEC_TOO_BIG,     /* the frame would exceed ES_MAX_FRAME */
    ES_CODEC_NO_MEMORY,
};

const char *es_codec_error(int result);

/* A growable byte buffer; zero-initialise, release with es_buf_free. */
typedef struct {
    uint8_t *data;
    size_t len;
    size_t cap;
} es_buf;

void es_buf_free(es_buf *buf);

/* The generated layout of an op (NULL if unknown). */
const es_op_layout *es_find_op(uint16_t op);

/* The field types and count of an op's message of `kind` (request, reply, or the error payload). */
int es_message_layout(uint16_t op, uint16_t kind, const es_type **types, unsigned *count);

/* Appends one complete frame (length prefix, header, payload) to `out`. String fields are sent as
 * valid UTF-8 without NUL: any other byte becomes '?', because the simulator rejects such text. */
int es_encode_frame(es_buf *out, uint16_t op, uint16_t kind, uint32_t request_id, const es_type *types,
                    unsigned count, const es_value *values);

/* es_encode_frame with the layout of op/kind. */
int es_encode_message(es_buf *out, uint16_t op, uint16_t kind, uint32_t request_id, const es_value *values);

typedef struct {
    uint16_t op;
    uint16_t kind;
    uint32_t request_id;
} es_header;

/* Reads the header at the start of a frame body (the bytes after the length prefix). */
int es_decode_header(const uint8_t *body, size_t len, es_header *header);

/* Decodes exactly `count` fields filling `payload`: no byte short, no byte over. Variable-length
 * values point into `payload`. */
int es_decode_payload(const es_type *types, unsigned count, const uint8_t *payload, size_t len,
                      es_value *values);

/* Decodes a whole frame body by the layout its header names; *count gets the number of values. */
int es_decode_message(const uint8_t *body, size_t len, es_header *header, es_value *values, unsigned *count);

/* Element k of a decoded ES_T_I32S value. */
int32_t es_i32s_at(const es_value *value, uint32_t k);

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif
