/* write_file.c - writes a mesh to a path in the format its extension names, all files or none. */
#include <string.h>

#include "formats.h"

cvm__format cvm__format_of(const char *path)
{
    if (cvm__path_has_ext(path, ".vtu"))
        return CVM__FMT_VTU;
    if (cvm__path_has_ext(path, ".msh"))
        return CVM__FMT_MSH;
    if (cvm__path_has_ext(path, ".node"))
        return CVM__FMT_NODE;
    if (cvm__path_has_ext(path, ".svg"))
        return CVM__FMT_SVG;
    return CVM__FMT_NONE;
}

/* About how many puts each format takes (the progress fraction of a write). */
static uint64_t expected_puts(cvm__format fmt, const cvm__mesh_out *mo)
{
    uint64_t nv = mo->nv, nt = mo->nt, ns = mo->nseg, na = mo->vattr ? mo->nattr : 0;
    switch (fmt) {
    case CVM__FMT_VTU: return nv * (4 + na) + nt * 7 + ns * 6;
    case CVM__FMT_MSH: return nv * 4 + nt * 4 + ns * 3;
    case CVM__FMT_SVG: return nt * 8 + ns * 4;
    default: return 0;
    }
}

static cvm_status write_one(cvm__write_set *ws, const char *path, const cvm__mesh_out *mo,
                            cvm__format fmt)
{
    cvm__writer *w;
    cvm_status s = cvm__writer_open(&w, ws->ctx, path);
    if (s)
        return s;
    cvm__writer_expect(w, 0, expected_puts(fmt, mo));
    switch (fmt) {
    case CVM__FMT_VTU: s = cvm__write_vtu(w, ws->ctx, mo); break;
    case CVM__FMT_MSH: s = cvm__write_msh(w, ws->ctx, mo); break;
    default: s = cvm__write_svg(w, ws->ctx, mo); break;
    }
    if (s) {
        cvm__writer_discard(w);
        return s;
    }
    return cvm__write_set_add(ws, w);
}

/* PREFIX.node, PREFIX.ele and (with edges) PREFIX.edge: all three are
 * written and closed before they join ws, so a write error leaves none. */
static cvm_status write_triangle(cvm__write_set *ws, const char *path, const cvm__mesh_out *mo)
{
    static const char *const ext[3] = {".node", ".ele", ".edge"};
    cvm__ctx *ctx = ws->ctx;
    size_t stem = strlen(path) - 5, i, nfiles = mo->edge ? 3 : 2, n0 = ws->n;
    cvm__writer *w[3] = {NULL, NULL, NULL};
    char *name = cvm__malloc(ctx, stem + 6);
    cvm_status s = CVM_OK;
    if (!name)
        return cvm__nomem(ctx);
    memcpy(name, path, stem);
    for (i = 0; i < nfiles && !s; i++) {
        memcpy(name + stem, ext[i], strlen(ext[i]) + 1);
        s = cvm__writer_open(&w[i], ctx, name);
    }
    cvm__free(ctx, name);
    if (!s) { /* each file only when the ones before it succeeded */
        uint64_t na = mo->vattr ? mo->nattr : 0, nnode = (uint64_t)mo->nv * (4 + na),
                 nele = (uint64_t)mo->nt * (mo->tattr ? 5 : 4), total = nnode + nele + (uint64_t)mo->ne * 4;
        cvm__writer_expect(w[0], 0, total);
        cvm__writer_expect(w[1], nnode, total);
        cvm__write_node(w[0], mo);
        if (!(s = cvm__writer_finish(w[0])))
            cvm__write_ele(w[1], mo);
        if (!s && !(s = cvm__writer_finish(w[1])) && w[2]) {
            cvm__writer_expect(w[2], nnode + nele, total);
            cvm__write_edge(w[2], mo);
            s = cvm__writer_finish(w[2]);
        }
    }
    for (i = 0; i < nfiles; i++) {
        if (!s && w[i]) {
            s = cvm__write_set_add(ws, w[i]);
        } else {
            cvm__writer_discard(w[i]);
        }
    }
    if (s) { /* a failed add: take back the files of this call already added */
        while (ws->n > n0)
            cvm__writer_discard(ws->w[--ws->n]);
    }
    return s;
}

cvm_status cvm__write_file_to_set(cvm__write_set *ws, const char *path, const cvm__mesh_out *mo)
{
    cvm__format fmt = cvm__format_of(path);
    if (fmt == CVM__FMT_NONE)
        return cvm__error(ws->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write %s: unknown extension (expected .vtu, .msh, .node or .svg)",
                          path);
    if (fmt == CVM__FMT_NODE)
        return write_triangle(ws, path, mo);
    return write_one(ws, path, mo, fmt);
}

/* Commit ws when s is CVM_OK, else discard it. */
static cvm_status settle(cvm__write_set *ws, cvm_status s)
{
    if (s) {
        cvm__write_set_discard(ws);
        return s;
    }
    return cvm__write_set_commit(ws);
}

cvm_status cvm__write_file(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo)
{
    cvm__write_set ws;
    cvm__write_set_init(&ws, ctx);
    return settle(&ws, cvm__write_file_to_set(&ws, path, mo));
}

cvm_status cvm__write_dual_file_to_set(cvm__write_set *ws, const char *path, const cvm__dual_out *d)
{
    cvm__writer *w;
    cvm_status s = cvm__writer_open(&w, ws->ctx, path);
    if (s)
        return s;
    cvm__writer_expect(w, 0, (uint64_t)d->npoint * 3 + (uint64_t)d->ncell * 9 + (uint64_t)d->nface * 8);
    cvm__write_dual_vtu(w, d);
    return cvm__write_set_add(ws, w);
}

cvm_status cvm__write_dual_file(cvm__ctx *ctx, const char *path, const cvm__dual_out *d)
{
    cvm__write_set ws;
    cvm__write_set_init(&ws, ctx);
    return settle(&ws, cvm__write_dual_file_to_set(&ws, path, d));
}
