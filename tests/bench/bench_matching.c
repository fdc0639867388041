/* bench_matching.c - driver of bench_matching.py: Delaunay triangulation of N uniform random
 * points (fixed seed), its dual graph weighted by the quality of the quad each pair of
 * triangles forms (identity metric, threshold 0.5, as lib/quad/recombine.c), then the
 * matching timed 5 times (blossom: maximum weight; blossom: maximum cardinality; greedy),
 * and the whole recombination. Prints key=value pairs; medians of CPU and wall seconds.
 * Usage: bench_matching N QMIN [graph_out.txt]: pairs with quality below QMIN are no candidates
 * (0: every convex pair); graph_out gets "n m" then "a b w" lines, for networkx. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cvmesh.h"
#include "quad/matching.h"
#include "quad/recombine.h"

static double clock_s(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double quality(const double *xy, const cvm_index p[4])
{
    double worst = 0;
    int k;
    for (k = 0; k < 4; k++) {
        const double *o = xy + 2 * p[k], *a = xy + 2 * p[(k + 3) % 4], *b = xy + 2 * p[(k + 1) % 4];
        double ux = a[0] - o[0], uy = a[1] - o[1], vx = b[0] - o[0], vy = b[1] - o[1];
        double cross = ux * vy - uy * vx, c;
        if (!(cross < 0)) /* corner turning the wrong way (u is the previous edge) */
            return 0;
        c = (ux * vx + uy * vy) / sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
        c = fabs(acos(c > 1 ? 1 : c < -1 ? -1 : c) * (180 / 3.14159265358979323846) - 90);
        worst = c > worst ? c : worst;
    }
    return 1 - worst / 90;
}

#define REPS 5

int main(int argc, char **argv)
{
    size_t np = argc > 1 ? (size_t)atol(argv[1]) : 10000, nt, i, m = 0, k;
    double qmin = argc > 2 ? atof(argv[2]) : 0.5;
    double *xy = malloc(2 * np * sizeof *xy), cpu[3][REPS], wall[3][REPS], rcpu[REPS];
    cvm_mesh *mesh = NULL;
    cvm_index *tri, *nb, *ends, *mate;
    int64_t *w, weight[3] = {0, 0, 0};
    size_t card[3] = {0, 0, 0};
    uint64_t s = 20261202;
    cvm__ctx ctx;
    cvm__recombine_in in;
    cvm__recombine_out out;
    int r, mode;
    for (i = 0; i < 2 * np; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        xy[i] = (double)(s >> 11) * (1.0 / 9007199254740992.0);
    }
    if (cvm_mesh_create(&mesh) || cvm_mesh_set_points(mesh, xy, np, 2) ||
        cvm_mesh_triangulate(mesh) || cvm_mesh_count(&nt, mesh, CVM_ENT_TRIANGLE)) {
        fprintf(stderr, "triangulation failed\n");
        return 1;
    }
    tri = malloc(3 * nt * sizeof *tri);
    nb = malloc(3 * nt * sizeof *nb);
    ends = malloc(3 * nt * sizeof *ends);
    w = malloc(3 * nt * sizeof *w);
    mate = malloc(nt * sizeof *mate);
    cvm_mesh_copy_cells(tri, 3 * nt, mesh, CVM_ENT_TRIANGLE);
    cvm_mesh_copy_neighbors(nb, 3 * nt, mesh);
    for (i = 0; i < 3 * nt; i++) {
        size_t t = i / 3, u = (size_t)nb[i], j;
        cvm_index a, b, c, d = -1, p[4];
        double q;
        if (nb[i] < 0 || u < t)
            continue;
        /* neighbour k lies opposite vertex k: the shared edge is (k+1, k+2) */
        a = tri[3 * t + (i % 3 + 1) % 3];
        b = tri[3 * t + (i % 3 + 2) % 3];
        c = tri[i];
        for (j = 0; j < 3; j++)
            if (tri[3 * u + j] != a && tri[3 * u + j] != b)
                d = tri[3 * u + j];
        p[0] = a;
        p[1] = d;
        p[2] = b;
        p[3] = c;
        q = quality(xy, p);
        if (q < qmin || !(q > 0))
            continue;
        ends[2 * m] = (cvm_index)t;
        ends[2 * m + 1] = (cvm_index)u;
        w[m++] = cvm__match_scale(q);
    }
    cvm__ctx_init_default(&ctx);
    for (r = 0; r < REPS; r++)
        for (mode = 0; mode < 3; mode++) {
            double c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID), w0 = clock_s(CLOCK_MONOTONIC);
            cvm_status st = mode < 2 ? cvm__matching_solve(mate, NULL, &ctx, nt, m, ends, w,
                                                           (cvm__match_mode)mode)
                                     : cvm__matching_greedy(mate, &ctx, nt, m, ends, w);
            cpu[mode][r] = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
            wall[mode][r] = clock_s(CLOCK_MONOTONIC) - w0;
            if (st) {
                fprintf(stderr, "matching: %s\n", ctx.errmsg);
                return 1;
            }
            weight[mode] = 0;
            card[mode] = 0;
            for (k = 0; k < m; k++)
                if (mate[ends[2 * k]] == (cvm_index)k) {
                    weight[mode] += w[k];
                    card[mode]++;
                }
        }
    memset(&in, 0, sizeof in);
    in.npts = np;
    in.xy = xy;
    in.ntri = nt;
    in.tri = tri;
    in.min_quality = qmin;
    for (r = 0; r < REPS; r++) {
        double c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
        if (cvm__recombine(&out, &ctx, &in)) {
            fprintf(stderr, "recombine: %s\n", ctx.errmsg);
            return 1;
        }
        rcpu[r] = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
        if (r + 1 < REPS)
            cvm__recombine_out_free(&ctx, &out);
    }
    for (mode = 0; mode < 3; mode++) {
        qsort(cpu[mode], REPS, sizeof(double), cmp_d);
        qsort(wall[mode], REPS, sizeof(double), cmp_d);
    }
    qsort(rcpu, REPS, sizeof(double), cmp_d);
    printf("triangles=%zu edges=%zu ", nt, m);
    printf("t_maxweight_cpu=%.4f t_maxweight_wall=%.4f w_maxweight=%lld card_maxweight=%zu ",
           cpu[0][REPS / 2], wall[0][REPS / 2], (long long)weight[0], card[0]);
    printf("t_maxcard_cpu=%.4f w_maxcard=%lld card_maxcard=%zu ", cpu[1][REPS / 2],
           (long long)weight[1], card[1]);
    printf("t_greedy_cpu=%.4f w_greedy=%lld card_greedy=%zu ", cpu[2][REPS / 2],
           (long long)weight[2], card[2]);
    printf("t_recombine_cpu=%.4f quads_pct=%.2f\n", rcpu[REPS / 2],
           100.0 * (double)out.nquad / (double)out.ncell);
    cvm__recombine_out_free(&ctx, &out);
    if (argc > 3) {
        FILE *f = fopen(argv[3], "w");
        if (!f)
            return 1;
        fprintf(f, "%zu %zu\n", nt, m);
        for (k = 0; k < m; k++)
            fprintf(f, "%ld %ld %lld\n", (long)ends[2 * k], (long)ends[2 * k + 1], (long long)w[k]);
        fclose(f);
    }
    cvm_mesh_free(mesh);
    free(xy);
    free(tri);
    free(nb);
    free(ends);
    free(w);
    free(mate);
    return 0;
}
