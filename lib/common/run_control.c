/* run_control.c - progress callback, time limit and cancellation checks. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L
#endif
#include <time.h>

#include "common_internal.h"

double cvm__now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cvm__run_begin(cvm__ctx *ctx, double time_limit_s)
{
    ctx->ops = 0;
    ctx->deadline = time_limit_s > 0 ? cvm__now() + time_limit_s : 0.0;
}

static double clamp01(double f)
{
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

cvm_status cvm__poll_cancel(cvm__ctx *ctx, cvm_stage stage, double fraction)
{
    if (ctx->progress_fn && ctx->progress_every > 0 &&
        ctx->progress_fn(ctx->progress_payload, stage, clamp01(fraction)))
        return CVM_INCOMPLETE_CANCELLED;
    return CVM_OK;
}

cvm_status cvm__tick(cvm__ctx *ctx, int64_t n, cvm_stage stage, double fraction)
{
    int64_t every = ctx->progress_fn && ctx->progress_every > 0 ? ctx->progress_every : 1024;
    ctx->ops += n;
    if (ctx->ops < every)
        return CVM_OK;
    ctx->ops = 0;
    if (ctx->progress_fn && ctx->progress_every > 0) {
        if (ctx->progress_fn(ctx->progress_payload, stage, clamp01(fraction)))
            return CVM_INCOMPLETE_CANCELLED;
    }
    if (ctx->deadline > 0 && cvm__now() > ctx->deadline)
        return CVM_INCOMPLETE_TIME_LIMIT;
    return CVM_OK;
}
