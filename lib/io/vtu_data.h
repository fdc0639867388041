/*
 * vtu_data.h - decoding the content of one VTK XML <DataArray> (ASCII text,
 * inline base64, appended raw or base64, optionally zlib-compressed) into
 * numbers. Shared by read_vtu.c; not used outside lib/io.
 */
#ifndef CVM_IO_VTU_DATA_H
#define CVM_IO_VTU_DATA_H

#include <stddef.h>
#include "io_internal.h"

/* The whole file and its file-wide encoding (attributes of <VTKFile> and
 * <AppendedData>). */
typedef struct cvm__vtu_file {
    cvm__ctx *ctx;
    const char *name;   /* file name for messages */
    const char *buf;    /* the whole file, NUL-terminated at n */
    size_t n;
    int big_endian;     /* byte_order="BigEndian" */
    int header64;       /* header_type="UInt64" (else UInt32) */
    int zlib;           /* compressor="vtkZLibDataCompressor" */
    size_t appended;    /* offset of the first byte after <AppendedData ...>'s '_'; 0: none */
    int appended_raw;   /* encoding="raw" (else base64) */
} cvm__vtu_file;

/* One <DataArray>: its start tag [ts, te) and content [cs, ce) (offsets into
 * the file). */
typedef struct cvm__vtu_array {
    size_t ts, te, cs, ce;
} cvm__vtu_array;

/* Decode array a into a fresh array (through f->ctx) of exactly want values
 * (want < 0: any count, *got receives it): long long when integer (values in
 * [-INT32_MAX, INT32_MAX]; a Float type is refused), else double (finite).
 * what names the array in messages, which give "name:line:" and, for binary
 * data, the byte offset. Returns CVM_OK, CVM_E_IO_FORMAT, CVM_E_UNSUPPORTED
 * (an unknown type or format), CVM_E_INPUT_NONFINITE, CVM_E_NOMEM; *out is
 * NULL on error. */
cvm_status cvm__vtu_decode(const cvm__vtu_file *f, const cvm__vtu_array *a, const char *what,
                           int integer, long long want, void **out, size_t *got);

/* One binary number of size bytes at p (kind CVM__BIN_*, big-endian when
 * big). integer: into *l, in [-INT32_MAX, INT32_MAX], else 1 (a float is
 * 1 too); otherwise into *d, 2 when not finite. 0 on success. */
enum { CVM__BIN_SIGNED, CVM__BIN_UNSIGNED, CVM__BIN_FLOAT };
int cvm__bin_number(const unsigned char *p, int size, int kind, int big, int integer,
                    long long *l, double *d);

/* Set an error "name:line: message" about byte offset at of f. */
cvm_status cvm__vtu_fail(const cvm__vtu_file *f, size_t at, cvm_status st, const char *fmt, ...)
    CVM__PRINTF(4, 5);

/* Value of attribute key in the tag [s, e) into out (cap CVM__VTU_ATTR_LEN,
 * truncated); 0 if absent. */
#define CVM__VTU_ATTR_LEN 64
int cvm__vtu_attr(const char *s, const char *e, const char *key, char *out);

#endif
