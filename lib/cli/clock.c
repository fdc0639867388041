/* clock.c - the monotonic clock behind --timings and the whole-command --time-limit. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <time.h>

#include "cli.h"

double cli_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_budget_begin(cli_budget *b, const cvm_mesh *m)
{
    b->start = cli_now();
    if (cvm_mesh_get_option(&b->limit, m, CVM_OPT_TIME_LIMIT_S) != CVM_OK)
        b->limit = 0;
}

void cli_budget_apply(const cli_budget *b, cvm_mesh *m)
{
    double left;
    if (!(b->limit > 0))
        return;
    left = b->limit - (cli_now() - b->start);
    (void)cvm_mesh_set_option(m, CVM_OPT_TIME_LIMIT_S, left > 1e-6 ? left : 1e-6);
}
