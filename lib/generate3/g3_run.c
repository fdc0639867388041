/*
 * g3_run.c - the sequence of 3D point generation: size field, inside test,
 * near field, free space (lattice, octree or refinement), and (without TetGen) the check that every surface
 * triangle stays a Delaunay face.
 */
#include <string.h>

#include "generate3/generate3.h"

cvm_status cvm__g3_generate(cvm__ctx *ctx, const cvm__g3_surface *s, const cvm__g3_params *p,
                            int check_faces, uint64_t seed, cvm__g3_points *out,
                            cvm__g3_report *rep, int64_t *bad_face)
{
    cvm__g3_points P;
    cvm__g3_size *z = NULL;
    cvm__g3_inside *in = NULL;
    size_t i;
    cvm_status st;
    memset(&P, 0, sizeof P);
    memset(out, 0, sizeof *out);
    memset(rep, 0, sizeof *rep);
    *bad_face = -1;
    /* the surface's points come first: every generated point keeps away from them */
    for (i = 0, st = CVM_OK; i < s->np && !st; i++)
        st = cvm__g3_points_push(ctx, &P, s->xyz + 3 * i, 0);
    if (!st)
        st = cvm__g3_size_create(&z, ctx, s, p);
    if (!st)
        st = cvm__g3_inside_create(&in, ctx, s);
    if (!st)
        st = cvm__g3_near_field(ctx, s, in, p->near_wall, &P, rep);
    /* without boundary recovery, a surface whose own points miss one of its
     * triangles cannot be helped by removing generated points: say so (the
     * check sees the surface's points only, and changes nothing) */
    if (!st && check_faces) {
        cvm__g3_points Q = P;
        Q.n = s->np;
        if ((st = cvm__g3_recover(ctx, s, &Q, seed, rep, bad_face)) == CVM_E_UNSUPPORTED)
            rep->surface_not_delaunay = 1;
    }
    if (!st && p->freespace == CVM_GEN3_FREESPACE_OCTREE)
        st = cvm__g3_octree(ctx, s, z, p->h, p->octree_balance, p->octree_split_hanging, in, &P,
                            rep);
    else if (!st && p->freespace == CVM_GEN3_FREESPACE_REFINE)
        st = cvm__g3_refine(ctx, s, z, p->h, in, p->refine_max, seed, &P, rep,
                            &rep->refine_limited);
    else if (!st)
        st = cvm__g3_lattice(ctx, s, z, p->h, p->lattice_dmf, in, &P, rep);
    if (!st && check_faces)
        st = cvm__g3_recover(ctx, s, &P, seed, rep, bad_face);
    cvm__g3_inside_free(in);
    cvm__g3_size_free(z);
    if (st) {
        cvm__g3_points_free(ctx, &P);
        return st;
    }
    /* hand over the generated points only */
    if (P.n > s->np) {
        memmove(P.xyz, P.xyz + 3 * s->np, 3 * (P.n - s->np) * sizeof *P.xyz);
        memmove(P.dm, P.dm + s->np, (P.n - s->np) * sizeof *P.dm);
    }
    P.n -= s->np;
    *out = P;
    return CVM_OK;
}
