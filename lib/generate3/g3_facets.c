/*
 * g3_facets.c - the planar facets of a closed surface for g3_surface.c:
 * triangles joined across two-triangle edges when exactly coplanar
 * (orient3d 0) and of equal key, and each facet's boundary loop.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_surface.h"
#include "geom/geom_internal.h"

static int g3f_edge_cmp(const void *pa, const void *pb)
{
    const g3s_edge *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    return (a->hi > b->hi) - (a->hi < b->hi);
}

int32_t cvm__g3s_find_edge(const g3s_state *S, int32_t a, int32_t b)
{
    size_t lo = 0, hi = S->ne;
    g3s_edge key;
    key.lo = a < b ? a : b;
    key.hi = a < b ? b : a;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        int c = g3f_edge_cmp(&key, &S->edge[mid]);
        if (!c)
            return (int32_t)mid;
        if (c < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return -1;
}

static const double *g3f_pt(const g3s_state *S, int32_t i)
{
    return S->s->xyz + 3 * (size_t)i;
}

/* The neighbour of every triangle edge (sorted half-edges). */
typedef struct g3s_half {
    int32_t lo, hi, t, j;
} g3s_half;

static int half_cmp(const void *pa, const void *pb)
{
    const g3s_half *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

cvm_status cvm__g3s_neighbours(g3s_state *S)
{
    const cvm__g3_surface *s = S->s;
    g3s_half *h;
    size_t i, k, n = 3 * s->nt;
    if (!(h = cvm__malloc(S->ctx, n * sizeof *h)))
        return cvm__nomem(S->ctx);
    for (i = 0; i < s->nt; i++)
        for (k = 0; k < 3; k++) {
            int32_t a = s->tri[3 * i + (k + 1) % 3], b = s->tri[3 * i + (k + 2) % 3];
            g3s_half *e = h + 3 * i + k;
            e->lo = a < b ? a : b;
            e->hi = a < b ? b : a;
            e->t = (int32_t)i;
            e->j = (int32_t)k;
        }
    qsort(h, n, sizeof *h, half_cmp);
    for (i = 0; i < n; i++)
        S->nbr[i] = -1;
    for (i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && h[j].lo == h[i].lo && h[j].hi == h[i].hi)
            j++;
        if (j - i == 2) {
            S->nbr[3 * (size_t)h[i].t + (size_t)h[i].j] = h[i + 1].t;
            S->nbr[3 * (size_t)h[i + 1].t + (size_t)h[i + 1].j] = h[i].t;
        }
        i = j;
    }
    cvm__free(S->ctx, h);
    return CVM_OK;
}

void cvm__g3s_frame(const g3s_state *S, int32_t t, g3s_frame *fr)
{
    const int32_t *v = S->s->tri + 3 * (size_t)t;
    const double *a = g3f_pt(S, v[0]), *b = g3f_pt(S, v[1]), *c = g3f_pt(S, v[2]);
    double e[3], f[3];
    int k;
    for (k = 0; k < 3; k++)
        e[k] = b[k] - a[k], f[k] = c[k] - a[k];
    fr->n[0] = e[1] * f[2] - e[2] * f[1];
    fr->n[1] = e[2] * f[0] - e[0] * f[2];
    fr->n[2] = e[0] * f[1] - e[1] * f[0];
    fr->ax = 0;
    for (k = 1; k < 3; k++)
        if (fabs(fr->n[k]) > fabs(fr->n[fr->ax]))
            fr->ax = k;
    fr->u = (fr->ax + 1) % 3;
    fr->v = (fr->ax + 2) % 3;
    fr->a = a;
}

cvm_status cvm__g3s_group(g3s_state *S, const int32_t *key)
{
    const cvm__g3_surface *s = S->s;
    size_t t, nt = s->nt;
    int32_t *stack;
    if (!(stack = cvm__malloc(S->ctx, nt * sizeof *stack)))
        return cvm__nomem(S->ctx);
    for (t = 0; t < nt; t++)
        S->fac[t] = -1;
    S->nf = 0;
    for (t = 0; t < nt; t++) {
        size_t ns = 0, cnt = 0;
        const int32_t *sv = s->tri + 3 * t;
        int32_t f;
        if (S->fac[t] >= 0)
            continue;
        f = (int32_t)S->nf++;
        S->fac[t] = f;
        S->fseed[f] = (int32_t)t;
        stack[ns++] = (int32_t)t;
        while (ns) {
            int32_t u = stack[--ns];
            int j;
            cnt++;
            for (j = 0; j < 3; j++) {
                int32_t w = S->nbr[3 * (size_t)u + (size_t)j];
                const int32_t *wv;
                int k, ok = 1;
                if (w < 0 || S->fac[w] >= 0 || (key && key[w] != key[t]))
                    continue;
                wv = s->tri + 3 * (size_t)w;
                for (k = 0; k < 3 && ok; k++)
                    ok = cvm__orient3d(g3f_pt(S, sv[0]), g3f_pt(S, sv[1]), g3f_pt(S, sv[2]), g3f_pt(S, wv[k])) == 0;
                if (!ok)
                    continue;
                S->fac[w] = f;
                stack[ns++] = w;
            }
        }
        S->fcount[f] = (int32_t)cnt;
    }
    cvm__free(S->ctx, stack);
    return CVM_OK;
}

/* Boundary directed edges of facet f, in loop order, into S->loop (3 t + j:
 * edge j of triangle t, from corner j+1 to j+2); *n their count. 0 when the
 * boundary is not one simple loop (or a triangle of the facet is degenerate
 * in the facet's projection). */
int cvm__g3s_loop(g3s_state *S, int32_t f, const int32_t *members, size_t nm, size_t *n)
{
    const cvm__g3_surface *s = S->s;
    g3s_frame fr;
    size_t i, k, cnt = 0;
    cvm__g3s_frame(S, S->fseed[f], &fr);
    for (i = 0; i < nm; i++) {
        const int32_t *v = s->tri + 3 * (size_t)members[i];
        double a[2], b[2], c[2];
        int j;
        a[0] = g3f_pt(S, v[0])[fr.u], a[1] = g3f_pt(S, v[0])[fr.v];
        b[0] = g3f_pt(S, v[1])[fr.u], b[1] = g3f_pt(S, v[1])[fr.v];
        c[0] = g3f_pt(S, v[2])[fr.u], c[1] = g3f_pt(S, v[2])[fr.v];
        if ((cvm__orient2d(a, b, c) > 0) != (fr.n[fr.ax] > 0) || cvm__orient2d(a, b, c) == 0)
            return 0;
        for (j = 0; j < 3; j++) {
            int32_t w = S->nbr[3 * (size_t)members[i] + (size_t)j];
            if (w >= 0 && S->fac[w] == f)
                continue;
            S->loop[cnt++] = 3 * members[i] + j;
        }
    }
    /* chain: the edge starting where the previous one ends, unique */
    for (i = 0; i + 1 < cnt; i++) {
        int32_t e = S->loop[i], t = e / 3, j = e % 3;
        int32_t end = s->tri[3 * t + (j + 2) % 3];
        size_t found = cnt;
        for (k = i + 1; k < cnt; k++) {
            int32_t e2 = S->loop[k], t2 = e2 / 3, j2 = e2 % 3;
            if (s->tri[3 * t2 + (j2 + 1) % 3] == end) {
                if (found < cnt)
                    return 0; /* the boundary touches itself at a point */
                found = k;
            }
        }
        if (found == cnt)
            return 0; /* more than one loop */
        e = S->loop[i + 1];
        S->loop[i + 1] = S->loop[found];
        S->loop[found] = e;
    }
    {
        int32_t e = S->loop[cnt - 1], t = e / 3, j = e % 3;
        int32_t e0 = S->loop[0];
        if (s->tri[3 * t + (j + 2) % 3] != s->tri[3 * (e0 / 3) + (e0 % 3 + 1) % 3])
            return 0;
    }
    *n = cnt;
    return 1;
}

cvm_status cvm__g3s_members(g3s_state *S, int32_t **start_out, int32_t **items_out)
{
    size_t t, f, nt = S->s->nt;
    int32_t *start = cvm__calloc(S->ctx, S->nf + 1, sizeof *start);
    int32_t *items = cvm__malloc(S->ctx, (nt ? nt : 1) * sizeof *items);
    if (!start || !items) {
        cvm__free(S->ctx, start);
        cvm__free(S->ctx, items);
        return cvm__nomem(S->ctx);
    }
    for (t = 0; t < nt; t++)
        start[S->fac[t] + 1]++;
    for (f = 0; f < S->nf; f++)
        start[f + 1] += start[f];
    for (t = 0; t < nt; t++)
        items[start[S->fac[t]]++] = (int32_t)t;
    for (f = S->nf; f > 0; f--)
        start[f] = start[f - 1];
    start[0] = 0;
    *start_out = start;
    *items_out = items;
    return CVM_OK;
}
