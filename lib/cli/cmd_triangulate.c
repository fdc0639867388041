/*
 * cmd_triangulate.c - `cvmesh triangulate IN.poly|IN.node|IN.vtu [-o OUT] [--svg PIC.svg]
 * [--dual DUAL.vtu] [--quality] [--timings] [option flags]`: read, triangulate
 * (unless the input is a mesh), write, report.
 */
#include <string.h>

#include "cli.h"

typedef struct args {
    const char *in;
    cli_outputs o;
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} args;

/* Time of the first segment-recovery progress report: splits triangulate
 * into Delaunay insertion and segment recovery for --timings. */
typedef struct phases {
    double recover_start;
} phases;

void cli_triangulate_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh triangulate IN.poly|IN.node|IN.vtu [-o OUT] [--svg PIC.svg]\n"
            "                          [--dual DUAL.vtu] [--quality] [--timings] [option flags]\n"
            "\n"
            "Delaunay triangulation of the points of a .node file, or constrained Delaunay\n"
            "triangulation of the planar straight-line graph of a .poly file (Triangle's\n"
            "formats), with the exterior and holes removed and regional attributes assigned.\n"
            "A .vtu mesh (as cvmesh writes it, with its weights) is read as it is, to\n"
            "convert it, draw it, write its dual or report its quality; so are .vtk\n"
            "(legacy VTK) and .msh (Gmsh 2.2/4.1) meshes, and a .vtk or .msh without\n"
            "triangles is a domain (its lines are segments, physical tags markers).\n"
            "\n"
            "Outputs and reports (--timings: read, triangulate, recover segments from the\n"
            "first recovered segment with carving, write, quality):\n");
    cli_print_output_help(f, 1, 1);
    cli_print_option_flags(f, CLI_CMD_TRIANGULATE);
    fprintf(f, "\nOn bad input the exit status is 1, one line names the file, line or item,\n"
               "and no output file is written. Command-line errors exit with 2.\n"
               "--time-limit bounds the whole command (reading and writing are not cut\n"
               "short). A triangulation cannot stop half-way: stopped by the limit, nothing\n"
               "is written, one line says where it stopped, and the exit status is 1.\n"
               "\nThe output files (-o, --svg, --dual) replace their old versions together or not\n"
               "at all, and a replaced file keeps its permissions. SIGINT (Ctrl-C) or SIGTERM\n"
               "stops the command: exit status 130 or 143, one line says what was interrupted,\n"
               "and no file is written or changed unless the outputs were already complete.\n");
}

static int parse(args *a, int argc, char **argv)
{
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "triangulate";
    a->o.with_svg = a->o.with_dual = 1;
    if ((r = cli_parse_args("triangulate", CLI_CMD_TRIANGULATE, argc, argv, cli_triangulate_help,
                            NULL, NULL, &a->o, a->set, &a->nset, &a->in)))
        return r;
    if (cli_need_input("triangulate", a->in))
        return CLI_EXIT_USAGE;
    return cli_check_outputs("triangulate", &a->o);
}

static int on_progress(void *payload, cvm_stage stage, double fraction)
{
    phases *ph = (phases *)payload;
    if (stage == CVM_STAGE_RECOVER_SEGMENTS && ph->recover_start == 0)
        ph->recover_start = cli_now();
    return cli_progress(NULL, stage, fraction);
}

static int run(args *a)
{
    cvm_mesh *m;
    cli_budget budget;
    phases ph = {0};
    double t0, t_read, t_tri, t_write;
    cvm_status s;
    int rc;
    if (cvm_mesh_create(&m) != CVM_OK) {
        fprintf(stderr, "cvmesh: out of memory\n");
        return CLI_EXIT_FAIL;
    }
    if ((rc = cli_apply_settings(m, a->set, a->nset))) {
        cvm_mesh_free(m);
        return rc;
    }
    /* every 1 for --timings: the first recovery report splits the phases */
    cvm_mesh_set_progress(m, on_progress, a->o.timings ? 1 : 256, &ph);
    t0 = cli_now();
    cli_budget_begin(&budget, m);
    cli_phase("reading", a->in);
    if (cvm_mesh_read(m, a->in) != CVM_OK)
        return cli_fail(m, NULL, NULL);
    t_read = cli_now();
    cli_budget_apply(&budget, m);
    cli_phase("triangulating", a->in);
    s = cli_is_triangulated(m) ? CVM_OK : cvm_mesh_triangulate(m); /* a .vtu is a mesh */
    if (s != CVM_OK || cli_interrupted())
        return cli_fail(m, NULL, a->in);
    t_tri = cli_now();
    cli_note_duplicates(m, a->in);
    if ((rc = cli_write_outputs(m, &a->o)) < 0)
        return cli_stop(m, NULL);
    if (rc) {
        cvm_mesh_free(m);
        return rc;
    }
    t_write = cli_now();
    if (a->o.timings) {
        double split = ph.recover_start > 0 ? ph.recover_start : t_tri;
        FILE *rep = cli_report_stream(&a->o);
        fprintf(rep, "read: %.6f\n", t_read - t0);
        fprintf(rep, "triangulate: %.6f\n", split - t_read);
        fprintf(rep, "recover segments: %.6f\n", t_tri - split);
        fprintf(rep, "write: %.6f\n", t_write - t_tri);
    }
    cli_timing_begin(&a->o);
    cli_phase("computing the quality report", NULL);
    if (a->o.quality) {
        if ((rc = cli_print_quality(cli_report_stream(&a->o), m, a->o.quality == 2))) {
            cvm_mesh_free(m);
            return rc;
        }
        cli_timing_mark(&a->o, "quality");
    }
    if (cli_interrupted())
        return cli_stop(m, NULL);
    cli_note_nothing_to_do("triangulate", a->in, &a->o);
    cvm_mesh_free(m);
    return CLI_EXIT_OK;
}

int cli_triangulate(int argc, char **argv)
{
    args a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
