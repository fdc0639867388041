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
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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
    cli_progress_clear();
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
    if (!g_signal)
        cli_progress_show(stage, fraction);
    return g_signal != 0;
}

void cli_outputs_committed(void)
{
    g_committed = 1;
}

int cli_stop(cvm_mesh *m, cvm_sizing *sz)
{
    int sig = (int)g_signal;
    cli_progress_clear();
    cvm_sizing_free(sz);
    cvm_mesh_free(m); /* removes the staged outputs */
    fprintf(stderr, "cvmesh: interrupted by %s while %s%s%s; %s\n",
            sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal", g_what,
            g_name ? " " : "", g_name ? g_name : "",
            g_committed ? "the output files were written" : "no output file was written or changed");
    return 128 + sig;
}

/* -o -: a private folder for the staged mesh (o->stdout_path); 0, or -1
 * after printing why. */
static int stdout_stage_begin(cli_outputs *o)
{
    const char *tmp = getenv("TMPDIR");
    if (!tmp || !*tmp)
        tmp = "/tmp";
    snprintf(o->stdout_dir, sizeof o->stdout_dir, "%s/cvmesh-stdout.XXXXXX", tmp);
    if (!mkdtemp(o->stdout_dir)) {
        fprintf(stderr, "cvmesh: -o -: cannot make a temporary folder in %s: %s\n", tmp,
                strerror(errno));
        o->stdout_dir[0] = '\0';
        return -1;
    }
    snprintf(o->stdout_path, sizeof o->stdout_path, "%s/mesh.%s", o->stdout_dir,
             o->format ? o->format : "vtu");
    return 0;
}

/* Copy the committed mesh to standard output (when copy), then remove it and
 * its folder. 0, or -1 after printing why. */
static int stdout_stage_end(cli_outputs *o, cvm_mesh *m, int copy)
{
    int rc = 0;
    if (!o->stdout_dir[0])
        return 0;
    if (copy) {
        FILE *f = fopen(o->stdout_path, "rb");
        char buf[65536];
        size_t n;
        if (!f) {
            fprintf(stderr, "cvmesh: -o -: %s: %s\n", o->stdout_path, strerror(errno));
            rc = -1;
        } else {
            while (rc == 0 && (n = fread(buf, 1, sizeof buf, f)) > 0)
                if (fwrite(buf, 1, n, stdout) != n)
                    rc = -1;
            if (ferror(f) || fflush(stdout) != 0)
                rc = -1;
            fclose(f);
            if (rc)
                fprintf(stderr, "cvmesh: -o -: writing to standard output failed\n");
        }
    }
    (void)cvm_mesh_discard_writes(m); /* staged, not committed: gone before the folder */
    remove(o->stdout_path);
    rmdir(o->stdout_dir);
    o->stdout_dir[0] = '\0';
    return rc;
}

int cli_write_outputs(cvm_mesh *m, cli_outputs *o)
{
    cvm_status s = CVM_OK;
    const char *out = o->out;
    if (out && strcmp(out, "-") == 0) {
        if (stdout_stage_begin(o))
            return CLI_EXIT_FAIL;
        out = o->stdout_path;
    }
    if (out) {
        cli_phase("writing", o->out);
        s = cvm_mesh_stage_write(m, out);
    }
    if (!s && o->svg) {
        cli_phase("writing", o->svg);
        s = cvm_mesh_stage_write(m, o->svg);
    }
    if (!s && o->dual) {
        cli_phase("writing", o->dual);
        if ((s = cvm_mesh_stage_write_dual(m, o->dual)) != CVM_OK && !cli_interrupted()) {
            fprintf(stderr, "cvmesh: --dual: %s\n", cvm_mesh_errmsg(m));
            stdout_stage_end(o, m, 0);
            return CLI_EXIT_FAIL;
        }
    }
    if (cli_interrupted()) {
        stdout_stage_end(o, m, 0);
        return -1;
    }
    if (s) {
        fprintf(stderr, "cvmesh: %s\n", cvm_mesh_errmsg(m));
        stdout_stage_end(o, m, 0);
        return CLI_EXIT_FAIL;
    }
    cli_phase("replacing the output files", NULL);
    if (cvm_mesh_commit_writes(m) != CVM_OK) {
        fprintf(stderr, "cvmesh: %s\n", cvm_mesh_errmsg(m));
        stdout_stage_end(o, m, 0);
        return CLI_EXIT_FAIL;
    }
    if (out || o->svg || o->dual)
        cli_outputs_committed();
    if (o->stdout_dir[0]) {
        cli_phase("copying the mesh to standard output", NULL);
        if (stdout_stage_end(o, m, 1))
            return CLI_EXIT_FAIL;
    }
    return CLI_EXIT_OK;
}
