/*
 * g3_recover.c - without TetGen the kernel recovers a surface only when every
 * surface triangle is a face of the Delaunay tetrahedralisation of all the
 * points. A triangle ABC (circumcentre c, radius R, inward normal n) is such
 * a face when some sphere of its pencil, centre c + t n and radius
 * sqrt(R^2 + t^2), holds no other point. A point p with (p - c).n < 0 (outer
 * side) lies in that sphere for t below tau(p) = (|p - c|^2 - R^2) / (2 (p -
 * c).n), so the surface's own points beyond ABC bound t from below by L, the
 * largest such tau. For each missing triangle the generated points inside the
 * sphere of parameter max(L, 0) + 0.05 R 2^round are dropped, and the
 * tetrahedralisation is rebuilt, for at most MAX_ROUNDS rounds.
 *
 * Which points to drop is a placement choice (plain doubles); whether a
 * triangle is a face is decided by the exact kernel (lib/delaunay3).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_internal.h"
#include "generate3/generate3.h"
#include "geom/measure3.h"

#define MAX_ROUNDS 8

typedef struct g3_face_key {
    int32_t v[3];
} g3_face_key;

static int cmp_key(const void *pa, const void *pb)
{
    const g3_face_key *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return 0;
}

static void sort3(const int32_t *in, g3_face_key *out)
{
    int32_t a = in[0], b = in[1], c = in[2], t;
    if (a > b) { t = a; a = b; b = t; }
    if (b > c) { t = b; b = c; c = t; }
    if (a > b) { t = a; a = b; b = t; }
    out->v[0] = a;
    out->v[1] = b;
    out->v[2] = c;
}

/* The missing triangles' indices into s->tri, in order, in *miss (count *nmiss). */
static cvm_status find_missing(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_points *P,
                               uint64_t seed, size_t *miss, size_t *nmiss)
{
    cvm__tet3 T;
    int32_t *tet = NULL;
    g3_face_key *keys = NULL;
    size_t t, f, nk;
    cvm_status st;
    *nmiss = 0;
    cvm__tet3_init(&T, ctx);
    if ((st = cvm__tet3_build(&T, P->xyz, NULL, P->n, seed)))
        goto done;
    tet = cvm__malloc(ctx, (4 * T.n_finite + 1) * sizeof *tet);
    keys = cvm__malloc(ctx, (4 * T.n_finite + 1) * sizeof *keys);
    if (!tet || !keys) {
        st = cvm__nomem(ctx);
        goto done;
    }
    if ((st = cvm__tet3_copy_tets(&T, tet)))
        goto done;
    nk = 4 * T.n_finite;
    for (t = 0; t < T.n_finite; t++) {
        int j;
        for (j = 0; j < 4; j++) {
            int32_t v[3];
            int q, n = 0;
            for (q = 0; q < 4; q++)
                if (q != j)
                    v[n++] = tet[4 * t + q];
            sort3(v, keys + 4 * t + j);
        }
    }
    qsort(keys, nk, sizeof *keys, cmp_key);
    for (f = 0; f < s->nt; f++) {
        g3_face_key k;
        sort3(s->tri + 3 * f, &k);
        if (!bsearch(&k, keys, nk, sizeof *keys, cmp_key))
            miss[(*nmiss)++] = f;
    }
done:
    cvm__free(ctx, tet);
    cvm__free(ctx, keys);
    cvm__tet3_free(&T);
    return st;
}

/* Mark in drop[] the generated points inside the pencil sphere chosen for triangle f. */
static void mark_blockers(const cvm__g3_surface *s, const cvm__g3_points *P, size_t f, int round,
                          uint8_t *drop)
{
    const int32_t *t = s->tri + 3 * f;
    const double *a = s->xyz + 3 * t[0], *b = s->xyz + 3 * t[1], *c = s->xyz + 3 * t[2];
    double cc[3], n[3], R2, L = 0, ctr[3], r2;
    size_t i;
    int k;
    cvm__tri3_circle(a, b, c, cc, &R2, n);
    for (i = 0; i < s->np; i++) {
        const double *p = s->xyz + 3 * i;
        double d2 = 0, dn = 0;
        if ((int32_t)i == t[0] || (int32_t)i == t[1] || (int32_t)i == t[2])
            continue;
        for (k = 0; k < 3; k++) {
            d2 += (p[k] - cc[k]) * (p[k] - cc[k]);
            dn += (p[k] - cc[k]) * n[k];
        }
        if (dn < 0 && (d2 - R2) / (2 * dn) > L)
            L = (d2 - R2) / (2 * dn);
    }
    L += 0.05 * sqrt(R2) * ldexp(1.0, round);
    for (k = 0; k < 3; k++)
        ctr[k] = cc[k] + L * n[k];
    r2 = R2 + L * L;
    for (i = s->np; i < P->n; i++) {
        const double *p = P->xyz + 3 * i;
        double d2 = 0;
        for (k = 0; k < 3; k++)
            d2 += (p[k] - ctr[k]) * (p[k] - ctr[k]);
        if (d2 < r2)
            drop[i] = 1;
    }
}

cvm_status cvm__g3_recover(cvm__ctx *ctx, const cvm__g3_surface *s, cvm__g3_points *P,
                           uint64_t seed, cvm__g3_report *rep, int64_t *bad_face)
{
    size_t *miss = cvm__malloc(ctx, (s->nt + 1) * sizeof *miss), nmiss = 0, i, j;
    uint8_t *drop = NULL;
    int round;
    cvm_status st = CVM_OK;
    *bad_face = -1;
    if (!miss)
        return cvm__nomem(ctx);
    for (round = 0; round <= MAX_ROUNDS; round++) {
        if ((st = find_missing(ctx, s, P, seed, miss, &nmiss)) || nmiss == 0)
            break;
        if (round == MAX_ROUNDS || P->n == s->np) {
            *bad_face = (int64_t)miss[0];
            st = CVM_E_UNSUPPORTED;
            break;
        }
        if (!(drop = cvm__calloc(ctx, P->n, 1))) {
            st = cvm__nomem(ctx);
            break;
        }
        for (i = 0; i < nmiss; i++)
            mark_blockers(s, P, miss[i], round, drop);
        for (i = j = s->np; i < P->n; i++) {
            if (drop[i]) {
                rep->recovery_dropped++;
                continue;
            }
            memmove(P->xyz + 3 * j, P->xyz + 3 * i, 3 * sizeof *P->xyz);
            P->dm[j] = P->dm[i];
            j++;
        }
        P->n = j;
        cvm__free(ctx, drop);
        drop = NULL;
    }
    cvm__free(ctx, miss);
    return st;
}
