/*
 * optimise.c - the sweep driver of the dual optimiser: scores every triangle,
 * visits the vertices of the non-compliant ones worst first, solves each
 * vertex's local problem, and restores the regular triangulation after each
 * sweep.
 *
 * Score of domain triangle k: F_k = W_k L_k |C_k - V_k| (centroid C, power
 * vertex V); W_k = 1 when V lies outside k (exact cvm__power_side2d) and k
 * cannot be merged (merge.c), else 0; L_k = 1 + c / (1 + layer_k) with c the
 * layer priority and layer_k the breadth-first layer of k from the boundary
 * (cvm__dual_layers; boundary cells first). Within a sweep the topology is
 * fixed and only coordinates and weights change; the triangles with F > 0 are
 * sorted by F (worst first, ties by slot), cut into min(20, N/25) bins of equal
 * count and shuffled within each bin by a stream keyed by (seed, sweep); each
 * vertex is solved at most once per sweep, and the triangles it touches (and
 * their neighbours, whose merge state depends on it) are re-scored at once.
 * After the sweep, Lawson flips under the exact power test restore the
 * regular triangulation; a vertex whose power cell vanished (the blocking
 * corner of an unflippable illegal edge) is removed when it is a removable
 * Steiner vertex and p->topology is set (topology.c; then compact() renumbers
 * the vertices and carries vsize, vbnd and p->vmap along); any other gets its
 * weight raised (by 0.1,
 * 0.2, 0.4 ... times its squared local size) until none vanishes; after 8
 * rounds every weight is reset to 0, which always leaves a valid
 * (constrained Delaunay) mesh. With p->topology 2, repair_degrees() removes
 * vertices after the first sweeps (experimental). The run stops when
 * nothing is non-compliant or weak, a sweep moves nothing, or at the sweep
 * limit, the time limit or cancellation; once all is compliant, PATIENCE
 * sweeps without progress (smallest angle up by PROGRESS_DEG, or the weak
 * count 1% below its last low) raise the target angle by PUSH_DEG (PUSHES
 * times), then end the run. keep_best() remembers the best state (fewest
 * non-compliant, then largest smallest angle) and end_at_best() returns to it
 * at a normal end: a later sweep can lower the smallest angle, since moves
 * trade angles against the penalty of others.
 *
 * When the run ends compliant, maxmin_phase() raises the smallest angle with
 * every triangle kept compliant: rounds of per-vertex max-min solves under
 * constraints that keep the star regular (so no flip follows and the
 * per-triangle state is kept up to date by the moves), then removal trials on
 * a snapshot of the whole triangulation when CVM_OPT_DUAL_MAXMIN_TRIALS asks
 * (see CVM_OPT_DUAL_MAXMIN_ROUNDS and _TRIALS in
 * cvmesh.h for the rules, docs/design/dual_optimisation.md for the effect).
 *
 * Parallel and deterministic: the order above is cut into batches of vertices
 * no two of which are equal or share a triangle's vertex (so their local
 * problems read no vertex that moves); a batch's problems are solved on
 * OpenMP threads, then applied and re-scored in batch order. Batches depend
 * only on the mesh and the order, so the result is identical for any
 * CVM_OPT_THREADS.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

static cvm_status run(dopt *D)
{
    const cvm__dual_opt_params *p = D->p;
    cvm_status s, s2;
    uint64_t k;
    size_t best_nc = (size_t)-1, stall = 0;
    double best_min = -1.0;
    int phase = 0;
    double prog_min;
    size_t weak_low = (size_t)-1; /* fewest weak triangles at a progress mark */
    if ((s = cvm__dopt_sizes(D)))
        return s;
    cvm__dopt_boundary_flags(D);
    if ((s = cvm__dopt_restore(D)))
        return s;
    cvm__dual_layers(D->T, D->vbnd, D->layer, D->list);
    cvm__dopt_score_all(D);
    D->nc0 = D->nc;
    D->rep->nc_before_pct = cvm__dopt_pct(D);
    cvm__dopt_keep_best(D, &best_nc, &best_min);
    prog_min = best_min;
    for (k = 0; k < (uint64_t)p->max_sweeps && (D->nc || D->nweak); k++) {
        size_t moved = 0, nc_prev, flips0, rem0;
        int better;
        if ((s = cvm__dopt_sizes(D)))
            return s;
        cvm__dopt_boundary_flags(D);
        cvm__dual_layers(D->T, D->vbnd, D->layer, D->list);
        cvm__dopt_score_all(D);
        if (!D->nc && !D->nweak)
            break;
        nc_prev = D->nc;
        cvm__dopt_save_state(D);
        s = cvm__dopt_sweep(D, k, &moved);
        D->rep->moves += moved;
        D->rep->sweeps++;
        flips0 = D->rep->flips;
        rem0 = D->rep->removed_vanished;
        if ((s2 = cvm__dopt_restore(D))) {
            /* out of memory: without a flip, go back to the regular state of the
             * sweep's start; after flips the topology follows the new positions,
             * which stay (conforming, counter-clockwise, maybe not regular) */
            if (D->rep->flips == flips0 && D->rep->removed_vanished == rem0)
                cvm__dopt_load_state(D);
            return s2;
        }
        if (s)
            return s;
        cvm__dopt_score_all(D);
        if (D->topo && D->p->topology >= 2 && k < DEG_SWEEPS) {
            size_t nrem = cvm__dopt_repair_degrees(D);
            if (nrem) {
                D->rep->removed_degree += nrem;
                cvm__dopt_compact(D);
                if ((s = cvm__dopt_restore(D)))
                    return s;
                cvm__dopt_score_all(D);
                best_nc = (size_t)-1; /* the old best had other vertices */
                cvm__dopt_keep_best(D, &best_nc, &best_min);
                continue; /* the topology changed: sweep again */
            }
        }
        cvm__dopt_keep_best(D, &best_nc, &best_min);
        better = best_min > prog_min + PROGRESS_DEG;
        if (better)
            prog_min = best_min;
        /* stop when nothing moved, or when everything is compliant and for
         * PATIENCE sweeps neither the smallest angle improved by PROGRESS_DEG
         * nor the weak triangles dropped 1% below their last low; then the
         * target angle is raised (PUSHES times) before the run ends */
        if (!moved)
            break;
        if (!D->nc && !nc_prev) {
            if (better || 100 * D->nweak < 99 * weak_low) {
                stall = 0;
                weak_low = D->nweak < weak_low ? D->nweak : weak_low;
            } else if (++stall >= (phase ? PUSH_PATIENCE : PATIENCE)) {
                double push = p->target_angle_deg + PUSH_DEG * (phase + 1);
                if (phase >= PUSHES || !(p->target_angle_deg > 0) || push > 60.0)
                    break;
                /* next phase: a higher target angle; keep_best keeps the best end */
                phase++;
                stall = 0;
                D->sin2_target = sin(push * CVM__PI / 180.0);
                D->sin2_target *= D->sin2_target;
            }
        }
    }
    if ((s = cvm__dopt_end_at_best(D, best_nc, best_min)))
        return s;
    if (p->maxmin_rounds > 0 && p->max_sweeps > 0 && !D->nc) {
        cvm__dopt_score_all(D);
        if (!D->nc && (s = cvm__dopt_maxmin_phase(D, k, &best_nc, &best_min)))
            return s;
        return cvm__dopt_end_at_best(D, best_nc, best_min);
    }
    return CVM_OK;
}

cvm_status cvm__dual_optimise(cvm__tri2 *T, const cvm__dual_opt_params *p, cvm__dual_opt_report *rep)
{
    cvm__ctx *ctx = T->ctx;
    dopt D;
    size_t nv = T->nv, nt = T->nt;
    double t0 = cvm__now();
    cvm_status s;
    memset(rep, 0, sizeof *rep);
    memset(&D, 0, sizeof D);
    D.T = T;
    D.p = p;
    D.rep = rep;
    D.sin2_min = sin(p->min_angle_deg * CVM__PI / 180.0);
    D.sin2_min *= D.sin2_min;
    D.nthreads = p->threads;
#ifdef _OPENMP
    if (D.nthreads <= 0)
        D.nthreads = omp_get_max_threads();
#endif
    if (D.nthreads <= 0)
        D.nthreads = 1;
    D.sin2_target = sin(p->target_angle_deg * CVM__PI / 180.0);
    D.sin2_target *= D.sin2_target;
    if (!T->w) {
        T->w = cvm__calloc(ctx, T->cap_v ? T->cap_v : 1, sizeof *T->w);
        if (!T->w)
            return CVM_E_NOMEM;
    }
    if (p->topology && p->vmap) {
        size_t v;
        for (v = 0; v < nv; v++)
            p->vmap[v] = (int32_t)v;
    }
    D.nv0 = nv;
    if (p->prepass && p->topology && p->vmap) {
        /* before the per-vertex and per-triangle arrays: counts may change */
        if ((s = cvm__dual_prepass(T, p, nv, &rep->prepass_removed, &rep->prepass_added))) {
            rep->seconds = cvm__now() - t0;
            return s;
        }
        nv = T->nv;
        nt = T->nt;
    }
    D.vsize = cvm__malloc(ctx, (nv + 1) * sizeof *D.vsize);
    D.msize = cvm__malloc(ctx, (nv + 1) * sizeof *D.msize);
    D.vbnd = cvm__malloc(ctx, nv + 1);
    D.mark = cvm__malloc(ctx, nv + 1);
    D.V = cvm__malloc(ctx, (2 * nt + 1) * sizeof *D.V);
    D.F = cvm__malloc(ctx, (nt + 1) * sizeof *D.F);
    D.st = cvm__calloc(ctx, nt + 1, 1);
    D.weak = cvm__calloc(ctx, nt + 1, 1);
    D.layer = cvm__calloc(ctx, nt + 1, sizeof *D.layer);
    D.list = cvm__malloc(ctx, (nt + 1) * sizeof *D.list);
    D.star = cvm__malloc(ctx, (nt + 1) * sizeof *D.star);
    D.save = cvm__malloc(ctx, (3 * nv + 1) * sizeof *D.save);
    D.best = cvm__malloc(ctx, (3 * nv + 1) * sizeof *D.best);
    /* the optimiser adds no triangle slot: nt bounds them (keep_best checks) */
    D.best_cap = nt;
    D.best_tv = cvm__malloc(ctx, (3 * nt + 1) * sizeof *D.best_tv);
    D.best_tn = cvm__malloc(ctx, (3 * nt + 1) * sizeof *D.best_tn);
    D.best_te = T->te ? cvm__malloc(ctx, (3 * nt + 1) * sizeof *D.best_te) : NULL;
    D.best_tf = cvm__malloc(ctx, nt + 1);
    D.best_ta = T->ta ? cvm__malloc(ctx, (nt + 1) * sizeof *D.best_ta) : NULL;
    D.best_vtri = cvm__malloc(ctx, (nv + 1) * sizeof *D.best_vtri);
    D.jobs = cvm__malloc(ctx, BATCH * sizeof *D.jobs);
    D.stamp = cvm__calloc(ctx, nv + 1, sizeof *D.stamp);
    D.region = cvm__calloc(ctx, nv + 1, 1);
    D.topo = p->topology && p->vmap;
    if (D.topo) {
        D.gone = cvm__calloc(ctx, nv + 1, 1);
        D.dup = cvm__malloc(ctx, (nv + 1) * sizeof *D.dup);
        D.map2 = cvm__malloc(ctx, (nv + 1) * sizeof *D.map2);
    }
    if (!D.vsize || !D.msize || !D.vbnd || !D.mark || !D.V || !D.F || !D.st || !D.weak || !D.layer || !D.list || !D.star || !D.save || !D.best || !D.jobs ||
        !D.best_tv || !D.best_tn || (T->te && !D.best_te) || !D.best_tf || (T->ta && !D.best_ta) || !D.best_vtri ||
        !D.stamp || !D.region || (D.topo && (!D.gone || !D.dup || !D.map2)))
        s = CVM_E_NOMEM;
    else
        s = run(&D);
    if (D.V && D.st && D.weak && D.layer && D.F && D.vsize && D.msize && D.vbnd && D.save) {
        cvm__dopt_score_all(&D);
        rep->nc_after_pct = cvm__dopt_pct(&D);
        if (!rep->sweeps && !D.nc0)
            rep->nc_before_pct = rep->nc_after_pct;
    }
    cvm__free(ctx, D.vsize);
    cvm__free(ctx, D.msize);
    cvm__free(ctx, D.vbnd);
    cvm__free(ctx, D.mark);
    cvm__free(ctx, D.V);
    cvm__free(ctx, D.F);
    cvm__free(ctx, D.st);
    cvm__free(ctx, D.weak);
    cvm__free(ctx, D.layer);
    cvm__free(ctx, D.list);
    cvm__free(ctx, D.star);
    cvm__free(ctx, D.save);
    cvm__free(ctx, D.best);
    cvm__free(ctx, D.best_tv);
    cvm__free(ctx, D.best_tn);
    cvm__free(ctx, D.best_te);
    cvm__free(ctx, D.best_tf);
    cvm__free(ctx, D.best_ta);
    cvm__free(ctx, D.best_vtri);
    cvm__free(ctx, D.jobs);
    cvm__free(ctx, D.stamp);
    cvm__free(ctx, D.region);
    cvm__free(ctx, D.gone);
    cvm__free(ctx, D.dup);
    cvm__free(ctx, D.map2);
    cvm__dopt_snap_free(ctx, D.snap);
    rep->seconds = cvm__now() - t0;
    return s;
}
