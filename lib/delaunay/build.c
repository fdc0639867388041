/* build.c - Delaunay triangulation of a whole point set by randomised incremental insertion. */
#include "delaunay_internal.h"
#include "tri2_store.h"
#include "spatial_sort.h"
#include "geom/geom_internal.h"

static int same_point(const cvm__tri2 *T, int32_t a, int32_t b)
{
    const double *pa = cvm__tri2_pt(T, a), *pb = cvm__tri2_pt(T, b);
    return pa[0] == pb[0] && pa[1] == pb[1];
}

/* The first triangle (v0, v1, v2), counter-clockwise, closed by three ghosts. */
static void make_first(cvm__tri2 *T, int32_t v0, int32_t v1, int32_t v2)
{
    int32_t t = cvm__tri2_new(T), g[3];
    const int32_t v[3] = {v0, v1, v2};
    int j;
    T->tv[0 + 3 * (size_t)t] = v0;
    T->tv[1 + 3 * (size_t)t] = v1;
    T->tv[2 + 3 * (size_t)t] = v2;
    for (j = 0; j < 3; j++) {
        g[j] = cvm__tri2_new(T);
        T->tv[3 * (size_t)g[j]] = v[(j + 2) % 3];
        T->tv[3 * (size_t)g[j] + 1] = v[(j + 1) % 3];
        T->tv[3 * (size_t)g[j] + 2] = CVM__GHOST;
        cvm__tri2_link(T, t, j, g[j], 2);
    }
    /* ghost g_j = (b, a, G): its edge (a, G) meets the ghost whose first vertex is a */
    cvm__tri2_link(T, g[0], 0, g[2], 1);
    cvm__tri2_link(T, g[1], 0, g[0], 1);
    cvm__tri2_link(T, g[2], 0, g[1], 1);
    T->vtri[v0] = T->vtri[v1] = T->vtri[v2] = t;
    T->last = t;
}

/* Make the lowest index of each group of duplicates the vertex that is kept. */
static cvm_status prefer_lowest(cvm__tri2 *T, int32_t *dup_of)
{
    size_t n = T->nv, v, k;
    int32_t *ren;
    int any = 0;
    for (v = 0; v < n; v++)
        if (dup_of[v] >= 0 && (int32_t)v < dup_of[v])
            any = 1;
    if (!any)
        return CVM_OK;
    ren = cvm__malloc(T->ctx, n * sizeof *ren);
    if (!ren)
        return CVM_E_NOMEM;
    for (v = 0; v < n; v++)
        ren[v] = (int32_t)v;
    for (v = 0; v < n; v++) {
        int32_t k0 = dup_of[v];
        if (k0 >= 0 && (int32_t)v < ren[k0])
            ren[k0] = (int32_t)v;
    }
    for (v = 0; v < n; v++) {
        if (dup_of[v] < 0 && ren[v] != (int32_t)v) {
            T->vtri[ren[v]] = T->vtri[v];
            T->vtri[v] = -1;
        }
    }
    for (v = 0; v < n; v++)
        if (dup_of[v] >= 0)
            dup_of[v] = ren[dup_of[v]];
    for (v = 0; v < n; v++)
        if (dup_of[v] < 0 && ren[v] != (int32_t)v) {
            dup_of[ren[v]] = -1;
            dup_of[v] = ren[v];
        }
    for (k = 0; k < 3 * T->nt; k++)
        if (!(T->tf[k / 3] & CVM__TF_DEAD) && T->tv[k] >= 0)
            T->tv[k] = ren[T->tv[k]];
    cvm__free(T->ctx, ren);
    return CVM_OK;
}

static void drop_triangles(cvm__tri2 *T)
{
    size_t v;
    T->nt = 0;
    T->free_head = -1;
    T->n_dead = 0;
    T->last = -1;
    for (v = 0; v < T->nv; v++)
        T->vtri[v] = -1;
}

/* The first triangle from order[0] and the next two points that make one, then every other
 * point in order; duplicates into dup_of. CVM_OK, a degenerate-input error (message set), or the
 * insertion's and the run control's statuses (no message). */
static cvm_status insert_in_order(cvm__tri2 *T, const int32_t *order, int32_t *dup_of)
{
    size_t n = T->nv, i, i1 = 0, i2 = 0;
    double o = 0;
    cvm_status s;
    for (i1 = 1; i1 < n && same_point(T, order[0], order[i1]); i1++)
        ;
    for (i2 = i1 + 1; i2 < n; i2++) {
        o = cvm__orient2d(cvm__tri2_pt(T, order[0]), cvm__tri2_pt(T, order[i1]),
                          cvm__tri2_pt(T, order[i2]));
        if (o != 0)
            break;
    }
    if (i1 >= n)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, 0,
                          "all %lu points coincide", (unsigned long)n);
    if (i2 >= n)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, -1,
                          "all %lu points are collinear", (unsigned long)n);
    if (o > 0)
        make_first(T, order[0], order[i1], order[i2]);
    else
        make_first(T, order[0], order[i2], order[i1]);
    for (i = 1; i < n; i++) {
        cvm__ins res;
        int32_t other;
        int32_t v = order[i];
        if (i == i1 || i == i2)
            continue;
        s = cvm__tri2_insert_vertex(T, v, T->last, 0, 0.0, &res, &other);
        if (s)
            return s;
        if (res == CVM__INS_DUPLICATE)
            dup_of[v] = other;
        s = cvm__tick(T->ctx, 1, CVM_STAGE_INSERT, (double)i / (double)n);
        if (s)
            return s;
    }
    return CVM_OK;
}

/* Exact duplicates: the first of a group to be inserted became its vertex and its index decided
 * every perturbed test, so the result could depend on the order (the seed). Swap in the order
 * each group's lowest index into the place of the vertex inserted first; 1 when any moved.
 * pos: n entries of scratch. */
static int lowest_first(const cvm__tri2 *T, int32_t *order, const int32_t *dup_of, int32_t *pos)
{
    size_t n = T->nv, i;
    int any = 0;
    for (i = 0; i < n; i++)
        pos[order[i]] = (int32_t)i;
    for (i = 0; i < n; i++) {
        int32_t g = dup_of[i];
        if (g >= 0 && (int32_t)i < g) { /* i is lower than its vertex: i takes g's place */
            int32_t pi = pos[i], pg = pos[g];
            order[pg] = (int32_t)i;
            order[pi] = g;
            pos[i] = pg;
            pos[g] = pi;
            any = 1;
        }
    }
    return any;
}

cvm_status cvm__tri2_build(cvm__tri2 *T, uint64_t seed, int32_t *dup_of)
{
    size_t n = T->nv, i;
    int32_t *order;
    cvm_status s;

    drop_triangles(T);
    for (i = 0; i < n; i++)
        dup_of[i] = -1;
    if (n < 3)
        return cvm__error(T->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, -1,
                          "need at least 3 points, got %lu", (unsigned long)n);
    order = cvm__malloc(T->ctx, 2 * n * sizeof *order);
    if (!order)
        return cvm__nomem(T->ctx);
    s = cvm__brio_order(T->ctx, T->xy, n, seed, order);
    if (s)
        goto fail;
    s = cvm__tri2_reserve_triangles(T, 2 * n + 8);
    if (s)
        goto fail;
    s = insert_in_order(T, order, dup_of);
    if (s == CVM_E_INPUT_DEGENERATE) {
        cvm__free(T->ctx, order);
        drop_triangles(T);
        return s;
    }
    if (s)
        goto fail;
    /* dup_of names the vertex each duplicate met, which is the first of its group; ties of a
     * group with a lower index: again in the order with the lowest first */
    if (lowest_first(T, order, dup_of, order + n)) {
        drop_triangles(T);
        for (i = 0; i < n; i++)
            dup_of[i] = -1;
        s = insert_in_order(T, order, dup_of);
        if (s)
            goto fail;
    }
    cvm__free(T->ctx, order);
    s = prefer_lowest(T, dup_of);
    if (s) {
        drop_triangles(T);
        return cvm__nomem(T->ctx);
    }
    return CVM_OK;
fail:
    cvm__free(T->ctx, order);
    drop_triangles(T);
    if (s == CVM_E_NOMEM)
        return cvm__nomem(T->ctx);
    if (s == CVM_INCOMPLETE_CANCELLED)
        return cvm__error(T->ctx, s, CVM_ENT_NONE, -1,
                          "triangulation cancelled by the progress callback; the mesh is empty");
    if (s == CVM_INCOMPLETE_TIME_LIMIT)
        return cvm__error(T->ctx, s, CVM_ENT_NONE, -1,
                          "time limit reached during triangulation; the mesh is empty");
    return cvm__error(T->ctx, s, CVM_ENT_NONE, -1, "triangulation failed: %s", cvm_status_str(s));
}
