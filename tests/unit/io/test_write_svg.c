/* test_write_svg.c - the SVG picture: one polygon per triangle, segments drawn, view fitted. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_tests.h"

static char *write_svg(cvm__mesh_out *mo)
{
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    snprintf(path, sizeof path, "%s/m.svg", dir);
    ck_assert_int_eq(cvm__write_file(&ctx, path, mo), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    iotest_rmdir(dir);
    free(dir);
    return text;
}

START_TEST(svg_draws_triangles_segments_and_legend)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    t = write_svg(&mo);
    ck_assert_ptr_nonnull(strstr(t, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 800.00 834.00\""));
    ck_assert_uint_eq(iotest_count(t, "<polygon "), 4);
    /* y points up: vertex (0, 0) is at the bottom left */
    ck_assert_ptr_nonnull(strstr(t, "<polygon points=\"10.00,790.00 790.00,790.00 400.00,400.00\" fill=\"#"));
    ck_assert_ptr_nonnull(strstr(t, "d=\"M10.00,790.00 L790.00,790.00 M790.00,790.00 L790.00,10.00 M"));
    ck_assert_ptr_nonnull(strstr(t, "smallest angle"));
    ck_assert_ptr_nonnull(strstr(t, "</svg>\n"));
    free(t);
}
END_TEST

START_TEST(svg_without_quality_is_uniform)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.tquality = NULL;
    mo.nseg = 0;
    t = write_svg(&mo);
    ck_assert_ptr_nonnull(strstr(t, "viewBox=\"0 0 800.00 800.00\""));
    ck_assert_uint_eq(iotest_count(t, "<polygon "), 4);
    ck_assert_uint_eq(iotest_count(t, "fill=\"#"), 1); /* the group's fill only */
    ck_assert_ptr_null(strstr(t, "<path"));
    ck_assert_ptr_null(strstr(t, "smallest angle"));
    free(t);
}
END_TEST

/* A window shows its region at 800 px wide, clips at its edge and leaves out
 * the triangles wholly outside it (the fan's top triangle and, in x, nothing). */
START_TEST(svg_window_frames_and_culls)
{
    cvm__mesh_out mo;
    char *t;
    iotest_mesh_out(&mo);
    mo.window[0] = 0;
    mo.window[1] = 0;
    mo.window[2] = 1;
    mo.window[3] = 0.25;
    t = write_svg(&mo);
    /* 780 px per unit: 0.25 high is 195 px, plus margins and the legend */
    ck_assert_ptr_nonnull(strstr(t, "viewBox=\"0 0 800.00 249.00\""));
    ck_assert_ptr_nonnull(strstr(t, "<clipPath id=\"window\"><rect x=\"10.00\" y=\"10.00\" width=\"780.00\" height=\"195.00\"/>"));
    ck_assert_uint_eq(iotest_count(t, "<polygon "), 3);
    /* vertex (0, 0) sits at the bottom left of the window */
    ck_assert_ptr_nonnull(strstr(t, "10.00,205.00"));
    /* an empty window (xmax <= xmin) is no window */
    mo.window[2] = -1;
    free(t);
    t = write_svg(&mo);
    ck_assert_ptr_null(strstr(t, "clipPath"));
    ck_assert_uint_eq(iotest_count(t, "<polygon "), 4);
    free(t);
}
END_TEST

TCase *io_write_svg_tcase(void)
{
    TCase *tc = tcase_create("write_svg");
    tcase_add_test(tc, svg_draws_triangles_segments_and_legend);
    tcase_add_test(tc, svg_without_quality_is_uniform);
    tcase_add_test(tc, svg_window_frames_and_culls);
    return tc;
}
