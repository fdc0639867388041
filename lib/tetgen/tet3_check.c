/* tet3_check.c - checks a tetrahedralisation handed back by TetGen, orients its tetrahedra by the exact orient3d and counts its Steiner points. */
#include "geom/geom_internal.h"
#include "tetgen_shim.h"

cvm_status cvm__tet3_finish(cvm__ctx *ctx, cvm__tet3_out *out)
{
    size_t i, nb = 0;
    unsigned char *on_face;
    for (i = 0; i < 4 * out->ntet; i++)
        if (out->tet[i] < 0 || (size_t)out->tet[i] >= out->np)
            return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)(i / 4),
                              "TetGen's tetrahedron %lu names point %ld of %lu", (unsigned long)(i / 4),
                              (long)out->tet[i], (unsigned long)out->np);
    for (i = 0; i < 3 * out->nface; i++)
        if (out->face[i] < 0 || (size_t)out->face[i] >= out->np)
            return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_FACET, (int64_t)(i / 3),
                              "TetGen's boundary face %lu names point %ld of %lu", (unsigned long)(i / 3),
                              (long)out->face[i], (unsigned long)out->np);
    for (i = 0; i < out->ntet; i++) {
        int32_t *t = out->tet + 4 * i;
        double o = cvm__orient3d(out->xyz + 3 * t[0], out->xyz + 3 * t[1], out->xyz + 3 * t[2],
                                 out->xyz + 3 * t[3]);
        if (o == 0.0)
            return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)i,
                              "TetGen's tetrahedron %lu (points %ld, %ld, %ld, %ld) is flat",
                              (unsigned long)i, (long)t[0], (long)t[1], (long)t[2], (long)t[3]);
        if (o < 0) {
            int32_t tmp = t[2];
            t[2] = t[3];
            t[3] = tmp;
        }
    }
    on_face = cvm__calloc(ctx, out->np > out->n_input ? out->np - out->n_input : 1, 1);
    if (!on_face)
        return cvm__nomem(ctx);
    for (i = 0; i < 3 * out->nface; i++)
        if ((size_t)out->face[i] >= out->n_input && !on_face[out->face[i] - (int32_t)out->n_input]) {
            on_face[out->face[i] - (int32_t)out->n_input] = 1;
            nb++;
        }
    cvm__free(ctx, on_face);
    out->n_steiner_boundary = nb;
    out->n_steiner_interior = out->np - out->n_input - nb;
    return CVM_OK;
}
