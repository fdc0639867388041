/*
 * read_msh.c - parses a Gmsh mesh file (.msh, format 2.2 or 4.1, ASCII or
 * binary) into points, triangles, line cells, their physical tags and the
 * physical names.
 *
 * Format (Gmsh reference manual, "MSH file format", versions 4.1 and 2.2):
 * sections $Name ... $EndName. $MeshFormat gives version, file type (0
 * ASCII, 1 binary) and the size of size_t; a binary file then holds the int
 * 1 to tell the byte order. 2.2: $Nodes "id x y z" and $Elements "id type
 * ntags tags... nodes..." (the first tag is the physical group); in binary,
 * the counts are text lines and the records binary ints and doubles, the
 * elements in blocks "type count ntags". 4.1: $Entities gives each entity's
 * physical groups; $Nodes and $Elements come in blocks per entity, and an
 * element's physical group is the first one of its entity; in binary
 * everything in those sections is binary (int32, size_t, double).
 * $PhysicalNames is text in both. Read: all nodes (the input points; z must
 * be 0); elements of type 15 (point: its physical tag becomes the point's
 * marker), 1 (2-node line: a line cell whose marker is its physical tag), 2
 * (3-node triangle: its physical tag becomes the triangle's attribute when
 * some triangle has one). Other element types are CVM_E_UNSUPPORTED; other
 * sections are skipped. Errors give file:line (ASCII) or the byte offset
 * (binary data).
 */
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_text.h"
#include "vtu_data.h"

#define MAX_COUNT ((long long)INT32_MAX / 4)
#define WORD 64

typedef struct ent {
    int32_t dim, tag, phys;
} ent;

typedef struct elem { /* a kept element: node tags, physical tag, type */
    long long node[3];
    long long id;
    int32_t phys, type;
} elem;

typedef struct msh {
    cvm__vtu_file f;  /* messages; f.appended: where binary data begins */
    char *buf;
    size_t pos;
    int v4, binary, big, dsize;
    long long *ntag;  /* node tags, in file order */
    double *xyz;
    size_t nn, cap_ntag, cap_xyz;
    elem *el;
    size_t nel, cap_el;
    ent *ent;
    size_t nent, cap_ent;
    cvm__phys_name *names;
    size_t nnames, cap_names;
} msh;

static cvm_status fail(msh *m, size_t at, cvm_status st, const char *fmt, ...) CVM__PRINTF(4, 5);
static cvm_status fail(msh *m, size_t at, cvm_status st, const char *fmt, ...)
{
    char what[CVM__ERRMSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cvm__vtu_fail(&m->f, at, st, "%s", what);
}

static int space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* Next text word into w (truncated); 0 at the end of the file. */
static int word(msh *m, char *w, size_t *at)
{
    size_t s, n;
    while (m->pos < m->f.n && space(m->buf[m->pos]))
        m->pos++;
    *at = m->pos;
    if (m->pos >= m->f.n)
        return 0;
    s = m->pos;
    while (m->pos < m->f.n && !space(m->buf[m->pos]))
        m->pos++;
    n = m->pos - s < WORD - 1 ? m->pos - s : WORD - 1;
    memcpy(w, m->buf + s, n);
    w[n] = '\0';
    return 1;
}

/* An integer: text (bin 0), or binary of bin bytes (4: int, else size_t). */
static cvm_status get_int(msh *m, int bin, const char *what, long long lo, long long hi,
                          long long *out)
{
    size_t at = m->pos;
    *out = 0;
    if (bin) {
        long long v = 0;
        double unused;
        if (m->f.n - m->pos < (size_t)bin)
            return fail(m, at, CVM_E_IO_FORMAT, "the file ends in %s (truncated?)", what);
        if (bin == 4) {
            if (cvm__bin_number((const unsigned char *)m->buf + m->pos, 4, CVM__BIN_SIGNED, m->big, 1,
                                &v, &unused))
                v = LLONG_MIN;
        } else if (cvm__bin_number((const unsigned char *)m->buf + m->pos, bin, CVM__BIN_UNSIGNED,
                                   m->big, 1, &v, &unused)) {
            v = LLONG_MAX;
        }
        m->pos += (size_t)bin;
        *out = v;
        if (v < lo || v > hi)
            return fail(m, at, CVM_E_IO_FORMAT, "%s is %lld, not in [%lld, %lld]", what, v, lo, hi);
        return CVM_OK;
    } else {
        char w[WORD];
        if (!word(m, w, &at))
            return fail(m, at, CVM_E_IO_FORMAT, "the file ends before %s", what);
        if (cvm__parse_long(w, lo, hi, out))
            return fail(m, at, CVM_E_IO_FORMAT, "%s is '%s', not an integer in [%lld, %lld]", what,
                        w, lo, hi);
        return CVM_OK;
    }
}

static cvm_status get_double(msh *m, int bin, const char *what, double *out)
{
    size_t at = m->pos;
    int r;
    *out = 0;
    if (bin) {
        long long unused;
        if (m->f.n - m->pos < 8)
            return fail(m, at, CVM_E_IO_FORMAT, "the file ends in %s (truncated?)", what);
        r = cvm__bin_number((const unsigned char *)m->buf + m->pos, 8, CVM__BIN_FLOAT, m->big, 0,
                            &unused, out);
        m->pos += 8;
        if (r)
            return fail(m, at, CVM_E_INPUT_NONFINITE, "%s is not a finite number", what);
        return CVM_OK;
    } else {
        char w[WORD];
        if (!word(m, w, &at))
            return fail(m, at, CVM_E_IO_FORMAT, "the file ends before %s", what);
        if ((r = cvm__parse_double(w, out)))
            return fail(m, at, r == 2 ? CVM_E_INPUT_NONFINITE : CVM_E_IO_FORMAT,
                        "%s is '%s', not a %snumber", what, w, r == 2 ? "finite " : "");
        return CVM_OK;
    }
}

/* Skip to just after the newline that ends the current line. */
static void end_line(msh *m)
{
    while (m->pos < m->f.n && m->buf[m->pos] != '\n')
        m->pos++;
    m->pos += m->pos < m->f.n;
}

/* Find "$End<name>" from pos (it may follow binary data) and move past it. */
static cvm_status section_end(msh *m, const char *name, size_t start)
{
    char tag[WORD + 8];
    size_t k = (size_t)snprintf(tag, sizeof tag, "$End%s", name), i;
    for (i = m->pos; i + k <= m->f.n; i++)
        if (m->buf[i] == '$' && memcmp(m->buf + i, tag, k) == 0) {
            m->pos = i + k;
            return CVM_OK;
        }
    return fail(m, start, CVM_E_IO_FORMAT, "$%s has no %s (truncated file?)", name, tag);
}

static cvm_status mesh_format(msh *m, size_t at)
{
    char w[WORD];
    long long ft, ds;
    cvm_status s;
    if (!word(m, w, &at))
        return fail(m, at, CVM_E_IO_FORMAT, "$MeshFormat without a version");
    if (strcmp(w, "4.1") != 0 && strncmp(w, "2.", 2) != 0)
        return fail(m, at, CVM_E_UNSUPPORTED, "MSH version %s is not read (2.2 or 4.1)", w);
    m->v4 = w[0] == '4';
    if ((s = get_int(m, 0, "the file type", 0, 1, &ft)) ||
        (s = get_int(m, 0, "the data size", 4, 8, &ds)))
        return s;
    if (ds != 8 && ds != 4)
        return fail(m, at, CVM_E_UNSUPPORTED, "data size %lld is not read (4 or 8)", ds);
    m->binary = (int)ft;
    m->dsize = (int)ds;
    if (m->binary) {
        const unsigned char *p;
        end_line(m);
        if (m->f.n - m->pos < 4)
            return fail(m, m->pos, CVM_E_IO_FORMAT, "the file ends in the byte-order mark");
        p = (const unsigned char *)m->buf + m->pos;
        if (!((p[0] == 1 && !p[1] && !p[2] && !p[3]) || (!p[0] && !p[1] && !p[2] && p[3] == 1)))
            return fail(m, m->pos, CVM_E_IO_FORMAT, "the binary byte-order mark is not the int 1");
        m->big = p[3] == 1;
        m->f.appended = m->pos; /* from here on, messages give byte offsets */
        m->f.appended_raw = 1;
        m->pos += 4;
    }
    return section_end(m, "MeshFormat", at);
}

static cvm_status physical_names(msh *m, size_t at)
{
    long long n, k, dim, tag;
    cvm_status s;
    if ((s = get_int(m, 0, "the number of physical names", 0, MAX_COUNT, &n)))
        return s;
    for (k = 0; k < n; k++) {
        cvm__phys_name *pn;
        const char *q, *e;
        size_t len;
        if ((s = get_int(m, 0, "a physical dimension", 0, 3, &dim)) ||
            (s = get_int(m, 0, "a physical tag", INT32_MIN + 1LL, INT32_MAX, &tag)))
            return s;
        while (m->pos < m->f.n && (m->buf[m->pos] == ' ' || m->buf[m->pos] == '\t'))
            m->pos++;
        q = m->buf + m->pos;
        if (m->pos >= m->f.n || *q != '"' || !(e = memchr(q + 1, '"', m->f.n - m->pos - 1)))
            return fail(m, m->pos, CVM_E_IO_FORMAT, "physical name %lld is not in double quotes", k);
        if (m->nnames + 1 > m->cap_names &&
            cvm__grow(m->f.ctx, (void **)&m->names, &m->cap_names, m->nnames + 1, sizeof *m->names))
            return cvm__nomem(m->f.ctx);
        pn = &m->names[m->nnames++];
        len = (size_t)(e - q - 1) < sizeof pn->name - 1 ? (size_t)(e - q - 1) : sizeof pn->name - 1;
        pn->dim = (int32_t)dim;
        pn->tag = (int32_t)tag;
        memcpy(pn->name, q + 1, len);
        pn->name[len] = '\0';
        m->pos = (size_t)(e + 1 - m->buf);
    }
    return section_end(m, "PhysicalNames", at);
}

/* 4.1 $Entities: the first physical tag of each point, curve and surface. */
static cvm_status entities(msh *m, size_t at)
{
    int bin = m->binary ? m->dsize : 0, ib = m->binary ? 4 : 0;
    long long cnt[4], k, j, tag, nphys, phys, nb, unused;
    double x;
    int dim;
    cvm_status s;
    for (dim = 0; dim < 4; dim++)
        if ((s = get_int(m, bin, "an entity count", 0, MAX_COUNT, &cnt[dim])))
            return s;
    for (dim = 0; dim < 4; dim++)
        for (k = 0; k < cnt[dim]; k++) {
            if ((s = get_int(m, ib, "an entity tag", INT32_MIN + 1LL, INT32_MAX, &tag)))
                return s;
            for (j = 0; j < (dim ? 6 : 3); j++)
                if ((s = get_double(m, bin ? 8 : 0, "an entity coordinate", &x)))
                    return s;
            if ((s = get_int(m, bin, "a number of physical tags", 0, MAX_COUNT, &nphys)))
                return s;
            for (j = 0, phys = 0; j < nphys; j++) {
                if ((s = get_int(m, ib, "a physical tag", INT32_MIN + 1LL, INT32_MAX, &unused)))
                    return s;
                if (j == 0)
                    phys = unused;
            }
            if (dim > 0) {
                if ((s = get_int(m, bin, "a number of bounding entities", 0, MAX_COUNT, &nb)))
                    return s;
                for (j = 0; j < nb; j++)
                    if ((s = get_int(m, ib, "a bounding entity", INT32_MIN + 1LL, INT32_MAX, &unused)))
                        return s;
            }
            if (m->nent + 1 > m->cap_ent &&
                cvm__grow(m->f.ctx, (void **)&m->ent, &m->cap_ent, m->nent + 1, sizeof *m->ent))
                return cvm__nomem(m->f.ctx);
            m->ent[m->nent].dim = dim;
            m->ent[m->nent].tag = (int32_t)tag;
            m->ent[m->nent++].phys = (int32_t)phys;
        }
    return section_end(m, "Entities", at);
}

static cvm_status add_node(msh *m, long long tag, const double *xyz)
{
    if ((m->nn + 1 > m->cap_ntag &&
         cvm__grow(m->f.ctx, (void **)&m->ntag, &m->cap_ntag, m->nn + 1, sizeof *m->ntag)) ||
        (3 * (m->nn + 1) > m->cap_xyz &&
         cvm__grow(m->f.ctx, (void **)&m->xyz, &m->cap_xyz, 3 * (m->nn + 1), sizeof *m->xyz)))
        return cvm__nomem(m->f.ctx);
    m->ntag[m->nn] = tag;
    memcpy(m->xyz + 3 * m->nn, xyz, 3 * sizeof *xyz);
    if (++m->nn > (size_t)MAX_COUNT)
        return fail(m, m->pos, CVM_E_TOO_LARGE, "more than %lld nodes", MAX_COUNT);
    return CVM_OK;
}

static cvm_status nodes(msh *m, size_t at)
{
    int bin = m->binary ? m->dsize : 0;
    long long nblk = 1, b, n, k, j, dim, par, tag;
    double xyz[3], uvw;
    cvm_status s;
    if (!m->v4) {
        if ((s = get_int(m, 0, "the node count", 0, MAX_COUNT, &n)))
            return s;
        if (m->binary)
            end_line(m);
        for (k = 0; k < n; k++) {
            if ((s = get_int(m, m->binary ? 4 : 0, "a node tag", 1, INT32_MAX, &tag)))
                return s;
            for (j = 0; j < 3; j++)
                if ((s = get_double(m, m->binary ? 8 : 0, "a node coordinate", &xyz[j])))
                    return s;
            if ((s = add_node(m, tag, xyz)))
                return s;
        }
        return section_end(m, "Nodes", at);
    }
    if ((s = get_int(m, bin, "the number of node blocks", 0, MAX_COUNT, &nblk)) ||
        (s = get_int(m, bin, "the node count", 0, MAX_COUNT, &n)) ||
        (s = get_int(m, bin, "the smallest node tag", 0, LLONG_MAX, &tag)) ||
        (s = get_int(m, bin, "the largest node tag", 0, LLONG_MAX, &tag)))
        return s;
    for (b = 0; b < nblk; b++) {
        size_t first = m->nn;
        int ib = m->binary ? 4 : 0;
        if ((s = get_int(m, ib, "an entity dimension", 0, 3, &dim)) ||
            (s = get_int(m, ib, "an entity tag", INT32_MIN + 1LL, INT32_MAX, &tag)) ||
            (s = get_int(m, ib, "the parametric flag", 0, 1, &par)) ||
            (s = get_int(m, bin, "a block's node count", 0, MAX_COUNT, &n)))
            return s;
        xyz[0] = xyz[1] = xyz[2] = 0;
        for (k = 0; k < n; k++)
            if ((s = get_int(m, bin, "a node tag", 1, LLONG_MAX, &tag)) || (s = add_node(m, tag, xyz)))
                return s;
        for (k = 0; k < n; k++) {
            for (j = 0; j < 3; j++)
                if ((s = get_double(m, bin ? 8 : 0, "a node coordinate", &m->xyz[3 * (first + (size_t)k) + (size_t)j])))
                    return s;
            for (j = 0; par && j < dim; j++)
                if ((s = get_double(m, bin ? 8 : 0, "a parametric coordinate", &uvw)))
                    return s;
        }
    }
    return section_end(m, "Nodes", at);
}

/* Nodes of a Gmsh element type that is read; 0 otherwise. */
static int nodes_of(long long type)
{
    return type == 15 ? 1 : type == 1 ? 2 : type == 2 ? 3 : 0;
}

static cvm_status add_elem(msh *m, long long id, long long type, long long phys,
                           const long long *node)
{
    elem *e;
    if (m->nel + 1 > m->cap_el &&
        cvm__grow(m->f.ctx, (void **)&m->el, &m->cap_el, m->nel + 1, sizeof *m->el))
        return cvm__nomem(m->f.ctx);
    e = &m->el[m->nel++];
    memset(e, 0, sizeof *e);
    e->id = id;
    e->type = (int32_t)type;
    e->phys = (int32_t)phys;
    memcpy(e->node, node, (size_t)nodes_of(type) * sizeof *node);
    if (m->nel > (size_t)MAX_COUNT)
        return fail(m, m->pos, CVM_E_TOO_LARGE, "more than %lld elements", MAX_COUNT);
    return CVM_OK;
}

static cvm_status unsupported_type(msh *m, size_t at, long long id, long long type)
{
    return fail(m, at, CVM_E_UNSUPPORTED, "element %lld has Gmsh type %lld (only points 15, "
                "2-node lines 1 and 3-node triangles 2 are read)", id, type);
}

/* 2.2 $Elements. */
static cvm_status elements2(msh *m, size_t at)
{
    int ib = m->binary ? 4 : 0;
    long long n, k = 0, j, id, type, ntags, tag, phys, node[3], follow = 0;
    cvm_status s;
    if ((s = get_int(m, 0, "the element count", 0, MAX_COUNT, &n)))
        return s;
    if (m->binary)
        end_line(m);
    while (k < n) {
        size_t eat;
        while (!m->binary && m->pos < m->f.n && space(m->buf[m->pos]))
            m->pos++;
        eat = m->pos;
        if (m->binary && follow == 0) { /* a block header: type, count, ntags */
            if ((s = get_int(m, 4, "an element type", 0, INT32_MAX, &type)) ||
                (s = get_int(m, 4, "an element count", 1, n - k, &follow)) ||
                (s = get_int(m, 4, "a number of tags", 0, 1000, &ntags)))
                return s;
            if (!nodes_of(type))
                return unsupported_type(m, eat, k + 1, type);
        }
        if ((s = get_int(m, ib, "an element tag", 1, INT32_MAX, &id)))
            return s;
        if (!m->binary && ((s = get_int(m, 0, "an element type", 0, INT32_MAX, &type)) ||
                           (s = get_int(m, 0, "a number of tags", 0, 1000, &ntags))))
            return s;
        if (!nodes_of(type))
            return unsupported_type(m, eat, id, type);
        for (j = 0, phys = 0; j < ntags; j++) {
            if ((s = get_int(m, ib, "an element tag", INT32_MIN + 1LL, INT32_MAX, &tag)))
                return s;
            if (j == 0)
                phys = tag;
        }
        for (j = 0; j < nodes_of(type); j++)
            if ((s = get_int(m, ib, "a node of an element", 1, INT32_MAX, &node[j])))
                return s;
        if ((s = add_elem(m, id, type, phys, node)))
            return s;
        k++;
        follow -= follow > 0;
    }
    return section_end(m, "Elements", at);
}

/* 4.1 $Elements. */
static cvm_status elements4(msh *m, size_t at)
{
    int bin = m->binary ? m->dsize : 0, ib = m->binary ? 4 : 0;
    long long nblk, n, b, k, j, dim, etag, type, id, node[3], phys;
    size_t e;
    cvm_status s;
    if ((s = get_int(m, bin, "the number of element blocks", 0, MAX_COUNT, &nblk)) ||
        (s = get_int(m, bin, "the element count", 0, MAX_COUNT, &n)) ||
        (s = get_int(m, bin, "the smallest element tag", 0, LLONG_MAX, &id)) ||
        (s = get_int(m, bin, "the largest element tag", 0, LLONG_MAX, &id)))
        return s;
    for (b = 0; b < nblk; b++) {
        size_t bat = m->pos;
        if ((s = get_int(m, ib, "an entity dimension", 0, 3, &dim)) ||
            (s = get_int(m, ib, "an entity tag", INT32_MIN + 1LL, INT32_MAX, &etag)) ||
            (s = get_int(m, ib, "an element type", 0, INT32_MAX, &type)) ||
            (s = get_int(m, bin, "a block's element count", 0, MAX_COUNT, &n)))
            return s;
        if (!nodes_of(type) && n > 0)
            return unsupported_type(m, bat, -1, type);
        for (e = 0, phys = 0; e < m->nent; e++)
            if (m->ent[e].dim == dim && m->ent[e].tag == etag) {
                phys = m->ent[e].phys;
                break;
            }
        for (k = 0; k < n; k++) {
            if ((s = get_int(m, bin, "an element tag", 1, LLONG_MAX, &id)))
                return s;
            for (j = 0; j < nodes_of(type); j++)
                if ((s = get_int(m, bin, "a node of an element", 1, LLONG_MAX, &node[j])))
                    return s;
            if ((s = add_elem(m, id, type, phys, node)))
                return s;
        }
    }
    return section_end(m, "Elements", at);
}

static cvm_status sections(msh *m)
{
    char w[WORD];
    size_t at;
    int seen_format = 0;
    cvm_status s = CVM_OK;
    while (!s && word(m, w, &at)) {
        if (w[0] != '$')
            return fail(m, at, CVM_E_IO_FORMAT, "'%s' where a $Section was expected", w);
        if (!seen_format && strcmp(w, "$MeshFormat") != 0)
            return fail(m, at, CVM_E_IO_FORMAT, "not a Gmsh file (no $MeshFormat first)");
        if (m->binary)
            end_line(m); /* binary data starts on the next line */
        if (strcmp(w, "$MeshFormat") == 0) {
            if (seen_format++)
                return fail(m, at, CVM_E_IO_FORMAT, "a second $MeshFormat");
            s = mesh_format(m, at);
        } else if (strcmp(w, "$PhysicalNames") == 0) {
            s = physical_names(m, at);
        } else if (strcmp(w, "$Entities") == 0 && m->v4) {
            s = entities(m, at);
        } else if (strcmp(w, "$Nodes") == 0) {
            if (m->nn)
                return fail(m, at, CVM_E_IO_FORMAT, "a second $Nodes section");
            s = nodes(m, at);
        } else if (strcmp(w, "$Elements") == 0) {
            if (m->nel)
                return fail(m, at, CVM_E_IO_FORMAT, "a second $Elements section");
            s = m->v4 ? elements4(m, at) : elements2(m, at);
        } else { /* another section: skipped */
            s = section_end(m, w + 1, at);
        }
    }
    if (!s && !seen_format)
        return fail(m, 0, CVM_E_IO_FORMAT, "not a Gmsh file (no $MeshFormat)");
    return s;
}

typedef struct tagidx {
    long long tag;
    size_t idx;
} tagidx;

static int cmp_tag(const void *pa, const void *pb)
{
    const tagidx *a = pa, *b = pb;
    return a->tag < b->tag ? -1 : a->tag > b->tag;
}

/* Index of node tag in the sorted map, or -1. */
static long long find_node(const tagidx *map, size_t n, long long tag)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (map[mid].tag == tag)
            return (long long)map[mid].idx;
        if (map[mid].tag < tag)
            lo = mid + 1;
        else
            hi = mid;
    }
    return -1;
}

/* Nodes and kept elements -> out. */
static cvm_status build(msh *m, cvm__vtu_mesh *out)
{
    cvm__ctx *ctx = m->f.ctx;
    tagidx *map = cvm__malloc(ctx, (m->nn + 1) * sizeof *map);
    size_t k, nt = 0, nl = 0, j;
    int pmarked = 0, tmarked = 0;
    cvm_status s = CVM_OK;
    if (!map)
        return cvm__nomem(ctx);
    for (k = 0; k < m->nn; k++) {
        map[k].tag = m->ntag[k];
        map[k].idx = k;
    }
    qsort(map, m->nn, sizeof *map, cmp_tag);
    for (k = 1; k < m->nn; k++)
        if (map[k].tag == map[k - 1].tag) {
            s = cvm__error(ctx, CVM_E_IO_FORMAT, CVM_ENT_NONE, -1, "%s: node tag %lld appears twice",
                           m->f.name, map[k].tag);
            goto out;
        }
    for (k = 0; k < m->nel; k++) {
        elem *e = &m->el[k];
        for (j = 0; j < (size_t)nodes_of(e->type); j++) {
            long long i = find_node(map, m->nn, e->node[j]);
            if (i < 0) {
                s = cvm__error(ctx, CVM_E_IO_FORMAT, CVM_ENT_NONE, -1, "%s: element %lld names "
                               "node %lld, which does not exist", m->f.name, e->id, e->node[j]);
                goto out;
            }
            e->node[j] = i;
        }
        nt += e->type == 2;
        nl += e->type == 1;
        pmarked |= e->type == 15 && e->phys != 0;
        tmarked |= e->type == 2 && e->phys != 0;
    }
    out->p.xy = cvm__malloc(ctx, (2 * m->nn + 1) * sizeof *out->p.xy);
    out->p.pmark = pmarked ? cvm__calloc(ctx, m->nn + 1, sizeof *out->p.pmark) : NULL;
    out->tri = cvm__malloc(ctx, (3 * nt + 1) * sizeof *out->tri);
    out->tattr = tmarked ? cvm__malloc(ctx, (nt + 1) * sizeof *out->tattr) : NULL;
    out->p.seg = cvm__malloc(ctx, (2 * nl + 1) * sizeof *out->p.seg);
    out->p.smark = cvm__malloc(ctx, (nl + 1) * sizeof *out->p.smark);
    if (!out->p.xy || (pmarked && !out->p.pmark) || !out->tri || (tmarked && !out->tattr) ||
        !out->p.seg || !out->p.smark) {
        s = cvm__nomem(ctx);
        goto out;
    }
    for (k = 0; k < m->nn; k++) {
        if (m->xyz[3 * k + 2] != 0) {
            s = cvm__error(ctx, CVM_E_IO_FORMAT, CVM_ENT_NONE, -1, "%s: node %lld has z = %.17g "
                           "(only planar meshes are read)", m->f.name, m->ntag[k], m->xyz[3 * k + 2]);
            goto out;
        }
        out->p.xy[2 * k] = m->xyz[3 * k];
        out->p.xy[2 * k + 1] = m->xyz[3 * k + 1];
    }
    out->p.np = m->nn;
    for (k = 0; k < m->nel; k++) {
        const elem *e = &m->el[k];
        if (e->type == 15 && out->p.pmark) {
            out->p.pmark[e->node[0]] = e->phys;
        } else if (e->type == 1) {
            out->p.seg[2 * out->p.nseg] = (int32_t)e->node[0];
            out->p.seg[2 * out->p.nseg + 1] = (int32_t)e->node[1];
            out->p.smark[out->p.nseg++] = e->phys;
        } else if (e->type == 2) {
            for (j = 0; j < 3; j++)
                out->tri[3 * out->nt + j] = (int32_t)e->node[j];
            if (out->tattr)
                out->tattr[out->nt] = e->phys;
            out->nt++;
        }
    }
    out->has_lines = nl > 0;
    out->names = m->names;
    out->nnames = m->nnames;
    m->names = NULL;
out:
    cvm__free(ctx, map);
    return s;
}

cvm_status cvm__read_msh(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out)
{
    msh m;
    cvm_status s;
    memset(&m, 0, sizeof m);
    memset(out, 0, sizeof *out);
    m.f.ctx = ctx;
    m.f.name = name;
    if (!(s = cvm__slurp(ctx, r, name, &m.buf, &m.f.n))) {
        m.f.buf = m.buf;
        if (!(s = sections(&m)))
            s = build(&m, out);
    }
    cvm__free(ctx, m.buf);
    cvm__free(ctx, m.ntag);
    cvm__free(ctx, m.xyz);
    cvm__free(ctx, m.el);
    cvm__free(ctx, m.ent);
    cvm__free(ctx, m.names);
    if (s)
        cvm__vtu_mesh_free(ctx, out);
    return s;
}

cvm_status cvm__read_msh_names(cvm__ctx *ctx, cvm__reader *r, const char *name,
                               cvm__phys_name **names_out, size_t *n_out)
{
    cvm__vtu_mesh vm;
    cvm_status s = cvm__read_msh(ctx, r, name, &vm);
    *names_out = NULL;
    *n_out = 0;
    if (s)
        return s;
    *names_out = vm.names;
    *n_out = vm.nnames;
    vm.names = NULL;
    vm.nnames = 0;
    cvm__vtu_mesh_free(ctx, &vm);
    return CVM_OK;
}
