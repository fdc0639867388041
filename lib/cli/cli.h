/*
 * cli.h - pieces of the cvmesh program shared by its files. The program sees
 * only the public API (include/cvmesh.h). Exit status: 0 success, 1 the
 * input or an output could not be processed, 2 the command line is wrong,
 * 130 / 143 interrupted by SIGINT / SIGTERM (no output file changed).
 */
#ifndef CVM_CLI_H
#define CVM_CLI_H

#include <stdio.h>
#include "cvmesh.h"

#define CLI_EXIT_OK 0
#define CLI_EXIT_FAIL 1
#define CLI_EXIT_USAGE 2

/* Subcommands, as bits: an option flag lists the subcommands that take it. */
enum {
    CLI_CMD_TRIANGULATE = 1u << 0,
    CLI_CMD_REFINE = 1u << 1,
    CLI_CMD_OPTIMISE = 1u << 2,
    CLI_CMD_TETRAHEDRALIZE = 1u << 3,
    CLI_CMD_MESH3 = 1u << 4,
    CLI_CMD_QUAD = 1u << 5
};

/* One flag that sets a library option (flags.c holds the one table). */
typedef struct cli_option_flag {
    const char *name;   /* "--seed" */
    const char *arg;    /* metavariable ("S"), or NULL for a switch */
    cvm_option key;
    double value;       /* value a switch sets */
    unsigned commands;  /* CLI_CMD_* bits */
    const char *help;
} cli_option_flag;

/* An option value chosen on the command line, applied once the mesh exists. */
typedef struct cli_setting {
    const cli_option_flag *flag;
    double value;
} cli_setting;

#define CLI_MAX_SETTINGS 32

/* ---- args.c: the flags every subcommand shares ---- */

/* "--name V" or "--name=V": when argv[*i] is flag name, *val is its value (the
 * next argument, consumed, or the text after '=') and the result is 1; 0 when
 * argv[*i] is another flag; -1 after printing why when the value is missing. */
int cli_take_value(int argc, char **argv, int *i, const char *name, const char **val);

/* What a command writes and prints: -o/--output (OUT or "-": standard output,
 * in --format), --svg, --dual, --quality[=short|full], --timings. */
typedef struct cli_outputs {
    const char *command;  /* the subcommand's name, for messages */
    const char *out, *svg, *dual;
    const char *format;   /* --format EXT for -o - (default vtu) */
    int quality;          /* 0 none, 1 short, 2 full */
    int timings;
    int with_svg, with_dual;      /* the command takes --svg / --dual */
    /* -o -: where the mesh is staged before it is copied to standard output */
    char stdout_dir[4096], stdout_path[4200];
    double t0, t_last;    /* --timings: start of the command and of the phase */
} cli_outputs;

/* If argv[*i] is one of the flags above, take it (with its value) and return
 * 1; 0 when it is not; -1 after printing a usage error. */
int cli_parse_outputs(cli_outputs *o, int argc, char **argv, int *i);
/* After the argument loop: the file names end in what their flag writes
 * (case-insensitive), "-o -" names a format that fits one stream. CLI_EXIT_OK,
 * or CLI_EXIT_USAGE after printing why (name: the subcommand). */
int cli_check_outputs(const char *name, const cli_outputs *o);
/* The stream of the reports: standard error when the mesh goes to standard
 * output, else standard output. */
FILE *cli_report_stream(const cli_outputs *o);
/* --timings: start the clock (cli_timing_begin), then print "PHASE: SECONDS"
 * for the time since the previous mark (nothing without --timings). */
void cli_timing_begin(cli_outputs *o);
void cli_timing_mark(cli_outputs *o, const char *phase);
/* The help lines of these flags (for a command with or without --svg/--dual). */
void cli_print_output_help(FILE *f, int with_svg, int with_dual);
/* A note on standard error when the command was asked for nothing to write or
 * print: its input was still read and checked. */
void cli_note_nothing_to_do(const char *name, const char *in, const cli_outputs *o);
/* A note on standard error when the triangulation of in merged duplicate points. */
void cli_note_duplicates(const cvm_mesh *m, const char *in);
/* "%.17g" shortened to the fewest digits that read back as v (0.15, not
 * 0.14999999999999999), into buf. */
const char *cli_fmt_number(char *buf, size_t len, double v);

/* The shared start of refine and optimise: a new mesh with the option
 * settings applied, cli_progress installed, and a sizing, uniform size when
 * size > 0. Returns
 * CLI_EXIT_OK, or an exit status after printing why (nothing left allocated). */
int cli_start(cvm_mesh **m, cvm_sizing **sz, const cli_setting *set, int nset, double size);

/* The shared end of refine and optimise: s is the status of their main call on
 * m (input file in). An error fails (message printed); an incomplete status
 * prints a note and goes on. Then write o's outputs as one set, print the
 * quality report and report(stream, m) when o asks for quality, the timings
 * "write" and "quality", and free m and sz. Returns CLI_EXIT_OK or the exit status of the
 * first failure or of an interruption. */
int cli_finish(cvm_mesh *m, cvm_sizing *sz, const char *in, cvm_status s, cli_outputs *o,
               void (*report)(FILE *, cvm_mesh *));

/* --algo NAME of command name: delaunay, frontal, and aflr when with_aflr,
 * into *out. CLI_EXIT_OK, or CLI_EXIT_USAGE after printing why. */
int cli_parse_algo(const char *name, const char *s, int with_aflr, cvm_algorithm *out);

/* The value v of flag as a positive finite number into *out. CLI_EXIT_OK, or
 * CLI_EXIT_USAGE after printing why ("cvmesh: FLAG V: must be a positive number"). */
int cli_parse_positive(const char *flag, const char *v, double *out);
/* The same for a finite number >= 0. */
int cli_parse_nonnegative(const char *flag, const char *v, double *out);

/* The shared tail of a subcommand's argument loop, after its own flags:
 * argv[*i] is an option flag of cmd (recorded in set), or else the one input
 * file (*in). Returns CLI_EXIT_OK, or CLI_EXIT_USAGE after printing why
 * ("cvmesh: NAME: ..."). */
int cli_parse_tail(const char *name, unsigned cmd, int argc, char **argv, int *i,
                   cli_setting *set, int *nset, const char **in);
/* A subcommand's own flags: if argv[*i] is one (args: the command's argument
 * record), take it with its value and return 1; 0 when it is not one; or an
 * exit status + 1 after printing why (so that 0 stays "not one"). */
typedef int (*cli_own_flags)(void *args, int argc, char **argv, int *i);
/* The argument loop every subcommand shares: -h or --help prints help(stdout)
 * and returns -1; every other argument is one of the command's own flags (own,
 * may be NULL), an output flag (o), or an option flag or the input
 * (cli_parse_tail). Returns CLI_EXIT_OK, or an exit status after printing why. */
int cli_parse_args(const char *name, unsigned cmd, int argc, char **argv, void (*help)(FILE *),
                   cli_own_flags own, void *args, cli_outputs *o, cli_setting *set, int *nset,
                   const char **in);
/* After the loop of a 3D command: an input was named, the outputs pass
 * cli_check_outputs(), and none is an .svg picture. CLI_EXIT_OK, or
 * CLI_EXIT_USAGE after printing why. */
int cli_check_outputs3(const char *name, const char *in, const cli_outputs *o);
/* After the loop: CLI_EXIT_OK when an input file was named, else a usage error. */
int cli_need_input(const char *name, const char *in);
/* Print the last error of m (after "prefix: " when prefix is not NULL and the
 * message does not start with "prefix:" already), free m and sz (either may be
 * NULL) and return CLI_EXIT_FAIL; once a signal arrived, cli_stop(m, sz)
 * instead (the failure is the interruption). */
int cli_fail(cvm_mesh *m, cvm_sizing *sz, const char *prefix);

/* If argv[*i] is an option flag of cmd, record its setting (taking its value
 * from "--flag=V" or the next argument) and return 1; return 0 if it is not
 * one; return -1 after printing a usage error. */
int cli_parse_option_flag(unsigned cmd, int argc, char **argv, int *i, cli_setting *set,
                          int *nset);
/* Apply settings to m; on error print it and return CLI_EXIT_USAGE. */
int cli_apply_settings(cvm_mesh *m, const cli_setting *set, int nset);
/* Print the option flags of cmd, one per line, for --help. */
void cli_print_option_flags(FILE *f, unsigned cmd);

/* Print the quality report of m (after triangulation) to f: counts and
 * measures, and with full also the angle, degree and q1-q5 histograms.
 * Returns CLI_EXIT_OK, or CLI_EXIT_FAIL after printing the library's error. */
int cli_print_quality(FILE *f, cvm_mesh *m, int full);
/* The power-dual part of the report (also printed by cli_print_quality):
 * containment, smallest dual edge, time-step proxy, q1-q5 summaries, and with
 * full their histograms. Returns CLI_EXIT_OK or CLI_EXIT_FAIL (error printed). */
int cli_print_dual_quality(FILE *f, cvm_mesh *m, int full);

/* 1 when m already holds triangles after cvm_mesh_read() (a .vtu input):
 * the command then skips cvm_mesh_triangulate(). */
int cli_is_triangulated(const cvm_mesh *m);

/* Monotonic seconds. */
double cli_now(void);

/* --time-limit bounds the whole command, not each library call: the time the
 * command started and the limit its settings gave (0: none). */
typedef struct cli_budget {
    double start, limit;
} cli_budget;

/* Start the budget now, with m's CVM_OPT_TIME_LIMIT_S (settings applied). */
void cli_budget_begin(cli_budget *b, const cvm_mesh *m);
/* Before a call that honours CVM_OPT_TIME_LIMIT_S: set it on m to what is
 * left of b, or to a microsecond when nothing is left (the call then stops
 * at its first check: a refinement keeps a valid mesh and says so, a
 * triangulation is left empty). No limit: nothing changes. */
void cli_budget_apply(const cli_budget *b, cvm_mesh *m);

/* ---- interrupt.c: SIGINT / SIGTERM and the outputs as one set ---- */

/* Install the SIGINT and SIGTERM handlers (not over a signal ignored at start). */
void cli_signals_install(void);
/* Record what runs now (what: "triangulating"; name: a file or NULL), for the
 * interruption message. what and name must outlive the command. */
void cli_phase(const char *what, const char *name);
/* The signal number that arrived, or 0. */
int cli_interrupted(void);
/* Progress callback of every command: asks the running call to stop once a
 * signal arrived. */
int cli_progress(void *payload, cvm_stage stage, double fraction);
/* Free m and sz (either may be NULL; freeing m removes its staged outputs),
 * print "cvmesh: interrupted by SIGINT while PHASE; ..." and return
 * 128 + the signal number. */
int cli_stop(cvm_mesh *m, cvm_sizing *sz);
/* Stage o's out, svg (as mesh writes) and dual (each when not NULL), then
 * commit them together; "-o -" stages in a temporary folder and copies the
 * file to standard output once all are committed. Returns CLI_EXIT_OK; CLI_EXIT_FAIL after printing why (no
 * file changed; m's staged writes are gone); or -1 when a signal arrived (call
 * cli_stop()). */
int cli_write_outputs(cvm_mesh *m, cli_outputs *o);
/* Called once the outputs are committed (the message then says so). */
void cli_outputs_committed(void);
/* The end of a 3D command whose mesh m is made (cli_finish() is the 2D one): write o's
 * outputs, print report(f, m) on the report stream under --quality, mark the timings, note when nothing was asked (name: the
 * command, in: its input) and free m. Returns the command's exit status. */
/* The quality report of a 3D mesh (cmd_mesh3.c): counts, the generator's and the
 * optimiser's reports when they ran, the measures. */
void cli_mesh3_report(FILE *f, cvm_mesh *m);
int cli_finish3(cvm_mesh *m, cli_outputs *o, const char *name, const char *in,
               void (*report)(FILE *f, cvm_mesh *m));

/* ---- progress.c: the progress line on standard error ---- */

/* --progress (1) or --quiet (0); without either, on when stderr is a terminal. */
void cli_progress_mode(int on);
/* Redraw the line for stage at fraction (0..1; outside: no percentage). */
void cli_progress_show(cvm_stage stage, double fraction);
/* Erase the line, if one is shown (before any other output to stderr). */
void cli_progress_clear(void);

/* Subcommands: argv[0] is the subcommand's name. */
int cli_triangulate(int argc, char **argv);
void cli_triangulate_help(FILE *f);
int cli_refine(int argc, char **argv);
void cli_refine_help(FILE *f);
int cli_optimise(int argc, char **argv);
void cli_optimise_help(FILE *f);
int cli_tetrahedralize(int argc, char **argv);
void cli_tetrahedralize_help(FILE *f);
int cli_mesh3(int argc, char **argv);
void cli_mesh3_help(FILE *f);
int cli_quad(int argc, char **argv);
void cli_quad_help(FILE *f);

#endif
