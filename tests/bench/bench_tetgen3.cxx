/*
 * bench_tetgen3.cxx - times TetGen 1.5 (Debian libtet1.5-dev, linked directly)
 * on one point file, for bench_delaunay3.py. Test-only C++: the library stays C.
 * Usage: bench_tetgen3 POINTS.bin REPS  (n * 3 doubles, native byte order)
 * Prints one JSON object: median wall and CPU seconds of tetrahedralize("Q")
 * (Delaunay tetrahedralisation of the points, output arrays included), its
 * tetrahedra, and the growth of the peak RSS during the last run.
 */
#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

static double clock_s(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* VmHWM in bytes; writing 5 to clear_refs resets it first. */
static long hwm_bytes()
{
    char line[256];
    long kb = -1;
    FILE *f = std::fopen("/proc/self/status", "r");
    if (!f)
        return -1;
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, "VmHWM:", 6) == 0)
            kb = std::atol(line + 6);
    std::fclose(f);
    return kb * 1024;
}

int main(int argc, char **argv)
{
    FILE *f;
    if (argc != 3 || !(f = std::fopen(argv[1], "rb"))) {
        std::fprintf(stderr, "usage: bench_tetgen3 POINTS.bin REPS\n");
        return 2;
    }
    int reps = std::max(1, std::min(64, std::atoi(argv[2])));
    std::fseek(f, 0, SEEK_END);
    long bytes = std::ftell(f);
    std::fseek(f, 0, SEEK_SET);
    size_t n = (size_t)bytes / (3 * sizeof(double));
    double *xyz = new double[3 * n];
    if (std::fread(xyz, sizeof(double), 3 * n, f) != 3 * n)
        return 2;
    std::fclose(f);
    double wall[64], cpu[64];
    long tets = 0, grow = -1;
    for (int r = 0; r < reps; r++) {
        tetgenio in, out;
        in.numberofpoints = (int)n;
        in.pointlist = new REAL[3 * n]; /* tetgenio frees it with delete[] */
        std::memcpy(in.pointlist, xyz, 3 * n * sizeof(double));
        FILE *cr = std::fopen("/proc/self/clear_refs", "w");
        if (cr) {
            std::fputs("5", cr);
            std::fclose(cr);
        }
        long base = hwm_bytes();
        tetgenbehavior b;
        b.parse_commandline((char *)"Q");
        double w0 = clock_s(CLOCK_MONOTONIC), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
        try {
            tetrahedralize(&b, &in, &out);
        } catch (int e) {
            std::fprintf(stderr, "bench_tetgen3: TetGen threw %d\n", e);
            return 1;
        }
        wall[r] = clock_s(CLOCK_MONOTONIC) - w0;
        cpu[r] = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
        tets = out.numberoftetrahedra;
        grow = hwm_bytes() - base;
    }
    std::sort(wall, wall + reps);
    std::sort(cpu, cpu + reps);
    std::printf("{\"n\": %zu, \"wall\": %.4f, \"cpu\": %.4f, \"tets\": %ld, \"peak_bytes\": %ld}\n", n,
                wall[reps / 2], cpu[reps / 2], tets, grow);
    delete[] xyz;
    return 0;
}
