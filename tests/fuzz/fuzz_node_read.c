/* fuzz_node_read.c - libFuzzer target: any bytes parsed as a Triangle .node file (see fuzz_poly_read.c). */
#define FUZZ_IS_POLY 0
#include "fuzz_poly_read.c"
