/*
 * minimal.c - the smallest complete cvmesh program: mesh a square with a
 * square hole, print the triangles, write a .vtu file for ParaView.
 *
 *   cc minimal.c $(pkg-config --cflags --libs cvmesh) -o minimal && ./minimal
 */
#include <stdio.h>
#include <stdlib.h>

#include <cvmesh.h>

/* On error: print what failed and the handle's message, which names the input. */
static int failed(cvm_status s, cvm_mesh *m, const char *what)
{
    if (!cvm_status_is_error(s))
        return 0;
    fprintf(stderr, "minimal: %s: %s: %s\n", what, cvm_status_str(s), cvm_mesh_errmsg(m));
    return 1;
}

int main(void)
{
    /* Outer square 0-3 (counter-clockwise) and inner square 4-7 around the hole. */
    static const double xy[] = {0, 0, 3, 0, 3, 3, 0, 3, 1, 1, 2, 1, 2, 2, 1, 2};
    static const cvm_index segs[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    static const double hole[] = {1.5, 1.5}; /* any point inside the hole */
    cvm_mesh *m = NULL;
    cvm_index *tri = NULL;
    size_t nv = 0, nt = 0, i;
    cvm_status s;
    int rc = EXIT_FAILURE;

    s = cvm_mesh_create(&m);
    if (s != CVM_OK) {
        fprintf(stderr, "minimal: cvm_mesh_create: %s\n", cvm_status_str(s));
        return EXIT_FAILURE;
    }
    if (failed(cvm_mesh_set_points(m, xy, 8, 2), m, "set_points") ||
        failed(cvm_mesh_set_segments(m, segs, 8), m, "set_segments") ||
        failed(cvm_mesh_set_holes(m, hole, 1), m, "set_holes") ||
        failed(cvm_mesh_triangulate(m), m, "triangulate"))
        goto done;

    /* Ask for the count, then copy into a buffer of that size. */
    if (failed(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), m, "count") ||
        failed(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), m, "count"))
        goto done;
    tri = malloc(3 * nt * sizeof *tri);
    if (!tri || failed(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), m, "copy_cells"))
        goto done;
    printf("%zu vertices, %zu triangles (0-based, counter-clockwise):\n", nv, nt);
    for (i = 0; i < nt; i++)
        printf("  %d %d %d\n", (int)tri[3 * i], (int)tri[3 * i + 1], (int)tri[3 * i + 2]);

    /* The format follows the extension: .vtu, .msh, .node, .svg. */
    if (failed(cvm_mesh_write(m, "minimal.vtu"), m, "write"))
        goto done;
    printf("wrote minimal.vtu\n");
    rc = EXIT_SUCCESS;
done:
    free(tri);
    cvm_mesh_free(m);
    return rc;
}
