/* quadmesh_sites.c - the sites of cvm_mesh_quadmesh() into the store: their triangulation,
 * the parallelogram smoothing of the cells made from it, and the all-quad split. */
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"
#include "quadmesh_internal.h"
#include "store.h"
#include "quad/quad_internal.h"

int cvm__qm_metric_at(double x, double y, double g[3], void *user)
{
    const cvm__qm_metric_cb *cb = (const cvm__qm_metric_cb *)user;
    double p[2];
    p[0] = x;
    p[1] = y;
    return cvm__metric_eval(cb->mt, p, g, NULL, cb->ctx) != CVM_OK;
}

cvm_status cvm__qm_triangulate_sites(cvm_mesh *m, const int32_t *loop, const int32_t *lseg,
                                     size_t nc, const double *bxy, size_t nb, const double *xi,
                                     size_t ni, size_t *kept_out)
{
    const cvm__pslg *P = &m->in;
    size_t np = P->np, na = P->nattr, nv = cvm__store_nv(m), total, k, c = 0, nnew = 0, kept = 0;
    int32_t *v2in = NULL, *seg = NULL, *smark = NULL, *pmark = NULL, *bid = NULL, *pseg = NULL;
    double *xy = NULL, *pattr = NULL;
    cvm__cdt_input in;
    cvm__cdt_fault f;
    cvm_status s;
    total = np + nb + ni;
    v2in = cvm__malloc(&m->ctx, (nv + 1) * sizeof *v2in);
    bid = cvm__malloc(&m->ctx, (nb + 1) * sizeof *bid);
    xy = cvm__malloc(&m->ctx, (2 * total + 1) * sizeof *xy);
    seg = cvm__malloc(&m->ctx, (2 * nb + 1) * sizeof *seg);
    smark = cvm__malloc(&m->ctx, (nb + 1) * sizeof *smark);
    pseg = cvm__malloc(&m->ctx, (nb + 1) * sizeof *pseg);
    pmark = cvm__malloc(&m->ctx, (total + 1) * sizeof *pmark);
    pattr = na ? cvm__malloc(&m->ctx, (total * na + 1) * sizeof *pattr) : NULL;
    if (!v2in || !bid || !xy || !seg || !smark || !pseg || !pmark || (na && !pattr)) {
        s = cvm__nomem(&m->ctx);
        goto done;
    }
    for (k = 0; k < nv; k++)
        v2in[k] = -1;
    for (k = np; k-- > 0;)
        if (m->input_map[k] >= 0)
            v2in[m->input_map[k]] = (int32_t)k;
    memcpy(xy, P->xy, 2 * np * sizeof *xy);
    for (k = 0; k < np; k++)
        pmark[k] = P->pmark ? P->pmark[k] : 0;
    if (na)
        memcpy(pattr, P->pattr, np * na * sizeof *pattr);
    /* boundary points: corner c of the loop where bxy repeats its coordinates exactly */
    for (k = 0; k < nb; k++) {
        const double *p = bxy + 2 * k;
        const double *q = cvm__store_point(m, (size_t)loop[c % nc]);
        if (c < nc && p[0] == q[0] && p[1] == q[1]) {
            bid[k] = v2in[loop[c]];
            c++;
            if (bid[k] < 0) {
                s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_VERTEX, loop[c - 1],
                               "cvm_mesh_quadmesh: boundary vertex %ld (%.17g, %.17g) is not an "
                               "input point (segments cross there)", (long)loop[c - 1], q[0], q[1]);
                goto done;
            }
            continue;
        }
        {   /* a new point on the loop edge from corner c - 1 to corner c */
            const double *a = cvm__store_point(m, (size_t)loop[(c + nc - 1) % nc]);
            size_t id = np + nnew++, j;
            int32_t ia = v2in[loop[(c + nc - 1) % nc]], ib = v2in[loop[c % nc]];
            double e0 = q[0] - a[0], e1 = q[1] - a[1];
            double tpar = (e0 * (p[0] - a[0]) + e1 * (p[1] - a[1])) / (e0 * e0 + e1 * e1);
            bid[k] = (int32_t)id;
            xy[2 * id] = p[0];
            xy[2 * id + 1] = p[1];
            pmark[id] = cvm__segment_marker(m, lseg[(c + nc - 1) % nc]);
            for (j = 0; j < na; j++)
                pattr[id * na + j] = (1 - tpar) * P->pattr[(size_t)ia * na + j] +
                                     tpar * P->pattr[(size_t)ib * na + j];
        }
    }
    if (c != nc) {
        s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                       "cvm_mesh_quadmesh: %lu of %lu boundary corners found among the boundary "
                       "points", (unsigned long)c, (unsigned long)nc);
        goto done;
    }
    /* segments: bxy point k to k + 1, on the loop edge of the last corner met */
    for (k = 0, c = 0; k < nb; k++) {
        const double *p = bxy + 2 * k;
        const double *q = cvm__store_point(m, (size_t)loop[c % nc]);
        if (c < nc && p[0] == q[0] && p[1] == q[1])
            c++;
        seg[2 * k] = bid[k];
        seg[2 * k + 1] = bid[(k + 1) % nb];
        pseg[k] = lseg[(c + nc - 1) % nc];
        smark[k] = cvm__segment_marker(m, pseg[k]);
    }
    for (k = 0; k < ni; k++) {
        size_t id = np + nnew + kept;
        if (!cvm__lpcvt_inside_polygon(bxy, nb, xi + 2 * k))
            continue;
        xy[2 * id] = xi[2 * k];
        xy[2 * id + 1] = xi[2 * k + 1];
        pmark[id] = 0;
        if (na)
            memset(pattr + id * na, 0, na * sizeof *pattr);
        kept++;
    }
    memset(&in, 0, sizeof in);
    cvm__mesh_cdt_input(&in, m, P);
    in.xy = xy;
    in.np = np + nnew + kept;
    in.pmark = pmark;
    in.pattr = pattr;
    in.seg = seg;
    in.nseg = nb;
    in.smark = smark;
    in.reject_duplicates = 0;
    in.keep_hull = 0;
    cvm__mesh_drop_output(m);
    s = cvm__mesh_cdt_build(m, &in, &f);
    if (!s) /* the pieces name the input segments they lie on */
        cvm__store_remap_segments(m, pseg, nb);
    if (s)
        s = f.kind == CVM__CDT_FAULT_NONE
                ? s
                : cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                             "cvm_mesh_quadmesh: the triangulation of the sites failed (fault %d "
                             "at item %lu)", (int)f.kind, (unsigned long)f.item);
    *kept_out = kept;
done:
    cvm__free(&m->ctx, v2in);
    cvm__free(&m->ctx, bid);
    cvm__free(&m->ctx, xy);
    cvm__free(&m->ctx, seg);
    cvm__free(&m->ctx, smark);
    cvm__free(&m->ctx, pseg);
    cvm__free(&m->ctx, pmark);
    cvm__free(&m->ctx, pattr);
    return s;
}

cvm_status cvm__qm_smooth_cells(cvm_mesh *m, const cvm__metric *mt, const int32_t *loop,
                                const int32_t *lseg, size_t nc, const double *bxy, size_t nb,
                                const double *xi, size_t ni, size_t kept)
{
    size_t nv = cvm__store_nv(m), first = nv - kept, k, j = 0, moves, again;
    cvm__quad_cells *q = m->quad;
    cvm__quad_smooth_in in;
    cvm__qm_metric_cb cb;
    double *xy;
    cvm_status s;
    if (kept > nv)
        return CVM_OK;
    for (k = 0; k < ni; k++) {
        const double *p;
        if (!cvm__lpcvt_inside_polygon(bxy, nb, xi + 2 * k))
            continue;
        p = cvm__store_point(m, first + j++);
        if (p[0] != xi[2 * k] || p[1] != xi[2 * k + 1])
            return CVM_OK;
    }
    xy = cvm__malloc(&m->ctx, (2 * nv + 1) * sizeof *xy);
    if (!xy)
        return cvm__nomem(&m->ctx);
    memcpy(xy, cvm__store_points(m), 2 * nv * sizeof *xy);
    cb.mt = mt;
    cb.ctx = &m->ctx;
    memset(&in, 0, sizeof in);
    in.nv = nv;
    in.first_free = first;
    in.ncell = q->ncell;
    in.off = q->off;
    in.types = q->types;
    in.conn = q->conn;
    in.metric = cvm__qm_metric_at;
    in.metric_user = &cb;
    in.sweeps = (int)cvm__opt(m, CVM_OPT_QUAD_SMOOTH);
    in.quality = q->quality;
    if ((s = cvm__quad_smooth(&m->ctx, xy, &in, &moves)) || moves == 0) {
        cvm__free(&m->ctx, xy);
        return s;
    }
    m->quad = NULL; /* kept through the new triangulation, which drops the output */
    s = cvm__qm_triangulate_sites(m, loop, lseg, nc, bxy, nb, xy + 2 * first, kept, &again);
    m->quad = q;
    cvm__free(&m->ctx, xy);
    if (!s && (again != kept || cvm__store_nv(m) != nv))
        s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                       "cvm_mesh_quadmesh: %lu of %lu smoothed sites kept",
                       (unsigned long)again, (unsigned long)kept);
    if (!s) {
        m->triangulated = 1;
        m->nv_triangulated = cvm__store_nv(m);
    }
    return s;
}


/* A point and its index, sorted by coordinates for the exact lookup of the split's points. */
typedef struct qm_keyed_pt {
    double x, y;
    int32_t id;
} qm_keyed_pt;

static int qm_keyed_cmp(const void *a, const void *b)
{
    const qm_keyed_pt *p = (const qm_keyed_pt *)a, *q = (const qm_keyed_pt *)b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return (p->id > q->id) - (p->id < q->id);
}

/* The entry of the sorted array a (n) with the coordinates of p, or NULL. */
static const qm_keyed_pt *qm_find(const qm_keyed_pt *a, size_t n, const double *p)
{
    qm_keyed_pt key;
    size_t lo = 0, hi = n;
    key.x = p[0];
    key.y = p[1];
    key.id = -1;
    while (lo < hi) { /* the first entry >= key */
        size_t mid = lo + (hi - lo) / 2;
        if (qm_keyed_cmp(a + mid, &key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && a[lo].x == p[0] && a[lo].y == p[1] ? a + lo : NULL;
}

cvm_status cvm__qm_adopt_split(cvm_mesh *m, const int32_t *loop, const int32_t *lseg, size_t nc,
                               const double *bxy, size_t nb, size_t kept_in, const double *pxy,
                               size_t np, double **bxy_out, size_t *nb_out, double **xi_out,
                               size_t *ni_out, size_t *kept_out)
{
    cvm__quad_cells *q = m->quad;
    size_t nv = cvm__store_nv(m), k, ni = 0, kept = 0, nv2;
    double *b2 = cvm__malloc(&m->ctx, (4 * nb + 1) * sizeof *b2);
    double *x2 = cvm__malloc(&m->ctx, (2 * np + 1) * sizeof *x2);
    qm_keyed_pt *mids = cvm__malloc(&m->ctx, (nb + 1) * sizeof *mids), *all = NULL;
    cvm_status s = CVM_OK;
    *bxy_out = *xi_out = NULL;
    if (!b2 || !x2 || !mids) {
        s = cvm__nomem(&m->ctx);
        goto done;
    }
    /* the boundary: each site, then its edge's midpoint, rounded as the split rounds it */
    for (k = 0; k < nb; k++) {
        const double *a = bxy + 2 * k, *b = bxy + 2 * ((k + 1) % nb);
        b2[4 * k] = a[0];
        b2[4 * k + 1] = a[1];
        b2[4 * k + 2] = mids[k].x = 0.5 * (a[0] + b[0]);
        b2[4 * k + 3] = mids[k].y = 0.5 * (a[1] + b[1]);
        mids[k].id = (int32_t)k;
    }
    qsort(mids, nb, sizeof *mids, qm_keyed_cmp);
    /* the interior: the interior sites of m (its last vertices), then the new points that are
     * not boundary midpoints, in the split's order */
    for (k = nv - (kept_in <= nv ? kept_in : nv); k < np; k++) {
        if (k >= nv && qm_find(mids, nb, pxy + 2 * k))
            continue;
        x2[2 * ni] = pxy[2 * k];
        x2[2 * ni + 1] = pxy[2 * k + 1];
        ni++;
    }
    m->quad = NULL; /* kept through the new triangulation, which drops the output */
    s = cvm__qm_triangulate_sites(m, loop, lseg, nc, b2, 2 * nb, x2, ni, &kept);
    m->quad = q;
    if (s)
        goto done;
    m->triangulated = 1;
    m->nv_triangulated = cvm__store_nv(m);
    /* the cells' point ids: found again by their exact coordinates among the new vertices */
    nv2 = cvm__store_nv(m);
    all = cvm__malloc(&m->ctx, (nv2 + 1) * sizeof *all);
    if (!all) {
        s = cvm__nomem(&m->ctx);
        goto done;
    }
    for (k = 0; k < nv2; k++) {
        const double *p = cvm__store_point(m, k);
        all[k].x = p[0];
        all[k].y = p[1];
        all[k].id = (int32_t)k;
    }
    qsort(all, nv2, sizeof *all, qm_keyed_cmp);
    for (k = 0; k < q->nconn; k++) {
        const qm_keyed_pt *f = q->conn[k] >= 0 && (size_t)q->conn[k] < np
                                   ? qm_find(all, nv2, pxy + 2 * (size_t)q->conn[k])
                                   : NULL;
        if (!f) {
            s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                           "cvm_mesh_quadmesh: point %ld of the all-quad split is not a vertex",
                           (long)q->conn[k]);
            goto done;
        }
        q->conn[k] = f->id;
    }
    *bxy_out = b2;
    *nb_out = 2 * nb;
    *xi_out = x2;
    *ni_out = ni;
    *kept_out = kept;
    b2 = x2 = NULL;
done:
    cvm__free(&m->ctx, b2);
    cvm__free(&m->ctx, x2);
    cvm__free(&m->ctx, mids);
    cvm__free(&m->ctx, all);
    return s;
}
