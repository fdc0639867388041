/* mesh_write.c - cvm_mesh_write: gathers the output arrays of a mesh (cvm__mesh_out) and hands them to lib/io. */
#include <string.h>

#include "output_internal.h"
#include "store.h"
#include "geom/measure.h"
#include "api/mesh3.h"

void cvm__mesh_out_free(cvm_mesh *m, cvm__mesh_out *mo)
{
    cvm__free(&m->ctx, (void *)mo->tri);
    cvm__free(&m->ctx, (void *)mo->tattr);
    cvm__free(&m->ctx, (void *)mo->edge);
    cvm__free(&m->ctx, (void *)mo->emark);
    cvm__free(&m->ctx, (void *)mo->seg);
    cvm__free(&m->ctx, (void *)mo->smark);
    cvm__free(&m->ctx, (void *)mo->tquality);
    cvm__free(&m->ctx, (void *)mo->tlayer);
    if (mo->vattr != m->vattr)
        cvm__free(&m->ctx, (void *)mo->vattr); /* the weight column (lib/api/dual.c) */
    memset(mo, 0, sizeof *mo);
}

/* Triangles, their attributes and (want_quality) their smallest angles and
 * AFLR layer indices. */
static cvm_status gather_triangles(cvm_mesh *m, cvm__mesh_out *mo, int want_quality)
{
    const double *cta = cvm__store_cell_attributes(m);
    size_t nt = cvm__domain_triangles(cvm__store_tri2_const(m)), k = 0;
    int32_t t;
    int32_t *tri = cvm__malloc(&m->ctx, (3 * nt + 1) * sizeof *tri);
    double *ta = cta ? cvm__malloc(&m->ctx, (nt + 1) * sizeof *ta) : NULL;
    double *q = want_quality ? cvm__malloc(&m->ctx, (nt + 1) * sizeof *q) : NULL;
    int layers = want_quality && m->tlayer && m->n_tlayer == cvm__store_nslots(m);
    double *la = layers ? cvm__malloc(&m->ctx, (nt + 1) * sizeof *la) : NULL;
    mo->tri = tri;
    mo->tattr = ta;
    mo->tquality = q;
    mo->tlayer = la;
    if (!tri || (cta && !ta) || (want_quality && !q) || (layers && !la))
        return CVM_E_NOMEM;
    for (t = cvm__store_next_cell(m, -1); t >= 0; t = cvm__store_next_cell(m, t)) {
        const int32_t *v = cvm__store_cell(m, (size_t)t);
        memcpy(tri + 3 * k, v, 3 * sizeof *tri);
        if (ta)
            ta[k] = cta[t];
        if (la)
            la[k] = m->tlayer[t];
        if (q)
            q[k] = cvm__min_angle_deg(cvm__store_point(m, (size_t)v[0]),
                                      cvm__store_point(m, (size_t)v[1]),
                                      cvm__store_point(m, (size_t)v[2]));
        k++;
    }
    mo->nt = nt;
    return CVM_OK;
}

/* Edges (or only segments) with their markers: the segment's marker on a
 * constrained edge; otherwise 1 on the domain boundary and 0 inside (the
 * markers Triangle writes to .edge files). */
static cvm_status gather_edges(cvm_mesh *m, cvm__mesh_out *mo, int segments)
{
    cvm__edges e;
    int32_t *mark;
    size_t k;
    if (cvm__domain_edges(&m->ctx, cvm__store_tri2_const(m), segments, &e))
        return CVM_E_NOMEM;
    mark = cvm__malloc(&m->ctx, (e.n + 1) * sizeof *mark);
    if (!mark) {
        cvm__edges_free(&m->ctx, &e);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < e.n; k++)
        mark[k] = e.seg[k] >= 0 ? cvm__segment_marker(m, e.seg[k]) : e.bnd[k] ? 1 : 0;
    if (segments) {
        mo->seg = e.ev;
        mo->smark = mark;
        mo->nseg = e.n;
    } else {
        mo->edge = e.ev;
        mo->emark = mark;
        mo->ne = e.n;
    }
    e.ev = NULL;
    cvm__edges_free(&m->ctx, &e);
    return CVM_OK;
}

cvm_status cvm__mesh_out_build(cvm_mesh *m, cvm__mesh_out *mo, int want_edges, int want_quality)
{
    memset(mo, 0, sizeof *mo);
    mo->xy = cvm__store_points(m);
    mo->nv = cvm__store_nv(m);
    mo->vmark = m->vmark;
    mo->vattr = m->in.nattr ? m->vattr : NULL;
    mo->nattr = mo->vattr ? m->in.nattr : 0;
    if (cvm__store_weights(m)) { /* weights set: the weight is the first attribute */
        double *wa;
        if (cvm__mesh_weight_attributes(m, &wa))
            return cvm__nomem(&m->ctx);
        mo->vattr = wa;
        mo->nattr++;
        mo->weight = cvm__store_weights(m);
    }
    if (gather_triangles(m, mo, want_quality) || gather_edges(m, mo, 1) ||
        (want_edges && gather_edges(m, mo, 0))) {
        cvm__mesh_out_free(m, mo);
        return cvm__nomem(&m->ctx);
    }
    return CVM_OK;
}

/* The checks and output arrays of cvm_mesh_write(), the files into ws. */
static cvm_status write_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    cvm__mesh_out mo;
    cvm__format fmt;
    cvm_status s;
    if (!path)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "path is NULL");
    if (m->m3)
        return cvm__mesh3_write_to_set(m, path, ws); /* lib/api/mesh3_out.c */
    if (!m->triangulated)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    fmt = cvm__format_of(path);
    if (fmt == CVM__FMT_NONE)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write %s: unknown extension (expected .vtu, .msh, .node or .svg)",
                          path);
    if (m->quad && fmt != CVM__FMT_VTU && fmt != CVM__FMT_MSH)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write %s: the quad-dominant cells of cvm_mesh_quadmesh() are "
                          "written to .vtu and .msh only in this version", path);
    if ((s = cvm__mesh_out_build(m, &mo, fmt == CVM__FMT_NODE,
                                 fmt == CVM__FMT_SVG || (fmt == CVM__FMT_VTU && !m->quad))))
        return s;
    if (m->quad) { /* the mixed cells in place of the triangles */
        const int32_t *tri = mo.tri;
        const double *tlayer = mo.tlayer, *tquality = mo.tquality;
        double *tattr = (double *)mo.tattr;
        size_t c;
        mo.tri = m->quad->conn;
        mo.nt = m->quad->ncell;
        mo.coff = m->quad->off;
        mo.ctype = m->quad->types;
        mo.tlayer = NULL;
        mo.tquality = m->quad->quality;
        mo.tquality_name = "quad_quality";
        for (c = 0; tattr && c < m->quad->ncell; c++) /* in place: first[c] >= c */
            tattr[c] = tattr[m->quad->first[c]];
        mo.vtu_encoding = (int)cvm__opt(m, CVM_OPT_VTU_ENCODING);
        s = cvm__write_file_to_set(ws, path, &mo);
        mo.tri = tri;
        mo.tlayer = tlayer;
        mo.tquality = tquality;
        cvm__mesh_out_free(m, &mo);
        return s;
    }
    mo.window[0] = cvm__opt(m, CVM_OPT_SVG_WINDOW_XMIN);
    mo.window[1] = cvm__opt(m, CVM_OPT_SVG_WINDOW_YMIN);
    mo.window[2] = cvm__opt(m, CVM_OPT_SVG_WINDOW_XMAX);
    mo.window[3] = cvm__opt(m, CVM_OPT_SVG_WINDOW_YMAX);
    mo.vtu_encoding = (int)cvm__opt(m, CVM_OPT_VTU_ENCODING);
    mo.names = m->names;
    mo.nnames = m->nnames;
    s = cvm__write_file_to_set(ws, path, &mo);
    cvm__mesh_out_free(m, &mo);
    return s;
}

cvm_status cvm__mesh_write_now(cvm_mesh *m, const char *path, cvm__mesh_write_fn write)
{
    cvm__write_set ws;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__write_set_init(&ws, &m->ctx);
    if ((s = write(m, path, &ws))) {
        cvm__write_set_discard(&ws);
        return s;
    }
    return cvm__write_set_commit(&ws);
}

cvm_status cvm_mesh_write(cvm_mesh *m, const char *path)
{
    return cvm__mesh_write_now(m, path, write_to_set);
}

cvm_status cvm__mesh_stage_settle(cvm_mesh *m, cvm_status s)
{
    if (s)
        cvm__write_set_discard(&m->staged);
    return s;
}

cvm_status cvm_mesh_stage_write(cvm_mesh *m, const char *path)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    return cvm__mesh_stage_settle(m, write_to_set(m, path, &m->staged));
}

cvm_status cvm_mesh_commit_writes(cvm_mesh *m)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    return cvm__write_set_commit(&m->staged);
}

cvm_status cvm_mesh_discard_writes(cvm_mesh *m)
{
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    cvm__write_set_discard(&m->staged);
    return CVM_OK;
}
