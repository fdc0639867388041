/* mesh_nd.c - the dimension-generic calls of the cvm_mesh handle: its dimension, and inputs and
 * outputs given as dim coordinates per item, dispatched to the 2D calls (the only kernel yet). */
#include "api_internal.h"
#include "api/mesh3.h"

/* A handle is 2D until it is given points of dimension 3 (m->m3). */
#define MESH_DIM(m) ((m)->m3 ? 3 : 2)

/* The checks every setter below starts with (cvm__mesh_begin_set()), then its dim, which must
 * be the mesh's (cvm__check_dim()). */
static cvm_status begin_nd(cvm_mesh *m, const double *items, size_t count, const char *name, int dim,
                           const char *call)
{
    cvm_status s = cvm__mesh_begin_set(m, items, count, name);
    if (s)
        return s;
    if (dim == 3 && m->m3)
        return CVM_OK;
    if (dim == 3) /* a 2D handle becomes 3D only through cvm_mesh_set_points() or a read */
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "%s: dim 3, but the mesh is 2D: a mesh goes to the 3D kernel "
                          "once it is given 3D points (cvm_mesh_set_points() with dim 3)", call);
    if (m->m3)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%s: dim %d, but the mesh is 3D", call, dim);
    return cvm__check_dim(&m->ctx, dim, call);
}

/* The statuses of cvm__check_dim() for the const readers, which record no message. */
static cvm_status check_dim_const(const cvm_mesh *m, int dim)
{
    if (dim == MESH_DIM(m))
        return CVM_OK;
    return dim == 3 ? CVM_E_UNSUPPORTED : CVM_E_ARGUMENT;
}

cvm_status cvm_mesh_dim(int32_t *out, const cvm_mesh *m)
{
    if (!out || !m)
        return CVM_E_NULL_ARG;
    *out = MESH_DIM(m);
    return CVM_OK;
}

cvm_status cvm_mesh_set_holes_nd(cvm_mesh *m, const double *coords, size_t count, int dim)
{
    cvm_status s = begin_nd(m, coords, count, "coords", dim, "cvm_mesh_set_holes_nd");
    if (!s && m->m3)
        return cvm__mesh3_set_holes(m, coords, count);
    return s ? s : cvm_mesh_set_holes(m, coords, count);
}

cvm_status cvm_mesh_set_regions_nd(cvm_mesh *m, const double *r, size_t count, int dim)
{
    cvm_status s = begin_nd(m, r, count, "r", dim, "cvm_mesh_set_regions_nd");
    if (!s && m->m3)
        return cvm__mesh3_set_regions(m, r, count); /* 3D: dim + 2 = 5 values per region */
    return s ? s : cvm_mesh_set_regions(m, r, count); /* 2D: dim + 2 = 4 values per region */
}

cvm_status cvm_mesh_insert_points_nd(cvm_index *ids_out, cvm_mesh *m, const double *coords,
                                     size_t count, int dim, double min_dist)
{
    cvm_status s = begin_nd(m, coords, count, "coords", dim, "cvm_mesh_insert_points_nd");
    if (!s && m->m3)
        return cvm__mesh3_insert_points(ids_out, m, coords, count, min_dist);
    return s ? s : cvm_mesh_insert_points(ids_out, m, coords, count, min_dist);
}

cvm_status cvm_mesh_copy_points_nd(double *dst, size_t dst_len, int dim, const cvm_mesh *m)
{
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = check_dim_const(m, dim)))
        return s;
    if (m->m3)
        return cvm__mesh3_copy_points(dst, dst_len, m);
    return cvm_mesh_copy_points(dst, dst_len, m);
}

cvm_status cvm_mesh_view_points_nd(const double **ptr_out, size_t *count_out, int32_t *dim_out,
                                   const cvm_mesh *m)
{
    cvm_status s;
    if (!ptr_out || !count_out || !dim_out || !m)
        return CVM_E_NULL_ARG;
    if (m->m3) {
        *ptr_out = cvm__mesh3_points(m, count_out);
        *dim_out = 3;
        return CVM_OK;
    }
    if ((s = cvm_mesh_view_points(ptr_out, count_out, m)))
        return s;
    *dim_out = MESH_DIM(m);
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_vertices_nd(double *dst, size_t dst_len, int dim, const cvm_mesh *m)
{
    if (m && m->m3)
        return dim == 3 ? cvm__mesh3_copy_dual_vertices(dst, dst_len, m) : CVM_E_ARGUMENT;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = check_dim_const(m, dim)))
        return s;
    return cvm_mesh_copy_dual_vertices(dst, dst_len, m);
}

cvm_status cvm_mesh_get_report(double *out, const cvm_mesh *m, cvm_report which)
{
    int w = (int)which;
    if (!out || !m)
        return CVM_E_NULL_ARG;
    if (w >= (int)CVM_REPORT_REFINE_STEINER && w <= (int)CVM_REPORT_REFINE_MET_ANGLE)
        return cvm__refine_measure(out, m, (cvm_measure)w);
    if (w >= (int)CVM_REPORT_DUAL_OPT_SWEEPS && w <= (int)CVM_REPORT_DUAL_OPT_REMOVED_MAXMIN)
        /* the run's report is stored: this path of cvm__optimise_measure() only reads m */
        return cvm__optimise_measure(out, (cvm_mesh *)m, (cvm_measure)w);
    if (w == (int)CVM_REPORT_READ_FLIPS) {
        *out = m->read_flips;
        return CVM_OK;
    }
    if (w >= (int)CVM_REPORT_GEN3_MATCHED_PAIRS && w <= (int)CVM_REPORT_GEN3_REFINE_ROUNDS)
        return cvm__mesh3_gen3_report(out, m, w);
    return cvm__quad_report(out, m, w);
}
