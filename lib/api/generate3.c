/*
 * generate3.c - cvm_mesh_generate3(): check the call, let lib/generate3 place
 * the points inside the handle's surface, and tetrahedralise surface and
 * points through the kernel path of cvm_mesh_triangulate() (TetGen recovery,
 * or Delaunay + carve), the generated points appended to the input for that
 * one call only.
 */
#include <math.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "generate3/generate3.h"
#include "surface3/surface3_internal.h"
#include "tetgen/tetgen_shim.h"

cvm_status cvm__mesh3_gen3_report(double *out, const cvm_mesh *m, int which)
{
    int k = which - (int)CVM_REPORT_GEN3_MATCHED_PAIRS;
    if (k < 0 || k >= CVM__GEN3_NREPORT || which == 749)
        return CVM_E_ARGUMENT;
    *out = m->m3 ? m->m3->gen3[k] : 0;
    return CVM_OK;
}

static cvm_status check_call(cvm_mesh *m, double size)
{
    double layers = cvm__opt(m, CVM_OPT_GEN3_LAYERS);
    if (isnan(size) || isinf(size))
        return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "size %g is not finite", size);
    if (!(size > 0))
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "size %.17g must be positive", size);
    if (!m->m3 || m->m3->in.npoly == 0)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "mesh generation needs a closed 3D surface: read one with "
                          "cvm_mesh_read() (.off, .stl, .poly, .smesh)");
    if (layers != 1)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_OPTION, CVM_OPT_GEN3_LAYERS,
                          "CVM_OPT_GEN3_LAYERS = %g is unsupported: only one near-field layer is implemented "
                          "in this version", layers);
    return CVM_OK;
}

/* Tetrahedralise the surface with the n points xyz appended to its input. */
static cvm_status tetrahedralise_with(cvm_mesh *m, const double *xyz, size_t n)
{
    cvm__surf3 *in = &m->m3->in;
    size_t np = in->np, i;
    cvm_status s = CVM_OK;
    for (i = 0; i < n && !s; i++)
        s = cvm__surf3_add_point(&m->ctx, in, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    if (!s)
        s = cvm__mesh3_triangulate(m);
    in->np = np; /* the input is the surface alone again; its array keeps the room */
    return s;
}

/* The surface of r as a cvm__surf3 (one facet per triangle, the marker of
 * the input facet it comes from; holes and regions borrowed from the input
 * by copy), validated as the input was. */
static cvm_status remeshed_surface(cvm_mesh *m, const cvm__g3_remeshed *r, const cvm__surf3_tris *st,
                                   cvm__surf3 *out)
{
    const cvm__surf3 *in = &m->m3->in;
    cvm__surf3_tris chk;
    size_t i;
    cvm_status s = CVM_OK;
    cvm__surf3_init(out);
    out->facet_word = "re-meshed surface triangle";
    for (i = 0; i < r->np && !s; i++)
        s = cvm__surf3_add_point(&m->ctx, out, r->xyz[3 * i], r->xyz[3 * i + 1], r->xyz[3 * i + 2]);
    for (i = 0; i < r->nt && !s; i++) {
        int32_t poly = st->tpoly[r->tsrc[i]];
        if (!(s = cvm__surf3_add_facet(&m->ctx, out, in->fmark[in->pfacet[poly]])))
            s = cvm__surf3_add_polygon(&m->ctx, out, r->tri + 3 * i, 3);
    }
    for (i = 0; i < in->nholes && !s; i++)
        s = cvm__surf3_add_hole(&m->ctx, out, in->holes + 3 * i);
    for (i = 0; i < in->nregions && !s; i++)
        s = cvm__surf3_add_region(&m->ctx, out, in->regions + 5 * i);
    if (s)
        return s;
    memset(&chk, 0, sizeof chk);
    s = cvm__surf3_validate(&m->ctx, out, CVM__SURF3_ALLOW_INTERNAL, &chk);
    cvm__surf3_tris_free(&m->ctx, &chk);
    if (s && s != CVM_E_NOMEM)
        s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                       "the re-meshed surface fails validation (%s: %s): "
                       "use CVM_OPT_GEN3_SURFACE = 0", cvm_status_str(s), m->ctx.errmsg);
    return s;
}

/* Re-meshings of the whole surface tried, each at half the size of the last. */
#define CVM__REMESH_ATTEMPTS 3

/* cvm_mesh_generate3_sized() with sizing NULL or checked for 3D. */
static cvm_status generate(cvm_mesh *m, double size, const cvm_sizing *sizing)
{
    cvm__g3_remeshed rm;
    cvm__surf3 saved, ns;
    int swapped = 0;
    double rm_count[3];
    cvm__mesh3 *g;
    cvm__surf3_tris st;
    cvm__g3_surface surf;
    cvm__g3_params p;
    cvm__g3_points pts;
    cvm__g3_report rep;
    int64_t bad = -1;
    double t0 = cvm__now();
    cvm_status s;
    memset(&saved, 0, sizeof saved);
    memset(&ns, 0, sizeof ns);
    if ((s = check_call(m, size)))
        return s;
    g = m->m3;
    memset(g->gen3, 0, sizeof g->gen3);
    memset(&st, 0, sizeof st);
    if ((s = cvm__surf3_validate(&m->ctx, &g->in, CVM__SURF3_ALLOW_INTERNAL, &st)))
        return s;
    surf.xyz = g->in.xyz;
    surf.np = g->in.np;
    surf.tri = st.tri;
    surf.nt = st.nt;
    p.h = size;
    p.grading = cvm__opt(m, CVM_OPT_GEN3_GRADING);
    p.follow_surface = cvm__opt(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE) != 0;
    p.layers = 1;
    p.sizing = sizing;
    p.freespace = (int)cvm__opt(m, CVM_OPT_GEN3_FREESPACE);
    p.octree_balance = 6; /* 26 measured no better: see g3_octree.c */
    p.octree_split_hanging = cvm__opt(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING) != 0;
    p.refine_max = (size_t)cvm__opt(m, CVM_OPT_MAX_STEINER);
    p.near_wall = CVM__G3_NEAR_WALL;
    p.lattice_dmf = cvm__opt(m, CVM_OPT_GEN3_SURFACE) == CVM_GEN3_SURFACE_REMESH_ALL
                        ? CVM__G3_DM_REMESHED : 0;
    if (sizing && sizing->bgrad > 0) {
        /* min(l + g1 d, l + g2 d) = l + min(g1, g2) d: one field, the smaller slope */
        p.grading = p.follow_surface && p.grading < sizing->bgrad ? p.grading : sizing->bgrad;
        p.follow_surface = 1;
    }
    memset(&rm, 0, sizeof rm);
    rm.tris_before = rm.tris_after = st.nt;
    if (cvm__opt(m, CVM_OPT_GEN3_SURFACE) != CVM_GEN3_SURFACE_AS_GIVEN) {
        int32_t *key = cvm__malloc(&m->ctx, (st.nt ? st.nt : 1) * sizeof *key);
        size_t t;
        if (!key) {
            cvm__surf3_tris_free(&m->ctx, &st);
            return cvm__nomem(&m->ctx);
        }
        for (t = 0; t < st.nt; t++)
            key[t] = g->in.fmark[g->in.pfacet[st.tpoly[t]]];
        if (cvm__opt(m, CVM_OPT_GEN3_SURFACE) == CVM_GEN3_SURFACE_REMESH_ALL) {
            /* a coarse re-meshing can fold at a sharp corner (two triangles of one point
             * crossing): then again at half and a quarter of the size, which the
             * generation itself keeps */
            double h0 = p.h;
            int attempt;
            for (attempt = 0; attempt < CVM__REMESH_ATTEMPTS; attempt++) {
                p.h = ldexp(h0, -attempt);
                s = cvm__g3_remesh_all(&m->ctx, &surf, key, &p, &rm);
                if (!s && rm.xyz)
                    s = remeshed_surface(m, &rm, &st, &ns);
                if (s != CVM_E_INTERNAL || attempt + 1 == CVM__REMESH_ATTEMPTS)
                    break;
                if (rm.xyz)
                    cvm__surf3_free(&m->ctx, &ns);
                cvm__g3_remeshed_free(&m->ctx, &rm);
                memset(&rm, 0, sizeof rm);
                rm.tris_before = rm.tris_after = st.nt;
            }
            p.h = h0;
        } else {
            s = cvm__g3_remesh_planar(&m->ctx, &surf, key, &p, &rm);
            if (!s && rm.xyz)
                s = remeshed_surface(m, &rm, &st, &ns);
        }
        cvm__free(&m->ctx, key);
        if (s) {
            if (rm.xyz)
                cvm__surf3_free(&m->ctx, &ns);
            cvm__g3_remeshed_free(&m->ctx, &rm);
            cvm__surf3_tris_free(&m->ctx, &st);
            return s;
        }
        if (rm.xyz) {
            /* generate and tetrahedralise with the new surface in the input's place */
            cvm__surf3_tris_free(&m->ctx, &st);
            memset(&st, 0, sizeof st);
            if ((s = cvm__surf3_validate(&m->ctx, &ns, CVM__SURF3_ALLOW_INTERNAL, &st))) {
                cvm__surf3_free(&m->ctx, &ns);
                cvm__g3_remeshed_free(&m->ctx, &rm);
                return s;
            }
            saved = g->in;
            g->in = ns;
            swapped = 1;
            surf.xyz = g->in.xyz;
            surf.np = g->in.np;
            surf.tri = st.tri;
            surf.nt = st.nt;
        }
        rm.tris_after = st.nt;
    }
    s = cvm__g3_generate(&m->ctx, &surf, &p, !cvm__tetgen_available(),
                         (uint64_t)cvm__opt(m, CVM_OPT_SEED), &pts, &rep, &bad);
    if (s == CVM_E_UNSUPPORTED && bad >= 0 && rep.surface_not_delaunay) {
        int32_t poly = st.tpoly[bad];
        s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_FACET, (int64_t)g->in.pfacet[poly],
                       "%s %ld of %s is not a face of the Delaunay tetrahedralisation of its "
                       "points, and this build has no boundary recovery (build with TETGEN=1)",
                       g->in.facet_word, (long)(g->in.pfacet[poly] + g->in.facet_base),
                       g->in.file ? g->in.file : "the input");
    } else if (s == CVM_E_UNSUPPORTED && bad >= 0) {
        int32_t poly = st.tpoly[bad];
        s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_FACET, (int64_t)g->in.pfacet[poly],
                       "%s %ld of %s stays off the Delaunay tetrahedralisation of the surface "
                       "and the generated points, and this build has no boundary recovery "
                       "(build with TETGEN=1)",
                       g->in.facet_word, (long)(g->in.pfacet[poly] + g->in.facet_base),
                       g->in.file ? g->in.file : "the input");
    }
    cvm__surf3_tris_free(&m->ctx, &st);
    if (!s) {
        s = tetrahedralise_with(m, pts.xyz, pts.n);
        cvm__g3_points_free(&m->ctx, &pts);
    }
    if (swapped) {
        ns = g->in;
        g->in = saved;
        cvm__surf3_free(&m->ctx, &ns);
    }
    rm_count[0] = (double)rm.facets_remeshed;
    rm_count[1] = (double)rm.tris_before;
    rm_count[2] = (double)rm.tris_after;
    cvm__g3_remeshed_free(&m->ctx, &rm);
    if (cvm_status_is_error(s))
        return s;
    g->gen3[0] = (double)rep.matched_pairs;
    g->gen3[1] = (double)rep.unmatched_faces;
    g->gen3[2] = (double)rep.pairs_rejected;
    g->gen3[3] = (double)rep.near_points;
    g->gen3[4] = (double)rep.near_rejected;
    g->gen3[5] = (double)rep.lattice_points;
    g->gen3[6] = (double)rep.lattice_levels;
    g->gen3[7] = (double)rep.recovery_dropped;
    g->gen3[8] = cvm__now() - t0;
    g->gen3[17] = rm_count[0];
    g->gen3[18] = rm_count[1];
    g->gen3[19] = rm_count[2];
    g->gen3[21] = (double)rep.octree_leaves;
    g->gen3[22] = (double)rep.octree_points;
    g->gen3[23] = (double)rep.refine_points;
    g->gen3[24] = (double)rep.refine_rounds;
    if (s == CVM_OK && rep.refine_limited)
        s = cvm__error(&m->ctx, CVM_INCOMPLETE_STEINER_LIMIT, CVM_ENT_OPTION, CVM_OPT_MAX_STEINER,
                       "the free-space refinement stopped at CVM_OPT_MAX_STEINER = %lu points; "
                       "the mesh is valid, its free space coarser than the size asks",
                       (unsigned long)rep.refine_points);
    return s;
}

cvm_status cvm_mesh_generate3(cvm_mesh *m, double size)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    return generate(m, size, NULL);
}

cvm_status cvm_mesh_generate3_sized(cvm_mesh *m, double size, const cvm_sizing *sizing)
{
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if ((s = cvm__sizing_check3(sizing, &m->ctx, "cvm_mesh_generate3_sized()", 1)))
        return s;
    return generate(m, size, cvm__sizing_is_empty(sizing) ? NULL : sizing);
}
