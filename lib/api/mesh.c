/* mesh.c - the cvm_mesh handle: creation, destruction, errors and the input setters. */
#include <math.h>
#include <string.h>

#include "api_internal.h"
#include "api/mesh3.h"
#include "store.h"

static cvm_status create(cvm_mesh **out, cvm__ctx *proto)
{
    cvm_mesh *m = proto->alloc_fn(proto->payload, sizeof *m);
    if (!m)
        return CVM_E_NOMEM;
    memset(m, 0, sizeof *m);
    m->ctx = *proto;
    cvm__options_default(m->opt);
    cvm__store_init(m);
    cvm__write_set_init(&m->staged, &m->ctx);
    *out = m;
    return CVM_OK;
}

cvm_status cvm_mesh_create(cvm_mesh **out)
{
    cvm__ctx proto;
    if (!out)
        return CVM_E_NULL_ARG;
    *out = NULL;
    cvm__ctx_init_default(&proto);
    return create(out, &proto);
}

cvm_status cvm_mesh_create_with_allocator(cvm_mesh **out, cvm_malloc_fn alloc_fn,
                                          cvm_realloc_fn realloc_fn, cvm_free_fn free_fn,
                                          void *payload)
{
    cvm__ctx proto;
    if (!out)
        return CVM_E_NULL_ARG;
    *out = NULL;
    if (!alloc_fn || !realloc_fn || !free_fn)
        return CVM_E_NULL_ARG;
    cvm__ctx_init_default(&proto);
    proto.alloc_fn = alloc_fn;
    proto.realloc_fn = realloc_fn;
    proto.free_fn = free_fn;
    proto.payload = payload;
    return create(out, &proto);
}

void cvm_mesh_free(cvm_mesh *m)
{
    cvm_free_fn f;
    void *payload;
    if (!m)
        return;
    cvm__write_set_discard(&m->staged);
    cvm__mesh3_free(m);
    cvm__pslg_free(&m->ctx, &m->in);
    cvm__store_destroy(m);
    cvm__free(&m->ctx, m->input_map);
    cvm__free(&m->ctx, m->vmark);
    cvm__free(&m->ctx, m->vattr);
    cvm__free(&m->ctx, m->front_marks);
    cvm__free(&m->ctx, m->refine_unmet);
    cvm__free(&m->ctx, m->tlayer);
    cvm__mesh_forget_quads(m);
    cvm__free(&m->ctx, m->names);
    f = m->ctx.free_fn;
    payload = m->ctx.payload;
    f(payload, m);
}

const char *cvm_mesh_errmsg(const cvm_mesh *m)
{
    if (!m)
        return "no mesh handle";
    return m->ctx.errmsg;
}

cvm_status cvm_mesh_error_item(cvm_entity *kind_out, int64_t *index_out, const cvm_mesh *m)
{
    if (!kind_out || !index_out || !m)
        return CVM_E_NULL_ARG;
    *kind_out = m->ctx.err_kind;
    *index_out = m->ctx.err_index;
    return CVM_OK;
}

cvm_status cvm_mesh_set_progress(cvm_mesh *m, cvm_progress_fn fn, int64_t every_n, void *payload)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!fn || every_n < 1) {
        m->ctx.progress_fn = NULL;
        m->ctx.progress_every = 0;
        m->ctx.progress_payload = NULL;
        return CVM_OK;
    }
    m->ctx.progress_fn = fn;
    m->ctx.progress_every = every_n;
    m->ctx.progress_payload = payload;
    return CVM_OK;
}

/* Copy n*k doubles after checking they are finite; kind/what name the item. */
static cvm_status copy_finite(cvm_mesh *m, double **dst, const double *src, size_t n, size_t k,
                              cvm_entity kind, const char *what)
{
    size_t i, bytes;
    double *p;
    for (i = 0; i < n * k; i++)
        if (!isfinite(src[i]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, kind, (int64_t)(i / k),
                              "%s %lu has a non-finite value (component %lu)", what,
                              (unsigned long)(i / k), (unsigned long)(i % k));
    if (!cvm__mul_ok(n, k * sizeof(double), &bytes))
        return cvm__error(&m->ctx, CVM_E_TOO_LARGE, kind, -1, "too many %ss", what);
    p = cvm__malloc(&m->ctx, bytes);
    if (!p)
        return cvm__nomem(&m->ctx);
    if (bytes)
        memcpy(p, src, bytes);
    *dst = p;
    return CVM_OK;
}

cvm_status cvm__mesh_begin_set(cvm_mesh *m, const void *items, size_t count, const char *name)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!items && count > 0)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "%s is NULL", name);
    return CVM_OK;
}

cvm_status cvm_mesh_set_points(cvm_mesh *m, const double *coords, size_t count, int dim)
{
    double *p = NULL;
    cvm_status s;
    if ((s = cvm__mesh_begin_set(m, coords, count, "coords")))
        return s;
    if (dim != 2 && dim != 3)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "dim must be 2 or 3, got %d", dim);
    if (dim == 3)
        return cvm__mesh3_set_points(m, coords, count);
    if (count > (size_t)INT32_MAX / 4)
        return cvm__error(&m->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_POINT, -1,
                          "%lu points exceed the limit of %ld", (unsigned long)count,
                          (long)(INT32_MAX / 4));
    if ((s = copy_finite(m, &p, coords, count, 2, CVM_ENT_INPUT_POINT, "point")))
        return s;
    cvm__mesh3_free(m); /* a 3D handle given 2D points is 2D again */
    cvm__free(&m->ctx, m->in.xy);
    cvm__free(&m->ctx, m->in.pmark);
    cvm__free(&m->ctx, m->in.pattr);
    m->in.xy = p;
    m->in.np = count;
    m->in.pmark = NULL;
    m->in.pattr = NULL;
    m->in.nattr = 0;
    cvm__item_src_free(&m->ctx, &m->in.src_point);
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_point_markers(cvm_mesh *m, const int32_t *markers, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_point_markers");
    }
    int32_t *p;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (count == 0) {
        cvm__free(&m->ctx, m->in.pmark);
        m->in.pmark = NULL;
        return CVM_OK;
    }
    if (!markers)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "markers is NULL");
    if (count != m->in.np)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%lu markers given for %lu points", (unsigned long)count,
                          (unsigned long)m->in.np);
    p = cvm__malloc(&m->ctx, count * sizeof *p);
    if (!p)
        return cvm__nomem(&m->ctx);
    memcpy(p, markers, count * sizeof *p);
    cvm__free(&m->ctx, m->in.pmark);
    m->in.pmark = p;
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_point_attributes(cvm_mesh *m, const double *attrs, size_t count,
                                         size_t nattr)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_point_attributes");
    }
    double *p = NULL;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (count == 0 || nattr == 0) {
        cvm__free(&m->ctx, m->in.pattr);
        m->in.pattr = NULL;
        m->in.nattr = 0;
        return CVM_OK;
    }
    if (!attrs)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "attrs is NULL");
    if (count != m->in.np)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "attributes given for %lu points, but there are %lu points",
                          (unsigned long)count, (unsigned long)m->in.np);
    if ((s = copy_finite(m, &p, attrs, count, nattr, CVM_ENT_INPUT_POINT, "point attribute of point")))
        return s;
    cvm__free(&m->ctx, m->in.pattr);
    m->in.pattr = p;
    m->in.nattr = nattr;
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_segments(cvm_mesh *m, const cvm_index *segs, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_segments");
    }
    int32_t *p;
    cvm_status s;
    if ((s = cvm__mesh_begin_set(m, segs, count, "segs")))
        return s;
    if (count > (size_t)INT32_MAX / 4)
        return cvm__error(&m->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_SEGMENT, -1, "too many segments");
    p = NULL;
    if (count) {
        p = cvm__malloc(&m->ctx, 2 * count * sizeof *p);
        if (!p)
            return cvm__nomem(&m->ctx);
        memcpy(p, segs, 2 * count * sizeof *p);
    }
    cvm__free(&m->ctx, m->in.seg);
    cvm__free(&m->ctx, m->in.smark);
    m->in.seg = p;
    m->in.nseg = count;
    m->in.smark = NULL;
    cvm__item_src_free(&m->ctx, &m->in.src_segment);
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_segment_markers(cvm_mesh *m, const int32_t *markers, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_segment_markers");
    }
    int32_t *p;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (count == 0) {
        cvm__free(&m->ctx, m->in.smark);
        m->in.smark = NULL;
        return CVM_OK;
    }
    if (!markers)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "markers is NULL");
    if (count != m->in.nseg)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%lu markers given for %lu segments", (unsigned long)count,
                          (unsigned long)m->in.nseg);
    p = cvm__malloc(&m->ctx, count * sizeof *p);
    if (!p)
        return cvm__nomem(&m->ctx);
    memcpy(p, markers, count * sizeof *p);
    cvm__free(&m->ctx, m->in.smark);
    m->in.smark = p;
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_holes(cvm_mesh *m, const double *xy, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_holes");
    }
    double *p = NULL;
    cvm_status s;
    if ((s = cvm__mesh_begin_set(m, xy, count, "xy")))
        return s;
    if ((s = copy_finite(m, &p, xy ? xy : (const double *)&m->opt[0], count, 2, CVM_ENT_HOLE, "hole")))
        return s;
    cvm__free(&m->ctx, m->in.holes);
    m->in.holes = p;
    m->in.nholes = count;
    cvm__item_src_free(&m->ctx, &m->in.src_hole);
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_regions(cvm_mesh *m, const double *r, size_t count)
{
    if (m && m->m3) {
        CVM__BEGIN(m);
        return cvm__mesh3_unsupported(m, "cvm_mesh_set_regions");
    }
    double *p = NULL;
    cvm_status s;
    if ((s = cvm__mesh_begin_set(m, r, count, "r")))
        return s;
    if ((s = copy_finite(m, &p, r ? r : (const double *)&m->opt[0], count, 4, CVM_ENT_REGION, "region")))
        return s;
    cvm__free(&m->ctx, m->in.regions);
    m->in.regions = p;
    m->in.nregions = count;
    cvm__item_src_free(&m->ctx, &m->in.src_region);
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

cvm_status cvm_mesh_read(cvm_mesh *m, const char *path)
{
    cvm__pslg p;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!path)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (cvm__path_has_ext(path, ".off") || cvm__path_has_ext(path, ".stl") ||
        cvm__path_has_ext(path, ".smesh") || cvm__path_has_ext(path, ".ele") ||
        ((cvm__path_has_ext(path, ".poly") || cvm__path_has_ext(path, ".node")) &&
         cvm__file_dimension(path) == 3)) {
        s = cvm__mesh3_read(m, path); /* lib/api/mesh3.c */
        if (s == CVM_OK)
            cvm__mesh_set_names(m, NULL, 0);
        return s;
    }
    if (cvm__is_mesh_file(path)) { /* .vtu, .vtk, .msh */
        cvm__phys_name *names;
        size_t nnames;
        cvm_status r = cvm__mesh_read_names(m, path, &names, &nnames); /* marker_names.c */
        if (r == CVM_OK)
            r = cvm__mesh_read_vtu(m, path); /* lib/api/mesh_read_vtu.c */
        if (r == CVM_OK) {
            cvm__mesh3_free(m);
            cvm__mesh_set_names(m, names, nnames);
        } else {
            cvm__free(&m->ctx, names);
        }
        return r;
    }
    memset(&p, 0, sizeof p);
    s = cvm__read_file(&m->ctx, path, &p);
    if (s)
        return s;
    cvm__mesh_set_names(m, NULL, 0);
    cvm__mesh3_free(m);
    cvm__pslg_free(&m->ctx, &m->in);
    m->in = p;
    cvm__mesh_drop_output(m);
    return CVM_OK;
}
