/*
 * bench_tetgen_quality.cxx - TetGen 1.5's quality mesh of a surface, for
 * bench_generate3.py. Test-only C++: the library stays C.
 * Usage: bench_tetgen_quality IN.poly SWITCHES OUTBASE
 * Runs tetrahedralize(SWITCHES) on the .poly (read by TetGen's own reader) and
 * writes OUTBASE.node and OUTBASE.ele; prints one JSON object with the wall
 * time of tetrahedralize() alone and the counts.
 */
#define TETLIBRARY
#include <tetgen.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

static double now()
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: bench_tetgen_quality IN.poly SWITCHES OUTBASE\n");
        return 2;
    }
    tetgenio in, out;
    std::string base(argv[1]);
    if (base.size() > 5 && base.compare(base.size() - 5, 5, ".poly") == 0)
        base.resize(base.size() - 5);
    char name[4096], sw[256], ob[4096];
    std::snprintf(name, sizeof name, "%s", base.c_str());
    if (!in.load_poly(name)) {
        std::fprintf(stderr, "bench_tetgen_quality: cannot read %s.poly\n", name);
        return 1;
    }
    std::snprintf(sw, sizeof sw, "%s", argv[2]);
    double t0 = now();
    tetrahedralize(sw, &in, &out);
    double t1 = now();
    std::snprintf(ob, sizeof ob, "%s", argv[3]);
    out.save_nodes(ob);
    out.save_elements(ob);
    std::printf("{\"seconds\": %.6f, \"points\": %d, \"tetrahedra\": %d}\n", t1 - t0,
                out.numberofpoints, out.numberoftetrahedra);
    return 0;
}
