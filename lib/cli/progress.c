/*
 * progress.c - the progress line on standard error: "cvmesh: refining 43% 12.3 s",
 * redrawn at most four times a second while a long call reports progress. On by
 * default when standard error is a terminal; --progress forces it on, --quiet
 * off. Like the signal state, it belongs to the program, not to the library.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <stdio.h>
#include <unistd.h>

#include "cli.h"

static int g_mode = -1; /* -1: decide by isatty, 0 off, 1 on */
static int g_forced = 0;
static int g_shown = 0;
static double g_start = -1, g_last = 0;

void cli_progress_mode(int on)
{
    g_mode = on;
    g_forced = on;
}

static const char *stage_name(cvm_stage s)
{
    switch (s) {
    case CVM_STAGE_READ: return "reading";
    case CVM_STAGE_SORT: return "sorting";
    case CVM_STAGE_INSERT: return "inserting points";
    case CVM_STAGE_RECOVER_SEGMENTS: return "recovering segments";
    case CVM_STAGE_CARVE: return "carving holes";
    case CVM_STAGE_WRITE: return "writing";
    case CVM_STAGE_REFINE: return "refining";
    case CVM_STAGE_SMOOTH: return "smoothing";
    case CVM_STAGE_OPTIMISE_DUAL: return "optimising the dual";
    case CVM_STAGE_QUAD_OPTIMISE: return "optimising the quad sites";
    }
    return "working";
}

void cli_progress_show(cvm_stage stage, double fraction)
{
    double now;
    if (g_mode < 0)
        g_mode = isatty(fileno(stderr)) ? 1 : 0;
    if (!g_mode)
        return;
    now = cli_now();
    if (g_start < 0)
        g_start = now;
    if (g_shown && now - g_last < 0.25)
        return;
    /* on a terminal a line only once the command has run a moment: short runs
     * print nothing; --progress shows every phase */
    if (!g_forced && now - g_start < 0.5)
        return;
    g_last = now;
    if (fraction >= 0 && fraction <= 1)
        fprintf(stderr, "\rcvmesh: %s %3.0f%% %.1f s\033[K", stage_name(stage), 100 * fraction,
                now - g_start);
    else
        fprintf(stderr, "\rcvmesh: %s %.1f s\033[K", stage_name(stage), now - g_start);
    fflush(stderr);
    g_shown = 1;
}

void cli_progress_clear(void)
{
    if (!g_shown)
        return;
    fprintf(stderr, "\r\033[K");
    fflush(stderr);
    g_shown = 0;
}
