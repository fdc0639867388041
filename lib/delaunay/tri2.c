/* tri2.c - storage of the 2D triangulation: vertex and triangle arrays, the free list. */
#include <string.h>

#include "delaunay_internal.h"
#include "geom/geom_internal.h"
#include "tri2_store.h"

void cvm__tri2_init(cvm__tri2 *T, cvm__ctx *ctx)
{
    memset(T, 0, sizeof *T);
    T->ctx = ctx;
    T->free_head = -1;
    T->last = -1;
}

void cvm__tri2_destroy(cvm__tri2 *T)
{
    cvm__ctx *ctx = T->ctx;
    cvm__free(ctx, T->xy);
    cvm__free(ctx, T->vtri);
    cvm__free(ctx, T->w);
    cvm__free(ctx, T->tv);
    cvm__free(ctx, T->tn);
    cvm__free(ctx, T->tf);
    cvm__free(ctx, T->te);
    cvm__free(ctx, T->ta);
    cvm__free(ctx, T->stack);
    cvm__free(ctx, T->cav);
    cvm__free(ctx, T->bnd);
    cvm__free(ctx, T->bta);
    cvm__tri2_init(T, ctx);
}

void cvm__tri2_clear(cvm__tri2 *T)
{
    T->nv = 0;
    T->nt = 0;
    T->free_head = -1;
    T->n_dead = 0;
    T->last = -1;
    cvm__free(T->ctx, T->te);
    T->te = NULL;
    cvm__free(T->ctx, T->ta);
    T->ta = NULL;
    cvm__free(T->ctx, T->w);
    T->w = NULL;
}

cvm_status cvm__tri2_reserve_vertices(cvm__tri2 *T, size_t need)
{
    size_t ncap;
    void *p;
    if (need <= T->cap_v)
        return CVM_OK;
    if (need > (size_t)INT32_MAX / 4)
        return CVM_E_TOO_LARGE;
    ncap = T->cap_v < 64 ? 64 : T->cap_v;
    while (ncap < need)
        ncap += ncap / 2;
    p = cvm__realloc(T->ctx, T->xy, 2 * ncap * sizeof(double));
    if (!p)
        return CVM_E_NOMEM;
    T->xy = p;
    p = cvm__realloc(T->ctx, T->vtri, ncap * sizeof(int32_t));
    if (!p)
        return CVM_E_NOMEM;
    T->vtri = p;
    if (T->w) {
        p = cvm__realloc(T->ctx, T->w, ncap * sizeof(double));
        if (!p)
            return CVM_E_NOMEM;
        T->w = p;
    }
    T->cap_v = ncap;
    return CVM_OK;
}

cvm_status cvm__tri2_add_vertex(cvm__tri2 *T, const double *p, int32_t *id_out)
{
    cvm_status s;
    if (T->nv >= T->cap_v) {
        s = cvm__tri2_reserve_vertices(T, T->nv + 1);
        if (s)
            return s;
    }
    T->xy[2 * T->nv] = p[0];
    T->xy[2 * T->nv + 1] = p[1];
    T->vtri[T->nv] = -1;
    if (T->w)
        T->w[T->nv] = 0.0;
    *id_out = (int32_t)T->nv++;
    return CVM_OK;
}

cvm_status cvm__tri2_reserve_triangles(cvm__tri2 *T, size_t need)
{
    size_t ncap, k;
    void *p;
    if (need <= T->cap_t)
        return CVM_OK;
    if (need > (size_t)INT32_MAX / 3)
        return CVM_E_TOO_LARGE;
    ncap = T->cap_t < 64 ? 64 : T->cap_t;
    while (ncap < need)
        ncap += ncap / 2;
    if (ncap > (size_t)INT32_MAX / 3)
        ncap = (size_t)INT32_MAX / 3;
    p = cvm__realloc(T->ctx, T->tv, 3 * ncap * sizeof(int32_t));
    if (!p)
        return CVM_E_NOMEM;
    T->tv = p;
    p = cvm__realloc(T->ctx, T->tn, 3 * ncap * sizeof(int32_t));
    if (!p)
        return CVM_E_NOMEM;
    T->tn = p;
    p = cvm__realloc(T->ctx, T->tf, ncap);
    if (!p)
        return CVM_E_NOMEM;
    T->tf = p;
    if (T->te) {
        p = cvm__realloc(T->ctx, T->te, 3 * ncap * sizeof(int32_t));
        if (!p)
            return CVM_E_NOMEM;
        T->te = p;
        for (k = 3 * T->cap_t; k < 3 * ncap; k++)
            T->te[k] = -1;
    }
    if (T->ta) {
        p = cvm__realloc(T->ctx, T->ta, ncap * sizeof(double));
        if (!p)
            return CVM_E_NOMEM;
        T->ta = p;
        for (k = T->cap_t; k < ncap; k++)
            T->ta[k] = 0.0;
    }
    T->cap_t = ncap;
    return CVM_OK;
}

int32_t cvm__tri2_new(cvm__tri2 *T)
{
    int32_t t;
    if (T->free_head >= 0) {
        t = T->free_head;
        T->free_head = T->tn[3 * (size_t)t];
        T->n_dead--;
    } else {
        t = (int32_t)T->nt++;
    }
    T->tf[t] = 0;
    if (T->te) {
        T->te[3 * (size_t)t] = T->te[3 * (size_t)t + 1] = T->te[3 * (size_t)t + 2] = -1;
    }
    return t;
}

void cvm__tri2_kill(cvm__tri2 *T, int32_t t)
{
    T->tf[t] = CVM__TF_DEAD;
    T->tn[3 * (size_t)t] = T->free_head;
    T->free_head = t;
    T->n_dead++;
}

cvm_status cvm__tri2_enable_constraints(cvm__tri2 *T)
{
    size_t k;
    if (T->te)
        return CVM_OK;
    T->te = cvm__malloc(T->ctx, 3 * (T->cap_t ? T->cap_t : 1) * sizeof(int32_t));
    if (!T->te)
        return CVM_E_NOMEM;
    for (k = 0; k < 3 * T->cap_t; k++)
        T->te[k] = -1;
    return CVM_OK;
}

cvm_status cvm__tri2_enable_attributes(cvm__tri2 *T)
{
    if (T->ta)
        return CVM_OK;
    T->ta = cvm__calloc(T->ctx, T->cap_t ? T->cap_t : 1, sizeof(double));
    return T->ta ? CVM_OK : CVM_E_NOMEM;
}

void cvm__tri2_compact(cvm__tri2 *T, const int32_t *dup_of, int32_t *map_out)
{
    size_t v, n = 0, k;
    for (v = 0; v < T->nv; v++) {
        if (dup_of[v] >= 0) {
            map_out[v] = map_out[dup_of[v]];
            continue;
        }
        map_out[v] = (int32_t)n;
        T->xy[2 * n] = T->xy[2 * v];
        T->xy[2 * n + 1] = T->xy[2 * v + 1];
        T->vtri[n] = T->vtri[v];
        if (T->w)
            T->w[n] = T->w[v];
        n++;
    }
    if (n == T->nv)
        return;
    for (k = 0; k < 3 * T->nt; k++) {
        if (!(T->tf[k / 3] & CVM__TF_DEAD) && T->tv[k] >= 0)
            T->tv[k] = map_out[T->tv[k]];
    }
    T->nv = n;
}

size_t cvm__tri2_star(const cvm__tri2 *T, int32_t v, int32_t *out, size_t cap)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    if (t0 < 0)
        return 0;
    do {
        if (n < cap)
            out[n] = t;
        n++;
        t = cvm__tri2_around(T, t, v);
    } while (t != t0 && n <= T->nt);
    return n;
}

int cvm__tri2_find_edge(const cvm__tri2 *T, int32_t a, int32_t b, int32_t *t_out, int *j_out)
{
    int32_t t0 = T->vtri[a], t = t0;
    size_t steps = 0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == a ? 0 : tv[1] == a ? 1 : 2;
        if (tv[(i + 1) % 3] == b) {
            *t_out = t;
            *j_out = (i + 2) % 3;
            return 1;
        }
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++steps <= T->nt);
    return 0;
}

/* The whole slot table is rebuilt from copies, so slot[] may name the slots
 * in any order. */
cvm_status cvm__tri2_reorder(cvm__tri2 *T, const int32_t *slot, const uint8_t *rotk, size_t nfile)
{
    cvm__ctx *ctx = T->ctx;
    size_t nt = T->nt, t, n = 0, v;
    int32_t *newof = cvm__malloc(ctx, (nt + 1) * sizeof *newof);
    uint8_t *rot = cvm__calloc(ctx, nt + 1, 1);
    int32_t *otv = cvm__malloc(ctx, (3 * nt + 1) * sizeof *otv);
    int32_t *otn = cvm__malloc(ctx, (3 * nt + 1) * sizeof *otn);
    int32_t *ote = T->te ? cvm__malloc(ctx, (3 * nt + 1) * sizeof *ote) : NULL;
    uint8_t *otf = cvm__malloc(ctx, nt + 1);
    double *ota = T->ta ? cvm__malloc(ctx, (nt + 1) * sizeof *ota) : NULL;
    cvm_status s = CVM_OK;
    if (!newof || !rot || !otv || !otn || (T->te && !ote) || !otf || (T->ta && !ota)) {
        s = CVM_E_NOMEM;
        goto out;
    }
    memcpy(otv, T->tv, 3 * nt * sizeof *otv);
    memcpy(otn, T->tn, 3 * nt * sizeof *otn);
    if (ote)
        memcpy(ote, T->te, 3 * nt * sizeof *ote);
    memcpy(otf, T->tf, nt);
    if (ota)
        memcpy(ota, T->ta, nt * sizeof *ota);
    for (t = 0; t < nt; t++)
        newof[t] = -1;
    for (t = 0; t < nfile; t++) {
        newof[slot[t]] = (int32_t)n++;
        rot[slot[t]] = rotk[t];
    }
    for (t = 0; t < nt; t++)
        if (newof[t] < 0 && !(otf[t] & CVM__TF_DEAD))
            newof[t] = (int32_t)n++;
    for (t = 0; t < nt; t++) {
        size_t ns = (size_t)newof[t];
        int j;
        if (newof[t] < 0)
            continue;
        for (j = 0; j < 3; j++) {
            size_t o = 3 * t + (size_t)(j + rot[t]) % 3;
            int32_t a = otn[o];
            T->tv[3 * ns + (size_t)j] = otv[o];
            T->tn[3 * ns + (size_t)j] =
                a < 0 ? a : 3 * newof[a / 3] + (a % 3 - rot[a / 3] + 3) % 3;
            if (ote)
                T->te[3 * ns + (size_t)j] = ote[o];
        }
        T->tf[ns] = otf[t];
        if (ota)
            T->ta[ns] = ota[t];
    }
    for (v = 0; v < T->nv; v++)
        if (T->vtri[v] >= 0)
            T->vtri[v] = newof[T->vtri[v]];
    T->nt = n;
    T->free_head = -1;
    T->n_dead = 0;
    T->last = 0;
out:
    cvm__free(ctx, newof);
    cvm__free(ctx, rot);
    cvm__free(ctx, otv);
    cvm__free(ctx, otn);
    cvm__free(ctx, ote);
    cvm__free(ctx, otf);
    cvm__free(ctx, ota);
    return s;
}

int cvm__tri2_all_ccw(const cvm__tri2 *T)
{
    size_t t;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        if (!cvm__tri2_is_live(T, (int32_t)t) || cvm__tri2_is_ghost(T, (int32_t)t))
            continue;
        if (cvm__orient2d(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1], T->xy + 2 * (size_t)v[2]) <= 0)
            return 0;
    }
    return 1;
}
