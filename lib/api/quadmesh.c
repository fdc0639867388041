/* quadmesh.c - cvm_mesh_quadmesh: the input's convex boundary loop, the lib/quad engine (boundary
 * at unit metric length, Lp-CVT by L-BFGS, Blossom-Quad), the sites' triangulation into the
 * store and the mixed cells and report onto the handle; the built-in metrics of a sizing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "api_internal.h"
#include "quadmesh_internal.h"
#include "store.h"
#include "geom/geom_internal.h"
#include "quad/quad_internal.h"
#include "quad/recombine.h"

cvm_status cvm_sizing_set_metric_builtin(cvm_sizing *s, cvm_metric_builtin kind, double scale)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (kind < CVM_METRIC_IDENTITY || kind > CVM_METRIC_SSHOCK)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "unknown built-in metric %d (1 identity, 2 stretch, 3 saddle, 4 sshock)",
                          (int)kind);
    if (!(scale > 0) || !isfinite(scale))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the scale of a built-in metric must be finite and positive, got %.17g",
                          scale);
    memset(&s->metric_own, 0, sizeof s->metric_own);
    /* the public numbering follows lib/quad's kinds, shifted past CVM__METRIC_CONSTANT */
    s->metric_own.kind = (int)CVM__METRIC_IDENTITY + (int)(kind - CVM_METRIC_IDENTITY);
    s->metric_own.scale = scale;
    return cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &s->metric_own);
}

cvm_status cvm_sizing_set_metric_constant(cvm_sizing *s, double g11, double g12, double g22)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (!isfinite(g11) || !isfinite(g12) || !isfinite(g22))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "the metric (%.17g, %.17g, %.17g) has a non-finite entry", g11, g12, g22);
    if (!(g11 > 0) || !(g11 * g22 - g12 * g12 > 0))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the metric g11 = %.17g, g12 = %.17g, g22 = %.17g is not positive "
                          "definite", g11, g12, g22);
    memset(&s->metric_own, 0, sizeof s->metric_own);
    s->metric_own.kind = (int)CVM__METRIC_CONSTANT;
    s->metric_own.scale = 1;
    s->metric_own.g[0] = g11;
    s->metric_own.g[1] = g12;
    s->metric_own.g[2] = g22;
    return cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &s->metric_own);
}

/* The boundary of the triangulated domain of m as one counter-clockwise loop of vertices
 * (from the lowest vertex id): *loop_out (nv entries, on m's ctx) and, per loop edge, the
 * input segment it lies on (*seg_out). CVM_E_UNSUPPORTED with a message when the domain is not
 * one convex polygon with every vertex on it; CVM_E_NOMEM. */
static cvm_status boundary_loop(cvm_mesh *m, int32_t **loop_out, int32_t **seg_out, size_t *n_out)
{
    size_t nv = cvm__store_nv(m), nb = 0, k, n = 0;
    int32_t *next = cvm__malloc(&m->ctx, (nv + 1) * sizeof *next);
    int32_t *eseg = cvm__malloc(&m->ctx, (nv + 1) * sizeof *eseg);
    int32_t *loop = cvm__malloc(&m->ctx, (nv + 1) * sizeof *loop);
    int32_t t, start = -1, v;
    cvm_status s = CVM_OK;
    *loop_out = *seg_out = NULL;
    if (!next || !eseg || !loop) {
        s = cvm__nomem(&m->ctx);
        goto fail;
    }
    for (k = 0; k < nv; k++)
        next[k] = -1;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        const int32_t *tv = cvm__store_cell(m, (size_t)t);
        int j;
        for (j = 0; j < 3; j++) {
            int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
            if (cvm__store_in_domain(m, cvm__store_across(m, (size_t)t, j)))
                continue;
            if (next[a] >= 0) {
                s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_VERTEX, a,
                               "cvm_mesh_quadmesh: the domain boundary passes twice through vertex "
                               "%ld (%.17g, %.17g): it must be one convex polygon",
                               (long)a, cvm__store_point(m, (size_t)a)[0],
                               cvm__store_point(m, (size_t)a)[1]);
                goto fail;
            }
            next[a] = b;
            eseg[a] = cvm__store_face_segment(m, (size_t)t, j);
            nb++;
            if (start < 0 || a < start)
                start = a;
        }
    }
    for (v = start; v >= 0 && n <= nb; v = next[v]) {
        loop[n++] = v;
        if (next[v] == start)
            break;
    }
    if (start < 0 || n != nb) {
        s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                       "cvm_mesh_quadmesh: the domain boundary is not one closed loop (holes or "
                       "several parts): the quad mesher needs one convex polygon");
        goto fail;
    }
    for (k = 0; k < nv; k++)
        if (next[k] < 0) {
            s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_VERTEX, (int64_t)k,
                           "cvm_mesh_quadmesh: vertex %lu (%.17g, %.17g) lies inside the domain: "
                           "the quad mesher takes only the points of the boundary polygon",
                           (unsigned long)k, cvm__store_point(m, k)[0], cvm__store_point(m, k)[1]);
            goto fail;
        }
    for (k = 0; k < n; k++) {
        const double *a = cvm__store_point(m, (size_t)loop[(k + n - 1) % n]);
        const double *b = cvm__store_point(m, (size_t)loop[k]);
        const double *c = cvm__store_point(m, (size_t)loop[(k + 1) % n]);
        if (cvm__orient2d(a, b, c) < 0) {
            s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_VERTEX, loop[k],
                           "cvm_mesh_quadmesh: the boundary turns right at vertex %ld "
                           "(%.17g, %.17g): the quad mesher needs a convex domain",
                           (long)loop[k], b[0], b[1]);
            goto fail;
        }
    }
    for (k = 0; k < n; k++)
        next[k] = eseg[loop[k]];
    cvm__free(&m->ctx, eseg);
    *loop_out = loop;
    *seg_out = next;
    *n_out = n;
    return CVM_OK;
fail:
    cvm__free(&m->ctx, next);
    cvm__free(&m->ctx, eseg);
    cvm__free(&m->ctx, loop);
    return s;
}


typedef struct qm_side {
    uint64_t key; /* lo << 32 | hi of the side's two points */
    int32_t s;    /* the side: 3 t + j */
} qm_side;

static int qm_side_cmp(const void *a, const void *b)
{
    const qm_side *x = (const qm_side *)a, *y = (const qm_side *)b;
    return x->key != y->key ? (x->key < y->key ? -1 : 1) : (x->s > y->s) - (x->s < y->s);
}

static int32_t qm_next(int32_t s)
{
    return s - s % 3 + (s % 3 + 1) % 3;
}

/* Lawson flips of tri (nt counter-clockwise triangles on m's points) toward the Delaunay
 * triangulation of the points mapped by M0 (z = M0 x), in which the sites were optimised: a
 * flip only of a quad strictly convex in x and in z, by the exact in-circle test in z (so the
 * flips terminate, as Lawson's algorithm on the points z). The store keeps its Delaunay
 * triangulation; only the triangles given to the recombination change. */
static cvm_status flip_in_metric(cvm_mesh *m, int32_t *tri, size_t nt, const double M0[4])
{
    size_t np = cvm__store_nv(m), k, pass, ns = 3 * nt;
    const double *xy = cvm__store_points(m);
    double *z = cvm__malloc(&m->ctx, (2 * np + 1) * sizeof *z);
    qm_side *sd = cvm__malloc(&m->ctx, (ns + 1) * sizeof *sd);
    if (!z || !sd) {
        cvm__free(&m->ctx, z);
        cvm__free(&m->ctx, sd);
        return cvm__nomem(&m->ctx);
    }
    for (k = 0; k < np; k++) {
        z[2 * k] = M0[0] * xy[2 * k] + M0[1] * xy[2 * k + 1];
        z[2 * k + 1] = M0[2] * xy[2 * k] + M0[3] * xy[2 * k + 1];
    }
    for (pass = 0; pass < 1000; pass++) {
        size_t nflip = 0;
        for (k = 0; k < ns; k++) {
            int32_t a = tri[k], b = tri[qm_next((int32_t)k)];
            uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
            sd[k].key = (uint64_t)lo << 32 | hi;
            sd[k].s = (int32_t)k;
        }
        qsort(sd, ns, sizeof *sd, qm_side_cmp);
        for (k = 0; k + 1 < ns; k++) {
            int32_t s1 = sd[k].s, s2 = sd[k + 1].s, a, b, c, d;
            if (sd[k].key != sd[k + 1].key)
                continue;
            a = tri[s1];
            b = tri[qm_next(s1)];
            if (tri[s2] != b || tri[qm_next(s2)] != a)
                continue; /* a flip earlier in this pass changed one of the two */
            c = tri[qm_next(qm_next(s1))];
            d = tri[qm_next(qm_next(s2))];
            if (cvm__orient2d(xy + 2 * c, xy + 2 * a, xy + 2 * d) > 0 &&
                cvm__orient2d(xy + 2 * d, xy + 2 * b, xy + 2 * c) > 0 &&
                cvm__orient2d(z + 2 * c, z + 2 * a, z + 2 * d) > 0 &&
                cvm__orient2d(z + 2 * d, z + 2 * b, z + 2 * c) > 0 &&
                cvm__orient2d(z + 2 * a, z + 2 * b, z + 2 * c) > 0 &&
                cvm__orient2d(z + 2 * b, z + 2 * a, z + 2 * d) > 0 &&
                cvm__incircle(z + 2 * a, z + 2 * b, z + 2 * c, z + 2 * d) > 0) {
                int32_t *t1 = tri + (s1 - s1 % 3), *t2 = tri + (s2 - s2 % 3);
                t1[0] = c;
                t1[1] = a;
                t1[2] = d;
                t2[0] = d;
                t2[1] = b;
                t2[2] = c;
                nflip++;
            }
        }
        if (!nflip)
            break;
    }
    cvm__free(&m->ctx, z);
    cvm__free(&m->ctx, sd);
    return CVM_OK;
}

/* The domain triangles of m as the mixed cells (recombined unless CVM_OPT_QUAD_RECOMBINE 2). */
/* The mixed cells of m's triangles. With all-quad, *split_xy (on m's ctx; the caller frees) and
 * *split_n receive the points the cells then refer to: m's points, then the new ones. */
static cvm_status make_cells(cvm_mesh *m, const cvm__metric *mt, const double *M0,
                             double **split_xy, size_t *split_n)
{
    size_t nt = 0, k;
    int32_t t, *tri = NULL;
    cvm__quad_cells *q;
    cvm__recombine_in in;
    cvm__recombine_out out;
    cvm__qm_metric_cb cb;
    int method = (int)cvm__opt(m, CVM_OPT_QUAD_RECOMBINE);
    cvm_status s = CVM_OK;
    memset(&out, 0, sizeof out);
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t))
        nt++;
    q = cvm__calloc(&m->ctx, 1, sizeof *q);
    tri = cvm__malloc(&m->ctx, (3 * nt + 1) * sizeof *tri);
    if (!q || !tri) {
        cvm__free(&m->ctx, q);
        cvm__free(&m->ctx, tri);
        return cvm__nomem(&m->ctx);
    }
    m->quad = q;
    k = 0;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t), k++)
        memcpy(tri + 3 * k, cvm__store_cell(m, (size_t)t), 3 * sizeof *tri);
    if (method == 2) {
        q->ncell = nt;
        q->nconn = 3 * nt;
        q->off = cvm__malloc(&m->ctx, (nt + 1) * sizeof *q->off);
        q->types = cvm__malloc(&m->ctx, (nt + 1) * sizeof *q->types);
        q->first = cvm__malloc(&m->ctx, (nt + 1) * sizeof *q->first);
        q->quality = cvm__calloc(&m->ctx, nt + 1, sizeof *q->quality);
        if (!q->off || !q->types || !q->first || !q->quality) {
            cvm__free(&m->ctx, tri);
            return cvm__nomem(&m->ctx);
        }
        for (k = 0; k <= nt; k++)
            q->off[k] = (int32_t)(3 * k);
        for (k = 0; k < nt; k++) {
            q->types[k] = CVM_CELL_TRIANGLE;
            q->first[k] = (int32_t)k;
        }
        q->conn = tri;
        return CVM_OK;
    }
    if (M0 && (s = flip_in_metric(m, tri, nt, M0)) != CVM_OK) {
        cvm__free(&m->ctx, tri);
        return s;
    }
    memset(&in, 0, sizeof in);
    cb.mt = mt;
    cb.ctx = &m->ctx;
    in.npts = cvm__store_nv(m);
    in.xy = cvm__store_points(m);
    in.ntri = nt;
    in.tri = tri;
    in.metric = cvm__qm_metric_at;
    in.metric_user = &cb;
    in.min_quality = cvm__opt(m, CVM_OPT_QUAD_MIN_QUALITY);
    in.method = method == 1 ? CVM__RECOMBINE_GREEDY : CVM__RECOMBINE_BLOSSOM;
    in.all_quad = cvm__opt(m, CVM_OPT_QUAD_ALL_QUAD) != 0;
    s = cvm__recombine(&out, &m->ctx, &in);
    cvm__free(&m->ctx, tri);
    if (s)
        return s;
    q->ncell = out.ncell;
    q->nconn = (size_t)out.offsets[out.ncell];
    q->off = out.offsets;
    q->types = out.types;
    q->conn = out.conn;
    q->first = cvm__malloc(&m->ctx, (out.ncell + 1) * sizeof *q->first);
    if (q->first) /* all-quad: one region, and at least as many new triangles as cells */
        for (k = 0; k < out.ncell; k++)
            q->first[k] = in.all_quad ? (int32_t)k : out.source[2 * k];
    q->quality = out.quality;
    cvm__free(&m->ctx, out.source);
    *split_xy = out.xy;
    *split_n = out.npts;
    return q->first ? CVM_OK : cvm__nomem(&m->ctx);
}

/* CVM_OPT_QUAD_MEAN_METRIC_VORONOI: the sites are optimised in z = M0 x, where the metric is
 * pulled back, g'(z) = A^T g(A z) A with A = M0^-1 (row-major 2x2). */
typedef struct qm_pullback {
    cvm__metric x; /* the metric in x, with the boundary in x for its fallback */
    double A[4];
    cvm__ctx *ctx;
} qm_pullback;

static void pull_tensor(const double A[4], const double g[3], double out[3])
{
    double ga0 = g[0] * A[0] + g[1] * A[2], ga1 = g[0] * A[1] + g[1] * A[3]; /* row 0 of gA */
    double gb0 = g[1] * A[0] + g[2] * A[2], gb1 = g[1] * A[1] + g[2] * A[3]; /* row 1 of gA */
    out[0] = A[0] * ga0 + A[2] * gb0;
    out[1] = A[0] * ga1 + A[2] * gb1;
    out[2] = A[1] * ga1 + A[3] * gb1;
}

static int pullback_fn(void *payload, const double *z, int dim, double *g, double *dg)
{
    const qm_pullback *P = (const qm_pullback *)payload;
    double x[2], gx[3], dgx[6], d[3];
    int k, c;
    if (dim != 2)
        return 1;
    x[0] = P->A[0] * z[0] + P->A[1] * z[1];
    x[1] = P->A[2] * z[0] + P->A[3] * z[1];
    if (cvm__metric_eval(&P->x, x, gx, dgx, P->ctx) != CVM_OK)
        return 1;
    pull_tensor(P->A, gx, g);
    if (dg)
        for (k = 0; k < 2; k++) { /* d/dz_k = sum_j d/dx_j A[j][k] */
            for (c = 0; c < 3; c++)
                d[c] = dgx[c] * P->A[k] + dgx[3 + c] * P->A[2 + k];
            pull_tensor(P->A, d, dg + 3 * k);
        }
    return 0;
}

/* M0 (row-major) and its inverse A for the mean metric of the sites xi, scaled to unit
 * determinant; 0 when that metric is a multiple of the identity (no transform). */
static int mean_metric_map(double M0[4], double A[4], const cvm__metric *mt, const double *xi,
                           size_t ni, cvm__ctx *ctx, cvm_status *st)
{
    double gb[3] = {0, 0, 0}, g[3], det;
    size_t k;
    *st = CVM_OK;
    if (ni == 0)
        return 0;
    for (k = 0; k < ni; k++) {
        if ((*st = cvm__metric_eval(mt, xi + 2 * k, g, NULL, ctx)))
            return 0;
        gb[0] += g[0];
        gb[1] += g[1];
        gb[2] += g[2];
    }
    if (gb[1] == 0 && gb[0] == gb[2])
        return 0;
    det = sqrt(gb[0] * gb[2] - gb[1] * gb[1]);
    gb[0] /= det;
    gb[1] /= det;
    gb[2] /= det;
    cvm__metric_factor(M0, NULL, gb, NULL);
    det = M0[0] * M0[3] - M0[1] * M0[2];
    A[0] = M0[3] / det;
    A[1] = -M0[1] / det;
    A[2] = -M0[2] / det;
    A[3] = M0[0] / det;
    return 1;
}

static int thread_count(const cvm_mesh *m)
{
    int n = (int)cvm__opt(m, CVM_OPT_THREADS);
#ifdef _OPENMP
    if (n == 0)
        n = omp_get_max_threads();
#endif
    return n < 1 ? 1 : n;
}

/* CVM_OPT_QUAD_ALL_QUAD: a metric callback times 1/4 (edges twice as long before the split). */
typedef struct qm_scaled {
    cvm_metric_fn fn;
    void *payload;
} qm_scaled;

static int scaled_fn(void *payload, const double *x, int dim, double *g, double *dg)
{
    const qm_scaled *w = (const qm_scaled *)payload;
    int r = w->fn(w->payload, x, dim, g, dg), k;
    for (k = 0; k < 3; k++)
        g[k] *= 0.25;
    for (k = 0; dg && k < 6; k++)
        dg[k] *= 0.25;
    return r;
}

cvm_status cvm_mesh_quadmesh(cvm_mesh *m, const cvm_sizing *metric)
{
    double t0 = cvm__now(), *bxy = NULL, *xi = NULL, *corners = NULL, *zb = NULL, M0[4], A[4];
    double *split_xy = NULL;
    size_t split_n = 0;
    int mapped = 0;
    cvm_sizing zs, hs;
    cvm__metric_builtin hb;
    qm_scaled hw;
    const cvm_sizing *metric0 = metric;
    cvm__metric mt0;
    cvm__metric_builtin zc;
    qm_pullback pb;
    int32_t *loop = NULL, *lseg = NULL;
    size_t nc = 0, nb = 0, ni = 0, kept = 0, k;
    cvm__metric mt;
    cvm__lpcvt L;
    cvm__lbfgs_opts o;
    cvm__lbfgs_result res;
    cvm_progress_fn progress_fn;
    cvm_status s, run = CVM_OK;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (m->m3)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cvm_mesh_quadmesh() meshes 2D domains; this mesh is 3D");
    if (!metric)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "metric is NULL");
    if (!cvm__sizing_has_metric(metric))
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "the sizing has no metric: set one with cvm_sizing_set_metric_fn(), "
                          "cvm_sizing_set_metric_builtin() or cvm_sizing_set_metric_constant()");
    if (cvm__opt(m, CVM_OPT_QUAD_ALL_QUAD) != 0) {
        if (cvm__opt(m, CVM_OPT_QUAD_RECOMBINE) == 2)
            return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "CVM_OPT_QUAD_ALL_QUAD splits the cells of a recombination; "
                              "CVM_OPT_QUAD_RECOMBINE is 2 (none)");
        /* the mesh before the split at twice the size: g / 4 */
        hs = *metric;
        if (metric->metric == cvm__metric_builtin_fn) {
            hb = *(const cvm__metric_builtin *)metric->metric_payload;
            hb.scale *= 0.25;
            hs.metric_payload = &hb;
        } else {
            hw.fn = metric->metric;
            hw.payload = metric->metric_payload;
            hs.metric = scaled_fn;
            hs.metric_payload = &hw;
        }
        metric = &hs;
    }
    memset(&L, 0, sizeof L);
    memset(&res, 0, sizeof res);
    if ((s = cvm_mesh_triangulate(m)) != CVM_OK)
        return s;
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    if ((s = boundary_loop(m, &loop, &lseg, &nc)))
        goto fail;
    corners = cvm__malloc(&m->ctx, 2 * nc * sizeof *corners);
    if (!corners) {
        s = cvm__nomem(&m->ctx);
        goto fail;
    }
    for (k = 0; k < nc; k++)
        memcpy(corners + 2 * k, cvm__store_point(m, (size_t)loop[k]), 2 * sizeof *corners);
    mt.s = metric;
    mt.bnd = corners;
    mt.nbnd = nc;
    mt0 = mt; /* the measures: the metric as given */
    mt0.s = metric0;
    if ((s = cvm__boundary_discretise(&bxy, &nb, &mt, corners, nc, &m->ctx)) ||
        (s = cvm__opt(m, CVM_OPT_QUAD_INITIAL_SITES) == 0
                 ? cvm__lpcvt_frontal_sites(&xi, &ni, &mt, bxy, nb, corners, nc,
                                            (size_t)1 << 30, &m->ctx)
                 : cvm__lpcvt_initial_sites(&xi, &ni, &mt, bxy, nb,
                                            (uint64_t)cvm__opt(m, CVM_OPT_SEED), &m->ctx)))
        goto fail;
    mapped = (int)cvm__opt(m, CVM_OPT_QUAD_MEAN_METRIC_VORONOI);
    if (mapped == 2) /* on where the map is exact: a constant tensor */
        mapped = metric->metric == cvm__metric_builtin_fn &&
                 ((const cvm__metric_builtin *)metric->metric_payload)->kind ==
                     CVM__METRIC_CONSTANT;
    if (mapped && (mapped = mean_metric_map(M0, A, &mt, xi, ni, &m->ctx, &s)) != 0) {
        /* the same problem in z = M0 x: boundary, sites and the metric pulled back */
        zb = cvm__malloc(&m->ctx, 2 * nb * sizeof *zb);
        if (!zb) {
            s = cvm__nomem(&m->ctx);
            goto fail;
        }
        for (k = 0; k < nb; k++) {
            double x = bxy[2 * k], y = bxy[2 * k + 1];
            zb[2 * k] = M0[0] * x + M0[1] * y;
            zb[2 * k + 1] = M0[2] * x + M0[3] * y;
        }
        for (k = 0; k < ni; k++) {
            double x = xi[2 * k], y = xi[2 * k + 1];
            xi[2 * k] = M0[0] * x + M0[1] * y;
            xi[2 * k + 1] = M0[2] * x + M0[3] * y;
        }
        zs = *metric;
        pb.x = mt;
        memcpy(pb.A, A, sizeof pb.A);
        pb.ctx = &m->ctx;
        zs.metric = pullback_fn;
        zs.metric_payload = &pb;
        zs.metric_has_dg = 1;
        if (metric->metric == cvm__metric_builtin_fn &&
            ((const cvm__metric_builtin *)metric->metric_payload)->kind == CVM__METRIC_CONSTANT) {
            /* a constant stays a constant built-in: the closed-form energy */
            const cvm__metric_builtin *c0 = (const cvm__metric_builtin *)metric->metric_payload;
            double g0[3];
            g0[0] = c0->scale * c0->g[0];
            g0[1] = c0->scale * c0->g[1];
            g0[2] = c0->scale * c0->g[2];
            memset(&zc, 0, sizeof zc);
            zc.kind = CVM__METRIC_CONSTANT;
            zc.scale = 1;
            pull_tensor(A, g0, zc.g);
            zs.metric = cvm__metric_builtin_fn;
            zs.metric_payload = &zc;
        }
    } else if (s) {
        goto fail;
    }
    cvm__lbfgs_defaults(&o);
    o.memory = (int)cvm__opt(m, CVM_OPT_QUAD_LBFGS_MEMORY);
    o.gtol = cvm__opt(m, CVM_OPT_QUAD_GRADIENT_TOL);
    o.max_iter = (long)cvm__opt(m, CVM_OPT_QUAD_MAX_ITERATIONS);
    o.relocations = (int)cvm__opt(m, CVM_OPT_QUAD_RELOCATIONS);
    /* the optimisation, then insertion/removal cycles while < 95 % of the sites' sides have
     * unit metric length */
    for (k = 0;; k++) {
        double *xn = NULL, pct;
        size_t nn = 0, nins = 0, nrem = 0;
        cvm__lbfgs_result r;
        cvm__lpcvt_free(&L);
        if ((s = cvm__lpcvt_init(&L, &m->ctx, mapped ? &zs : metric, mapped ? zb : bxy, nb, ni,
                                 (int)cvm__opt(m, CVM_OPT_QUAD_P),
                                 (int)cvm__opt(m, CVM_OPT_QUAD_CLIP))))
            goto fail;
        L.cellwise = cvm__opt(m, CVM_OPT_QUAD_CELLWISE_METRIC) != 0;
        L.threads = thread_count(m);
        if (ni == 0)
            break;
        memset(&r, 0, sizeof r);
        s = cvm__lpcvt_optimise(&L, xi, &o, &r);
        r.iterations += res.iterations;
        r.evaluations += res.evaluations;
        r.restarts += res.restarts;
        res = r;
        if (s == CVM_INCOMPLETE_TIME_LIMIT || s == CVM_INCOMPLETE_CANCELLED) {
            run = s; /* the sites so far make a valid mesh */
            cvm__clear_error(&m->ctx);
            break;
        } else if (s) {
            goto fail;
        }
        if (k >= (size_t)cvm__opt(m, CVM_OPT_QUAD_CYCLES))
            break;
        if ((s = cvm__lpcvt_adapt_sites(&L, xi, &xn, &nn, &nins, &nrem, &pct)))
            goto fail;
        if (!xn || pct >= 95 || nn == 0) {
            cvm__free(&m->ctx, xn);
            break;
        }
        cvm__free(&m->ctx, xi);
        xi = xn;
        ni = nn;
    }
    for (k = 0; mapped && k < ni; k++) { /* back to x; build_triangulation drops any outside */
        double z0 = xi[2 * k], z1 = xi[2 * k + 1];
        xi[2 * k] = A[0] * z0 + A[1] * z1;
        xi[2 * k + 1] = A[2] * z0 + A[3] * z1;
    }
    /* the rest is short and is not interrupted: a stop leaves the sites reached so far */
    progress_fn = m->ctx.progress_fn;
    m->ctx.progress_fn = NULL;
    cvm__run_begin(&m->ctx, 0);
    s = cvm__qm_triangulate_sites(m, loop, lseg, nc, bxy, nb, xi, ni, &kept);
    if (!s) {
        m->triangulated = 1;
        m->nv_triangulated = cvm__store_nv(m);
        s = make_cells(m, &mt, mapped ? M0 : NULL, &split_xy, &split_n);
    }
    if (!s && split_xy) { /* all-quad: the new points join the sites, triangulated again */
        double *bxy2 = NULL, *xi2 = NULL;
        size_t nb2 = 0, ni2 = 0;
        s = cvm__qm_adopt_split(m, loop, lseg, nc, bxy, nb, kept, split_xy, split_n, &bxy2, &nb2,
                                &xi2, &ni2, &kept);
        cvm__free(&m->ctx, split_xy);
        split_xy = NULL;
        if (!s) {
            cvm__free(&m->ctx, bxy);
            cvm__free(&m->ctx, xi);
            bxy = bxy2;
            nb = nb2;
            xi = xi2;
            ni = ni2;
        }
    }
    if (!s && m->quad && cvm__opt(m, CVM_OPT_QUAD_SMOOTH) > 0)
        s = cvm__qm_smooth_cells(m, &mt, loop, lseg, nc, bxy, nb, xi, ni, kept);
    if (!s)
        s = cvm__quad_measures(m->quad_report, &mt0, cvm__store_points(m), m->quad->ncell,
                               m->quad->off, m->quad->types, m->quad->conn, &m->ctx);
    m->ctx.progress_fn = progress_fn;
    if (s)
        goto fail;
    m->quad_report[CVM_REPORT_QUAD_ENERGY - 800] = res.f;
    m->quad_report[CVM_REPORT_QUAD_GRADIENT_INF - 800] = res.gnorm_inf;
    m->quad_report[CVM_REPORT_QUAD_ITERATIONS - 800] = (double)res.iterations;
    m->quad_report[CVM_REPORT_QUAD_EVALUATIONS - 800] = (double)res.evaluations;
    for (k = 0; k < m->quad->ncell; k++)
        m->quad_report[m->quad->types[k] == CVM_CELL_QUAD ? CVM_REPORT_QUAD_QUADS - 800
                                                          : CVM_REPORT_QUAD_TRIANGLES - 800] += 1;
    m->quad_report[CVM_REPORT_QUAD_INTERIOR_SITES - 800] = (double)kept;
    m->quad_report[CVM_REPORT_QUAD_BOUNDARY_SITES - 800] = (double)nb;
    m->quad_report[CVM_REPORT_QUAD_SECONDS - 800] = cvm__now() - t0;
    s = run == CVM_OK ? CVM_OK
                      : cvm__error(&m->ctx, run, CVM_ENT_NONE, -1,
                                   "quad meshing %s after %ld L-BFGS iterations; the mesh of the "
                                   "sites reached so far is valid",
                                   run == CVM_INCOMPLETE_CANCELLED ? "cancelled"
                                                                   : "stopped at the time limit",
                                   res.iterations);
    goto done;
fail:
    if (s == CVM_INCOMPLETE_TIME_LIMIT || s == CVM_INCOMPLETE_CANCELLED) {
        /* stopped before there were sites to keep: no mesh, as a stopped triangulation */
        s = cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "quad meshing %s before the optimisation; "
                       "no mesh", s == CVM_INCOMPLETE_CANCELLED ? "cancelled" : "stopped at the "
                       "time limit");
    }
    cvm__mesh_drop_output(m);
done:
    cvm__lpcvt_free(&L);
    cvm__free(&m->ctx, bxy);
    cvm__free(&m->ctx, xi);
    cvm__free(&m->ctx, corners);
    cvm__free(&m->ctx, zb);
    cvm__free(&m->ctx, split_xy);
    cvm__free(&m->ctx, loop);
    cvm__free(&m->ctx, lseg);
    return s;
}

cvm_status cvm__quad_report(double *out, const cvm_mesh *m, int which)
{
    if (which < (int)CVM_REPORT_QUAD_PCT || which > (int)CVM_REPORT_QUAD_BOUNDARY_SITES)
        return CVM_E_ARGUMENT;
    *out = m->quad_report[which - (int)CVM_REPORT_QUAD_PCT];
    return CVM_OK;
}
