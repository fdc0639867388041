/* optimise.c - cvm_mesh_optimise_dual, merge groups and the compliance measures: options in, lib/dual run, report out. */
#include <math.h>
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "dual/dual_internal.h"
#include "sizing_fields.h"
#include "api/mesh3.h"

enum { REP_SWEEPS, REP_BEFORE, REP_AFTER, REP_MOVES, REP_FLIPS, REP_FIXES, REP_SECONDS,
       REP_REMOVED_VANISHED, REP_REMOVED_DEGREE, REP_REMOVED_MAXMIN };

typedef struct size_payload {
    const cvm_sizing *sizing;
    cvm__ctx *err;
} size_payload;

static cvm_status size_at(void *payload, double x, double y, double *h)
{
    const size_payload *sp = payload;
    return cvm__sizing_at(sp->sizing, x, y, h, sp->err);
}

/* Vertices of the input points: 0 .. (largest input vertex id). */
static size_t input_vertices(const cvm_mesh *m)
{
    size_t i, n = 0;
    for (i = 0; m->input_map && i < m->in.np; i++)
        if (m->input_map[i] >= 0 && (size_t)m->input_map[i] + 1 > n)
            n = (size_t)m->input_map[i] + 1;
    return n;
}

/* The optimiser removed vertices (vmap: old id -> new id or -1, nv0 entries):
 * renumber the per-vertex markers and attributes the same way. Removed
 * vertices are Steiner points, so input_map is unchanged. */
static void drop_vertex_data(cvm_mesh *m, const int32_t *vmap, size_t nv0)
{
    size_t v, na = m->vattr ? m->in.nattr : 0;
    for (v = 0; v < nv0; v++) {
        size_t n;
        if (vmap[v] < 0)
            continue;
        n = (size_t)vmap[v]; /* n <= v: in place */
        if (m->vmark)
            m->vmark[n] = m->vmark[v];
        if (na)
            memmove(m->vattr + n * na, m->vattr + v * na, na * sizeof *m->vattr);
    }
}

/* The pre-pass appended vertices after the survivors of the nv0 old ones:
 * marker 0 and attributes 0 (they are interior points: no constrained edge is
 * split). CVM_OK or CVM_E_NOMEM (the mesh stays valid; the new vertices then
 * have no marker or attribute storage yet, so the caller reports the error). */
static cvm_status new_vertex_data(cvm_mesh *m, const int32_t *vmap, size_t nv0)
{
    size_t v, kept = 0, nv = cvm__store_nv(m), na = m->vattr ? m->in.nattr : 0;
    for (v = 0; v < nv0; v++)
        kept += vmap[v] >= 0;
    if (nv <= kept)
        return CVM_OK;
    if (m->vmark && nv > m->cap_vmark &&
        cvm__grow(&m->ctx, (void **)&m->vmark, &m->cap_vmark, nv, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (na && nv * na > m->cap_vattr &&
        cvm__grow(&m->ctx, (void **)&m->vattr, &m->cap_vattr, nv * na, sizeof(double)))
        return CVM_E_NOMEM;
    for (v = kept; v < nv; v++) {
        if (m->vmark)
            m->vmark[v] = 0;
        if (na)
            memset(m->vattr + v * na, 0, na * sizeof *m->vattr);
    }
    return CVM_OK;
}

cvm_status cvm_mesh_optimise_dual(cvm_mesh *m, const cvm_sizing *sizing)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_optimise_dual");
    }
    cvm__dual_opt_params p;
    cvm__dual_opt_report rep;
    size_payload sp;
    cvm__sizing_fields fields;
    const cvm_sizing *use;
    cvm_status s;
    int32_t *vmap = NULL;
    size_t nv0;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (cvm__sizing_refuse_metric(m, sizing, "cvm_mesh_optimise_dual()"))
        return CVM_E_UNSUPPORTED;
    if (cvm__sizing_refuse_3d(m, sizing, "cvm_mesh_optimise_dual()"))
        return CVM_E_ARGUMENT;
    cvm__mesh_forget_layers(m);
    if (!m->triangulated || cvm__store_next_cell(m, -1) < 0)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    memset(&p, 0, sizeof p);
    p.solver = (int)cvm__opt(m, CVM_OPT_DUAL_SOLVER);
    p.max_sweeps = (int)cvm__opt(m, CVM_OPT_DUAL_MAX_SWEEPS);
    p.min_angle_deg = cvm__opt(m, CVM_OPT_DUAL_MIN_ANGLE_DEG);
    p.target_angle_deg = cvm__opt(m, CVM_OPT_DUAL_TARGET_ANGLE_DEG);
    p.cuckoo_budget = (int)cvm__opt(m, CVM_OPT_DUAL_CUCKOO_BUDGET);
    p.pattern_budget = (int)cvm__opt(m, CVM_OPT_DUAL_PATTERN_BUDGET);
    p.margin = cvm__opt(m, CVM_OPT_DUAL_MARGIN);
    p.merge_tol = cvm__opt(m, CVM_OPT_DUAL_MERGE_TOL);
    p.layer_priority = cvm__opt(m, CVM_OPT_DUAL_LAYER_PRIORITY);
    p.seed = (uint64_t)cvm__opt(m, CVM_OPT_SEED);
    p.threads = (int)cvm__opt(m, CVM_OPT_THREADS);
    p.n_fixed = cvm__opt(m, CVM_OPT_DUAL_KEEP_INPUT_POINTS) != 0 ? input_vertices(m) : 0;
    p.n_input = input_vertices(m);
    p.topology = (int)cvm__opt(m, CVM_OPT_DUAL_TOPOLOGY);
    p.prepass = (int)cvm__opt(m, CVM_OPT_DUAL_PREPASS);
    p.maxmin_rounds = (int)cvm__opt(m, CVM_OPT_DUAL_MAXMIN_ROUNDS);
    p.maxmin_trials = (int)cvm__opt(m, CVM_OPT_DUAL_MAXMIN_TRIALS);
    /* both remove or insert vertices: without topology changes they could do nothing */
    if (!p.topology && (p.prepass || p.maxmin_trials))
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_OPTION,
                          (int64_t)(p.prepass ? CVM_OPT_DUAL_PREPASS : CVM_OPT_DUAL_MAXMIN_TRIALS),
                          "%s needs CVM_OPT_DUAL_TOPOLOGY >= 1 (it changes the vertices)",
                          p.prepass ? "CVM_OPT_DUAL_PREPASS" : "CVM_OPT_DUAL_MAXMIN_TRIALS");
    nv0 = cvm__store_nv(m);
    if (p.topology) {
        vmap = cvm__malloc(&m->ctx, (nv0 + 1) * sizeof *vmap);
        if (!vmap)
            return cvm__nomem(&m->ctx);
        p.vmap = vmap;
    }
    /* the automatic length scale and the boundary spacing of the mesh as it is */
    if ((s = cvm__sizing_fields_begin(m, sizing, &fields, &use)) != CVM_OK) {
        cvm__free(&m->ctx, vmap);
        return s;
    }
    if (!cvm__sizing_is_empty(use)) {
        sp.sizing = use;
        sp.err = &m->ctx;
        p.size_fn = size_at;
        p.size_payload = &sp;
    }
    memset(m->dual_opt_report, 0, sizeof m->dual_opt_report);
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    s = cvm__dual_optimise(cvm__store_tri2(m), &p, &rep);
    cvm__sizing_fields_end(m, &fields);
    if (vmap && (cvm__store_nv(m) < nv0 || rep.prepass_removed || rep.prepass_added))
        drop_vertex_data(m, vmap, nv0);
    if (vmap && rep.prepass_added && new_vertex_data(m, vmap, nv0) && s == CVM_OK)
        s = CVM_E_NOMEM;
    cvm__free(&m->ctx, vmap);
    m->dual_opt_report[REP_SWEEPS] = (double)rep.sweeps;
    m->dual_opt_report[REP_BEFORE] = rep.nc_before_pct;
    m->dual_opt_report[REP_AFTER] = rep.nc_after_pct;
    m->dual_opt_report[REP_MOVES] = (double)rep.moves;
    m->dual_opt_report[REP_FLIPS] = (double)rep.flips;
    m->dual_opt_report[REP_FIXES] = (double)rep.weight_fixes;
    m->dual_opt_report[REP_SECONDS] = rep.seconds;
    m->dual_opt_report[REP_REMOVED_VANISHED] = (double)rep.removed_vanished;
    m->dual_opt_report[REP_REMOVED_DEGREE] = (double)rep.removed_degree;
    m->dual_opt_report[REP_REMOVED_MAXMIN] = (double)rep.removed_maxmin;
    switch (s) {
    case CVM_OK:
        return CVM_OK;
    case CVM_E_NOMEM:
        return cvm__nomem(&m->ctx);
    case CVM_INCOMPLETE_TIME_LIMIT:
        return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                          "dual optimisation stopped at the time limit after %lu sweeps; the mesh "
                          "is a valid regular triangulation",
                          (unsigned long)rep.sweeps);
    case CVM_INCOMPLETE_CANCELLED:
        return cvm__error(&m->ctx, s, CVM_ENT_NONE, -1,
                          "dual optimisation cancelled after %lu sweeps; the mesh is a valid "
                          "regular triangulation",
                          (unsigned long)rep.sweeps);
    default:
        return s; /* sizing errors carry their message already */
    }
}

/* Sizes and power vertices of m's mesh: fresh arrays (free both). */
static cvm_status merge_inputs(cvm__ctx *ctx, const cvm_mesh *m, double **vsize, double **V)
{
    const cvm__tri2 *T = cvm__store_tri2_const(m);
    int32_t t;
    *vsize = cvm__malloc(ctx, (cvm__store_nv(m) + 1) * sizeof **vsize);
    *V = cvm__malloc(ctx, (2 * cvm__store_nslots(m) + 1) * sizeof **V);
    if (!*vsize || !*V) {
        cvm__free(ctx, *vsize);
        cvm__free(ctx, *V);
        *vsize = *V = NULL;
        return CVM_E_NOMEM;
    }
    cvm__dual_mesh_sizes(T, *vsize);
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        cvm__dual_tri_vertex(T, t, *V + 2 * (size_t)t);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_merge_groups(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    const cvm__tri2 *T;
    double *vsize, *V;
    int32_t *group, *map;
    size_t n, k = 0;
    int32_t t;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    n = cvm__mesh_n_triangles(m);
    if ((s = cvm__room(dst, dst_len, n)))
        return s;
    if (!n)
        return CVM_OK;
    ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    T = cvm__store_tri2_const(m);
    if (merge_inputs(ctx, m, &vsize, &V))
        return CVM_E_NOMEM;
    group = cvm__malloc(ctx, (cvm__store_nslots(m) + 1) * sizeof *group);
    if (!group || cvm__domain_map(ctx, T, &map)) {
        cvm__free(ctx, group);
        cvm__free(ctx, vsize);
        cvm__free(ctx, V);
        return CVM_E_NOMEM;
    }
    cvm__dual_merge_groups(ctx, T, vsize, cvm__opt(m, CVM_OPT_DUAL_MERGE_TOL), V, group);
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        dst[k++] = map[group[t]]; /* slot order = output order, so the root is the smallest */
    cvm__free(ctx, map);
    cvm__free(ctx, group);
    cvm__free(ctx, vsize);
    cvm__free(ctx, V);
    return CVM_OK;
}

int cvm__optimise_measure_needs_triangles(cvm_measure which)
{
    return which == CVM_MEASURE_DUAL_MERGED_PCT || which == CVM_MEASURE_DUAL_NONCOMPLIANT_PCT ||
           which == CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT;
}

/* % merged, % non-compliant, % non-compliant among the triangles with a
 * vertex on the domain boundary (an edge with a domain triangle on one side
 * only), as CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT counts them. */
static cvm_status merge_stats(cvm_mesh *m, double *merged, double *nc, double *nc_bnd)
{
    const cvm__tri2 *T = cvm__store_tri2_const(m);
    double *vsize, *V, tol = cvm__opt(m, CVM_OPT_DUAL_MERGE_TOL);
    int32_t *group;
    size_t *gsize, t, n = 0, nm = 0, nn = 0, nb = 0, nnb = 0;
    uint8_t *on_bnd;
    if (merge_inputs(&m->ctx, m, &vsize, &V))
        return cvm__nomem(&m->ctx);
    group = cvm__malloc(&m->ctx, (cvm__store_nslots(m) + 1) * sizeof *group);
    gsize = cvm__calloc(&m->ctx, cvm__store_nslots(m) + 1, sizeof *gsize);
    on_bnd = cvm__calloc(&m->ctx, cvm__store_nv(m) + 1, 1);
    if (!group || !gsize || !on_bnd) {
        cvm__free(&m->ctx, group);
        cvm__free(&m->ctx, gsize);
        cvm__free(&m->ctx, on_bnd);
        cvm__free(&m->ctx, vsize);
        cvm__free(&m->ctx, V);
        return cvm__nomem(&m->ctx);
    }
    cvm__dual_merge_groups(&m->ctx, T, vsize, tol, V, group);
    for (t = 0; t < cvm__store_nslots(m); t++) {
        const int32_t *v = cvm__store_cell(m, t);
        int j;
        if (group[t] < 0)
            continue;
        gsize[group[t]]++;
        for (j = 0; j < 3; j++)
            if (!cvm__store_in_domain(m, cvm__store_across(m, t, j))) {
                on_bnd[v[(j + 1) % 3]] = 1;
                on_bnd[v[(j + 2) % 3]] = 1;
            }
    }
    for (t = 0; t < cvm__store_nslots(m); t++) {
        const int32_t *v = cvm__store_cell(m, t);
        int bnd, bad;
        if (group[t] < 0)
            continue;
        bnd = on_bnd[v[0]] || on_bnd[v[1]] || on_bnd[v[2]];
        bad = cvm__dual_tri_compliance(T, vsize, tol, V, (int32_t)t) == CVM__DUAL_NONCOMPLIANT;
        n++;
        nm += gsize[group[t]] > 1;
        nn += (size_t)bad;
        nb += (size_t)bnd;
        nnb += (size_t)(bad && bnd);
    }
    cvm__free(&m->ctx, group);
    cvm__free(&m->ctx, gsize);
    cvm__free(&m->ctx, on_bnd);
    cvm__free(&m->ctx, vsize);
    cvm__free(&m->ctx, V);
    *merged = n ? 100.0 * (double)nm / (double)n : 0.0;
    *nc = n ? 100.0 * (double)nn / (double)n : 0.0;
    *nc_bnd = nb ? 100.0 * (double)nnb / (double)nb : 0.0;
    return CVM_OK;
}

cvm_status cvm__optimise_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    double merged, nc, ncb;
    cvm_status s;
    if ((int)which >= (int)CVM_MEASURE_DUAL_OPT_SWEEPS &&
        (int)which <= (int)CVM_MEASURE_DUAL_OPT_REMOVED_MAXMIN) {
        *out = m->dual_opt_report[(int)which - (int)CVM_MEASURE_DUAL_OPT_SWEEPS];
        return CVM_OK;
    }
    if (!cvm__optimise_measure_needs_triangles(which))
        return CVM_E_ARGUMENT;
    if ((s = merge_stats(m, &merged, &nc, &ncb)))
        return s;
    *out = which == CVM_MEASURE_DUAL_MERGED_PCT ? merged
         : which == CVM_MEASURE_DUAL_NONCOMPLIANT_PCT ? nc : ncb;
    return CVM_OK;
}
