/* read_file.c - reads a .poly or .node file by name, taking the points of a 0-point .poly from its .node. */
#include <string.h>

#include "io_text.h"

static cvm_status read_one(cvm__ctx *ctx, const char *path, int is_poly,
                           const cvm__node_points *ext, cvm__pslg *p, int *base_out)
{
    cvm__reader r;
    cvm_status s = cvm__file_reader_open(ctx, &r, path);
    if (s)
        return s;
    s = cvm__read_triangle_ex(ctx, &r, path, is_poly, ext, p, base_out);
    cvm__file_reader_close(&r);
    return s;
}

/* A .poly without points: read STEM.node, then the .poly again with its
 * segments checked against those points. */
static cvm_status read_poly_with_node(cvm__ctx *ctx, const char *path, cvm__pslg *p)
{
    size_t n = strlen(path) - 5;
    char *node = cvm__malloc(ctx, n + 6);
    cvm__pslg pts, poly;
    cvm__node_points ext;
    int base = -1;
    cvm_status s;
    if (!node)
        return cvm__nomem(ctx);
    memcpy(node, path, n);
    memcpy(node + n, ".node", 6);
    s = read_one(ctx, node, 0, NULL, &pts, &base);
    if (s == CVM_E_IO_OPEN) {
        char why[CVM__ERRMSG_LEN];
        memcpy(why, ctx->errmsg, sizeof why);
        why[sizeof why - 1] = '\0';
        s = cvm__error(ctx, s, CVM_ENT_NONE, -1, "%s has no points, so they must come from %s: %s",
                       path, node, why);
    }
    cvm__free(ctx, node);
    if (s)
        return s;
    ext.np = pts.np;
    ext.base = base < 0 ? 0 : base;
    s = read_one(ctx, path, 1, &ext, &poly, NULL);
    if (s) {
        cvm__pslg_free(ctx, &pts);
        return s;
    }
    poly.xy = pts.xy;
    poly.np = pts.np;
    poly.pmark = pts.pmark;
    poly.pattr = pts.pattr;
    poly.nattr = pts.nattr;
    poly.src_point = pts.src_point;
    *p = poly;
    return CVM_OK;
}

cvm_status cvm__read_file(cvm__ctx *ctx, const char *path, cvm__pslg *p)
{
    cvm_status s;
    memset(p, 0, sizeof *p);
    if (cvm__path_has_ext(path, ".node"))
        return read_one(ctx, path, 0, NULL, p, NULL);
    if (!cvm__path_has_ext(path, ".poly"))
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot read %s: unknown extension (expected .poly, .node, .vtu, .vtk or .msh)", path);
    if ((s = read_one(ctx, path, 1, NULL, p, NULL)))
        return s;
    if (p->np > 0)
        return CVM_OK;
    cvm__pslg_free(ctx, p);
    return read_poly_with_node(ctx, path, p);
}
