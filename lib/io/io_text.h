/*
 * io_text.h - text helpers shared by the io module's readers and writers: a
 * line scanner over a cvm__reader (comments, blank lines, line numbers,
 * fields) and locale-independent number conversion. Not used outside lib/io.
 */
#ifndef CVM_IO_TEXT_H
#define CVM_IO_TEXT_H

#include <stddef.h>
#include "io_internal.h"

/* Longest accepted line, in bytes (without the newline). A longer line is
 * reported as CVM_E_IO_FORMAT, so garbage without newlines cannot make the
 * reader allocate without bound. */
#define CVM__LINE_MAX 65536

/* A line scanner. Lines end at '\n'; '#' starts a comment that runs to the
 * end of the line; fields are separated by spaces, tabs, '\r', '\v', '\f'.
 * Lines with no field are skipped. */
typedef struct cvm__scan {
    cvm__ctx *ctx;
    cvm__reader *r;
    const char *name;   /* file name for messages */
    char *chunk;        /* raw bytes read, chunk[pos..len) not yet consumed */
    size_t pos, len;
    char *line;         /* current line, whitespace turned into NULs */
    size_t line_len, line_cap;
    size_t cursor;      /* where cvm__scan_field() goes on */
    size_t nfields;     /* fields on the current line */
    long lineno;        /* 1-based number of the current line */
    long nlines;        /* physical lines seen so far */
    int eof;            /* the reader said end of file */
} cvm__scan;

/* Start scanning r; name is kept (not copied) for messages. Allocates
 * nothing until the first line is read. */
void cvm__scan_init(cvm__scan *s, cvm__ctx *ctx, cvm__reader *r, const char *name);
/* Free the scanner's buffers (not the reader). */
void cvm__scan_free(cvm__scan *s);

/* Advance to the next line that has a field. *got = 1 on a line, 0 at end of
 * file. Returns CVM_OK, CVM_E_IO_READ, CVM_E_IO_FORMAT (NUL byte, line too
 * long) or CVM_E_NOMEM, with the message set ("name:line: ..."). */
cvm_status cvm__scan_line(cvm__scan *s, int *got);

/* Next field of the current line, NUL-terminated, or NULL when none is left. */
const char *cvm__scan_field(cvm__scan *s);

/* Record an error about the current line: "name:line: " + the formatted text,
 * entity CVM_ENT_FILE_LINE with the line number. Returns st. */
cvm_status cvm__scan_error(cvm__scan *s, cvm_status st, const char *fmt, ...) CVM__PRINTF(3, 4);

/* Parse a whole field as a decimal number, whatever the C locale. Returns 0
 * on success, 1 if the field is not a number (hexadecimal floats such as
 * 0x1p-3 included: Triangle's formats and VTK ASCII arrays are decimal), 2 if
 * it is NaN or infinite (or overflows); *out is set in cases 0 and 2. */
int cvm__parse_double(const char *field, double *out);

/* Parse a whole field as a decimal integer in [lo, hi]. Returns 0 on
 * success, 1 if it is not an integer, 2 if it is out of range. */
int cvm__parse_long(const char *field, long long lo, long long hi, long long *out);

/* Buffer size that holds any output of cvm__format_double(). */
#define CVM__DOUBLE_BUF 40

/* Write x with '.' as decimal point, in the shortest of %.15g, %.16g, %.17g that
 * reads back to exactly x. buf holds CVM__DOUBLE_BUF bytes. Returns the length.
 * x must be finite. The same bytes whatever the C locale; computed by
 * cvm__format_double_fast() (fmt_double.h) when it can prove the result, else
 * by cvm__format_double_libc(). */
size_t cvm__format_double(char *buf, double x);

/* The same text as cvm__format_double(), always computed with snprintf and
 * strtod (slow; the reference the fast path is tested against). */
size_t cvm__format_double_libc(char *buf, double x);

/* Buffer size that holds any output of cvm__format_long()/cvm__format_ulong(). */
#define CVM__INT_BUF 24

/* Write v in decimal ("%lld"/"%llu"), NUL-terminated; returns the length. */
size_t cvm__format_long(char *buf, long long v);
size_t cvm__format_ulong(char *buf, unsigned long long v);

/* ---- Triangle format reader internals ---- */

/* The points that the segments of a .poly without points of its own name:
 * np points of a .node file, numbered from base (0 or 1). */
typedef struct cvm__node_points {
    size_t np;
    int base;
} cvm__node_points;

/* cvm__read_triangle_format with two more parameters: ext (may be NULL) gives
 * the points of a 0-point .poly, against which its segments are checked
 * (without ext such segments are not checked and keep the file's numbers);
 * *base_out (may be NULL) receives the first point number of the file (0 or
 * 1), or -1 when it has no points. */
cvm_status cvm__read_triangle_ex(cvm__ctx *ctx, cvm__reader *r, const char *name, int is_poly,
                                 const cvm__node_points *ext, cvm__pslg *p, int *base_out);

#endif
