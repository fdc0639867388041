/* suite.c - the io suite: one TCase per source file under test. */
#include "suites.h"
#include "io/io_tests.h"

Suite *io_suite(void)
{
    Suite *s = suite_create("io");
    suite_add_tcase(s, io_numtext_tcase());
    suite_add_tcase(s, io_fmt_double_tcase());
    suite_add_tcase(s, io_scan_tcase());
    suite_add_tcase(s, io_read_triangle_tcase());
    suite_add_tcase(s, io_reader_tcase());
    suite_add_tcase(s, io_read_file_tcase());
    suite_add_tcase(s, io_writer_tcase());
    suite_add_tcase(s, io_write_file_tcase());
    suite_add_tcase(s, io_write_triangle_tcase());
    suite_add_tcase(s, io_write_vtu_tcase());
    suite_add_tcase(s, io_write_vtu_binary_tcase());
    suite_add_tcase(s, io_read_vtu_tcase());
    suite_add_tcase(s, io_vtu_data_tcase());
    suite_add_tcase(s, io_read_vtk_tcase());
    suite_add_tcase(s, io_read_msh_tcase());
    suite_add_tcase(s, io_write_msh_tcase());
    suite_add_tcase(s, io_write_svg_tcase());
    return s;
}
