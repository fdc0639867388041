/*
 * mesh_read_vtu.c - cvm_mesh_read of a mesh file (.vtu, .vtk, .msh): the
 * file's cells handed to the engine's rebuild (lib/delaunay/rebuild.h),
 * its messages prefixed with the file name, and the rebuilt mesh moved into
 * the handle only on success.
 */
#include <string.h>

#include "api_internal.h"
#include "store.h"
#include "delaunay/rebuild.h"

/* The file's message for an error of the rebuild on ctx (rb->fault, when
 * set, named with the segments of rb and the points of vm). */
static cvm_status rebuild_error(cvm_mesh *m, const char *path, cvm_status s, cvm__ctx *ctx,
                                const cvm__rebuild *rb, const cvm__vtu_mesh *vm)
{
    if (s == CVM_E_NOMEM && !rb->rebuilding)
        return cvm__nomem(&m->ctx);
    if (rb->fault.kind != CVM__CDT_FAULT_NONE) {
        cvm__pslg in;
        memset(&in, 0, sizeof in);
        in.xy = vm->p.xy;
        in.np = vm->p.np;
        in.seg = rb->seg;
        in.nseg = rb->nseg;
        in.smark = rb->smark;
        in.holes = rb->holes;
        in.nholes = rb->nholes;
        cvm__cdt_fault_message(ctx, &in, s, &rb->fault);
    }
    return cvm__error(&m->ctx, ctx->status, ctx->err_kind, ctx->err_index, "%s: %s%s", path,
                      rb->rebuilding ? "rebuilding the mesh: " : "", ctx->errmsg);
}

/* Move the rebuilt mesh into m: its input and triangulation replace m's
 * (which are freed, with the reports of m's earlier runs); m's context,
 * options, front markers and staged writes stay. Takes the file's point
 * arrays from vm. Cannot fail. */
static void adopt(cvm_mesh *m, cvm__rebuild *rb, cvm__vtu_mesh *vm)
{
    cvm__mesh_drop_output(m);
    cvm__pslg_free(&m->ctx, &m->in);
    m->in.xy = vm->p.xy;
    m->in.np = vm->p.np;
    m->in.pmark = vm->p.pmark;
    m->in.pattr = vm->p.pattr;
    m->in.nattr = vm->p.pattr ? vm->p.nattr : 0;
    vm->p.xy = NULL; /* now m->in's */
    vm->p.pmark = NULL;
    vm->p.pattr = NULL;
    if (rb->nseg) {
        m->in.seg = rb->seg;
        m->in.smark = rb->smark;
        m->in.nseg = rb->nseg;
        rb->seg = rb->smark = NULL;
    }
    m->in.holes = rb->holes;
    m->in.nholes = rb->nholes;
    rb->holes = NULL;
    cvm__store_adopt_tri2(m, &rb->tri);
    m->input_map = rb->out.input_map;
    m->n_dup = rb->out.n_dup;
    cvm__free(&m->ctx, m->vmark);
    cvm__free(&m->ctx, m->vattr);
    m->vmark = rb->out.vmark;
    m->vattr = rb->out.vattr;
    m->cap_vmark = rb->out.cap_vmark;
    m->cap_vattr = rb->out.cap_vattr;
    memset(&rb->out, 0, sizeof rb->out);
    m->triangulated = 1;
    m->nv_triangulated = cvm__store_nv(m);
    m->read_flips = (double)rb->nflips;
}

cvm_status cvm__mesh_read_vtu(cvm_mesh *m, const char *path)
{
    cvm__vtu_mesh vm;
    cvm__rebuild rb;
    cvm__rebuild_input in;
    cvm__ctx ctx;
    cvm__pslg pts;
    cvm_status s = cvm__read_mesh_file(&m->ctx, path, &vm);
    if (s)
        return s;
    if (vm.nt == 0 && !cvm__path_has_ext(path, ".vtu")) { /* a domain: points and lines */
        cvm__mesh_drop_output(m);
        cvm__pslg_free(&m->ctx, &m->in);
        m->in = vm.p;
        memset(&vm.p, 0, sizeof vm.p);
        cvm__vtu_mesh_free(&m->ctx, &vm);
        return CVM_OK;
    }
    if (vm.nt == 0) {
        cvm__vtu_mesh_free(&m->ctx, &vm);
        return cvm__error(&m->ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1,
                          "%s has no triangle cells", path);
    }
    /* the handle's allocator; no progress callback and no time limit (a read
       is not cut short) */
    ctx = m->ctx;
    ctx.progress_fn = NULL;
    ctx.progress_payload = NULL;
    ctx.progress_every = 0;
    cvm__clear_error(&ctx);
    cvm__run_begin(&ctx, 0);
    memset(&pts, 0, sizeof pts);
    pts.xy = vm.p.xy;
    pts.np = vm.p.np;
    pts.pmark = vm.p.pmark;
    pts.pattr = vm.p.pattr;
    pts.nattr = vm.p.pattr ? vm.p.nattr : 0;
    memset(&in, 0, sizeof in);
    cvm__mesh_cdt_input(&in.cdt, m, &pts);
    in.tri = vm.tri;
    in.nt = vm.nt;
    in.lines = vm.p.seg;
    in.lmark = vm.p.smark;
    in.nlines = vm.p.nseg;
    in.has_lines = vm.has_lines;
    in.w = vm.w;
    in.tattr = vm.tattr;
    cvm__rebuild_init(&rb, &ctx);
    if ((s = cvm__rebuild_cells(&rb, &in)))
        s = rebuild_error(m, path, s, &ctx, &rb, &vm);
    else
        adopt(m, &rb, &vm);
    cvm__rebuild_free(&rb);
    cvm__vtu_mesh_free(&m->ctx, &vm);
    return s;
}
