/* sizing3.c - the cvm_sizing handle evaluated in 3D: point, line and triangle distances, the
 * size at a point, its least value and the boxes where it can fall below a bound. */
#include <math.h>

#include "sizing_internal.h"

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double cvm__dist_point_seg3(const double *p, const double *a, const double *b)
{
    double d[3], w[3], len2, t = 0, q[3];
    int k;
    for (k = 0; k < 3; k++) {
        d[k] = b[k] - a[k];
        w[k] = p[k] - a[k];
    }
    len2 = dot3(d, d);
    if (len2 > 0) {
        t = dot3(w, d) / len2;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
    }
    for (k = 0; k < 3; k++)
        q[k] = w[k] - t * d[k];
    return sqrt(dot3(q, q));
}

/* The closest point of a triangle to p is its projection onto the plane when
 * that falls inside, else on one of its edges. Plain doubles: a size, not a
 * topological decision. */
double cvm__dist_point_tri3(const double *p, const double *t)
{
    const double *a = t, *b = t + 3, *c = t + 6;
    double e1[3], e2[3], n[3], w[3], nn, dn, best;
    int k, inside = 1;
    for (k = 0; k < 3; k++) {
        e1[k] = b[k] - a[k];
        e2[k] = c[k] - a[k];
        w[k] = p[k] - a[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    nn = dot3(n, n);
    if (nn > 0) {
        /* the projection is inside when it lies left of each edge, seen along n */
        const double *v[3];
        v[0] = a;
        v[1] = b;
        v[2] = c;
        for (k = 0; k < 3 && inside; k++) {
            const double *u = v[k], *z = v[(k + 1) % 3];
            double ez[3], wz[3], cr[3];
            int j;
            for (j = 0; j < 3; j++) {
                ez[j] = z[j] - u[j];
                wz[j] = p[j] - u[j];
            }
            cr[0] = ez[1] * wz[2] - ez[2] * wz[1];
            cr[1] = ez[2] * wz[0] - ez[0] * wz[2];
            cr[2] = ez[0] * wz[1] - ez[1] * wz[0];
            inside = dot3(cr, n) >= 0;
        }
        if (inside) {
            dn = dot3(w, n);
            return fabs(dn) / sqrt(nn);
        }
    }
    best = cvm__dist_point_seg3(p, a, b);
    best = fmin(best, cvm__dist_point_seg3(p, b, c));
    return fmin(best, cvm__dist_point_seg3(p, c, a));
}

cvm_status cvm__sizing_check3(const cvm_sizing *s, cvm__ctx *err, const char *call, int meshing)
{
    if (!s)
        return CVM_OK;
    if (s->dim == 2)
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%s: the sizing holds 2D sources (%s); 3D needs sources added with "
                          "dim 3",
                          call, s->npts ? "point sources" : s->nlines ? "line sources"
                                        : s->ntris ? "triangle sources" : "a background mesh");
    if (s->fn || s->fn_batch)
        return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%s: the sizing callback takes 2D positions; set a 3D one with "
                          "cvm_sizing_set_callback_nd()",
                          call);
    if (!meshing)
        return CVM_OK; /* evaluation reads neither the automatic field nor the metric */
    if (s->has_auto)
        return cvm__error(err, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "%s: the automatic sizing (cvm_sizing_set_automatic()) is 2D only in "
                          "this version; turn it off with cvm_sizing_set_automatic(s, 0, 0)",
                          call);
    if (s->metric)
        return cvm__error(err, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "%s: no 3D call of this version meshes to a metric (tensor) source; "
                          "remove it with cvm_sizing_set_metric_fn(s, NULL, 0, NULL)",
                          call);
    return CVM_OK;
}

cvm_status cvm__sizing_at3(const cvm_sizing *s, const double *x, double *h, cvm__ctx *err)
{
    double best = HUGE_VAL, d;
    size_t i;
    if (!s) {
        *h = HUGE_VAL;
        return CVM_OK;
    }
    if (s->has_uniform)
        best = s->uniform;
    for (i = 0; i < s->npts; i++) {
        const cvm__point_source *q = s->pts + i;
        double c[3];
        c[0] = q->x;
        c[1] = q->y;
        c[2] = q->z;
        d = q->h + q->growth * cvm__dist_point_seg3(x, c, c);
        best = d < best ? d : best;
    }
    for (i = 0; i < s->nlines; i++) {
        const cvm__line_source *l = s->lines + i;
        double a[3], b[3];
        a[0] = l->x0;
        a[1] = l->y0;
        a[2] = l->z0;
        b[0] = l->x1;
        b[1] = l->y1;
        b[2] = l->z1;
        d = l->h + l->growth * cvm__dist_point_seg3(x, a, b);
        best = d < best ? d : best;
    }
    for (i = 0; i < s->ntris; i++) {
        const cvm__tri_source *t = s->tris + i;
        d = t->h + t->growth * cvm__dist_point_tri3(x, t->p);
        best = d < best ? d : best;
    }
    if (s->bg3) {
        d = cvm__background3_at(s->bg3, x);
        best = d < best ? d : best;
    }
    if (s->fn_nd) {
        d = s->fn_nd(s->fn_payload, x, 3);
        if (!isfinite(d))
            return cvm__error(err, CVM_E_INPUT_NONFINITE, CVM_ENT_NONE, -1,
                              "the sizing callback returned a non-finite size at (%.17g, %.17g, "
                              "%.17g)",
                              x[0], x[1], x[2]);
        if (!(d > 0))
            return cvm__error(err, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "the sizing callback returned size %.17g at (%.17g, %.17g, %.17g) "
                              "(must be positive and finite)",
                              d, x[0], x[1], x[2]);
        best = d < best ? d : best;
    }
    *h = best;
    return CVM_OK;
}

double cvm__sizing_min3(const cvm_sizing *s)
{
    double m = HUGE_VAL;
    size_t i;
    if (!s)
        return m;
    if (s->has_uniform)
        m = s->uniform;
    for (i = 0; i < s->npts; i++)
        m = fmin(m, s->pts[i].h);
    for (i = 0; i < s->nlines; i++)
        m = fmin(m, s->lines[i].h);
    for (i = 0; i < s->ntris; i++)
        m = fmin(m, s->tris[i].h);
    if (s->bg3)
        m = fmin(m, cvm__background3_min(s->bg3));
    return m;
}

/* The box of the n points p (3 doubles each) grown by r into box. */
static void grown_box(const double *p, int n, double r, double *box)
{
    int c, k;
    for (k = 0; k < 3; k++) {
        box[k] = HUGE_VAL;
        box[3 + k] = -HUGE_VAL;
    }
    for (c = 0; c < n; c++)
        for (k = 0; k < 3; k++) {
            box[k] = fmin(box[k], p[3 * c + k] - r);
            box[3 + k] = fmax(box[3 + k], p[3 * c + k] + r);
        }
}

/* Reach of a source of size h and growth g towards the bound a: the distance
 * within which it gives a size <= a (negative: nowhere; infinite: anywhere). */
static double reach(double h, double g, double a)
{
    if (h > a)
        return -1;
    return g > 0 ? (a - h) / g : HUGE_VAL;
}

size_t cvm__sizing_boxes3(const cvm_sizing *s, double a, double *box)
{
    size_t n = 0, i;
    double r, p[9], tmp[6];
    double *b;
    int k;
    if (!s)
        return 0;
#define NEXT_BOX (b = box ? box + 6 * n : tmp, n++, b)
    if ((s->has_uniform && s->uniform <= a) || s->fn_nd) {
        b = NEXT_BOX;
        for (k = 0; k < 3; k++) {
            b[k] = -HUGE_VAL;
            b[3 + k] = HUGE_VAL;
        }
    }
    for (i = 0; i < s->npts; i++)
        if ((r = reach(s->pts[i].h, s->pts[i].growth, a)) >= 0) {
            p[0] = s->pts[i].x;
            p[1] = s->pts[i].y;
            p[2] = s->pts[i].z;
            grown_box(p, 1, r, NEXT_BOX);
        }
    for (i = 0; i < s->nlines; i++)
        if ((r = reach(s->lines[i].h, s->lines[i].growth, a)) >= 0) {
            const cvm__line_source *l = s->lines + i;
            p[0] = l->x0;
            p[1] = l->y0;
            p[2] = l->z0;
            p[3] = l->x1;
            p[4] = l->y1;
            p[5] = l->z1;
            grown_box(p, 2, r, NEXT_BOX);
        }
    for (i = 0; i < s->ntris; i++)
        if ((r = reach(s->tris[i].h, s->tris[i].growth, a)) >= 0)
            grown_box(s->tris[i].p, 3, r, NEXT_BOX);
    if (s->bg3 && cvm__background3_min(s->bg3) <= a) {
        b = NEXT_BOX;
        cvm__background3_box(s->bg3, b, b + 3);
    }
#undef NEXT_BOX
    return n;
}
