/*
 * cmd_mesh3.c - `cvmesh mesh3 IN --size H [--grading G] [--uniform] [--freespace lattice|octree|refine]
 * [--layers N] [--point-source X,Y,Z,H[,G]]... [--optimise] -o OUT.{vtu,msh,node}
 * [--dual DUAL.vtu] [--quality] [--timings]`: a co-volume tetrahedral mesh inside a
 * closed surface (cvm_mesh_generate3(), or cvm_mesh_generate3_sized() with sources),
 * optionally optimised (cvm_mesh_optimise_dual3()); write, report.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define MESH3_MAX_SOURCES 64

typedef struct margs {
    const char *in;
    double size;
    double src[MESH3_MAX_SOURCES][5]; /* --point-source x, y, z, h, growth */
    int nsrc;
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
            "                    [--freespace lattice|octree|refine] [--layers N]\n"
            "                    [--point-source X,Y,Z,H[,G]]\n"
            "                    [--optimise] [-o OUT] [--dual DUAL.vtu] [--quality]\n"
            "                    [--timings] [option flags]\n"
            "\n"
            "A tetrahedral co-volume mesh inside a closed surface: one near-field point per\n"
            "pair of surface triangles matched across an edge (or per unmatched triangle),\n"
            "then a body-centred cubic lattice in the free space (--freespace octree: the\n"
            "centroids of a 2:1-balanced octree instead; refine: rounds of circumcentres of\n"
            "the tetrahedra larger than the size, at most --max-steiner N of them), every\n"
            "point strictly inside the domain, tetrahedralised with the surface as\n"
            "`cvmesh tetrahedralize` does.\n"
            "H is the largest size; by default the size near the surface follows its own\n"
            "triangles and grows away from them by the grading G (--uniform: H everywhere).\n"
            "--point-source X,Y,Z,H[,G] (repeatable, up to 64): size H at (X, Y, Z), growing\n"
            "by G (default 0.2) per unit distance; the size is the least of all of them.\n"
            "--optimise then moves vertices and sets power weights (cvm_mesh_optimise_dual3():\n"
            "connectivity kept; boundary vertices stay, but those inside an axis-aligned planar\n"
            "facet slide in it) so that more tetrahedra contain their power vertex; --time-limit S\n"
            "bounds it; --dual writes the weighted power cells. --quality also reports the\n"
            "tetrahedra merged into polyhedral dual cells (--merge-tol F, see\n"
            "cvm_mesh_copy_dual3_merge_groups()) and those non-compliant after merging.\n"
            "Not yet implemented: --layers above 1.\n"
            "\n"
            "Outputs and reports (--timings: read, generate, optimise, write, quality):\n");
    cli_print_output_help(f, 0, 1);
    fprintf(f, "  (.vtu (VTK_TETRA cells), .msh (Gmsh 4.1) or .node (OUT.node + .ele + .face))\n");
    cli_print_option_flags(f, CLI_CMD_MESH3);
    fprintf(f, "\nOn bad input the exit status is 1 and one line names the file, line or face;\n"
               "no output file is written. Command-line errors exit with 2.\n");
}

/* --point-source X,Y,Z,H[,G] into the next source of a. CLI_EXIT_OK, or
 * CLI_EXIT_USAGE after printing why. */
static int parse_point_source(margs *a, const char *v)
{
    double t[5] = {0, 0, 0, 0, 0.2};
    const char *p = v;
    char *end;
    int k;
    if (a->nsrc >= MESH3_MAX_SOURCES) {
        fprintf(stderr, "cvmesh: mesh3: more than %d --point-source flags\n", MESH3_MAX_SOURCES);
        return CLI_EXIT_USAGE;
    }
    for (k = 0; k < 5; k++) {
        t[k] = strtod(p, &end);
        if (end == p || !isfinite(t[k]) || (*end != ',' && *end != '\0'))
            break;
        p = end + (*end == ',');
        if (*end == '\0') {
            k++;
            break;
        }
    }
    if ((k != 4 && k != 5) || *end != '\0' || !(t[3] > 0) || t[4] < 0) {
        fprintf(stderr, "cvmesh: mesh3: --point-source %s: give X,Y,Z,H[,G] (H > 0, G >= 0, "
                        "finite numbers)\n", v);
        return CLI_EXIT_USAGE;
    }
    memcpy(a->src[a->nsrc++], t, sizeof t);
    return CLI_EXIT_OK;
}

/* The flags of this command alone: 1 taken, 0 not one of them, or an exit status + 1. */
static int own_flag(void *args, int argc, char **argv, int *i)
{
    margs *a = args;
    const char *v;
    int r;
    if ((r = cli_take_value(argc, argv, i, "--size", &v)) != 0)
        return r < 0 || cli_parse_positive("--size", v, &a->size) ? CLI_EXIT_USAGE + 1 : 1;
    if ((r = cli_take_value(argc, argv, i, "--point-source", &v)) != 0)
        return r < 0 || parse_point_source(a, v) ? CLI_EXIT_USAGE + 1 : 1;
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
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "mesh3";
    a->o.with_dual = 1; /* --dual DUAL.vtu: the power cells, weights included */
    if ((r = cli_parse_args("mesh3", CLI_CMD_MESH3, argc, argv, cli_mesh3_help, own_flag, a, &a->o,
                            a->set, &a->nset, &a->in)) ||
        (r = cli_check_outputs3("mesh3", a->in, &a->o)))
        return r;
    if (!(a->size > 0)) {
        fprintf(stderr, "cvmesh: mesh3: --size H is required (the largest size)\n");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

void cli_mesh3_report(FILE *f, cvm_mesh *m)
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
        {CVM_REPORT_GEN3_OCTREE_LEAVES, 3, "octree leaves", "%.0f"},
        {CVM_REPORT_GEN3_OCTREE_POINTS, 3, "octree points", "%.0f"},
        {CVM_REPORT_GEN3_REFINE_POINTS, 4, "refinement points", "%.0f"},
        {CVM_REPORT_GEN3_REFINE_ROUNDS, 4, "refinement rounds", "%.0f"},
        {CVM_REPORT_GEN3_RECOVERY_DROPPED, 1, "points dropped for recovery", "%.0f"},
        {CVM_REPORT_DUAL3_SWEEPS, 2, "optimiser sweeps", "%.0f"},
        {CVM_REPORT_DUAL3_MOVES, 2, "optimiser moves", "%.0f"},
        {CVM_REPORT_DUAL3_FLIPS, 2, "optimiser flips", "%.0f"},
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
        {CVM_MEASURE_DUAL3_MERGED_PCT, 0, "merged (--merge-tol)", "%.3f %%"},
        {CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT, 0, "non-compliant after merging", "%.3f %%"},
        {CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT, 0, "  at the boundary", "%.3f %%"},
        {CVM_MEASURE_DUAL3_MERGE_DISSOLVED, 0, "merge groups dissolved", "%.0f"},
        {CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D, 0, "min dual edge / face edge", "%.4g"},
        {CVM_MEASURE_RECOVERY_STEINER, 0, "recovery steiner points", "%.0f"},
    };
    size_t i, n;
    double sw = 0, leaves = 0, rounds = 0;
    int generated = 0;
    /* report 2: optimiser rows, shown after an optimisation; 3: octree rows, after an
     * octree; 4: refinement rows, after a refinement */
    int optimised = cvm_mesh_get_report(&sw, m, CVM_REPORT_DUAL3_SECONDS) == CVM_OK && sw > 0;
    int octree = cvm_mesh_get_report(&leaves, m, CVM_REPORT_GEN3_OCTREE_LEAVES) == CVM_OK &&
                 leaves > 0;
    int refined = cvm_mesh_get_report(&rounds, m, CVM_REPORT_GEN3_REFINE_ROUNDS) == CVM_OK &&
                  rounds > 0;
    /* report 1: generator rows, shown after cvm_mesh_generate3() (which always reports
     * near-field or free-space points); not for a mesh read or tetrahedralised */
    for (i = 0; i < 7 && !generated; i++) {
        double v = 0;
        generated = cvm_mesh_get_report(&v, m, (cvm_report)rows[i].which) == CVM_OK && v > 0;
    }
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (cvm_mesh_count(&n, m, counts[i].kind) == CVM_OK)
            fprintf(f, "%-28s %lu\n", counts[i].label, (unsigned long)n);
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        cvm_status s = rows[i].is_report ? cvm_mesh_get_report(&v, m, (cvm_report)rows[i].which)
                                         : cvm_mesh_get_measure(&v, m, (cvm_measure)rows[i].which);
        if (s != CVM_OK || (rows[i].is_report == 1 && !generated) ||
            (rows[i].is_report == 2 && !optimised) ||
            (rows[i].is_report == 3 && !octree) || (rows[i].is_report == 4 && !refined))
            continue;
        fprintf(f, "%-28s ", rows[i].label);
        fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
}

/* The sizing of the --point-source flags into *out (NULL without any). */
static int make_sizing(margs *a, cvm_sizing **out)
{
    int k;
    *out = NULL;
    if (a->nsrc == 0)
        return CLI_EXIT_OK;
    if (cvm_sizing_create(out) != CVM_OK) {
        fprintf(stderr, "cvmesh: out of memory\n");
        return CLI_EXIT_FAIL;
    }
    for (k = 0; k < a->nsrc; k++)
        if (cvm_sizing_add_point_source_nd(*out, a->src[k], 3, a->src[k][3], a->src[k][4]) !=
            CVM_OK) {
            fprintf(stderr, "cvmesh: mesh3: --point-source: %s\n", cvm_sizing_errmsg(*out));
            cvm_sizing_free(*out);
            *out = NULL;
            return CLI_EXIT_FAIL;
        }
    return CLI_EXIT_OK;
}

static int run(margs *a)
{
    cvm_mesh *m;
    cvm_sizing *sz;
    cli_budget budget;
    int rc;
    cvm_status gs;
    int32_t dim = 0;
    if ((rc = make_sizing(a, &sz)))
        return rc;
    if (cvm_mesh_create(&m) != CVM_OK) {
        fprintf(stderr, "cvmesh: out of memory\n");
        cvm_sizing_free(sz);
        return CLI_EXIT_FAIL;
    }
    if ((rc = cli_apply_settings(m, a->set, a->nset))) {
        cvm_mesh_free(m);
        cvm_sizing_free(sz);
        return rc;
    }
    if (cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, a->freespace) != CVM_OK)
        return cli_fail(m, sz, NULL);
    cvm_mesh_set_progress(m, cli_progress, 256, NULL);
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, sz, NULL);
    if (cvm_mesh_dim(&dim, m) != CVM_OK || dim != 3) {
        fprintf(stderr, "cvmesh: mesh3: %s is a 2D input (use cvmesh refine)\n", a->in);
        cvm_mesh_free(m);
        cvm_sizing_free(sz);
        return CLI_EXIT_FAIL;
    }
    cli_timing_mark(&a->o, "read");
    cli_budget_apply(&budget, m);
    cli_phase("generating", a->in);
    gs = sz ? cvm_mesh_generate3_sized(m, a->size, sz) : cvm_mesh_generate3(m, a->size);
    if (cvm_status_is_error(gs) || cli_interrupted())
        return cli_fail(m, sz, a->in);
    if (gs != CVM_OK)
        fprintf(stderr, "cvmesh: mesh3: %s\n", cvm_mesh_errmsg(m));
    cvm_sizing_free(sz);
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
    return cli_finish3(m, &a->o, "mesh3", a->in, cli_mesh3_report);
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
