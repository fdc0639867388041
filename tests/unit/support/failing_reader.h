/*
 * failing_reader.h - a cvm__reader over bytes in memory that hands out at
 * most `chunk` bytes per read (short reads) and fails (-1) once `fail_after`
 * bytes have been delivered, so tests can inject a read error at every byte
 * offset of an input (SQLite's I/O error simulation).
 */
#ifndef CVMTEST_FAILING_READER_H
#define CVMTEST_FAILING_READER_H

#include <stddef.h>
#include "io/io_internal.h"

typedef struct cvmtest_reader {
    const char *data;
    size_t len;
    size_t pos;          /* bytes delivered so far */
    size_t chunk;        /* at most this many bytes per read; 0 = no limit */
    long fail_after;     /* fail once this many bytes were delivered; -1 = never */
    long n_reads;        /* read calls so far */
} cvmtest_reader;

/* Set up tr over data[0..len) and point r at it. */
void cvmtest_reader_init(cvmtest_reader *tr, cvm__reader *r, const char *data, size_t len,
                         size_t chunk, long fail_after);

#endif
