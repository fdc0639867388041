/* triangulate.c - cvm_mesh_triangulate (the engine's PSLG triangulation, its input faults worded for the user), point insertion and checking. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"
#include "api/mesh3.h"

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

/* Number naming input point i of in in messages (i in range). */
static long long in_point_num(const cvm__pslg *in, size_t i)
{
    return cvm__src_num(&in->src_point, i);
}

cvm_status cvm__cdt_fault_message(cvm__ctx *ctx, const cvm__pslg *in, cvm_status s,
                                  const cvm__cdt_fault *f)
{
    char where[CVM__WHERE_LEN], also[CVM__WHERE_LEN];
    size_t k = f->item;
    const cvm__item_src *src;
    const int32_t *sg, *o;
    const double *p;
    switch (f->kind) {
    case CVM__CDT_FAULT_RANGE:
        src = &in->src_point;
        return cvm__error(ctx, s, CVM_ENT_INPUT_POINT, (int64_t)k,
                          "%spoint %lld has %c = %.17g, more than 2^180 times smaller than the "
                          "largest coordinate %.17g: exact predicates cannot span that range; "
                          "round it to 0 or translate the input",
                          cvm__src_where(where, sizeof where, src, k), in_point_num(in, k),
                          f->axis ? 'y' : 'x', in->xy[2 * k + (size_t)f->axis], f->big);
    case CVM__CDT_FAULT_DUPLICATE:
        src = &in->src_point;
        return cvm__error(ctx, s, CVM_ENT_INPUT_POINT, (int64_t)k,
                          "%spoint %lld at (%.17g, %.17g) duplicates point %lld%s",
                          cvm__src_where(where, sizeof where, src, k), in_point_num(in, k),
                          in->xy[2 * k], in->xy[2 * k + 1], in_point_num(in, f->other),
                          cvm__src_also(also, sizeof also, src, f->other, src));
    case CVM__CDT_FAULT_ZERO_LENGTH:
        src = &in->src_segment;
        sg = in->seg + 2 * k;
        return cvm__error(ctx, s, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                          "%ssegment %lld (points %lld-%lld) has zero length%s",
                          cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k),
                          in_point_num(in, (size_t)sg[0]), in_point_num(in, (size_t)sg[1]),
                          sg[0] == sg[1] ? "" : ": its endpoints are at the same position");
    case CVM__CDT_FAULT_CROSSING:
        src = &in->src_segment;
        sg = in->seg + 2 * k;
        o = in->seg + 2 * f->other;
        return cvm__error(ctx, s, CVM_ENT_INPUT_SEGMENT, (int64_t)k,
                          "%ssegment %lld (points %lld-%lld) crosses segment %lld%s (points "
                          "%lld-%lld) in its interior",
                          cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k),
                          in_point_num(in, (size_t)sg[0]), in_point_num(in, (size_t)sg[1]),
                          cvm__src_num(src, f->other),
                          cvm__src_also(also, sizeof also, src, f->other, src),
                          in_point_num(in, (size_t)o[0]), in_point_num(in, (size_t)o[1]));
    case CVM__CDT_FAULT_HOLE_OUTSIDE:
    case CVM__CDT_FAULT_HOLE_ALL:
        src = &in->src_hole;
        p = in->holes + 2 * k;
        return cvm__error(ctx, s, CVM_ENT_HOLE, (int64_t)k,
                          f->kind == CVM__CDT_FAULT_HOLE_OUTSIDE
                              ? "%shole %lld at (%.17g, %.17g) lies outside the convex hull of the points"
                              : "%shole %lld at (%.17g, %.17g) removed every remaining triangle: no "
                                "closed loop of segments separates it from the rest of the domain",
                          cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k), p[0], p[1]);
    case CVM__CDT_FAULT_REGION_OUTSIDE:
        src = &in->src_region;
        p = in->regions + 4 * k;
        return cvm__error(ctx, s, CVM_ENT_REGION, (int64_t)k,
                          "%sregion %lld at (%.17g, %.17g) lies outside the domain",
                          cvm__src_where(where, sizeof where, src, k), cvm__src_num(src, k), p[0], p[1]);
    case CVM__CDT_FAULT_NONE:
        break;
    }
    return s; /* not an input fault: the engine set the message */
}

void cvm__mesh_cdt_input(cvm__cdt_input *out, const cvm_mesh *m, const cvm__pslg *p)
{
    out->xy = p->xy;
    out->np = p->np;
    out->pmark = p->pmark;
    out->pattr = p->pattr;
    out->nattr = p->nattr;
    out->seg = p->seg;
    out->nseg = p->nseg;
    out->smark = p->smark;
    out->holes = p->holes;
    out->nholes = p->nholes;
    out->regions = p->regions;
    out->nregions = p->nregions;
    out->seed = (uint64_t)cvm__opt(m, CVM_OPT_SEED);
    out->reject_duplicates = cvm__opt(m, CVM_OPT_REJECT_DUPLICATES) != 0;
    out->split = cvm__opt(m, CVM_OPT_SPLIT_INTERSECTIONS) != 0;
    out->keep_hull = cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0;
}

/* Locate a seed point: the domain triangle containing it, or -1 outside. */
int32_t cvm__mesh_seed_triangle(cvm_mesh *m, const double *p)
{
    int32_t t;
    int j;
    cvm__loc loc = cvm__tri2_locate(&m->tri, p, -1, &t, &j);
    if (loc == CVM__LOC_OUTSIDE || t < 0)
        return -1;
    return t;
}

cvm_status cvm__mesh_carve(cvm_mesh *m)
{
    cvm__cdt_input in;
    cvm__cdt_fault f;
    cvm_status s;
    cvm__mesh_cdt_input(&in, m, &m->in);
    s = cvm__cdt_carve(&m->tri, &in, &f);
    return s ? cvm__cdt_fault_message(&m->ctx, &m->in, s, &f) : CVM_OK;
}

/* The engine's triangulation of m's input; the input map, markers and
 * attributes it makes go to m also on failure (dropped with the output). */
static cvm_status triangulate(cvm_mesh *m)
{
    cvm__cdt_input in;
    cvm__cdt_out out;
    cvm__cdt_fault f;
    cvm_status s;
    if ((s = check_segments(m)))
        return s;
    cvm__mesh_cdt_input(&in, m, &m->in);
    out.input_map = m->input_map;
    out.n_dup = m->n_dup;
    out.vmark = m->vmark;
    out.vattr = m->vattr;
    out.cap_vmark = m->cap_vmark;
    out.cap_vattr = m->cap_vattr;
    s = cvm__cdt_build(&m->tri, &in, &out, &f);
    m->input_map = out.input_map;
    m->n_dup = out.n_dup;
    m->vmark = out.vmark;
    m->vattr = out.vattr;
    m->cap_vmark = out.cap_vmark;
    m->cap_vattr = out.cap_vattr;
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
    m->nv_triangulated = m->tri.nv;
    return CVM_OK;
}

cvm_status cvm_mesh_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xy, size_t count,
                                  double min_dist)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_insert_points");
    }
    cvm__tri2 *T;
    size_t i;
    cvm_status s = CVM_OK;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__mesh_forget_layers(m);
    T = &m->tri;
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
        int32_t v, other;
        cvm__ins res;
        if ((s = cvm__tri2_add_vertex(T, xy + 2 * i, &v)))
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i, "too many vertices");
        if (cvm__grow_vertex_data(m)) {
            T->nv--;
            return cvm__nomem(&m->ctx);
        }
        s = cvm__tri2_insert_vertex(T, v, T->last, CVM__INSF_DOMAIN_ONLY, min_dist, &res, &other);
        if (s) {
            T->nv--;
            return s == CVM_E_NOMEM ? cvm__nomem(&m->ctx)
                                    : cvm__error(&m->ctx, s, CVM_ENT_INPUT_POINT, (int64_t)i,
                                                 "inserting point %lu failed", (unsigned long)i);
        }
        if (res != CVM__INS_DONE) {
            T->nv--;
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
    const cvm__tri2 *T;
    size_t t;
    int j;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1, "nothing triangulated");
    if ((s = cvm__tri2_check(&m->tri)) ||
        (s = cvm__cdt_check_chains(&m->tri, m->in.seg, m->in.nseg, m->input_map)))
        return s;
    T = &m->tri;
    /* the domain is bounded by constrained edges or by the convex hull */
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t u = T->tn[3 * t + j] / 3;
            if (cvm__tri2_in_domain(T, u) || cvm__tri2_edge_seg(T, (int32_t)t, j) >= 0)
                continue;
            if (cvm__tri2_is_ghost(T, u) && (m->in.nseg == 0 || cvm__opt(m, CVM_OPT_KEEP_CONVEX_HULL) != 0))
                continue;
            return cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TRIANGLE, (int64_t)t,
                              "check failed: triangle slot %lu borders the outside across an "
                              "unconstrained edge",
                              (unsigned long)t);
        }
    }
    return CVM_OK;
}
