/* skip.h - a test that cannot run in this build says so and returns.
 *
 * Check has no skipped state: CVMTEST_SKIP prints one "SKIP: file:line: test:
 * why" line to stderr, and .ci/run_unit_tests.sh counts those lines in its
 * summary, so a build that skips tests (TETGEN=0: the amalgamation) shows how
 * many. Use it only for what the build lacks, never to hide a failure. */
#ifndef CVMTEST_SKIP_H
#define CVMTEST_SKIP_H

#include <stdio.h>

#define CVMTEST_SKIP(why)                                                                  \
    do {                                                                                   \
        fprintf(stderr, "SKIP: %s:%d: %s: %s\n", __FILE__, __LINE__, __func__, (why));     \
        return;                                                                            \
    } while (0)

#endif
