/* aflr_layers.c - the layers of the advancing-front pass: the layer of each edge, recorded per triangle slot during the pass, and the layer index of each cell of the output (cvm_mesh_copy_layer_index()). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "aflr_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* ---- edge layers, per triangle slot ---- */

/* Layer of edge j of triangle t: from its segment when constrained, else
 * what slot t (or the triangle across) stored, else AF_INF. */
int32_t cvm__af_edge_layer(const cvm__refiner *R, int32_t t, int j)
{
    const af_state *A = R->aflr;
    const cvm__tri2 *T = R->T;
    int32_t seg = T->te[3 * (size_t)t + (size_t)j], h;
    if (seg >= 0)
        return (size_t)seg < A->nfront && A->front[seg] ? 0 : AF_INF;
    if (af_slot_valid(A, T, t))
        return A->sl[3 * (size_t)t + (size_t)j];
    h = T->tn[3 * (size_t)t + (size_t)j];
    if (af_slot_valid(A, T, h / 3))
        return A->sl[(size_t)h];
    return AF_INF;
}

/* Record the three edge layers of slot t and the quality q of its triangle.
 * CVM_OK or CVM_E_NOMEM. */
cvm_status cvm__af_store(af_state *A, cvm__refiner *R, int32_t t, const int32_t *l, int q)
{
    size_t need = 3 * (size_t)t + 3;
    int k;
    if ((need > A->cap_sl && cvm__grow(R->ctx, (void **)&A->sl, &A->cap_sl, need, sizeof *A->sl)) ||
        af_grow_fill(R->ctx, &A->sv, &A->cap_sv, need, -1) || /* new slots hold no record */
        ((size_t)t >= A->cap_sq &&
         cvm__grow(R->ctx, (void **)&A->sq, &A->cap_sq, (size_t)t + 1, sizeof *A->sq)))
        return CVM_E_NOMEM;
    A->sq[t] = (unsigned char)q;
    for (k = 0; k < 3; k++) {
        A->sl[3 * (size_t)t + (size_t)k] = l[k];
        A->sv[3 * (size_t)t + (size_t)k] = R->T->tv[3 * (size_t)t + (size_t)k];
    }
    return CVM_OK;
}

/* ---- output: the layer index of each cell ---- */

/* Pass layers on along the ne layerless edges ie (2 vertices each): the
 * fixed point of vl[b] = min(vl[b], vl[a] + 1) over them, i.e. the distance
 * in edges from the layered vertices, each starting at its own layer: one
 * breadth-first search that takes its sources in order of their layer (ties
 * by index), linear in the edges apart from that sort. CVM_OK or CVM_E_NOMEM. */
static int cmp_pair32(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

static cvm_status af_pass_layers(cvm__refiner *R, int32_t *vl, const int32_t *ie, size_t ne)
{
    size_t nv = R->T->nv, k, ns = 0, head = 0, tail = 0, si = 0;
    size_t *first = cvm__calloc(R->ctx, nv + 2, sizeof *first);
    int32_t *adj = cvm__malloc(R->ctx, (2 * ne + 1) * sizeof *adj);
    int32_t *fifo = cvm__malloc(R->ctx, (nv + 1) * sizeof *fifo);
    int32_t *src = cvm__malloc(R->ctx, (2 * nv + 1) * sizeof *src);
    cvm_status s = CVM_OK;
    if (!first || !adj || !fifo || !src) {
        s = cvm__nomem(R->ctx);
        goto out;
    }
    for (k = 0; k < 2 * ne; k++)
        first[ie[k] + 2]++;
    for (k = 2; k < nv + 2; k++)
        first[k] += first[k - 1];
    for (k = 0; k < ne; k++) {
        adj[first[ie[2 * k] + 1]++] = ie[2 * k + 1];
        adj[first[ie[2 * k + 1] + 1]++] = ie[2 * k];
    }
    for (k = 0; k < nv; k++)
        if (vl[k] != AF_INF && first[k + 1] > first[k]) {
            src[2 * ns] = vl[k];
            src[2 * ns++ + 1] = (int32_t)k;
        }
    qsort(src, ns, 2 * sizeof *src, cmp_pair32);
    /* the FIFO's layers never decrease; the next vertex is the lower of its
     * head and the next source (a source lowered since was queued then) */
    while (head < tail || si < ns) {
        int32_t u, w;
        size_t e;
        if (si < ns && (head == tail || src[2 * si] <= vl[fifo[head]])) {
            u = src[2 * si + 1];
            if (src[2 * si++] != vl[u])
                continue;
        } else {
            u = fifo[head++];
        }
        for (e = first[u]; e < first[u + 1]; e++)
            if (vl[u] + 1 < vl[w = adj[e]]) {
                vl[w] = vl[u] + 1;
                fifo[tail++] = w;
            }
    }
out:
    cvm__free(R->ctx, first);
    cvm__free(R->ctx, adj);
    cvm__free(R->ctx, fifo);
    cvm__free(R->ctx, src);
    return s;
}

cvm_status cvm__rf_aflr_cell_layers(cvm__refiner *R, double **out)
{
    const cvm__tri2 *T = R->T;
    int32_t *vl, *el, *ie; /* ie: the layerless edges, 2 vertices each */
    double *cl;
    size_t t, ne = 0;
    *out = NULL;
    if (!R->aflr)
        return CVM_OK;
    vl = cvm__malloc(R->ctx, (T->nv + 1) * sizeof *vl);
    el = cvm__malloc(R->ctx, (3 * T->nt + 1) * sizeof *el);
    cl = cvm__malloc(R->ctx, (T->nt + 1) * sizeof *cl);
    ie = cvm__malloc(R->ctx, (6 * T->nt + 1) * sizeof *ie);
    if (!vl || !el || !cl || !ie) {
        cvm__free(R->ctx, vl);
        cvm__free(R->ctx, el);
        cvm__free(R->ctx, cl);
        cvm__free(R->ctx, ie);
        return cvm__nomem(R->ctx);
    }
    for (t = 0; t < T->nv; t++)
        vl[t] = AF_INF;
    /* each edge's layer once, and the lowest known layer at each vertex */
    for (t = 0; t < T->nt; t++) {
        int j;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t l = cvm__af_edge_layer(R, (int32_t)t, j), a = T->tv[3 * t + (size_t)af_n1[j]];
            int32_t b = T->tv[3 * t + (size_t)af_n2[j]];
            el[3 * t + (size_t)j] = l;
            vl[a] = l < vl[a] ? l : vl[a];
            vl[b] = l < vl[b] ? l : vl[b];
            if (l == AF_INF) {
                ie[2 * ne] = a;
                ie[2 * ne + 1] = b;
                ne++;
            }
        }
    }
    /* edges without a layer (made after the fronts stopped) pass one more
     * than the lower end's on */
    if (af_pass_layers(R, vl, ie, ne)) {
        cvm__free(R->ctx, vl);
        cvm__free(R->ctx, el);
        cvm__free(R->ctx, cl);
        cvm__free(R->ctx, ie);
        return CVM_E_NOMEM;
    }
    for (t = 0; t < T->nt; t++) {
        int32_t lo = AF_INF, hi = -1;
        int j;
        cl[t] = -1;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++) {
            int32_t l = el[3 * t + (size_t)j];
            if (l == AF_INF) { /* made after the pass, or a segment that starts no front */
                int32_t a = vl[T->tv[3 * t + (size_t)af_n1[j]]];
                int32_t b = vl[T->tv[3 * t + (size_t)af_n2[j]]];
                l = a < b ? a : b;
                l = l == AF_INF ? AF_INF : l + 1;
            }
            lo = l < lo ? l : lo;
            hi = l > hi ? l : hi;
        }
        if (hi != AF_INF)
            cl[t] = (double)hi + 0.1 * (double)lo;
    }
    cvm__free(R->ctx, vl);
    cvm__free(R->ctx, el);
    cvm__free(R->ctx, ie);
    *out = cl;
    return CVM_OK;
}
