/*
 * fuzz_msh_read.c - libFuzzer target: any bytes, parsed as a Gmsh .msh (2.2 or 4.1, ASCII or binary)
 * through an in-memory cvm__reader, give a status and
 * never a crash, a leak or undefined behaviour. Fault injection as in
 * fuzz_poly_read.c (short reads, a read error, one failed allocation,
 * selected by the input size). A successful read must be consistent:
 * finite coordinates, triangle and line indices in range, weights finite;
 * when it is small, it is rebuilt through cvm_mesh_read() of a temporary
 * file, which must give a mesh that passes cvm_mesh_check() (fuzz_mesh_check.h) or an error
 * with a message. The names pass of cvm_mesh_read() runs on the same bytes and faults.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_msh_read"
#include "fuzz_require.h"
#include "fuzz_mesh_check.h"

static void check_mesh(const cvm__vtu_mesh *vm)
{
    size_t i;
    for (i = 0; i < 2 * vm->p.np; i++)
        FUZZ_REQUIRE(isfinite(vm->p.xy[i]), "coordinate %zu is not finite", i);
    for (i = 0; i < 3 * vm->nt; i++)
        FUZZ_REQUIRE(vm->tri[i] >= 0 && (size_t)vm->tri[i] < vm->p.np, "triangle corner %zu", i);
    for (i = 0; i < 2 * vm->p.nseg; i++)
        FUZZ_REQUIRE(vm->p.seg[i] >= 0 && (size_t)vm->p.seg[i] < vm->p.np, "line end %zu", i);
    for (i = 0; vm->w && i < vm->p.np; i++)
        FUZZ_REQUIRE(isfinite(vm->w[i]), "weight %zu is not finite", i);
}

/* Rebuild a small mesh through the public API from a temporary file. */
static void rebuild(const uint8_t *data, size_t size)
{
    char dir[] = "/tmp/fuzz_msh_XXXXXX", path[64];
    cvm_mesh *m = NULL;
    cvm_status s;
    FILE *f;
    if (!mkdtemp(dir))
        return;
    snprintf(path, sizeof path, "%s/m.msh", dir);
    f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size) {
        if (f)
            fclose(f);
        remove(path);
        rmdir(dir);
        return;
    }
    fclose(f);
    if (cvm_mesh_create(&m) != CVM_OK)
        abort();
    s = cvm_mesh_read(m, path);
    remove(path);
    rmdir(dir);
    if (s == CVM_OK) { /* a file without triangles is a domain to triangulate */
        size_t nt = 0;
        FUZZ_REQUIRE(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "count");
        if (nt == 0)
            s = cvm_mesh_triangulate(m);
    }
    if (!cvm_status_is_error(s)) {
        fuzz_require_read_mesh(m);
    } else {
        FUZZ_REQUIRE(cvm_mesh_errmsg(m)[0] != '\0', "status %d without a message", (int)s);
    }
    cvm_mesh_free(m);
}

/* The names pass of cvm_mesh_read() (cvm__read_msh_names), with the same
 * faults: a status with a message, or the names; it fails only where the full
 * read (full_ok) failed, or by an injected fault. */
static void names_only(const uint8_t *data, size_t size, int full_ok)
{
    cvm__ctx ctx;
    cvm__reader r;
    fuzz_input src;
    cvmtest_alloc a;
    cvm__phys_name *names;
    size_t n, k;
    cvm_status s;
    fuzz_input_setup(data, size, &src, &r, &ctx, &a);
    s = cvm__read_msh_names(&ctx, &r, "fuzz.msh", &names, &n);
    if (s == CVM_OK) {
        for (k = 0; k < n; k++)
            FUZZ_REQUIRE(memchr(names[k].name, '\0', sizeof names[k].name) != NULL, "name %zu", k);
        FUZZ_REQUIRE((names == NULL) == (n == 0), "names without a count");
    } else {
        FUZZ_REQUIRE(!full_ok || a.n_failed > 0 || src.failed, "the full read succeeded: %s", ctx.errmsg);
        FUZZ_REQUIRE(ctx.errmsg[0] != '\0', "status %d without a message", (int)s);
        FUZZ_REQUIRE(names == NULL && n == 0, "names not left empty on error");
    }
    cvm__free(&ctx, names);
    FUZZ_REQUIRE(a.live_blocks == 0, "names: %ld blocks leaked (status %d)", a.live_blocks, (int)s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cvm__ctx ctx;
    cvm__vtu_mesh vm;
    cvm__reader r;
    fuzz_input src;
    cvmtest_alloc a;
    cvm_status s;
    fuzz_input_setup(data, size, &src, &r, &ctx, &a);

    s = cvm__read_msh(&ctx, &r, "fuzz.msh", &vm);
    if (s == CVM_OK) {
        FUZZ_REQUIRE(!src.failed, "read error at byte %zu was ignored", src.fail_at);
        check_mesh(&vm);
        if (a.n_failed == 0 && vm.p.np <= 200 && vm.nt <= 400)
            rebuild(data, size);
    } else {
        FUZZ_REQUIRE(cvm_status_is_error(s), "status %d", (int)s);
        FUZZ_REQUIRE(ctx.errmsg[0] != '\0', "status %d without a message", (int)s);
        FUZZ_REQUIRE(s != CVM_E_NOMEM || a.n_failed > 0, "NOMEM with no failed allocation");
        FUZZ_REQUIRE(vm.tri == NULL && vm.p.xy == NULL, "mesh not left empty on error");
    }
    cvm__vtu_mesh_free(&ctx, &vm);
    FUZZ_REQUIRE(a.live_blocks == 0, "%ld blocks leaked (status %d)", a.live_blocks, (int)s);
    names_only(data, size, s == CVM_OK);
    return 0;
}
