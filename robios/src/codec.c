/* codec.c: protocol frames to and from field values, by the generated ES_OP_LAYOUTS (no per-op code). */
#include "codec.h"

#include <stdlib.h>
#include <string.h>

#define ERROR_FIELD_COUNT ((unsigned)(sizeof ES_ERROR_LAYOUT / sizeof ES_ERROR_LAYOUT[0]))

const char *es_codec_error(int result)
{
    switch (result) {
    case ES_CODEC_OK: return "ok";
    case ES_CODEC_UNKNOWN_OP: return "unknown operation";
    case ES_CODEC_BAD_KIND: return "unknown message kind";
    case ES_CODEC_TOO_SHORT: return "message too short for its fields";
    case ES_CODEC_TRAILING: return "unexpected bytes after the last field";
    case ES_CODEC_BAD_UTF8: return "a text field is not valid UTF-8";
    case ES_CODEC_TOO_BIG: return "message larger than the protocol allows";
    case ES_CODEC_NO_MEMORY: return "out of memory";
    default: return "codec error";
    }
}

void es_buf_free(es_buf *buf)
{
    free(buf->data);
    buf->data = NULL;
    buf->len = buf->cap = 0;
}

static int buf_reserve(es_buf *buf, size_t more)
{
    if (more > ES_MAX_FRAME + 4u || buf->len + more > ES_MAX_FRAME + 4u)
        return ES_CODEC_TOO_BIG;
    if (buf->len + more <= buf->cap)
        return ES_CODEC_OK;
    size_t cap = buf->cap ? buf->cap : 64;
    while (cap < buf->len + more)
        cap *= 2;
    uint8_t *data = realloc(buf->data, cap);
    if (!data)
        return ES_CODEC_NO_MEMORY;
    buf->data = data;
    buf->cap = cap;
    return ES_CODEC_OK;
}

/* Little-endian by shifts, so the host's byte order never matters. */
static void put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put_u32(uint8_t *p, uint32_t v)
{
    for (int k = 0; k < 4; k++)
        p[k] = (uint8_t)(v >> (8 * k));
}

static void put_u64(uint8_t *p, uint64_t v)
{
    for (int k = 0; k < 8; k++)
        p[k] = (uint8_t)(v >> (8 * k));
}

static uint16_t get_u16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint64_t get_u64(const uint8_t *p)
{
    return (uint64_t)get_u32(p) | (uint64_t)get_u32(p + 4) << 32;
}

/* Length of the valid UTF-8 sequence at s (at most n bytes), or 0 if it is not one (the same
 * rules as Python's decoder, which the simulator uses). */
static size_t utf8_sequence(const uint8_t *s, size_t n)
{
    uint8_t c = s[0];
    size_t len;
    uint32_t min;
    if (c < 0x80)
        return 1;
    if ((c & 0xE0) == 0xC0) { len = 2; min = 0x80; }
    else if ((c & 0xF0) == 0xE0) { len = 3; min = 0x800; }
    else if ((c & 0xF8) == 0xF0) { len = 4; min = 0x10000; }
    else return 0;
    if (len > n)
        return 0;
    uint32_t cp = c & (0x7F >> len);
    for (size_t k = 1; k < len; k++) {
        if ((s[k] & 0xC0) != 0x80)
            return 0;
        cp = cp << 6 | (s[k] & 0x3F);
    }
    /* Overlong forms, UTF-16 surrogates and values past U+10FFFF are not UTF-8. */
    if (cp < min || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF)
        return 0;
    return len;
}

const es_op_layout *es_find_op(uint16_t op)
{
    for (unsigned k = 0; k < ES_OP_COUNT; k++)
        if (ES_OP_LAYOUTS[k].code == op)
            return &ES_OP_LAYOUTS[k];
    return NULL;
}

int es_message_layout(uint16_t op, uint16_t kind, const es_type **types, unsigned *count)
{
    if (kind == ES_KIND_ERROR) { /* the same for every op, even one this side does not know */
        *types = ES_ERROR_LAYOUT;
        *count = ERROR_FIELD_COUNT;
        return ES_CODEC_OK;
    }
    const es_op_layout *layout = es_find_op(op);
    if (!layout)
        return ES_CODEC_UNKNOWN_OP;
    switch (kind) {
    case ES_KIND_REQUEST:
        *types = layout->request;
        *count = layout->n_request;
        return ES_CODEC_OK;
    case ES_KIND_REPLY:
        *types = layout->reply;
        *count = layout->n_reply;
        return ES_CODEC_OK;
    default:
        return ES_CODEC_BAD_KIND;
    }
}

static int encode_string(es_buf *out, const uint8_t *s, uint32_t n)
{
    int rc = buf_reserve(out, 4 + (size_t)n);
    if (rc)
        return rc;
    put_u32(out->data + out->len, n);
    uint8_t *dst = out->data + out->len + 4;
    size_t pos = 0;
    while (pos < n) {
        size_t len = s[pos] ? utf8_sequence(s + pos, n - pos) : 0; /* NUL: the protocol has none */
        if (len == 0) {
            dst[pos++] = '?';
        } else {
            memcpy(dst + pos, s + pos, len);
            pos += len;
        }
    }
    out->len += 4 + (size_t)n;
    return ES_CODEC_OK;
}

static int encode_field(es_buf *out, es_type type, const es_value *v)
{
    int rc;
    switch (type) {
    case ES_T_I32:
    case ES_T_U32:
        if ((rc = buf_reserve(out, 4)))
            return rc;
        put_u32(out->data + out->len, (uint32_t)v->i); /* two's complement for i32 */
        out->len += 4;
        return ES_CODEC_OK;
    case ES_T_F64: {
        uint64_t bits;
        memcpy(&bits, &v->f, sizeof bits);
        if ((rc = buf_reserve(out, 8)))
            return rc;
        put_u64(out->data + out->len, bits);
        out->len += 8;
        return ES_CODEC_OK;
    }
    case ES_T_STR:
        return encode_string(out, v->p, v->n);
    case ES_T_BYTES:
        if ((rc = buf_reserve(out, 4 + (size_t)v->n)))
            return rc;
        put_u32(out->data + out->len, v->n);
        if (v->n)
            memcpy(out->data + out->len + 4, v->p, v->n);
        out->len += 4 + (size_t)v->n;
        return ES_CODEC_OK;
    case ES_T_I32S: {
        if ((rc = buf_reserve(out, 4 + 4 * (size_t)v->n)))
            return rc;
        const int32_t *items = v->p;
        put_u32(out->data + out->len, v->n);
        for (uint32_t k = 0; k < v->n; k++)
            put_u32(out->data + out->len + 4 + 4 * k, (uint32_t)items[k]);
        out->len += 4 + 4 * (size_t)v->n;
        return ES_CODEC_OK;
    }
    default:
        return ES_CODEC_BAD_KIND;
    }
}

int es_encode_frame(es_buf *out, uint16_t op, uint16_t kind, uint32_t request_id, const es_type *types,
                    unsigned count, const es_value *values)
{
    size_t start = out->len;
    int rc = buf_reserve(out, 4 + ES_HEADER_SIZE);
    if (rc)
        return rc;
    out->len += 4; /* the length prefix, filled in below */
    put_u16(out->data + out->len, op);
    put_u16(out->data + out->len + 2, kind);
    put_u32(out->data + out->len + 4, request_id);
    out->len += ES_HEADER_SIZE;
    for (unsigned k = 0; k < count; k++) {
        if ((rc = encode_field(out, types[k], &values[k]))) {
            out->len = start;
            return rc;
        }
    }
    size_t body = out->len - start - 4;
    if (body > ES_MAX_FRAME) {
        out->len = start;
        return ES_CODEC_TOO_BIG;
    }
    put_u32(out->data + start, (uint32_t)body);
    return ES_CODEC_OK;
}

int es_encode_message(es_buf *out, uint16_t op, uint16_t kind, uint32_t request_id, const es_value *values)
{
    const es_type *types;
    unsigned count;
    int rc = es_message_layout(op, kind, &types, &count);
    if (rc)
        return rc;
    return es_encode_frame(out, op, kind, request_id, types, count, values);
}

int es_decode_header(const uint8_t *body, size_t len, es_header *header)
{
    if (len < ES_HEADER_SIZE)
        return ES_CODEC_TOO_SHORT;
    header->op = get_u16(body);
    header->kind = get_u16(body + 2);
    header->request_id = get_u32(body + 4);
    return ES_CODEC_OK;
}

int es_decode_payload(const es_type *types, unsigned count, const uint8_t *payload, size_t len,
                      es_value *values)
{
    size_t pos = 0;
    for (unsigned k = 0; k < count; k++) {
        es_value *v = &values[k];
        memset(v, 0, sizeof *v);
        switch (types[k]) {
        case ES_T_I32:
            if (len - pos < 4)
                return ES_CODEC_TOO_SHORT;
            v->i = (int32_t)get_u32(payload + pos);
            pos += 4;
            break;
        case ES_T_U32:
            if (len - pos < 4)
                return ES_CODEC_TOO_SHORT;
            v->i = get_u32(payload + pos);
            pos += 4;
            break;
        case ES_T_F64: {
            if (len - pos < 8)
                return ES_CODEC_TOO_SHORT;
            uint64_t bits = get_u64(payload + pos);
            memcpy(&v->f, &bits, sizeof bits);
            pos += 8;
            break;
        }
        case ES_T_STR:
        case ES_T_BYTES:
        case ES_T_I32S: {
            if (len - pos < 4)
                return ES_CODEC_TOO_SHORT;
            uint32_t n = get_u32(payload + pos);
            pos += 4;
            uint64_t size = types[k] == ES_T_I32S ? 4 * (uint64_t)n : n;
            if (len - pos < size)
                return ES_CODEC_TOO_SHORT;
            if (types[k] == ES_T_STR) {
                for (size_t at = 0; at < n;) {
                    size_t step = utf8_sequence(payload + pos + at, n - at);
                    if (step == 0)
                        return ES_CODEC_BAD_UTF8;
                    at += step;
                }
            }
            v->p = payload + pos;
            v->n = n;
            pos += (size_t)size;
            break;
        }
        default:
            return ES_CODEC_BAD_KIND;
        }
    }
    return pos == len ? ES_CODEC_OK : ES_CODEC_TRAILING;
}

int es_decode_message(const uint8_t *body, size_t len, es_header *header, es_value *values, unsigned *count)
{
    const es_type *types;
    int rc = es_decode_header(body, len, header);
    if (rc)
        return rc;
    if ((rc = es_message_layout(header->op, header->kind, &types, count)))
        return rc;
    return es_decode_payload(types, *count, body + ES_HEADER_SIZE, len - ES_HEADER_SIZE, values);
}

int32_t es_i32s_at(const es_value *value, uint32_t k)
{
    return (int32_t)get_u32((const uint8_t *)value->p + 4 * (size_t)k);
}
