/*
 * cmd_mesh3.c - `cvmesh mesh3 IN --size H [--grading G] [--uniform] [--freespace lattice]
 * [--layers N] [--optimise] -o OUT.{vtu,msh,node} [--quality] [--timings]`: a co-volume
 * tetrahedral mesh inside a closed surface (cvm_mesh_generate3()); write, report.
 */
#include <string.h>

#include "cli.h"

typedef struct margs {
    const char *in;
    double size;
    int freespace; /* CVM_GEN3_FREESPACE_* */
    int optimise;
    cli_outputs o;
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} margs;

void cli_mesh3_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh mesh3 IN.off|IN.stl|IN.poly|IN.smesh --size H [--grading G] [--uniform]\n"
            "                    [--freespace lattice] [--layers N] [--optimise] [-o OUT]\n"
            "                    [--dual DUAL.vtu] [--quality]\n"
            "                    [--timings] [option flags]\n"
            "\n"
            "A tetrahedral co-volume mesh inside a closed surface: one near-field point per\n"
            "pair of surface triangles matched across an edge (or per unmatched triangle),\n"
            "then a body-centred cubic lattice in the free space, every point strictly inside\n"
            "the domain, tetrahedralised with the surface as `cvmesh tetrahedralize` does.\n"
            "H is the largest size; by default the size near the surface follows its own\n"
            "triangles and grows away from them by the grading G (--uniform: H everywhere).\n"
            "--optimise then moves vertices and sets power weights (cvm_mesh_optimise_dual3():\n"
            "connectivity kept; boundary vertices stay, but those inside an axis-aligned planar\n"
            "facet slide in it) so that more tetrahedra contain their power vertex; --time-limit S\n"
            "bounds it; --dual writes the weighted power cells.\n"
            "Not yet implemented: --freespace octree|refine, --layers above 1.\n"
            "\n"
            "Outputs and reports (--timings: read, generate, optimise, write, quality):\n");
    cli_print_output_help(f, 0, 1);
    fprintf(f, "  (.vtu (VTK_TETRA cells), .msh (Gmsh 4.1) or .node (OUT.node + .ele + .face))\n");
    cli_print_option_flags(f, CLI_CMD_MESH3);
    fprintf(f, "\nOn bad input the exit status is 1 and one line names the file, line or face;\n"
               "no output file is written. Command-line errors exit with 2.\n");
}

/* The flags of this command alone: 1 taken, 0 not one of them, or an exit status + 1. */
static int own_flag(margs *a, int argc, char **argv, int *i)
{
    const char *v;
    int r;
    if ((r = cli_take_value(argc, argv, i, "--size", &v)) != 0)
        return r < 0 || cli_parse_positive("--size", v, &a->size) ? CLI_EXIT_USAGE + 1 : 1;
    if ((r = cli_take_value(argc, argv, i, "--freespace", &v)) != 0) {
        if (r < 0)
            return CLI_EXIT_USAGE + 1;
        if (strcmp(v, "lattice") == 0)
            a->freespace = CVM_GEN3_FREESPACE_LATTICE;
        else if (strcmp(v, "octree") == 0)
            a->freespace = CVM_GEN3_FREESPACE_OCTREE;
        else if (strcmp(v, "refine") == 0)
            a->freespace = CVM_GEN3_FREESPACE_REFINE;
        else {
            fprintf(stderr, "cvmesh: mesh3: --freespace %s: use lattice, octree or refine\n", v);
            return CLI_EXIT_USAGE + 1;
        }
        return 1;
    }
    if (strcmp(argv[*i], "--optimise") == 0 || strcmp(argv[*i], "--optimize") == 0) {
        a->optimise = 1;
        return 1;
    }
    return 0;
}

static int parse(margs *a, int argc, char **argv)
{
    int i, r;
    memset(a, 0, sizeof *a);
    a->o.command = "mesh3";
    a->o.with_dual = 1; /* --dual DUAL.vtu: the power cells, weights included */
    for (i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "-h") == 0 || strcmp(s, "--help") == 0) {
            cli_mesh3_help(stdout);
            return -1;
        }
        if ((r = own_flag(a, argc, argv, &i)) != 0) {
            if (r > 1)
                return r - 1;
            continue;
        }
        if ((r = cli_parse_outputs(&a->o, argc, argv, &i)) != 0) {
            if (r < 0)
                return CLI_EXIT_USAGE;
            continue;
        }
        if ((r = cli_parse_tail("mesh3", CLI_CMD_MESH3, argc, argv, &i, a->set, &a->nset, &a->in)))
            return r;
    }
    if (cli_need_input("mesh3", a->in) || cli_check_outputs("mesh3", &a->o))
        return CLI_EXIT_USAGE;
    if (!(a->size > 0)) {
        fprintf(stderr, "cvmesh: mesh3: --size H is required (the largest size)\n");
        return CLI_EXIT_USAGE;
    }
    if ((a->o.out && strcmp(a->o.out, "-") != 0 && strlen(a->o.out) > 4 &&
         strcmp(a->o.out + strlen(a->o.out) - 4, ".svg") == 0) ||
        (a->o.format && strcmp(a->o.format, "svg") == 0)) {
        fprintf(stderr, "cvmesh: mesh3: no .svg picture of a 3D mesh (use .vtu, .msh or .node)\n");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static void report(FILE *f, cvm_mesh *m)
{
    static const struct {
        cvm_entity kind;
        const char *label;
    } counts[] = {{CVM_ENT_VERTEX, "vertices"},
                  {CVM_ENT_TETRAHEDRON, "tetrahedra"},
                  {CVM_ENT_TRIANGLE, "boundary faces"}};
    static const struct {
        int which, is_report;
        const char *label, *fmt;
    } rows[] = {
        {CVM_REPORT_GEN3_MATCHED_PAIRS, 1, "matched face pairs", "%.0f"},
        {CVM_REPORT_GEN3_UNMATCHED_FACES, 1, "unmatched faces", "%.0f"},
        {CVM_REPORT_GEN3_PAIRS_REJECTED, 1, "pairs rejected", "%.0f"},
        {CVM_REPORT_GEN3_NEAR_POINTS, 1, "near-field points", "%.0f"},
        {CVM_REPORT_GEN3_NEAR_REJECTED, 1, "near-field points rejected", "%.0f"},
        {CVM_REPORT_GEN3_LATTICE_POINTS, 1, "lattice points", "%.0f"},
        {CVM_REPORT_GEN3_LATTICE_LEVELS, 1, "lattice levels", "%.0f"},
        {CVM_REPORT_GEN3_RECOVERY_DROPPED, 1, "points dropped for recovery", "%.0f"},
        {CVM_REPORT_DUAL3_SWEEPS, 2, "optimiser sweeps", "%.0f"},
        {CVM_REPORT_DUAL3_MOVES, 2, "optimiser moves", "%.0f"},
        {CVM_REPORT_DUAL3_OUTSIDE_BEFORE_PCT, 2, "outside before optimising", "%.3f %%"},
        {CVM_REPORT_DUAL3_OUTSIDE_BOUNDARY_BEFORE_PCT, 2, "  at the boundary", "%.3f %%"},
        {CVM_REPORT_DUAL3_SECONDS, 2, "optimiser seconds", "%.3g"},
        {CVM_MEASURE_VOLUME, 0, "volume", "%.10g"},
        {CVM_MEASURE_MIN_DIHEDRAL_DEG, 0, "min dihedral angle", "%.4g deg"},
        {CVM_MEASURE_MAX_DIHEDRAL_DEG, 0, "max dihedral angle", "%.4g deg"},
        {CVM_MEASURE_MAX_RADIUS_EDGE, 0, "max radius-edge ratio", "%.4g"},
        {CVM_MEASURE_MIN_EDGE, 0, "min edge", "%.6g"},
        {CVM_MEASURE_MAX_EDGE, 0, "max edge", "%.6g"},
        {CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT, 0, "circumcentre outside", "%.3f %%"},
        {CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT, 0, "  at the boundary", "%.3f %%"},
        {CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D, 0, "min dual edge / face edge", "%.4g"},
        {CVM_MEASURE_RECOVERY_STEINER, 0, "recovery steiner points", "%.0f"},
    };
    size_t i, n;
    double sw = 0;
    int optimised = cvm_mesh_get_report(&sw, m, CVM_REPORT_DUAL3_SECONDS) == CVM_OK && sw > 0;
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (cvm_mesh_count(&n, m, counts[i].kind) == CVM_OK)
            fprintf(f, "%-28s %lu\n", counts[i].label, (unsigned long)n);
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        cvm_status s = rows[i].is_report ? cvm_mesh_get_report(&v, m, (cvm_report)rows[i].which)
                                         : cvm_mesh_get_measure(&v, m, (cvm_measure)rows[i].which);
        if (s != CVM_OK || (rows[i].is_report == 2 && !optimised))
            continue;
        fprintf(f, "%-28s ", rows[i].label);
        fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
}

static int run(margs *a)
{
    cvm_mesh *m;
    cli_budget budget;
    int rc;
    int32_t dim = 0;
    if (cvm_mesh_create(&m) != CVM_OK) {
        fprintf(stderr, "cvmesh: out of memory\n");
        return CLI_EXIT_FAIL;
    }
    if ((rc = cli_apply_settings(m, a->set, a->nset))) {
        cvm_mesh_free(m);
        return rc;
    }
    if (cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, a->freespace) != CVM_OK)
        return cli_fail(m, NULL, NULL);
    cvm_mesh_set_progress(m, cli_progress, 256, NULL);
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, NULL, NULL);
    if (cvm_mesh_dim(&dim, m) != CVM_OK || dim != 3) {
        fprintf(stderr, "cvmesh: mesh3: %s is a 2D input (use cvmesh refine)\n", a->in);
        cvm_mesh_free(m);
        return CLI_EXIT_FAIL;
    }
    cli_timing_mark(&a->o, "read");
    cli_budget_apply(&budget, m);
    cli_phase("generating", a->in);
    if (cvm_mesh_generate3(m, a->size) != CVM_OK || cli_interrupted())
        return cli_fail(m, NULL, a->in);
    cli_timing_mark(&a->o, "generate");
    if (a->optimise) {
        cvm_status s;
        cli_budget_apply(&budget, m);
        cli_phase("optimising", a->in);
        s = cvm_mesh_optimise_dual3(m);
        if (cvm_status_is_error(s) || cli_interrupted())
            return cli_fail(m, NULL, a->in);
        if (s != CVM_OK)
            fprintf(stderr, "cvmesh: mesh3: %s\n", cvm_mesh_errmsg(m));
        cli_timing_mark(&a->o, "optimise");
    }
    return cli_finish3(m, &a->o, "mesh3", a->in, report);
}

int cli_mesh3(int argc, char **argv)
{
    margs a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
