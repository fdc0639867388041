/*
 * args.c - the flags every subcommand shares: outputs, reports, timings, and
 * "--flag=value" beside "--flag value".
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

int cli_take_value(int argc, char **argv, int *i, const char *name, const char **val)
{
    const char *s = argv[*i];
    size_t n = strlen(name);
    if (strncmp(s, name, n) != 0)
        return 0;
    if (s[n] == '=' && n > 2) { /* "--x=V"; "-o=V" is not a form anyone types */
        *val = s + n + 1;
        return 1;
    }
    if (s[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        fprintf(stderr, "cvmesh: %s needs a value\n", name);
        return -1;
    }
    *val = argv[++*i];
    return 1;
}

/* Case-insensitive "path ends in ext" (ext lower case, with its dot). */
static int has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext), j;
    if (n <= k)
        return 0;
    for (j = 0; j < k; j++) {
        char c = path[n - k + j];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != ext[j])
            return 0;
    }
    return 1;
}

int cli_parse_outputs(cli_outputs *o, int argc, char **argv, int *i)
{
    const char *s = argv[*i], *v = NULL;
    int r;
    if ((r = cli_take_value(argc, argv, i, "-o", &v)) != 0 ||
        (r = cli_take_value(argc, argv, i, "--output", &v)) != 0) {
        if (r > 0)
            o->out = v;
        return r;
    }
    if (o->with_svg && (r = cli_take_value(argc, argv, i, "--svg", &v)) != 0) {
        if (r > 0)
            o->svg = v;
        return r;
    }
    if (o->with_dual && (r = cli_take_value(argc, argv, i, "--dual", &v)) != 0) {
        if (r > 0)
            o->dual = v;
        return r;
    }
    if ((r = cli_take_value(argc, argv, i, "--format", &v)) != 0) {
        if (r > 0)
            o->format = v;
        return r;
    }
    if (strcmp(s, "--quality") == 0 || strcmp(s, "--quality=short") == 0) {
        o->quality = 1;
        return 1;
    }
    if (strcmp(s, "--quality=full") == 0) {
        o->quality = 2;
        return 1;
    }
    if (strncmp(s, "--quality=", 10) == 0) {
        fprintf(stderr, "cvmesh: %s: expected --quality, --quality=short or --quality=full\n", s);
        return -1;
    }
    if (strcmp(s, "--progress") == 0 || strcmp(s, "--quiet") == 0) {
        cli_progress_mode(s[2] == 'p');
        return 1;
    }
    if (strcmp(s, "--timings") == 0) {
        o->timings = 1;
        return 1;
    }
    if (strncmp(s, "--timings=", 10) == 0) {
        fprintf(stderr, "cvmesh: --timings takes no value (got '%s')\n", s);
        return -1;
    }
    return 0;
}

int cli_check_outputs(const char *name, const cli_outputs *o)
{
    static const char *const exts[] = {".vtu", ".msh", ".node", ".svg"};
    size_t k;
    if (o->out && strcmp(o->out, "-") == 0) {
        const char *f = o->format ? o->format : "vtu";
        if (strcmp(f, "vtu") != 0 && strcmp(f, "msh") != 0 && strcmp(f, "svg") != 0) {
            fprintf(stderr, "cvmesh: %s: --format %s: standard output takes vtu, msh or svg "
                            "(.node is three files)\n", name, f);
            return CLI_EXIT_USAGE;
        }
    } else if (o->format) {
        fprintf(stderr, "cvmesh: %s: --format is for -o - (a file's extension names its "
                        "format)\n", name);
        return CLI_EXIT_USAGE;
    } else if (o->out) {
        for (k = 0; k < sizeof exts / sizeof exts[0] && !has_ext(o->out, exts[k]); k++)
            ;
        if (k == sizeof exts / sizeof exts[0]) {
            fprintf(stderr, "cvmesh: %s: %s: unknown output format (use .vtu, .msh, .node or "
                            ".svg, or -o - with --format)\n", name, o->out);
            return CLI_EXIT_USAGE;
        }
    }
    if (o->svg && !has_ext(o->svg, ".svg")) {
        fprintf(stderr, "cvmesh: %s: --svg %s: the file name must end in .svg\n", name, o->svg);
        return CLI_EXIT_USAGE;
    }
    if (o->dual && !has_ext(o->dual, ".vtu")) {
        fprintf(stderr, "cvmesh: %s: --dual %s: the file name must end in .vtu\n", name, o->dual);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

FILE *cli_report_stream(const cli_outputs *o)
{
    return o->out && strcmp(o->out, "-") == 0 ? stderr : stdout;
}

void cli_timing_begin(cli_outputs *o)
{
    o->t0 = o->t_last = cli_now();
}

void cli_timing_mark(cli_outputs *o, const char *phase)
{
    double t = cli_now();
    if (o->timings)
        fprintf(cli_report_stream(o), "%s: %.6f\n", phase, t - o->t_last);
    o->t_last = t;
}

void cli_print_output_help(FILE *f, int with_svg, int with_dual)
{
    fprintf(f,
            "  -o, --output OUT           write the mesh; the extension chooses the format\n"
            "                             (case-insensitive): .vtu (VTK XML), .msh (Gmsh 4.1),\n"
            "                             .svg (picture), .node (OUT.node + .ele + .edge)\n"
            "  -o -                       write the mesh to standard output, as --format\n"
            "  --format vtu|msh|svg       the format of -o - (default vtu)\n");
    if (with_svg)
        fprintf(f, "  --svg PIC.svg              also draw the mesh, coloured by smallest angle\n");
    if (with_dual)
        fprintf(f, "  --dual DUAL.vtu            write the power (Voronoi) cells as VTK polygons on\n"
                   "                             shared points with vertex id, area and weight, and\n"
                   "                             the face table (cells, edge, lengths) as field data\n");
    fprintf(f,
            "  --quality[=short|full]     print the quality report: counts and measures\n"
            "                             (short, the default), or also the histograms of\n"
            "                             angles, degrees and the dual's q1-q5 (full)\n"
            "  --timings                  print 'phase: seconds' for each phase\n"
            "  --progress, --quiet        show (hide) the progress line on standard error;\n"
            "                             default: shown when standard error is a terminal\n"
            "  -h, --help                 print this help\n"
            "Every flag that takes a value takes it as --flag V or --flag=V. With -o -, the\n"
            "reports go to standard error.\n");
}

void cli_note_nothing_to_do(const char *name, const char *in, const cli_outputs *o)
{
    if (o->out || o->svg || o->dual || o->quality || o->timings)
        return;
    fprintf(stderr, "cvmesh: note: %s: nothing to write or print (no -o, --svg, --dual or "
                    "--quality): %s was read and meshed, and nothing else was done\n", name, in);
}

const char *cli_fmt_number(char *buf, size_t len, double v)
{
    int digits;
    if (!buf || len == 0) /* also tells gcc's -Wformat-truncation (with UBSan) buf is set */
        return "";
    if (v == floor(v) && fabs(v) < 1e15) { /* 300, not 3e+02 */
        snprintf(buf, len, "%.0f", v);
        return buf;
    }
    for (digits = 1; digits < 17; digits++) {
        snprintf(buf, len, "%.*g", digits, v);
        if (strtod(buf, NULL) == v)
            return buf;
    }
    snprintf(buf, len, "%.17g", v);
    return buf;
}

void cli_note_duplicates(const cvm_mesh *m, const char *in)
{
    size_t ndup = 0;
    if (cvm_mesh_count(&ndup, m, CVM_ENT_DUPLICATE) == CVM_OK && ndup)
        fprintf(stderr, "cvmesh: note: %s: %lu duplicate points merged\n", in, (unsigned long)ndup);
}
