/* fuzz_run.c - shared steps of the PSLG-driven fuzz targets (see fuzz_run.h). */
#include <stdlib.h>

#include "fuzz_run.h"

#define FUZZ_NAME "fuzz_run"
#include "fuzz_require.h"

void *fuzz_alloc(size_t n)
{
    void *p = malloc(n + 1);
    FUZZ_REQUIRE(p != NULL, "out of memory");
    return p;
}

double fuzz_measure(cvm_mesh *m, cvm_measure which)
{
    double v = 0;
    cvm_status s = cvm_mesh_get_measure(&v, m, which);
    FUZZ_REQUIRE(s == CVM_OK, "measure %d: %s", (int)which, cvm_mesh_errmsg(m));
    return v;
}

cvm_mesh *fuzz_pslg_mesh(const fuzz_pslg *g)
{
    cvm_mesh *m = NULL;
    cvm_status s;
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    s = fuzz_pslg_set(m, g);
    FUZZ_REQUIRE(s == CVM_OK, "setting input: %s", cvm_mesh_errmsg(m));
    return m;
}

cvm_status fuzz_triangulate(cvm_mesh *m)
{
    cvm_status s = cvm_mesh_triangulate(m);
    if (s != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(s), "triangulate returned %d", (int)s);
        FUZZ_REQUIRE(cvm_mesh_errmsg(m)[0] != '\0', "status %d without a message", (int)s);
    }
    return s;
}

void fuzz_validate(cvm_mesh *m, const cvmtest_expect *e)
{
    char msg[512];
    cvm_status c = cvm_mesh_check(m);
    FUZZ_REQUIRE(c == CVM_OK, "cvm_mesh_check: %s", cvm_mesh_errmsg(m));
    if (e)
        FUZZ_REQUIRE(cvmtest_mesh_validate(msg, sizeof msg, m, e), "oracle: %s", msg);
}
