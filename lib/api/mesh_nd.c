/* mesh_nd.c - the dimension-generic calls of the cvm_mesh handle: its dimension, and inputs and
 * outputs given as dim coordinates per item, dispatched to the 2D calls (the only kernel yet). */
#include "api_internal.h"

/* The dimension of every handle until the 3D kernel sets points of dim 3. */
#define MESH_DIM 2

/* The checks every setter below starts with (cvm__mesh_begin_set()), then its dim, which must
 * be the mesh's (cvm__check_dim()). */
static cvm_status begin_nd(cvm_mesh *m, const double *items, size_t count, const char *name, int dim,
                           const char *call)
{
    cvm_status s = cvm__mesh_begin_set(m, items, count, name);
    return s ? s : cvm__check_dim(&m->ctx, dim, call);
}

/* The statuses of cvm__check_dim() for the const readers, which record no message. */
static cvm_status check_dim_const(int dim)
{
    return dim == MESH_DIM ? CVM_OK : dim == 3 ? CVM_E_UNSUPPORTED : CVM_E_ARGUMENT;
}

cvm_status cvm_mesh_dim(int32_t *out, const cvm_mesh *m)
{
    if (!out || !m)
        return CVM_E_NULL_ARG;
    *out = MESH_DIM;
    return CVM_OK;
}

cvm_status cvm_mesh_set_holes_nd(cvm_mesh *m, const double *coords, size_t count, int dim)
{
    cvm_status s = begin_nd(m, coords, count, "coords", dim, "cvm_mesh_set_holes_nd");
    return s ? s : cvm_mesh_set_holes(m, coords, count);
}

cvm_status cvm_mesh_set_regions_nd(cvm_mesh *m, const double *r, size_t count, int dim)
{
    cvm_status s = begin_nd(m, r, count, "r", dim, "cvm_mesh_set_regions_nd");
    return s ? s : cvm_mesh_set_regions(m, r, count); /* 2D: dim + 2 = 4 values per region */
}

cvm_status cvm_mesh_insert_points_nd(cvm_index *ids_out, cvm_mesh *m, const double *coords,
                                     size_t count, int dim, double min_dist)
{
    cvm_status s = begin_nd(m, coords, count, "coords", dim, "cvm_mesh_insert_points_nd");
    return s ? s : cvm_mesh_insert_points(ids_out, m, coords, count, min_dist);
}

cvm_status cvm_mesh_copy_points_nd(double *dst, size_t dst_len, int dim, const cvm_mesh *m)
{
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = check_dim_const(dim)))
        return s;
    return cvm_mesh_copy_points(dst, dst_len, m);
}

cvm_status cvm_mesh_view_points_nd(const double **ptr_out, size_t *count_out, int32_t *dim_out,
                                   const cvm_mesh *m)
{
    cvm_status s;
    if (!ptr_out || !count_out || !dim_out || !m)
        return CVM_E_NULL_ARG;
    if ((s = cvm_mesh_view_points(ptr_out, count_out, m)))
        return s;
    *dim_out = MESH_DIM;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual_vertices_nd(double *dst, size_t dst_len, int dim, const cvm_mesh *m)
{
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = check_dim_const(dim)))
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
    return CVM_E_ARGUMENT;
}
