/*
 * vtu_data.c - decodes the content of one VTK XML <DataArray> into numbers.
 *
 * Format (VTK file formats, "XML File Formats"; VTK's vtkXMLDataParser and
 * vtkZLibDataCompressor describe the binary layout): format="ascii" is text;
 * format="binary" is base64 inside the element; format="appended" is found at
 * offset="N" bytes after the '_' that opens <AppendedData encoding="raw" or
 * "base64">. Binary data starts with a header of header_type words (UInt32 or
 * UInt64, byte_order of the file): uncompressed, one word giving the byte
 * count; with compressor="vtkZLibDataCompressor", the words nblocks,
 * block size, size of the last block (0: a full block) and the compressed
 * size of each block, followed by the zlib streams. Writers encode the header
 * and the data as one base64 string (meshio) or as two (VTK), so padding may
 * appear between them: the decoder treats '=' as the end of a group and goes
 * on. <InformationKey> elements before the values are skipped. Every size is
 * checked against the bytes present before memory is allocated.
 */
#include <limits.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <zlib.h>

#include "io_text.h"
#include "vtu_data.h"

enum { K_SIGNED = CVM__BIN_SIGNED, K_UNSIGNED = CVM__BIN_UNSIGNED, K_FLOAT = CVM__BIN_FLOAT };

static const struct vtype {
    const char *name;
    int size, kind;
} k_types[] = {
    {"Int8", 1, K_SIGNED},    {"UInt8", 1, K_UNSIGNED},  {"Int16", 2, K_SIGNED},
    {"UInt16", 2, K_UNSIGNED}, {"Int32", 4, K_SIGNED},   {"UInt32", 4, K_UNSIGNED},
    {"Int64", 8, K_SIGNED},   {"UInt64", 8, K_UNSIGNED}, {"Float32", 4, K_FLOAT},
    {"Float64", 8, K_FLOAT}};

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

cvm_status cvm__vtu_fail(const cvm__vtu_file *f, size_t at, cvm_status st, const char *fmt, ...)
{
    char what[CVM__ERRMSG_LEN];
    long line = 1;
    size_t i;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (f->appended && f->appended_raw && at >= f->appended)
        return cvm__error(f->ctx, st, CVM_ENT_FILE_LINE, -1, "%s: byte %lu: %s", f->name,
                          (unsigned long)at, what);
    for (i = 0; i < at && i < f->n; i++)
        line += f->buf[i] == '\n';
    return cvm__error(f->ctx, st, CVM_ENT_FILE_LINE, (int64_t)line, "%s:%ld: %s", f->name, line,
                      what);
}

int cvm__vtu_attr(const char *s, const char *e, const char *key, char *out)
{
    size_t k = strlen(key);
    const char *p;
    for (p = s + 1; p + k + 2 < e; p++) {
        const char *q;
        size_t n;
        if (!is_space(p[-1]) || strncmp(p, key, k) != 0 || p[k] != '=' ||
            (p[k + 1] != '"' && p[k + 1] != '\''))
            continue;
        q = memchr(p + k + 2, p[k + 1], (size_t)(e - (p + k + 2)));
        if (!q)
            return 0;
        n = (size_t)(q - (p + k + 2));
        if (n >= CVM__VTU_ATTR_LEN)
            n = CVM__VTU_ATTR_LEN - 1;
        memcpy(out, p + k + 2, n);
        out[n] = '\0';
        return 1;
    }
    return 0;
}

/* The values' text of a: the content less leading whitespace and child
 * elements (<InformationKey>...</InformationKey>), up to the next '<'. */
static cvm_status data_text(const cvm__vtu_file *f, const cvm__vtu_array *a, size_t *ds, size_t *de)
{
    const char *b = f->buf;
    size_t p = a->cs;
    for (;;) {
        const char *te, *close;
        char tag[CVM__VTU_ATTR_LEN + 3];
        size_t k = 0;
        while (p < a->ce && is_space(b[p]))
            p++;
        if (p >= a->ce || b[p] != '<')
            break;
        te = memchr(b + p, '>', a->ce - p);
        if (!te)
            return cvm__vtu_fail(f, p, CVM_E_IO_FORMAT, "unterminated tag inside a DataArray");
        if (te[-1] == '/') {
            p = (size_t)(te - b) + 1;
            continue;
        }
        tag[0] = '<';
        tag[1] = '/';
        while (k < CVM__VTU_ATTR_LEN && p + 1 + k < a->ce && !is_space(b[p + 1 + k]) &&
               b[p + 1 + k] != '>') {
            tag[2 + k] = b[p + 1 + k];
            k++;
        }
        tag[2 + k] = '\0';
        close = strstr(te, tag);
        if (!close || (size_t)(close - b) >= a->ce || !memchr(close, '>', a->ce - (size_t)(close - b)))
            return cvm__vtu_fail(f, p, CVM_E_IO_FORMAT, "element %s> inside a DataArray is not closed",
                                 tag + 1);
        p = (size_t)((const char *)memchr(close, '>', a->ce - (size_t)(close - b)) - b) + 1;
    }
    *ds = p;
    *de = p;
    while (*de < a->ce && b[*de] != '<')
        (*de)++;
    return CVM_OK;
}

/* ASCII values of [s, e). */
static cvm_status ascii(const cvm__vtu_file *f, size_t s, size_t e, const char *what, int integer,
                        long long want, void **out, size_t *got)
{
    size_t cap = 0, n = 0, p = s;
    double *d = NULL;
    long long *l = NULL;
    const char *b = f->buf;
    for (;;) {
        char tok[CVM__DOUBLE_BUF + 24];
        size_t t, len;
        int r;
        while (p < e && is_space(b[p]))
            p++;
        if (p >= e)
            break;
        t = p;
        while (p < e && !is_space(b[p]))
            p++;
        len = p - t;
        if (want >= 0 && (long long)n >= want) {
            cvm__free(f->ctx, integer ? (void *)l : (void *)d);
            return cvm__vtu_fail(f, t, CVM_E_IO_FORMAT, "%s: more than the %lld values expected",
                                 what, want);
        }
        if (len >= sizeof tok)
            len = sizeof tok - 1; /* too long for a number: fails below */
        memcpy(tok, b + t, len);
        tok[len] = '\0';
        if (n + 1 > cap && cvm__grow(f->ctx, integer ? (void **)&l : (void **)&d, &cap, n + 1,
                                     integer ? sizeof *l : sizeof *d))
            goto nomem;
        if (integer) {
            r = cvm__parse_long(tok, -(long long)INT32_MAX, INT32_MAX, &l[n]);
            if (r) {
                cvm__free(f->ctx, l);
                return cvm__vtu_fail(f, t, CVM_E_IO_FORMAT,
                                     "%s: entry %lld (from 0) is '%s', not an integer in [%lld, %lld]",
                                     what, (long long)n, tok, -(long long)INT32_MAX,
                                     (long long)INT32_MAX);
            }
        } else {
            r = cvm__parse_double(tok, &d[n]);
            if (r) {
                cvm__free(f->ctx, d);
                return cvm__vtu_fail(f, t, r == 2 ? CVM_E_INPUT_NONFINITE : CVM_E_IO_FORMAT,
                                     "%s: entry %lld (from 0) is '%s', not a %snumber", what,
                                     (long long)n, tok, r == 2 ? "finite " : "");
            }
        }
        n++;
    }
    if (want >= 0 && (long long)n != want) {
        cvm__free(f->ctx, integer ? (void *)l : (void *)d);
        return cvm__vtu_fail(f, e, CVM_E_IO_FORMAT, "%s: %lld values, expected %lld", what,
                             (long long)n, want);
    }
    if (!(integer ? (void *)l : (void *)d)) { /* empty: still a valid array */
        if (integer ? !(l = cvm__malloc(f->ctx, sizeof *l)) : !(d = cvm__malloc(f->ctx, sizeof *d)))
            goto nomem;
    }
    *out = integer ? (void *)l : (void *)d;
    if (got)
        *got = n;
    return CVM_OK;
nomem:
    cvm__free(f->ctx, l);
    cvm__free(f->ctx, d);
    return cvm__nomem(f->ctx);
}

/* A byte stream: raw bytes, or base64 text decoded on the fly. */
typedef struct bsrc {
    const char *p, *end;
    int b64;
    unsigned char pend[3];
    int npend, ipend;
} bsrc;

static int b64_value(char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : c == '=' ? 64 : -1;
}

/* An upper bound of the bytes left in s. */
static size_t bsrc_left(const bsrc *s)
{
    size_t t = (size_t)(s->end - s->p);
    return (size_t)(s->npend - s->ipend) + (s->b64 ? t / 4 * 3 + 3 : t);
}

/* Decode the next group of 4 base64 characters into s->pend. 0 ok, 1 end of
 * the text, 2 a character that is not base64 (s->p points at it). */
static int b64_group(bsrc *s)
{
    int v[4], k = 0;
    while (k < 4) {
        int x;
        while (s->p < s->end && is_space(*s->p))
            s->p++;
        if (s->p >= s->end || *s->p == '<')
            return 1;
        if ((x = b64_value(*s->p)) < 0 || (x == 64 && k < 2) || (k == 3 && v[2] == 64 && x != 64))
            return 2;
        v[k++] = x;
        s->p++;
    }
    s->pend[0] = (unsigned char)(v[0] << 2 | v[1] >> 4);
    s->pend[1] = (unsigned char)((v[1] & 15) << 4 | (v[2] & 63) >> 2);
    s->pend[2] = (unsigned char)((v[2] & 3) << 6 | (v[3] & 63));
    s->npend = v[2] == 64 ? 1 : v[3] == 64 ? 2 : 3;
    s->ipend = 0;
    return 0;
}

/* n bytes of s into dst: 0 ok, 1 the data ends first, 2 bad base64. */
static int bget(bsrc *s, unsigned char *dst, size_t n)
{
    if (!s->b64) {
        if ((size_t)(s->end - s->p) < n)
            return 1;
        memcpy(dst, s->p, n);
        s->p += n;
        return 0;
    }
    while (n > 0) {
        int r;
        if (s->ipend < s->npend) {
            *dst++ = s->pend[s->ipend++];
            n--;
            continue;
        }
        if ((r = b64_group(s)))
            return r;
    }
    return 0;
}

/* One unsigned or signed integer, or float, of size bytes at p. */
static uint64_t load(const unsigned char *p, int size, int big)
{
    uint64_t u = 0;
    int i;
    for (i = 0; i < size; i++)
        u |= (uint64_t)p[big ? size - 1 - i : i] << (8 * i);
    return u;
}

static uint64_t header_word(const cvm__vtu_file *f, const unsigned char *p)
{
    return load(p, f->header64 ? 8 : 4, f->big_endian);
}

static cvm_status short_data(const cvm__vtu_file *f, const bsrc *s, int r, const char *what)
{
    size_t at = (size_t)(s->p - f->buf);
    if (r == 2)
        return cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: '%c' is not a base64 character", what,
                             *s->p);
    return cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: the data ends early (truncated file?)", what);
}

static voidpf z_alloc(voidpf ctx, uInt items, uInt size)
{
    if (size && items > SIZE_MAX / size)
        return Z_NULL;
    return cvm__malloc(ctx, (size_t)items * size);
}

static void z_free(voidpf ctx, voidpf p)
{
    cvm__free(ctx, p);
}

/* The zlib blocks of s after their header into bytes (*len_out). */
static cvm_status inflate_blocks(const cvm__vtu_file *f, bsrc *s, const char *what,
                                 unsigned char **out, size_t *len_out)
{
    unsigned char w[24], *hdr = NULL, *cbuf = NULL, *dst = NULL;
    size_t hs = f->header64 ? 8 : 4, at = (size_t)(s->p - f->buf), k;
    uint64_t nb, bs, last, total = 0, csum = 0, cmax = 0;
    cvm_status st = CVM_OK;
    z_stream zs;
    int r;
    if ((r = bget(s, w, 3 * hs)))
        return short_data(f, s, r, what);
    nb = header_word(f, w);
    bs = header_word(f, w + hs);
    last = header_word(f, w + 2 * hs);
    if (nb > bsrc_left(s) / hs || (nb > 0 && (bs == 0 || last > bs)))
        return cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: bad compression header (%llu blocks "
                             "of %llu bytes, last %llu)", what, (unsigned long long)nb,
                             (unsigned long long)bs, (unsigned long long)last);
    if (!(hdr = cvm__malloc(f->ctx, (size_t)nb * hs + 1)))
        return cvm__nomem(f->ctx);
    if ((r = bget(s, hdr, (size_t)nb * hs))) {
        cvm__free(f->ctx, hdr);
        return short_data(f, s, r, what);
    }
    for (k = 0; k < nb; k++) {
        uint64_t c = header_word(f, hdr + k * hs);
        csum += c;
        cmax = c > cmax ? c : cmax;
        if (c > bsrc_left(s) || csum > bsrc_left(s) || c > UINT_MAX)
            break;
    }
    if (nb > 0)
        total = (nb - 1) * bs + (last ? last : bs); /* nb, bs < 2^61: no overflow */
    /* deflate expands at most 1032:1, so larger claims are corrupt */
    if (k < nb || bs > SIZE_MAX / 2 || nb > SIZE_MAX / (bs ? bs : 1) || total / 1032 > csum + nb) {
        cvm__free(f->ctx, hdr);
        return cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: compressed block sizes do not fit the "
                             "data (%llu blocks, %llu bytes)", what, (unsigned long long)nb,
                             (unsigned long long)total);
    }
    memset(&zs, 0, sizeof zs);
    zs.zalloc = z_alloc;
    zs.zfree = z_free;
    zs.opaque = f->ctx;
    if (!(cbuf = cvm__malloc(f->ctx, (size_t)cmax + 1)) || !(dst = cvm__malloc(f->ctx, (size_t)total + 1)) ||
        inflateInit(&zs) != Z_OK) {
        cvm__free(f->ctx, hdr);
        cvm__free(f->ctx, cbuf);
        cvm__free(f->ctx, dst);
        return cvm__nomem(f->ctx);
    }
    for (k = 0; k < nb && !st; k++) {
        size_t c = (size_t)header_word(f, hdr + k * hs);
        size_t want = (size_t)(k + 1 < nb || !last ? bs : last);
        at = (size_t)(s->p - f->buf);
        if ((r = bget(s, cbuf, c))) {
            st = short_data(f, s, r, what);
            break;
        }
        inflateReset(&zs);
        zs.next_in = cbuf;
        zs.avail_in = (uInt)c;
        zs.next_out = dst + k * (size_t)bs;
        zs.avail_out = (uInt)want;
        r = inflate(&zs, Z_FINISH);
        if (r == Z_MEM_ERROR)
            st = cvm__nomem(f->ctx);
        else if (r != Z_STREAM_END || zs.total_out != want)
            st = cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: zlib block %lu (of %llu) does not "
                               "inflate to %lu bytes (%s)", what, (unsigned long)k,
                               (unsigned long long)nb, (unsigned long)want,
                               zs.msg ? zs.msg : "wrong size");
    }
    inflateEnd(&zs);
    cvm__free(f->ctx, hdr);
    cvm__free(f->ctx, cbuf);
    if (st) {
        cvm__free(f->ctx, dst);
        return st;
    }
    *out = dst;
    *len_out = (size_t)total;
    return CVM_OK;
}

/* The bytes of binary or appended array a (after header and decompression). */
static cvm_status binary_bytes(const cvm__vtu_file *f, const cvm__vtu_array *a, int appended,
                               const char *what, unsigned char **out, size_t *len_out)
{
    const char *b = f->buf;
    bsrc s;
    size_t at;
    memset(&s, 0, sizeof s);
    s.b64 = 1;
    if (!appended) {
        size_t ds, de;
        cvm_status st = data_text(f, a, &ds, &de);
        if (st)
            return st;
        s.p = b + ds;
        s.end = b + de;
    } else {
        char v[CVM__VTU_ATTR_LEN];
        long long off;
        if (!f->appended)
            return cvm__vtu_fail(f, a->ts, CVM_E_IO_FORMAT, "%s: format=\"appended\" but the file "
                                 "has no <AppendedData>", what);
        if (!cvm__vtu_attr(b + a->ts, b + a->te, "offset", v) ||
            cvm__parse_long(v, 0, LLONG_MAX, &off) || (unsigned long long)off > f->n - f->appended)
            return cvm__vtu_fail(f, a->ts, CVM_E_IO_FORMAT, "%s: missing or bad offset= (the "
                                 "appended data has %lu bytes)", what,
                                 (unsigned long)(f->n - f->appended));
        s.p = b + f->appended + off;
        s.end = b + f->n;
        s.b64 = !f->appended_raw;
    }
    at = (size_t)(s.p - b);
    if (f->zlib)
        return inflate_blocks(f, &s, what, out, len_out);
    {
        unsigned char w[8], *dst;
        uint64_t nbytes;
        int r;
        if ((r = bget(&s, w, f->header64 ? 8 : 4)))
            return short_data(f, &s, r, what);
        nbytes = header_word(f, w);
        if (nbytes > bsrc_left(&s))
            return cvm__vtu_fail(f, at, CVM_E_IO_FORMAT, "%s: the header gives %llu bytes, more "
                                 "than the file holds", what, (unsigned long long)nbytes);
        if (!(dst = cvm__malloc(f->ctx, (size_t)nbytes + 1)))
            return cvm__nomem(f->ctx);
        if ((r = bget(&s, dst, (size_t)nbytes))) {
            cvm__free(f->ctx, dst);
            return short_data(f, &s, r, what);
        }
        *out = dst;
        *len_out = (size_t)nbytes;
        return CVM_OK;
    }
}

int cvm__bin_number(const unsigned char *p, int size, int kind, int big, int integer,
                     long long *l, double *d)
{
    uint64_t u = load(p, size, big);
    int bits = 8 * size;
    if (kind == CVM__BIN_FLOAT) {
        double x;
        if (size == 4) {
            uint32_t u32 = (uint32_t)u;
            float g;
            memcpy(&g, &u32, sizeof g);
            x = g;
        } else {
            memcpy(&x, &u, sizeof x);
        }
        if (integer)
            return 1;
        *d = x;
        return x - x == 0 ? 0 : 2;
    }
    if (kind == CVM__BIN_SIGNED) {
        long long v;
        if (bits < 64 && (u >> (bits - 1)) & 1)
            u |= ~(uint64_t)0 << bits; /* sign-extend */
        v = u > (uint64_t)INT64_MAX ? -(long long)(~u) - 1 : (long long)u;
        if (!integer) {
            *d = (double)v;
            return 0;
        }
        if (v < -(long long)INT32_MAX || v > INT32_MAX)
            return 1;
        *l = v;
        return 0;
    }
    if (!integer) {
        *d = (double)u;
        return 0;
    }
    if (u > INT32_MAX)
        return 1;
    *l = (long long)u;
    return 0;
}

/* Binary bytes of type t into values. */
static cvm_status convert(const cvm__vtu_file *f, const cvm__vtu_array *a, const struct vtype *t,
                          const unsigned char *bytes, size_t len, const char *what, int integer,
                          long long want, void **out, size_t *got)
{
    size_t n = len / (size_t)t->size, k;
    long long *l = NULL;
    double *d = NULL;
    if (len % (size_t)t->size || (want >= 0 && (unsigned long long)n != (unsigned long long)want))
        return cvm__vtu_fail(f, a->ts, CVM_E_IO_FORMAT, "%s: %lu bytes of %s, expected %lld values",
                             what, (unsigned long)len, t->name, want);
    if (integer ? !(l = cvm__malloc(f->ctx, (n + 1) * sizeof *l)) :
                  !(d = cvm__malloc(f->ctx, (n + 1) * sizeof *d)))
        return cvm__nomem(f->ctx);
    for (k = 0; k < n; k++) {
        long long lv = 0;
        double dv = 0;
        int r = cvm__bin_number(bytes + k * (size_t)t->size, t->size, t->kind, f->big_endian,
                                integer, &lv, &dv);
        if (integer)
            l[k] = lv;
        else
            d[k] = dv;
        if (r) {
            cvm__free(f->ctx, integer ? (void *)l : (void *)d);
            if (r == 2)
                return cvm__vtu_fail(f, a->ts, CVM_E_INPUT_NONFINITE, "%s: entry %lu (from 0) "
                                     "is not a finite number", what, (unsigned long)k);
            return cvm__vtu_fail(f, a->ts, CVM_E_IO_FORMAT, "%s: entry %lu (from 0) of type %s "
                                 "is not an integer in [%lld, %lld]", what, (unsigned long)k,
                                 t->name, -(long long)INT32_MAX, (long long)INT32_MAX);
        }
    }
    *out = integer ? (void *)l : (void *)d;
    if (got)
        *got = n;
    return CVM_OK;
}

cvm_status cvm__vtu_decode(const cvm__vtu_file *f, const cvm__vtu_array *a, const char *what,
                           int integer, long long want, void **out, size_t *got)
{
    char fmt[CVM__VTU_ATTR_LEN] = "", type[CVM__VTU_ATTR_LEN] = "";
    const char *ts = f->buf + a->ts, *te = f->buf + a->te;
    const struct vtype *t = NULL;
    unsigned char *bytes = NULL;
    size_t len = 0, k;
    cvm_status s;
    *out = NULL;
    cvm__vtu_attr(ts, te, "format", fmt);
    if (strcmp(fmt, "ascii") == 0) {
        size_t ds, de;
        if ((s = data_text(f, a, &ds, &de)))
            return s;
        return ascii(f, ds, de, what, integer, want, out, got);
    }
    if (strcmp(fmt, "binary") != 0 && strcmp(fmt, "appended") != 0)
        return cvm__vtu_fail(f, a->ts, CVM_E_UNSUPPORTED, "%s: format=\"%s\" is not read (ascii, "
                             "binary or appended)", what, fmt);
    cvm__vtu_attr(ts, te, "type", type);
    for (k = 0; k < sizeof k_types / sizeof k_types[0]; k++)
        if (strcmp(type, k_types[k].name) == 0)
            t = &k_types[k];
    if (!t)
        return cvm__vtu_fail(f, a->ts, CVM_E_UNSUPPORTED, "%s: type=\"%s\" is not read (Int8..Int64, "
                             "UInt8..UInt64, Float32, Float64)", what, type);
    if ((s = binary_bytes(f, a, fmt[0] == 'a', what, &bytes, &len)))
        return s;
    s = convert(f, a, t, bytes, len, what, integer, want, out, got);
    cvm__free(f->ctx, bytes);
    return s;
}
