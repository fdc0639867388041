/* resample_rebuild.c - the constrained triangulation of a re-discretised boundary: kept edges
 * and new pieces inserted into a fresh triangulation, refused when two edges coincide or a piece
 * cannot be recovered as one edge. */
#include <stdlib.h>
#include <string.h>

#include "resample.h"

/* 1 when a-b is an edge of T. */
static int rs_has_edge(const cvm__tri2 *T, int32_t a, int32_t b)
{
    int32_t t;
    int j;
    return cvm__tri2_find_edge(T, a, b, &t, &j) || cvm__tri2_find_edge(T, b, a, &t, &j);
}

static int cmp_pair(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* 1 when two of the final edges (kept edges, new pieces; ends as new vertex
 * ids) join the same two vertices: two chains cut down to the same chord
 * would collapse the domain between them. */
static cvm_status rs_duplicate_edges(const rs_state *S, const int32_t *newid, size_t nk, int *dup)
{
    size_t n = 0, k;
    int32_t *e = cvm__malloc(S->ctx, (2 * (S->ne + S->npc) + 2) * sizeof *e);
    *dup = 0;
    if (!e)
        return CVM_E_NOMEM;
    for (k = 0; k < S->ne + S->npc; k++) {
        int32_t a, b;
        if (k < S->ne) {
            if (S->replaced[k])
                continue;
            a = newid[S->e[k].a];
            b = newid[S->e[k].b];
        } else {
            a = S->pc[3 * (k - S->ne)];
            b = S->pc[3 * (k - S->ne) + 1];
            a = a >= 0 ? newid[a] : (int32_t)nk + (-2 - a);
            b = b >= 0 ? newid[b] : (int32_t)nk + (-2 - b);
        }
        e[2 * n] = a < b ? a : b;
        e[2 * n + 1] = a < b ? b : a;
        n++;
    }
    qsort(e, n, 2 * sizeof *e, cmp_pair);
    for (k = 1; k < n && !*dup; k++)
        *dup = e[2 * k] == e[2 * k - 2] && e[2 * k + 1] == e[2 * k - 1];
    cvm__free(S->ctx, e);
    return CVM_OK;
}

cvm_status cvm__resample_rebuild(const rs_state *S, cvm__resample_result *R, int *fallback)
{
    cvm__tri2 *T2 = &R->T;
    int32_t *newid = NULL, *dup = NULL;
    size_t v, k, nk = 0, nv2;
    cvm_status s = CVM_OK;
    *fallback = 0;
    newid = cvm__malloc(S->ctx, (S->nv + 1) * sizeof *newid);
    if (!newid)
        return CVM_E_NOMEM;
    for (v = 0; v < S->nv; v++)
        newid[v] = S->removed[v] ? -1 : (int32_t)nk++;
    nv2 = nk + S->nnew;
    {
        int d;
        if ((s = rs_duplicate_edges(S, newid, nk, &d)) || d) {
            *fallback = d;
            cvm__free(S->ctx, newid);
            return s;
        }
    }
    dup = cvm__malloc(S->ctx, (nv2 + 1) * sizeof *dup);
    if (!dup || cvm__tri2_reserve_vertices(T2, nv2)) {
        s = CVM_E_NOMEM;
        goto done;
    }
    for (v = 0; v < S->nv; v++) {
        int32_t id;
        if (newid[v] >= 0 && (s = cvm__tri2_add_vertex(T2, S->T->xy + 2 * v, &id)))
            goto done;
    }
    for (k = 0; k < S->nnew; k++) {
        int32_t id;
        if ((s = cvm__tri2_add_vertex(T2, S->nxy + 2 * k, &id)))
            goto done;
    }
    if ((s = cvm__tri2_build(T2, S->in->seed, dup))) {
        if (s != CVM_E_NOMEM && !cvm_status_is_error(s))
            goto done; /* stopped by the time limit or the callback */
        if (s != CVM_E_NOMEM) {
            *fallback = 1;
            s = CVM_OK;
        }
        goto done;
    }
    for (v = 0; v < nv2; v++)
        if (dup[v] >= 0) {
            *fallback = 1;
            goto done;
        }
    if ((s = cvm__tri2_enable_constraints(T2)))
        goto done;
    for (k = 0; k < S->ne; k++) {
        int32_t other = -1;
        if (S->replaced[k])
            continue;
        s = cvm__tri2_insert_segment(T2, newid[S->e[k].a], newid[S->e[k].b], S->e[k].seg, 0, &other);
        if (s == CVM_E_INPUT_INTERSECTING || (!s && (T2->nv != nv2 ||
                                                     !rs_has_edge(T2, newid[S->e[k].a], newid[S->e[k].b])))) {
            *fallback = 1;
            s = CVM_OK;
            goto done;
        }
        if (s)
            goto done;
    }
    for (k = 0; k < S->npc; k++) {
        int32_t a = S->pc[3 * k], b = S->pc[3 * k + 1], other = -1;
        a = a >= 0 ? newid[a] : (int32_t)nk + (-2 - a);
        b = b >= 0 ? newid[b] : (int32_t)nk + (-2 - b);
        s = cvm__tri2_insert_segment(T2, a, b, S->pc[3 * k + 2], 0, &other);
        if (s == CVM_E_INPUT_INTERSECTING || (!s && (T2->nv != nv2 || !rs_has_edge(T2, a, b)))) {
            *fallback = 1;
            s = CVM_OK;
            goto done;
        }
        if (s)
            goto done;
    }
    R->newid = newid;
    R->nkept = nk;
    newid = NULL;
done:
    cvm__free(S->ctx, newid);
    cvm__free(S->ctx, dup);
    return s;
}
