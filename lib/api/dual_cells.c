/* dual_cells.c - the power (Voronoi) cells of a mesh handle (lib/dual/cells.c) as CSR arrays in
 * the caller's buffers and as a .vtu file of polygons. */
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "api/mesh3.h"

/* Fresh offsets of m's cells (nv + 1 entries). */
static cvm_status offsets(cvm__ctx *ctx, const cvm_mesh *m, int32_t **out)
{
    int32_t *off = cvm__malloc(ctx, (cvm__store_nv(m) + 1) * sizeof *off);
    cvm_status s;
    *out = NULL;
    if (!off)
        return CVM_E_NOMEM;
    if ((s = cvm__dual_cells(ctx, cvm__store_tri2_const(m), off, NULL))) {
        cvm__free(ctx, off);
        return s;
    }
    *out = off;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_cell_offsets(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    int32_t *off;
    size_t nv;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    nv = m->triangulated ? cvm__store_nv(m) : 0;
    if ((s = cvm__room(dst, dst_len, nv + 1)))
        return s;
    if (!nv) {
        dst[0] = 0;
        return CVM_OK;
    }
    ctx = (cvm__ctx *)&m->ctx; /* allocation does not change the handle */
    if ((s = offsets(ctx, m, &off)))
        return s;
    memcpy(dst, off, (nv + 1) * sizeof *dst);
    cvm__free(ctx, off);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_cells(double *dst, size_t dst_len, const cvm_mesh *m)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    cvm__ctx *ctx;
    int32_t *off;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->triangulated || !cvm__store_nv(m))
        return cvm__room(dst, dst_len, 0);
    ctx = (cvm__ctx *)&m->ctx;
    if ((s = offsets(ctx, m, &off)))
        return s;
    if ((s = cvm__room(dst, dst_len, 2 * (size_t)off[cvm__store_nv(m)])) == CVM_OK)
        s = cvm__dual_cells(ctx, cvm__store_tri2_const(m), off, dst);
    cvm__free(ctx, off);
    return s;
}

/* The non-empty cells of m as a cvm__dual_out (arrays freed by dual_out_free). */
static cvm_status dual_out_build(cvm_mesh *m, cvm__dual_out *d)
{
    const cvm__tri2 *T = cvm__store_tri2_const(m);
    const double *wt = cvm__store_weights(m);
    size_t nv = cvm__store_nv(m);
    int32_t *off = NULL, *coff, *vid;
    double *xy, *area, *w;
    size_t v, n = 0;
    cvm_status s;
    memset(d, 0, sizeof *d);
    if ((s = offsets(&m->ctx, m, &off)))
        return s;
    xy = cvm__malloc(&m->ctx, (2 * (size_t)off[nv] + 1) * sizeof *xy);
    coff = cvm__malloc(&m->ctx, (nv + 1) * sizeof *coff);
    vid = cvm__malloc(&m->ctx, (nv + 1) * sizeof *vid);
    area = cvm__malloc(&m->ctx, (nv + 1) * sizeof *area);
    w = cvm__malloc(&m->ctx, (nv + 1) * sizeof *w);
    d->xy = xy;
    d->off = coff;
    d->vertex = vid;
    d->area = area;
    d->weight = w;
    if (!xy || !coff || !vid || !area || !w) {
        cvm__free(&m->ctx, off);
        return CVM_E_NOMEM;
    }
    if ((s = cvm__dual_cells(&m->ctx, T, off, xy)) ||
        (s = cvm_mesh_copy_dual_areas(area, nv, m))) {
        cvm__free(&m->ctx, off);
        return s;
    }
    coff[0] = 0;
    for (v = 0; v < nv; v++) {
        if (off[v + 1] == off[v])
            continue; /* no domain triangle: no cell */
        vid[n] = (int32_t)v;
        area[n] = area[v];
        w[n] = wt ? wt[v] : 0.0;
        coff[++n] = off[v + 1];
    }
    d->ncell = n;
    d->ncorner = (size_t)off[nv];
    cvm__free(&m->ctx, off);
    return CVM_OK;
}

static void dual_out_free(cvm_mesh *m, cvm__dual_out *d)
{
    cvm__free(&m->ctx, (void *)d->xy);
    cvm__free(&m->ctx, (void *)d->off);
    cvm__free(&m->ctx, (void *)d->vertex);
    cvm__free(&m->ctx, (void *)d->area);
    cvm__free(&m->ctx, (void *)d->weight);
    memset(d, 0, sizeof *d);
}

/* The checks and cells of cvm_mesh_write_dual(), the file into ws. */
static cvm_status write_dual_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    cvm__dual_out d;
    cvm_status s;
    if (!path)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    if (cvm__format_of(path) != CVM__FMT_VTU)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write the dual to %s: only .vtu is supported", path);
    s = dual_out_build(m, &d);
    if (s == CVM_E_NOMEM)
        s = cvm__nomem(&m->ctx);
    else if (s == CVM_E_TOO_LARGE)
        s = cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "the dual has more than INT32_MAX corners");
    if (!s)
        s = cvm__write_dual_file_to_set(ws, path, &d);
    dual_out_free(m, &d);
    return s;
}

cvm_status cvm_mesh_write_dual(cvm_mesh *m, const char *path)
{
    if (m && m->m3)
        return cvm__mesh_write_now(m, path, cvm__mesh3_write_dual_to_set);
    return cvm__mesh_write_now(m, path, write_dual_to_set);
}

cvm_status cvm_mesh_stage_write_dual(cvm_mesh *m, const char *path)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh_stage_settle(m, cvm__mesh3_write_dual_to_set(m, path, &m->staged));
    }
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    return cvm__mesh_stage_settle(m, write_dual_to_set(m, path, &m->staged));
}
