/*
 * mesh3_insert.c - cvm_mesh_insert_points_nd() on a 3D handle: the mesh goes
 * into the tetrahedral store of lib/delaunay3 (cvm__tet3_load()), each point
 * is inserted by a Bowyer-Watson cavity that never crosses a constrained face
 * (cvm__tet3_insert_point()), and the result comes back in canonical order.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api/mesh3_internal.h"

/* A tetrahedron of the result with its region attribute, for the sort. */
typedef struct cvm__ins3_tet {
    int32_t v[4];
    double attr;
} cvm__ins3_tet;

static int cmp_ins3_tet(const void *pa, const void *pb)
{
    const cvm__ins3_tet *a = pa, *b = pb;
    int k;
    for (k = 0; k < 4; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return 0;
}

/* Nonzero coordinates within 2^-100 of the largest magnitude (the range of
 * the exact predicates, as cvm_mesh_triangulate() demands). */
static cvm_status check_points(cvm_mesh *m, const double *xyz, size_t count)
{
    const cvm__mesh3 *g = m->m3;
    double big = 0.0;
    size_t i;
    for (i = 0; i < 3 * count; i++)
        if (!isfinite(xyz[i]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_INPUT_POINT, (int64_t)(i / 3),
                              "point %lu has a non-finite %c", (unsigned long)(i / 3),
                              "xyz"[i % 3]);
    for (i = 0; i < 3 * g->nv; i++)
        big = fabs(g->xyz[i]) > big ? fabs(g->xyz[i]) : big;
    for (i = 0; i < 3 * count; i++)
        big = fabs(xyz[i]) > big ? fabs(xyz[i]) : big;
    for (i = 0; i < 3 * count; i++)
        if (xyz[i] != 0.0 && fabs(xyz[i]) < ldexp(big, -100))
            return cvm__error(&m->ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)(i / 3),
                              "point %lu has a coordinate of magnitude %g, more than 2^100 below the "
                              "largest magnitude %g: outside the range of exact arithmetic",
                              (unsigned long)(i / 3), fabs(xyz[i]), big);
    return CVM_OK;
}

/* 4 flags per tetrahedron: the listed faces (boundary and internal facets). */
static cvm_status constrained_faces(cvm_mesh *m, const int32_t *nbr, uint8_t **out)
{
    cvm__mesh3 *g = m->m3;
    cvm__face_key *index = NULL;
    uint8_t *cons;
    size_t i;
    cvm_status s;
    *out = NULL;
    if (!(cons = cvm__calloc(&m->ctx, 4 * g->ntet, 1)))
        return cvm__nomem(&m->ctx);
    if ((s = cvm__mesh3_face_index(&m->ctx, g->tet, g->ntet, &index))) {
        cvm__free(&m->ctx, cons);
        return s;
    }
    for (i = 0; i < g->nface; i++) {
        int32_t slot = cvm__mesh3_find_face(index, 4 * g->ntet, g->face[3 * i], g->face[3 * i + 1],
                                            g->face[3 * i + 2]);
        if (slot < 0) {
            s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_FACET, (int64_t)i,
                           "boundary face %lu is not a face of the mesh", (unsigned long)i);
            break;
        }
        cons[slot] = 1;
        if (nbr[slot] >= 0)
            cons[nbr[slot]] = 1;
    }
    cvm__free(&m->ctx, index);
    if (s)
        cvm__free(&m->ctx, cons);
    else
        *out = cons;
    return s;
}

/* The store's mesh back into g: its vertices nv .. np - 1 become vertices
 * fin[v - nv] (weight 0); the tetrahedra are turned and sorted as
 * cvm_mesh_triangulate() orders them, with their attributes; an unconstrained
 * mesh gets its hull faces again. All or nothing: CVM_OK, or CVM_E_NOMEM
 * (or CVM_E_INTERNAL) with g unchanged. */
static cvm_status write_back(cvm_mesh *m, const cvm__tet3 *store, size_t np, const int32_t *fin)
{
    cvm__mesh3 *g = m->m3;
    cvm__ins3_tet *rec = NULL;
    double *xyz = NULL, *w = NULL, *tattr = NULL, *attr = NULL;
    int32_t *tet = NULL, *nbr = NULL, *face = NULL;
    size_t i, nt = cvm__tet3_count_finite(store), nface = 0;
    cvm_status s = CVM_E_NOMEM;
    rec = cvm__malloc(&m->ctx, nt * sizeof *rec);
    tet = cvm__malloc(&m->ctx, 4 * nt * sizeof *tet);
    xyz = cvm__malloc(&m->ctx, 3 * np * sizeof *xyz);
    if (g->w)
        w = cvm__malloc(&m->ctx, np * sizeof *w);
    if (g->tattr) {
        tattr = cvm__malloc(&m->ctx, nt * sizeof *tattr);
        attr = cvm__malloc(&m->ctx, nt * sizeof *attr);
    }
    if (!rec || !tet || !xyz || (g->w && !w) || (g->tattr && (!tattr || !attr)))
        goto done;
    cvm__tet3_export(store, g->nv, fin, tet, attr, xyz, w);
    for (i = 0; i < nt; i++) {
        memcpy(rec[i].v, tet + 4 * i, sizeof rec[i].v);
        rec[i].attr = attr ? attr[i] : 0.0;
    }
    qsort(rec, nt, sizeof *rec, cmp_ins3_tet);
    for (i = 0; i < nt; i++) {
        memcpy(tet + 4 * i, rec[i].v, 4 * sizeof *tet);
        if (tattr)
            tattr[i] = rec[i].attr;
    }
    if (g->delaunay) { /* the hull may have grown by points on it: its faces again */
        if ((s = cvm__mesh3_adjacency(&m->ctx, tet, nt, &nbr)) != CVM_OK) {
            if (s != CVM_E_NOMEM)
                s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "insertion: %s",
                               cvm_mesh_errmsg(m));
            goto done_set;
        }
        for (i = 0; i < 4 * nt; i++)
            nface += nbr[i] < 0;
        if (!(face = cvm__malloc(&m->ctx, (nface ? 3 * nface : 1) * sizeof *face)))
            goto done;
        for (i = 0, nface = 0; i < 4 * nt; i++)
            if (nbr[i] < 0)
                cvm__mesh3_face_corners(tet + 4 * (i / 4), (int)(i % 4), face + 3 * nface++);
        cvm__free(&m->ctx, g->face);
        g->face = face;
        g->nface = nface;
        face = NULL;
    }
    cvm__free(&m->ctx, g->xyz);
    cvm__free(&m->ctx, g->tet);
    cvm__free(&m->ctx, g->w);
    cvm__free(&m->ctx, g->tattr);
    g->xyz = xyz, g->tet = tet, g->w = w, g->tattr = tattr;
    g->nv = np, g->ntet = nt;
    xyz = w = tattr = NULL;
    tet = NULL;
    s = CVM_OK;
    goto done_set;
done:
    s = cvm__nomem(&m->ctx);
done_set:
    cvm__free(&m->ctx, rec);
    cvm__free(&m->ctx, tet);
    cvm__free(&m->ctx, xyz);
    cvm__free(&m->ctx, w);
    cvm__free(&m->ctx, tattr);
    cvm__free(&m->ctx, attr);
    cvm__free(&m->ctx, nbr);
    cvm__free(&m->ctx, face);
    return s;
}

/* A point of the call with its index, for finding repeated points. */
typedef struct cvm__ins3_pt {
    double x[3];
    size_t i;
} cvm__ins3_pt;

static int cmp_ins3_pt(const void *pa, const void *pb)
{
    const cvm__ins3_pt *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->x[k] != b->x[k])
            return a->x[k] < b->x[k] ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/*
 * The order in which the points go in. In input order, unless the result
 * cannot depend on it: a point set's unweighted Delaunay mesh and min_dist 0,
 * where a point is refused only outside the hull (which does not move) or on
 * a vertex, and the tetrahedralisation of the rest is unique (ties broken by
 * ids, which stay in input order). There BRIO + Hilbert order (as
 * cvm_mesh_triangulate()) keeps the walks short; a point repeating an earlier
 * one of the call is refused beforehand (skip), as input order would.
 * *order NULL: input order. CVM_OK or CVM_E_NOMEM (message set).
 */
static cvm_status insertion_order(cvm_mesh *m, const double *xyz, size_t count, double min_dist,
                                  int32_t **order, uint8_t **skip)
{
    const cvm__mesh3 *g = m->m3;
    cvm__ins3_pt *pt;
    size_t i;
    *order = NULL;
    *skip = NULL;
    if (!g->delaunay || g->w || min_dist > 0 || count < 2)
        return CVM_OK;
    *order = cvm__malloc(&m->ctx, count * sizeof **order);
    *skip = cvm__calloc(&m->ctx, count, 1);
    pt = cvm__malloc(&m->ctx, count * sizeof *pt);
    if (!*order || !*skip || !pt
        || cvm__tet3_brio_order(&m->ctx, xyz, count, (uint64_t)cvm__opt(m, CVM_OPT_SEED), *order)) {
        cvm__free(&m->ctx, pt);
        return cvm__nomem(&m->ctx);
    }
    for (i = 0; i < count; i++) {
        memcpy(pt[i].x, xyz + 3 * i, sizeof pt[i].x);
        pt[i].i = i;
    }
    qsort(pt, count, sizeof *pt, cmp_ins3_pt);
    for (i = 1; i < count; i++)
        if (memcmp(pt[i].x, pt[i - 1].x, sizeof pt[i].x) == 0)
            (*skip)[pt[i].i] = 1;
    cvm__free(&m->ctx, pt);
    return CVM_OK;
}

cvm_status cvm__mesh3_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xyz,
                                    size_t count, double min_dist)
{
    cvm__mesh3 *g = m->m3;
    cvm__tet3 T;
    int32_t *nbr = NULL, *order = NULL, *ip = NULL, *fin = NULL;
    uint8_t *cons = NULL, *skip = NULL;
    size_t i, k, nv0, done = 0;
    cvm_status s, stop = CVM_OK;
    if (!xyz && count > 0)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "coords is NULL");
    if (!g->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no tetrahedralisation: call cvm_mesh_triangulate() first");
    if (!isfinite(min_dist))
        return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1, "min_dist is not finite");
    if (min_dist < 0)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "min_dist %.17g is negative",
                          min_dist);
    if ((s = check_points(m, xyz, count)))
        return s;
    if (ids_out)
        for (i = 0; i < count; i++)
            ids_out[i] = CVM_REJECTED;
    if (count == 0 || g->ntet == 0)
        return CVM_OK;
    nv0 = g->nv;
    if (count > (size_t)INT32_MAX - nv0 || nv0 + count > CVM__T3_MAX_POINTS)
        return cvm__error(&m->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_POINT, -1,
                          "%lu points on %lu vertices exceed the 3D limit of %lu",
                          (unsigned long)count, (unsigned long)nv0,
                          (unsigned long)CVM__T3_MAX_POINTS);
    if ((s = insertion_order(m, xyz, count, min_dist, &order, &skip)))
        goto out;
    ip = cvm__malloc(&m->ctx, count * sizeof *ip);
    fin = cvm__malloc(&m->ctx, count * sizeof *fin);
    if (!ip || !fin) {
        s = cvm__nomem(&m->ctx);
        goto out;
    }
    if ((s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr))) {
        if (s != CVM_E_NOMEM)
            s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "insertion: %s",
                           cvm_mesh_errmsg(m));
        goto out;
    }
    if (!g->delaunay && (s = constrained_faces(m, nbr, &cons)))
        goto out;
    cvm__tet3_init(&T, &m->ctx);
    s = cvm__tet3_load(&T, g->xyz, g->w, nv0, nv0 + count, g->tet, g->ntet, nbr,
                       g->delaunay ? NULL : cons, g->tattr);
    if (s) {
        cvm__tet3_free(&T);
        s = cvm__nomem(&m->ctx);
        goto out;
    }
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    for (k = 0; k < count; k++) {
        cvm__t3_ins res = CVM__T3_INS_DUPLICATE;
        int32_t other;
        i = order ? (size_t)order[k] : k;
        ip[i] = -1;
        if (!(skip && skip[i])
            && (s = cvm__tet3_insert_point(&T, xyz + 3 * i, (int32_t)(nv0 + i), min_dist, &res,
                                           &other))) {
            stop = cvm__nomem(&m->ctx);
            break;
        }
        if (res == CVM__T3_INS_DONE) {
            ip[i] = (int32_t)(T.np - 1);
            done++;
        }
        s = cvm__tick(&m->ctx, 1, CVM_STAGE_INSERT, (double)k / (double)count);
        if (s) {
            stop = cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "%s after %lu of %lu points%s; the points not inserted by then "
                              "were rejected",
                              s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached",
                              (unsigned long)(k + 1), (unsigned long)count,
                              order ? " (taken in space-filling-curve order)" : "");
            ++k;
            break;
        }
    }
    for (; k < count; k++) /* not reached: a stop */
        ip[order ? (size_t)order[k] : k] = -1;
    /* ids in input order: the k-th point inserted, counted in input order, is vertex nv0 + k */
    for (i = 0, k = 0; i < count; i++)
        if (ip[i] >= 0)
            fin[(size_t)ip[i] - nv0] = (int32_t)(nv0 + k++);
    s = done ? write_back(m, &T, T.np, fin) : CVM_OK;
    cvm__tet3_free(&T);
    if (!s && ids_out)
        for (i = 0; i < count; i++)
            if (ip[i] >= 0)
                ids_out[i] = fin[(size_t)ip[i] - nv0];
    if (!s)
        s = stop;
out:
    cvm__free(&m->ctx, nbr);
    cvm__free(&m->ctx, cons);
    cvm__free(&m->ctx, order);
    cvm__free(&m->ctx, skip);
    cvm__free(&m->ctx, ip);
    cvm__free(&m->ctx, fin);
    return s;
}
