/*
 * cvmesh_numpy.i - the numpy typemaps of the cvmesh binding: the few array
 * shapes that include/cvmesh.h uses, written for this project (numpy's own
 * numpy.i is not shipped in numpy wheels and Debian's copy does not build
 * with SWIG >= 4.3).
 *
 * Inputs (copied by the library, so a temporary contiguous array is enough):
 *   (const double *coords, size_t count, int dim)    (n, d) float64 points
 *   (const double *attrs, size_t count, size_t nattr) (n, k) float64 attributes
 *   (const double *xy, size_t count)                  (k, 2) float64 points
 *   (const double *r, size_t count)                   (k, 4) float64 regions
 *   (const double *r, size_t count, int dim)          (k, d + 2) float64 regions
 *   (const double *x, int dim)                        (d,) float64 point
 *   (const double *ends, int dim)                     (2, d) float64 segment ends
 *   (const double *corners, int dim)                  (3, d) float64 triangle corners
 *   (const cvm_index *segs, size_t count)             (m, 2) integer pairs
 *   (const cvm_index *tets, size_t count)             (m, 4) integer tetrahedra
 *   const double *tet_attr                            None or (m,) float64
 *   (const int32_t *markers, size_t count)            (n,) integers
 * Any array-like is accepted; it is converted without a Python loop. Integer
 * arrays of another width are range-checked, never wrapped around. An empty
 * array is passed as (NULL, 0), as C callers do to remove an input.
 *
 * Outputs, "count then copy": the Python argument is the capacity (an int;
 * a new array of that length is created here) or an existing writable
 * C-contiguous array of the exact dtype, which is filled. The array is returned.
 *   (double *dst, size_t dst_len)      float64
 *   (cvm_index *dst, size_t dst_len)   int32
 *   (int32_t *dst, size_t dst_len)     int32
 *   (offsets, offsets_len), (types, types_len), (conn, conn_len)   int32, in that order
 *
 * Every typemap returns its output only when the call did not fail
 * ($result is NULL after an error status; see cvmesh.i) and releases its
 * arrays in "freearg", so no path leaks a reference.
 */

%{
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <limits.h>

/* Append obj (a new reference, or NULL after a failed conversion) to the
 * result of a wrapper: None is replaced by obj, a second value turns the
 * result into a list. Returns NULL with an exception set when obj is NULL.
 * (SWIG_Python_AppendOutput changed its signature and its handling of None
 * in SWIG 4.3; this keeps both versions alike.) */
static PyObject *cvmpy_append(PyObject *result, PyObject *obj)
{
    if (!obj) {
        Py_XDECREF(result);
        return NULL;
    }
    if (!result || result == Py_None) {
        Py_XDECREF(result);
        return obj;
    }
    if (!PyList_Check(result)) {
        PyObject *list = PyList_New(1);
        if (!list) {
            Py_DECREF(result);
            Py_DECREF(obj);
            return NULL;
        }
        PyList_SET_ITEM(list, 0, result);
        result = list;
    }
    if (PyList_Append(result, obj) < 0) {
        Py_DECREF(result);
        result = NULL;
    }
    Py_DECREF(obj);
    return result;
}
%}

%init %{
    import_array();
%}

%fragment("cvmpy_numpy", "header") %{
/* "(5, 3)" for the shape of a, into buf. */
static const char *cvmpy_shape_str(char *buf, size_t len, PyArrayObject *a)
{
    int nd = PyArray_NDIM(a);
    if (nd == 0)
        snprintf(buf, len, "a scalar");
    else if (nd == 1)
        snprintf(buf, len, "shape (%ld,)", (long)PyArray_DIM(a, 0));
    else if (nd == 2)
        snprintf(buf, len, "shape (%ld, %ld)", (long)PyArray_DIM(a, 0), (long)PyArray_DIM(a, 1));
    else
        snprintf(buf, len, "%d dimensions", nd);
    return buf;
}

/*
 * Check that a has 2 dimensions with ncols columns (ncols < 0: any), or
 * 1 dimension when ncols == 0. An empty 1-D array stands for zero rows.
 * Sets ValueError naming what and returns 0 when it does not fit.
 */
static int cvmpy_check_shape(PyArrayObject *a, npy_intp ncols, const char *what)
{
    char got[64];
    if (ncols == 0) {
        if (PyArray_NDIM(a) == 1)
            return 1;
        PyErr_Format(PyExc_ValueError, "%s must be a 1-D array, got %s", what,
                     cvmpy_shape_str(got, sizeof got, a));
        return 0;
    }
    if (PyArray_NDIM(a) == 1 && PyArray_DIM(a, 0) == 0)
        return 1;
    if (PyArray_NDIM(a) == 2 && (ncols < 0 || PyArray_DIM(a, 1) == ncols))
        return 1;
    if (ncols < 0)
        PyErr_Format(PyExc_ValueError, "%s must be a 2-D array of shape (n, d), got %s", what,
                     cvmpy_shape_str(got, sizeof got, a));
    else
        PyErr_Format(PyExc_ValueError, "%s must have shape (n, %ld), got %s", what, (long)ncols,
                     cvmpy_shape_str(got, sizeof got, a));
    return 0;
}

/* Rows of a checked array (0 for an empty 1-D stand-in). */
static size_t cvmpy_rows(PyArrayObject *a)
{
    return PyArray_NDIM(a) == 0 ? 0 : (size_t)PyArray_DIM(a, 0);
}

/* Columns of a checked 2-D array (0 for an empty 1-D stand-in). */
static size_t cvmpy_cols(PyArrayObject *a)
{
    return PyArray_NDIM(a) == 2 ? (size_t)PyArray_DIM(a, 1) : 0;
}

/* New reference: obj as an aligned C-contiguous float64 array of the given
 * column count (see cvmpy_check_shape), or NULL with an exception set. */
static PyArrayObject *cvmpy_in_double(PyObject *obj, npy_intp ncols, const char *what)
{
    PyArrayObject *a;
    if (obj == Py_None) {
        PyErr_Format(PyExc_TypeError, "%s must be an array, not None", what);
        return NULL;
    }
    a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!a) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be an array of real numbers", what);
        return NULL;
    }
    if (!cvmpy_check_shape(a, ncols, what)) {
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

/* New reference: obj as an aligned C-contiguous int32 array (shape rules of
 * cvmpy_check_shape). Other integer widths are range-checked first, so a
 * value that does not fit in 32 bits raises OverflowError naming its
 * position instead of wrapping around; floats and bools are refused. */
static PyArrayObject *cvmpy_in_int32(PyObject *obj, npy_intp ncols, const char *what)
{
    PyArrayObject *a, *wide;
    PyArray_Descr *d;
    npy_intp i, n;
    const npy_int64 *v;
    if (obj == Py_None) {
        PyErr_Format(PyExc_TypeError, "%s must be an array, not None", what);
        return NULL;
    }
    if (PyArray_Check(obj)) {
        d = PyArray_DESCR((PyArrayObject *)obj);
        if (!PyTypeNum_ISINTEGER(d->type_num) && !(PyArray_SIZE((PyArrayObject *)obj) == 0)) {
            PyErr_Format(PyExc_TypeError, "%s must be an integer array, got dtype %s", what,
                         d->typeobj->tp_name);
            return NULL;
        }
        if (d->type_num == NPY_INT32 || PyArray_SIZE((PyArrayObject *)obj) == 0) {
            a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_INT32, 0, 0,
                                                 NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST);
            if (a && !cvmpy_check_shape(a, ncols, what)) {
                Py_DECREF(a);
                return NULL;
            }
            return a;
        }
    }
    wide = (PyArrayObject *)PyArray_FROMANY(obj, NPY_INT64, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!wide) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be an array of integers", what);
        return NULL;
    }
    if (!cvmpy_check_shape(wide, ncols, what)) {
        Py_DECREF(wide);
        return NULL;
    }
    n = PyArray_SIZE(wide);
    v = (const npy_int64 *)PyArray_DATA(wide);
    for (i = 0; i < n; i++) {
        if (v[i] < INT32_MIN || v[i] > INT32_MAX) {
            npy_intp w = PyArray_NDIM(wide) == 2 ? PyArray_DIM(wide, 1) : 1;
            if (PyArray_NDIM(wide) == 2)
                PyErr_Format(PyExc_OverflowError, "%s[%ld, %ld] = %lld does not fit in 32 bits",
                             what, (long)(i / w), (long)(i % w), (long long)v[i]);
            else
                PyErr_Format(PyExc_OverflowError, "%s[%ld] = %lld does not fit in 32 bits", what,
                             (long)i, (long long)v[i]);
            Py_DECREF(wide);
            return NULL;
        }
    }
    a = (PyArrayObject *)PyArray_FROMANY((PyObject *)wide, NPY_INT32, 0, 0,
                                         NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST);
    Py_DECREF(wide);
    return a;
}

/* New reference to the output array for a (dst, dst_len) pair: obj is a
 * capacity (a new zeroed 1-D array of that length) or an existing writable,
 * aligned, C-contiguous array of exactly typenum, which is used as is. */
static PyArrayObject *cvmpy_out_array(PyObject *obj, int typenum, const char *what)
{
    if (PyLong_Check(obj) || PyArray_IsScalar(obj, Integer)) {
        npy_intp n = (npy_intp)PyLong_AsSsize_t(obj);
        if (n == -1 && PyErr_Occurred())
            return NULL;
        if (n < 0) {
            PyErr_Format(PyExc_ValueError, "%s: capacity must be >= 0, got %ld", what, (long)n);
            return NULL;
        }
        return (PyArrayObject *)PyArray_ZEROS(1, &n, typenum, 0);
    }
    if (PyArray_Check(obj)) {
        PyArrayObject *a = (PyArrayObject *)obj;
        if (PyArray_TYPE(a) != typenum || !PyArray_ISCARRAY(a)) {
            PyArray_Descr *want = PyArray_DescrFromType(typenum);
            PyErr_Format(PyExc_TypeError,
                         "%s: an output array must be writable, C-contiguous and of dtype %s",
                         what, want ? want->typeobj->tp_name : "?");
            Py_XDECREF(want);
            return NULL;
        }
        Py_INCREF(a);
        return a;
    }
    PyErr_Format(PyExc_TypeError, "%s: expected a capacity (int) or a numpy array", what);
    return NULL;
}
%}

/* ---- inputs ------------------------------------------------------------ */

%typemap(in, fragment="cvmpy_numpy") (const double *coords, size_t count, int dim)
    (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "points");
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (double *)PyArray_DATA(arr) : NULL;
    $3 = $2 ? (int)cvmpy_cols(arr) : 2;
}
%typemap(freearg) (const double *coords, size_t count, int dim) { Py_XDECREF(arr$argnum); }

%typemap(in, fragment="cvmpy_numpy") (const double *attrs, size_t count, size_t nattr)
    (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "attributes");
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (double *)PyArray_DATA(arr) : NULL;
    $3 = cvmpy_cols(arr);
}
%typemap(freearg) (const double *attrs, size_t count, size_t nattr) { Py_XDECREF(arr$argnum); }

/* Regions in the mesh's dimension: (k, dim + 2) rows (point, attribute, max measure). */
%typemap(in, fragment="cvmpy_numpy") (const double *r, size_t count, int dim)
    (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "regions");
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (double *)PyArray_DATA(arr) : NULL;
    $3 = $2 ? (int)cvmpy_cols(arr) - 2 : 2;
}
%typemap(freearg) (const double *r, size_t count, int dim) { Py_XDECREF(arr$argnum); }

/* One point in the mesh's dimension: a 1-D array of dim coordinates. */
%typemap(in, fragment="cvmpy_numpy") (const double *x, int dim) (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, 0, "x");
    if (!arr)
        SWIG_fail;
    $1 = (double *)PyArray_DATA(arr);
    $2 = (int)PyArray_DIM(arr, 0);
}
%typemap(freearg) (const double *x, int dim) { Py_XDECREF(arr$argnum); }

/* The two ends of a line source: a (2, dim) array. */
%typemap(in, fragment="cvmpy_numpy") (const double *ends, int dim) (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "ends");
    if (!arr)
        SWIG_fail;
    if (cvmpy_rows(arr) != 2) {
        PyErr_SetString(PyExc_ValueError, "ends must have shape (2, dim)");
        SWIG_fail;
    }
    $1 = (double *)PyArray_DATA(arr);
    $2 = (int)cvmpy_cols(arr);
}
%typemap(freearg) (const double *ends, int dim) { Py_XDECREF(arr$argnum); }

/* The three corners of a triangle source: a (3, dim) array. */
%typemap(in, fragment="cvmpy_numpy") (const double *corners, int dim) (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "corners");
    if (!arr)
        SWIG_fail;
    if (cvmpy_rows(arr) != 3) {
        PyErr_SetString(PyExc_ValueError, "corners must have shape (3, dim)");
        SWIG_fail;
    }
    $1 = (double *)PyArray_DATA(arr);
    $2 = (int)cvmpy_cols(arr);
}
%typemap(freearg) (const double *corners, int dim) { Py_XDECREF(arr$argnum); }

/* A background mesh in the mesh's dimension (cvmpy_sizing_set_background_nd):
 * nodes (n, dim + 1) float64 and cells (m, dim + 1) int32, each with its
 * column count for the helper to check. */
%typemap(in, fragment="cvmpy_numpy") (const double *bg_xh, size_t bg_n, int bg_cols)
    (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_double($input, -1, "background nodes");
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (double *)PyArray_DATA(arr) : NULL;
    $3 = (int)cvmpy_cols(arr);
}
%typemap(freearg) (const double *bg_xh, size_t bg_n, int bg_cols) { Py_XDECREF(arr$argnum); }
%typemap(in, fragment="cvmpy_numpy") (const cvm_index *bg_cells, size_t bg_nc, int bg_ccols)
    (PyArrayObject *arr = NULL) {
    arr = cvmpy_in_int32($input, -1, "background cells");
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (cvm_index *)PyArray_DATA(arr) : NULL;
    $3 = (int)cvmpy_cols(arr);
}
%typemap(freearg) (const cvm_index *bg_cells, size_t bg_nc, int bg_ccols) { Py_XDECREF(arr$argnum); }

/* CVMPY_IN_ROWS(CTYPE, NAME, CONVERT, NCOLS, WHAT): (const CTYPE *NAME, size_t count). */
%define CVMPY_IN_ROWS(CTYPE, NAME, CONVERT, NCOLS, WHAT)
%typemap(in, fragment="cvmpy_numpy") (const CTYPE *NAME, size_t count) (PyArrayObject *arr = NULL) {
    arr = CONVERT($input, NCOLS, WHAT);
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (CTYPE *)PyArray_DATA(arr) : NULL; /* empty: NULL, as C callers pass */
}
%typemap(freearg) (const CTYPE *NAME, size_t count) { Py_XDECREF(arr$argnum); }
%enddef

CVMPY_IN_ROWS(double, xy, cvmpy_in_double, 2, "xy")
CVMPY_IN_ROWS(double, r, cvmpy_in_double, 4, "regions")
CVMPY_IN_ROWS(cvm_index, segs, cvmpy_in_int32, 2, "segments")
CVMPY_IN_ROWS(int32_t, markers, cvmpy_in_int32, 0, "markers")
CVMPY_IN_ROWS(double, w, cvmpy_in_double, 0, "weights")
CVMPY_IN_ROWS(cvm_index, tets, cvmpy_in_int32, 4, "tetrahedra")

/* const double *tet_attr: None (NULL) or float64 values; the Python wrapper checks
 * that there is one per tetrahedron. */
%typemap(in, fragment="cvmpy_numpy") const double *tet_attr (PyArrayObject *arr = NULL) {
    if ($input == Py_None) {
        $1 = NULL;
    } else {
        arr = cvmpy_in_double($input, 0, "tetrahedron attributes");
        if (!arr)
            SWIG_fail;
        $1 = (double *)PyArray_DATA(arr);
    }
}
%typemap(freearg) const double *tet_attr { Py_XDECREF(arr$argnum); }

/* CVMPY_IN_ROWS_N: the same with another name for the count. */
%define CVMPY_IN_ROWS_N(CTYPE, NAME, COUNT, CONVERT, NCOLS, WHAT)
%typemap(in, fragment="cvmpy_numpy") (const CTYPE *NAME, size_t COUNT) (PyArrayObject *arr = NULL) {
    arr = CONVERT($input, NCOLS, WHAT);
    if (!arr)
        SWIG_fail;
    $2 = cvmpy_rows(arr);
    $1 = $2 ? (CTYPE *)PyArray_DATA(arr) : NULL;
}
%typemap(freearg) (const CTYPE *NAME, size_t COUNT) { Py_XDECREF(arr$argnum); }
%enddef

CVMPY_IN_ROWS_N(double, xyh, npoints, cvmpy_in_double, 3, "background nodes (x, y, size)")
CVMPY_IN_ROWS_N(cvm_index, tri, ntri, cvmpy_in_int32, 3, "background triangles")

/* ---- outputs: count then copy ----------------------------------------- */

/* CVMPY_OUT_ARRAY(CTYPE, NPYTYPE): (CTYPE *dst, size_t dst_len). */
%define CVMPY_OUT_ARRAY(CTYPE, NPYTYPE)
%typemap(in, fragment="cvmpy_numpy") (CTYPE *dst, size_t dst_len) (PyArrayObject *arr = NULL) {
    arr = cvmpy_out_array($input, NPYTYPE, "$symname");
    if (!arr)
        SWIG_fail;
    $1 = (CTYPE *)PyArray_DATA(arr);
    $2 = (size_t)PyArray_SIZE(arr);
}
%typemap(argout) (CTYPE *dst, size_t dst_len) {
    if ($result) {
        $result = cvmpy_append($result, (PyObject *)arr$argnum);
        arr$argnum = NULL;
    }
}
%typemap(freearg) (CTYPE *dst, size_t dst_len) { Py_XDECREF(arr$argnum); }
%enddef

CVMPY_OUT_ARRAY(double, NPY_DOUBLE)
CVMPY_OUT_ARRAY(cvm_index, NPY_INT32)
CVMPY_OUT_ARRAY(int32_t, NPY_INT32)

/* CVMPY_OUT_ARRAY_N(CTYPE, NAME, LEN, NPYTYPE): (CTYPE *NAME, size_t LEN), for calls
 * with several output arrays (cvm_mesh_copy_cells_mixed); returned in order. */
%define CVMPY_OUT_ARRAY_N(CTYPE, NAME, LEN, NPYTYPE)
%typemap(in, fragment="cvmpy_numpy") (CTYPE *NAME, size_t LEN) (PyArrayObject *arr = NULL) {
    arr = cvmpy_out_array($input, NPYTYPE, "$symname");
    if (!arr)
        SWIG_fail;
    $1 = (CTYPE *)PyArray_DATA(arr);
    $2 = (size_t)PyArray_SIZE(arr);
}
%typemap(argout) (CTYPE *NAME, size_t LEN) {
    if ($result) {
        $result = cvmpy_append($result, (PyObject *)arr$argnum);
        arr$argnum = NULL;
    }
}
%typemap(freearg) (CTYPE *NAME, size_t LEN) { Py_XDECREF(arr$argnum); }
%enddef

CVMPY_OUT_ARRAY_N(cvm_index, offsets, offsets_len, NPY_INT32)
CVMPY_OUT_ARRAY_N(int32_t, types, types_len, NPY_INT32)
CVMPY_OUT_ARRAY_N(cvm_index, conn, conn_len, NPY_INT32)

/* Read-only views are returned as (n, 2) copies: a view into the handle
 * would dangle after the next call that modifies it. */
%typemap(in, numinputs=0) (const double **ptr_out, size_t *count_out)
    (const double *ptr = NULL, size_t cnt = 0) {
    $1 = ($1_ltype)&ptr;
    $2 = &cnt;
}
%typemap(argout, fragment="cvmpy_numpy") (const double **ptr_out, size_t *count_out) {
    if ($result) {
        npy_intp dims[2];
        PyArrayObject *a;
        dims[0] = (npy_intp)cnt$argnum;
        dims[1] = 2;
        a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
        if (a && cnt$argnum)
            memcpy(PyArray_DATA(a), ptr$argnum, 2 * cnt$argnum * sizeof(double));
        $result = cvmpy_append($result, (PyObject *)a);
    }
}

/* The same in the mesh's dimension: an (n, dim) copy, and dim itself is in its shape. */
%typemap(in, numinputs=0) (const double **ptr_out, size_t *count_out, int32_t *dim_out)
    (const double *ptr = NULL, size_t cnt = 0, int32_t dim = 0) {
    $1 = ($1_ltype)&ptr;
    $2 = &cnt;
    $3 = &dim;
}
%typemap(argout, fragment="cvmpy_numpy") (const double **ptr_out, size_t *count_out,
                                          int32_t *dim_out) {
    if ($result) {
        npy_intp dims[2];
        PyArrayObject *a;
        dims[0] = (npy_intp)cnt$argnum;
        dims[1] = (npy_intp)dim$argnum;
        a = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
        if (a && cnt$argnum)
            memcpy(PyArray_DATA(a), ptr$argnum, (size_t)dims[0] * (size_t)dims[1] * sizeof(double));
        $result = cvmpy_append($result, (PyObject *)a);
    }
}
