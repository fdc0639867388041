/*
 * d3_merge.c - merged dual cells of a tetrahedral mesh (dual3.h): which
 * adjacent tetrahedra share one polyhedral cell because their dual edge is
 * tiny, the convexity and star check of each group, and the compliance count.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dual3/dual3.h"
#include "geom/geom_internal.h"
#include "geom/measure3.h"

/* A fraction of the mean edge: the length of a dual edge in the BCC lattice
 * relative to the lattice's mean edge, the ideal the tolerance is taken of. */
#define D3_MERGE_IDEAL 0.38

static int d3m_cmp_u64(const void *pa, const void *pb)
{
    uint64_t a = *(const uint64_t *)pa, b = *(const uint64_t *)pb;
    return (a > b) - (a < b);
}

/* lv[v] = the mean length of v's edges, each edge once (0 for a vertex in no
 * tetrahedron); keys: 6 ntet scratch. */
static void d3m_sizes(const cvm__d3_mesh *M, uint64_t *keys, double *lv, double *cnt)
{
    static const int ea[6] = {0, 0, 0, 1, 1, 2}, eb[6] = {1, 2, 3, 2, 3, 3};
    size_t t, i, n = 0;
    int k;
    for (t = 0; t < M->ntet; t++)
        for (k = 0; k < 6; k++) {
            uint64_t a = (uint32_t)M->tet[4 * t + (size_t)ea[k]];
            uint64_t b = (uint32_t)M->tet[4 * t + (size_t)eb[k]];
            keys[n++] = a < b ? a << 32 | b : b << 32 | a;
        }
    qsort(keys, n, sizeof *keys, d3m_cmp_u64);
    memset(lv, 0, M->nv * sizeof *lv);
    memset(cnt, 0, M->nv * sizeof *cnt);
    for (i = 0; i < n; i++) {
        size_t a = (size_t)(keys[i] >> 32), b = (size_t)(keys[i] & 0xffffffffu);
        double len;
        if (i > 0 && keys[i] == keys[i - 1])
            continue;
        len = sqrt(cvm__dist2_3(M->xyz + 3 * a, M->xyz + 3 * b));
        lv[a] += len, lv[b] += len;
        cnt[a] += 1, cnt[b] += 1;
    }
    for (i = 0; i < M->nv; i++)
        lv[i] = cnt[i] > 0 ? lv[i] / cnt[i] : 0;
}

static double d3m_w(const cvm__d3_mesh *M, int32_t v)
{
    return M->w ? M->w[v] : 0.0;
}

/* 1 when face f of t (not constrained, neighbour u across it) is mergeable. */
static int d3m_face_mergeable(const cvm__d3_mesh *M, const double *region, const double *lv,
                              const double *pv, double tol, size_t t, int f)
{
    int32_t s = M->nbr[4 * t + (size_t)f], e, q[4];
    size_t u;
    double l = 0, d;
    int k, j = 0;
    if (s < 0 || M->cface[4 * t + (size_t)f] || !(tol > 0))
        return 0;
    u = (size_t)s >> 2;
    if (region && region[t] != region[u])
        return 0;
    for (k = 0; k < 4; k++)
        q[k] = M->tet[4 * t + (size_t)k];
    e = M->tet[(size_t)s];
    /* coincident power vertices (the exact power test ties): mergeable at any tol > 0 */
    if (cvm__power3d(M->xyz + 3 * (size_t)q[0], M->xyz + 3 * (size_t)q[1],
                     M->xyz + 3 * (size_t)q[2], M->xyz + 3 * (size_t)q[3], M->xyz + 3 * (size_t)e,
                     d3m_w(M, q[0]), d3m_w(M, q[1]), d3m_w(M, q[2]), d3m_w(M, q[3]),
                     d3m_w(M, e)) == 0)
        return 1;
    for (k = 0; k < 4; k++)
        if (k != f) {
            l += lv[q[k]];
            j++;
        }
    l /= j;
    d = sqrt(cvm__dist2_3(pv + 3 * t, pv + 3 * u));
    return d < tol * D3_MERGE_IDEAL * l;
}

static int32_t d3m_find(int32_t *g, int32_t x)
{
    while (g[x] != x) {
        g[x] = g[g[x]];
        x = g[x];
    }
    return x;
}

static int d3m_sgn(double x)
{
    return (x > 0) - (x < 0);
}

/* The convexity and star check of the group of tetrahedra mem[0 .. n - 1] (all
 * with group root r): 1 when it passes and no constrained face lies between two
 * of its tetrahedra (a ring of mergeable faces around such a face could join
 * them). gvert: scratch of 4 n vertex ids; stamp: nv, stamp[v] == r marks v as
 * seen. */
static int d3m_group_ok(const cvm__d3_mesh *M, const int32_t *group, const double *pv,
                        const int32_t *mem, size_t n, int32_t r, int32_t *stamp, int32_t *gvert)
{
    const double *c = pv + 3 * (size_t)r;
    size_t i, nvq = 0, k;
    int f, j;
    if (!(isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2])))
        return 0;
    for (i = 0; i < n; i++)
        for (j = 0; j < 4; j++) {
            int32_t q = M->tet[4 * (size_t)mem[i] + (size_t)j];
            if (stamp[q] != r) {
                stamp[q] = r;
                gvert[nvq++] = q;
            }
        }
    for (i = 0; i < n; i++) {
        size_t t = (size_t)mem[i];
        for (f = 0; f < 4; f++) {
            int32_t s = M->nbr[4 * t + (size_t)f];
            const double *a[3];
            int in, m = 0;
            if (s >= 0 && group[(size_t)s >> 2] == r) {
                /* a constrained face may not lie inside a merged cell */
                if (M->cface[4 * t + (size_t)f])
                    return 0;
                continue;
            }
            for (j = 0; j < 4; j++)
                if (j != f)
                    a[m++] = M->xyz + 3 * (size_t)M->tet[4 * t + (size_t)j];
            in = d3m_sgn(cvm__orient3d(a[0], a[1], a[2], M->xyz + 3 * (size_t)M->tet[4 * t + (size_t)f]));
            /* star: the dual vertex on the inner side or on the plane */
            if (d3m_sgn(cvm__orient3d(a[0], a[1], a[2], c)) == -in)
                return 0;
            for (k = 0; k < nvq; k++)
                if (d3m_sgn(cvm__orient3d(a[0], a[1], a[2], M->xyz + 3 * (size_t)gvert[k])) == -in)
                    return 0;
        }
    }
    return 1;
}

/* Groups of >= 2 tetrahedra: check each, dissolve those that fail. size: ntet
 * (the group size at each root), then scratch off (ntet + 1), mem (ntet), stamp
 * (nv), gvert (4 ntet). */
static void d3m_check_groups(const cvm__d3_mesh *M, int32_t *group, const double *pv,
                             int32_t *size, int32_t *off, int32_t *mem, int32_t *stamp,
                             int32_t *gvert, cvm__d3_merge_report *r)
{
    size_t t, nt = M->ntet;
    for (t = 0; t <= nt; t++)
        off[t] = 0;
    for (t = 0; t < nt; t++)
        off[group[t] + 1]++;
    for (t = 0; t < nt; t++)
        off[t + 1] += off[t];
    for (t = 0; t < nt; t++)
        mem[off[group[t]] + size[group[t]]++] = (int32_t)t; /* size counts while filling */
    for (t = 0; t < M->nv; t++)
        stamp[t] = -1;
    for (t = 0; t < nt; t++) {
        int32_t n = size[t], i;
        if (group[t] != (int32_t)t || n < 2)
            continue;
        if (d3m_group_ok(M, group, pv, mem + off[t], (size_t)n, (int32_t)t, stamp, gvert)) {
            r->ngroups++;
            r->nmerged += (size_t)n;
            continue;
        }
        r->ndissolved++;
        for (i = 0; i < n; i++) {
            int32_t u = mem[off[t] + i];
            group[u] = u;
        }
        size[t] = 1;
    }
}

/* Exact compliance of every tetrahedron into r. */
static void d3m_count(const cvm__d3_mesh *M, const int32_t *group, const int32_t *size,
                      const uint8_t *mf, cvm__d3_merge_report *r)
{
    size_t t;
    for (t = 0; t < M->ntet; t++) {
        const double *P[4];
        double W[4];
        int s[4], k, bnd = 0, out = 0, nc = 0;
        int kept = size[group[t]] >= 2;
        for (k = 0; k < 4; k++) {
            int32_t q = M->tet[4 * t + (size_t)k];
            P[k] = M->xyz + 3 * (size_t)q;
            W[k] = d3m_w(M, q);
            bnd |= M->nbr[4 * t + (size_t)k] < 0;
        }
        if (cvm__tet_centre_side(P[0], P[1], P[2], P[3], M->w ? W : NULL, s) != 0)
            s[0] = s[1] = s[2] = s[3] = -1; /* flat: never compliant */
        for (k = 0; k < 4; k++)
            if (s[k] < 0) {
                out = 1;
                /* beyond face k: compliant only when it is mergeable inside a kept group */
                if (!kept || !mf[4 * t + (size_t)k])
                    nc = 1;
            }
        r->nbnd += (size_t)bnd;
        r->nout += (size_t)out;
        r->nbout += (size_t)(out && bnd);
        r->nnc += (size_t)nc;
        r->nbnc += (size_t)(nc && bnd);
    }
}

cvm_status cvm__d3_merge(cvm__ctx *ctx, const cvm__d3_mesh *M, const double *region, double tol,
                         int32_t *group, cvm__d3_merge_report *r)
{
    size_t nt = M->ntet, nv = M->nv, t;
    double *pv = cvm__malloc(ctx, (3 * nt + 2 * nv + 1) * sizeof *pv);
    uint64_t *keys = cvm__malloc(ctx, (6 * nt + 1) * sizeof *keys);
    uint8_t *mf = cvm__calloc(ctx, 4 * nt + 1, 1);
    int32_t *iw = cvm__malloc(ctx, (7 * nt + nv + 1) * sizeof *iw);
    int f;
    memset(r, 0, sizeof *r);
    r->ntet = nt;
    if (!pv || !keys || !mf || !iw) {
        cvm__free(ctx, pv);
        cvm__free(ctx, keys);
        cvm__free(ctx, mf);
        cvm__free(ctx, iw);
        return cvm__nomem(ctx);
    }
    d3m_sizes(M, keys, pv + 3 * nt, pv + 3 * nt + nv);
    cvm__free(ctx, keys);
    for (t = 0; t < nt; t++) {
        const int32_t *q = M->tet + 4 * t;
        double W[4];
        for (f = 0; f < 4; f++)
            W[f] = d3m_w(M, q[f]);
        if (cvm__tet_power_centre(M->xyz + 3 * (size_t)q[0], M->xyz + 3 * (size_t)q[1],
                                  M->xyz + 3 * (size_t)q[2], M->xyz + 3 * (size_t)q[3], W,
                                  pv + 3 * t))
            pv[3 * t] = pv[3 * t + 1] = pv[3 * t + 2] = NAN;
    }
    /* each shared face decided once, from its tetrahedron of smaller slot */
    for (t = 0; t < nt; t++)
        for (f = 0; f < 4; f++) {
            int32_t s = M->nbr[4 * t + (size_t)f];
            if (s < 0 || (size_t)s < 4 * t + (size_t)f)
                continue;
            if (d3m_face_mergeable(M, region, pv + 3 * nt, pv, tol, t, f))
                mf[4 * t + (size_t)f] = mf[s] = 1;
        }
    for (t = 0; t < nt; t++)
        group[t] = (int32_t)t;
    for (t = 0; t < 4 * nt; t++)
        if (mf[t]) {
            int32_t a = d3m_find(group, (int32_t)(t / 4)), b = d3m_find(group, M->nbr[t] >> 2);
            /* the smaller root wins, so a root is its group's smallest tetrahedron */
            if (a < b)
                group[b] = a;
            else if (b < a)
                group[a] = b;
        }
    for (t = 0; t < nt; t++) {
        group[t] = d3m_find(group, (int32_t)t);
        iw[t] = 0;
    }
    d3m_check_groups(M, group, pv, iw, iw + nt, iw + 2 * nt + 1, iw + 3 * nt + 1,
                     iw + 3 * nt + 1 + nv, r);
    d3m_count(M, group, iw, mf, r);
    cvm__free(ctx, pv);
    cvm__free(ctx, mf);
    cvm__free(ctx, iw);
    return CVM_OK;
}
