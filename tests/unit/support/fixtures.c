/* fixtures.c - shared test inputs with known area and Euler characteristic. */
#include <stdlib.h>

#include "fixtures.h"

static const double k_swh_xy[] = {0, 0, 3, 0, 3, 3, 0, 3, 1, 1, 2, 1, 2, 2, 1, 2};
static const cvm_index k_swh_seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
static const double k_swh_holes[] = {1.5, 1.5};

const cvmtest_pslg cvmtest_square_with_hole = {
    "square_with_hole", k_swh_xy, 8, k_swh_seg, 8, k_swh_holes, 1, 8.0, 0};

static const double k_us_xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
static const cvm_index k_us_seg[] = {0, 1, 1, 2, 2, 3, 3, 0};

const cvmtest_pslg cvmtest_unit_square = {"unit_square", k_us_xy, 4, k_us_seg, 4, NULL, 0, 1.0, 1};

cvm_status cvmtest_pslg_set(cvm_mesh *m, const cvmtest_pslg *p)
{
    cvm_status s = cvm_mesh_set_points(m, p->xy, p->np, 2);
    if (s == CVM_OK && p->nseg)
        s = cvm_mesh_set_segments(m, p->seg, p->nseg);
    if (s == CVM_OK && p->nholes)
        s = cvm_mesh_set_holes(m, p->holes, p->nholes);
    return s;
}

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void cvmtest_random_points(double *xy, size_t n, uint64_t seed)
{
    size_t i;
    for (i = 0; i < 2 * n; i++)
        xy[i] = (double)(splitmix64(&seed) >> 11) * (1.0 / 9007199254740992.0);
}

cvmtest_pslg *cvmtest_hole_grid(size_t n)
{
    static const double corner[8] = {0.25, 0.25, 0.75, 0.25, 0.75, 0.75, 0.25, 0.75};
    size_t nh = n * n, np = 4 + 4 * nh, i, j, a, k;
    cvmtest_pslg *p = malloc(sizeof *p);
    double *xy = malloc(2 * np * sizeof *xy), *holes = malloc((2 * nh + 1) * sizeof *holes);
    cvm_index *seg = malloc(2 * np * sizeof *seg);
    if (!p || !xy || !holes || !seg) {
        free(p);
        free(xy);
        free(holes);
        free(seg);
        return NULL;
    }
    xy[0] = xy[1] = xy[3] = xy[6] = 0;
    xy[2] = xy[4] = xy[5] = xy[7] = (double)n;
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            k = j * n + i;
            for (a = 0; a < 4; a++) {
                xy[2 * (4 + 4 * k + a)] = (double)i + corner[2 * a];
                xy[2 * (4 + 4 * k + a) + 1] = (double)j + corner[2 * a + 1];
            }
            holes[2 * k] = (double)i + 0.5;
            holes[2 * k + 1] = (double)j + 0.5;
        }
    for (k = 0; k < 1 + nh; k++)
        for (a = 0; a < 4; a++) {
            size_t b = k == 0 ? 0 : 4 + 4 * (k - 1);
            seg[2 * (4 * k + a)] = (cvm_index)(b + a);
            seg[2 * (4 * k + a) + 1] = (cvm_index)(b + (a + 1) % 4);
        }
    p->name = "hole_grid";
    p->xy = xy;
    p->np = np;
    p->seg = seg;
    p->nseg = np;
    p->holes = holes;
    p->nholes = nh;
    p->area = (double)nh - 0.25 * (double)nh;
    p->euler = 1 - (long)nh;
    return p;
}

void cvmtest_pslg_free(cvmtest_pslg *p)
{
    if (!p)
        return;
    free((void *)p->xy);
    free((void *)p->seg);
    free((void *)p->holes);
    free(p);
}
