// tetgen_shim.cxx - boundary recovery of a cvm__surf3 by TetGen 1.5's tetrahedralize(), as a C function.
//
// The only C++ in the tree. TetGen reports errors by throw int (1 out of
// memory, 2 internal error, 3 self-intersection, 4 feature below tolerance,
// 5 facet-facet overlap, 10 duplicate or degenerate input); every exception
// is caught here and becomes a cvm_status with a message. Every array handed
// to a tetgenio comes from new[] because its destructor delete[]s them.
#define TETLIBRARY
#include <tetgen.h>

#include <cstring>
#include <new>

extern "C" {
#include "tetgen/tetgen_shim.h"
}

namespace {

struct tetgen_failure {
    int code;
};

// Fill in from s (0-based). Throws std::bad_alloc.
void build_input(const cvm__surf3 *s, tetgenio &in)
{
    in.firstnumber = 0;
    in.mesh_dim = 3;
    in.numberofpoints = (int)s->np;
    in.pointlist = new REAL[3 * s->np];
    std::memcpy(in.pointlist, s->xyz, 3 * s->np * sizeof(double));
    in.facetlist = new tetgenio::facet[s->nfacet];
    for (size_t f = 0; f < s->nfacet; f++)
        tetgenio::init(&in.facetlist[f]);
    in.numberoffacets = (int)s->nfacet;
    in.facetmarkerlist = new int[s->nfacet ? s->nfacet : 1];
    size_t k = 0;
    for (size_t f = 0; f < s->nfacet; f++) {
        tetgenio::facet &tf = in.facetlist[f];
        size_t k1 = k;
        while (k1 < s->npoly && (size_t)s->pfacet[k1] == f)
            k1++;
        in.facetmarkerlist[f] = s->fmark[f];
        tf.polygonlist = new tetgenio::polygon[k1 > k ? k1 - k : 1];
        for (size_t j = k; j < k1; j++)
            tetgenio::init(&tf.polygonlist[j - k]);
        tf.numberofpolygons = (int)(k1 - k);
        for (size_t j = k; j < k1; j++) {
            tetgenio::polygon &p = tf.polygonlist[j - k];
            size_t n = (size_t)(s->poff[j + 1] - s->poff[j]);
            p.vertexlist = new int[n ? n : 1];
            p.numberofvertices = (int)n;
            for (size_t c = 0; c < n; c++)
                p.vertexlist[c] = s->pidx[s->poff[j] + c];
        }
        size_t nh = (size_t)(s->fhole_off[f + 1] - s->fhole_off[f]);
        if (nh) {
            tf.holelist = new REAL[3 * nh];
            std::memcpy(tf.holelist, s->fhole + 3 * (size_t)s->fhole_off[f], 3 * nh * sizeof(double));
            tf.numberofholes = (int)nh;
        }
        k = k1;
    }
    if (s->nholes) {
        in.holelist = new REAL[3 * s->nholes];
        std::memcpy(in.holelist, s->holes, 3 * s->nholes * sizeof(double));
        in.numberofholes = (int)s->nholes;
    }
    if (s->nregions) {
        in.regionlist = new REAL[5 * s->nregions];
        std::memcpy(in.regionlist, s->regions, 5 * s->nregions * sizeof(double));
        in.numberofregions = (int)s->nregions;
    }
}

// One run of tetrahedralize(); a status, with TetGen's code in *code when it threw an int.
cvm_status run(cvm__ctx *ctx, const cvm__surf3 *s, const char *switches, tetgenio &out, int *code)
{
    *code = 0;
    try {
        tetgenio in;
        char sw[16];
        std::strncpy(sw, switches, sizeof sw - 1);
        sw[sizeof sw - 1] = '\0';
        build_input(s, in);
        tetrahedralize(sw, &in, &out);
        return CVM_OK;
    } catch (int e) {
        *code = e;
        return CVM_E_INTERNAL;
    } catch (std::bad_alloc &) {
        return cvm__error(ctx, CVM_E_NOMEM, CVM_ENT_NONE, -1, "out of memory inside TetGen");
    } catch (...) {
        return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "TetGen threw an unexpected exception");
    }
}

cvm_status code_error(cvm__ctx *ctx, const cvm__surf3 *s, int code)
{
    const char *file = s->file ? s->file : "the surface";
    switch (code) {
    case 1:
        return cvm__error(ctx, CVM_E_NOMEM, CVM_ENT_NONE, -1, "TetGen ran out of memory on %s", file);
    case 3:
        return cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_NONE, -1,
                          "TetGen found self-intersecting facets in %s (its code 3)", file);
    case 5:
        return cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_NONE, -1,
                          "TetGen found two overlapping facets in %s (its code 5)", file);
    case 4:
        return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                          "TetGen found an input feature below its tolerance in %s (its code 4)", file);
    case 10:
        return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_NONE, -1,
                          "TetGen found duplicate or degenerate input in %s (its code 10)", file);
    default:
        return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                          "TetGen failed with its internal error code %d on %s", code, file);
    }
}

// Copy TetGen's output through the ctx allocator.
cvm_status copy_out(cvm__ctx *ctx, const cvm__surf3 *s, const tetgenio &o, cvm__tet3_out *out)
{
    size_t np = (size_t)o.numberofpoints, nt = (size_t)o.numberoftetrahedra, nf = (size_t)o.numberoftrifaces;
    int base = o.firstnumber;
    if (np < s->np || o.numberofcorners != 4 ||
        std::memcmp(o.pointlist, s->xyz, 3 * s->np * sizeof(double)) != 0)
        return cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                          "TetGen's output does not start with the %lu input points in order",
                          (unsigned long)s->np);
    out->xyz = (double *)cvm__malloc(ctx, 3 * np * sizeof(double));
    out->tet = (int32_t *)cvm__malloc(ctx, (nt ? 4 * nt : 1) * sizeof(int32_t));
    out->face = (int32_t *)cvm__malloc(ctx, (nf ? 3 * nf : 1) * sizeof(int32_t));
    out->fmark = (int32_t *)cvm__malloc(ctx, (nf ? nf : 1) * sizeof(int32_t));
    if (s->nregions && o.numberoftetrahedronattributes > 0)
        out->tattr = (double *)cvm__malloc(ctx, (nt ? nt : 1) * sizeof(double));
    if (!out->xyz || !out->tet || !out->face || !out->fmark ||
        (s->nregions && o.numberoftetrahedronattributes > 0 && !out->tattr))
        return cvm__nomem(ctx);
    std::memcpy(out->xyz, o.pointlist, 3 * np * sizeof(double));
    out->np = np;
    out->n_input = s->np;
    for (size_t i = 0; i < 4 * nt; i++)
        out->tet[i] = o.tetrahedronlist[i] - base;
    out->ntet = nt;
    for (size_t i = 0; i < 3 * nf; i++)
        out->face[i] = o.trifacelist[i] - base;
    for (size_t i = 0; i < nf; i++)
        out->fmark[i] = o.trifacemarkerlist ? o.trifacemarkerlist[i] : 0;
    out->nface = nf;
    if (out->tattr)
        for (size_t i = 0; i < nt; i++)
            out->tattr[i] = o.tetrahedronattributelist[i * (size_t)o.numberoftetrahedronattributes];
    return CVM_OK;
}

} // namespace

extern "C" int cvm__tetgen_available(void)
{
    return 1;
}

extern "C" cvm_status cvm__tetgen_recover(cvm__ctx *ctx, const cvm__surf3 *s, cvm__tet3_out *out)
{
    std::memset(out, 0, sizeof *out);
    if (s->np > (size_t)INT32_MAX / 4 || s->nfacet > (size_t)INT32_MAX / 4)
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1, "the surface is too large for TetGen");
    int code = 0;
    int kept = 1;
    cvm_status st;
    try {
        tetgenio o;
        st = run(ctx, s, s->nregions ? "pYAQ" : "pYQ", o, &code);
        if (st == CVM_E_INTERNAL && code != 0 && code != 1 && code != 3 && code != 5) {
            // The boundary cannot be kept as it is: let TetGen split it.
            tetgenio o2;
            kept = 0;
            st = run(ctx, s, s->nregions ? "pAQ" : "pQ", o2, &code);
            if (st == CVM_OK)
                st = copy_out(ctx, s, o2, out);
        } else if (st == CVM_OK) {
            st = copy_out(ctx, s, o, out);
        }
    } catch (std::bad_alloc &) {
        st = cvm__error(ctx, CVM_E_NOMEM, CVM_ENT_NONE, -1, "out of memory inside TetGen");
    } catch (...) {
        st = cvm__error(ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1, "TetGen threw an unexpected exception");
    }
    if (st == CVM_E_INTERNAL && code)
        st = code_error(ctx, s, code);
    if (st == CVM_OK)
        st = cvm__tet3_finish(ctx, out);
    if (st) {
        cvm__tet3_out_free(ctx, out);
        return st;
    }
    out->boundary_kept = kept;
    return CVM_OK;
}
