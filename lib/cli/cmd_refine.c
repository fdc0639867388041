/*
 * cmd_refine.c - `cvmesh refine IN.poly|IN.vtu [--algo delaunay|frontal|aflr] [--size H]
 * [--auto R] [--grading G] [--boundary-grading G] [--fronts M,...] [-o OUT] [--svg PIC.svg] [--dual DUAL.vtu]
 * [--quality] [option flags]`: read, triangulate (unless the input is a mesh), refine,
 * write, report.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

typedef struct rargs {
    const char *in;
    cli_outputs o;
    cvm_algorithm algo;
    double size; /* 0: none */
    double auto_r, grading; /* --auto R (0: off), --grading G */
    double bgrad; /* --boundary-grading G (0: off) */
    int32_t fronts[64]; /* --fronts: segment markers that start fronts (aflr) */
    size_t nfronts;
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} rargs;

void cli_refine_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh refine IN.poly|IN.vtu [--algo delaunay|frontal|aflr] [--size H]\n"
            "                     [--auto R [--grading G]] [--boundary-grading G]\n"
            "                     [--fronts M1,M2,...] [-o OUT]\n"
            "                     [--svg PIC.svg] [--dual DUAL.vtu] [--quality] [option flags]\n"
            "\n"
            "Constrained Delaunay triangulation of IN, then refinement until every triangle\n"
            "meets the minimum angle, the size H and the maximum area. Segments are kept.\n"
            "A .vtu mesh is read as it is (with its weights) and refined further.\n"
            "\n"
            "  --algo NAME                delaunay (Delaunay refinement, default), frontal\n"
            "                             (frontal-Delaunay: more regular triangles) or aflr\n"
            "                             (advancing-front layers from the --fronts segments)\n"
            "  --fronts M1,M2,...         aflr: segment markers whose segments start fronts\n"
            "                             (default every segment)\n"
            "  --size H                   target edge length (uniform); default none\n"
            "  --auto R                   automatic size from the geometry: local feature\n"
            "                             size / R (R edges per feature), graded by --grading\n"
            "  --grading G                with --auto: the size grows by at most 1/G per unit\n"
            "                             of distance (default 4)\n"
            "  --boundary-grading G       also cap the size by l(e) + G x distance from each\n"
            "                             boundary edge e of length l(e): fine input spacing\n"
            "                             grows into the interior at slope G (e.g. 0.3)\n"
            "Outputs and reports (--timings: read, triangulate, refine, write, quality;\n"
            "--quality adds the refinement report; --svg colours aflr meshes by layer):\n");
    cli_print_output_help(f, 1, 1);
    cli_print_option_flags(f, CLI_CMD_REFINE);
    fprintf(f, "\nStopped by --max-steiner or --time-limit the mesh is still valid and written;\n"
               "the exit status is 0 and a note says what was left unmet. --time-limit bounds\n"
               "the whole command (reading and writing are not cut short); stopped during the\n"
               "triangulation before refinement, nothing is written and the exit status is 1.\n"
               "\nThe output files (-o, --svg, --dual) replace their old versions together or not\n"
               "at all, and a replaced file keeps its permissions. SIGINT (Ctrl-C) or SIGTERM\n"
               "stops the command: exit status 130 or 143, one line says what was interrupted,\n"
               "and no file is written or changed unless the outputs were already complete.\n");
}

/* --fronts 1,2,...: integer markers separated by commas. */
static int parse_fronts(rargs *a, const char *s)
{
    const char *p = s;
    a->nfronts = 0;
    for (;;) {
        char *end;
        long v = strtol(p, &end, 10);
        if (end == p || v < INT32_MIN || v > INT32_MAX || (*end && *end != ',') ||
            a->nfronts >= sizeof a->fronts / sizeof a->fronts[0]) {
            fprintf(stderr, "cvmesh: --fronts %s: expected up to 64 integer markers separated by "
                            "commas\n", s);
            return CLI_EXIT_USAGE;
        }
        a->fronts[a->nfronts++] = (int32_t)v;
        if (!*end)
            return CLI_EXIT_OK;
        p = end + 1;
    }
}

/* The flags of refine's own that take a value: 1 taken, 0 not one, or an
 * exit status + 1 (so 0 stays "not one"): CLI_EXIT_USAGE + 1 after printing why. */
static int parse_value(void *args, int argc, char **argv, int *i)
{
    rargs *a = args;
    static const char *const sizes[] = {"--size", "--auto", "--grading", "--boundary-grading"};
    double *dst[4];
    const char *v;
    size_t k;
    int r;
    dst[0] = &a->size;
    dst[1] = &a->auto_r;
    dst[2] = &a->grading;
    dst[3] = &a->bgrad;
    if ((r = cli_take_value(argc, argv, i, "--algo", &v)) != 0)
        return r < 0 || cli_parse_algo("refine", v, 1, &a->algo) ? CLI_EXIT_USAGE + 1 : 1;
    for (k = 0; k < 4; k++)
        if ((r = cli_take_value(argc, argv, i, sizes[k], &v)) != 0)
            return r < 0 || cli_parse_positive(sizes[k], v, dst[k]) ? CLI_EXIT_USAGE + 1 : 1;
    if ((r = cli_take_value(argc, argv, i, "--fronts", &v)) != 0)
        return r < 0 || parse_fronts(a, v) ? CLI_EXIT_USAGE + 1 : 1;
    return 0;
}

static int parse(rargs *a, int argc, char **argv)
{
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "refine";
    a->o.with_svg = a->o.with_dual = 1;
    a->algo = CVM_ALGO_DELAUNAY;
    a->grading = 0; /* 0: not given (4 with --auto) */
    if ((r = cli_parse_args("refine", CLI_CMD_REFINE, argc, argv, cli_refine_help, parse_value, a,
                            &a->o, a->set, &a->nset, &a->in)))
        return r;
    if (a->grading > 0 && !(a->auto_r > 0)) {
        fprintf(stderr, "cvmesh: refine: --grading needs --auto (it grades the automatic size)\n");
        return CLI_EXIT_USAGE;
    }
    if (a->grading == 0)
        a->grading = 4;
    if (cli_need_input("refine", a->in))
        return CLI_EXIT_USAGE;
    return cli_check_outputs("refine", &a->o);
}

/* The refinement report: Steiner points and what was left unmet. */
static void print_report(FILE *f, cvm_mesh *m)
{
    static const struct { cvm_measure w; const char *name; } rows[] = {
        {CVM_MEASURE_REFINE_STEINER, "steiner points"},
        {CVM_MEASURE_REFINE_REQUESTED_ANGLE, "requested min angle"},
        {CVM_MEASURE_REFINE_MET_ANGLE, "met min angle (away from small input angles)"},
        {CVM_MEASURE_REFINE_UNMET_ANGLE, "triangles below the angle"},
        {CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE, "  of which at small input angles"},
        {CVM_MEASURE_REFINE_UNMET_SIZE, "triangles above the size"},
    };
    size_t i, n = 0;
    double *all;
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        if (cvm_mesh_get_measure(&v, m, rows[i].w) == CVM_OK)
            fprintf(f, "%s: %.10g\n", rows[i].name, v);
    }
    /* where: the first few unmet triangles by centroid */
    if (cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET) != CVM_OK || n == 0)
        return;
    all = malloc(3 * n * sizeof *all);
    if (all && cvm_mesh_copy_refine_unmet(all, 3 * n, m) == CVM_OK)
        for (i = 0; i < n && i < 5; i++) {
            int why = (int)all[3 * i + 2];
            fprintf(f, "unmet at (%.6g, %.6g):%s%s%s%s\n", all[3 * i], all[3 * i + 1],
                    (why & CVM_UNMET_ANGLE) ? " angle" : "", (why & CVM_UNMET_SIZE) ? " size" : "",
                    (why & CVM_UNMET_SMALL_INPUT_ANGLE) ? " (small input angle)" : "",
                    i == 4 && n > 5 ? " ..." : "");
        }
    free(all);
}

static int run(rargs *a)
{
    cvm_mesh *m;
    cvm_sizing *sz = NULL;
    cli_budget budget;
    cvm_status s;
    int rc;
    if ((rc = cli_start(&m, &sz, a->set, a->nset, a->size)))
        return rc;
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    if ((a->auto_r > 0 && cvm_sizing_set_automatic(sz, a->auto_r, a->grading) != CVM_OK) ||
        cvm_sizing_set_boundary_grading(sz, a->bgrad) != CVM_OK) {
        fprintf(stderr, "cvmesh: sizing: %s\n", cvm_sizing_errmsg(sz));
        cvm_sizing_free(sz);
        cvm_mesh_free(m);
        return CLI_EXIT_USAGE;
    }
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, sz, NULL);
    cli_timing_mark(&a->o, "read");
    cli_budget_apply(&budget, m);
    cli_phase("triangulating", a->in);
    if ((!cli_is_triangulated(m) && cvm_mesh_triangulate(m) != CVM_OK) || /* a .vtu is a mesh */
        cli_interrupted())
        return cli_fail(m, sz, a->in);
    if (a->nfronts && cvm_mesh_set_front_markers(m, a->fronts, a->nfronts) != CVM_OK)
        return cli_fail(m, sz, NULL);
    cli_timing_mark(&a->o, "triangulate");
    cli_budget_apply(&budget, m);
    cli_phase("refining", a->in);
    s = cvm_mesh_refine(m, sz, a->algo);
    cli_timing_mark(&a->o, "refine");
    return cli_finish(m, sz, a->in, s, &a->o, print_report);
}

int cli_refine(int argc, char **argv)
{
    rargs a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
