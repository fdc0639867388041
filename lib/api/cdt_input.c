/* cdt_input.c - a mesh handle's input and options as the CDT engine's input, the build that
 * hands the engine's outputs back to the handle, and the engine's input faults as messages
 * naming the items in the user's terms. */
#include <string.h>

#include "api_internal.h"
#include "store.h"

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

cvm_status cvm__mesh_cdt_build(cvm_mesh *m, const cvm__cdt_input *in, cvm__cdt_fault *f)
{
    cvm__cdt_out out;
    cvm_status s;
    memset(f, 0, sizeof *f);
    out.input_map = m->input_map;
    out.n_dup = m->n_dup;
    out.vmark = m->vmark;
    out.vattr = m->vattr;
    out.cap_vmark = m->cap_vmark;
    out.cap_vattr = m->cap_vattr;
    s = cvm__cdt_build(cvm__store_tri2(m), in, &out, f);
    m->input_map = out.input_map;
    m->n_dup = out.n_dup;
    m->vmark = out.vmark;
    m->vattr = out.vattr;
    m->cap_vmark = out.cap_vmark;
    m->cap_vattr = out.cap_vattr;
    return s;
}
