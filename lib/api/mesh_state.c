/* mesh_state.c - forgetting what a mesh handle computed: the whole output (triangulation,
 * input map, reports) when its input changes, or only the AFLR layer indices or the quads. */
#include <string.h>

#include "api_internal.h"
#include "store.h"

void cvm__mesh_forget_layers(cvm_mesh *m)
{
    cvm__free(&m->ctx, m->tlayer);
    m->tlayer = NULL;
    m->n_tlayer = 0;
    cvm__mesh_forget_quads(m); /* the same calls change the triangles the quads are made of */
}

void cvm__mesh_drop_output(cvm_mesh *m)
{
    cvm__store_clear(m);
    m->triangulated = 0;
    cvm__free(&m->ctx, m->input_map);
    m->input_map = NULL;
    m->n_dup = 0;
    m->nv_triangulated = 0;
    memset(m->refine_report, 0, sizeof m->refine_report);
    cvm__free(&m->ctx, m->refine_unmet);
    m->refine_unmet = NULL;
    m->n_refine_unmet = 0;
    memset(m->dual_opt_report, 0, sizeof m->dual_opt_report);
    m->read_flips = 0;
    cvm__free(&m->ctx, m->tlayer);
    m->tlayer = NULL;
    m->n_tlayer = 0;
    cvm__mesh_forget_quads(m);
}

void cvm__mesh_forget_quads(cvm_mesh *m)
{
    cvm__quad_cells *q = m->quad;
    memset(m->quad_report, 0, sizeof m->quad_report);
    if (!q)
        return;
    cvm__free(&m->ctx, q->off);
    cvm__free(&m->ctx, q->types);
    cvm__free(&m->ctx, q->conn);
    cvm__free(&m->ctx, q->first);
    cvm__free(&m->ctx, q->quality);
    cvm__free(&m->ctx, q);
    m->quad = NULL;
}
