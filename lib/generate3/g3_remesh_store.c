/*
 * g3_remesh_store.c - the half-edge store of the surface re-meshing
 * (g3_remesh.c): room, triangles and twins, the turn around a vertex, and the
 * store built from the input with its feature edges.
 */
#include <math.h>
#include <string.h>

#include "generate3/g3_remesh.h"

#define G3R_SHARP_DEG 35.0

cvm_status cvm__g3r_room(g3r_state *R, size_t nv, size_t nt)
{
    /* per-vertex arrays share cap_v, per-half-edge arrays cap_h, per-triangle tsrc cap_t:
     * each group grows through the same sequence of capacities */
    if (nv > R->cap_v) {
        size_t c0 = R->cap_v, c;
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->L, &c, nv, sizeof *R->L))
            return cvm__nomem(R->ctx);
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->vflag, &c, nv, sizeof *R->vflag))
            return cvm__nomem(R->ctx);
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->vpatch, &c, nv, sizeof *R->vpatch))
            return cvm__nomem(R->ctx);
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->vhe, &c, nv, sizeof *R->vhe))
            return cvm__nomem(R->ctx);
        R->cap_v = c;
    }
    if (3 * nv > R->cap_x && cvm__grow(R->ctx, (void **)&R->x, &R->cap_x, 3 * nv, sizeof *R->x))
        return cvm__nomem(R->ctx);
    if (3 * nt > R->cap_h) {
        size_t c0 = R->cap_h, c;
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->tv, &c, 3 * nt, sizeof *R->tv))
            return cvm__nomem(R->ctx);
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->opp, &c, 3 * nt, sizeof *R->opp))
            return cvm__nomem(R->ctx);
        c = c0;
        if (cvm__grow(R->ctx, (void **)&R->feat, &c, 3 * nt, sizeof *R->feat))
            return cvm__nomem(R->ctx);
        R->cap_h = c;
    }
    if (nt > R->cap_t && cvm__grow(R->ctx, (void **)&R->tsrc, &R->cap_t, nt, sizeof *R->tsrc))
        return cvm__nomem(R->ctx);
    return CVM_OK;
}

void cvm__g3r_link(g3r_state *R, int32_t a, int32_t b)
{
    R->opp[a] = b;
    R->opp[b] = a;
}

/* Triangle t = (p0, p1, p2): its half-edges 0, 1, 2 go p1->p2, p2->p0, p0->p1. */
void cvm__g3r_set(g3r_state *R, int32_t t, int32_t p0, int32_t p1, int32_t p2, int32_t src)
{
    R->tv[3 * t] = p0;
    R->tv[3 * t + 1] = p1;
    R->tv[3 * t + 2] = p2;
    R->tsrc[t] = src;
    R->vhe[p0] = 3 * t + 2;
    R->vhe[p1] = 3 * t;
    R->vhe[p2] = 3 * t + 1;
}

void cvm__g3r_setf(g3r_state *R, int32_t h, unsigned char f)
{
    R->feat[h] = f;
    R->feat[R->opp[h]] = f;
}

/* The half-edges leaving v, in turning order, into R->ring (*n). 0 when the
 * ring does not close within the room (a corrupt store: never expected). */
int cvm__g3r_ring(g3r_state *R, int32_t v, size_t *n)
{
    int32_t h0 = R->vhe[v], h = h0;
    size_t k = 0;
    do {
        if (k >= R->cap_ring)
            return 0;
        R->ring[k++] = h;
        /* h leaves v; the previous half-edge of its triangle enters v: its twin leaves v */
        h = R->opp[G3R_PREV(h)];
    } while (h != h0);
    *n = k;
    return 1;
}

cvm_status cvm__g3r_build(g3r_state *R, const cvm__g3_surface *s, const int32_t *key)
{
    size_t nt = s->nt, i, k;
    int64_t *ek;
    int32_t *eh;
    cvm_status st;
    if ((st = cvm__g3r_room(R, s->np + 1, nt + 1)))
        return st;
    memcpy(R->x, s->xyz, 3 * s->np * sizeof *R->x);
    R->nv = s->np;
    R->nt = nt;
    for (i = 0; i < s->np; i++)
        R->vhe[i] = -1;
    for (i = 0; i < nt; i++)
        cvm__g3r_set(R, (int32_t)i, s->tri[3 * i], s->tri[3 * i + 1], s->tri[3 * i + 2], (int32_t)i);
    /* twins: sort the half-edges by (lower, higher) end */
    ek = cvm__malloc(R->ctx, 3 * nt * sizeof *ek);
    eh = cvm__malloc(R->ctx, 3 * nt * sizeof *eh);
    if (!ek || !eh) {
        cvm__free(R->ctx, ek);
        cvm__free(R->ctx, eh);
        return cvm__nomem(R->ctx);
    }
    for (i = 0; i < 3 * nt; i++) {
        int64_t a = g3r_org(R, (int32_t)i), b = g3r_dst(R, (int32_t)i);
        ek[i] = a < b ? (a << 32 | b) : (b << 32 | a);
        eh[i] = (int32_t)i;
        R->opp[i] = -1;
    }
    if (cvm__g3r_sort_pairs(R->ctx, ek, eh, 3 * nt)) {
        cvm__free(R->ctx, ek);
        cvm__free(R->ctx, eh);
        return CVM_E_NOMEM;
    }
    R->ok = 1;
    for (i = 0; i < 3 * nt;) {
        k = i + 1;
        while (k < 3 * nt && ek[k] == ek[i])
            k++;
        if (k - i != 2 || g3r_org(R, eh[i]) != g3r_dst(R, eh[i + 1]))
            R->ok = 0; /* not a closed 2-manifold oriented surface: keep it as given */
        else
            cvm__g3r_link(R, eh[i], eh[i + 1]);
        i = k;
    }
    cvm__free(R->ctx, ek);
    cvm__free(R->ctx, eh);
    if (!R->ok)
        return CVM_OK;
    /* features */
    for (i = 0; i < 3 * nt; i++) {
        int32_t h = (int32_t)i, o = R->opp[h];
        double n1[3], n2[3];
        unsigned char f = 0;
        if (o < h)
            continue;
        g3r_normal(g3r_x(R, R->tv[3 * G3R_T(h)]), g3r_x(R, R->tv[3 * G3R_T(h) + 1]),
                 g3r_x(R, R->tv[3 * G3R_T(h) + 2]), n1);
        g3r_normal(g3r_x(R, R->tv[3 * G3R_T(o)]), g3r_x(R, R->tv[3 * G3R_T(o) + 1]),
                 g3r_x(R, R->tv[3 * G3R_T(o) + 2]), n2);
        if (key && key[G3R_T(h)] != key[G3R_T(o)])
            f = 1;
        else if (g3r_unit(n1) == 0 || g3r_unit(n2) == 0 ||
                 n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] < cos(G3R_SHARP_DEG * 3.14159265358979323846 / 180))
            f = 1;
        R->feat[h] = R->feat[o] = f;
    }
    R->iopp = cvm__malloc(R->ctx, 3 * nt * sizeof *R->iopp);
    R->ifeat = cvm__malloc(R->ctx, 3 * nt);
    if (!R->iopp || !R->ifeat)
        return cvm__nomem(R->ctx);
    memcpy(R->iopp, R->opp, 3 * nt * sizeof *R->iopp);
    memcpy(R->ifeat, R->feat, 3 * nt);
    return CVM_OK;
}

cvm_status cvm__g3r_sort_pairs(cvm__ctx *ctx, int64_t *key, int32_t *val, size_t n)
{
    /* the library's stable radix sort on the key; val is in ascending order within each
     * run of equal keys wherever the callers use this, so ties keep it */
    int32_t *ord = cvm__malloc(ctx, (n ? n : 1) * sizeof *ord);
    int32_t *tmp = cvm__malloc(ctx, (n ? n : 1) * sizeof *tmp);
    uint64_t top = 0;
    size_t i;
    int bits = 0;
    cvm_status s = CVM_OK;
    if (!ord || !tmp) {
        s = cvm__nomem(ctx);
        goto done;
    }
    for (i = 0; i < n; i++)
        top |= (uint64_t)key[i];
    while (bits < 64 && (top >> bits))
        bits++;
    if (cvm__sort_by_key(ctx, (uint64_t *)key, ord, n, bits)) {
        s = cvm__nomem(ctx);
        goto done;
    }
    for (i = 0; i < n; i++)
        tmp[i] = val[ord[i]];
    memcpy(val, tmp, n * sizeof *val);
done:
    cvm__free(ctx, ord);
    cvm__free(ctx, tmp);
    return s;
}

