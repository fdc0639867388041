/* status.c - version numbers and the fixed text of each status code. */
#include "api_internal.h"

int32_t cvm_version_number(void)
{
    return CVM_VERSION_NUMBER;
}

#define CVM__STR2(x) #x
#define CVM__STR(x) CVM__STR2(x)

const char *cvm_version_string(void)
{
    return CVM__STR(CVM_VERSION_MAJOR) "." CVM__STR(CVM_VERSION_MINOR) "." CVM__STR(CVM_VERSION_PATCH);
}

#ifdef CVM_WITH_TETGEN
#define CVM__BUILD_TETGEN "; TetGen 1.5 boundary recovery (AGPL-3+ build)"
#else
#define CVM__BUILD_TETGEN "; no TetGen (BSD-3-Clause build)"
#endif
#ifdef _OPENMP
#define CVM__BUILD_OPENMP "; OpenMP"
#else
#define CVM__BUILD_OPENMP "; no OpenMP"
#endif

const char *cvm_build_string(void)
{
    return "cvmesh " CVM__STR(CVM_VERSION_MAJOR) "." CVM__STR(CVM_VERSION_MINOR) "." CVM__STR(
        CVM_VERSION_PATCH) CVM__BUILD_TETGEN CVM__BUILD_OPENMP;
}

const char *cvm_status_str(cvm_status s)
{
    switch (s) {
    case CVM_OK: return "ok";
    case CVM_E_NULL_ARG: return "a required argument is NULL";
    case CVM_E_ARGUMENT: return "invalid argument";
    case CVM_E_OPTION_KEY: return "unknown option key";
    case CVM_E_OPTION_RANGE: return "option value out of range";
    case CVM_E_STATE: return "call made in the wrong state";
    case CVM_E_UNSUPPORTED: return "unsupported";
    case CVM_E_INPUT_NONFINITE: return "input has a NaN or infinite value";
    case CVM_E_INPUT_INDEX: return "input index out of range";
    case CVM_E_INPUT_DUPLICATE: return "duplicate input points";
    case CVM_E_INPUT_DEGENERATE: return "degenerate input";
    case CVM_E_INPUT_INTERSECTING: return "input segments intersect";
    case CVM_E_INPUT_NOT_CLOSED: return "boundary is not closed";
    case CVM_E_INPUT_EMPTY: return "input is empty";
    case CVM_E_INPUT_OUTSIDE: return "seed point outside the domain";
    case CVM_E_IO_OPEN: return "cannot open file";
    case CVM_E_IO_READ: return "read error";
    case CVM_E_IO_WRITE: return "write error";
    case CVM_E_IO_FORMAT: return "malformed file";
    case CVM_E_NOMEM: return "out of memory";
    case CVM_E_BUFFER_TOO_SMALL: return "buffer too small";
    case CVM_E_TOO_LARGE: return "input too large";
    case CVM_E_INTERNAL: return "internal error";
    case CVM_INCOMPLETE_TIME_LIMIT: return "stopped at the time limit";
    case CVM_INCOMPLETE_CANCELLED: return "cancelled";
    case CVM_INCOMPLETE_STEINER_LIMIT: return "stopped at the Steiner point limit";
    }
    return "unknown status";
}

int cvm_status_is_error(cvm_status s)
{
    return (int)s >= 1 && (int)s <= 99;
}
