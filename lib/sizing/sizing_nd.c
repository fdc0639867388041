/* sizing_nd.c - the dimension-generic calls of the cvm_sizing handle (positions as arrays of the
 * mesh's dimension) and its metric (tensor) source. */
#include <math.h>

#include "sizing_internal.h"

/* The checks the positional calls below start with: a handle (whose message is then cleared),
 * the array x (named name in the message), dim 2 or 3. */
static cvm_status begin_nd(cvm_sizing *s, const double *x, const char *name, int dim, const char *call)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (!x)
        return cvm__error(&s->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "%s is NULL", name);
    if (dim != 2 && dim != 3)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%s: dim must be 2 or 3, got %d", call, dim);
    return CVM_OK;
}

cvm_status cvm_sizing_add_point_source_nd(cvm_sizing *s, const double *x, int dim, double h,
                                          double growth)
{
    cvm_status st = begin_nd(s, x, "x", dim, "cvm_sizing_add_point_source_nd");
    return st ? st : cvm__sizing_add_point(s, x, dim, h, growth);
}

cvm_status cvm_sizing_add_line_source_nd(cvm_sizing *s, const double *ends, int dim, double h,
                                         double growth)
{
    cvm_status st = begin_nd(s, ends, "ends", dim, "cvm_sizing_add_line_source_nd");
    return st ? st : cvm__sizing_add_line(s, ends, dim, h, growth);
}

cvm_status cvm_sizing_add_triangle_source_nd(cvm_sizing *s, const double *corners, int dim,
                                             double h, double growth)
{
    cvm_status st = begin_nd(s, corners, "corners", dim, "cvm_sizing_add_triangle_source_nd");
    return st ? st : cvm__sizing_add_tri(s, corners, dim, h, growth);
}

cvm_status cvm_sizing_set_background_nd(cvm_sizing *s, const double *xh, size_t npoints, int dim,
                                        const cvm_index *cells, size_t ncells)
{
    cvm_status st;
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (dim != 2 && dim != 3)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "cvm_sizing_set_background_nd: dim must be 2 or 3, got %d", dim);
    if (dim == 2)
        return cvm_sizing_set_background(s, xh, npoints, cells, ncells);
    if (npoints == 0 && ncells == 0) {
        cvm__background3_free(s->bg3, &s->ctx);
        s->bg3 = NULL;
        cvm__sizing_recount_dim(s);
        return CVM_OK;
    }
    if (!xh || (!cells && ncells > 0))
        return cvm__error(&s->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1,
                          "background mesh: xh or cells is NULL");
    if (npoints > (size_t)INT32_MAX / 4 || ncells > (size_t)INT32_MAX / 4)
        return cvm__error(&s->ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "background mesh: %zu nodes and %zu tetrahedra exceed what cvm_index "
                          "can address",
                          npoints, ncells);
    if ((st = cvm__sizing_check_dim(s, 3, "background mesh")))
        return st;
    return cvm__background3_set(s, xh, npoints, cells, ncells);
}

cvm_status cvm_sizing_set_callback_nd(cvm_sizing *s, cvm_sizing_nd_fn fn, void *payload)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    s->fn = NULL; /* one user function per handle */
    s->fn_batch = NULL;
    s->fn_nd = fn;
    s->fn_payload = fn ? payload : NULL;
    return CVM_OK;
}

cvm_status cvm_sizing_eval_nd(double *out, cvm_sizing *s, const double *x, int dim)
{
    cvm_status st;
    if (!out)
        return CVM_E_NULL_ARG;
    st = begin_nd(s, x, "x", dim, "cvm_sizing_eval_nd");
    if (st)
        return st;
    if (dim == 2) {
        if ((st = cvm__sizing_check_dim(s, 2, "cvm_sizing_eval_nd")))
            return st;
        return cvm_sizing_eval(out, s, x[0], x[1]);
    }
    if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "position (%.17g, %.17g, %.17g) is not finite", x[0], x[1], x[2]);
    if ((st = cvm__sizing_check3(s, &s->ctx, "cvm_sizing_eval_nd", 0)))
        return st;
    return cvm__sizing_at3(s, x, out, &s->ctx);
}

cvm_status cvm_sizing_set_metric_fn(cvm_sizing *s, cvm_metric_fn fn, int has_derivatives,
                                    void *payload)
{
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (has_derivatives != 0 && has_derivatives != 1)
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "has_derivatives must be 0 or 1, got %d", has_derivatives);
    s->metric = fn;
    s->metric_payload = fn ? payload : NULL;
    s->metric_has_dg = fn ? has_derivatives : 0;
    return CVM_OK;
}

int cvm__sizing_has_metric(const cvm_sizing *s)
{
    return s && s->metric;
}

cvm_status cvm_sizing_eval_metric(double *dst, size_t dst_len, cvm_sizing *s, const double *x,
                                  int dim)
{
    double g[3] = {0, 0, 0};
    int k;
    cvm_status st;
    if (!s)
        return CVM_E_NULL_ARG;
    cvm__clear_error(&s->ctx);
    if (!x)
        return cvm__error(&s->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "x is NULL");
    if (!dst && dst_len > 0)
        return cvm__error(&s->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "dst is NULL");
    if ((st = cvm__check_dim(&s->ctx, dim, "cvm_sizing_eval_metric")))
        return st;
    if (!s->metric)
        return cvm__error(&s->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "the sizing has no metric: set one with cvm_sizing_set_metric_fn()");
    if (dst_len < 3)
        return cvm__error(&s->ctx, CVM_E_BUFFER_TOO_SMALL, CVM_ENT_NONE, -1,
                          "dst holds %lu values; a 2D metric has 3 (g11, g12, g22)",
                          (unsigned long)dst_len);
    if (!isfinite(x[0]) || !isfinite(x[1]))
        return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                          "position (%.17g, %.17g) is not finite", x[0], x[1]);
    if (s->metric(s->metric_payload, x, 2, g, NULL) != 0)
        return cvm__error(&s->ctx, CVM_E_INPUT_OUTSIDE, CVM_ENT_NONE, -1,
                          "the metric callback refused the point (%.17g, %.17g)", x[0], x[1]);
    for (k = 0; k < 3; k++)
        if (!isfinite(g[k]))
            return cvm__error(&s->ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                              "the metric callback returned a non-finite entry %d at "
                              "(%.17g, %.17g)", k, x[0], x[1]);
    /* Sylvester's criterion; a measure check on plain doubles, not a topological decision */
    if (!(g[0] > 0) || !(g[0] * g[2] - g[1] * g[1] > 0))
        return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "the metric at (%.17g, %.17g) is not positive definite: g11 = %.17g, "
                          "g12 = %.17g, g22 = %.17g",
                          x[0], x[1], g[0], g[1], g[2]);
    for (k = 0; k < 3; k++)
        dst[k] = g[k];
    return CVM_OK;
}
