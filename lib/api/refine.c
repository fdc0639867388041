/* refine.c - cvm_mesh_refine and its report: options in, lib/refine run, vertex markers, attributes and layers out. */
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "refine/refine_internal.h"
#include "sizing_fields.h"
#include "api/mesh3.h"

enum { REP_STEINER, REP_UNMET_ANGLE, REP_UNMET_SIZE, REP_SMALL_ANGLE, REP_REQUESTED, REP_MET };

/* Markers and attributes of the vertices nv0..nv-1 added by the refiner. */
static cvm_status refine_vertex_data(cvm_mesh *m, size_t nv0)
{
    size_t v, na = m->in.nattr, nv = cvm__store_nv(m);
    int32_t t;
    if (cvm__grow_vertex_data(m))
        return CVM_E_NOMEM;
    for (v = nv0; v < nv; v++) {
        m->vmark[v] = 0;
        if (na)
            memset(m->vattr + v * na, 0, na * sizeof(double));
    }
    for (t = nv > nv0 ? cvm__store_next_cell(m, -1) : -1; t >= 0; t = cvm__store_next_cell(m, t)) {
        const int32_t *c = cvm__store_cell(m, (size_t)t);
        int j, k;
        for (j = 0; j < 3; j++) {
            int32_t seg = cvm__store_face_segment(m, (size_t)t, j);
            if (seg < 0)
                continue;
            for (k = 1; k <= 2; k++) {
                int32_t u = c[(j + k) % 3];
                if ((size_t)u >= nv0)
                    cvm__segment_vertex_data(m, (size_t)u, seg);
            }
        }
    }
    return CVM_OK;
}

/* Regional maximum areas: when a region sets one, each triangle's attribute is
 * replaced by its region's index (-1: none) for the run, so that new
 * triangles inherit it; *area_out receives the areas by index. */
static cvm_status refine_regions_begin(cvm_mesh *m, double **area_out)
{
    double *ta = cvm__store_cell_attributes(m);
    size_t k, t;
    int any = 0;
    *area_out = NULL;
    for (k = 0; k < m->in.nregions; k++)
        any |= m->in.regions[4 * k + 3] > 0;
    if (!any || !ta)
        return CVM_OK;
    *area_out = cvm__malloc(&m->ctx, m->in.nregions * sizeof **area_out);
    if (!*area_out)
        return cvm__nomem(&m->ctx);
    for (t = 0; t < cvm__store_nslots(m); t++)
        ta[t] = -1;
    for (k = 0; k < m->in.nregions; k++) {
        int32_t seed = cvm__mesh_seed_triangle(m, m->in.regions + 4 * k);
        (*area_out)[k] = m->in.regions[4 * k + 3];
        if (seed >= 0 && cvm__store_in_domain(m, seed) &&
            cvm__store_flood_attribute(m, seed, (double)k)) {
            cvm__free(&m->ctx, *area_out);
            *area_out = NULL;
            return cvm__nomem(&m->ctx);
        }
    }
    return CVM_OK;
}

/* Per input segment: 1 when its marker is one of the front markers (AFLR);
 * NULL in *out when no front markers are set (every segment starts a front). */
static cvm_status refine_front_flags(cvm_mesh *m, unsigned char **out)
{
    size_t k, i;
    *out = NULL;
    if (!m->n_front_marks)
        return CVM_OK;
    if (!(*out = cvm__malloc(&m->ctx, m->in.nseg + 1)))
        return CVM_E_NOMEM;
    for (k = 0; k < m->in.nseg; k++) {
        int32_t mk = cvm__segment_marker(m, (int32_t)k);
        (*out)[k] = 0;
        for (i = 0; i < m->n_front_marks; i++)
            if (m->front_marks[i] == mk)
                (*out)[k] = 1;
    }
    return CVM_OK;
}

/* Back from region indices to the regional attributes (0 outside every region). */
static void refine_regions_end(cvm_mesh *m, double *area)
{
    double *ta = cvm__store_cell_attributes(m);
    size_t t;
    if (!area)
        return;
    for (t = 0; t < cvm__store_nslots(m); t++) {
        double r = ta[t];
        ta[t] = r >= 0 && r < (double)m->in.nregions ? m->in.regions[4 * (size_t)r + 2] : 0.0;
    }
    cvm__free(&m->ctx, area);
}

static cvm_status refine_run(cvm_mesh *m, const cvm_sizing *sizing, cvm_algorithm algo)
{
    double *region_area = NULL;
    cvm__sizing_fields fields;
    cvm__refine_params p;
    cvm__refine_report rep;
    int32_t *ends = NULL;
    unsigned char *front = NULL;
    size_t k, nv0, n_chains = 0;
    cvm_status s, s2;
    memset(&p, 0, sizeof p);
    cvm__free(&m->ctx, m->tlayer);
    m->tlayer = NULL;
    m->n_tlayer = 0;
    p.algo = (int)algo;
    p.min_angle_deg = cvm__opt(m, CVM_OPT_MIN_ANGLE_DEG);
    p.max_area = cvm__opt(m, CVM_OPT_MAX_AREA);
    p.max_steiner = (uint64_t)cvm__opt(m, CVM_OPT_MAX_STEINER);
    p.lens = cvm__opt(m, CVM_OPT_ENCROACH_LENS) != 0;
    p.march = cvm__opt(m, CVM_OPT_MARCH_SEGMENTS) != 0;
    p.march_grade = CVM__MARCH_GRADE;
    if (algo == CVM_ALGO_FRONTAL || algo == CVM_ALGO_AFLR) {
        p.swap = cvm__opt(m, CVM_OPT_SWAP) != 0;
        p.smooth_sweeps = (int)cvm__opt(m, CVM_OPT_SMOOTH_SWEEPS);
        p.smooth_method = (int)cvm__opt(m, CVM_OPT_SMOOTH_METHOD);
        p.relax_sweeps = (int)cvm__opt(m, CVM_OPT_RELAX_SWEEPS);
        /* -1 (the default): the algorithm's own (refine_internal.h) */
        if (p.smooth_sweeps < 0)
            p.smooth_sweeps = algo == CVM_ALGO_FRONTAL ? CVM__FRONTAL_SMOOTH_SWEEPS
                                                       : CVM__AFLR_SMOOTH_SWEEPS;
        if (p.relax_sweeps < 0)
            p.relax_sweeps = algo == CVM_ALGO_FRONTAL ? CVM__FRONTAL_RELAX_SWEEPS
                                                      : CVM__AFLR_RELAX_SWEEPS;
    }
    if (algo == CVM_ALGO_AFLR)
        p.aflr_smooth_layers = (int)cvm__opt(m, CVM_OPT_AFLR_SMOOTH_LAYERS);
    p.restore_delaunay = cvm__opt(m, CVM_OPT_RESTORE_DELAUNAY) != 0;
    p.sizing = sizing;
    p.nseg = m->in.nseg;
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    /* the automatic length scale and the boundary spacing need the domain */
    if ((s = cvm__sizing_fields_begin(m, sizing, &fields, &p.sizing)) != CVM_OK)
        return s;
    /* CVM_OPT_KEEP_SEGMENT_VERTICES = 0: smooth chains re-discretised, the
       triangulation rebuilt (unchanged when no chain qualifies) */
    if (cvm__opt(m, CVM_OPT_KEEP_SEGMENT_VERTICES) == 0) {
        if (!p.sizing || cvm__sizing_is_empty(p.sizing))
            s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_OPTION,
                           (int64_t)CVM_OPT_KEEP_SEGMENT_VERTICES,
                           "CVM_OPT_KEEP_SEGMENT_VERTICES = 0 re-discretises the segments with "
                           "the sizing: give cvm_mesh_refine() a non-empty sizing");
        else
            s = cvm__mesh_resample_boundary(m, p.sizing, &n_chains);
        if (s != CVM_OK) {
            cvm__sizing_fields_end(m, &fields);
            return s;
        }
    }
    nv0 = cvm__store_nv(m);
    if (m->in.nseg) {
        ends = cvm__malloc(&m->ctx, 2 * m->in.nseg * sizeof *ends);
        if (!ends) {
            cvm__sizing_fields_end(m, &fields);
            return cvm__nomem(&m->ctx);
        }
        for (k = 0; k < 2 * m->in.nseg; k++)
            ends[k] = m->input_map[m->in.seg[k]];
    }
    if (algo == CVM_ALGO_AFLR && refine_front_flags(m, &front)) {
        cvm__sizing_fields_end(m, &fields);
        cvm__free(&m->ctx, ends);
        return cvm__nomem(&m->ctx);
    }
    (void)n_chains; /* how many chains were re-discretised: not reported yet */
    if ((s = refine_regions_begin(m, &region_area)) != CVM_OK) {
        cvm__sizing_fields_end(m, &fields);
        cvm__free(&m->ctx, ends);
        cvm__free(&m->ctx, front);
        return s;
    }
    p.region_area = region_area;
    p.seg_ends = ends;
    p.seg_front = front;
    p.nregion = m->in.nregions;
    s = cvm__refine(cvm__store_tri2(m), &p, &rep);
    refine_regions_end(m, region_area);
    cvm__sizing_fields_end(m, &fields);
    cvm__free(&m->ctx, ends);
    cvm__free(&m->ctx, front);
    m->tlayer = rep.cell_layer;
    m->n_tlayer = rep.cell_layer ? cvm__store_nslots(m) : 0;
    s2 = refine_vertex_data(m, nv0);
    if (s2) {
        /* the vertex arrays cannot follow the kernel: the mesh cannot be kept */
        cvm__free(&m->ctx, rep.unmet);
        cvm__mesh_drop_output(m);
        return cvm__error(&m->ctx, CVM_E_NOMEM, CVM_ENT_NONE, -1,
                          "out of memory after refinement; the mesh was dropped");
    }
    m->refine_report[REP_STEINER] = (double)rep.steiner;
    m->refine_report[REP_UNMET_ANGLE] = (double)rep.unmet_angle;
    m->refine_report[REP_UNMET_SIZE] = (double)rep.unmet_size;
    m->refine_report[REP_SMALL_ANGLE] = (double)rep.small_angle;
    m->refine_report[REP_REQUESTED] = p.min_angle_deg;
    m->refine_report[REP_MET] = rep.met_angle_deg;
    m->refine_unmet = rep.unmet;
    m->n_refine_unmet = rep.n_unmet;
    return s;
}

cvm_status cvm_mesh_refine(cvm_mesh *m, const cvm_sizing *sizing, cvm_algorithm algo)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_refine");
    }
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no triangulation: call cvm_mesh_triangulate() first");
    cvm__mesh_forget_quads(m);
    if (algo != CVM_ALGO_DELAUNAY && algo != CVM_ALGO_FRONTAL && algo != CVM_ALGO_AFLR)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1, "unknown algorithm %d",
                          (int)algo);
    if (algo != CVM_ALGO_AFLR && cvm__opt(m, CVM_OPT_AFLR_SMOOTH_LAYERS) != 0)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_OPTION,
                          (int64_t)CVM_OPT_AFLR_SMOOTH_LAYERS,
                          "CVM_OPT_AFLR_SMOOTH_LAYERS = %.17g smooths between AFLR layers: "
                          "only CVM_ALGO_AFLR has layers (set it to 0 for %s)",
                          cvm__opt(m, CVM_OPT_AFLR_SMOOTH_LAYERS),
                          algo == CVM_ALGO_FRONTAL ? "CVM_ALGO_FRONTAL" : "CVM_ALGO_DELAUNAY");
    if (cvm__sizing_refuse_metric(m, sizing, "cvm_mesh_refine()"))
        return CVM_E_UNSUPPORTED;
    if (cvm__sizing_refuse_3d(m, sizing, "cvm_mesh_refine()"))
        return CVM_E_ARGUMENT;
    memset(m->refine_report, 0, sizeof m->refine_report);
    cvm__free(&m->ctx, m->refine_unmet);
    m->refine_unmet = NULL;
    m->n_refine_unmet = 0;
    return refine_run(m, sizing, algo);
}

cvm_status cvm_mesh_set_front_markers(cvm_mesh *m, const int32_t *markers, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_front_markers");
    }
    int32_t *copy = NULL;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!markers && count > 0)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "markers is NULL");
    if (count) {
        size_t bytes;
        if (!cvm__mul_ok(count, sizeof *copy, &bytes) || !(copy = cvm__malloc(&m->ctx, bytes)))
            return cvm__nomem(&m->ctx);
        memcpy(copy, markers, bytes);
    }
    cvm__free(&m->ctx, m->front_marks);
    m->front_marks = copy;
    m->n_front_marks = count;
    return CVM_OK;
}

cvm_status cvm__refine_measure(double *out, const cvm_mesh *m, cvm_measure which)
{
    switch (which) {
    case CVM_MEASURE_REFINE_STEINER: *out = m->refine_report[REP_STEINER]; return CVM_OK;
    case CVM_MEASURE_REFINE_UNMET_ANGLE: *out = m->refine_report[REP_UNMET_ANGLE]; return CVM_OK;
    case CVM_MEASURE_REFINE_UNMET_SIZE: *out = m->refine_report[REP_UNMET_SIZE]; return CVM_OK;
    case CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE: *out = m->refine_report[REP_SMALL_ANGLE]; return CVM_OK;
    case CVM_MEASURE_REFINE_REQUESTED_ANGLE: *out = m->refine_report[REP_REQUESTED]; return CVM_OK;
    case CVM_MEASURE_REFINE_MET_ANGLE: *out = m->refine_report[REP_MET]; return CVM_OK;
    default: return CVM_E_ARGUMENT;
    }
}

cvm_status cvm_mesh_copy_refine_unmet(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m || (!dst && dst_len > 0))
        return CVM_E_NULL_ARG;
    if (dst_len < 3 * m->n_refine_unmet)
        return CVM_E_BUFFER_TOO_SMALL;
    if (m->n_refine_unmet)
        memcpy(dst, m->refine_unmet, 3 * m->n_refine_unmet * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_layer_index(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    size_t k = 0, nt;
    int32_t t;
    int have;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nt = cvm__mesh_n_triangles(m);
    if ((s = cvm__room(dst, dst_len, nt)))
        return s;
    have = m->tlayer && m->n_tlayer == cvm__store_nslots(m);
    for (t = nt ? cvm__store_next_cell(m, -1) : -1; t >= 0; t = cvm__store_next_cell(m, t))
        dst[k++] = have ? m->tlayer[t] : -1.0;
    return CVM_OK;
}
