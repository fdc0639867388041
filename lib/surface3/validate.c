/* validate.c - the checks of a 3D boundary surface in order: faces, edges and vertices, intersections. */
#include "surface3_internal.h"

cvm_status cvm__surf3_validate(cvm__ctx *ctx, const cvm__surf3 *s, int flags, cvm__surf3_tris *out)
{
    cvm_status st = cvm__surf3_triangulate(ctx, s, out);
    if (st)
        return st;
    if (out->nt == 0)
        st = cvm__error(ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1, "%s%sthe surface has no faces",
                        s->file ? s->file : "", s->file ? ": " : "");
    if (!st)
        st = cvm__surf3_check_topology(ctx, s, out, flags);
    if (!st)
        st = cvm__surf3_check_intersections(ctx, s, out);
    if (st)
        cvm__surf3_tris_free(ctx, out);
    return st;
}
