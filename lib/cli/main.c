/*
 * main.c - the cvmesh program: dispatches to a subcommand from one table.
 * A later subcommand (refine, optimise) is a row here plus its own file.
 */
#include <string.h>

#include "cli.h"

typedef struct cli_command {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv);
    void (*help)(FILE *f);
} cli_command;

static const cli_command k_commands[] = {
    {"triangulate", "Delaunay / constrained Delaunay triangulation of a .node or .poly file",
     cli_triangulate, cli_triangulate_help},
    {"refine", "quality mesh of a .poly file: Delaunay refinement, frontal-Delaunay or AFLR",
     cli_refine, cli_refine_help},
    {"optimise", "optimise a mesh's power (weighted Voronoi) dual: every triangle holds its dual vertex",
     cli_optimise, cli_optimise_help},
    {"tetrahedralize", "Delaunay tetrahedralisation of 3D points, or the tetrahedral mesh of a closed surface",
     cli_tetrahedralize, cli_tetrahedralize_help},
    {"mesh3", "co-volume tetrahedral mesh inside a closed surface: near field + BCC lattice",
     cli_mesh3, cli_mesh3_help},
    {"quad", "quad-dominant mesh of a convex domain aligned with a metric (Lp-CVT + Blossom-Quad)",
     cli_quad, cli_quad_help},
};

#define NCOMMANDS (sizeof k_commands / sizeof k_commands[0])

static void usage(FILE *f)
{
    size_t i;
    fprintf(f, "usage: cvmesh COMMAND [ARGS...]\n"
               "       cvmesh COMMAND --help\n"
               "       cvmesh --version\n\n"
               "commands:\n");
    for (i = 0; i < NCOMMANDS; i++)
        fprintf(f, "  %-14s %s\n", k_commands[i].name, k_commands[i].summary);
    fprintf(f, "\nexample: cvmesh triangulate domain.poly -o mesh.vtu --svg mesh.svg --quality\n");
}

int main(int argc, char **argv)
{
    size_t i;
    if (argc < 2) {
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "help") == 0) {
        if (argc > 2)
            for (i = 0; i < NCOMMANDS; i++)
                if (strcmp(argv[2], k_commands[i].name) == 0) {
                    k_commands[i].help(stdout);
                    return CLI_EXIT_OK;
                }
        usage(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "-V") == 0) {
        printf("cvmesh %s\n%s\n", cvm_version_string(), cvm_build_string());
        return CLI_EXIT_OK;
    }
    for (i = 0; i < NCOMMANDS; i++)
        if (strcmp(argv[1], k_commands[i].name) == 0) {
            int rc;
            cli_signals_install();
            rc = k_commands[i].run(argc - 1, argv + 1);
            cli_progress_clear();
            return rc;
        }
    fprintf(stderr, "cvmesh: unknown command '%s' (see cvmesh --help)\n", argv[1]);
    return CLI_EXIT_USAGE;
}
