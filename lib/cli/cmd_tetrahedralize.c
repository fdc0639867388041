/*
 * cmd_tetrahedralize.c - `cvmesh tetrahedralize IN.node|IN.poly|IN.smesh|IN.off|IN.stl
 * [-o OUT] [--dual DUAL.vtu] [--quality] [--timings] [option flags]`: the Delaunay tetrahedralisation of a
 * 3D point set, or the tetrahedral mesh of the inside of a closed surface; write, report.
 */
#include <string.h>

#include "cli.h"

typedef struct targs {
    const char *in;
    cli_outputs o;
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} targs;

void cli_tetrahedralize_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh tetrahedralize IN.node|IN.poly|IN.smesh|IN.off|IN.stl [-o OUT]\n"
            "                             [--dual DUAL.vtu] [--quality] [--timings]\n"
            "                             [option flags]\n"
            "\n"
            "The Delaunay tetrahedralisation of the points of a 3D .node file (TetGen's\n"
            "format), or the tetrahedral mesh of the inside of a closed surface (.off, .stl,\n"
            "TetGen .poly/.smesh with holes and regions). Every decision is exact (filtered\n"
            "predicates with symbolic perturbation), so cospherical input such as a lattice\n"
            "has one answer, the same for every seed and machine. A surface is recovered by\n"
            "TetGen when this build has it (cvmesh --version says so); without it, the\n"
            "surface's triangles must be faces of the Delaunay tetrahedralisation of its\n"
            "points, and the command says which one is not.\n"
            "\n"
            "Outputs and reports (--timings: read, tetrahedralize, write, quality):\n");
    cli_print_output_help(f, 0, 1);
    fprintf(f, "  (3D meshes write .vtu (VTK_TETRA cells), .msh (Gmsh 4.1: volumes per region,\n"
               "  surfaces per marker) or .node (OUT.node + .ele + .face); not .svg. --dual\n"
               "  writes the bounded power cells, those of the interior vertices, as\n"
               "  VTK_POLYHEDRON cells sharing their corners, with their volumes)\n");
    cli_print_option_flags(f, CLI_CMD_TETRAHEDRALIZE);
    fprintf(f, "\nOn bad input the exit status is 1 and one line names the file, line or face;\n"
               "no output file is written. Command-line errors exit with 2.\n");
}

static int parse(targs *a, int argc, char **argv)
{
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "tetrahedralize";
    a->o.with_dual = 1;
    if ((r = cli_parse_args("tetrahedralize", CLI_CMD_TETRAHEDRALIZE, argc, argv,
                            cli_tetrahedralize_help, NULL, NULL, &a->o, a->set, &a->nset, &a->in)))
        return r;
    return cli_check_outputs3("tetrahedralize", a->in, &a->o);
}

static void report(FILE *f, cvm_mesh *m)
{
    static const struct {
        cvm_entity kind;
        const char *label;
    } counts[] = {{CVM_ENT_VERTEX, "vertices"},
                  {CVM_ENT_TETRAHEDRON, "tetrahedra"},
                  {CVM_ENT_TRIANGLE, "boundary faces"},
                  {CVM_ENT_DUPLICATE, "duplicates merged"}};
    static const struct {
        cvm_measure which;
        const char *label, *fmt;
    } rows[] = {
        {CVM_MEASURE_VOLUME, "volume", "%.10g"},
        {CVM_MEASURE_MIN_DIHEDRAL_DEG, "min dihedral angle", "%.4g deg"},
        {CVM_MEASURE_MAX_DIHEDRAL_DEG, "max dihedral angle", "%.4g deg"},
        {CVM_MEASURE_MAX_RADIUS_EDGE, "max radius-edge ratio", "%.4g"},
        {CVM_MEASURE_MEAN_RADIUS_EDGE, "mean radius-edge ratio", "%.4g"},
        {CVM_MEASURE_MIN_EDGE, "min edge", "%.6g"},
        {CVM_MEASURE_MAX_EDGE, "max edge", "%.6g"},
        {CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT, "circumcentre outside", "%.3f %%"},
        {CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT, "  at the boundary", "%.3f %%"},
        {CVM_MEASURE_MIN_DUAL_EDGE_3D, "min dual edge", "%.6g"},
        {CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D, "min dual edge / face edge", "%.4g"},
        {CVM_MEASURE_TIME_STEP_PROXY_3D, "time-step proxy", "%.6g"},
        {CVM_MEASURE_VALENCE14_PCT, "interior valence 14", "%.3f %%"},
        {CVM_MEASURE_VANISHED_VERTICES, "vanished vertices", "%.0f"},
        {CVM_MEASURE_RECOVERY_STEINER, "recovery steiner points", "%.0f"},
    };
    size_t i, n;
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++)
        if (cvm_mesh_count(&n, m, counts[i].kind) == CVM_OK)
            fprintf(f, "%-28s %lu\n", counts[i].label, (unsigned long)n);
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        if (cvm_mesh_get_measure(&v, m, rows[i].which) != CVM_OK)
            continue;
        fprintf(f, "%-28s ", rows[i].label);
        fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
    {
        double h[18];
        int k;
        if (cvm_mesh_copy_histogram(h, 18, m, CVM_HIST_DIHEDRAL_DEG) == CVM_OK) {
            fprintf(f, "%-28s", "dihedral angles (10 deg)");
            for (k = 0; k < 18; k++)
                fprintf(f, " %.0f", h[k]);
            fputc('\n', f);
        }
    }
}

static int run(targs *a)
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
    cvm_mesh_set_progress(m, cli_progress, 256, NULL);
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, NULL, NULL);
    if (cvm_mesh_dim(&dim, m) != CVM_OK || dim != 3) {
        fprintf(stderr, "cvmesh: tetrahedralize: %s is a 2D input (use cvmesh triangulate)\n", a->in);
        cvm_mesh_free(m);
        return CLI_EXIT_FAIL;
    }
    cli_timing_mark(&a->o, "read");
    cli_budget_apply(&budget, m);
    cli_phase("tetrahedralizing", a->in);
    if (cvm_mesh_triangulate(m) != CVM_OK || cli_interrupted())
        return cli_fail(m, NULL, a->in);
    cli_timing_mark(&a->o, "tetrahedralize");
    cli_note_duplicates(m, a->in);
    return cli_finish3(m, &a->o, "tetrahedralize", a->in, report);
}

int cli_tetrahedralize(int argc, char **argv)
{
    targs a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
