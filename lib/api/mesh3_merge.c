/*
 * mesh3_merge.c - merged dual cells of a 3D handle: the handle's mesh handed
 * to lib/dual3's merge rule (dual3.h), the measures 725-728,
 * cvm_mesh_copy_dual3_merge_groups() and the cells of a .vtu with
 * CVM_OPT_VTU_MERGED_CELLS.
 */
#include <string.h>

#include "api/mesh3_internal.h"
#include "api/output_internal.h"
#include "dual3/dual3.h"
#include "io/io_internal.h"

/* Run the merge rule on g (g->have); group: ntet entries or NULL. CVM_OK or
 * CVM_E_NOMEM (message set in ctx). */
static cvm_status mesh3_merge_run(cvm__ctx *ctx, const cvm_mesh *m, int32_t *group,
                                  cvm__d3_merge_report *r)
{
    const cvm__mesh3 *g = m->m3;
    int32_t *nbr = NULL, *grp = group;
    uint8_t *cf = NULL;
    cvm__d3_mesh M;
    cvm_status s;
    if ((s = cvm__mesh3_adjacency(ctx, g->tet, g->ntet, &nbr)))
        return s;
    if ((s = cvm__mesh3_constrained_faces(ctx, g, nbr, &cf))) {
        cvm__free(ctx, nbr);
        return s;
    }
    if (!grp && !(grp = cvm__malloc(ctx, (g->ntet + 1) * sizeof *grp))) {
        cvm__free(ctx, nbr);
        cvm__free(ctx, cf);
        return cvm__nomem(ctx);
    }
    M.xyz = g->xyz; /* read only: the merge rule moves nothing */
    M.w = g->w;
    M.nv = g->nv;
    M.tet = g->tet;
    M.ntet = g->ntet;
    M.nbr = nbr;
    M.cface = cf;
    M.attr = g->tattr;
    s = cvm__d3_merge(ctx, &M, g->tattr, cvm__opt(m, CVM_OPT_DUAL3_MERGE_TOL), grp, r);
    if (grp != group)
        cvm__free(ctx, grp);
    cvm__free(ctx, nbr);
    cvm__free(ctx, cf);
    return s;
}

static double m3m_pct(size_t a, size_t b)
{
    return b ? 100.0 * (double)a / (double)b : 0;
}

cvm_status cvm__mesh3_merge_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    cvm__d3_merge_report r;
    cvm_status s;
    if (!m->m3->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no mesh to measure: call cvm_mesh_triangulate() first");
    if ((s = mesh3_merge_run(&m->ctx, m, NULL, &r)))
        return s;
    switch (which) {
    case CVM_MEASURE_DUAL3_MERGED_PCT: *out = m3m_pct(r.nmerged, r.ntet); break;
    case CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT: *out = m3m_pct(r.nnc, r.ntet); break;
    case CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT: *out = m3m_pct(r.nbnc, r.nbnd); break;
    default: *out = (double)r.ndissolved; break;
    }
    return CVM_OK;
}

cvm_status cvm_mesh_copy_dual3_merge_groups(cvm_index *dst, size_t dst_len, const cvm_mesh *m)
{
    cvm__ctx tmp;
    cvm__d3_merge_report r;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if (!m->m3)
        return CVM_E_UNSUPPORTED;
    if (!m->m3->have)
        return CVM_E_STATE;
    if ((s = cvm__room(dst, dst_len, m->m3->ntet)))
        return s;
    if (!m->m3->ntet)
        return CVM_OK;
    tmp = m->ctx; /* a const reader: an error leaves the handle's message alone */
    /* cvm_index is int32_t: the rule writes the groups straight into dst, and
       on CVM_E_NOMEM before it writes anything */
    return mesh3_merge_run(&tmp, m, dst, &r);
}

/* The arrays behind a cvm__mesh3_cells, owned. */
typedef struct m3_cells_mem {
    int32_t *group, *nbr, *off, *memb, *stamp, *tet, *conn;
    uint8_t *type;
    int64_t *conn_off, *faces, *face_off;
} m3_cells_mem;

static void m3_cells_free(cvm__ctx *ctx, m3_cells_mem *a)
{
    cvm__free(ctx, a->group);
    cvm__free(ctx, a->nbr);
    cvm__free(ctx, a->off);
    cvm__free(ctx, a->memb);
    cvm__free(ctx, a->stamp);
    cvm__free(ctx, a->tet);
    cvm__free(ctx, a->conn);
    cvm__free(ctx, a->type);
    cvm__free(ctx, a->conn_off);
    cvm__free(ctx, a->faces);
    cvm__free(ctx, a->face_off);
}

/* One polyhedron per kept group (bounded by the group's outer faces, oriented
 * outwards) and per unmerged tetrahedron (its 4 faces), in the order of the
 * cells' smallest tetrahedra. */
static void m3_cells_fill(const cvm__mesh3 *g, m3_cells_mem *a, cvm__mesh3_cells *c)
{
    size_t nt = g->ntet, t, nc = 0;
    int64_t nconn = 0, nfs = 0;
    for (t = 0; t <= nt; t++)
        a->off[t] = 0;
    for (t = 0; t < nt; t++)
        a->off[a->group[t] + 1]++;
    for (t = 0; t < nt; t++)
        a->off[t + 1] += a->off[t];
    for (t = 0; t < nt; t++)
        a->memb[a->off[a->group[t]]++] = (int32_t)t; /* off[r] ends at the group's end */
    for (t = 0; t < g->nv; t++)
        a->stamp[t] = -1;
    a->conn_off[0] = a->face_off[0] = 0;
    for (t = 0; t < nt; t++) {
        int32_t r = (int32_t)t, n, begin;
        if (a->group[t] != r)
            continue;
        begin = t > 0 ? a->off[t - 1] : 0;
        /* off[t - 1] is the end of group t - 1 = the start of group t's slots */
        n = a->off[t] - begin;
        a->tet[nc] = r;
        /* a lone tetrahedron is a polyhedron too: readers such as meshio take a
           .vtu of polyhedra but not polyhedra mixed with other cells */
        {
            int64_t head = nfs++, i;
            a->type[nc] = 42;
            a->faces[head] = 0;
            for (i = begin; i < begin + n; i++) {
                size_t u = (size_t)a->memb[i];
                int f;
                for (f = 0; f < 4; f++) {
                    int32_t s = a->nbr[4 * u + (size_t)f], fc[3];
                    int j;
                    if (f == 0)
                        for (j = 0; j < 4; j++) {
                            int32_t q = g->tet[4 * u + (size_t)j];
                            if (a->stamp[q] != r) {
                                a->stamp[q] = r;
                                a->conn[nconn++] = q;
                            }
                        }
                    if (s >= 0 && a->group[(size_t)s >> 2] == r)
                        continue;
                    cvm__mesh3_face_corners(g->tet + 4 * u, f, fc);
                    a->faces[head]++;
                    a->faces[nfs++] = 3;
                    for (j = 0; j < 3; j++)
                        a->faces[nfs++] = fc[j];
                }
            }
        }
        nc++;
        a->conn_off[nc] = nconn;
        a->face_off[nc] = nfs;
    }
    c->ncell = nc;
    c->tet = a->tet;
    c->type = a->type;
    c->conn = a->conn;
    c->conn_off = a->conn_off;
    c->faces = a->faces;
    c->face_off = a->face_off;
}

cvm_status cvm__mesh3_write_merged_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws,
                                          struct cvm__mesh3_out *mo)
{
    const cvm__mesh3 *g = m->m3;
    cvm__ctx *ctx = &m->ctx;
    size_t nt = g->ntet;
    m3_cells_mem a;
    cvm__mesh3_cells c;
    cvm__d3_merge_report r;
    cvm_status s;
    memset(&a, 0, sizeof a);
    a.group = cvm__malloc(ctx, (nt + 1) * sizeof *a.group);
    a.off = cvm__malloc(ctx, (nt + 1) * sizeof *a.off);
    a.memb = cvm__malloc(ctx, (nt + 1) * sizeof *a.memb);
    a.stamp = cvm__malloc(ctx, (g->nv + 1) * sizeof *a.stamp);
    a.tet = cvm__malloc(ctx, (nt + 1) * sizeof *a.tet);
    a.conn = cvm__malloc(ctx, (4 * nt + 1) * sizeof *a.conn);
    a.type = cvm__malloc(ctx, nt + 1);
    a.conn_off = cvm__malloc(ctx, (nt + 1) * sizeof *a.conn_off);
    a.faces = cvm__malloc(ctx, (17 * nt + 1) * sizeof *a.faces);
    a.face_off = cvm__malloc(ctx, (nt + 1) * sizeof *a.face_off);
    if (!a.group || !a.off || !a.memb || !a.stamp || !a.tet || !a.conn || !a.type || !a.conn_off ||
        !a.faces || !a.face_off) {
        m3_cells_free(ctx, &a);
        return cvm__nomem(ctx);
    }
    if ((s = mesh3_merge_run(ctx, m, a.group, &r)) ||
        (s = cvm__mesh3_adjacency(ctx, g->tet, nt, &a.nbr))) {
        m3_cells_free(ctx, &a);
        return s;
    }
    m3_cells_fill(g, &a, &c);
    mo->cells = &c;
    s = cvm__write_file3_to_set(ws, path, mo);
    mo->cells = NULL;
    m3_cells_free(ctx, &a);
    return s;
}
