/* dual_cells.c - the power (Voronoi) cells of a mesh handle (lib/dual/cells.c) as CSR arrays in
 * the caller's buffers, as a finite-volume mesh (shared points, a face table) and as a .vtu file
 * of polygons on shared points. */
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

/* The finite-volume dual of m (fv zeroed when m has no triangles). */
static cvm_status fv_of(const cvm_mesh *m, cvm__dual_fv *fv)
{
    memset(fv, 0, sizeof *fv);
    if (!m->triangulated || !cvm__store_nv(m))
        return CVM_OK;
    /* allocation does not change the handle */
    return cvm__dual_fv_build((cvm__ctx *)&m->ctx, cvm__store_tri2_const(m), fv);
}

cvm_status cvm_mesh_count_dual(size_t *points_out, size_t *corners_out, size_t *faces_out,
                               const cvm_mesh *m)
{
    cvm__dual_fv fv;
    cvm_status s;
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m || !points_out || !corners_out || !faces_out)
        return CVM_E_NULL_ARG;
    if ((s = fv_of(m, &fv)))
        return s;
    *points_out = fv.npt;
    *corners_out = fv.off ? (size_t)fv.off[cvm__store_nv(m)] : 0;
    *faces_out = fv.nface;
    cvm__dual_fv_free((cvm__ctx *)&m->ctx, &fv);
    return CVM_OK;
}

/* What a cvm_mesh_copy_dual_* call of the finite-volume dual copies. */
typedef enum fv_part { FV_POINTS, FV_POLYGONS, FV_FACES, FV_FACE_LENGTHS } fv_part;

static cvm_status copy_fv(void *dst, size_t dst_len, const cvm_mesh *m, fv_part part)
{
    cvm__dual_fv fv;
    size_t n = 0, size = 0;
    const void *src = NULL;
    cvm_status s;
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m)
        return CVM_E_NULL_ARG;
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    if ((s = fv_of(m, &fv)))
        return s;
    switch (part) {
    case FV_POINTS: n = 2 * fv.npt, size = sizeof(double), src = fv.pt; break;
    case FV_POLYGONS:
        n = fv.off ? (size_t)fv.off[cvm__store_nv(m)] : 0, size = sizeof(int32_t), src = fv.corner;
        break;
    case FV_FACES: n = 6 * fv.nface, size = sizeof(int32_t), src = fv.face; break;
    default: n = 2 * fv.nface, size = sizeof(double), src = fv.flen; break;
    }
    if (!(s = cvm__room(dst, dst_len, n)) && n)
        memcpy(dst, src, n * size);
    cvm__dual_fv_free((cvm__ctx *)&m->ctx, &fv);
    return s;
}

cvm_status cvm_mesh_copy_dual_points(double *dst, size_t dst_len, const cvm_mesh *m)
{
    return copy_fv(dst, dst_len, m, FV_POINTS);
}

cvm_status cvm_mesh_copy_dual_polygons(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    return copy_fv(dst, dst_len, m, FV_POLYGONS);
}

cvm_status cvm_mesh_copy_dual_faces(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    return copy_fv(dst, dst_len, m, FV_FACES);
}

cvm_status cvm_mesh_copy_dual_face_lengths(double *dst, size_t dst_len, const cvm_mesh *m)
{
    return copy_fv(dst, dst_len, m, FV_FACE_LENGTHS);
}

/* The non-empty cells of m on shared points, with the face table, as a
 * cvm__dual_out (its arrays, and fv's, freed by dual_out_free). Cells go by
 * corner count, then vertex id: a reader that keeps polygons of one size
 * together (meshio) then makes one block per size. */
static cvm_status dual_out_build(cvm_mesh *m, cvm__dual_out *d, cvm__dual_fv *fv)
{
    const double *wt = cvm__store_weights(m);
    size_t nv = cvm__store_nv(m), maxc = 0, v, c, n = 0;
    int32_t *coff, *vid, *cell_of, *corner;
    size_t *bucket = NULL;
    double *area, *w;
    cvm_status s;
    memset(d, 0, sizeof *d);
    if ((s = cvm__dual_fv_build(&m->ctx, cvm__store_tri2_const(m), fv)))
        return s;
    coff = cvm__malloc(&m->ctx, (nv + 1) * sizeof *coff);
    vid = cvm__malloc(&m->ctx, (nv + 1) * sizeof *vid);
    cell_of = cvm__malloc(&m->ctx, (nv + 1) * sizeof *cell_of);
    area = cvm__malloc(&m->ctx, (nv + 1) * sizeof *area);
    w = cvm__malloc(&m->ctx, (nv + 1) * sizeof *w);
    corner = cvm__malloc(&m->ctx, ((size_t)fv->off[nv] + 1) * sizeof *corner);
    d->off = coff;
    d->vertex = vid;
    d->cell_of = cell_of;
    d->area = area;
    d->weight = w;
    d->corner = corner;
    for (v = 0; v < nv; v++)
        if ((size_t)(fv->off[v + 1] - fv->off[v]) > maxc)
            maxc = (size_t)(fv->off[v + 1] - fv->off[v]);
    if (coff && vid && cell_of && area && w && corner)
        bucket = cvm__calloc(&m->ctx, maxc + 2, sizeof *bucket);
    if (!bucket)
        return CVM_E_NOMEM;
    if ((s = cvm_mesh_copy_dual_areas(w, nv, m))) {
        cvm__free(&m->ctx, bucket);
        return s;
    }
    for (v = 0; v < nv; v++) /* cells of each size, then the first cell of each size */
        bucket[(size_t)(fv->off[v + 1] - fv->off[v]) + 1]++;
    bucket[1] = 0; /* no cell: no corners */
    for (c = 0; c <= maxc; c++)
        bucket[c + 1] += bucket[c];
    for (v = 0; v < nv; v++) {
        size_t size = (size_t)(fv->off[v + 1] - fv->off[v]);
        cell_of[v] = size ? (int32_t)bucket[size]++ : -1;
        if (size) {
            vid[cell_of[v]] = (int32_t)v;
            n++;
        }
    }
    cvm__free(&m->ctx, bucket);
    coff[0] = 0;
    for (c = 0; c < n; c++) {
        size_t u = (size_t)vid[c], size = (size_t)(fv->off[u + 1] - fv->off[u]);
        memcpy(corner + coff[c], fv->corner + fv->off[u], size * sizeof *corner);
        coff[c + 1] = coff[c] + (int32_t)size;
        area[c] = w[u];
    }
    for (c = 0; c < n; c++)
        w[c] = wt ? wt[vid[c]] : 0.0;
    d->ncell = n;
    d->xy = fv->pt;
    d->npoint = fv->npt;
    d->face = fv->face;
    d->flen = fv->flen;
    d->nface = fv->nface;
    return CVM_OK;
}

static void dual_out_free(cvm_mesh *m, cvm__dual_out *d, cvm__dual_fv *fv)
{
    cvm__free(&m->ctx, (void *)d->off);
    cvm__free(&m->ctx, (void *)d->vertex);
    cvm__free(&m->ctx, (void *)d->cell_of);
    cvm__free(&m->ctx, (void *)d->area);
    cvm__free(&m->ctx, (void *)d->weight);
    cvm__free(&m->ctx, (void *)d->corner);
    memset(d, 0, sizeof *d);
    cvm__dual_fv_free(&m->ctx, fv);
}

/* The checks and cells of cvm_mesh_write_dual(), the file into ws. */
static cvm_status write_dual_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    cvm__dual_out d;
    cvm__dual_fv fv;
    cvm_status s;
    if (!path)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    if (cvm__format_of(path) != CVM__FMT_VTU)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write the dual to %s: only .vtu is supported", path);
    s = dual_out_build(m, &d, &fv);
    if (s == CVM_E_NOMEM)
        s = cvm__nomem(&m->ctx);
    else if (s == CVM_E_TOO_LARGE)
        s = cvm__error(&m->ctx, s, CVM_ENT_NONE, -1, "the dual has more than INT32_MAX corners");
    if (!s)
        s = cvm__write_dual_file_to_set(ws, path, &d);
    dual_out_free(m, &d, &fv);
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
