/*
 * cmd_triangulate.c - `cvmesh triangulate IN.poly|IN.node|IN.vtu [-o OUT] [--svg PIC.svg]
 * [--dual DUAL.vtu] [--quality] [--timings] [option flags]`: read, triangulate
 * (unless the input is a mesh), write, report.
 */
#include <string.h>

#include "cli.h"

typedef struct args {
    const char *in, *out, *svg, *dual;
    int quality, timings;
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
            "  -o, --output OUT           write the mesh; the extension chooses the format:\n"
            "                             .vtu (VTK XML), .msh (Gmsh 4.1), .svg (picture),\n"
            "                             .node (OUT.node + .ele + .edge beside each other)\n"
            "  --svg PIC.svg              also draw the mesh, coloured by smallest angle\n"
            "  --dual DUAL.vtu            write the power (Voronoi) cells as VTK polygons with\n"
            "                             vertex id, area and weight\n"
            "  --quality                  print the quality report (with the dual's q1-q5)\n"
            "  --timings                  print 'phase: seconds' for read, triangulate,\n"
            "                             recover segments (from the first recovered segment,\n"
            "                             with carving), write\n"
            "  -h, --help                 print this help\n");
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

static int has_ext(const char *path, const char *ext)
{
    size_t n = strlen(path), k = strlen(ext);
    return n > k && strcmp(path + n - k, ext) == 0;
}

static int parse(args *a, int argc, char **argv)
{
    int i;
    memset(a, 0, sizeof *a);
    for (i = 1; i < argc; i++) {
        const char *s = argv[i];
        int r;
        if (strcmp(s, "-h") == 0 || strcmp(s, "--help") == 0) {
            cli_triangulate_help(stdout);
            return -1;
        }
        if (strcmp(s, "-o") == 0 || strcmp(s, "--output") == 0 || strcmp(s, "--svg") == 0 ||
            strcmp(s, "--dual") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "cvmesh: %s needs a file name\n", s);
                return CLI_EXIT_USAGE;
            }
            if (strcmp(s, "--svg") == 0)
                a->svg = argv[++i];
            else if (strcmp(s, "--dual") == 0)
                a->dual = argv[++i];
            else
                a->out = argv[++i];
            continue;
        }
        if (strcmp(s, "--quality") == 0) {
            a->quality = 1;
            continue;
        }
        if (strcmp(s, "--timings") == 0) {
            a->timings = 1;
            continue;
        }
        if ((r = cli_parse_tail("triangulate", CLI_CMD_TRIANGULATE, argc, argv, &i, a->set,
                                &a->nset, &a->in)))
            return r;
    }
    if (cli_need_input("triangulate", a->in))
        return CLI_EXIT_USAGE;
    if (a->out && !has_ext(a->out, ".vtu") && !has_ext(a->out, ".msh") &&
        !has_ext(a->out, ".node") && !has_ext(a->out, ".svg")) {
        fprintf(stderr, "cvmesh: %s: unknown output format (use .vtu, .msh, .node or .svg)\n", a->out);
        return CLI_EXIT_USAGE;
    }
    if (a->svg && !has_ext(a->svg, ".svg")) {
        fprintf(stderr, "cvmesh: --svg %s: the file name must end in .svg\n", a->svg);
        return CLI_EXIT_USAGE;
    }
    if (a->dual && !has_ext(a->dual, ".vtu")) {
        fprintf(stderr, "cvmesh: --dual %s: the file name must end in .vtu\n", a->dual);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int on_progress(void *payload, cvm_stage stage, double fraction)
{
    phases *ph = (phases *)payload;
    if (stage == CVM_STAGE_RECOVER_SEGMENTS && ph->recover_start == 0)
        ph->recover_start = cli_now();
    return cli_progress(NULL, stage, fraction);
}

static int run(const args *a)
{
    cvm_mesh *m;
    cli_budget budget;
    phases ph = {0};
    double t0, t_read, t_tri, t_write;
    cvm_status s;
    size_t ndup = 0;
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
    cvm_mesh_set_progress(m, on_progress, a->timings ? 1 : 256, &ph);
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
    if (cvm_mesh_count(&ndup, m, CVM_ENT_DUPLICATE) == CVM_OK && ndup)
        fprintf(stderr, "cvmesh: note: %s: %lu duplicate points merged\n", a->in, (unsigned long)ndup);
    if ((rc = cli_write_outputs(m, a->out, a->svg, a->dual)) < 0)
        return cli_stop(m, NULL);
    if (rc) {
        cvm_mesh_free(m);
        return rc;
    }
    t_write = cli_now();
    cli_phase("computing the quality report", NULL);
    if (a->quality && (rc = cli_print_quality(stdout, m))) {
        cvm_mesh_free(m);
        return rc;
    }
    if (cli_interrupted())
        return cli_stop(m, NULL);
    if (a->timings) {
        double split = ph.recover_start > 0 ? ph.recover_start : t_tri;
        printf("read: %.6f\n", t_read - t0);
        printf("triangulate: %.6f\n", split - t_read);
        printf("recover segments: %.6f\n", t_tri - split);
        printf("write: %.6f\n", t_write - t_tri);
    }
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
