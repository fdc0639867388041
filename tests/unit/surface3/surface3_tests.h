/* surface3_tests.h - TCases of the surface3 suite (3D surface readers, validation, TetGen recovery) and their helpers (util.c). */
#ifndef CVMTEST_SURFACE3_TESTS_H
#define CVMTEST_SURFACE3_TESTS_H

#include <check.h>
#include <stddef.h>

#include "io/surf3_io.h"
#include "surface3/surface3_internal.h"
#include "support/failing_alloc.h"

TCase *surface3_read_tcase(void);     /* test_read.c: read_off.c, read_stl.c, read_tetpoly.c */
TCase *surface3_faults_tcase(void);   /* test_faults.c: malformed files, OOM, read faults */
TCase *surface3_validate_tcase(void); /* test_validate.c: lib/surface3 */
TCase *surface3_tetgen_tcase(void);   /* test_tetgen.c: lib/tetgen */

/* Path of a generated 3D surface: CVM_DATA3D_DIR (make data3d), else examples/data3d. */
void s3test_path(char *buf, size_t len, const char *name);
/* A context on the failing allocator a. */
void s3test_ctx(cvm__ctx *ctx, cvmtest_alloc *a);
/* Read the named surface file (in the data directory); asserts CVM_OK. */
void s3test_read(cvm__ctx *ctx, const char *name, cvm__surf3 *s);
/* Parse text as a file named name (by its extension: .off, .stl, .poly, .smesh). */
cvm_status s3test_parse(cvm__ctx *ctx, const char *name, const char *text, size_t len, cvm__surf3 *s);
/* Signed volume of the triangles of s (polygons fanned), divergence theorem. */
double s3test_volume(const cvm__surf3 *s);
/* Whole file into a malloc'd buffer (NULL if unreadable). */
char *s3test_slurp(const char *path, size_t *len);

#endif
