/* fixtures.c - shared test inputs with known area and Euler characteristic. */
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
