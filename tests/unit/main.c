/* main.c - runs the Check suites of the unit tests; exit status 0 only if all pass.
 *
 *   unit_tests            every suite, in one runner
 *   unit_tests --list     the suite names, one a line
 *   unit_tests NAME...    only the suites named (.ci/run_unit_tests.sh runs
 *                         each in its own process, several at once)
 *
 * Check's CK_RUN_SUITE and CK_RUN_CASE still narrow any of these. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "suites.h"

typedef struct unit_suite {
    const char *name;
    Suite *(*make)(void);
} unit_suite;

static const unit_suite k_suites[] = {
    {"geom", geom_suite},
    {"delaunay", delaunay_suite},
    {"delaunay3", delaunay3_suite},
    {"io", io_suite},
    {"api", api_suite},
    {"refine", refine_suite},
    {"dual", dual_suite},
    {"surface3", surface3_suite},
    {"quad_recombine", quad_recombine_suite},
    {"quad", quad_suite},
    {"generate3", generate3_suite},
    {"dual3", dual3_suite},
    {"support", support_suite},
};
#define N_SUITES (sizeof k_suites / sizeof k_suites[0])

int main(int argc, char **argv)
{
    SRunner *sr = NULL;
    size_t i;
    int a, failed;
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (i = 0; i < N_SUITES; i++)
            printf("%s\n", k_suites[i].name);
        return EXIT_SUCCESS;
    }
    for (a = 1; a < argc; a++) {
        for (i = 0; i < N_SUITES && strcmp(argv[a], k_suites[i].name) != 0; i++)
            ;
        if (i == N_SUITES) {
            fprintf(stderr, "unit_tests: no suite named '%s' (see --list)\n", argv[a]);
            if (sr)
                srunner_free(sr);
            return 2;
        }
    }
    for (i = 0; i < N_SUITES; i++) {
        int wanted = argc == 1;
        for (a = 1; a < argc && !wanted; a++)
            wanted = strcmp(argv[a], k_suites[i].name) == 0;
        if (!wanted)
            continue;
        if (!sr)
            sr = srunner_create(k_suites[i].make());
        else
            srunner_add_suite(sr, k_suites[i].make());
    }
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
