/* triangulate.c - cvm_mesh_triangulate (the engine's PSLG triangulation, its input faults worded for the user), point insertion and checking. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"
#include "api/mesh3.h"
#include "store.h"

/* Number naming input point i in messages (the file's, or i; i may be out of range). */
static long long point_num(const cvm_mesh *m, int32_t i)
{
    return i < 0 ? (long long)i : cvm__src_num(&m->in.src_point, (size_t)i);
}

static cvm_status check_segments(cvm_mesh *m)
{
    size_t k;
    for (k = 0; k < m->in.nseg; k++) {
        int32_t a = m->in.seg[2 * k], b = m->in.seg[2 * k + 1];
        char where[CVM__WHERE_LEN];
        if (a < 0 || b < 0 || (size_t)a >= m->in.np || (size_t)b >= m->in.np)
            return cvm__error(&m->ctx, CVM_E_INPUT_INDEX, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                              "%ssegment %lld (points %lld-%lld) names a point that does not exist "
                              "(there are %lu points)",
                              cvm__src_where(where, sizeof where, &m->in.src_segment, k),
                              cvm__src_num(&m->in.src_segment, k), point_num(m, a), point_num(m, b),
                              (unsigned long)m->in.np);
    }
    return CVM_OK;
}

/* Locate a seed point: the domain triangle containing it, or -1 outside. */
int32_t cvm__mesh_seed_triangle(cvm_mesh *m, const double *p)
{
    return cvm__store_locate(m, p);
}

cvm_status cvm__mesh_carve(cvm_mesh *m)
{
    cvm__cdt_input in;
    cvm__cdt_fault f;
    cvm_status s;
    cvm__mesh_cdt_input(&in, m, &m->in);
    s = cvm__cdt_carve(cvm__store_tri2(m), &in, &f);
    return s ? cvm__cdt_fault_message(&m->ctx, &m->in, s, &f) : CVM_OK;
}

/* The engine's triangulation of m's input; the input map, markers and
 * attributes it makes go to m also on failure (dropped with the output). */
static cvm_status triangulate(cvm_mesh *m)
{
    cvm__cdt_input in;
    cvm__cdt_fault f;
    cvm_status s;
    if ((s = check_segments(m)))
        return s;
    cvm__mesh_cdt_input(&in, m, &m->in);
    s = cvm__mesh_cdt_build(m, &in, &f);
    return s ? cvm__cdt_fault_message(&m->ctx, &m->in, s, &f) : CVM_OK;
}

cvm_status cvm_mesh_triangulate(cvm_mesh *m)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_triangulate(m);
    }
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_drop_output(m);
    if (m->in.np == 0)
        return cvm__error(&m->ctx, CVM_E_INPUT_EMPTY, CVM_ENT_INPUT_POINT, -1, "no input points");
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    s = triangulate(m);
    if (s) {
        cvm__mesh_drop_output(m);
        return s;
    }
    m->triangulated = 1;
    m->nv_triangulated = cvm__store_nv(m);
    return CVM_OK;
}

cvm_status cvm_mesh_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xy, size_t count,
                                  double min_dist)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_insert_points");
    }
    size_t i;
    cvm_status s = CVM_OK;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_forget_layers(m);
    if (!xy && count > 0)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "xy is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    if (!isfinite(min_dist))
        return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1, "min_dist is not finite");
    if (min_dist < 0)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "min_dist %.17g is negative",
                          min_dist);
    for (i = 0; i < 2 * count; i++)
        if (!isfinite(xy[i]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_INPUT_POINT, (int64_t)(i / 2),
                              "point %lu has a non-finite %c", (unsigned long)(i / 2),
                              i % 2 ? 'y' : 'x');
    if (ids_out)
        for (i = 0; i < count; i++)
            ids_out[i] = CVM_REJECTED;
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    for (i = 0; i < count; i++) {
        int32_t v;
        int inserted;
        if ((s = cvm__store_add_vertex(m, xy + 2 * i, &v)))
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i, "too many vertices");
        if (cvm__grow_vertex_data(m)) {
            cvm__store_drop_last_vertex(m);
            return cvm__nomem(&m->ctx);
        }
        s = cvm__store_insert_vertex(m, v, min_dist, &inserted);
        if (s) {
            cvm__store_drop_last_vertex(m);
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                                                 "inserting point %lu failed", (unsigned long)i);
        }
        if (!inserted) {
            cvm__store_drop_last_vertex(m);
            continue;
        }
        m->vmark[v] = 0;
        if (m->in.nattr)
            memset(m->vattr + (size_t)v * m->in.nattr, 0, m->in.nattr * sizeof(double));
        if (ids_out)
            ids_out[i] = v;
        s = cvm__tick(&m->ctx, 1, CVM_STAGE_INSERT, (double)i / (double)count);
        if (s)
            return cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "%s after point %lu; points after it were not inserted",
                              s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "time limit reached",
                              (unsigned long)i);
    }
    return CVM_OK;
}

cvm_status cvm_mesh_check(cvm_mesh *m)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_check(m);
    }
    int32_t t;
    int j;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1, "nothing triangulated");
    if ((s = cvm__store_check(m)))
        return s;
    /* the domain is bounded by constrained edges or by the convex hull */
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        for (j = 0; j < 3; j++) {
            int32_t u = cvm__store_across(m, (size_t)t, j);
            if (cvm__store_in_domain(m, u) || cvm__store_face_segment(m, (size_t)t, j) >= 0)
                continue;
            if (u >= 0 && cvm__store_is_ghost(m, u) && (m->in.nseg == 0 || cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0))
                continue;
            return cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TRIANGLE, (int64_t)t,
                              "check failed: triangle slot %lu borders the outside across an "
                              "unconstrained edge",
                              (unsigned long)t);
        }
    }
    return CVM_OK;
}
