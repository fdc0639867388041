/*
 * read_stl.c - parses STL surfaces, ASCII or binary, into a cvm__surf3,
 * merging vertices with exactly equal coordinates.
 *
 * ASCII:  solid [name] / facet normal nx ny nz / outer loop / vertex x y z (3x)
 *         / endloop / endfacet ... / endsolid [name], one or more solids; the
 *         triangles of the k-th solid get marker k (from 1). The normal is not
 *         read: orientation comes from the vertex order.
 * Binary: 80-byte header, uint32 triangle count, then per triangle 12 float32
 *         (normal, 3 vertices) and a uint16 attribute, little-endian; marker 1.
 * The whole file is read first: it is binary when its size is exactly
 * 84 + 50 * count (binary headers may start with "solid" too), ASCII when it
 * starts with "solid", and otherwise refused with the size it should have.
 */
#include <stdio.h>
#include <string.h>

#include "surf3_io.h"

#define CHUNK 65536

/* ---- exact vertex merging: open addressing on the coordinates' bits ---- */

typedef struct vmap {
    int32_t *slot;      /* -1 empty, else a point index */
    size_t cap;         /* power of two, or 0 */
} vmap;

static uint64_t hash3(const double *p)
{
    uint64_t h = 0x9e3779b97f4a7c15u, b;
    int k;
    for (k = 0; k < 3; k++) {
        double v = p[k] + 0.0; /* -0 and +0 are one coordinate */
        memcpy(&b, &v, sizeof b);
        h ^= b + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdu;
        h ^= h >> 33;
    }
    return h;
}

static cvm_status vmap_rehash(cvm__ctx *ctx, vmap *m, const cvm__surf3 *s, size_t cap)
{
    int32_t *slot;
    size_t i, bytes;
    if (!cvm__mul_ok(cap, sizeof(int32_t), &bytes) || !(slot = cvm__malloc(ctx, bytes)))
        return cvm__nomem(ctx);
    memset(slot, 0xff, bytes);
    for (i = 0; i < s->np; i++) {
        size_t h = (size_t)hash3(s->xyz + 3 * i) & (cap - 1);
        while (slot[h] >= 0)
            h = (h + 1) & (cap - 1);
        slot[h] = (int32_t)i;
    }
    cvm__free(ctx, m->slot);
    m->slot = slot;
    m->cap = cap;
    return CVM_OK;
}

/* The index of the point at p, added when new. */
static cvm_status vmap_point(cvm__ctx *ctx, vmap *m, cvm__surf3 *s, const double *p, int32_t *out)
{
    size_t h;
    cvm_status st;
    if (2 * (s->np + 1) > m->cap && (st = vmap_rehash(ctx, m, s, m->cap ? 2 * m->cap : 64)))
        return st;
    h = (size_t)hash3(p) & (m->cap - 1);
    while (m->slot[h] >= 0) {
        const double *q = s->xyz + 3 * m->slot[h];
        if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) {
            *out = m->slot[h];
            return CVM_OK;
        }
        h = (h + 1) & (m->cap - 1);
    }
    if ((st = cvm__surf3_add_point(ctx, s, p[0] + 0.0, p[1] + 0.0, p[2] + 0.0)))
        return st;
    m->slot[h] = (int32_t)(s->np - 1);
    *out = m->slot[h];
    return CVM_OK;
}

static cvm_status add_triangle(cvm__ctx *ctx, vmap *m, cvm__surf3 *s, const double *v, int32_t marker)
{
    int32_t idx[3];
    cvm_status st;
    int k;
    for (k = 0; k < 3; k++)
        if ((st = vmap_point(ctx, m, s, v + 3 * k, &idx[k])))
            return st;
    if ((st = cvm__surf3_add_facet(ctx, s, marker)))
        return st;
    return cvm__surf3_add_polygon(ctx, s, idx, 3);
}

/* ---- the whole input in memory ---- */

static cvm_status slurp(cvm__ctx *ctx, cvm__reader *r, const char *name, char **buf, size_t *len)
{
    size_t cap = 0;
    *buf = NULL;
    *len = 0;
    for (;;) {
        long got;
        if (cvm__grow(ctx, (void **)buf, &cap, *len + CHUNK, 1))
            return cvm__nomem(ctx);
        if (*len && cvm__poll_cancel(ctx, CVM_STAGE_READ, 0.0))
            return cvm__error(ctx, CVM_INCOMPLETE_CANCELLED, CVM_ENT_NONE, -1, "reading %s was cancelled",
                              name);
        got = r->read(r->self, *buf + *len, CHUNK);
        if (got < 0 || got > CHUNK)
            return cvm__error(ctx, CVM_E_IO_READ, CVM_ENT_NONE, -1, "%s: byte %lu: read error", name,
                              (unsigned long)*len);
        if (got == 0)
            return CVM_OK;
        *len += (size_t)got;
        if (*len > (size_t)0x7fffffff)
            return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1, "%s is larger than 2 GiB", name);
    }
}

/* A cvm__reader over the bytes already read, for the ASCII scanner. */
typedef struct mem_src {
    const char *p;
    size_t len, pos;
} mem_src;

static long mem_read(void *self, char *buf, size_t len)
{
    mem_src *m = (mem_src *)self;
    size_t n = m->len - m->pos;
    if (n > len)
        n = len;
    memcpy(buf, m->p + m->pos, n);
    m->pos += n;
    return (long)n;
}

/* ---- binary ---- */

static uint32_t le32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static cvm_status read_binary(cvm__ctx *ctx, const unsigned char *b, size_t n, const char *name,
                              cvm__surf3 *s)
{
    vmap m = {NULL, 0};
    cvm_status st = CVM_OK;
    size_t i;
    for (i = 0; i < n && !st; i++) {
        const unsigned char *t = b + 84 + 50 * i + 12;
        double v[9];
        int k;
        for (k = 0; k < 9; k++) {
            uint32_t u = le32(t + 4 * k);
            float f;
            memcpy(&f, &u, sizeof f);
            v[k] = (double)f;
            if (v[k] - v[k] != 0.0) {
                st = cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_FACET, (int64_t)i,
                                "%s: byte %lu: facet %lu has a non-finite %c in vertex %d", name,
                                (unsigned long)(84 + 50 * i + 12 + 4 * (size_t)k), (unsigned long)i + 1,
                                "xyz"[k % 3], k / 3 + 1);
                break;
            }
        }
        if (!st)
            st = add_triangle(ctx, &m, s, v, 1);
    }
    cvm__free(ctx, m.slot);
    return st;
}

/* ---- ASCII ---- */

static int field_is(const char *f, const char *word)
{
    return f && strcmp(f, word) == 0;
}

/* The next line must start with word (and have exactly nf fields when nf > 0). */
static cvm_status expect_word(cvm__scan *sc, const char *word, size_t nf, long facet)
{
    cvm_status st;
    const char *f;
    char what[64];
    snprintf(what, sizeof what, "'%s' of facet %ld", word, facet);
    if ((st = cvm__s3_need_line(sc, what)))
        return st;
    f = cvm__scan_field(sc);
    if (!field_is(f, word))
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "facet %ld: expected '%s', found '%.40s'", facet,
                               word, f);
    if (nf && sc->nfields != nf)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "facet %ld: '%s' line: expected %lu fields, found %lu",
                               facet, word, (unsigned long)nf, (unsigned long)sc->nfields);
    return CVM_OK;
}

static cvm_status read_facet(cvm__ctx *ctx, cvm__scan *sc, vmap *m, cvm__surf3 *s, long facet,
                             int32_t marker)
{
    double v[9];
    cvm_status st;
    int k;
    if ((st = expect_word(sc, "outer", 2, facet)))
        return st;
    if (!field_is(cvm__scan_field(sc), "loop"))
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "facet %ld: expected 'outer loop'", facet);
    for (k = 0; k < 3; k++)
        if ((st = expect_word(sc, "vertex", 4, facet)) || (st = cvm__s3_real(sc, "facet", facet, &v[3 * k])) ||
            (st = cvm__s3_real(sc, "facet", facet, &v[3 * k + 1])) ||
            (st = cvm__s3_real(sc, "facet", facet, &v[3 * k + 2])))
            return st;
    if ((st = cvm__s3_need_line(sc, "'endloop'")))
        return st;
    if (field_is(cvm__scan_field(sc), "vertex"))
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "facet %ld has more than 3 vertices (only triangles are read)",
                               facet);
    sc->cursor = 0;
    if (!field_is(cvm__scan_field(sc), "endloop") || sc->nfields != 1)
        return cvm__scan_error(sc, CVM_E_IO_FORMAT, "facet %ld: expected 'endloop'", facet);
    if ((st = expect_word(sc, "endfacet", 1, facet)))
        return st;
    if ((st = add_triangle(ctx, m, s, v, marker)))
        return st;
    if (s->nfacet > CVM__SURF3_MAX_COUNT)
        return cvm__scan_error(sc, CVM_E_TOO_LARGE, "more than %lu facets",
                               (unsigned long)CVM__SURF3_MAX_COUNT);
    return CVM_OK;
}

static cvm_status read_ascii(cvm__ctx *ctx, const char *text, size_t len, const char *name,
                             cvm__surf3 *s)
{
    mem_src src = {text, len, 0};
    cvm__reader r;
    cvm__scan sc;
    vmap m = {NULL, 0};
    cvm_status st = CVM_OK;
    int32_t solid = 0, in_solid = 0;
    long facet = 0;
    r.read = mem_read;
    r.self = &src;
    cvm__scan_init(&sc, ctx, &r, name);
    for (;;) {
        int got;
        const char *f;
        if ((st = cvm__scan_line(&sc, &got)))
            break;
        if (!got) {
            if (in_solid)
                st = cvm__scan_error(&sc, CVM_E_IO_FORMAT, "unexpected end of file: solid %d has no 'endsolid'",
                                     (int)solid);
            break;
        }
        f = cvm__scan_field(&sc);
        if (!in_solid) {
            if (!field_is(f, "solid")) {
                st = cvm__scan_error(&sc, CVM_E_IO_FORMAT, "expected 'solid', found '%.40s'", f);
                break;
            }
            if (solid == INT32_MAX - 1) {
                st = cvm__scan_error(&sc, CVM_E_TOO_LARGE, "too many solids");
                break;
            }
            solid++;
            in_solid = 1;
        } else if (field_is(f, "endsolid")) {
            in_solid = 0;
        } else if (field_is(f, "facet")) {
            if ((st = read_facet(ctx, &sc, &m, s, ++facet, solid)))
                break;
        } else {
            st = cvm__scan_error(&sc, CVM_E_IO_FORMAT, "expected 'facet' or 'endsolid', found '%.40s'", f);
            break;
        }
    }
    cvm__scan_free(&sc);
    cvm__free(ctx, m.slot);
    return st;
}

static int starts_with_solid(const char *b, size_t len)
{
    size_t i = 0;
    while (i < len && (b[i] == ' ' || b[i] == '\t' || b[i] == '\r' || b[i] == '\n'))
        i++;
    return len - i >= 5 && memcmp(b + i, "solid", 5) == 0;
}

cvm_status cvm__read_stl(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out)
{
    char *buf;
    size_t len;
    cvm_status st;
    cvm__surf3_init(out);
    out->facet_base = 1;
    out->points_numbered = 0;
    st = slurp(ctx, r, name, &buf, &len);
    if (!st) {
        const unsigned char *b = (const unsigned char *)buf;
        size_t n = len >= 84 ? (size_t)le32(b + 80) : 0;
        int binary_size = len >= 84 && n <= (len - 84) / 50 && 84 + 50 * n == len;
        if (binary_size && n > CVM__SURF3_MAX_COUNT)
            st = cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1, "%s: %lu facets exceed the limit of %lu",
                            name, (unsigned long)n, (unsigned long)CVM__SURF3_MAX_COUNT);
        else if (binary_size)
            st = read_binary(ctx, b, n, name, out);
        else if (starts_with_solid(buf, len))
            st = read_ascii(ctx, buf, len, name, out);
        else if (len < 84)
            st = cvm__error(ctx, CVM_E_IO_FORMAT, CVM_ENT_NONE, -1,
                            "%s: not an STL file: no 'solid' keyword, and %lu bytes are too few for "
                            "binary STL (84 at least)", name, (unsigned long)len);
        else
            st = cvm__error(ctx, CVM_E_IO_FORMAT, CVM_ENT_NONE, -1,
                            "%s: byte 80: binary STL with %lu facets must have 84 + 50 * %lu = %.0f "
                            "bytes, but the file has %lu (truncated or not STL)", name, (unsigned long)n,
                            (unsigned long)n, 84.0 + 50.0 * (double)n, (unsigned long)len);
    }
    cvm__free(ctx, buf);
    if (!st)
        st = cvm__surf3_set_file(ctx, out, name);
    if (st)
        cvm__surf3_free(ctx, out);
    if (!st) {
        out->facet_base = 1;
        out->points_numbered = 0;
    }
    return st;
}
