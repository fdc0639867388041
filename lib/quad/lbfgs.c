/* lbfgs.c - quasi-Newton minimisation for the quad mesher through Debian's liblbfgs (Okazaki's
 * C port of Nocedal's L-BFGS), behind one internal call so another backend changes no caller. */
#include <lbfgs.h>
#include <math.h>
#include <string.h>

#include "quad_internal.h"

typedef struct run {
    cvm__minimise_fn fn;
    void *payload;
    const cvm__lbfgs_opts *o;
    cvm__ctx *ctx;
    double scale;        /* x = scale z: liblbfgs works on z */
    double *x;           /* scratch: x of the z being evaluated */
    cvm_status st;       /* the first error of fn, or a stop of the run control */
    double f_valid;      /* the last defined value: the scale of the penalty */
    long iter, evals;
    int converged;
} run;

static lbfgsfloatval_t evaluate(void *inst, const lbfgsfloatval_t *x, lbfgsfloatval_t *g,
                                const int n, const lbfgsfloatval_t step)
{
    run *r = (run *)inst;
    double f = 0;
    int valid = 0, k;
    (void)step;
    r->evals++;
    for (k = 0; k < n; k++)
        r->x[k] = r->scale * x[k];
    if (r->st == CVM_OK)
        r->st = r->fn(r->payload, r->x, &f, g, &valid);
    if (r->st != CVM_OK || !valid) {
        /* undefined there (or stopping): a value above every defined one, no slope, so the line
         * search shortens its step */
        for (k = 0; k < n; k++)
            g[k] = 0;
        return 1e3 * (fabs(r->f_valid) + 1);
    }
    r->f_valid = f;
    for (k = 0; k < n; k++)
        g[k] *= r->scale;
    return f;
}

static int progress(void *inst, const lbfgsfloatval_t *x, const lbfgsfloatval_t *g,
                    const lbfgsfloatval_t fx, const lbfgsfloatval_t xnorm,
                    const lbfgsfloatval_t gnorm, const lbfgsfloatval_t step, int n, int k, int ls)
{
    run *r = (run *)inst;
    double ginf = 0;
    int i;
    (void)x;
    (void)xnorm;
    (void)gnorm;
    (void)step;
    (void)k;
    (void)ls;
    r->iter++;
    if (r->st != CVM_OK)
        return 1;
    for (i = 0; i < n; i++)
        ginf = fmax(ginf, fabs(g[i]) / r->scale);
    if (ginf <= r->o->gtol * fabs(fx) / r->o->length) {
        r->converged = 1;
        return 1;
    }
    if ((r->st = cvm__tick(r->ctx, 1, CVM_STAGE_QUAD_OPTIMISE, 0)) != CVM_OK)
        return 1;
    return r->o->max_iter > 0 && r->iter >= r->o->max_iter;
}

void cvm__lbfgs_defaults(cvm__lbfgs_opts *o)
{
    o->memory = 8;
    o->max_iter = 10000;
    o->gtol = 1e-10;
    o->length = 1;
    o->delta = 1e-12;
    o->past = 10;
    o->relocations = 8;
    o->step0 = 1;
}

static double inf_norm(const double *g, size_t n)
{
    double m = 0;
    size_t k;
    for (k = 0; k < n; k++)
        m = fmax(m, fabs(g[k]));
    return m;
}

cvm_status cvm__lbfgs_minimise(double *x, size_t n, cvm__minimise_fn fn, void *payload,
                               const cvm__lbfgs_opts *o, cvm__lbfgs_result *res, cvm__ctx *ctx)
{
    lbfgs_parameter_t prm;
    run r;
    double f = 0, f_restart, *g;
    size_t k;
    int valid = 0, ret;
    cvm_status st;
    memset(res, 0, sizeof *res);
    memset(&r, 0, sizeof r);
    r.fn = fn;
    r.payload = payload;
    r.o = o;
    r.ctx = ctx;
    r.scale = o->step0 > 0 ? o->step0 : 1;
    g = cvm__malloc(ctx, (n ? n : 1) * sizeof *g);
    r.x = cvm__malloc(ctx, (n ? n : 1) * sizeof *r.x);
    if (!g || !r.x) {
        cvm__free(ctx, g);
        cvm__free(ctx, r.x);
        return cvm__nomem(ctx);
    }
    if ((st = fn(payload, x, &f, g, &valid)) || !valid) {
        cvm__free(ctx, g);
        cvm__free(ctx, r.x);
        return st ? st
                  : cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                               "the starting point of the minimisation is outside the domain of "
                               "the energy (sites off the domain or on one another)");
    }
    r.f_valid = f;
    res->evaluations = 1;
    lbfgs_parameter_init(&prm);
    prm.m = o->memory;
    prm.epsilon = 0; /* the gradient test is ours (progress) */
    prm.past = o->past;
    prm.delta = o->delta;
    prm.linesearch = LBFGS_LINESEARCH_MORETHUENTE;
    res->stop = CVM__LBFGS_LINE_SEARCH;
    for (;;) {
        if (inf_norm(g, n) <= o->gtol * fabs(f) / o->length) {
            res->stop = CVM__LBFGS_GRADIENT;
            break;
        }
        f_restart = f;
        r.converged = 0;
        for (k = 0; k < n; k++)
            x[k] /= r.scale;
        ret = lbfgs((int)n, x, &f, evaluate, progress, &r, &prm);
        for (k = 0; k < n; k++)
            x[k] *= r.scale;
        res->backend_code = ret;
        if (r.st != CVM_OK) {
            st = r.st;
            res->stop = CVM__LBFGS_TIME;
            break;
        }
        if (ret == LBFGSERR_OUTOFMEMORY) {
            st = cvm__nomem(ctx);
            break;
        }
        /* x is the last accepted iterate (liblbfgs reverts a failed line search) */
        if ((st = fn(payload, x, &f, g, &valid)))
            break;
        res->evaluations++;
        if (r.converged) {
            res->stop = CVM__LBFGS_GRADIENT;
            break;
        }
        if (ret == LBFGS_STOP) {
            res->stop = o->max_iter > 0 && r.iter >= o->max_iter ? CVM__LBFGS_ITERATIONS
                                                                  : CVM__LBFGS_DECREASE;
            break;
        }
        if (ret >= 0 || ret == LBFGSERR_MAXIMUMITERATION) {
            res->stop = CVM__LBFGS_ITERATIONS;
            break;
        }
        /* a failed line search: restart the memory, unless nothing improved since the last one */
        if (!(f < f_restart)) {
            res->stop = CVM__LBFGS_LINE_SEARCH;
            break;
        }
        res->restarts++;
    }
    res->f = f;
    res->gnorm_inf = inf_norm(g, n);
    res->iterations = r.iter;
    res->evaluations += r.evals;
    cvm__free(ctx, g);
    cvm__free(ctx, r.x);
    return st;
}
