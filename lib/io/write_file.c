/* write_file.c - writes a mesh to a path in the format its extension names, all files or none. */
#include <string.h>

#include "formats.h"

static int ends_with(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext), i;
    if (n <= k)
        return 0;
    for (i = 0; i < k; i++) {
        char c = path[n - k + i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != ext[i])
            return 0;
    }
    return 1;
}

cvm__format cvm__format_of(const char *path)
{
    if (ends_with(path, ".vtu"))
        return CVM__FMT_VTU;
    if (ends_with(path, ".msh"))
        return CVM__FMT_MSH;
    if (ends_with(path, ".node"))
        return CVM__FMT_NODE;
    if (ends_with(path, ".svg"))
        return CVM__FMT_SVG;
    return CVM__FMT_NONE;
}

static cvm_status write_one(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo,
                            cvm__format fmt)
{
    cvm__writer *w;
    cvm_status s = cvm__writer_open(&w, ctx, path);
    if (s)
        return s;
    switch (fmt) {
    case CVM__FMT_VTU: s = cvm__write_vtu(w, ctx, mo); break;
    case CVM__FMT_MSH: s = cvm__write_msh(w, ctx, mo); break;
    default: s = cvm__write_svg(w, ctx, mo); break;
    }
    if (s) {
        cvm__writer_discard(w);
        return s;
    }
    return cvm__writer_commit(w);
}

/* PREFIX.node, PREFIX.ele and (with edges) PREFIX.edge: all three are written
 * and closed before the first is renamed, so a write error leaves none. */
static cvm_status write_triangle(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo)
{
    static const char *const ext[3] = {".node", ".ele", ".edge"};
    size_t stem = strlen(path) - 5, i, nfiles = mo->edge ? 3 : 2;
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
    if (!s) {
        cvm__write_node(w[0], mo);
        cvm__write_ele(w[1], mo);
        if (w[2])
            cvm__write_edge(w[2], mo);
    }
    for (i = 0; i < nfiles && !s; i++)
        s = cvm__writer_finish(w[i]);
    for (i = 0; i < nfiles; i++) {
        if (!s && w[i])
            s = cvm__writer_commit(w[i]);
        else
            cvm__writer_discard(w[i]);
    }
    return s;
}

cvm_status cvm__write_file(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo)
{
    cvm__format fmt = cvm__format_of(path);
    if (fmt == CVM__FMT_NONE)
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write %s: unknown extension (expected .vtu, .msh, .node or .svg)",
                          path);
    if (fmt == CVM__FMT_NODE)
        return write_triangle(ctx, path, mo);
    return write_one(ctx, path, mo, fmt);
}

cvm_status cvm__write_dual_file(cvm__ctx *ctx, const char *path, const cvm__dual_out *d)
{
    cvm__writer *w;
    cvm_status s = cvm__writer_open(&w, ctx, path);
    if (s)
        return s;
    cvm__write_dual_vtu(w, d);
    return cvm__writer_commit(w);
}
