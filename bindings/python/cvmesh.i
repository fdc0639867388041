/*
 * cvmesh.i - SWIG interface that wraps include/cvmesh.h as the Python module
 * cvmesh.capi; the Pythonic layer (cvmesh/__init__.py) is built on it.
 *
 * The header is wrapped whole (%include at the end), so a new public function
 * appears in Python without a change here as long as it follows the house
 * conventions (STYLE.md sections 2, 4, 6):
 *   - it returns cvm_status: an error raises a cvmesh.Error subclass carrying
 *     the message of its handle (cvm_mesh_errmsg(), cvm_sizing_errmsg()); OK
 *     returns None or its outputs; an incomplete status (>= 100) emits
 *     cvmesh.IncompleteWarning;
 *   - its handle parameter is named as the argout typemaps below expect
 *     (cvm_mesh *m, cvm_sizing *s), and its outputs come first with the names
 *     typemapped here (out, *_out, dst + dst_len) or in cvmesh_numpy.i;
 *   - a call that reports progress is listed with CVMPY_LONG_CALL: it releases
 *     the GIL and returns its status as an int (0 or >= 100) before its outputs.
 * What needs a line here: a new handle type (its argout and CVMPY_HANDLE_OUT),
 * a function with a handle parameter that does not return cvm_status (a
 * helper, as for the _free and _errmsg functions), a C callback (a trampoline,
 * as for progress and sizing callbacks), a new input shape (cvmesh_numpy.i).
 */
%module(package="cvmesh") capi

%feature("autodoc", "1");

%{
#include "cvmesh.h"
#include <string.h>
%}

%include <stdint.i>
%include "cvmesh_numpy.i"

/* ---- status -> exception ---------------------------------------------- */

%{
/* cvmesh._errors._from_status(status, message, kind, index): an exception
 * instance of the class for that status family. */
static PyObject *cvmpy_errors_module = NULL;

static PyObject *cvmpy_errors(void)
{
    if (!cvmpy_errors_module)
        cvmpy_errors_module = PyImport_ImportModule("cvmesh._errors");
    return cvmpy_errors_module;
}

/* Raise the exception for error status s with message msg (cvm_status_str(s)
 * when msg is NULL or empty) naming input item (kind, index). */
static void cvmpy_raise(cvm_status s, const char *msg, cvm_entity kind, int64_t index)
{
    PyObject *mod, *exc;
    if (!msg || !*msg)
        msg = cvm_status_str(s);
    mod = cvmpy_errors();
    if (!mod) {
        PyErr_Clear();
        PyErr_Format(PyExc_RuntimeError, "cvmesh status %d: %s", (int)s, msg);
        return;
    }
    exc = PyObject_CallMethod(mod, "_from_status", "isiL", (int)s, msg, (int)kind,
                              (long long)index);
    if (!exc)
        return; /* the exception of the failed call stands */
    PyErr_SetObject((PyObject *)Py_TYPE(exc), exc);
    Py_DECREF(exc);
}

/* Raise the exception for error status s of a call on mesh m (may be NULL). */
static void cvmpy_set_error(cvm_status s, const cvm_mesh *m)
{
    cvm_entity kind = CVM_ENT_NONE;
    int64_t index = -1;
    if (m && cvm_mesh_error_item(&kind, &index, m) != CVM_OK) {
        kind = CVM_ENT_NONE;
        index = -1;
    }
    cvmpy_raise(s, m ? cvm_mesh_errmsg(m) : NULL, kind, index);
}

/* Python result of a call that returned s, or NULL with an exception set.
 * An error leaves NULL *without* an exception: the argout typemap of the
 * handle (which knows cvm_mesh_errmsg) or the "ret" typemap raises it.
 * An exception already pending (raised by the progress callback, e.g.
 * KeyboardInterrupt) wins over everything. */
static PyObject *cvmpy_status_result(cvm_status s, int long_call)
{
    if (PyErr_Occurred())
        return NULL;
    if (cvm_status_is_error(s))
        return NULL;
    if (long_call)
        return PyLong_FromLong((long)s);
    if (s != CVM_OK) {
        PyObject *mod = cvmpy_errors();
        PyObject *cls = mod ? PyObject_GetAttrString(mod, "IncompleteWarning") : NULL;
        int bad;
        if (!cls)
            return NULL;
        bad = PyErr_WarnFormat(cls, 1, "%s", cvm_status_str(s));
        Py_DECREF(cls);
        if (bad)
            return NULL;
    }
    Py_RETURN_NONE;
}
%}

%typemap(out) cvm_status {
    $result = cvmpy_status_result($1, 0);
}
/* Raise a status error that no handle argument has raised yet. */
%typemap(ret) cvm_status {
    if (!$result && !PyErr_Occurred())
        cvmpy_set_error($1, NULL);
}
/* The handle knows the message: raise here, after the call. */
%typemap(argout) cvm_mesh *m, const cvm_mesh *m {
    if (!$result && !PyErr_Occurred() && cvm_status_is_error(result))
        cvmpy_set_error(result, $1);
}
%typemap(argout) cvm_sizing *s, const cvm_sizing *s {
    if (!$result && !PyErr_Occurred() && cvm_status_is_error(result))
        cvmpy_raise(result, cvm_sizing_errmsg($1), CVM_ENT_NONE, -1);
}

/* CVMPY_NOGIL(name): release the GIL around the call (it must not touch
 * Python objects; a C callback it makes re-acquires the GIL).
 * CVMPY_LONG_CALL(name): the same, and return the status as an int, for the
 * calls that report progress and can stop early. Naming a function that the
 * header does not declare is harmless. */
%define CVMPY_NOGIL(NAME)
%exception NAME {
    Py_BEGIN_ALLOW_THREADS
    $action
    Py_END_ALLOW_THREADS
}
%enddef
%define CVMPY_LONG_CALL(NAME)
CVMPY_NOGIL(NAME)
%typemap(out) cvm_status NAME {
    $result = cvmpy_status_result($1, 1);
}
%enddef

CVMPY_LONG_CALL(cvm_mesh_triangulate)
CVMPY_LONG_CALL(cvm_mesh_refine)
CVMPY_LONG_CALL(cvm_mesh_optimise_dual)
CVMPY_LONG_CALL(cvm_mesh_generate3)
CVMPY_LONG_CALL(cvm_mesh_generate3_sized)
CVMPY_LONG_CALL(cvm_mesh_optimise_dual3)
CVMPY_LONG_CALL(cvm_mesh_quadmesh)
CVMPY_LONG_CALL(cvm_mesh_read)
CVMPY_LONG_CALL(cvm_mesh_write)
CVMPY_LONG_CALL(cvm_mesh_stage_write)
CVMPY_LONG_CALL(cvm_mesh_stage_write_dual)
CVMPY_LONG_CALL(cvm_mesh_check)
CVMPY_NOGIL(cvm_mesh_set_weights)

/* ---- scalar outputs ---------------------------------------------------- */

/* CVMPY_OUT_SCALAR(CTYPE, NAME, TO_PY): CTYPE *NAME becomes a return value. */
%define CVMPY_OUT_SCALAR(CTYPE, NAME, TO_PY)
%typemap(in, numinputs=0) CTYPE *NAME (CTYPE tmp) {
    memset(&tmp, 0, sizeof tmp);
    $1 = &tmp;
}
%typemap(argout) CTYPE *NAME {
    if ($result) {
        $result = cvmpy_append($result, TO_PY(tmp$argnum));
    }
}
%enddef

CVMPY_OUT_SCALAR(size_t, out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, nattr_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(double, out, PyFloat_FromDouble)
CVMPY_OUT_SCALAR(int64_t, index_out, PyLong_FromLongLong)
CVMPY_OUT_SCALAR(cvm_entity, kind_out, PyLong_FromLong)
CVMPY_OUT_SCALAR(int32_t, out, PyLong_FromLong)
CVMPY_OUT_SCALAR(size_t, ncells_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, nconn_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, edges_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, points_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, corners_out, PyLong_FromSize_t)
CVMPY_OUT_SCALAR(size_t, faces_out, PyLong_FromSize_t)

%{
/* (lo, hi, default, is_integer) */
static PyObject *cvmpy_bounds_tuple(cvm_bounds b)
{
    return Py_BuildValue("dddi", b.lo, b.hi, b.def, (int)b.is_integer);
}
%}
CVMPY_OUT_SCALAR(cvm_bounds, out, cvmpy_bounds_tuple)

/* cvm_mesh_create(&m), cvm_sizing_create(&s): return the handle. Python does
 * not free it on its own: call cvm_mesh_free() / cvm_sizing_free(), or use
 * cvmesh.Mesh / cvmesh.Sizing, which do. */
%define CVMPY_HANDLE_OUT(TYPE)
%typemap(in, numinputs=0) TYPE **out (TYPE *tmp = NULL) {
    $1 = &tmp;
}
%typemap(argout) TYPE **out {
    if ($result)
        $result = cvmpy_append($result, SWIG_NewPointerObj(tmp$argnum, $descriptor(TYPE *), 0));
}
%enddef
CVMPY_HANDLE_OUT(cvm_mesh)
CVMPY_HANDLE_OUT(cvm_sizing)

/* ---- helpers for functions outside the conventions --------------------- */

/* Each is replaced by a cvmpy_ helper of the same Python name. */
%ignore cvm_mesh_free;
%ignore cvm_mesh_errmsg;
%ignore cvm_mesh_get_marker_name;
%ignore cvm_mesh_set_progress;
%ignore cvm_mesh_insert_points;
%ignore cvm_sizing_free;
%ignore cvm_sizing_errmsg;
%ignore cvm_sizing_set_callback;
%ignore cvm_mesh_insert_points_nd;
%ignore cvm_sizing_set_callback_nd;
%ignore cvm_sizing_set_metric_fn;
%ignore cvm_sizing_set_batch_callback;
%ignore cvm_sizing_set_background_nd;
%rename(cvm_mesh_free) cvmpy_mesh_free;
%rename(cvm_mesh_errmsg) cvmpy_mesh_errmsg;
%rename(cvm_mesh_get_marker_name) cvmpy_mesh_get_marker_name;
%rename(cvm_mesh_set_progress) cvmpy_set_progress;
%rename(cvm_mesh_insert_points) cvmpy_insert_points;
%rename(cvm_sizing_free) cvmpy_sizing_free;
%rename(cvm_sizing_errmsg) cvmpy_sizing_errmsg;
%rename(cvm_sizing_set_callback) cvmpy_sizing_set_callback;
%rename(cvm_mesh_insert_points_nd) cvmpy_insert_points_nd;
%rename(cvm_sizing_set_callback_nd) cvmpy_sizing_set_callback_nd;
%rename(cvm_sizing_set_metric_fn) cvmpy_sizing_set_metric_fn;
%rename(cvm_sizing_set_batch_callback) cvmpy_sizing_set_batch_callback;
%rename(cvm_sizing_set_background_nd) cvmpy_sizing_set_background_nd;
/* Allocation hooks are C function pointers; there is nothing to pass from Python. */
%ignore cvm_mesh_create_with_allocator;
%ignore cvm_malloc_fn;
%ignore cvm_realloc_fn;
%ignore cvm_free_fn;

%{
/* Python callables installed as C callbacks, keyed by handle address (one
 * dict per handle type), so each stays alive as long as it is installed. */
static PyObject *cvmpy_progress_fns = NULL;
static PyObject *cvmpy_sizing_fns = NULL;
static PyObject *cvmpy_metric_fns = NULL;

/* Keep fn (NULL: forget) for handle h in *registry; 0, or -1 with an exception. */
static int cvmpy_keep(PyObject **registry, const void *h, PyObject *fn)
{
    PyObject *key;
    int rc = 0;
    if (!*registry) {
        if (!fn)
            return 0;
        if (!(*registry = PyDict_New()))
            return -1;
    }
    if (!(key = PyLong_FromVoidPtr((void *)h)))
        return -1;
    if (fn) {
        rc = PyDict_SetItem(*registry, key, fn);
    } else if (PyDict_DelItem(*registry, key) < 0) {
        PyErr_Clear(); /* was not there */
    }
    Py_DECREF(key);
    return rc;
}

/*
 * The C callback behind every Python progress callback. It runs with the GIL
 * released by the long call, so it takes the GIL, calls payload(stage,
 * fraction) if payload is not NULL, and asks the library to stop when the
 * callable returned a true value, raised, or when a signal handler raised
 * (Ctrl-C: PyErr_CheckSignals), leaving the exception for the wrapper to
 * re-raise once the call has returned.
 */
static int cvmpy_progress_trampoline(void *payload, cvm_stage stage, double fraction)
{
    PyGILState_STATE g = PyGILState_Ensure();
    int stop = 0;
    if (PyErr_Occurred()) {
        stop = 1;
    } else {
        if (payload) {
            PyObject *r = PyObject_CallFunction((PyObject *)payload, "id", (int)stage, fraction);
            if (!r) {
                stop = 1;
            } else {
                int t = PyObject_IsTrue(r);
                Py_DECREF(r);
                stop = t != 0; /* -1: __bool__ raised */
            }
        }
        if (!stop && PyErr_CheckSignals() != 0)
            stop = 1;
    }
    PyGILState_Release(g);
    return stop;
}

/*
 * The C sizing function behind a Python sizing callback: takes the GIL (the
 * refinement runs without it) and returns callback(x, y) as a float. When the
 * callable raises, it returns NaN, which stops the refinement; the wrapper
 * then re-raises the callable's exception.
 */
static double cvmpy_sizing_trampoline(void *payload, double x, double y)
{
    PyGILState_STATE g = PyGILState_Ensure();
    double h = Py_NAN;
    if (!PyErr_Occurred()) {
        PyObject *r = PyObject_CallFunction((PyObject *)payload, "dd", x, y);
        if (r) {
            h = PyFloat_AsDouble(r);
            if (h == -1.0 && PyErr_Occurred())
                h = Py_NAN;
            Py_DECREF(r);
        }
    }
    PyGILState_Release(g);
    return h;
}

/*
 * The C batch sizing function behind a Python callback(xy) -> sizes: xy a new
 * (n, 2) float64 array (a copy: the callable may keep it), the result n
 * sizes (anything numpy turns into n float64 values). It returns non-zero,
 * which stops the refinement, when the callable raised or returned another
 * count; the wrapper then re-raises the exception.
 */
static int cvmpy_sizing_batch_trampoline(void *payload, const double *xy, size_t n,
                                         double *h_out)
{
    PyGILState_STATE g = PyGILState_Ensure();
    int rc = 1;
    if (!PyErr_Occurred()) {
        npy_intp dims[2];
        PyArrayObject *p, *a = NULL;
        PyObject *r = NULL;
        dims[0] = (npy_intp)n;
        dims[1] = 2;
        p = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
        if (p) {
            memcpy(PyArray_DATA(p), xy, 2 * n * sizeof(double));
            r = PyObject_CallFunctionObjArgs((PyObject *)payload, (PyObject *)p, NULL);
            Py_DECREF(p);
        }
        if (r)
            a = (PyArrayObject *)PyArray_FROMANY(r, NPY_DOUBLE, 0, 2, NPY_ARRAY_IN_ARRAY);
        if (a && PyArray_SIZE(a) == (npy_intp)n) {
            memcpy(h_out, PyArray_DATA(a), n * sizeof(double));
            rc = 0;
        } else if (a) {
            PyErr_Format(PyExc_ValueError, "the batch sizing callback must return one size "
                         "per point: %ld points, %ld values", (long)n, (long)PyArray_SIZE(a));
        }
        Py_XDECREF(a);
        Py_XDECREF(r);
    }
    PyGILState_Release(g);
    return rc;
}

/* A new float64 array holding the dim coordinates of x, or NULL with an exception. */
static PyObject *cvmpy_point_array(const double *x, int dim)
{
    npy_intp n = (npy_intp)dim;
    PyArrayObject *a = (PyArrayObject *)PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (a && dim > 0)
        memcpy(PyArray_DATA(a), x, (size_t)dim * sizeof(double));
    return (PyObject *)a;
}

/* The C sizing function behind a Python callback(x) -> float of the
 * dimension-generic setter; errors as cvmpy_sizing_trampoline. */
static double cvmpy_sizing_nd_trampoline(void *payload, const double *x, int dim)
{
    PyGILState_STATE g = PyGILState_Ensure();
    double h = Py_NAN;
    if (!PyErr_Occurred()) {
        PyObject *p = cvmpy_point_array(x, dim);
        PyObject *r = p ? PyObject_CallFunctionObjArgs((PyObject *)payload, p, NULL) : NULL;
        Py_XDECREF(p);
        if (r) {
            h = PyFloat_AsDouble(r);
            if (h == -1.0 && PyErr_Occurred())
                h = Py_NAN;
            Py_DECREF(r);
        }
    }
    PyGILState_Release(g);
    return h;
}

/*
 * The C metric function behind a Python callback(x) -> dim*(dim+1)/2 floats
 * (upper triangle, row by row), or None to refuse the point. An exception
 * refuses the point and is re-raised by the wrapper. Derivatives are never
 * asked of a Python metric (it is installed with has_derivatives = 0).
 */
static int cvmpy_metric_trampoline(void *payload, const double *x, int dim, double *gout,
                                   double *dg)
{
    PyGILState_STATE gil = PyGILState_Ensure();
    int refused = 1;
    (void)dg;
    if (!PyErr_Occurred()) {
        PyObject *p = cvmpy_point_array(x, dim);
        PyObject *r = p ? PyObject_CallFunctionObjArgs((PyObject *)payload, p, NULL) : NULL;
        Py_XDECREF(p);
        if (r && r != Py_None) {
            npy_intp want = (npy_intp)(dim * (dim + 1) / 2);
            PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(r, NPY_DOUBLE, 0, 1,
                                                                NPY_ARRAY_IN_ARRAY);
            if (a && PyArray_SIZE(a) == want) {
                memcpy(gout, PyArray_DATA(a), (size_t)want * sizeof(double));
                refused = 0;
            } else if (a) {
                PyErr_Format(PyExc_ValueError, "the metric callback must return %ld values "
                             "(the upper triangle of the tensor), got %ld", (long)want,
                             (long)PyArray_SIZE(a));
            }
            Py_XDECREF(a);
        }
        Py_XDECREF(r);
    }
    PyGILState_Release(gil);
    return refused;
}
%}

%inline %{
/* Free a handle (None is a no-op) and drop its progress callback. */
void cvmpy_mesh_free(cvm_mesh *handle)
{
    if (handle && cvmpy_keep(&cvmpy_progress_fns, handle, NULL) < 0)
        PyErr_Clear();
    cvm_mesh_free(handle);
}

/* Message of the last failing call on handle ("" after success). */
const char *cvmpy_mesh_errmsg(const cvm_mesh *handle)
{
    return cvm_mesh_errmsg(handle);
}

/* The name of (dim, marker), or None (it returns a string, not a status). */
const char *cvmpy_mesh_get_marker_name(const cvm_mesh *handle, int dim, int32_t marker)
{
    return cvm_mesh_get_marker_name(handle, dim, marker);
}
%}

%typemap(in) PyObject *callback {
    $1 = $input;
}
%inline %{
/*
 * Install callback(stage, fraction) -> bool as the progress callback of m,
 * called about every every_n operations of long calls; a true result stops
 * the call (CVM_INCOMPLETE_CANCELLED), an exception stops it and is re-raised.
 * callback None with every_n >= 1 still lets Ctrl-C (KeyboardInterrupt) stop
 * long calls; every_n < 1 removes the callback.
 */
cvm_status cvmpy_set_progress(cvm_mesh *m, PyObject *callback, int64_t every_n)
{
    cvm_status s;
    int on = every_n >= 1;
    PyObject *fn = on && callback != Py_None ? callback : NULL;
    if (callback != Py_None && !PyCallable_Check(callback)) {
        PyErr_SetString(PyExc_TypeError, "progress callback must be callable or None");
        return CVM_E_ARGUMENT;
    }
    s = cvm_mesh_set_progress(m, on ? cvmpy_progress_trampoline : NULL, every_n, (void *)fn);
    if (s == CVM_OK && cvmpy_keep(&cvmpy_progress_fns, m, fn) < 0)
        return CVM_E_NOMEM;
    return s;
}
%}

%inline %{
/* Free a sizing handle (None is a no-op) and drop its callback. */
void cvmpy_sizing_free(cvm_sizing *handle)
{
    if (handle && cvmpy_keep(&cvmpy_sizing_fns, handle, NULL) < 0)
        PyErr_Clear();
    if (handle && cvmpy_keep(&cvmpy_metric_fns, handle, NULL) < 0)
        PyErr_Clear();
    cvm_sizing_free(handle);
}

/* Message of the last failing call on a sizing handle. */
const char *cvmpy_sizing_errmsg(const cvm_sizing *handle)
{
    return cvm_sizing_errmsg(handle);
}

/*
 * Set callback(x, y) -> float as the sizing function of s (None removes it).
 * An exception in the callback stops the refinement and is re-raised.
 */
cvm_status cvmpy_sizing_set_callback(cvm_sizing *s, PyObject *callback)
{
    cvm_status st;
    PyObject *fn = callback != Py_None ? callback : NULL;
    if (fn && !PyCallable_Check(fn)) {
        PyErr_SetString(PyExc_TypeError, "sizing callback must be callable or None");
        return CVM_E_ARGUMENT;
    }
    st = cvm_sizing_set_callback(s, fn ? cvmpy_sizing_trampoline : NULL, (void *)fn);
    if (st == CVM_OK && cvmpy_keep(&cvmpy_sizing_fns, s, fn) < 0)
        return CVM_E_NOMEM;
    return st;
}

/*
 * Set callback(x) -> float, x a float64 array of the mesh's dimension, as the
 * sizing function of s (None removes it); it replaces a callback(x, y).
 */
cvm_status cvmpy_sizing_set_callback_nd(cvm_sizing *s, PyObject *callback)
{
    cvm_status st;
    PyObject *fn = callback != Py_None ? callback : NULL;
    if (fn && !PyCallable_Check(fn)) {
        PyErr_SetString(PyExc_TypeError, "sizing callback must be callable or None");
        return CVM_E_ARGUMENT;
    }
    st = cvm_sizing_set_callback_nd(s, fn ? cvmpy_sizing_nd_trampoline : NULL, (void *)fn);
    if (st == CVM_OK && cvmpy_keep(&cvmpy_sizing_fns, s, fn) < 0)
        return CVM_E_NOMEM;
    return st;
}

/*
 * Set callback(xy) -> sizes, xy an (n, 2) float64 array, as the batch sizing
 * function of s (None removes it); it replaces a callback(x, y) or callback(x).
 */
cvm_status cvmpy_sizing_set_batch_callback(cvm_sizing *s, PyObject *callback)
{
    cvm_status st;
    PyObject *fn = callback != Py_None ? callback : NULL;
    if (fn && !PyCallable_Check(fn)) {
        PyErr_SetString(PyExc_TypeError, "sizing callback must be callable or None");
        return CVM_E_ARGUMENT;
    }
    st = cvm_sizing_set_batch_callback(s, fn ? cvmpy_sizing_batch_trampoline : NULL, (void *)fn);
    if (st == CVM_OK && cvmpy_keep(&cvmpy_sizing_fns, s, fn) < 0)
        return CVM_E_NOMEM;
    return st;
}

/*
 * Set callback(x) -> (g11, g12, g22) (None: the point is refused) as the
 * metric source of s (None removes it). See cvm_sizing_set_metric_fn().
 */
cvm_status cvmpy_sizing_set_metric_fn(cvm_sizing *s, PyObject *callback)
{
    cvm_status st;
    PyObject *fn = callback != Py_None ? callback : NULL;
    if (fn && !PyCallable_Check(fn)) {
        PyErr_SetString(PyExc_TypeError, "metric callback must be callable or None");
        return CVM_E_ARGUMENT;
    }
    st = cvm_sizing_set_metric_fn(s, fn ? cvmpy_metric_trampoline : NULL, 0, (void *)fn);
    if (st == CVM_OK && cvmpy_keep(&cvmpy_metric_fns, s, fn) < 0)
        return CVM_E_NOMEM;
    return st;
}
%}

%typemap(in, numinputs=0) PyObject **ids_out (PyObject *tmp = NULL) {
    $1 = &tmp;
}
%typemap(argout) PyObject **ids_out {
    if ($result) {
        $result = cvmpy_append($result, tmp$argnum);
        tmp$argnum = NULL;
    }
}
%typemap(freearg) PyObject **ids_out { Py_XDECREF(tmp$argnum); }
%typemap(out) cvm_status cvmpy_insert_points {
    $result = cvmpy_status_result($1, 1);
}
%typemap(out) cvm_status cvmpy_insert_points_nd {
    $result = cvmpy_status_result($1, 1);
}
%inline %{
/*
 * cvm_mesh_insert_points() returning (status, ids): ids is a new int32 array
 * of one entry per point (CVM_REJECTED = -1 for a rejected point). The GIL is
 * released during the insertion.
 */
cvm_status cvmpy_insert_points(PyObject **ids_out, cvm_mesh *m, const double *xy, size_t count,
                               double min_dist)
{
    cvm_status s;
    npy_intp n = (npy_intp)count;
    cvm_index *ids;
    PyArrayObject *a = (PyArrayObject *)PyArray_ZEROS(1, &n, NPY_INT32, 0);
    if (!a)
        return CVM_E_NOMEM;
    ids = (cvm_index *)PyArray_DATA(a);
    Py_BEGIN_ALLOW_THREADS
    s = cvm_mesh_insert_points(ids, m, xy, count, min_dist);
    Py_END_ALLOW_THREADS
    *ids_out = (PyObject *)a;
    return s;
}

/* cvm_mesh_insert_points_nd() returning (status, ids), as cvmpy_insert_points. */
cvm_status cvmpy_insert_points_nd(PyObject **ids_out, cvm_mesh *m, const double *coords,
                                  size_t count, int dim, double min_dist)
{
    cvm_status s;
    npy_intp n = (npy_intp)count;
    cvm_index *ids;
    PyArrayObject *a = (PyArrayObject *)PyArray_ZEROS(1, &n, NPY_INT32, 0);
    if (!a)
        return CVM_E_NOMEM;
    ids = (cvm_index *)PyArray_DATA(a);
    Py_BEGIN_ALLOW_THREADS
    s = cvm_mesh_insert_points_nd(ids, m, coords, count, dim, min_dist);
    Py_END_ALLOW_THREADS
    *ids_out = (PyObject *)a;
    return s;
}
%}

%inline %{
/*
 * cvm_sizing_set_background_nd() from two arrays: nodes (n, dim + 1) (the
 * coordinates, then the size) and cells (m, dim + 1); dim comes from the
 * nodes' shape, and cells of another width raise ValueError before the call.
 */
cvm_status cvmpy_sizing_set_background_nd(cvm_sizing *s, const double *bg_xh, size_t bg_n,
                                          int bg_cols, const cvm_index *bg_cells, size_t bg_nc,
                                          int bg_ccols)
{
    int dim = bg_cols - 1;
    if (bg_n == 0 && bg_nc == 0)
        dim = bg_cols == 3 ? 2 : 3; /* removal: of the dimension the empty shape says */
    else if (dim != 2 && dim != 3) {
        PyErr_Format(PyExc_ValueError, "background nodes must have shape (n, 3) or (n, 4) "
                     "(coordinates, then the size), got %d columns", bg_cols);
        return CVM_E_ARGUMENT;
    } else if (bg_nc > 0 && bg_ccols != dim + 1) {
        PyErr_Format(PyExc_ValueError, "background cells must have shape (m, %d) for %dD "
                     "nodes, got %d columns", dim + 1, dim, bg_ccols);
        return CVM_E_ARGUMENT;
    }
    return cvm_sizing_set_background_nd(s, bg_xh, bg_n, dim, bg_cells, bg_nc);
}
%}

/* ---- the API ------------------------------------------------------------ */

#define CVM_API
/* cvm_bounds.def: 'def' is a Python keyword. */
%rename(default) cvm_bounds::def;
%include "cvmesh.h"
