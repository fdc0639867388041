/*
 * cmd_optimise.c - `cvmesh optimise IN.poly|IN.node|IN.vtu [--algo delaunay|frontal]
 * [--size H] [--boundary-grading G] [-o OUT] [--dual DUAL.vtu] [--quality] [option flags]`: read, triangulate
 * (a .vtu is already a mesh), optionally refine, optimise the power dual, write, report.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* The boundary grading of the refinement before the optimisation: the cylinder's
 * 0.033 wall spacing against h = 0.2 leaves the optimiser at 37.3 degrees on the
 * uniform size and 41.6 with it (bench_dual), for 1.5% more triangles. */
#define OPT_BGRAD_DEFAULT 0.3

typedef struct oargs {
    const char *in;
    cli_outputs o;
    int refine;
    cvm_algorithm algo;
    double size; /* 0: none */
    double bgrad; /* --boundary-grading G (0: off; < 0: not given, OPT_BGRAD_DEFAULT) */
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} oargs;

void cli_optimise_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh optimise IN.poly|IN.node|IN.vtu|IN.ele [--algo delaunay|frontal] [--size H]\n"
            "                       [--boundary-grading G] [-o OUT] [--dual DUAL.vtu]\n"
            "                       [--quality] [option flags]\n"
            "\n"
            "Triangulate IN (a .vtu written by cvmesh is read back as its mesh, weights\n"
            "included; refined first when --algo or --size is given), then move the\n"
            "vertices and set their power weights so that every triangle contains its power\n"
            "(weighted Voronoi) vertex or is merged with a neighbour, and dual edges are not\n"
            "tiny. Segments and input points are kept; the result is a regular triangulation.\n"
            "3D input: a tetrahedral mesh made elsewhere (TetGen's IN.ele with IN.node), or a\n"
            "closed surface or 3D point set tetrahedralised first (as `cvmesh tetrahedralize`),\n"
            "is optimised by cvm_mesh_optimise_dual3() (the --opt-* flags; the 3D report).\n"
            "\n"
            "  --algo NAME                refine first: frontal (default when --size is given)\n"
            "                             or delaunay\n"
            "  --size H                   target edge length of that refinement (uniform)\n"
            "  --boundary-grading G       with --size: also cap the size by l(e) + G x distance\n"
            "                             from each boundary edge e of length l(e), so a finely\n"
            "                             spaced wall grows at slope G (default 0.3: larger\n"
            "                             smallest angles after the optimisation; 0: off)\n"
            "Outputs and reports (.node files carry each vertex's weight as their first\n"
            "attribute; --quality adds the optimiser's report; --timings: read, triangulate,\n"
            "refine, optimise, write, quality):\n");
    cli_print_output_help(f, 0, 1);
    cli_print_option_flags(f, CLI_CMD_OPTIMISE);
    fprintf(f, "\nStopped by --time-limit the mesh is still a valid regular triangulation and\n"
               "is written; the exit status is 0 and a note says so. --time-limit bounds the\n"
               "whole command (reading and writing are not cut short); stopped during the\n"
               "triangulation before refinement, nothing is written and the exit status is 1.\n"
               "\nThe output files (-o, --dual) replace their old versions together or not at\n"
               "all, and a replaced file keeps its permissions. SIGINT (Ctrl-C) or SIGTERM\n"
               "stops the command: exit status 130 or 143, one line says what was interrupted,\n"
               "and no file is written or changed unless the outputs were already complete.\n");
}

/* optimise's own flags that take a value: 1 taken, 0 not one, or
 * CLI_EXIT_USAGE + 1 after printing why. */
static int parse_value(void *args, int argc, char **argv, int *i)
{
    oargs *a = args;
    const char *v;
    int r;
    if ((r = cli_take_value(argc, argv, i, "--algo", &v)) != 0) {
        a->refine = 1;
        return r < 0 || cli_parse_algo("optimise", v, 0, &a->algo) ? CLI_EXIT_USAGE + 1 : 1;
    }
    if ((r = cli_take_value(argc, argv, i, "--size", &v)) != 0) {
        a->refine = 1;
        return r < 0 || cli_parse_positive("--size", v, &a->size) ? CLI_EXIT_USAGE + 1 : 1;
    }
    if ((r = cli_take_value(argc, argv, i, "--boundary-grading", &v)) != 0)
        return r < 0 || cli_parse_nonnegative("--boundary-grading", v, &a->bgrad)
                   ? CLI_EXIT_USAGE + 1 : 1;
    return 0;
}

static int parse(oargs *a, int argc, char **argv)
{
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "optimise";
    a->o.with_dual = 1;
    a->algo = CVM_ALGO_FRONTAL;
    a->bgrad = -1;
    if ((r = cli_parse_args("optimise", CLI_CMD_OPTIMISE, argc, argv, cli_optimise_help,
                            parse_value, a, &a->o, a->set, &a->nset, &a->in)))
        return r;
    if (a->bgrad >= 0 && !(a->size > 0)) {
        fprintf(stderr, "cvmesh: optimise: --boundary-grading needs --size (it grades the "
                        "refinement's size)\n");
        return CLI_EXIT_USAGE;
    }
    if (a->bgrad < 0)
        a->bgrad = a->size > 0 ? OPT_BGRAD_DEFAULT : 0;
    if (cli_need_input("optimise", a->in))
        return CLI_EXIT_USAGE;
    return cli_check_outputs("optimise", &a->o);
}

/* The dual report: compliance, merging, the optimiser's run. */
static void print_dual_report(FILE *f, cvm_mesh *m)
{
    static const struct { cvm_measure w; const char *name, *fmt; } rows[] = {
        {CVM_MEASURE_DUAL_OUTSIDE_PCT, "power vertex outside", "%.4f %%"},
        {CVM_MEASURE_DUAL_NONCOMPLIANT_PCT, "non-compliant (not merged)", "%.4f %%"},
        {CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT, "non-compliant, boundary", "%.4f %%"},
        {CVM_MEASURE_DUAL_MERGED_PCT, "merged", "%.4f %%"},
        {CVM_MEASURE_MIN_DUAL_EDGE, "min dual edge", "%.6g"},
        {CVM_MEASURE_TIME_STEP_PROXY, "time-step proxy", "%.6g"},
        {CVM_MEASURE_VANISHED_VERTICES, "vanished vertices", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_BEFORE_PCT, "non-compliant before", "%.4f %%"},
        {CVM_MEASURE_DUAL_OPT_SWEEPS, "sweeps", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_MOVES, "moves", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_FLIPS, "flips", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_WEIGHT_FIXES, "weight fixes", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_REMOVED_VANISHED, "removed (vanished)", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_REMOVED_DEGREE, "removed (degree repair)", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_REMOVED_MAXMIN, "removed (max-min trials)", "%.0f"},
        {CVM_MEASURE_DUAL_OPT_SECONDS, "optimisation time", "%.3f s"},
    };
    size_t i;
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        if (cvm_mesh_get_measure(&v, m, rows[i].w) == CVM_OK) {
            fprintf(f, "%-28s ", rows[i].name);
            fprintf(f, rows[i].fmt, v);
            fputc('\n', f);
        }
    }
}

/* A 3D input: a tetrahedral mesh (.ele) as it is, or a surface or point set
 * tetrahedralised first; then cvm_mesh_optimise_dual3(). */
static int run3(oargs *a, cvm_mesh *m, cvm_sizing *sz, cli_budget *budget)
{
    size_t nt = 0;
    cvm_status s;
    cvm_sizing_free(sz);
    if (a->refine) {
        fprintf(stderr, "cvmesh: optimise: %s is 3D: --algo and --size refine 2D meshes only "
                        "(cvmesh mesh3 generates 3D ones)\n", a->in);
        cvm_mesh_free(m);
        return CLI_EXIT_USAGE;
    }
    if (cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON) != CVM_OK || nt == 0) {
        cli_phase("tetrahedralizing", a->in);
        if (cvm_mesh_triangulate(m) != CVM_OK || cli_interrupted())
            return cli_fail(m, NULL, a->in);
        cli_timing_mark(&a->o, "triangulate");
        cli_budget_apply(budget, m);
    }
    cli_phase("optimising the dual of", a->in);
    s = cvm_mesh_optimise_dual3(m);
    if (cvm_status_is_error(s) || cli_interrupted())
        return cli_fail(m, NULL, a->in);
    if (s != CVM_OK)
        fprintf(stderr, "cvmesh: note: %s: %s\n", a->in, cvm_mesh_errmsg(m));
    cli_timing_mark(&a->o, "optimise");
    return cli_finish3(m, &a->o, "optimise", a->in, cli_mesh3_report);
}

static int run(oargs *a)
{
    cvm_mesh *m;
    int32_t dim = 2;
    cvm_sizing *sz = NULL;
    cli_budget budget;
    cvm_status s;
    int rc;
    if ((rc = cli_start(&m, &sz, a->set, a->nset, a->size)))
        return rc;
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    if (cvm_sizing_set_boundary_grading(sz, a->bgrad) != CVM_OK) {
        fprintf(stderr, "cvmesh: --boundary-grading: %s\n", cvm_sizing_errmsg(sz));
        cvm_sizing_free(sz);
        cvm_mesh_free(m);
        return CLI_EXIT_USAGE;
    }
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, sz, NULL);
    {
        double flips = 0;
        if (cvm_mesh_get_report(&flips, m, CVM_REPORT_READ_FLIPS) == CVM_OK && flips > 0)
            fprintf(stderr, "cvmesh: note: %s: the triangles were not constrained Delaunay "
                    "(regular, with weights): %.0f edge flips changed the connectivity\n", a->in,
                    flips);
    }
    cli_timing_mark(&a->o, "read");
    cli_budget_apply(&budget, m);
    if (cvm_mesh_dim(&dim, m) == CVM_OK && dim == 3)
        return run3(a, m, sz, &budget);
    cli_phase("triangulating", a->in);
    if ((!cli_is_triangulated(m) && cvm_mesh_triangulate(m) != CVM_OK) || /* a .vtu is a mesh */
        cli_interrupted())
        return cli_fail(m, sz, a->in);
    cli_timing_mark(&a->o, "triangulate");
    if (a->refine) {
        cli_budget_apply(&budget, m);
        cli_phase("refining", a->in);
        s = cvm_mesh_refine(m, sz, a->algo);
        if (cvm_status_is_error(s) || cli_interrupted())
            return cli_fail(m, sz, a->in);
        if (s != CVM_OK)
            fprintf(stderr, "cvmesh: note: %s: %s\n", a->in, cvm_mesh_errmsg(m));
        cli_timing_mark(&a->o, "refine");
    }
    cli_budget_apply(&budget, m);
    cli_phase("optimising the dual of", a->in);
    s = cvm_mesh_optimise_dual(m, NULL);
    cli_timing_mark(&a->o, "optimise");
    return cli_finish(m, sz, a->in, s, &a->o, print_dual_report);
}

int cli_optimise(int argc, char **argv)
{
    oargs a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
