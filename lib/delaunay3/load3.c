/* load3.c - an existing tetrahedral mesh into the store, for point insertion (cvm__tet3_insert_point()). */
#include <string.h>

#include "delaunay3/delaunay3_internal.h"

/* The corners of face f of a tetrahedron, as the boundary of a positively
 * oriented one lists them (tet3_store.c): a ghost on this face has them in
 * this order. */
static const int8_t face_pos[4][3] = { { 1, 2, 3 }, { 2, 0, 3 }, { 0, 1, 3 }, { 1, 0, 2 } };

cvm_status cvm__tet3_load(cvm__tet3 *T, const double *xyz, const double *w, size_t nv, size_t cap,
                          const int32_t *tet, size_t ntet, const int32_t *nbr, const uint8_t *cons,
                          const double *attr)
{
    cvm__ctx *ctx = T->ctx;
    size_t i, nb = 0;
    cvm_status s;
    cvm__tet3_free(T);
    if (cap < nv || cap > (size_t)INT32_MAX || ntet == 0)
        return CVM_E_NOMEM;
    T->np = nv;
    cvm__tet3_alloc_points(T, cap);
    T->orig = cvm__malloc(ctx, cap * sizeof *T->orig);
    T->merged = cvm__malloc(ctx, cap * sizeof *T->merged);
    T->outid = cvm__malloc(ctx, cap * sizeof *T->outid);
    T->fate = cvm__calloc(ctx, cap, 1);
    T->etab = cvm__calloc(ctx, CVM__T3_ETAB * CVM__T3_ETAB, sizeof *T->etab);
    if (!T->pt || !T->orig || !T->merged || !T->outid || !T->fate || !T->etab)
        return CVM_E_NOMEM;
    if (w) {
        T->w = cvm__malloc(ctx, cap * sizeof *T->w);
        T->vseen = cvm__calloc(ctx, cap, sizeof *T->vseen);
        T->vkeep = cvm__calloc(ctx, cap, sizeof *T->vkeep);
        if (!T->w || !T->vseen || !T->vkeep)
            return CVM_E_NOMEM;
        memcpy(T->w, w, nv * sizeof *w);
    }
    if (cons && !(T->cface = cvm__calloc(ctx, 1, 1)))
        return CVM_E_NOMEM;
    if (attr && !(T->sattr = cvm__calloc(ctx, 1, sizeof *T->sattr)))
        return CVM_E_NOMEM;
    for (i = 0; i < nv; i++) {
        memcpy(T->pt[i].x, xyz + 3 * i, 3 * sizeof *xyz);
        T->orig[i] = T->outid[i] = (int32_t)i;
        T->merged[i] = -1;
        T->fate[i] = CVM__T3_VERTEX;
    }
    for (i = 0; i < 4 * ntet; i++)
        nb += nbr[i] < 0;
    /* the coordinates are not known to be small integers once points come in */
    T->small_int = 0;
    if ((s = cvm__tet3_reserve(T, ntet + nb)) != CVM_OK
        || (s = cvm__grow(ctx, (void **)&T->bf, &T->bfcap, nb ? nb : 1, sizeof *T->bf)) != CVM_OK
        || (s = cvm__tet3_reserve_hash(T, nb ? nb : 1)) != CVM_OK)
        return s;
    for (i = 0; i < ntet; i++) {
        int32_t t = cvm__tet3_take_slot(T); /* = i: the store is empty */
        int f;
        memcpy(T->tt + 8 * (size_t)t, tet + 4 * i, 4 * sizeof *tet);
        if (T->cface)
            T->cface[t] = 0;
        if (T->sattr)
            T->sattr[t] = attr[i];
        for (f = 0; f < 4; f++) {
            CVM__T3_TN(T, 4 * (size_t)t + f) = nbr[4 * i + f];
            if (cons && (cons[4 * i + f] || nbr[4 * i + f] < 0))
                T->cface[t] |= (uint8_t)(1u << f);
        }
    }
    T->nbf = 0;
    for (i = 0; i < 4 * ntet; i++) {
        cvm__t3_bface *b;
        int32_t g, *gv, k;
        const int32_t *tv = tet + 4 * (i / 4);
        if (nbr[i] >= 0)
            continue;
        g = cvm__tet3_take_slot(T);
        gv = T->tt + 8 * (size_t)g;
        for (k = 0; k < 3; k++)
            gv[k] = tv[face_pos[i % 4][k]];
        gv[3] = CVM__T3_GHOST;
        CVM__T3_TN(T, 4 * (size_t)g + 3) = (int32_t)i;
        CVM__T3_TN(T, i) = 4 * g + 3;
        if (T->sattr)
            T->sattr[g] = 0.0;
        if (T->cface) { /* never crossed: its other faces need no neighbours */
            T->cface[g] = 15;
            for (k = 0; k < 3; k++)
                CVM__T3_TN(T, 4 * (size_t)g + k) = 4 * g + k;
            continue;
        }
        b = &T->bf[T->nbf++];
        memcpy(b->v, gv, 4 * sizeof *gv);
        b->f = 3;
        b->tet = g;
    }
    if (T->nbf)
        cvm__tet3_link_around(T);
    T->nbf = 0;
    T->last = 0;
    T->walk = UINT64_C(0x9E3779B97F4A7C15);
    return CVM_OK;
}

size_t cvm__tet3_count_finite(const cvm__tet3 *T)
{
    size_t i, n = 0;
    for (i = 0; i < T->nslot; i++)
        n += T->tt[8 * i] != CVM__T3_DEAD && T->tt[8 * i + 3] != CVM__T3_GHOST;
    return n;
}

void cvm__tet3_export(const cvm__tet3 *T, size_t nv_old, const int32_t *fin, int32_t *tet,
                      double *attr, double *xyz, double *w)
{
    size_t i, nt = 0;
    int k;
    for (i = 0; i < T->nslot; i++) {
        const int32_t *v = T->tt + 8 * i;
        if (v[0] == CVM__T3_DEAD || v[3] == CVM__T3_GHOST)
            continue;
        for (k = 0; k < 4; k++)
            tet[4 * nt + k] = (size_t)v[k] < nv_old ? v[k] : fin[(size_t)v[k] - nv_old];
        cvm__tet3_canonical_turn(tet + 4 * nt);
        if (attr)
            attr[nt] = T->sattr ? T->sattr[i] : 0.0;
        nt++;
    }
    for (i = 0; i < T->np; i++) {
        size_t to = i < nv_old ? i : (size_t)fin[i - nv_old];
        memcpy(xyz + 3 * to, T->pt[i].x, 3 * sizeof *xyz);
        if (w && T->w)
            w[to] = T->w[i];
    }
}
