/*
 * interrupt.c - SIGINT and SIGTERM. The handler only records the signal. The
 * running library call sees it through the progress callback and stops (a
 * write removes its temporary files); a phase that does not report progress
 * runs to its end. The command then frees the mesh, which removes its staged
 * outputs, prints one line saying what was interrupted and exits with
 * 128 + the signal number (130, 143). Output files are staged and committed
 * together (cli_write_outputs), so an interrupted command leaves every file
 * as it was.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <signal.h>
#include <string.h>

#include "cli.h"

/* A signal handler has no payload: the signal and the phase it interrupts
 * are the program's only mutable globals. */
static volatile sig_atomic_t g_signal = 0;
static const char *g_what = "starting";
static const char *g_name = NULL;
static int g_committed = 0;

static void on_signal(int sig)
{
    g_signal = sig;
}

void cli_signals_install(void)
{
    static const int sigs[2] = {SIGINT, SIGTERM};
    size_t i;
    for (i = 0; i < 2; i++) {
        struct sigaction sa, old;
        /* A signal ignored at start stays ignored: a shell without job
         * control starts background commands with SIGINT ignored so that
         * Ctrl-C reaches only the foreground one. */
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESTART; /* a write in progress goes on until the library stops it */
        sigaction(sigs[i], &sa, NULL);
    }
}

void cli_phase(const char *what, const char *name)
{
    g_what = what;
    g_name = name;
}

int cli_interrupted(void)
{
    return (int)g_signal;
}

int cli_progress(void *payload, cvm_stage stage, double fraction)
{
    (void)payload;
    (void)stage;
    (void)fraction;
    return g_signal != 0;
}

void cli_outputs_committed(void)
{
    g_committed = 1;
}

int cli_stop(cvm_mesh *m, cvm_sizing *sz)
{
    int sig = (int)g_signal;
    cvm_sizing_free(sz);
    cvm_mesh_free(m); /* removes the staged outputs */
    fprintf(stderr, "cvmesh: interrupted by %s while %s%s%s; %s\n",
            sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal", g_what,
            g_name ? " " : "", g_name ? g_name : "",
            g_committed ? "the output files were written" : "no output file was written or changed");
    return 128 + sig;
}

int cli_write_outputs(cvm_mesh *m, const char *out, const char *svg, const char *dual)
{
    cvm_status s = CVM_OK;
    if (out) {
        cli_phase("writing", out);
        s = cvm_mesh_stage_write(m, out);
    }
    if (!s && svg) {
        cli_phase("writing", svg);
        s = cvm_mesh_stage_write(m, svg);
    }
    if (!s && dual) {
        cli_phase("writing", dual);
        if ((s = cvm_mesh_stage_write_dual(m, dual)) != CVM_OK && !cli_interrupted()) {
            fprintf(stderr, "cvmesh: --dual: %s\n", cvm_mesh_errmsg(m));
            return CLI_EXIT_FAIL;
        }
    }
    if (cli_interrupted())
        return -1;
    if (s) {
        fprintf(stderr, "cvmesh: %s\n", cvm_mesh_errmsg(m));
        return CLI_EXIT_FAIL;
    }
    cli_phase("replacing the output files", NULL);
    if (cvm_mesh_commit_writes(m) != CVM_OK) {
        fprintf(stderr, "cvmesh: %s\n", cvm_mesh_errmsg(m));
        return CLI_EXIT_FAIL;
    }
    if (out || svg || dual)
        cli_outputs_committed();
    return CLI_EXIT_OK;
}
