/* lpcvt_optimise.c - the initial sites of the Lp-CVT from the metric density and their
 * optimisation by L-BFGS. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quad_internal.h"

/* sqrt(det g) at y. */
static cvm_status density(double *out, const cvm__metric *mt, const double *y, cvm__ctx *ctx)
{
    double g[3];
    cvm_status st = cvm__metric_eval(mt, y, g, NULL, ctx);
    if (!st)
        *out = sqrt(g[0] * g[2] - g[1] * g[1]);
    return st;
}

static cvm_status rule_on(double *out, double *rmax, const cvm__metric *mt, const double *a,
                          const double *b, const double *c, int deg, cvm__ctx *ctx)
{
    size_t n, q;
    int d;
    const double (*r)[4] = cvm__dunavant_rule(deg, &n, &d);
    double s = 0, area = 0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    cvm_status st;
    for (q = 0; q < n; q++) {
        double y[2], rho;
        y[0] = r[q][0] * a[0] + r[q][1] * b[0] + r[q][2] * c[0];
        y[1] = r[q][0] * a[1] + r[q][1] * b[1] + r[q][2] * c[1];
        if ((st = density(&rho, mt, y, ctx)))
            return st;
        *rmax = fmax(*rmax, rho);
        s += r[q][3] * rho;
    }
    *out = area * s;
    return CVM_OK;
}

static cvm_status tri_area(double *out, double *rmax, const cvm__metric *mt, const double *a,
                           const double *b, const double *c, int depth, cvm__ctx *ctx)
{
    double lo, hi, ab[2], bc[2], ca[2], s[4];
    cvm_status st;
    if ((st = rule_on(&lo, rmax, mt, a, b, c, 8, ctx)) || (st = rule_on(&hi, rmax, mt, a, b, c, 12, ctx)))
        return st;
    if (fabs(hi - lo) <= 1e-6 * fabs(hi) || depth >= 8) {
        *out = hi;
        return CVM_OK;
    }
    ab[0] = 0.5 * (a[0] + b[0]);
    ab[1] = 0.5 * (a[1] + b[1]);
    bc[0] = 0.5 * (b[0] + c[0]);
    bc[1] = 0.5 * (b[1] + c[1]);
    ca[0] = 0.5 * (c[0] + a[0]);
    ca[1] = 0.5 * (c[1] + a[1]);
    if ((st = tri_area(s, rmax, mt, a, ab, ca, depth + 1, ctx)) ||
        (st = tri_area(s + 1, rmax, mt, ab, b, bc, depth + 1, ctx)) ||
        (st = tri_area(s + 2, rmax, mt, ca, bc, c, depth + 1, ctx)) ||
        (st = tri_area(s + 3, rmax, mt, ab, bc, ca, depth + 1, ctx)))
        return st;
    *out = s[0] + s[1] + s[2] + s[3];
    return CVM_OK;
}

cvm_status cvm__metric_area(double *area, double *rho_max, const cvm__metric *mt, const double *bxy,
                            size_t nb, cvm__ctx *ctx)
{
    size_t k;
    cvm_status st;
    *area = 0;
    *rho_max = 0;
    for (k = 1; k + 1 < nb; k++) {
        double a;
        if ((st = tri_area(&a, rho_max, mt, bxy, bxy + 2 * k, bxy + 2 * (k + 1), 0, ctx)))
            return st;
        *area += a;
    }
    return CVM_OK;
}

/* The radical inverse of i in base b (the Halton coordinate). */
static double radical_inverse(uint64_t i, unsigned b)
{
    double f = 1, r = 0;
    while (i > 0) {
        f /= b;
        r += f * (double)(i % b);
        i /= b;
    }
    return r;
}

cvm_status cvm__lpcvt_initial_sites(double **xi_out, size_t *ni_out, const cvm__metric *mt,
                                    const double *bxy, size_t nb, uint64_t seed, cvm__ctx *ctx)
{
    cvm__lpcvt box; /* only its boundary, for the exact inside test */
    cvm__rng rng;
    double A, rmax, lo[2], hi[2], shift[3], *xi;
    size_t k, n, got = 0;
    uint64_t i;
    cvm_status st;
    *xi_out = NULL;
    *ni_out = 0;
    if ((st = cvm__metric_area(&A, &rmax, mt, bxy, nb, ctx)))
        return st;
    A = floor(A - 0.5 * (double)nb + 1 + 0.5);
    if (!(A < 1e9))
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "the metric asks for %.6g interior sites", A);
    n = A > 0 ? (size_t)A : 0;
    xi = cvm__malloc(ctx, (2 * n + 1) * sizeof *xi);
    if (!xi)
        return cvm__nomem(ctx);
    memset(&box, 0, sizeof box);
    box.xy = (double *)bxy;
    box.nb = nb;
    lo[0] = hi[0] = bxy[0];
    lo[1] = hi[1] = bxy[1];
    for (k = 1; k < nb; k++) {
        lo[0] = fmin(lo[0], bxy[2 * k]);
        hi[0] = fmax(hi[0], bxy[2 * k]);
        lo[1] = fmin(lo[1], bxy[2 * k + 1]);
        hi[1] = fmax(hi[1], bxy[2 * k + 1]);
    }
    cvm__rng_seed(&rng, seed);
    for (k = 0; k < 3; k++)
        shift[k] = cvm__rng_uniform(&rng);
    /* a sample is accepted with probability rho / rmax; rmax came from the area's quadrature
     * points, a point above it is always accepted */
    for (i = 1; got < n && i < ((uint64_t)1 << 40); i++) {
        double u = fmod(radical_inverse(i, 2) + shift[0], 1.0);
        double v = fmod(radical_inverse(i, 3) + shift[1], 1.0);
        double w = fmod(radical_inverse(i, 5) + shift[2], 1.0), p[2], rho;
        p[0] = lo[0] + u * (hi[0] - lo[0]);
        p[1] = lo[1] + v * (hi[1] - lo[1]);
        if (!cvm__lpcvt_inside(&box, p))
            continue;
        if ((st = density(&rho, mt, p, ctx))) {
            cvm__free(ctx, xi);
            return st;
        }
        if (w * rmax < rho) {
            xi[2 * got] = p[0];
            xi[2 * got + 1] = p[1];
            got++;
        }
    }
    *xi_out = xi;
    *ni_out = got;
    return CVM_OK;
}

static cvm_status eval_fn(void *payload, const double *x, double *f, double *g, int *valid)
{
    cvm__lpcvt *L = (cvm__lpcvt *)payload;
    cvm_status st = cvm__lpcvt_eval(L, x, f, g);
    *valid = L->valid;
    return st;
}

/* Sites ordered by cell energy, then index (a total order: qsort is not stable). */
typedef struct by_energy {
    double e;
    size_t i;
} by_energy;

static int cmp_energy(const void *a, const void *b)
{
    const by_energy *x = (const by_energy *)a, *y = (const by_energy *)b;
    if (x->e != y->e)
        return x->e < y->e ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

/* Most energy first, then index. */
static int cmp_energy_desc(const void *a, const void *b)
{
    const by_energy *x = (const by_energy *)a, *y = (const by_energy *)b;
    if (x->e != y->e)
        return x->e > y->e ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

/* Half-way from site hi to the farthest vertex of its cell into p; 0 when that is not inside. */
static int target_in(const cvm__lpcvt *L, size_t hi, double *p)
{
    double far = -1;
    size_t k;
    for (k = L->cstart[hi]; k < L->cstart[hi + 1]; k++) {
        const cvm__pvert *v = L->pv + k;
        const double *q = v->kind == CVM__PV_FIXED ? v->off : L->cc + 2 * v->t;
        double d = hypot(q[0] - L->xy[2 * hi], q[1] - L->xy[2 * hi + 1]);
        if (d > far) {
            far = d;
            p[0] = 0.5 * (q[0] + L->xy[2 * hi]);
            p[1] = 0.5 * (q[1] + L->xy[2 * hi + 1]);
        }
    }
    return far > 0 && cvm__lpcvt_inside(L, p);
}

/* The relocation of a local minimum (see quad_internal.h): the nmove moving sites of least cell
 * energy into the nmove cells of most energy (ties to the lower index; each site into one cell),
 * or 0 when none moved. With nmove 1 a target outside the domain stops the relocations; with
 * more the next cell is tried. ord: scratch of 2 L->ns entries. */
static int relocate(cvm__lpcvt *L, double *xi, by_energy *ord, size_t nmove)
{
    by_energy *up = ord, *down = ord + L->ns;
    size_t i, lo = 0, hi = 0, moved = 0, nm = L->ns - L->nb;
    uint8_t *taken = L->cstat; /* per site: already moved, or already a target */
    for (i = 0; i < L->ns; i++) {
        up[i].e = down[i].e = L->ecell[i];
        up[i].i = down[i].i = i;
        taken[i] = 0;
    }
    qsort(up, L->ns, sizeof *up, cmp_energy);
    qsort(down, L->ns, sizeof *down, cmp_energy_desc);
    while (moved < nmove && moved < (nm + 1) / 2) {
        size_t s, c;
        double p[2];
        while (lo < L->ns && (up[lo].i < L->nb || taken[up[lo].i]))
            lo++;
        while (hi < L->ns && taken[down[hi].i])
            hi++;
        if (lo >= L->ns || hi >= L->ns)
            break;
        s = up[lo].i;
        c = down[hi++].i;
        if (s == c)
            break;
        if (!target_in(L, c, p)) {
            if (nmove == 1)
                break;
            continue;
        }
        xi[2 * (s - L->nb)] = p[0];
        xi[2 * (s - L->nb) + 1] = p[1];
        taken[s] = taken[c] = 1;
        moved++;
    }
    return moved > 0;
}

static void add_result(cvm__lbfgs_result *sum, const cvm__lbfgs_result *r)
{
    long it = sum->iterations + r->iterations, ev = sum->evaluations + r->evaluations;
    long rs = sum->restarts + r->restarts;
    *sum = *r;
    sum->iterations = it;
    sum->evaluations = ev;
    sum->restarts = rs;
}

cvm_status cvm__lpcvt_optimise(cvm__lpcvt *L, double *xi, const cvm__lbfgs_opts *o,
                               cvm__lbfgs_result *res)
{
    cvm__lbfgs_opts opt = *o;
    cvm__lbfgs_result r;
    double lo[2], hi[2], *keep, E;
    by_energy *ord;
    size_t k, n = 2 * (L->ns - L->nb);
    int move;
    cvm_status st;
    lo[0] = hi[0] = L->xy[0];
    lo[1] = hi[1] = L->xy[1];
    for (k = 1; k < L->nb; k++) {
        lo[0] = fmin(lo[0], L->xy[2 * k]);
        hi[0] = fmax(hi[0], L->xy[2 * k]);
        lo[1] = fmin(lo[1], L->xy[2 * k + 1]);
        hi[1] = fmax(hi[1], L->xy[2 * k + 1]);
    }
    opt.length = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    opt.step0 = INFINITY;
    for (k = 0; k < L->nb; k++) {
        const double *a = L->xy + 2 * k, *b = L->xy + 2 * ((k + 1) % L->nb);
        opt.step0 = fmin(opt.step0, 0.25 * hypot(b[0] - a[0], b[1] - a[1]));
    }
    if ((st = cvm__lbfgs_minimise(xi, n, eval_fn, L, &opt, res, L->ctx)) || o->relocations <= 0 ||
        n == 0) {
        for (k = 0; k < n / 2 && !st; k++)
            res->outside += !cvm__lpcvt_inside(L, xi + 2 * k);
        return st;
    }
    keep = cvm__malloc(L->ctx, n * sizeof *keep);
    ord = cvm__malloc(L->ctx, 2 * L->ns * sizeof *ord);
    if (!keep || !ord) {
        cvm__free(L->ctx, keep);
        cvm__free(L->ctx, ord);
        return cvm__nomem(L->ctx);
    }
    for (move = 0; move < o->relocations; move++) {
        memcpy(keep, xi, n * sizeof *xi);
        /* the cell energies and polygons of the minimum; one site moves per 256 moving sites, so
         * a round is worth its re-optimisation on a large mesh */
        if ((st = cvm__lpcvt_eval(L, xi, &E, NULL)) || !L->valid ||
            !relocate(L, xi, ord, 1 + (n / 2) / 256))
            break;
        if ((st = cvm__lbfgs_minimise(xi, n, eval_fn, L, &opt, &r, L->ctx)) &&
            st != CVM_E_ARGUMENT)
            break;
        if (st || !(r.f < res->f - 1e-9 * fabs(res->f))) {
            /* undefined there (CVM_E_ARGUMENT: the start), or no better: undo and stop */
            memcpy(xi, keep, n * sizeof *xi);
            st = CVM_OK;
            cvm__clear_error(L->ctx);
            break;
        }
        add_result(res, &r);
    }
    cvm__free(L->ctx, keep);
    cvm__free(L->ctx, ord);
    for (k = 0; k < n / 2; k++)
        res->outside += !cvm__lpcvt_inside(L, xi + 2 * k);
    return st;
}
