/* suite.c - the quad suite: one TCase per source file under test. */
#include "suites.h"
#include "quad/quad_tests.h"

void qtest_box(double *xy, double x0, double y0, double x1, double y1, int n)
{
    int k, i = 0;
    for (k = 0; k < n; k++, i++) { /* bottom, right, top, left */
        xy[2 * i] = x0 + (x1 - x0) * k / n;
        xy[2 * i + 1] = y0;
    }
    for (k = 0; k < n; k++, i++) {
        xy[2 * i] = x1;
        xy[2 * i + 1] = y0 + (y1 - y0) * k / n;
    }
    for (k = 0; k < n; k++, i++) {
        xy[2 * i] = x1 - (x1 - x0) * k / n;
        xy[2 * i + 1] = y1;
    }
    for (k = 0; k < n; k++, i++) {
        xy[2 * i] = x0;
        xy[2 * i + 1] = y1 - (y1 - y0) * k / n;
    }
}

double qtest_uniform(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

Suite *quad_suite(void)
{
    Suite *s = suite_create("quad");
    suite_add_tcase(s, quad_dunavant_tcase());
    suite_add_tcase(s, quad_metric_tcase());
    suite_add_tcase(s, quad_lpcvt_energy_tcase());
    suite_add_tcase(s, quad_lpcvt_optimise_tcase());
    suite_add_tcase(s, quad_quadmesh_tcase());
    return s;
}
