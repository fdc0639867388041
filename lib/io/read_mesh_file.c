/* read_mesh_file.c - opens a mesh file (.vtu, .vtk, .msh) and parses it with the reader its extension names. */
#include <string.h>

#include "io_internal.h"

int cvm__is_mesh_file(const char *path)
{
    return cvm__path_has_ext(path, ".vtu") || cvm__path_has_ext(path, ".vtk") ||
           cvm__path_has_ext(path, ".msh");
}

cvm_status cvm__read_mesh_file(cvm__ctx *ctx, const char *path, cvm__vtu_mesh *out)
{
    cvm_status (*parse)(cvm__ctx *, cvm__reader *, const char *, cvm__vtu_mesh *);
    cvm__reader r;
    cvm_status s;
    memset(out, 0, sizeof *out);
    if (cvm__path_has_ext(path, ".vtu"))
        parse = cvm__read_vtu;
    else if (cvm__path_has_ext(path, ".vtk"))
        parse = cvm__read_vtk;
    else if (cvm__path_has_ext(path, ".msh"))
        parse = cvm__read_msh;
    else
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot read %s as a mesh: unknown extension (expected .vtu, .vtk or "
                          ".msh)", path);
    if ((s = cvm__file_reader_open(ctx, &r, path)))
        return s;
    s = parse(ctx, &r, path, out);
    cvm__file_reader_close(&r);
    return s;
}

cvm_status cvm__read_msh_names_file(cvm__ctx *ctx, const char *path, cvm__phys_name **names_out,
                                    size_t *n_out)
{
    cvm__reader r;
    cvm_status s;
    *names_out = NULL;
    *n_out = 0;
    if ((s = cvm__file_reader_open(ctx, &r, path)))
        return s;
    s = cvm__read_msh_names(ctx, &r, path, names_out, n_out);
    cvm__file_reader_close(&r);
    return s;
}
