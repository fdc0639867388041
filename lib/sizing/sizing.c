/* sizing.c - the cvm_sizing handle: uniform, point, line, triangle and callback sizes combined by
 * their minimum, evaluated in 2D. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sizing_internal.h"

cvm_status cvm_sizing_create(cvm_sizing **out)
{
    cvm__ctx proto;
    cvm_sizing *s;
    if (!out)
        return CVM_E_NULL_ARG;
    *out = NULL;
    cvm__ctx_init_default(&proto);
    s = cvm__malloc(&proto, sizeof *s);
    if (!s)
        return CVM_E_NOMEM;
    memset(s, 0, sizeof *s);
    s->ctx = proto;
    *out = s;
    return CVM_OK;
}

void cvm_sizing_free(cvm_sizing *s)
{
    cvm__ctx ctx;
    if (!s)
        return;
    ctx = s->ctx;
    cvm__free(&ctx, s->pts);
    cvm__free(&ctx, s->lines);
    cvm__free(&ctx, s->tris);
    cvm__background_free(s->bg, &ctx);
    cvm__background3_free(s->bg3, &ctx);
    cvm__free(&ctx, s);
}

const char *cvm_sizing_errmsg(const cvm_sizing *s)
{
    if (!s)
        return "no sizing handle";
    return s->ctx.errmsg;
}

/* A size h and growth g of source `what` k (k < 0: no index) must be valid. */
static cvm_status check_size(cvm_sizing *s, const char *what, long k, double h, double g)
{
    char name[64];
    if (k >= 0)
        snprintf(name, sizeof name, "%s %ld", what, k);
    else
        snprintf(name, sizeof name, "%s", what);
    if (!isfinite(h))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, k,
                          "%s has a non-finite size (must be positive and finite)", name);
    if (!(h > 0))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, k,
                          "%s has size %.17g (must be positive and finite)", name, h);
    if (!isfinite(g))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, k,
                          "%s has a non-finite growth (must be finite and >= 0)", name);
    if (g < 0)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, k,
                          "%s has growth %.17g (must be finite and >= 0)", name, g);
    return CVM_OK;
}

static cvm_status check_position(cvm_sizing *s, const char *what, long k, const double *v,
                                 size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, k,
                              "%s %ld has a non-finite coordinate", what, k);
    return CVM_OK;
}

cvm_status cvm_sizing_set_uniform(cvm_sizing *s, double h)
{
    cvm_status st;
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if ((st = check_size(s, "uniform size", -1, h, 0.0)))
        return st;
    s->has_uniform = 1;
    s->uniform = h;
    return CVM_OK;
}

/* The checks of a new source of kind what (index k) with n coordinates v in
 * dimension dim. */
static cvm_status check_source(cvm_sizing *s, const char *what, long k, const double *v, size_t n,
                               int dim, double h, double growth)
{
    char call[64];
    cvm_status st;
    snprintf(call, sizeof call, "%s %ld", what, k);
    if ((st = cvm__sizing_check_dim(s, dim, call)) || (st = check_position(s, what, k, v, n)))
        return st;
    return check_size(s, what, k, h, growth);
}

cvm_status cvm__sizing_add_point(cvm_sizing *s, const double *x, int dim, double h, double growth)
{
    cvm__point_source *q;
    long k = (long)s->npts;
    cvm_status st;
    if ((st = check_source(s, "point source", k, x, (size_t)dim, dim, h, growth)))
        return st;
    if (cvm__grow(&s->ctx, (void **)&s->pts, &s->cap_pts, s->npts + 1, sizeof *s->pts))
        return cvm__nomem(&s->ctx);
    q = s->pts + s->npts++;
    q->x = x[0];
    q->y = x[1];
    q->z = dim == 3 ? x[2] : 0.0;
    q->h = h;
    q->growth = growth;
    s->dim = dim;
    return CVM_OK;
}

cvm_status cvm_sizing_add_point_source(cvm_sizing *s, double x, double y, double h, double growth)
{
    double xy[2];
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    xy[0] = x;
    xy[1] = y;
    return cvm__sizing_add_point(s, xy, 2, h, growth);
}

cvm_status cvm__sizing_add_line(cvm_sizing *s, const double *ends, int dim, double h,
                                double growth)
{
    cvm__line_source *l;
    long k = (long)s->nlines;
    cvm_status st;
    if ((st = check_source(s, "line source", k, ends, 2 * (size_t)dim, dim, h, growth)))
        return st;
    if (cvm__grow(&s->ctx, (void **)&s->lines, &s->cap_lines, s->nlines + 1, sizeof *s->lines))
        return cvm__nomem(&s->ctx);
    l = s->lines + s->nlines++;
    l->x0 = ends[0];
    l->y0 = ends[1];
    l->z0 = dim == 3 ? ends[2] : 0.0;
    l->x1 = ends[dim];
    l->y1 = ends[dim + 1];
    l->z1 = dim == 3 ? ends[5] : 0.0;
    l->h = h;
    l->growth = growth;
    s->dim = dim;
    return CVM_OK;
}

cvm_status cvm_sizing_add_line_source(cvm_sizing *s, double x0, double y0, double x1, double y1,
                                      double h, double growth)
{
    double v[4];
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    v[0] = x0;
    v[1] = y0;
    v[2] = x1;
    v[3] = y1;
    return cvm__sizing_add_line(s, v, 2, h, growth);
}

cvm_status cvm__sizing_add_tri(cvm_sizing *s, const double *corners, int dim, double h,
                               double growth)
{
    cvm__tri_source *t;
    long k = (long)s->ntris;
    int c;
    cvm_status st;
    if ((st = check_source(s, "triangle source", k, corners, 3 * (size_t)dim, dim, h, growth)))
        return st;
    if (cvm__grow(&s->ctx, (void **)&s->tris, &s->cap_tris, s->ntris + 1, sizeof *s->tris))
        return cvm__nomem(&s->ctx);
    t = s->tris + s->ntris++;
    for (c = 0; c < 3; c++) {
        t->p[3 * c] = corners[dim * c];
        t->p[3 * c + 1] = corners[dim * c + 1];
        t->p[3 * c + 2] = dim == 3 ? corners[dim * c + 2] : 0.0;
    }
    t->h = h;
    t->growth = growth;
    s->dim = dim;
    return CVM_OK;
}

cvm_status cvm_sizing_set_callback(cvm_sizing *s, cvm_sizing_fn fn, void *payload)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    s->fn = fn;
    s->fn_nd = NULL;
    s->fn_batch = NULL;
    s->fn_payload = fn ? payload : NULL;
    return CVM_OK;
}

cvm_status cvm_sizing_set_batch_callback(cvm_sizing *s, cvm_sizing_batch_fn fn, void *payload)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    s->fn = NULL;
    s->fn_nd = NULL;
    s->fn_batch = fn;
    s->fn_payload = fn ? payload : NULL;
    return CVM_OK;
}

cvm_status cvm_sizing_set_automatic(cvm_sizing *s, double R, double G)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (R == 0 && G == 0) {
        s->has_auto = 0;
        return CVM_OK;
    }
    if (!isfinite(R) || !isfinite(G))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "automatic sizing: R = %.17g and G = %.17g must be finite", R, G);
    if (!(R > 0))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "automatic sizing: refinement parameter R = %.17g (must be positive)", R);
    if (!(G > 0))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "automatic sizing: grading G = %.17g (must be positive)", G);
    s->has_auto = 1;
    s->auto_R = R;
    s->auto_G = G;
    return CVM_OK;
}

cvm_status cvm_sizing_set_boundary_grading(cvm_sizing *s, double g)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (!isfinite(g))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "boundary grading: slope g = %.17g must be finite", g);
    if (g < 0)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "boundary grading: slope g = %.17g (must be positive, or 0 for off)", g);
    s->bgrad = g;
    return CVM_OK;
}

int cvm__sizing_is_empty(const cvm_sizing *s)
{
    return !s || (!s->has_uniform && s->npts == 0 && s->nlines == 0 && s->ntris == 0 && !s->fn &&
                  !s->fn_nd && !s->fn_batch && !s->has_auto && !s->bg && !s->bg3 &&
                  !(s->bgrad > 0));
}

/* Distance from p to the segment a-b (a point when a == b). */
static double dist_segment(double px, double py, const cvm__line_source *l)
{
    double dx = l->x1 - l->x0, dy = l->y1 - l->y0;
    double len2 = dx * dx + dy * dy, t = 0;
    double qx, qy;
    if (len2 > 0) {
        t = ((px - l->x0) * dx + (py - l->y0) * dy) / len2;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
    }
    qx = l->x0 + t * dx - px;
    qy = l->y0 + t * dy - py;
    return sqrt(qx * qx + qy * qy);
}

/* The user function's size d at (x, y) must be positive and finite. */
static cvm_status check_user_size(double d, double x, double y, cvm__ctx *err)
{
    if (!isfinite(d))
        return cvm__error(err, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "the sizing callback returned a non-finite size at (%.17g, %.17g)", x, y);
    if (!(d > 0))
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the sizing callback returned size %.17g at (%.17g, %.17g) (must "
                          "be positive and finite)",
                          d, x, y);
    return CVM_OK;
}

/* Ask the batch callback for the n <= CVM__SIZING_BATCH points xy and lower
 * h[0..n-1] to its sizes. */
static cvm_status batch_below(const cvm_sizing *s, const double *xy, size_t n, double *h,
                              cvm__ctx *err)
{
    double d[CVM__SIZING_BATCH];
    size_t i;
    cvm_status st;
    int rc = s->fn_batch(s->fn_payload, xy, n, d);
    if (rc)
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the sizing callback failed (returned %d) for a batch of %lu points "
                          "from (%.17g, %.17g)",
                          rc, (unsigned long)n, xy[0], xy[1]);
    for (i = 0; i < n; i++) {
        if ((st = check_user_size(d[i], xy[2 * i], xy[2 * i + 1], err)))
            return st;
        if (d[i] < h[i])
            h[i] = d[i];
    }
    return CVM_OK;
}

/* The size of every source but the user function at (x, y). */
static double sources_at(const cvm_sizing *s, double x, double y)
{
    double best = HUGE_VAL;
    size_t i;
    if (s->has_uniform)
        best = s->uniform;
    for (i = 0; i < s->npts; i++) {
        const cvm__point_source *q = s->pts + i;
        double d = q->h + q->growth * hypot(x - q->x, y - q->y);
        if (d < best)
            best = d;
    }
    for (i = 0; i < s->nlines; i++) {
        const cvm__line_source *l = s->lines + i;
        double d = l->h + l->growth * dist_segment(x, y, l);
        if (d < best)
            best = d;
    }
    for (i = 0; i < s->ntris; i++) {
        const cvm__tri_source *t = s->tris + i;
        double p[3], d;
        p[0] = x;
        p[1] = y;
        p[2] = 0;
        d = t->h + t->growth * cvm__dist_point_tri3(p, t->p);
        if (d < best)
            best = d;
    }
    if (s->bg) {
        double d = cvm__background_at(s->bg, x, y);
        if (d < best)
            best = d;
    }
    if (s->autof)
        best = cvm__auto_field_below(s->autof, x, y, best);
    if (s->spacingf)
        best = cvm__auto_field_below(s->spacingf, x, y, best);
    return best;
}

cvm_status cvm__sizing_at(const cvm_sizing *s, double x, double y, double *h, cvm__ctx *err)
{
    double p[2], best, d;
    cvm_status st;
    if (!s) {
        *h = HUGE_VAL;
        return CVM_OK;
    }
    best = sources_at(s, x, y);
    p[0] = x;
    p[1] = y;
    if (s->fn_batch) {
        if ((st = batch_below(s, p, 1, &best, err)))
            return st;
    } else if (s->fn || s->fn_nd) {
        d = s->fn ? s->fn(s->fn_payload, x, y) : s->fn_nd(s->fn_payload, p, 2);
        if ((st = check_user_size(d, x, y, err)))
            return st;
        if (d < best)
            best = d;
    }
    *h = best;
    return CVM_OK;
}

cvm_status cvm__sizing_at_many(const cvm_sizing *s, const double *xy, size_t n, double *h,
                               cvm__ctx *err)
{
    size_t i, k, m;
    cvm_status st;
    if (!s || !s->fn_batch) {
        for (i = 0; i < n; i++)
            if ((st = cvm__sizing_at(s, xy[2 * i], xy[2 * i + 1], h + i, err)))
                return st;
        return CVM_OK;
    }
    for (i = 0; i < n; i++)
        h[i] = sources_at(s, xy[2 * i], xy[2 * i + 1]);
    for (k = 0; k < n; k += m) {
        m = n - k < CVM__SIZING_BATCH ? n - k : CVM__SIZING_BATCH;
        if ((st = batch_below(s, xy + 2 * k, m, h + k, err)))
            return st;
    }
    return CVM_OK;
}

cvm_status cvm_sizing_eval(double *out, cvm_sizing *s, double x, double y)
{
    if (!out || !s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (!isfinite(x) || !isfinite(y))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "position (%.17g, %.17g) is not finite", x, y);
    if (cvm__sizing_check_dim(s, 2, "cvm_sizing_eval"))
        return s->ctx.status;
    return cvm__sizing_at(s, x, y, out, &s->ctx);
}
