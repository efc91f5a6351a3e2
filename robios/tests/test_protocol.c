/* test_protocol.c: the C codec against every shared vector (encode -> exact hex, hex -> same values). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "codec.h"
#include "vectors_gen.h"

static int failures;

#define CHECK(cond, ...)                                                                          \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            failures++;                                                                           \
            printf("FAIL %s:%d: ", __FILE__, __LINE__);                                          \
            printf(__VA_ARGS__);                                                                  \
            printf("\n");                                                                         \
        }                                                                                         \
    } while (0)

static size_t from_hex(const char *hex, uint8_t *out)
{
    size_t n = strlen(hex) / 2;
    for (size_t k = 0; k < n; k++) {
        unsigned byte;
        sscanf(hex + 2 * k, "%2x", &byte);
        out[k] = (uint8_t)byte;
    }
    return n;
}

static void to_hex(const uint8_t *data, size_t n, char *out)
{
    for (size_t k = 0; k < n; k++)
        sprintf(out + 2 * k, "%02x", data[k]);
    out[2 * n] = 0;
}

/* The vector's values as codec values. */
static void vector_values(const protocol_vector *v, const es_type *types, es_value *values)
{
    for (int k = 0; k < v->n_values; k++) {
        es_value *value = &values[k];
        memset(value, 0, sizeof *value);
        switch (types[k]) {
        case ES_T_I32:
        case ES_T_U32: value->i = v->values[k].i; break;
        case ES_T_F64: value->f = v->values[k].f; break;
        case ES_T_STR:
            value->p = v->values[k].s;
            value->n = (uint32_t)strlen(v->values[k].s);
            break;
        case ES_T_BYTES:
            value->p = v->values[k].b.p;
            value->n = v->values[k].b.n;
            break;
        case ES_T_I32S:
            value->p = v->values[k].a.p;
            value->n = v->values[k].a.n;
            break;
        default: break;
        }
    }
}

static int same_value(es_type type, const es_value *got, const es_value *want)
{
    switch (type) {
    case ES_T_I32:
    case ES_T_U32: return got->i == want->i;
    case ES_T_F64: return memcmp(&got->f, &want->f, sizeof got->f) == 0;
    case ES_T_STR:
    case ES_T_BYTES: return got->n == want->n && memcmp(got->p, want->p, got->n) == 0;
    case ES_T_I32S:
        if (got->n != want->n)
            return 0;
        for (uint32_t k = 0; k < got->n; k++)
            if (es_i32s_at(got, k) != ((const int32_t *)want->p)[k])
                return 0;
        return 1;
    default: return 0;
    }
}

static void check_vector(const protocol_vector *v)
{
    const es_type *types;
    unsigned count;
    es_value want[8], got[8];
    es_buf buf = {0};
    static uint8_t frame[ES_HEADER_SIZE + 4096];
    static char hex[2 * sizeof frame + 1];

    CHECK(es_message_layout(v->op, v->kind, &types, &count) == ES_CODEC_OK, "%s: no layout", v->name);
    CHECK(count == (unsigned)v->n_values, "%s: %u fields, vector has %d", v->name, count, v->n_values);
    vector_values(v, types, want);

    /* Encoding gives exactly the vector's bytes. */
    int rc = es_encode_message(&buf, v->op, v->kind, v->request_id, want);
    CHECK(rc == ES_CODEC_OK, "%s: encode failed: %s", v->name, es_codec_error(rc));
    if (rc == ES_CODEC_OK && buf.len < sizeof frame) {
        to_hex(buf.data, buf.len, hex);
        CHECK(strcmp(hex, v->hex) == 0, "%s: encoded\n  %s\nwant\n  %s", v->name, hex, v->hex);
    }
    es_buf_free(&buf);

    /* Decoding the vector's bytes gives its values back. */
    size_t n = from_hex(v->hex, frame);
    uint32_t length = (uint32_t)frame[0] | (uint32_t)frame[1] << 8 | (uint32_t)frame[2] << 16 |
                      (uint32_t)frame[3] << 24;
    CHECK(length == n - 4, "%s: length prefix %u for %zu body bytes", v->name, length, n - 4);
    es_header header;
    unsigned decoded;
    rc = es_decode_message(frame + 4, n - 4, &header, got, &decoded);
    CHECK(rc == ES_CODEC_OK, "%s: decode failed: %s", v->name, es_codec_error(rc));
    if (rc != ES_CODEC_OK)
        return;
    CHECK(header.op == v->op && header.kind == v->kind && header.request_id == v->request_id,
          "%s: header %u/%u/%u", v->name, header.op, header.kind, header.request_id);
    for (unsigned k = 0; k < count; k++)
        CHECK(same_value(types[k], &got[k], &want[k]), "%s: field %u differs", v->name, k);

    /* Strict lengths: one byte short or one byte over is an error. */
    if (n - 4 > ES_HEADER_SIZE) {
        rc = es_decode_message(frame + 4, n - 5, &header, got, &decoded);
        CHECK(rc == ES_CODEC_TOO_SHORT, "%s: one byte short decoded as %s", v->name, es_codec_error(rc));
    }
    frame[n] = 0;
    rc = es_decode_message(frame + 4, n - 3, &header, got, &decoded);
    CHECK(rc == ES_CODEC_TRAILING, "%s: one byte over decoded as %s", v->name, es_codec_error(rc));
}

/* Cases outside the shared vectors: the codec's own guarantees. */
static void check_codec_rules(void)
{
    es_buf buf = {0};
    es_value text = {.p = "a\xff" "b\0c", .n = 5};
    int rc = es_encode_message(&buf, ES_OP_LCD_PRINTF, ES_KIND_REQUEST, 1, &text);
    CHECK(rc == ES_CODEC_OK, "invalid UTF-8 text not encoded");
    CHECK(buf.len == 4 + ES_HEADER_SIZE + 4 + 5 && memcmp(buf.data + 16, "a?b?c", 5) == 0,
          "invalid UTF-8 and NUL not replaced by '?'");
    es_buf_free(&buf);

    static const uint8_t bad_utf8[] = {2, 0, 0, 0, 0xC3, 0x28};
    es_value got[1];
    rc = es_decode_payload((const es_type[]){ES_T_STR}, 1, bad_utf8, sizeof bad_utf8, got);
    CHECK(rc == ES_CODEC_BAD_UTF8, "invalid UTF-8 decoded as %s", es_codec_error(rc));

    static const uint8_t long_string[] = {0xFF, 0xFF, 0xFF, 0xFF, 'x'};
    rc = es_decode_payload((const es_type[]){ES_T_STR}, 1, long_string, sizeof long_string, got);
    CHECK(rc == ES_CODEC_TOO_SHORT, "overlong string length decoded as %s", es_codec_error(rc));

    rc = es_encode_message(&buf, 999, ES_KIND_REQUEST, 1, NULL);
    CHECK(rc == ES_CODEC_UNKNOWN_OP, "unknown op encoded");
    es_buf_free(&buf);

    static const int32_t items[] = {-1, 7};
    es_value list = {.p = items, .n = 2}, back;
    es_encode_frame(&buf, 1, ES_KIND_REQUEST, 1, (const es_type[]){ES_T_I32S}, 1, &list);
    rc = es_decode_payload((const es_type[]){ES_T_I32S}, 1, buf.data + 12, buf.len - 12, &back);
    CHECK(rc == ES_CODEC_OK && back.n == 2 && es_i32s_at(&back, 0) == -1 && es_i32s_at(&back, 1) == 7,
          "i32s round trip");
    es_buf_free(&buf);

    es_value number = {.f = -2.5}, number_back;
    es_encode_frame(&buf, 1, ES_KIND_REQUEST, 1, (const es_type[]){ES_T_F64}, 1, &number);
    rc = es_decode_payload((const es_type[]){ES_T_F64}, 1, buf.data + 12, buf.len - 12, &number_back);
    CHECK(rc == ES_CODEC_OK && number_back.f == -2.5, "f64 round trip");
    es_buf_free(&buf);
}

int main(void)
{
    for (int k = 0; k < PROTOCOL_VECTOR_COUNT; k++)
        check_vector(&PROTOCOL_VECTORS[k]);
    check_codec_rules();
    if (failures) {
        printf("%d failure(s)\n", failures);
        return 1;
    }
    printf("ok: %d vectors\n", PROTOCOL_VECTOR_COUNT);
    return 0;
}
