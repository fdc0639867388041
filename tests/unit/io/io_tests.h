/* io_tests.h - TCases of the io suite (one per source file of lib/io) and their shared helpers (util.c). */
#ifndef CVMTEST_IO_TESTS_H
#define CVMTEST_IO_TESTS_H

#include <check.h>
#include <stddef.h>

#include "io/io_internal.h"
#include "support/failing_alloc.h"

TCase *io_numtext_tcase(void);       /* test_numtext.c: numtext.c */
TCase *io_fmt_double_tcase(void);    /* test_fmt_double.c: fmt_double.c, integer output of numtext.c */
TCase *io_scan_tcase(void);          /* test_scan.c: scan.c */
TCase *io_read_triangle_tcase(void); /* test_read_triangle.c: read_triangle.c */
TCase *io_reader_tcase(void);        /* test_reader.c: reader.c and injected read faults */
TCase *io_read_file_tcase(void);     /* test_read_file.c: read_file.c */
TCase *io_writer_tcase(void);        /* test_writer.c: writer.c */
TCase *io_write_file_tcase(void);    /* test_write_file.c: write_file.c, OOM and failures */
TCase *io_write_triangle_tcase(void);/* test_write_triangle.c: write_triangle.c round trip */
TCase *io_write_vtu_tcase(void);     /* test_write_vtu.c */
TCase *io_write_vtu_binary_tcase(void); /* test_write_vtu_binary.c: write_vtu_binary.c */
TCase *io_read_vtu_tcase(void);      /* test_read_vtu.c: read_vtu.c */
TCase *io_vtu_data_tcase(void);      /* test_vtu_data.c: vtu_data.c and files VTK and meshio wrote */
TCase *io_read_vtk_tcase(void);      /* test_read_vtk.c: read_vtk.c */
TCase *io_read_msh_tcase(void);      /* test_read_msh.c: read_msh.c, read_mesh_file.c */
TCase *io_write_msh_tcase(void);     /* test_write_msh.c */
TCase *io_write_svg_tcase(void);     /* test_write_svg.c */

/* Directory of the example domains (CVM_DATA_DIR, default examples/data) and of
 * tests/data (CVM_TEST_DATA, default tests/data); path joins dir and name
 * into a static buffer of the calling test. */
const char *iotest_domain_dir(void);
const char *iotest_data_dir(void);
void iotest_path(char *buf, size_t len, const char *dir, const char *name);

/* A context whose allocations go through the failing allocator a. */
void iotest_ctx(cvm__ctx *ctx, cvmtest_alloc *a);

/* Parse text (len bytes; 0 = strlen) as "t.poly" (is_poly) or "t.node". */
cvm_status iotest_parse(cvm__ctx *ctx, const char *text, size_t len, int is_poly, cvm__pslg *p);

/* A fresh empty directory under TMPDIR (or /tmp); free() the result. */
char *iotest_tmpdir(void);
/* Number of entries in dir (without . and ..). */
int iotest_count_entries(const char *dir);
/* Remove every file in dir, then dir. */
void iotest_rmdir(const char *dir);
/* Whole file into a NUL-terminated malloc'd buffer, or NULL. */
char *iotest_slurp(const char *path, size_t *len_out);
/* Number of non-overlapping occurrences of needle in hay. */
size_t iotest_count(const char *hay, const char *needle);

/* A small hand-made mesh: the unit square split into 4 triangles around a
 * centre vertex, with awkward coordinates, markers, attributes, segments. */
void iotest_mesh_out(cvm__mesh_out *mo);

#endif
