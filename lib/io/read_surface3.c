/* read_surface3.c - reads a 3D surface file by extension (.off, .stl, .poly, .smesh), taking the points of a 0-point .poly or .smesh from its .node. */
#include <string.h>

#include "surf3_io.h"

/* The point count on the first content line of a TetGen file (-1 if unreadable). */
static long long first_count(cvm__ctx *ctx, const char *path)
{
    cvm__reader r;
    cvm__scan sc;
    long long n = -1;
    int got = 0;
    cvm__ctx quiet = *ctx; /* errors of this peek are not reported */
    if (cvm__file_reader_open(&quiet, &r, path))
        return -1;
    cvm__scan_init(&sc, &quiet, &r, path);
    if (cvm__scan_line(&sc, &got) == CVM_OK && got &&
        cvm__parse_long(cvm__scan_field(&sc), 0, (long long)CVM__SURF3_MAX_COUNT, &n))
        n = -1;
    cvm__scan_free(&sc);
    cvm__file_reader_close(&r);
    return n;
}

static cvm_status read_node(cvm__ctx *ctx, const char *path, cvm__surf3 *pts)
{
    size_t n = strlen(path);
    const char *dot = strrchr(path, '.');
    size_t stem = dot ? (size_t)(dot - path) : n;
    char *node = cvm__malloc(ctx, stem + 6);
    cvm__reader r;
    cvm_status s;
    if (!node)
        return cvm__nomem(ctx);
    memcpy(node, path, stem);
    memcpy(node + stem, ".node", 6);
    s = cvm__file_reader_open(ctx, &r, node);
    if (s == CVM_OK)
        s = cvm__read_tetnode(ctx, &r, node, pts);
    else {
        char why[CVM__ERRMSG_LEN];
        memcpy(why, ctx->errmsg, sizeof why);
        why[sizeof why - 1] = '\0';
        s = cvm__error(ctx, s, CVM_ENT_NONE, -1, "%s has no points, so they must come from %s: %s",
                       path, node, why);
    }
    cvm__file_reader_close(&r);
    cvm__free(ctx, node);
    return s;
}

static cvm_status read_tetgen(cvm__ctx *ctx, const char *path, int is_smesh, cvm__surf3 *out)
{
    cvm__surf3 pts;
    cvm__surf3_ext_points ext;
    cvm__reader r;
    cvm_status s;
    int with_node = first_count(ctx, path) == 0;
    cvm__surf3_init(&pts);
    if (with_node && (s = read_node(ctx, path, &pts)))
        return s;
    ext.xyz = pts.xyz;
    ext.np = pts.np;
    ext.base = pts.point_base;
    s = cvm__file_reader_open(ctx, &r, path);
    if (s == CVM_OK)
        s = cvm__read_tetpoly(ctx, &r, path, is_smesh, with_node ? &ext : NULL, out);
    cvm__file_reader_close(&r);
    cvm__surf3_free(ctx, &pts);
    return s;
}

cvm_status cvm__read_surface3_file(cvm__ctx *ctx, const char *path, cvm__surf3 *out)
{
    cvm__reader r;
    cvm_status s;
    cvm__surf3_init(out);
    if (cvm__path_has_ext(path, ".poly"))
        return read_tetgen(ctx, path, 0, out);
    if (cvm__path_has_ext(path, ".smesh"))
        return read_tetgen(ctx, path, 1, out);
    if (!cvm__path_has_ext(path, ".off") && !cvm__path_has_ext(path, ".stl"))
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot read %s: unknown extension (expected .off, .stl, .poly or .smesh)", path);
    if ((s = cvm__file_reader_open(ctx, &r, path)))
        return s;
    if (cvm__path_has_ext(path, ".off"))
        s = cvm__read_off(ctx, &r, path, out);
    else
        s = cvm__read_stl(ctx, &r, path, out);
    cvm__file_reader_close(&r);
    return s;
}
