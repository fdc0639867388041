/* lpcvt_topo.c - the set-up of an Lp-CVT energy and, per configuration, its Delaunay topology and
 * the polygon of every Voronoi cell (interior, reconstructed or clipped boundary cells). */
#include <math.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "quad_internal.h"

void cvm__lpcvt_free(cvm__lpcvt *L)
{
    cvm__ctx *c = L->ctx;
    if (!c)
        return;
    cvm__free(c, L->xy);
    cvm__free(c, L->bmid);
    cvm__free(c, L->seg);
    cvm__tri2_destroy(&L->T);
    cvm__free(c, L->co.input_map);
    cvm__free(c, L->co.vmark);
    cvm__free(c, L->co.vattr);
    cvm__free(c, L->cstart);
    cvm__free(c, L->copen);
    cvm__free(c, L->pv);
    cvm__free(c, L->cc);
    cvm__free(c, L->gcc);
    cvm__free(c, L->gpv);
    cvm__free(c, L->gsite);
    cvm__free(c, L->ecell);
    cvm__free(c, L->cstat);
    cvm__free(c, L->star);
    memset(L, 0, sizeof *L);
}

static double cross2(const double *u, const double *v)
{
    return u[0] * v[1] - u[1] * v[0];
}

/* The offset from boundary site b to a ghost: unit metric length (metric g at b) along the
 * outward normal of the boundary edge from a to c. */
static void ghost_offset(const double *a, const double *c, const double g[3], double off[2])
{
    double e[2], n[2], l;
    e[0] = c[0] - a[0];
    e[1] = c[1] - a[1];
    l = hypot(e[0], e[1]);
    n[0] = e[1] / l; /* the domain lies on the left of a->c: outward is its right */
    n[1] = -e[0] / l;
    l = sqrt(n[0] * n[0] * g[0] + 2 * n[0] * n[1] * g[1] + n[1] * n[1] * g[2]);
    off[0] = n[0] / l;
    off[1] = n[1] / l;
}

/* The ghost sites of the reconstruction (see quad_internal.h), appended to L->xy. */
static cvm_status make_ghosts(cvm__lpcvt *L, const double *bxy)
{
    size_t nb = L->nb, k, ng = 0;
    double *gx;
    cvm_status st;
    gx = cvm__malloc(L->ctx, (6 * nb + 8) * sizeof *gx);
    if (!gx)
        return cvm__nomem(L->ctx);
    for (k = 0; k < nb; k++) {
        const double *a = bxy + 2 * ((k + nb - 1) % nb), *b = bxy + 2 * k, *c = bxy + 2 * ((k + 1) % nb);
        double u[2], v[2], g[3], oa[2], ob[2];
        if ((st = cvm__metric_eval(&L->metric, b, g, NULL, L->ctx))) {
            cvm__free(L->ctx, gx);
            return st;
        }
        ghost_offset(b, c, g, oa); /* A: off the edge to the next site */
        ghost_offset(a, b, g, ob); /* B: off the edge from the previous one */
        u[0] = b[0] - a[0];
        u[1] = b[1] - a[1];
        v[0] = c[0] - b[0];
        v[1] = c[1] - b[1];
        if (cross2(u, v) > 1e-9 * hypot(u[0], u[1]) * hypot(v[0], v[1])) {
            /* C = A + s v on the line through B along u: cross(A + s v - B, u) = 0 */
            double A[2], B[2], d[2], s;
            A[0] = b[0] + oa[0];
            A[1] = b[1] + oa[1];
            B[0] = b[0] + ob[0];
            B[1] = b[1] + ob[1];
            d[0] = B[0] - A[0];
            d[1] = B[1] - A[1];
            s = cross2(d, u) / cross2(v, u);
            gx[2 * ng] = A[0];
            gx[2 * ng + 1] = A[1];
            gx[2 * ng + 2] = A[0] + s * v[0];
            gx[2 * ng + 3] = A[1] + s * v[1];
            gx[2 * ng + 4] = B[0];
            gx[2 * ng + 5] = B[1];
            ng += 3;
        } else {
            gx[2 * ng] = b[0] + 0.5 * (oa[0] + ob[0]);
            gx[2 * ng + 1] = b[1] + 0.5 * (oa[1] + ob[1]);
            ng++;
        }
    }
    { /* a far frame, so that a moving site pushed past the ghosts still has a bounded (and
       * costly) cell and the line search gets a value and a slope back, not a hole */
        double lo[2], hi[2], c[2], R;
        lo[0] = hi[0] = gx[0];
        lo[1] = hi[1] = gx[1];
        for (k = 1; k < ng; k++) {
            lo[0] = fmin(lo[0], gx[2 * k]);
            hi[0] = fmax(hi[0], gx[2 * k]);
            lo[1] = fmin(lo[1], gx[2 * k + 1]);
            hi[1] = fmax(hi[1], gx[2 * k + 1]);
        }
        c[0] = 0.5 * (lo[0] + hi[0]);
        c[1] = 0.5 * (lo[1] + hi[1]);
        R = 3 * fmax(hi[0] - lo[0], hi[1] - lo[1]);
        for (k = 0; k < 4; k++) {
            gx[2 * ng] = c[0] + (k == 1 || k == 2 ? R : -R);
            gx[2 * ng + 1] = c[1] + (k >= 2 ? R : -R);
            ng++;
        }
    }
    L->nall = L->ns + ng;
    L->xy = cvm__malloc(L->ctx, 2 * L->nall * sizeof *L->xy);
    if (L->xy)
        memcpy(L->xy + 2 * L->ns, gx, 2 * ng * sizeof *gx);
    cvm__free(L->ctx, gx);
    return L->xy ? CVM_OK : cvm__nomem(L->ctx);
}

cvm_status cvm__lpcvt_init(cvm__lpcvt *L, cvm__ctx *ctx, const cvm_sizing *s, const double *bxy,
                           size_t nb, size_t ni, int p, int clip)
{
    double area = 0;
    size_t k, ns = nb + ni;
    int deg;
    cvm_status st;
    memset(L, 0, sizeof *L);
    L->ctx = ctx;
    cvm__tri2_init(&L->T, ctx);
    if (p < 2 || p > 12 || p % 2)
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the Lp-CVT exponent p must be even, 2 to 12; got %d", p);
    if (nb < 3)
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the boundary needs 3 vertices or more, got %lu", (unsigned long)nb);
    L->p = p;
    L->clip = clip ? 1 : 0;
    L->threads = 1;
    L->rule = cvm__dunavant_rule(p, &L->nq, &deg);
    L->nb = nb;
    L->ns = ns;
    L->nall = ns;
    L->metric.s = s;
    L->metric.bnd = bxy;
    L->metric.nbnd = nb;
    for (k = 0; k < nb; k++)
        area += cross2(bxy + 2 * k, bxy + 2 * ((k + 1) % nb));
    for (k = 0; k < nb && area > 0; k++) {
        const double *a = bxy + 2 * ((k + nb - 1) % nb), *b = bxy + 2 * k, *c = bxy + 2 * ((k + 1) % nb);
        double u[2], v[2];
        u[0] = b[0] - a[0];
        u[1] = b[1] - a[1];
        v[0] = c[0] - b[0];
        v[1] = c[1] - b[1];
        /* convexity of fixed input: a tolerance for the rounding of subdivided straight edges */
        if (cross2(u, v) < -1e-12 * hypot(u[0], u[1]) * hypot(v[0], v[1]) || (!u[0] && !u[1]))
            return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_VERTEX, (int64_t)k,
                              "boundary vertex %lu (%.17g, %.17g) makes the boundary non-convex or "
                              "repeats a vertex: the Lp-CVT boundary must be convex",
                              (unsigned long)k, b[0], b[1]);
    }
    if (!(area > 0))
        return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the boundary polygon is not counter-clockwise (signed area %.17g)",
                          0.5 * area);
    if (s && s->metric == cvm__metric_builtin_fn &&
        (((const cvm__metric_builtin *)s->metric_payload)->kind == CVM__METRIC_CONSTANT ||
         ((const cvm__metric_builtin *)s->metric_payload)->kind == CVM__METRIC_IDENTITY)) {
        double dM[8];
        if ((st = cvm__metric_eval_M(&L->metric, bxy, L->Mc, dM, ctx)))
            return st;
        L->mconst = 1;
    }
    if (!clip && (st = make_ghosts(L, bxy)))
        return st;
    if (clip)
        L->xy = cvm__malloc(ctx, 2 * ns * sizeof *L->xy);
    L->bmid = cvm__malloc(ctx, 4 * nb * sizeof *L->bmid);
    L->seg = cvm__malloc(ctx, 2 * nb * sizeof *L->seg);
    L->cstart = cvm__malloc(ctx, (ns + 1) * sizeof *L->cstart);
    L->copen = cvm__malloc(ctx, ns);
    L->gsite = cvm__malloc(ctx, 2 * L->nall * sizeof *L->gsite);
    L->ecell = cvm__malloc(ctx, ns * sizeof *L->ecell);
    L->cstat = cvm__malloc(ctx, ns);
    if (!L->xy || !L->bmid || !L->seg || !L->cstart || !L->copen || !L->gsite || !L->ecell ||
        !L->cstat)
        return cvm__nomem(ctx);
    memcpy(L->xy, bxy, 2 * nb * sizeof *L->xy);
    for (k = 0; k < nb; k++) {
        const double *a = bxy + 2 * ((k + nb - 1) % nb), *b = bxy + 2 * k, *c = bxy + 2 * ((k + 1) % nb);
        L->bmid[4 * k] = 0.5 * (b[0] + c[0]);
        L->bmid[4 * k + 1] = 0.5 * (b[1] + c[1]);
        L->bmid[4 * k + 2] = 0.5 * (a[0] + b[0]);
        L->bmid[4 * k + 3] = 0.5 * (a[1] + b[1]);
        L->seg[2 * k] = (int32_t)k;
        L->seg[2 * k + 1] = (int32_t)((k + 1) % nb);
    }
    return CVM_OK;
}

/* 1 when p lies strictly inside the convex boundary polygon (exact orientations; a binary
 * search for the wedge of the fan from boundary vertex 0 that holds p). */
int cvm__lpcvt_inside(const cvm__lpcvt *L, const double *p)
{
    return cvm__lpcvt_inside_polygon(L->xy, L->nb, p);
}

int cvm__lpcvt_inside_polygon(const double *b, size_t nb, const double *p)
{
    size_t lo = 1, hi = nb - 1;
    if (cvm__orient2d(b, b + 2, p) <= 0 || cvm__orient2d(b + 2 * hi, b, p) <= 0)
        return 0;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (cvm__orient2d(b, b + 2 * mid, p) > 0)
            lo = mid;
        else
            hi = mid;
    }
    return cvm__orient2d(b + 2 * lo, b + 2 * hi, p) > 0;
}

static cvm_status push_pv(cvm__lpcvt *L, int kind, int32_t t, const double *off)
{
    cvm__pvert *v;
    if (L->npv == L->cap_pv &&
        cvm__grow(L->ctx, (void **)&L->pv, &L->cap_pv, L->npv + 1, sizeof *L->pv))
        return cvm__nomem(L->ctx);
    v = L->pv + L->npv++;
    memset(v, 0, sizeof *v);
    v->kind = kind;
    v->t = t;
    if (off) {
        v->off[0] = off[0];
        v->off[1] = off[1];
    }
    return CVM_OK;
}

/* The live triangles around v, counter-clockwise, into L->star; *n_out how many. */
static cvm_status star_of(cvm__lpcvt *L, int32_t v, size_t *n_out)
{
    size_t n = cvm__tri2_star(&L->T, v, L->star, L->cap_star);
    if (n > L->cap_star) {
        if (cvm__grow(L->ctx, (void **)&L->star, &L->cap_star, n, sizeof *L->star))
            return cvm__nomem(L->ctx);
        n = cvm__tri2_star(&L->T, v, L->star, L->cap_star);
    }
    *n_out = n;
    return CVM_OK;
}

/* The clipped polygon of boundary site b: the midpoint of its edge to the next site, its
 * in-domain triangles counter-clockwise, the midpoint of the edge from the previous site. */
static cvm_status clipped_cell(cvm__lpcvt *L, int32_t b)
{
    const cvm__tri2 *T = &L->T;
    size_t n = 0, k, first = 0, cnt = 0;
    cvm_status st;
    if ((st = star_of(L, b, &n)))
        return st;
    for (k = 0; k < n; k++) /* the run starts after a triangle outside the domain */
        if (cvm__tri2_in_domain(T, L->star[k]) && !cvm__tri2_in_domain(T, L->star[(k + n - 1) % n])) {
            first = k;
            cnt++;
        }
    if (cnt != 1) /* no in-domain triangle, or two runs: the boundary is not convex there */
        return cvm__error(L->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, b,
                          "Lp-CVT: boundary site %ld has %lu runs of domain triangles", (long)b,
                          (unsigned long)cnt);
    if ((st = push_pv(L, CVM__PV_FIXED, -1, L->bmid + 4 * b)))
        return st;
    for (k = 0; k < n && cvm__tri2_in_domain(T, L->star[(first + k) % n]); k++)
        if ((st = push_pv(L, CVM__PV_CC, L->star[(first + k) % n], NULL)))
            return st;
    return push_pv(L, CVM__PV_FIXED, -1, L->bmid + 4 * b + 2);
}

/* 1 when the triangulation of the last valid topology is still the Delaunay triangulation of the
 * sites now in L->xy (copied into it): every real triangle strictly counter-clockwise and every
 * edge between two real triangles locally Delaunay under the builder's own perturbed in-circle
 * test (exact, one global perturbation: the triangulation it defines is unique, so the builder
 * would make the same triangles). The hull is the fixed far frame. Reconstruction only. */
static int lpcvt_still_delaunay(cvm__lpcvt *L)
{
    cvm__tri2 *T = &L->T;
    size_t t;
    memcpy(T->xy + 2 * L->nb, L->xy + 2 * L->nb, 2 * (L->ns - L->nb) * sizeof *T->xy);
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        int j;
        if (!cvm__tri2_is_live(T, (int32_t)t) || cvm__tri2_is_ghost(T, (int32_t)t))
            continue;
        if (!(cvm__orient2d(T->xy + 2 * v[0], T->xy + 2 * v[1], T->xy + 2 * v[2]) > 0))
            return 0;
        for (j = 0; j < 3; j++) {
            int32_t h = T->tn[3 * t + j], u = h / 3, d = T->tv[h];
            if (u <= (int32_t)t || cvm__tri2_is_ghost(T, u))
                continue; /* each edge once; hull edges are the frame's */
            if (cvm__incircle_sos(T->xy + 2 * v[0], T->xy + 2 * v[1], T->xy + 2 * v[2],
                                  T->xy + 2 * d, v[0], v[1], v[2], d) > 0)
                return 0;
        }
    }
    return 1;
}

cvm_status cvm__lpcvt_topology(cvm__lpcvt *L, const double *xi)
{
    cvm__cdt_input in;
    cvm__cdt_fault fault;
    size_t i, k, n = 0, ns = L->ns;
    cvm_status st;
    memcpy(L->xy + 2 * L->nb, xi, 2 * (ns - L->nb) * sizeof *xi);
    L->valid = 0;
    for (i = 0; i < 2 * (ns - L->nb); i++)
        if (!isfinite(xi[i])) {
            L->kept = 0;
            return CVM_OK;
        }
    if (L->kept && !L->clip && lpcvt_still_delaunay(L)) {
        L->valid = 1; /* the same triangles, so the same cell polygons */
        return CVM_OK;
    }
    L->kept = 0;
    L->npv = 0;
    /* clipping needs the sites in the domain; with ghosts the energy is defined (and pushes them
     * back) as long as every cell is bounded */
    for (i = L->nb; i < ns && L->clip; i++)
        if (!cvm__lpcvt_inside(L, L->xy + 2 * i))
            return CVM_OK;
    memset(&in, 0, sizeof in);
    in.xy = L->xy;
    in.np = L->nall;
    in.seg = L->seg;
    in.nseg = L->clip ? L->nb : 0;
    in.seed = 1;
    memset(&fault, 0, sizeof fault);
    cvm__tri2_clear(&L->T);
    st = cvm__cdt_build(&L->T, &in, &L->co, &fault);
    if (fault.kind != CVM__CDT_FAULT_NONE || L->co.n_dup > 0 || (!st && L->T.nv != L->nall))
        return CVM_OK; /* two sites at one point: no energy here */
    if (st)
        return st;
    for (i = 0; i < L->nall; i++)
        if (L->co.input_map[i] != (int32_t)i)
            return cvm__error(L->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, (int64_t)i,
                              "Lp-CVT: site %lu is vertex %ld of the triangulation", (unsigned long)i,
                              (long)L->co.input_map[i]);
    if ((2 * L->T.nt > L->cap_cc &&
         cvm__grow(L->ctx, (void **)&L->cc, &L->cap_cc, 2 * L->T.nt, sizeof *L->cc)) ||
        (2 * L->T.nt > L->cap_gcc &&
         cvm__grow(L->ctx, (void **)&L->gcc, &L->cap_gcc, 2 * L->T.nt, sizeof *L->gcc)))
        return cvm__nomem(L->ctx);
    for (i = 0; i < ns; i++) {
        L->cstart[i] = L->npv;
        L->copen[i] = i < L->nb && L->clip;
        if (L->copen[i]) {
            if ((st = clipped_cell(L, (int32_t)i)))
                return st;
            continue;
        }
        if ((st = star_of(L, (int32_t)i, &n)))
            return st;
        for (k = 0; k < n; k++) {
            if (!cvm__tri2_in_domain(&L->T, L->star[k])) {
                if (i < L->nb) /* fixed sites and ghosts only: the ghosts fail the boundary */
                    return cvm__error(L->ctx, CVM_E_ARGUMENT, CVM_ENT_VERTEX, (int64_t)i,
                                      "Lp-CVT: the ghost sites leave the cell of boundary site "
                                      "%lu (%.17g, %.17g) unbounded", (unsigned long)i,
                                      L->xy[2 * i], L->xy[2 * i + 1]);
                return CVM_OK; /* a moving site beyond the ghosts: undefined */
            }
            if ((st = push_pv(L, CVM__PV_CC, L->star[k], NULL)))
                return st;
        }
    }
    L->cstart[ns] = L->npv;
    if (2 * L->npv > L->cap_gpv &&
        cvm__grow(L->ctx, (void **)&L->gpv, &L->cap_gpv, 2 * L->npv, sizeof *L->gpv))
        return cvm__nomem(L->ctx);
    L->valid = 1;
    L->kept = 1;
    return CVM_OK;
}
