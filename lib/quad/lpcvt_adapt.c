/* lpcvt_adapt.c - one insertion/removal cycle of the Lp-CVT sites: the Delaunay edges of the
 * sites measured in the metric, a site added at the midpoint of each edge longer than sqrt 2,
 * and one end removed from each edge shorter than 1/sqrt 2. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_internal.h"
#include "quad_internal.h"

typedef struct la_edge {
    int32_t a, b; /* sites, a < b */
    double l;     /* metric length */
    int side;     /* 1 when the edge is not the longest of some triangle beside it */
} la_edge;

static int la_cmp(const void *x, const void *y)
{
    const la_edge *p = (const la_edge *)x, *q = (const la_edge *)y;
    if (p->a != q->a)
        return p->a < q->a ? -1 : 1;
    return (p->b > q->b) - (p->b < q->b);
}

static la_edge *la_find(la_edge *e, size_t ne, int32_t a, int32_t b)
{
    size_t lo = 0, hi = ne;
    if (a > b) {
        int32_t c = a;
        a = b;
        b = c;
    }
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (e[mid].a < a || (e[mid].a == a && e[mid].b < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < ne && e[lo].a == a && e[lo].b == b ? e + lo : NULL;
}

cvm_status cvm__lpcvt_adapt_sites(cvm__lpcvt *L, const double *xi, double **xo, size_t *no,
                                  size_t *nins, size_t *nrem, double *pct_in)
{
    const cvm__tri2 *T = &L->T;
    size_t ns = L->ns, nb = L->nb, ne = 0, k, nin = 0, ntest = 0, add = 0, rem = 0, n = 0;
    la_edge *e = NULL;
    double *sum = NULL, *sq = NULL, *cnt = NULL, *out = NULL;
    uint8_t *gone = NULL;
    int32_t t;
    cvm_status st;
    *xo = NULL;
    *no = *nins = *nrem = 0;
    *pct_in = 100;
    if ((st = cvm__lpcvt_topology(L, xi)))
        return st;
    if (!L->valid)
        return CVM_OK; /* no triangulation to measure: nothing to change */
    e = cvm__malloc(L->ctx, (3 * T->nt + 1) * sizeof *e);
    sum = cvm__calloc(L->ctx, ns + 1, sizeof *sum);
    sq = cvm__calloc(L->ctx, ns + 1, sizeof *sq);
    cnt = cvm__calloc(L->ctx, ns + 1, sizeof *cnt);
    gone = cvm__calloc(L->ctx, ns + 1, sizeof *gone);
    if (!e || !sum || !sq || !cnt || !gone) {
        st = cvm__nomem(L->ctx);
        goto done;
    }
    /* the edges between sites with a moving end, each once */
    for (t = 0; t < (int32_t)T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t a = T->tv[3 * t + j], b = T->tv[3 * t + (j + 1) % 3];
            if (a > b) {
                int32_t c = a;
                a = b;
                b = c;
            }
            if (a < 0 || (size_t)b >= ns || (size_t)b < nb)
                continue;
            e[ne].a = a;
            e[ne].b = b;
            ne++;
        }
    }
    qsort(e, ne, sizeof *e, la_cmp);
    for (k = 0; k < ne; k++)
        if (k == 0 || e[k].a != e[n - 1].a || e[k].b != e[n - 1].b)
            e[n++] = e[k];
    ne = n;
    for (k = 0; k < ne; k++) {
        if ((st = cvm__metric_length(&e[k].l, &L->metric, L->xy + 2 * (size_t)e[k].a,
                                     L->xy + 2 * (size_t)e[k].b, 0, 1, L->ctx)))
            goto done;
        sum[e[k].a] += e[k].l;
        sq[e[k].a] += e[k].l * e[k].l;
        cnt[e[k].a] += 1;
        sum[e[k].b] += e[k].l;
        sq[e[k].b] += e[k].l * e[k].l;
        cnt[e[k].b] += 1;
        ntest++;
        nin += e[k].l >= sqrt(0.5) && e[k].l <= sqrt(2.0);
    }
    /* quad sides, not diagonals: an edge counts when it is not the longest of a triangle
     * beside it (a square's diagonal, sqrt 2 long, is the longest of both of its triangles) */
    for (k = 0; k < ne; k++)
        e[k].side = 0;
    for (t = 0; t < (int32_t)T->nt; t++) {
        la_edge *f[3];
        int j, top = 0;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        for (j = 0; j < 3; j++)
            f[j] = la_find(e, ne, T->tv[3 * t + j], T->tv[3 * t + (j + 1) % 3]);
        for (j = 1; j < 3; j++)
            if (f[j] && (!f[top] || f[j]->l > f[top]->l))
                top = j;
        for (j = 0; j < 3; j++)
            if (f[j] && j != top)
                f[j]->side = 1;
    }
    ntest = nin = 0;
    for (k = 0; k < ne; k++)
        if (e[k].side) {
            ntest++;
            nin += e[k].l >= sqrt(0.5) && e[k].l <= sqrt(2.0);
        }
    *pct_in = ntest ? 100.0 * (double)nin / (double)ntest : 100;
    /* removals first, in edge order: the end with the larger coefficient of variation of its
     * edges' lengths (a moving site only), unless an end is already gone */
    for (k = 0; k < ne; k++) {
        int32_t a = e[k].a, b = e[k].b, v;
        if (!e[k].side || !(e[k].l < sqrt(0.5)) || gone[a] || gone[b])
            continue;
        if ((size_t)a < nb) {
            v = b;
        } else {
            double ma = sum[a] / cnt[a], mb = sum[b] / cnt[b];
            double ca = sqrt(fmax(0, sq[a] / cnt[a] - ma * ma)) / ma;
            double cb = sqrt(fmax(0, sq[b] / cnt[b] - mb * mb)) / mb;
            v = ca >= cb ? a : b;
        }
        gone[v] = 1;
        rem++;
    }
    for (k = 0; k < ne; k++)
        add += e[k].side && e[k].l > sqrt(2.0) && !gone[e[k].a] && !gone[e[k].b];
    if (add == 0 && rem == 0)
        goto done;
    out = cvm__malloc(L->ctx, (2 * (ns - nb - rem + add) + 1) * sizeof *out);
    if (!out) {
        st = cvm__nomem(L->ctx);
        goto done;
    }
    n = 0;
    for (k = nb; k < ns; k++)
        if (!gone[k]) {
            out[2 * n] = L->xy[2 * k];
            out[2 * n + 1] = L->xy[2 * k + 1];
            n++;
        }
    for (k = 0; k < ne; k++)
        if (e[k].side && e[k].l > sqrt(2.0) && !gone[e[k].a] && !gone[e[k].b]) {
            const double *p = L->xy + 2 * (size_t)e[k].a, *q = L->xy + 2 * (size_t)e[k].b;
            out[2 * n] = 0.5 * (p[0] + q[0]);
            out[2 * n + 1] = 0.5 * (p[1] + q[1]);
            n++;
        }
    *xo = out;
    *no = n;
    *nins = add;
    *nrem = rem;
done:
    cvm__free(L->ctx, e);
    cvm__free(L->ctx, sum);
    cvm__free(L->ctx, sq);
    cvm__free(L->ctx, cnt);
    cvm__free(L->ctx, gone);
    return st;
}
