/*
 * g3_remesh_field.c - what the surface re-meshing (g3_remesh.c) needs to know
 * about the input surface: vertex classes, smooth patches, the target size at
 * each input vertex, and the nearest point of a patch to a moved vertex.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_remesh.h"

#define G3RF_STRAIGHT_COS 0.996 /* a feature line turning by less than 5 degrees at a vertex */
#define G3RF_MAX_CELLS 256      /* grid cells along the bounding box's diagonal, at most */

static double g3rf_dist(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static const double *g3rf_in(const g3r_state *R, int32_t v) { return R->in->xyz + 3 * (size_t)v; }

static void g3rf_unit_normal(const double *a, const double *b, const double *c, double *n)
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double l;
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0) {
        n[0] /= l;
        n[1] /= l;
        n[2] /= l;
    }
}

/* Smooth patches: input triangles joined across non-feature edges. */
static cvm_status g3r_patches(g3r_state *R)
{
    size_t nt = R->in->nt, t, top;
    int32_t *stack = cvm__malloc(R->ctx, (nt ? nt : 1) * sizeof *stack), np = 0;
    if (!stack)
        return cvm__nomem(R->ctx);
    for (t = 0; t < nt; t++)
        R->ipatch[t] = -1;
    for (t = 0; t < nt; t++) {
        if (R->ipatch[t] >= 0)
            continue;
        R->ipatch[t] = np;
        stack[0] = (int32_t)t;
        top = 1;
        while (top) {
            int32_t u = stack[--top], k;
            for (k = 0; k < 3; k++) {
                int32_t h = 3 * u + k, w = R->opp[h] / 3;
                if (!R->feat[h] && R->ipatch[w] < 0) {
                    R->ipatch[w] = np;
                    stack[top++] = w;
                }
            }
        }
        np++;
    }
    cvm__free(R->ctx, stack);
    return CVM_OK;
}

/* Vertex classes from the number of feature edges at each vertex; the size a
 * vertex on a feature line that cannot move must keep (its feature edges'). */
static cvm_status g3r_classes(g3r_state *R, double *L0)
{
    size_t nv = R->nv, h;
    int32_t *cnt = cvm__calloc(R->ctx, nv ? nv : 1, sizeof *cnt);
    int32_t *fe = cvm__malloc(R->ctx, 2 * (nv ? nv : 1) * sizeof *fe); /* two feature neighbours */
    double *fmin = cvm__malloc(R->ctx, (nv ? nv : 1) * sizeof *fmin);
    size_t v;
    if (!cnt || !fe || !fmin) {
        cvm__free(R->ctx, cnt);
        cvm__free(R->ctx, fe);
        cvm__free(R->ctx, fmin);
        return cvm__nomem(R->ctx);
    }
    for (v = 0; v < nv; v++)
        fmin[v] = HUGE_VAL;
    for (h = 0; h < 3 * R->nt; h++) {
        int32_t o = R->opp[h], a, b;
        double l;
        if (!R->feat[h] || o < (int32_t)h)
            continue;
        a = R->tv[3 * (h / 3) + (h % 3 + 1) % 3];
        b = R->tv[3 * (h / 3) + (h % 3 + 2) % 3];
        l = g3rf_dist(g3rf_in(R, a), g3rf_in(R, b));
        if (cnt[a] < 2)
            fe[2 * a + cnt[a]] = b;
        if (cnt[b] < 2)
            fe[2 * b + cnt[b]] = a;
        cnt[a]++;
        cnt[b]++;
        fmin[a] = l < fmin[a] ? l : fmin[a];
        fmin[b] = l < fmin[b] ? l : fmin[b];
    }
    for (v = 0; v < nv; v++) {
        R->vflag[v] = cnt[v] == 0 ? G3R_FREE : cnt[v] == 2 ? G3R_LINE : G3R_FIXED;
        R->vpatch[v] = cnt[v] == 0 && R->vhe[v] >= 0 ? R->ipatch[R->vhe[v] / 3] : -1;
        if (R->vflag[v] == G3R_LINE) {
            const double *p = g3rf_in(R, (int32_t)v), *a = g3rf_in(R, fe[2 * v]), *b = g3rf_in(R, fe[2 * v + 1]);
            double u[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
            double w[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
            double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            double lw = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            double c = lu > 0 && lw > 0 ? (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / (lu * lw) : -1;
            if (c < G3RF_STRAIGHT_COS) {
                R->vflag[v] = G3R_FIXED; /* a corner of a curved feature line stays */
                L0[v] = 0.5 * (lu + lw) < L0[v] ? 0.5 * (lu + lw) : L0[v];
            }
        } else if (R->vflag[v] == G3R_FIXED && fmin[v] < L0[v]) {
            L0[v] = fmin[v];
        }
    }
    cvm__free(R->ctx, cnt);
    cvm__free(R->ctx, fe);
    cvm__free(R->ctx, fmin);
    return CVM_OK;
}

/* Curvature: the angle between the normals of an edge's two triangles over
 * the distance of their centroids. */
static void g3r_curvature(g3r_state *R, double *L0)
{
    size_t h;
    for (h = 0; h < 3 * R->nt; h++) {
        int32_t o = R->opp[h], t = (int32_t)(h / 3), u = o / 3, a, b;
        double n1[3], n2[3], c1[3], c2[3], d, phi, l;
        int k;
        if (R->feat[h] || o < (int32_t)h)
            continue;
        g3rf_unit_normal(g3rf_in(R, R->tv[3 * t]), g3rf_in(R, R->tv[3 * t + 1]), g3rf_in(R, R->tv[3 * t + 2]), n1);
        g3rf_unit_normal(g3rf_in(R, R->tv[3 * u]), g3rf_in(R, R->tv[3 * u + 1]), g3rf_in(R, R->tv[3 * u + 2]), n2);
        for (k = 0; k < 3; k++) {
            c1[k] = (g3rf_in(R, R->tv[3 * t])[k] + g3rf_in(R, R->tv[3 * t + 1])[k] + g3rf_in(R, R->tv[3 * t + 2])[k]) / 3;
            c2[k] = (g3rf_in(R, R->tv[3 * u])[k] + g3rf_in(R, R->tv[3 * u + 1])[k] + g3rf_in(R, R->tv[3 * u + 2])[k]) / 3;
        }
        d = g3rf_dist(c1, c2);
        phi = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
        phi = acos(phi > 1 ? 1 : phi < -1 ? -1 : phi);
        if (!(phi > 1e-9) || !(d > 0))
            continue;
        l = G3R_TURN * d / phi;
        a = R->tv[3 * t + (h % 3 + 1) % 3];
        b = R->tv[3 * t + (h % 3 + 2) % 3];
        L0[a] = l < L0[a] ? l : L0[a];
        L0[b] = l < L0[b] ? l : L0[b];
    }
}

/* L(v) = min over u of L0(u) + g d(u, v), d along the input's edges (Dijkstra
 * with a binary heap of (value, vertex)). */
static cvm_status g3r_grade(g3r_state *R, const double *L0, double g)
{
    size_t nv = R->nv, n = 0, v;
    int32_t *heap = cvm__malloc(R->ctx, (3 * R->nt + nv + 1) * sizeof *heap);
    unsigned char *done = cvm__calloc(R->ctx, nv ? nv : 1, 1);
    double *L = R->iL;
    if (!heap || !done) {
        cvm__free(R->ctx, heap);
        cvm__free(R->ctx, done);
        return cvm__nomem(R->ctx);
    }
#define G3RF_LESS(i, j) (L[heap[i]] < L[heap[j]] || (L[heap[i]] == L[heap[j]] && heap[i] < heap[j]))
    for (v = 0; v < nv; v++) {
        size_t i;
        L[v] = L0[v];
        heap[n] = (int32_t)v;
        for (i = n++; i > 0 && G3RF_LESS(i, (i - 1) / 2); i = (i - 1) / 2) {
            int32_t tmp = heap[i];
            heap[i] = heap[(i - 1) / 2];
            heap[(i - 1) / 2] = tmp;
        }
    }
    while (n) {
        int32_t u = heap[0], h0, h;
        size_t i = 0;
        heap[0] = heap[--n];
        for (;;) {
            size_t l = 2 * i + 1, r = l + 1, m = i;
            if (l < n && G3RF_LESS(l, m))
                m = l;
            if (r < n && G3RF_LESS(r, m))
                m = r;
            if (m == i)
                break;
            {
                int32_t tmp = heap[i];
                heap[i] = heap[m];
                heap[m] = tmp;
            }
            i = m;
        }
        if (done[u] || R->vhe[u] < 0)
            continue;
        done[u] = 1;
        h = h0 = R->vhe[u];
        do {
            int32_t w = R->tv[3 * (h / 3) + (h % 3 + 2) % 3];
            double c = L[u] + g * g3rf_dist(g3rf_in(R, u), g3rf_in(R, w));
            if (!done[w] && c < L[w]) {
                L[w] = c;
                heap[n] = w;
                for (i = n++; i > 0 && G3RF_LESS(i, (i - 1) / 2); i = (i - 1) / 2) {
                    int32_t tmp = heap[i];
                    heap[i] = heap[(i - 1) / 2];
                    heap[(i - 1) / 2] = tmp;
                }
            }
            h = R->opp[3 * (h / 3) + (h % 3 + 2) % 3];
        } while (h != h0);
    }
#undef G3RF_LESS
    cvm__free(R->ctx, heap);
    cvm__free(R->ctx, done);
    return CVM_OK;
}

static void g3r_cell_of(const g3r_state *R, const double *x, int *c)
{
    int k;
    for (k = 0; k < 3; k++) {
        double f = floor((x[k] - R->glo[k]) / R->gcell);
        c[k] = f < 0 ? 0 : f >= R->gdim[k] ? R->gdim[k] - 1 : (int)f;
    }
}

static int64_t g3r_cell_key(const g3r_state *R, int i, int j, int k)
{
    return ((int64_t)i * R->gdim[1] + j) * R->gdim[2] + k;
}

static cvm_status g3r_grid(g3r_state *R)
{
    const cvm__g3_surface *s = R->in;
    double hi[3], area = 0, diag;
    size_t t, n = 0, v;
    int64_t *key;
    int k;
    for (k = 0; k < 3; k++)
        R->glo[k] = hi[k] = s->xyz[k];
    for (v = 0; v < s->np; v++)
        for (k = 0; k < 3; k++) {
            R->glo[k] = s->xyz[3 * v + k] < R->glo[k] ? s->xyz[3 * v + k] : R->glo[k];
            hi[k] = s->xyz[3 * v + k] > hi[k] ? s->xyz[3 * v + k] : hi[k];
        }
    for (t = 0; t < s->nt; t++) {
        double nn[3];
        const double *a = g3rf_in(R, s->tri[3 * t]), *b = g3rf_in(R, s->tri[3 * t + 1]), *c = g3rf_in(R, s->tri[3 * t + 2]);
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        nn[0] = u[1] * w[2] - u[2] * w[1];
        nn[1] = u[2] * w[0] - u[0] * w[2];
        nn[2] = u[0] * w[1] - u[1] * w[0];
        area += 0.5 * sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
    }
    diag = g3rf_dist(R->glo, hi);
    R->gcell = sqrt(area / (double)(s->nt ? s->nt : 1));
    if (R->gcell < diag / G3RF_MAX_CELLS)
        R->gcell = diag / G3RF_MAX_CELLS;
    if (!(R->gcell > 0))
        R->gcell = 1;
    for (k = 0; k < 3; k++)
        R->gdim[k] = (int)floor((hi[k] - R->glo[k]) / R->gcell) + 1;
    for (t = 0; t < s->nt; t++) {
        int lo[3], up[3], c[3];
        double bl[3], bh[3];
        for (k = 0; k < 3; k++) {
            bl[k] = bh[k] = s->xyz[3 * s->tri[3 * t] + k];
            bl[k] = fmin(bl[k], fmin(s->xyz[3 * s->tri[3 * t + 1] + k], s->xyz[3 * s->tri[3 * t + 2] + k]));
            bh[k] = fmax(bh[k], fmax(s->xyz[3 * s->tri[3 * t + 1] + k], s->xyz[3 * s->tri[3 * t + 2] + k]));
        }
        g3r_cell_of(R, bl, lo);
        g3r_cell_of(R, bh, up);
        n += (size_t)(up[0] - lo[0] + 1) * (size_t)(up[1] - lo[1] + 1) * (size_t)(up[2] - lo[2] + 1);
        (void)c;
    }
    key = cvm__malloc(R->ctx, (n ? n : 1) * sizeof *key);
    R->gtri = cvm__malloc(R->ctx, (n ? n : 1) * sizeof *R->gtri);
    R->gkey = (uint64_t *)key;
    if (!key || !R->gtri)
        return cvm__nomem(R->ctx);
    n = 0;
    for (t = 0; t < s->nt; t++) {
        int lo[3], up[3], i, j, l;
        double bl[3], bh[3];
        for (k = 0; k < 3; k++) {
            bl[k] = fmin(s->xyz[3 * s->tri[3 * t] + k], fmin(s->xyz[3 * s->tri[3 * t + 1] + k], s->xyz[3 * s->tri[3 * t + 2] + k]));
            bh[k] = fmax(s->xyz[3 * s->tri[3 * t] + k], fmax(s->xyz[3 * s->tri[3 * t + 1] + k], s->xyz[3 * s->tri[3 * t + 2] + k]));
        }
        g3r_cell_of(R, bl, lo);
        g3r_cell_of(R, bh, up);
        for (i = lo[0]; i <= up[0]; i++)
            for (j = lo[1]; j <= up[1]; j++)
                for (l = lo[2]; l <= up[2]; l++) {
                    key[n] = g3r_cell_key(R, i, j, l);
                    R->gtri[n++] = (int32_t)t;
                }
    }
    R->ng = n;
    return cvm__g3r_sort_pairs(R->ctx, key, R->gtri, n);
}

cvm_status cvm__g3r_field(g3r_state *R, const cvm__g3_params *p)
{
    size_t nv = R->nv, v;
    double *L0;
    cvm__g3_size *z = NULL;
    cvm_status st;
    R->ipatch = cvm__malloc(R->ctx, (R->in->nt ? R->in->nt : 1) * sizeof *R->ipatch);
    R->iL = cvm__malloc(R->ctx, (nv ? nv : 1) * sizeof *R->iL);
    L0 = cvm__malloc(R->ctx, (nv ? nv : 1) * sizeof *L0);
    if (!R->ipatch || !R->iL || !L0) {
        cvm__free(R->ctx, L0);
        return cvm__nomem(R->ctx);
    }
    if ((st = g3r_patches(R)))
        goto done;
    for (v = 0; v < nv; v++)
        L0[v] = p->h;
    if (p->sizing) {
        cvm__g3_params q = *p;
        q.follow_surface = 0;
        if ((st = cvm__g3_size_create(&z, R->ctx, R->in, &q)))
            goto done;
        for (v = 0; v < nv && !st; v++)
            st = cvm__g3_size_at(z, g3rf_in(R, (int32_t)v), &L0[v]);
        if (st)
            goto done;
    }
    /* the input's own size: no triangle is meant coarser than the mean edge of those
     * around its vertices (a finely triangulated sphere stays as fine) */
    for (v = 0; v < R->in->nt; v++) {
        const int32_t *tv = R->in->tri + 3 * v;
        double l = (g3rf_dist(g3rf_in(R, tv[0]), g3rf_in(R, tv[1])) +
                    g3rf_dist(g3rf_in(R, tv[1]), g3rf_in(R, tv[2])) +
                    g3rf_dist(g3rf_in(R, tv[2]), g3rf_in(R, tv[0]))) / 3;
        int k;
        for (k = 0; k < 3; k++)
            L0[tv[k]] = l < L0[tv[k]] ? l : L0[tv[k]];
    }
    if ((st = g3r_classes(R, L0)))
        goto done;
    g3r_curvature(R, L0);
    if ((st = g3r_grade(R, L0, p->grading > 0 ? p->grading : 0.3)))
        goto done;
    memcpy(R->L, R->iL, nv * sizeof *R->L);
    st = g3r_grid(R);
done:
    cvm__g3_size_free(z);
    cvm__free(R->ctx, L0);
    return st;
}

/* The nearest point y of triangle abc to x and its barycentric weights w
 * (regions of the triangle's Voronoi diagram, as in Ericson, "Real-Time
 * Collision Detection", 5.1.5). */
static void g3r_nearest_on_tri(const double *x, const double *a, const double *b, const double *c,
                           double *y, double *w)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], d1, d2, d3, d4, d5, d6, va, vb, vc, den, v, u;
    int k;
    for (k = 0; k < 3; k++) {
        ab[k] = b[k] - a[k];
        ac[k] = c[k] - a[k];
        ap[k] = x[k] - a[k];
        bp[k] = x[k] - b[k];
        cp[k] = x[k] - c[k];
    }
#define DOT(p, q) ((p)[0] * (q)[0] + (p)[1] * (q)[1] + (p)[2] * (q)[2])
    d1 = DOT(ab, ap);
    d2 = DOT(ac, ap);
    d3 = DOT(ab, bp);
    d4 = DOT(ac, bp);
    d5 = DOT(ab, cp);
    d6 = DOT(ac, cp);
#undef DOT
    if (d1 <= 0 && d2 <= 0) {
        w[0] = 1, w[1] = 0, w[2] = 0;
    } else if (d3 >= 0 && d4 <= d3) {
        w[0] = 0, w[1] = 1, w[2] = 0;
    } else if ((vc = d1 * d4 - d3 * d2) <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        w[0] = 1 - v, w[1] = v, w[2] = 0;
    } else if (d6 >= 0 && d5 <= d6) {
        w[0] = 0, w[1] = 0, w[2] = 1;
    } else if ((vb = d5 * d2 - d1 * d6) <= 0 && d2 >= 0 && d6 <= 0) {
        v = d2 / (d2 - d6);
        w[0] = 1 - v, w[1] = 0, w[2] = v;
    } else if ((va = d3 * d6 - d5 * d4) <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        w[0] = 0, w[1] = 1 - v, w[2] = v;
    } else {
        den = 1 / (va + vb + vc);
        v = vb * den;
        u = vc * den;
        w[0] = 1 - v - u, w[1] = v, w[2] = u;
    }
    for (k = 0; k < 3; k++) {
        y[k] = w[0] * a[k] + w[1] * b[k] + w[2] * c[k];
        /* a plane of constant coordinate keeps it exactly (box sides) */
        if (a[k] == b[k] && a[k] == c[k])
            y[k] = a[k];
    }
}

int cvm__g3r_project(const g3r_state *R, int32_t patch, const double *x, double r, double *y,
                     double *L)
{
    int lo[3], up[3], i, j, k, found = 0;
    double bl[3], bh[3], best = r, bw[3] = {1, 1, 1};
    int32_t bt = -1;
    for (k = 0; k < 3; k++) {
        bl[k] = x[k] - r;
        bh[k] = x[k] + r;
    }
    g3r_cell_of(R, bl, lo);
    g3r_cell_of(R, bh, up);
    for (i = lo[0]; i <= up[0]; i++)
        for (j = lo[1]; j <= up[1]; j++)
            for (k = lo[2]; k <= up[2]; k++) {
                uint64_t key = (uint64_t)g3r_cell_key(R, i, j, k);
                size_t a = 0, b = R->ng;
                while (a < b) {
                    size_t m = a + (b - a) / 2;
                    if (R->gkey[m] < key)
                        a = m + 1;
                    else
                        b = m;
                }
                for (; a < R->ng && R->gkey[a] == key; a++) {
                    int32_t t = R->gtri[a];
                    const int32_t *tv = R->in->tri + 3 * (size_t)t;
                    double q[3], w[3], d;
                    if (R->ipatch[t] != patch)
                        continue;
                    g3r_nearest_on_tri(x, g3rf_in(R, tv[0]), g3rf_in(R, tv[1]), g3rf_in(R, tv[2]), q, w);
                    d = g3rf_dist(x, q);
                    if (d < best || (d == best && found && t < bt)) {
                        best = d;
                        bt = t;
                        found = 1;
                        memcpy(y, q, sizeof q);
                        memcpy(bw, w, sizeof w);
                        *L = w[0] * R->iL[tv[0]] + w[1] * R->iL[tv[1]] + w[2] * R->iL[tv[2]];
                    }
                }
            }
    if (found) {
        /* on an edge of the nearest triangle: that edge must lie inside the patch, else
         * the point would sit on a feature line (where another vertex may already be) */
        for (k = 0; k < 3; k++) {
            int32_t hh = 3 * bt + k, u;
            if (bw[k] > 1e-6) /* rounding leaves a point on an edge a hair off it */
                continue;
            u = R->iopp[hh] / 3;
            if (R->ifeat[hh] || R->ipatch[u] != patch)
                return 0;
        }
    }
    return found;
}

void cvm__g3r_free(g3r_state *R)
{
    cvm__ctx *ctx = R->ctx;
    cvm__free(ctx, R->x);
    cvm__free(ctx, R->L);
    cvm__free(ctx, R->vflag);
    cvm__free(ctx, R->vpatch);
    cvm__free(ctx, R->vhe);
    cvm__free(ctx, R->tv);
    cvm__free(ctx, R->opp);
    cvm__free(ctx, R->feat);
    cvm__free(ctx, R->tsrc);
    cvm__free(ctx, R->ring);
    cvm__free(ctx, R->ipatch);
    cvm__free(ctx, R->iopp);
    cvm__free(ctx, R->ifeat);
    cvm__free(ctx, R->iL);
    cvm__free(ctx, R->gkey);
    cvm__free(ctx, R->gtri);
    memset(R, 0, sizeof *R);
    R->ctx = ctx;
}
