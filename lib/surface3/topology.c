/*
 * topology.c - the edges of a triangulated surface: every edge shared by two
 * faces running opposite ways (closed and consistently oriented), no edge of
 * three or more faces unless internal facets are allowed, no vertex where
 * separate fans of faces meet, no repeated face; and the count of shells.
 *
 * Edges come from sorting the 3 nt directed half-edges by (smaller point,
 * larger point, triangle), so reports are deterministic. Vertex fans: a
 * union-find over the triangle corners joins the two corners of every
 * point on each shared edge; a point whose corners fall into more than one
 * set is non-manifold.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "surface3_internal.h"

typedef struct half {
    int32_t lo, hi;   /* points, lo < hi */
    int32_t tri;
    int32_t fwd;      /* 1 when the triangle runs lo -> hi */
} half;

static int cmp_half(const void *pa, const void *pb)
{
    const half *a = (const half *)pa, *b = (const half *)pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->tri > b->tri) - (a->tri < b->tri);
}

static int32_t find(int32_t *up, int32_t x)
{
    while (up[x] != x) {
        up[x] = up[up[x]];
        x = up[x];
    }
    return x;
}

static void join(int32_t *up, int32_t a, int32_t b)
{
    a = find(up, a);
    b = find(up, b);
    if (a != b) {
        if (a < b)
            up[b] = a;
        else
            up[a] = b;
    }
}

/* The corner slot of point p in triangle t. */
static int32_t corner(const cvm__surf3_tris *t, int32_t tri, int32_t p)
{
    int k;
    for (k = 0; k < 3; k++)
        if (t->tri[3 * tri + k] == p)
            break;
    return 3 * tri + k;
}

static cvm_status edge_error(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t,
                             cvm_status st, const half *h, size_t n, const char *what)
{
    char a[160], b[160], c[160];
    cvm__surf3_name_poly(s, (size_t)t->tpoly[h[0].tri], a, sizeof a);
    b[0] = c[0] = '\0';
    if (n > 1)
        cvm__surf3_name_poly(s, (size_t)t->tpoly[h[1].tri], b, sizeof b);
    if (n > 2)
        cvm__surf3_name_poly(s, (size_t)t->tpoly[h[2].tri], c, sizeof c);
    if (s->points_numbered)
        return cvm__error(ctx, st, CVM_ENT_FACET, s->pfacet[t->tpoly[h[0].tri]],
                          "%s%sthe edge between points %lld and %lld %s: %s%s%s%s%s%s",
                          s->file ? s->file : "", s->file ? ": " : "", (long long)h->lo + s->point_base,
                          (long long)h->hi + s->point_base, what, a, n > 1 ? ", " : "", b,
                          n > 2 ? ", " : "", c, n > 3 ? ", ..." : "");
    {
        const double *p = s->xyz + 3 * h->lo, *q = s->xyz + 3 * h->hi;
        return cvm__error(ctx, st, CVM_ENT_FACET, s->pfacet[t->tpoly[h[0].tri]],
                          "%s%sthe edge (%.17g, %.17g, %.17g)-(%.17g, %.17g, %.17g) %s: %s%s%s%s%s%s",
                          s->file ? s->file : "", s->file ? ": " : "", p[0], p[1], p[2], q[0], q[1],
                          q[2], what, a, n > 1 ? ", " : "", b, n > 2 ? ", " : "", c, n > 3 ? ", ..." : "");
    }
}

/* Check one group of n half-edges of the same edge; join corners and shells. */
static cvm_status check_edge(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t, int flags,
                             const half *h, size_t n, int32_t *cup, int32_t *tup)
{
    size_t i;
    if (n == 1)
        return edge_error(ctx, s, t, CVM_E_INPUT_NOT_CLOSED, h, n,
                          "belongs to one face only, so the surface is open");
    if (n == 2 && h[0].fwd == h[1].fwd)
        return edge_error(ctx, s, t, CVM_E_INPUT_NOT_CLOSED, h, n,
                          "runs the same way in both its faces, so one of them is flipped "
                          "(orientation is inconsistent)");
    if (n > 2 && !(flags & CVM__SURF3_ALLOW_INTERNAL))
        return edge_error(ctx, s, t, CVM_E_INPUT_INTERSECTING, h, n,
                          "is shared by more than two faces (non-manifold edge)");
    for (i = 1; i < n; i++) {
        join(tup, h[0].tri, h[i].tri);
        join(cup, corner(t, h[0].tri, h[0].lo), corner(t, h[i].tri, h[0].lo));
        join(cup, corner(t, h[0].tri, h[0].hi), corner(t, h[i].tri, h[0].hi));
    }
    return CVM_OK;
}

/* Every point's corners must form one fan; first[] marks a point's first root. */
static cvm_status check_vertices(cvm__ctx *ctx, const cvm__surf3 *s, const cvm__surf3_tris *t,
                                 int32_t *cup)
{
    int32_t *root = cvm__malloc(ctx, (s->np ? s->np : 1) * sizeof(int32_t));
    size_t i;
    if (!root)
        return cvm__nomem(ctx);
    for (i = 0; i < s->np; i++)
        root[i] = -1;
    for (i = 0; i < 3 * t->nt; i++) {
        int32_t p = t->tri[i], r = find(cup, (int32_t)i);
        if (root[p] < 0) {
            root[p] = r;
        } else if (root[p] != r) {
            char a[160], b[160];
            int32_t other = root[p] / 3;
            cvm_status st;
            cvm__surf3_name_poly(s, (size_t)t->tpoly[other], a, sizeof a);
            cvm__surf3_name_poly(s, (size_t)t->tpoly[i / 3], b, sizeof b);
            if (s->points_numbered)
                st = cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_FACET, s->pfacet[t->tpoly[i / 3]],
                                "%s%spoint %lld is a non-manifold vertex: separate fans of faces meet "
                                "there (%s and %s)", s->file ? s->file : "", s->file ? ": " : "",
                                (long long)p + s->point_base, a, b);
            else
                st = cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_FACET, s->pfacet[t->tpoly[i / 3]],
                                "%s%sthe point (%.17g, %.17g, %.17g) is a non-manifold vertex: separate "
                                "fans of faces meet there (%s and %s)", s->file ? s->file : "",
                                s->file ? ": " : "", s->xyz[3 * p], s->xyz[3 * p + 1], s->xyz[3 * p + 2], a, b);
            cvm__free(ctx, root);
            return st;
        }
    }
    cvm__free(ctx, root);
    return CVM_OK;
}

/* Two triangles of one edge group with the same three points. */
static int same_face(const cvm__surf3_tris *t, int32_t a, int32_t b)
{
    int32_t x[3], y[3], k, tmp;
    for (k = 0; k < 3; k++)
        x[k] = t->tri[3 * a + k], y[k] = t->tri[3 * b + k];
#define SORT3(v)                                                           \
    do {                                                                   \
        if (v[0] > v[1]) tmp = v[0], v[0] = v[1], v[1] = tmp;              \
        if (v[1] > v[2]) tmp = v[1], v[1] = v[2], v[2] = tmp;              \
        if (v[0] > v[1]) tmp = v[0], v[0] = v[1], v[1] = tmp;              \
    } while (0)
    SORT3(x);
    SORT3(y);
#undef SORT3
    return x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
}

static cvm_status check_groups(cvm__ctx *ctx, const cvm__surf3 *s, cvm__surf3_tris *t, int flags,
                               half *h, size_t nh, int32_t *cup, int32_t *tup)
{
    size_t i = 0, j, a, b;
    cvm_status st;
    while (i < nh) {
        for (j = i + 1; j < nh && h[j].lo == h[i].lo && h[j].hi == h[i].hi; j++)
            ;
        for (a = i; a < j; a++)
            for (b = a + 1; b < j && b < a + 8; b++)
                if (same_face(t, h[a].tri, h[b].tri)) {
                    half pair[2];
                    pair[0] = h[a];
                    pair[1] = h[b];
                    return edge_error(ctx, s, t, CVM_E_INPUT_INTERSECTING, pair, 2,
                                      "belongs to two faces with the same corners");
                }
        if ((st = check_edge(ctx, s, t, flags, h + i, j - i, cup, tup)))
            return st;
        i = j;
    }
    return CVM_OK;
}

cvm_status cvm__surf3_check_topology(cvm__ctx *ctx, const cvm__surf3 *s, cvm__surf3_tris *t, int flags)
{
    size_t nh = 3 * t->nt, i;
    half *h = cvm__malloc(ctx, (nh ? nh : 1) * sizeof *h);
    int32_t *cup = cvm__malloc(ctx, (nh ? nh : 1) * sizeof(int32_t));
    int32_t *tup = cvm__malloc(ctx, (t->nt ? t->nt : 1) * sizeof(int32_t));
    cvm_status st;
    if (!h || !cup || !tup) {
        st = cvm__nomem(ctx);
        goto done;
    }
    for (i = 0; i < nh; i++) {
        int32_t p = t->tri[i], q = t->tri[3 * (i / 3) + (i % 3 + 1) % 3];
        h[i].lo = p < q ? p : q;
        h[i].hi = p < q ? q : p;
        h[i].tri = (int32_t)(i / 3);
        h[i].fwd = p < q;
        cup[i] = (int32_t)i;
    }
    for (i = 0; i < t->nt; i++)
        tup[i] = (int32_t)i;
    qsort(h, nh, sizeof *h, cmp_half);
    if ((st = check_groups(ctx, s, t, flags, h, nh, cup, tup)) ||
        (st = check_vertices(ctx, s, t, cup)))
        goto done;
    t->nshell = 0;
    for (i = 0; i < t->nt; i++)
        t->nshell += find(tup, (int32_t)i) == (int32_t)i;
done:
    cvm__free(ctx, h);
    cvm__free(ctx, cup);
    cvm__free(ctx, tup);
    return st;
}
