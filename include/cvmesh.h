/*
 * cvmesh.h - the entire stable API of cvmesh, a BSD-3-Clause library that
 * generates triangle meshes whose Delaunay primal and Voronoi (power) dual are
 * both of high quality.
 *
 * Introduction
 * ------------
 * 1. Create a handle:            cvm_mesh_create(&m).
 * 2. Give it input:              cvm_mesh_set_points(m, xy, n, 2), then optionally
 *                                cvm_mesh_set_segments(), cvm_mesh_set_holes(),
 *                                cvm_mesh_set_regions(); or cvm_mesh_read(m, "a.poly").
 * 3. Choose options:             cvm_mesh_set_option(m, CVM_OPT_..., value).
 * 4. Mesh:                       cvm_mesh_triangulate(m) (Delaunay or constrained
 *                                Delaunay), then cvm_mesh_insert_points() to add points,
 *                                or cvm_mesh_refine(m, sizing, algo) for a quality mesh.
 * 5. Read the output:            cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE), then
 *                                cvm_mesh_copy_cells(buf, len, m, CVM_ENT_TRIANGLE),
 *                                or write it with cvm_mesh_write(m, "out.vtu").
 * 6. Free it:                    cvm_mesh_free(m).
 * Every call returns a cvm_status; cvm_mesh_errmsg(m) says what went wrong and
 * names the offending input. Indices are 0-based everywhere.
 *
 * Threads: one call at a time per handle; different handles may be used from
 * different threads at once. The library has no global mutable state.
 * Geometry: every topological decision uses exact adaptive predicates with
 * symbolic perturbation; coordinates computed by the library (Steiner points)
 * are ordinary doubles.
 */
#ifndef CVMESH_H
#define CVMESH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(CVM_BUILDING_DLL)
#  define CVM_API __declspec(dllexport)
#elif defined(_WIN32) && defined(CVM_USING_DLL)
#  define CVM_API __declspec(dllimport)
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define CVM_API __attribute__((visibility("default")))
#else
#  define CVM_API
#endif

/* ------------------------------------------------------------------------ */
/* Version                                                                   */
/* ------------------------------------------------------------------------ */

#define CVM_VERSION_MAJOR 0
#define CVM_VERSION_MINOR 1
#define CVM_VERSION_PATCH 0
#define CVM_VERSION_NUMBER \
    (CVM_VERSION_MAJOR * 10000 + CVM_VERSION_MINOR * 100 + CVM_VERSION_PATCH)

/**
 * Version of the library actually linked, as MAJOR*10000 + MINOR*100 + PATCH.
 * Thread-safety: callable from any thread.
 * @return the version number; equals CVM_VERSION_NUMBER of the header it was built with.
 * @since 0.1
 */
CVM_API int32_t cvm_version_number(void);

/**
 * Version of the library as a static string "MAJOR.MINOR.PATCH".
 * Ownership: the string is static; do not free it.
 * Thread-safety: callable from any thread.
 * @since 0.1
 */
CVM_API const char *cvm_version_string(void);

/**
 * How the linked library was built, as a static string: the version, then the
 * optional components and the licence they put the build under, e.g.
 * "cvmesh 0.1.0; TetGen 1.5 boundary recovery (AGPL-3+ build); OpenMP" or
 * "cvmesh 0.1.0; no TetGen (BSD-3-Clause build); OpenMP". Without TetGen,
 * cvm_mesh_triangulate() of a 3D surface recovers it only when every surface
 * triangle is a Delaunay face (see there). cvm_version_string() keeps its
 * "MAJOR.MINOR.PATCH" form for programs that parse it.
 * Ownership: static; do not free. Thread-safety: callable from any thread.
 * @since 0.2
 */
CVM_API const char *cvm_build_string(void);

/* ------------------------------------------------------------------------ */
/* Types                                                                     */
/* ------------------------------------------------------------------------ */

/** Index of a vertex, cell or input item; 0-based. */
typedef int32_t cvm_index;

/** Marker that cvm_mesh_insert_points() writes for a point it rejected. */
#define CVM_REJECTED ((cvm_index)-1)

/** Opaque mesh handle; see cvm_mesh_create(). */
typedef struct cvm_mesh cvm_mesh;

/**
 * Status of a call. CVM_OK is 0. Values 1..99 are errors (nothing useful was
 * produced; the handle keeps its previous state unless the function says
 * otherwise). Values 100 and up mean "stopped early: the result is valid but
 * incomplete". Test with cvm_status_is_error(). Values never change.
 */
typedef enum cvm_status {
    CVM_OK = 0,
    CVM_E_NULL_ARG = 1,            /**< a required pointer argument is NULL */
    CVM_E_ARGUMENT = 2,            /**< an argument is out of its domain (e.g. dim, entity kind) */
    CVM_E_OPTION_KEY = 3,          /**< unknown option key */
    CVM_E_OPTION_RANGE = 4,        /**< option value outside cvm_option_bounds() */
    CVM_E_STATE = 5,               /**< call made in the wrong order (e.g. insert before triangulate) */
    CVM_E_UNSUPPORTED = 6,         /**< feature not available in this build or version */
    CVM_E_INPUT_NONFINITE = 10,    /**< NaN or infinite coordinate, hole, region or value */
    CVM_E_INPUT_INDEX = 11,        /**< an index names an item that does not exist */
    CVM_E_INPUT_DUPLICATE = 12,    /**< duplicate points (only with CVM_OPT_REJECT_DUPLICATES) */
    CVM_E_INPUT_DEGENERATE = 13,   /**< zero-length segment, all points collinear, too few points */
    CVM_E_INPUT_INTERSECTING = 14, /**< two segments cross (only with CVM_OPT_SPLIT_INTERSECTIONS = 0) */
    CVM_E_INPUT_NOT_CLOSED = 15,   /**< boundary is open: a hole or the exterior leaks into the domain */
    CVM_E_INPUT_EMPTY = 16,        /**< no input points, or nothing left of the domain */
    CVM_E_INPUT_OUTSIDE = 17,      /**< a hole or region point lies outside the triangulated domain */
    CVM_E_IO_OPEN = 30,            /**< a file could not be opened or created */
    CVM_E_IO_READ = 31,            /**< reading failed (short read, device error) */
    CVM_E_IO_WRITE = 32,           /**< writing failed (disk full, rename failed); no partial file left */
    CVM_E_IO_FORMAT = 33,          /**< malformed file content; the message gives file and line */
    CVM_E_NOMEM = 40,              /**< out of memory; the handle stays usable and freeable */
    CVM_E_BUFFER_TOO_SMALL = 41,   /**< caller's buffer too short; nothing was written */
    CVM_E_TOO_LARGE = 42,          /**< sizes exceed what cvm_index can address */
    CVM_E_INTERNAL = 99,           /**< internal consistency check failed; a bug: please report */
    CVM_INCOMPLETE_TIME_LIMIT = 100, /**< stopped at CVM_OPT_TIME_LIMIT_S; result valid, incomplete */
    CVM_INCOMPLETE_CANCELLED = 101,  /**< the progress callback asked to stop; result valid, incomplete */
    CVM_INCOMPLETE_STEINER_LIMIT = 102 /**< stopped at CVM_OPT_MAX_STEINER; result valid, incomplete */
} cvm_status;

/**
 * Fixed English text for a status code, e.g. "out of memory".
 * Ownership: static string. Thread-safety: callable from any thread.
 * @return never NULL; "unknown status" for a value not listed above.
 * @since 0.1
 */
CVM_API const char *cvm_status_str(cvm_status s);

/**
 * 1 if @p s is an error (1..99), 0 for CVM_OK and the CVM_INCOMPLETE_* values.
 * Thread-safety: callable from any thread.
 * @since 0.1
 */
CVM_API int cvm_status_is_error(cvm_status s);

/** Kinds of mesh entities, for counts, copies and error reports. Values never change. */
typedef enum cvm_entity {
    CVM_ENT_NONE = 0,
    CVM_ENT_VERTEX = 1,       /**< mesh vertices (input points less duplicates, then Steiner points) */
    CVM_ENT_TRIANGLE = 2,     /**< triangles of the domain, 3 vertex ids each, counter-clockwise */
    CVM_ENT_EDGE = 3,         /**< edges of the domain triangles, 2 vertex ids each */
    CVM_ENT_SEGMENT = 4,      /**< constrained edges of the output (input segments and their pieces) */
    CVM_ENT_INPUT_POINT = 5,  /**< points as given to cvm_mesh_set_points() */
    CVM_ENT_INPUT_SEGMENT = 6,/**< segments as given to cvm_mesh_set_segments() */
    CVM_ENT_HOLE = 7,         /**< hole seed points */
    CVM_ENT_REGION = 8,       /**< region seed points */
    CVM_ENT_DUPLICATE = 9,    /**< input points merged into an earlier identical point */
    CVM_ENT_FILE_LINE = 10,   /**< a line of an input file (error reports only) */
    CVM_ENT_OPTION = 11,      /**< an option key (error reports only) */
    CVM_ENT_TETRAHEDRON = 12, /**< tetrahedra of a 3D mesh, 4 vertex ids, positively oriented */
    CVM_ENT_FACET = 13,       /**< facets of a 3D input surface (polygons with a marker) */
    CVM_ENT_REFINE_UNMET = 20, /**< triangles the last cvm_mesh_refine() left below the angle or
                                   above the size (cvm_mesh_copy_refine_unmet()) */
    CVM_ENT_CELL = 21,        /**< the cells of the mesh's dimension, of any type (triangles
                                   today; quads, tetrahedra later): cvm_mesh_copy_cells_mixed() */
    CVM_ENT_QUAD = 22         /**< reserved for quad-dominant meshing */
} cvm_entity;

/* ------------------------------------------------------------------------ */
/* Handle lifecycle and errors                                               */
/* ------------------------------------------------------------------------ */

/**
 * Create an empty mesh handle that uses the C library's malloc/realloc/free.
 *
 * @param out  receives the handle; set to NULL on failure.
 * Ownership:  the caller owns *out and releases it with cvm_mesh_free().
 * Thread-safety: callable from any thread.
 * @return CVM_OK
 *         CVM_E_NULL_ARG   out is NULL
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_create(cvm_mesh **out);

/** Allocation hooks of cvm_mesh_create_with_allocator(); same contract as malloc/realloc/free. */
typedef void *(*cvm_malloc_fn)(void *payload, size_t size);
typedef void *(*cvm_realloc_fn)(void *payload, void *ptr, size_t size);
typedef void (*cvm_free_fn)(void *payload, void *ptr);

/**
 * Create an empty mesh handle whose every allocation goes through the given
 * functions (the handle itself included).
 *
 * @param out       receives the handle; set to NULL on failure.
 * @param alloc_fn  malloc-like; may return NULL, which cvmesh reports as CVM_E_NOMEM.
 * @param realloc_fn realloc-like; on NULL the old block must stay valid.
 * @param free_fn   free-like; must accept NULL.
 * @param payload   passed unchanged to each function; may be NULL.
 * Ownership:  the functions and payload must outlive the handle.
 * Thread-safety: the functions are called only from calls on this handle.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  out, alloc_fn, realloc_fn or free_fn is NULL
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_create_with_allocator(cvm_mesh **out, cvm_malloc_fn alloc_fn,
                                                  cvm_realloc_fn realloc_fn, cvm_free_fn free_fn,
                                                  void *payload);

/**
 * Free a mesh handle and everything it owns. NULL is a no-op.
 * Views obtained from @p m become invalid.
 * @since 0.1
 */
CVM_API void cvm_mesh_free(cvm_mesh *m);

/**
 * Message describing the last failing (or incomplete) call on @p m, naming the
 * offending input, e.g. "segment 17 (points 4-9) crosses segment 22 (points 5-11)".
 * Input read by cvm_mesh_read() is named in the file's terms (see there). The
 * text is valid UTF-8 without control characters: such bytes echoed from a file
 * or a file name appear as \xHH.
 * Ownership: owned by @p m; valid until the next call on @p m.
 * @return "" when the last call succeeded; "no mesh handle" when m is NULL.
 * @since 0.1
 */
CVM_API const char *cvm_mesh_errmsg(const cvm_mesh *m);

/**
 * The input item named by the last error on @p m, for programs.
 *
 * @param kind_out   receives the entity kind (CVM_ENT_NONE when no item is named).
 * @param index_out  receives its 0-based index (a file line is 1-based, as editors count).
 * @return CVM_OK, or CVM_E_NULL_ARG when any pointer is NULL.
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_error_item(cvm_entity *kind_out, int64_t *index_out, const cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* Input                                                                     */
/* ------------------------------------------------------------------------ */

/**
 * Set the input points. Clears any triangulation and the point markers and
 * attributes; segments, holes and regions are kept.
 *
 * With dim 3 the handle becomes a 3D mesh (cvm_mesh_dim() 3; 2D input and
 * output are forgotten, 3D holes and regions kept): cvm_mesh_triangulate()
 * then builds the Delaunay tetrahedralisation of the points, and the calls
 * that have a 3D meaning follow (counts, points and cells, check, weights,
 * measures, histograms, files, the 3D dual; each documents it). The 2D-only
 * calls (segments, refine, optimise, insert, the 2D dual copies) return
 * CVM_E_UNSUPPORTED on a 3D mesh.
 * Points of dim 2 make a 3D handle 2D again.
 *
 * @param m      mesh handle; not NULL.
 * @param coords dim*count coordinates, point i at coords[dim*i ..].
 * @param count  number of points; may be 0.
 * @param dim    2 or 3.
 * Ownership:    copied; the caller keeps @p coords.
 * Units:        any consistent length unit.
 * Thread-safety: one call at a time on @p m.
 * Atomicity:    on error the previous input is kept unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or coords is NULL while count > 0
 *         CVM_E_ARGUMENT          dim is not 2 or 3
 *         CVM_E_INPUT_NONFINITE   a coordinate is NaN or infinite (message gives the point)
 *         CVM_E_TOO_LARGE         count exceeds INT32_MAX/4 (2D) or 60,000,000 (3D)
 *         CVM_E_NOMEM
 * @since 0.1 (dim 3 since 0.2; it returned CVM_E_UNSUPPORTED before)
 */
CVM_API cvm_status cvm_mesh_set_points(cvm_mesh *m, const double *coords, size_t count, int dim);

/**
 * Dimension of @p m: the number of coordinates per point of its input and
 * output (points, holes, regions, inserted points, dual vertices) in the
 * dimension-generic calls (the *_nd functions, cvm_sizing_*_nd).
 *
 * @param out  receives 2 or 3: a new handle is 2D; one given 3D points
 *             (cvm_mesh_set_points() with dim 3, or cvm_mesh_read() of a 3D file)
 *             is 3D.
 * @param m    mesh handle; not NULL.
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK, CVM_E_NULL_ARG (out or m is NULL)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_dim(int32_t *out, const cvm_mesh *m);

/**
 * Set an integer boundary marker for each input point (as Triangle's .node markers).
 * @param markers count values; count must equal the number of input points (0 removes them).
 * Ownership: copied.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT (count differs from the point count), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_point_markers(cvm_mesh *m, const int32_t *markers, size_t count);

/**
 * Set @p nattr attributes per input point (interpolated linearly onto points
 * inserted on segments, as Triangle does).
 * @param attrs  count*nattr values, point i at attrs[nattr*i ..]; count equals the point count.
 * Ownership: copied.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT, CVM_E_INPUT_NONFINITE (names the point), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_point_attributes(cvm_mesh *m, const double *attrs, size_t count,
                                                 size_t nattr);

/**
 * Set the constraint segments of a planar straight-line graph (PSLG).
 * With segments present, cvm_mesh_triangulate() builds the constrained
 * Delaunay triangulation and removes triangles outside the domain (those
 * reachable from the convex hull without crossing a segment, unless
 * CVM_OPT_KEEP_CONVEX_HULL is set) and in holes.
 *
 * @param segs   2*count point indices into the input points.
 * @param count  number of segments; 0 removes all segments.
 * Ownership:    copied. Indices are checked by cvm_mesh_triangulate(), since
 *               points may be set after segments.
 * Atomicity:    on error the previous segments are kept unchanged.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_TOO_LARGE, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_segments(cvm_mesh *m, const cvm_index *segs, size_t count);

/**
 * Set a boundary marker per segment (written to outputs, used by the refiners
 * to choose fronts). @p count equals the segment count, or 0 to remove.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_segment_markers(cvm_mesh *m, const int32_t *markers, size_t count);

/**
 * Set hole seed points: every triangle reachable from a hole point without
 * crossing a segment is removed.
 * @param xy  2*count coordinates. Ownership: copied.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_INPUT_NONFINITE (names the hole), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_holes(cvm_mesh *m, const double *xy, size_t count);

/**
 * cvm_mesh_set_holes() in the mesh's dimension: dim coordinates per hole.
 *
 * @param m       mesh handle; not NULL.
 * @param coords  dim*count coordinates, hole k at coords[dim*k ..]; NULL only with count 0.
 * @param count   number of holes; 0 removes them.
 * @param dim     the mesh's dimension (cvm_mesh_dim()): 2. 3 is for the 3D kernel,
 *                which is not there yet: CVM_E_UNSUPPORTED.
 * Ownership:    copied. Units: length.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on error the previous holes are kept unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         m is NULL, or coords is NULL while count > 0
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3
 *         CVM_E_UNSUPPORTED      dim is 3 (no 3D kernel yet; message says so)
 *         CVM_E_INPUT_NONFINITE  a coordinate is NaN or infinite (names hole k)
 *         CVM_E_TOO_LARGE, CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_set_holes_nd(cvm_mesh *m, const double *coords, size_t count, int dim);

/**
 * Set regional attributes: region k is seeded at (r[4k], r[4k+1]); every
 * triangle reachable from it without crossing a segment gets attribute r[4k+2];
 * r[4k+3] is a maximum triangle area for the refiners (<= 0 means none, as a
 * negative area in Triangle's .poly and CVM_OPT_MAX_AREA; with CVM_OPT_MAX_AREA
 * also set, the smaller bound holds).
 * Triangles in no region get attribute 0. Later regions win over earlier ones.
 * Ownership: copied.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_INPUT_NONFINITE (names the region), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_regions(cvm_mesh *m, const double *r, size_t count);

/**
 * cvm_mesh_set_regions() in the mesh's dimension: dim + 2 values per region,
 * the seed point (dim coordinates), the attribute, and the largest cell
 * measure for the refiners (an area in 2D, a volume in 3D; <= 0: no bound).
 *
 * @param m      mesh handle; not NULL.
 * @param r      (dim+2)*count values, region k at r[(dim+2)*k ..]; NULL only with count 0.
 * @param count  number of regions; 0 removes them.
 * @param dim    2; 3 gives CVM_E_UNSUPPORTED (no 3D kernel yet).
 * Ownership:    copied.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on error the previous regions are kept unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         m is NULL, or r is NULL while count > 0
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3
 *         CVM_E_UNSUPPORTED      dim is 3 (message says so)
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (names region k)
 *         CVM_E_TOO_LARGE, CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_set_regions_nd(cvm_mesh *m, const double *r, size_t count, int dim);

/**
 * Read a Triangle .poly (PSLG) or .node (point set) file into the input of @p m,
 * replacing points, markers, attributes, segments, holes and regions.
 * Comments (#), 0- or 1-based numbering, markers, attributes, holes and
 * regional attributes are understood. A .poly whose point count is 0 takes its
 * points from the .node file of the same stem, as Triangle does. Numbers are
 * decimal: a hexadecimal float (0x1p-3) is CVM_E_IO_FORMAT. A region's maximum
 * area of 0 or below (Triangle's files use -1) means no bound.
 * Later errors about the points, segments, holes and regions read from a
 * .poly/.node (cvm_mesh_triangulate(): duplicates, zero-length or crossing
 * segments, holes and regions) name them as the file does, by its numbers,
 * and start with "FILE:LINE: ", e.g. "a.node:6: point 4 at (0, 0) duplicates
 * point 1 (line 2)" in a file numbered from 1; cvm_mesh_error_item() still
 * gives the 0-based index. Setting points, segments, holes or regions through
 * the API makes later messages name those by their indices again.
 *
 *
 * A .vtu file (VTK XML unstructured grid as cvm_mesh_write(), VTK and meshio
 * write it: ASCII, inline base64 or appended raw/base64 data arrays, zlib
 * compression, UInt32 or UInt64 headers, either byte order, any integer or
 * float type; other writers' files with triangle cells are read too) gives a triangulated handle: the file's points become the input
 * points (point data "marker" and "attribute" their markers and attributes),
 * its line cells (VTK type 3, cell data "marker") and the boundary edges of its
 * triangles the segments, with a hole point in each hole; the handle is
 * triangulated, point data "weight" is set as the weights
 * (cvm_mesh_set_weights()) and cell data "attribute" as the triangles'
 * regional attributes. When the result holds exactly the file's triangles
 * they keep the file's order and first vertex, so cvm_mesh_write() of a file
 * cvm_mesh_write() wrote reproduces it byte for byte. A file without line
 * cells is first tried as the Delaunay triangulation of its points (no
 * segments). Any other conforming triangulation (a structured grid split
 * into triangles, a Gmsh mesh, a mesh that is not Delaunay) is made
 * (constrained) Delaunay, or regular with weights, by Lawson flips under the
 * exact in-circle (power) test: its boundary edges, line cells and the edges
 * between triangles of different attributes are segments and never flipped;
 * the connectivity then changes, the triangles keep the file's slots (the two
 * a flip makes take the slots of the two it replaced), and
 * CVM_REPORT_READ_FLIPS says how many flips it took (0: the file's own
 * triangles). A vertex whose power cell is empty stays, as after
 * cvm_mesh_set_weights() (CVM_MEASURE_VANISHED_VERTICES). Vertex ids are the
 * file's point numbers (unless the file repeats a point). Cell type 1
 * (vertex) is ignored; z must be 0. The rebuild ignores CVM_OPT_TIME_LIMIT_S
 * and uses the handle's other options.
 *
 * A legacy .vtk file (ASCII or BINARY, UNSTRUCTURED_GRID or POLYDATA; cell
 * layouts before and after version 5.1; POINT_DATA/CELL_DATA arrays of the
 * same names as SCALARS or FIELD arrays) and a Gmsh .msh file (2.2 or 4.1,
 * ASCII or binary) are read the same way as a .vtu. In a .msh, 2-node lines
 * are the line cells with their physical tags as markers, point elements'
 * physical tags are point markers, and 3-node triangles' physical tags are
 * the triangles' attributes. A .vtk or .msh file without triangles is a
 * domain instead: its points and line cells (with markers) become the input
 * points and segments, and the handle is left untriangulated, as after
 * reading a .poly.
 *
 * 3D input makes the handle 3D (see cvm_mesh_set_points()): a closed surface
 * in .off, .stl (ASCII, one marker per solid, or binary; vertices merged by
 * exact coordinates) or TetGen .poly/.smesh (facets of convex polygons with
 * markers, hole and region points; a .poly is 3D when its first line says
 * dimension 3), or a 3D point set in a TetGen .node. The surface is checked
 * by cvm_mesh_triangulate(), which meshes its inside. A TetGen .ele (4 corners
 * per tetrahedron; the first attribute, if any, as the region attribute) with
 * the points of the .node of the same stem is a tetrahedral mesh: it is taken
 * as the handle's mesh as by cvm_mesh_set_tetrahedra(), with its checks and
 * statuses (messages in the files' numbering); quadratic (10-node) tetrahedra
 * give CVM_E_UNSUPPORTED. @since 0.2 for .ele.
 *
 * @param path  file name; the format follows the extension (.poly, .node, .vtu,
 *              .vtk, .msh, .smesh, .off, .stl, .ele; case-insensitive).
 * Atomicity:   on error or cancellation the previous input (and, for .vtu, the
 *              previous mesh) is kept unchanged.
 * Stops:       the progress callback (stage CVM_STAGE_READ, fraction 0) is asked
 *              after every 64 KiB read and can cancel; the time limit does not apply.
 * @return CVM_OK
 *         CVM_E_NULL_ARG, CVM_E_IO_READ
 *         CVM_E_IO_OPEN          the file cannot be opened, or is a directory
 *         CVM_E_IO_FORMAT        malformed content (message gives file:line); in a .vtu
 *                                also a cell naming a point that does not exist, wrong
 *                                value counts or offsets (message names the cell)
 *         CVM_E_INPUT_NONFINITE  a NaN/Inf coordinate or value (message gives file:line)
 *         CVM_E_TOO_LARGE        a count beyond INT32_MAX/4 (message gives file:line)
 *         CVM_E_UNSUPPORTED      unknown extension; in a .vtu a compressor other than zlib,
 *                                more than one Piece, or a cell type other than 1, 3, 5;
 *                                in a .vtk another DATASET or keyword, cells other than
 *                                triangles, lines, polylines and vertices; in a .msh
 *                                another version or element types other than 1, 2, 15
 *         CVM_E_INPUT_EMPTY      .vtu without triangle cells
 *         CVM_E_IO_FORMAT, CVM_E_INPUT_INDEX  a 3D file's malformed content or a face naming a
 *                                point that does not exist (message names file:line, or the
 *                                byte offset of a binary .stl, and the face)
 *         CVM_E_INPUT_DEGENERATE .vtu whose cells are not a conforming triangulation: a
 *                                triangle repeats a point, has two corners at one position
 *                                or all three on one line, a line cell has zero length, a
 *                                point inside the mesh is in no triangle, an edge has three
 *                                triangles, a triangle is inverted (on the same side of an
 *                                edge as its neighbour), or a triangle is not one of the
 *                                constrained triangulation of the file's points and edges
 *                                (triangles overlap; message names the triangle and its
 *                                points; cvm_mesh_error_item() gives CVM_ENT_TRIANGLE, k)
 *         other CVM_E_INPUT_* of cvm_mesh_triangulate() for a .vtu (message prefixed
 *                                with the file name)
 *         CVM_E_NOMEM
 *         CVM_INCOMPLETE_CANCELLED  the progress callback stopped the reading
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_read(cvm_mesh *m, const char *path);

/* ------------------------------------------------------------------------ */
/* Options                                                                   */
/* ------------------------------------------------------------------------ */

/**
 * Option keys, numbered in blocks of 100 per module; never renumbered.
 * Each value is a double; integer options must be given as whole numbers.
 * Blocks: 100 Delaunay kernel, 200 refinement, 400 run control, 500 dual
 * optimisation, 600 output; 700-799 are reserved for the 3D kernel, 800-899
 * for quad-dominant meshing, 1000 and up for experimental keys, which only
 * include/cvmesh_experimental.h declares (with CVM_EXPERIMENTAL defined).
 * Every key and value declared here is stable; a value documented as
 * experimental is named in cvmesh_experimental.h and may change meaning.
 */
typedef enum cvm_option {
    /** Delaunay kernel (100..199). */
    /** 1: duplicate input points fail with CVM_E_INPUT_DUPLICATE; 0 (default): they are merged
     *  and counted as CVM_ENT_DUPLICATE. Integer, bounds [0, 1]. */
    CVM_OPT_REJECT_DUPLICATES = 100,
    /** 1 (default): crossing input segments are split at their intersection point (a new vertex);
     *  0: they fail with CVM_E_INPUT_INTERSECTING naming both segments. Integer, [0, 1]. */
    CVM_OPT_SPLIT_INTERSECTIONS = 101,
    /** 1: keep every triangle of the convex hull (holes are still removed); 0 (default):
     *  remove triangles outside the segments. Integer, [0, 1]. */
    CVM_OPT_KEEP_CONVEX_HULL = 102,
    /** 1 (default): with no segments the result is the Delaunay triangulation of the convex
     *  hull. Reserved for later kernels; integer, [1, 1]. */
    CVM_OPT_CONVEX_HULL_IF_NO_SEGMENTS = 103,

    /** Refinement (200..299): read by cvm_mesh_refine(). */
    /** Minimum angle requested from the refiners, degrees, default 30, bounds [0, 40].
     *  Termination is guaranteed up to about 20.7 (diametral circles) or 25.7
     *  (CVM_OPT_ENCROACH_LENS = 1) and observed in practice up to 33-34; above that,
     *  bound the run with CVM_OPT_MAX_STEINER. Triangles at small input angles
     *  (below about 60 degrees between segments) may stay below it. 0 = sizes only. */
    CVM_OPT_MIN_ANGLE_DEG = 200,
    /** Maximum triangle area, squared length units, 0 = none (default), bounds [-1e300, 1e300].
     *  A value <= 0 means no bound, the rule of a region's maximum area
     *  (cvm_mesh_set_regions()) and of Triangle's .poly files, where -1 is the usual
     *  "no constraint".
     *  Combined with the sizing of cvm_mesh_refine(): a triangle must meet both. */
    CVM_OPT_MAX_AREA = 201,
    /** Encroachment test of segments: 0 (default) diametral circle (a point p encroaches
     *  segment ab when angle apb > 90 degrees; boundary circumcentres stay in the domain,
     *  as Triangle's -D); 1 diametral lens (angle apb >= 180 - 2 x
     *  CVM_OPT_MIN_ANGLE_DEG, Shewchuk's lens, Triangle's default): fewer segment splits,
     *  about half the vertices between nearly coincident segments, guarantee 25.7
     *  degrees. Integer, [0, 1]. */
    CVM_OPT_ENCROACH_LENS = 202,
    /** 1 (default): every input vertex of a segment stays where it is; segments are
     *  marched one by one (CVM_OPT_MARCH_SEGMENTS). 0: when cvm_mesh_refine() gets a
     *  non-empty sizing, first every chain of segments that forms a smooth curve is
     *  re-discretised as one curve. A chain runs between corners; an inner vertex of a
     *  chain has exactly two incident segments (constrained edges bordering the
     *  domain), both with the same marker, turning by less than 30 degrees; closed
     *  loops without a corner are one chain anchored (kept) at their lowest vertex id.
     *  Its n = round(integral of ds/h) new pieces (at least 1; at least 3 for a loop)
     *  equidistribute ds/h along the arc length; the new points lie ON the input
     *  polyline (rounded), so the domain becomes the input polygon with the corners
     *  of the chain cut by chords (area change within the sagitta bound). The inner
     *  input vertices disappear: cvm_mesh_copy_input_map() gives -1 for them; markers
     *  of new points are the chain's, attributes are interpolated along it. The
     *  triangulation is then rebuilt (constrained Delaunay, holes and regions as in
     *  cvm_mesh_triangulate()) before the refiners run; each piece carries the index
     *  of the input segment holding its midpoint (its first and last: the chain's
     *  end segments). Safe fallback: a chord fails when it would replace an arc
     *  turning more than 90 degrees, enclose (between chord and polyline) or touch
     *  another vertex, a hole or region point, pass closer than 0.1 x its length to
     *  another vertex, or when another segment at a chain end points into the cut;
     *  the inner vertex turning most under a failed chord then becomes a corner and
     *  the chains are planned again (at most 64 passes); a chain with a failed chord
     *  that has no inner vertex keeps all its vertices. If the pieces would join two
     *  vertices twice, or the rebuilt triangulation does not take every piece as one
     *  edge, nothing changes. Needs the mesh as
     *  cvm_mesh_triangulate() left it (CVM_E_STATE after a refinement, inserted
     *  points or weights: triangulate again). Without a sizing (NULL or empty) 0
     *  gives CVM_E_UNSUPPORTED and changes nothing.
     *  Integer, bounds [0, 1]. */
    CVM_OPT_KEEP_SEGMENT_VERTICES = 203,
    /** 1 (default): before refining, each input segment is split by marching along it
     *  with the sizing (pieces of about the local size, no 2:1 jumps); only when a sizing
     *  is given. Along each segment the size is capped by h_b(x) = min(h(x), l(e) + 0.3
     *  d(x, e)) over both ends e, l(e) the shortest piece of the neighbouring segments at
     *  e and d the distance along the segment, so pieces grow geometrically (ratio about
     *  1.35) away from a short neighbour instead of jumping (re-planned until the end
     *  pieces settle; input vertices are kept). 0: segments are split only when
     *  encroached (Triangle's behaviour). Integer, [0, 1]. */
    CVM_OPT_MARCH_SEGMENTS = 204,
    /** 1 (default): after CVM_ALGO_FRONTAL refinement, flip interior unconstrained edges
     *  towards the ideal vertex degree (6 inside, round(boundary angle / 60 degrees) + 1
     *  on the boundary) when the sum of squared degree deviations of the edge's four
     *  vertices drops and no angle below CVM_OPT_MIN_ANGLE_DEG is created; segments are
     *  never flipped. Runs before smoothing and the Delaunay-restoring flips. 0: off.
     *  Not applied to CVM_ALGO_DELAUNAY. Integer, [0, 1]. */
    CVM_OPT_SWAP = 205,
    /** Sweeps of smart smoothing after CVM_ALGO_FRONTAL and CVM_ALGO_AFLR (after
     *  CVM_OPT_SWAP and the CVM_OPT_RELAX_SWEEPS relaxation, before the
     *  Delaunay-restoring flips), bounds [-1, 100]; 0 = off (no relaxation either);
     *  -1 (the default) = the refiner's own: 4 for CVM_ALGO_FRONTAL, 3 for
     *  CVM_ALGO_AFLR. Frontal's seams, where fronts meet, are rougher before smoothing
     *  and keep gaining from more sweeps, each sweep costing time; AFLR already meets
     *  the same regularity with 3. Only Steiner points whose triangles are all inside the domain move
     *  (never an input point or a vertex on a segment), in vertex index order. Each
     *  visited vertex tries 0.5, 1 and 1.5 times the step towards the centroid of its
     *  neighbours and towards its ODT point (the area-weighted mean of its triangles'
     *  circumcentres, Chen and Xu's optimal Delaunay triangulation update), from the
     *  third sweep on (from the second in graded stars; otherwise only in stars with
     *  7 or more angles out of [55, 65]) also the apexes of the equilateral triangles
     *  on its star's outer edges, points between them and a small pattern search
     *  around the best point,
     *  and takes the candidate that makes its star most regular by the count
     *  16 x (obtuse angles) - (angles in [55, 65] degrees), provided no triangle
     *  inverts (exact orient2d), no spoke of those extra candidates gets shorter than
     *  0.6 x min(size, root mean square spoke), no angle drops below min(its old
     *  smallest angle, CVM_OPT_MIN_ANGLE_DEG) and no more triangles exceed the size
     *  bound. The first sweep visits the vertices of
     *  triangles with an angle outside [55, 65] degrees, each later one only the
     *  neighbourhoods of the vertices moved by the sweep before (the result is that of
     *  full sweeps); smoothing stops early when a sweep moves nothing. Not applied
     *  to CVM_ALGO_DELAUNAY. Integer. */
    CVM_OPT_SMOOTH_SWEEPS = 206,
    /** 1 (default): after swapping and smoothing, flip every non-locally-Delaunay
     *  unconstrained edge (exact in-circle), so the result stays a constrained Delaunay
     *  triangulation. This undoes the degree swaps that smoothing did not make
     *  Delaunay, but keeps most of the regularity gained by smoothing. 0 (a non-Delaunay
     *  result) is reserved. Integer, bounds [1, 1]. */
    CVM_OPT_RESTORE_DELAUNAY = 207,
    /** Smoothing method of CVM_OPT_SMOOTH_SWEEPS: 0 (default) the smart
     *  Laplacian described there; 1 max-min optimisation (Freitag and Ollivier's
     *  active-set method): each visited Steiner point moves to increase the smallest
     *  angle of its star (the minimum sine of its angles), along the smallest-norm point
     *  of the convex hull of the active gradients, with a line search; a move is kept
     *  only when that smallest angle strictly grows, no triangle inverts (exact test)
     *  and no more triangles exceed the size bound, so the smallest angle of the mesh
     *  never drops; same vertices, order and sweep rule as the Laplacian; 2: the
     *  Laplacian sweeps, then the max-min sweeps; 3: the Laplacian sweeps, then guarded
     *  max-min sweeps (only stars with an angle below 40 degrees, and only moves that
     *  do not make the star less regular by the Laplacian's count of obtuse angles and
     *  angles in [55, 65] degrees). 1 and 2 raise the smallest angle but make fewer
     *  angles near 60 degrees and take longer; 0 is the default for regularity.
     *  Integer, [0, 3].
     *  Not applied to CVM_ALGO_DELAUNAY. */
    CVM_OPT_SMOOTH_METHOD = 208,
    /** Relaxation sweeps before the smart sweeps of CVM_OPT_SMOOTH_SWEEPS (smoothing
     *  methods 0, 2 and 3), bounds [-1, 100]; 0 = none; -1 (the default) = the
     *  refiner's own: 3 for CVM_ALGO_FRONTAL, 5 for CVM_ALGO_AFLR (frontal spends the
     *  difference on smart sweeps, see CVM_OPT_SMOOTH_SWEEPS). A relaxation sweep
     *  moves each visited Steiner point (same rule of which may move) straight to its
     *  ODT point when no triangle inverts (exact orient2d), no angle drops below
     *  min(its old smallest angle, CVM_OPT_MIN_ANGLE_DEG), no more triangles exceed
     *  the size bound and the star's regularity count (see CVM_OPT_SMOOTH_SWEEPS)
     *  worsens by at most 1. Accepting slightly worse stars spreads the misfit where a
     *  straight lattice of equilateral triangles meets a curved boundary over several
     *  rows instead of one, which the strictly improving smart sweeps cannot do. The
     *  first sweep visits the vertices of triangles with an angle outside [55, 65]
     *  degrees and their neighbours, later ones the neighbourhoods of moves longer
     *  than about 3% of the vertex's shortest edge; a vertex whose longest edge is
     *  more than 1.5 times its shortest (a graded star, where the ODT point is not
     *  the target) is left to the smart sweeps. Integer. */
    CVM_OPT_RELAX_SWEEPS = 209,
    /** CVM_ALGO_AFLR only: smoothing interleaved with the layers. 0 (default): off,
     *  the mesh is smoothed only after refinement (CVM_OPT_SMOOTH_SWEEPS). N > 0: the
     *  advancing-front pass works in bands of N layers and smooths each band as soon
     *  as it is completed. Layer k holds the points placed for front edges of layer
     *  k - 1 (the front-starting segments are layer 0); the pass takes only front
     *  edges of layers below done + N (in its usual order inside the band), so when
     *  none is left, layers done + 1 .. done + N are completed: no more points of
     *  those layers will be placed (an edge of a lower layer made later, by a
     *  segment split, is taken but not waited for). Then the free Steiner points of
     *  those layers and of the band before whose triangles are all good (not on the
     *  front: the centroid of a front point lies in the unrefined part) are smoothed
     *  with CVM_OPT_SMOOTH_METHOD (2 relaxation and 2 smart sweeps for methods 0, 2
     *  and 3; 2 max-min sweeps for 1, 2 and 3), under the same rules as
     *  CVM_OPT_SMOOTH_SWEEPS: no triangle inverts (exact orient2d), no angle drops
     *  below min(its old smallest angle, CVM_OPT_MIN_ANGLE_DEG), no more triangles
     *  exceed the size bound; points on segments and input points never move. The
     *  Delaunay property is restored by flips around the moved points, subsegments
     *  they encroach are split, and the next band starts. The post-processing
     *  (CVM_OPT_SWAP, CVM_OPT_SMOOTH_SWEEPS) still follows. The band order costs
     *  regularity on curved fronts and the smoothing adds time, hence off by
     *  default. Integer, default 0, bounds
     *  [0, 1000]. With CVM_ALGO_DELAUNAY or CVM_ALGO_FRONTAL a non-zero value makes
     *  cvm_mesh_refine() return CVM_E_UNSUPPORTED (no layers there). Ignored for a
     *  weighted (regular) triangulation, which is never smoothed. */
    CVM_OPT_AFLR_SMOOTH_LAYERS = 210,

    /** Run control (400..499). */
    /** Time limit, seconds on a monotonic clock, 0 = none (default), bounds [0, 1e9].
     *  It bounds each call that reads it (cvm_mesh_triangulate(), cvm_mesh_refine(),
     *  cvm_mesh_optimise_dual(), cvm_mesh_insert_points()), from the call's start; to
     *  bound several calls together, set it to what is left before each (as the
     *  cvmesh program does). The one documented source of non-determinism. */
    CVM_OPT_TIME_LIMIT_S = 400,
    /** Seed of the handle's random stream, integer, default 1, bounds [0, 2^53]. */
    CVM_OPT_SEED = 401,
    /** Maximum Steiner points a refinement may add, integer, 0 = none (default), [0, 2^31-1].
     *  Also bounds the points of cvm_mesh_generate3()'s refinement free space
     *  (CVM_GEN3_FREESPACE_REFINE). */
    CVM_OPT_MAX_STEINER = 402,
    /** Threads for parallel stages, integer, 0 = OpenMP default (default), [0, 1024].
     *  Output does not depend on it. Parallel: cvm_mesh_optimise_dual() (its local
     *  problems), the quad mesher's energy, and the point insertion of a 3D Delaunay or
     *  regular (weighted, cvm_mesh_set_weights()) tetrahedralisation of a large point
     *  set; 2D triangulation and refinement are serial. */
    CVM_OPT_THREADS = 403,

    /** Dual optimisation (500..599): read by cvm_mesh_optimise_dual(). */
    /** Local solver: 1 (default) deterministic compass (pattern) search on a smooth
     *  penalty; 2 Modified Cuckoo Search (Walton et al. 2011; population 10 x the
     *  degrees of freedom, streams keyed by (CVM_OPT_SEED, sweep, vertex)). Integer,
     *  [1, 2]. Both reach the same compliance with similar angles and dual edges;
     *  the pattern search is faster. */
    CVM_OPT_DUAL_SOLVER = 500,
    /** Largest number of sweeps, integer, default 50, bounds [0, 100000]; 0 only
     *  restores the regular triangulation and scores it. */
    CVM_OPT_DUAL_MAX_SWEEPS = 501,
    /** Smallest angle a local move may create, degrees, default 30, bounds [0, 50]. A
     *  move is rejected when an angle of the vertex's star would drop below
     *  min(this, the star's smallest angle before the move): angles already below it
     *  never get worse, so a mesh refined at 30 degrees stays at 30 or above. */
    CVM_OPT_DUAL_MIN_ANGLE_DEG = 502,
    /** Objective evaluations per vertex and sweep of the cuckoo solver, integer,
     *  default 300, bounds [30, 1000000]. */
    CVM_OPT_DUAL_CUCKOO_BUDGET = 503,
    /** Objective evaluations per vertex and sweep of the pattern solver, integer,
     *  default 60, bounds [1, 1000000]. */
    CVM_OPT_DUAL_PATTERN_BUDGET = 504,
    /** Margin of the local objective: each power vertex is pushed at least this
     *  fraction of each edge length inside its triangle (so a dual edge is at least
     *  twice this fraction of its primal edge where it is met), default 0.15, bounds
     *  [0, 0.25]. 0 only asks for containment; a smaller margin allows shorter dual
     *  edges and slightly larger minimum angles. */
    CVM_OPT_DUAL_MARGIN = 505,
    /** Target angle, degrees, default 40, bounds [0, 60]: compliant triangles with an
     *  angle below it (or merged, or whose power vertex lies within half the margin of
     *  an edge) are visited too, after the non-compliant ones, and the local objective
     *  adds (1 - sin^2(angle) / sin^2(target))^2 for each triangle below it.
     *  When the run stalls it raises the target by 5 degrees once (see
     *  cvm_mesh_optimise_dual()).
     *  0: only non-compliant triangles are visited. */
    CVM_OPT_DUAL_TARGET_ANGLE_DEG = 506,
    /** 1: input points keep their position (only their weights change); 0 (default):
     *  they move like Steiner points, so a mesh read as points can be optimised. In
     *  both cases a vertex on a constrained edge moves only along its segment, and only
     *  when it lies between two constrained edges of one segment or of two exactly
     *  collinear segments (exact orient2d); corners, segment ends and convex-hull
     *  vertices of unconstrained hulls never move. Integer, [0, 1]. */
    CVM_OPT_DUAL_KEEP_INPUT_POINTS = 507,
    /** Layer priority c of the dual optimiser, default 1, bounds [0, 100]. The score
     *  of a non-compliant triangle is F = L |C - V| with L = 1 + c / (1 + layer):
     *  layer 0 are the domain triangles with a vertex on the domain boundary, layer
     *  k + 1 the domain triangles sharing an edge with layer k and not in a lower
     *  layer (breadth-first over triangles; a triangle the search never reaches has
     *  L = 1). Higher scores are visited first, so c > 0 works from the boundary
     *  inwards; c = 0 orders by |C - V| alone. Recomputed each sweep. */
    CVM_OPT_DUAL_LAYER_PRIORITY = 508,
    /** Vertex removal by the dual optimiser, integer, [0, 2], default 1. 1: a Steiner
     *  vertex whose power cell vanished (the blocking corner of an illegal edge no
     *  flip can fix) is removed, counted in CVM_MEASURE_DUAL_OPT_REMOVED_VANISHED,
     *  instead of being kept by raising its weight; input points and vertices on a
     *  segment, the hull or a region border are never removed (their weight is raised
     *  as with 0). Removal flips the vertex's edges away (exact orient2d) and ends
     *  with the 3-to-1 flip; the remaining vertices keep their order and are
     *  renumbered (markers and attributes follow). 2: also a degree repair after each
     *  of the first 10 sweeps: around every vertex whose corners average under 47
     *  degrees (degree 8 or more inside) and that touches a triangle below
     *  CVM_OPT_DUAL_TARGET_ANGLE_DEG, its removable Steiner neighbour of least degree
     *  is removed, and interior Steiner vertices of degree 4 or less are removed
     *  (CVM_MEASURE_DUAL_OPT_REMOVED_DEGREE). Experimental: it tends to lower the
     *  minimum angle, so it is not the default (the value is
     *  CVM_DUAL_TOPOLOGY_DEGREE_REPAIR of cvmesh_experimental.h; 0 and 1 are stable).
     *  0: no vertex is ever removed. */
    CVM_OPT_DUAL_TOPOLOGY = 509,
    /** Topology pre-pass of cvm_mesh_optimise_dual(), integer, [0, 1], default 0
     *  (off). 1: before the sweeps, up to two rounds of: removal of
     *  every removable Steiner vertex (no segment, hull or region-border vertex; no
     *  two neighbours in one round) with an edge shorter than 0.5 x the local size,
     *  or ending the shortest edge of a triangle below min(35 degrees,
     *  CVM_OPT_DUAL_TARGET_ANGLE_DEG), the latter re-seeded at the mean of its former
     *  neighbours; then every unconstrained interior edge longer than 1.5 x the local
     *  size gets its midpoint inserted (no point closer than 0.5 x the size to a
     *  vertex, nor one whose insertion among the weights would empty another
     *  vertex's power cell). Local size: the sizing when given, else the mean edge length at the
     *  vertex. Input points and segments are untouched; flips restore the regular
     *  triangulation. Vertices are renumbered as with CVM_OPT_DUAL_TOPOLOGY (markers
     *  and attributes follow); added vertices have marker 0 and attributes 0. Needs
     *  CVM_OPT_DUAL_TOPOLOGY >= 1 (with 0, cvm_mesh_optimise_dual() returns
     *  CVM_E_UNSUPPORTED). Deterministic. */
    CVM_OPT_DUAL_PREPASS = 510,
    /** Rounds of the max-min-angle phase of cvm_mesh_optimise_dual(), integer,
     *  default 5, bounds [0, 10000]; 0: no such phase (nor with
     *  CVM_OPT_DUAL_MAX_SWEEPS 0). Once every triangle is
     *  compliant, each round visits the vertices of the triangles within 2 degrees
     *  of the smallest angle (smallest first) and maximises the smallest angle of
     *  the vertex's star over its position (Freitag's active-set ascent, then the
     *  compass search over position and weight), subject to: no triangle inverts
     *  and the star stays regular (exact orient2d and power tests, so no flip
     *  follows), each power vertex keeps min(margin / 3, what it had) x each edge
     *  inside that edge, each dual edge keeps min(1.1 x margin, what it had) x
     *  its primal edge, and the star's smallest angle does not drop; a move that
     *  makes a triangle non-compliant (exact test) is undone. The rounds end at
     *  this count, when a round moves nothing, or after 3 rounds gaining less
     *  than 0.01 degree; removal trials (CVM_OPT_DUAL_MAXMIN_TRIALS) may follow.
     *  Deterministic. */
    CVM_OPT_DUAL_MAXMIN_ROUNDS = 511,
    /** Removal-trial calls after the max-min rounds of cvm_mesh_optimise_dual(),
     *  integer, default 0 (none), bounds [0, 64]; needs CVM_OPT_DUAL_TOPOLOGY >= 1
     *  (with 0, cvm_mesh_optimise_dual() returns CVM_E_UNSUPPORTED) and
     *  CVM_OPT_DUAL_MAXMIN_ROUNDS >= 1. Each call tries removal for the
     *  triangles within 0.5 degree of the smallest angle: up to 8 removable
     *  Steiner vertices (first the least-degree neighbour of each hub, an interior
     *  vertex of 8 or more triangles holding such a smallest angle, which caps it
     *  at 360 / its degree; then the triangles' corners, highest degree first) are
     *  removed one at a time on a copy of the state; sweeps over the non-compliant
     *  triangles and up to 15 rounds over 4 rings around the vertex follow, and the
     *  trial is kept when every triangle is compliant and the smallest angle rose,
     *  or did not drop and fewer triangles lie within 0.01 degree of it; else the
     *  copy comes back and that position is not tried again. A call that keeps a
     *  trial is followed by the next, up to this count; removals are counted in
     *  CVM_MEASURE_DUAL_OPT_REMOVED_MAXMIN. The trials follow the rounds whether
     *  or not those stalled. Deterministic. Off by default: the trials raise the
     *  smallest angle by a degree or two but can more than double the time. */
    CVM_OPT_DUAL_MAXMIN_TRIALS = 512,
    /** Merge tolerance, a fraction of the local ideal dual edge l / sqrt(3), default
     *  0.1, bounds [0, 1]; 0 merges nothing. l at an edge is the mean of the local
     *  sizes of its two ends, each the mean length of the vertex's edges (taken from
     *  the mesh, so merge decisions can be recomputed from the mesh alone). Two domain
     *  triangles sharing an unconstrained edge (same region) whose power vertices are
     *  closer than tol * l / sqrt(3) belong to the same merged cell (see
     *  cvm_mesh_copy_dual_merge_groups()). Read by the measures and copies too. */
    CVM_OPT_DUAL_MERGE_TOL = 520,

    /* ---- output (600-699) ---- */
    /** Window of an .svg picture written by cvm_mesh_write(), in mesh coordinates:
     *  the picture shows [XMIN, XMAX] x [YMIN, YMAX] (800 px wide, the height in
     *  proportion) and leaves out the triangles that lie wholly outside it. Default
     *  0 for all four, bounds [-1e300, 1e300]; the window is used only when
     *  XMAX > XMIN and YMAX > YMIN, otherwise the picture shows the whole mesh.
     *  Other formats ignore these options. */
    CVM_OPT_SVG_WINDOW_XMIN = 600,
    CVM_OPT_SVG_WINDOW_YMIN = 601, /**< see CVM_OPT_SVG_WINDOW_XMIN */
    CVM_OPT_SVG_WINDOW_XMAX = 602, /**< see CVM_OPT_SVG_WINDOW_XMIN */
    CVM_OPT_SVG_WINDOW_YMAX = 603, /**< see CVM_OPT_SVG_WINDOW_XMIN */
    /** Data encoding of a .vtu written by cvm_mesh_write() and cvm_mesh_stage_write():
     *  CVM_VTU_ASCII (0: text), CVM_VTU_BINARY (1: one raw <AppendedData> block,
     *  little-endian, header_type UInt64; about 3x smaller and written at disk
     *  speed), CVM_VTU_ZLIB (2: the same, each array in zlib-compressed 32 KiB
     *  blocks, level 1, vtkZLibDataCompressor) or CVM_VTU_AUTO (3, the default:
     *  ASCII for a mesh of at most CVM_VTU_AUTO_MAX_ASCII_POINTS (1,000,000)
     *  vertices, as before, CVM_VTU_BINARY above). Integer, bounds [0, 3]. The
     *  arrays, names and order are the same in every encoding; VTK, ParaView,
     *  meshio and cvm_mesh_read() read all three. Other formats, 3D meshes and
     *  the dual (cvm_mesh_write_dual()) ignore it. @since 0.2 (value 3 and the
     *  default 3: since 0.2 as well; before, the default was 0) */
    CVM_OPT_VTU_ENCODING = 604,
    /** 1: the .vtu of a 3D mesh (cvm_mesh_write()) holds each kept merged dual cell
     *  (cvm_mesh_copy_dual3_merge_groups(), CVM_OPT_DUAL3_MERGE_TOL) as one
     *  VTK_POLYHEDRON (42) cell, its faces the group's boundary triangles oriented
     *  outwards, and every other tetrahedron as a VTK_POLYHEDRON of its 4 faces (a
     *  file of polyhedra only, which meshio reads too: "faces" / "faceoffsets"
     *  arrays), in the order of each cell's smallest tetrahedron; cell data
     *  "tetrahedron" (that index) and "attribute" (its region, when there are
     *  regions). ASCII. 0 (default): one VTK_TETRA per tetrahedron. Other formats
     *  and 2D meshes ignore it; cvm_mesh_read() does not read such a file back.
     *  Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_VTU_MERGED_CELLS = 605,

    /* ---- 700-799: reserved for the 3D kernel ---- */
    /** 3D mesh generation (cvm_mesh_generate3()), 740-749. Boundary grading g: the size
     *  near the surface is each surface triangle's mean edge length l and grows away from
     *  it as l + g * distance, capped by the size given to cvm_mesh_generate3(). Default
     *  0.3, bounds [0.01, 100]. Ignored when CVM_OPT_GEN3_SIZE_FROM_SURFACE is 0. @since 0.2 */
    CVM_OPT_GEN3_GRADING = 740,
    /** Near-field layers of the advancing front. Default 1, integer, bounds [1, 16]; only
     *  1 is implemented in this version (more: CVM_E_UNSUPPORTED). @since 0.2 */
    CVM_OPT_GEN3_LAYERS = 741,
    /** Free-space method: CVM_GEN3_FREESPACE_LATTICE (0, default: BCC lattice),
     *  CVM_GEN3_FREESPACE_OCTREE (1: centroids of a 2:1-balanced octree) or
     *  CVM_GEN3_FREESPACE_REFINE (2: Delaunay refinement by circumcentres, at most
     *  CVM_OPT_MAX_STEINER points when that is set). Integer, bounds [0, 2]. See
     *  cvm_mesh_generate3(). @since 0.2 */
    CVM_OPT_GEN3_FREESPACE = 742,
    /** 1 (default): the size follows the surface's own triangles (see
     *  CVM_OPT_GEN3_GRADING); 0: the size is uniform. Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_GEN3_SIZE_FROM_SURFACE = 743,
    /** The surface before the points are placed: CVM_GEN3_SURFACE_AS_GIVEN (0, default) or
     *  CVM_GEN3_SURFACE_REMESH_PLANAR (1: every planar facet of two or more coplanar
     *  triangles re-meshed by the 2D frontal refiner at the 3D size, the points on edges
     *  shared by two facets made once for both; other triangles kept as given, and a facet
     *  whose refinement would put a point on one of their edges is only re-triangulated),
     *  or CVM_GEN3_SURFACE_REMESH_ALL (2: every triangle, curved ones too, re-meshed
     *  isotropically; see cvm_gen3_surface). Integer, bounds [0, 2]. @since 0.2 */
    CVM_OPT_GEN3_SURFACE = 744,
    /** CVM_GEN3_FREESPACE_OCTREE only: 1 splits once, after the 2:1 balance, every leaf
     *  octant with a split octant of its own size across a face (the finer leaves' corners
     *  hang on its face), then balances again: more points (about 1.4x on the sphere in a
     *  box) and a smoother transition between sizes. 0 (default): the balanced tree as it
     *  is. Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_GEN3_OCTREE_SPLIT_HANGING = 745,
    /** 3D dual optimisation (cvm_mesh_optimise_dual3()), 750-759. Sweep limit, integer,
     *  default 50, bounds [0, 1e6] (0: measure only). @since 0.2 */
    CVM_OPT_DUAL3_MAX_SWEEPS = 750,
    /** No move may make a dihedral angle of the moved vertex's tetrahedra smaller than
     *  min(this, the smallest there before), degrees. Default 10, bounds [0, 60]. @since 0.2 */
    CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG = 751,
    /** Trial positions per vertex and sweep (compass search), integer, default 48, bounds
     *  [1, 100000]. @since 0.2 */
    CVM_OPT_DUAL3_BUDGET = 752,
    /** The power vertex is wanted this x the tetrahedron's root-mean-square edge inside each face;
     *  default 0.03, bounds [0, 0.2]. Compliance itself is the exact strict test. @since 0.2 */
    CVM_OPT_DUAL3_MARGIN = 753,
    /** 1 (default): a boundary vertex all of whose boundary faces lie in one axis-aligned
     *  plane (inside a planar facet such as a box side) moves within that plane, exactly;
     *  0: every boundary vertex keeps its position (its weight is free either way); 2: as
     *  1, and also a vertex of the boundary (no internal facet at it) whose boundary
     *  faces all turn less than 25 degrees from their mean normal (inside a smooth curved
     *  patch or an oblique plane) slides: trial points in that normal's tangent plane are
     *  put on the nearest point of its faces as they were when the run began, so every
     *  vertex stays on the input surface; the new chords change the volume slightly on
     *  curved patches. Edges and corners (sharper bends) never move. Integer, bounds
     *  [0, 2] (2 since 0.2 as well). @since 0.2 */
    CVM_OPT_DUAL3_SLIDE_BOUNDARY = 754,
    /** Merge tolerance of the 3D dual (cvm_mesh_copy_dual3_merge_groups(), measures
     *  725-728), a fraction of the local ideal dual edge l_V = 0.38 x l; default 0.1,
     *  bounds [0, 1]; 0 merges nothing. l at a face is the mean of the local sizes of
     *  its 3 corners, each the mean length of the vertex's edges (taken from the mesh,
     *  so merge decisions can be recomputed from the mesh alone). Two tetrahedra of one
     *  region sharing a face that is not constrained (not on the boundary, not an
     *  internal facet of the surface) belong to the same merged cell when their power
     *  vertices coincide (exact power test) or are closer than tol x l_V. Read by the
     *  measures and copies only; the mesh never changes. @since 0.2 */
    CVM_OPT_DUAL3_MERGE_TOL = 755,
    /** 1 (default): cvm_mesh_optimise_dual3() may change the connectivity: a trial move
     *  that leaves faces not locally regular is followed by exact 2-3 and 3-2 flips of
     *  unconstrained faces between tetrahedra of one region until every face there is
     *  locally regular again (else the move is undone), and a first pass flips the faces
     *  of the input that are not; the surface triangles stay faces and no vertex is
     *  lost, but tetrahedra are renumbered and their count changes. 0: the connectivity
     *  is kept. Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_DUAL3_FLIPS = 756,
    /** The per-vertex search of cvm_mesh_optimise_dual3(): 1 (default) compass search
     *  (CVM_OPT_DUAL3_BUDGET trials); 2 Modified Cuckoo Search (Walton et al. 2011;
     *  population 10 x the vertex's degrees of freedom, 40 for an interior vertex,
     *  CVM_OPT_DUAL3_CUCKOO_BUDGET evaluations, streams keyed by (CVM_OPT_SEED, sweep,
     *  vertex)), whose best points are then tried under the same exact checks; 3 the
     *  compass search, then the cuckoo search at the vertices where it found no move.
     *  Integer, bounds [1, 3]. @since 0.2 */
    CVM_OPT_DUAL3_SOLVER = 757,
    /** Evaluations of the star's penalty per vertex and sweep of the cuckoo search
     *  (CVM_OPT_DUAL3_SOLVER 2 or 3), integer, default 300, bounds [40, 1000000].
     *  @since 0.2 */
    CVM_OPT_DUAL3_CUCKOO_BUDGET = 758,
    /** What cvm_mesh_optimise_dual3() does when its sweeps stall (three sweeps without a
     *  new least count of tetrahedra outside, or a sweep without a move): with 1 (default)
     *  it stops; with E > 1 it doubles the compass search's budget (CVM_OPT_DUAL3_BUDGET)
     *  and searches every vertex again, until the budget has reached E times its start
     *  and stalls once more. CVM_OPT_DUAL3_MAX_SWEEPS and the time limit still bound the
     *  run. Integer, bounds [1, 64]. @since 0.2 */
    CVM_OPT_DUAL3_ESCALATE = 759,
    /* ---- quad-dominant meshing (800-899): read by cvm_mesh_quadmesh() ---- */
    /** Exponent p of the Lp-CVT energy, even integer, default 6, bounds [2, 12]. p = 2 is
     *  the classic CVT (hexagonal cells); larger p pulls the cells towards squares of unit
     *  metric size aligned with the eigenvectors of the metric. @since 0.2 */
    CVM_OPT_QUAD_P = 800,
    /** Corrections kept by L-BFGS, integer, default 8, bounds [1, 64]. @since 0.2 */
    CVM_OPT_QUAD_LBFGS_MEMORY = 801,
    /** Gradient stop of the optimiser: |grad E|_inf <= this x E / L (L the larger side of
     *  the domain's bounding box), default 1e-10, bounds [0, 1]. The run also stops when E
     *  decreases by less than 1e-12 (relative) over 10 iterations, at
     *  CVM_OPT_QUAD_MAX_ITERATIONS or at the time limit. @since 0.2 */
    CVM_OPT_QUAD_GRADIENT_TOL = 802,
    /** Iteration limit of each L-BFGS run, integer, default 10000, 0 = none, bounds
     *  [0, 1e9]. Counts work, so the result stays reproducible. @since 0.2 */
    CVM_OPT_QUAD_MAX_ITERATIONS = 803,
    /** Recombination into quads: 0 Blossom-Quad (default; maximum-weight matching),
     *  1 greedy (pairs by decreasing quality), 2 none (the cells are the triangles).
     *  Integer, bounds [0, 2]. @since 0.2 */
    CVM_OPT_QUAD_RECOMBINE = 804,
    /** Quality threshold of the recombination, default 0.5, bounds [0, 1]: two triangles
     *  form a quad only when the quad's quality 1 - max|corner - 90 deg| / 90 deg, corners
     *  measured in the metric at its centroid, is at least this; a quad that is not
     *  strictly convex (exact orientation tests) is never formed. @since 0.2 */
    CVM_OPT_QUAD_MIN_QUALITY = 805,
    /** Boundary cells of the energy: 0 (default) reconstructed from ghost sites at unit
     *  metric length outside each boundary site (Ekelschot et al.); 1 clipped to the domain.
     *  Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_QUAD_CLIP = 806,
    /** Metric sampling of the energy: 0 (default) M(y) at every quadrature point; 1 the
     *  metric of each site over its whole cell (every integral exact, a C^1 energy, about
     *  half the time). Integer, bounds [0, 1]. @since 0.2 */
    CVM_OPT_QUAD_CELLWISE_METRIC = 807,
    /** Escapes from a local minimum after convergence, integer, default 0, bounds
     *  [0, 64]: the site of least cell energy moves into the cell of most energy and the
     *  sites are optimised again; kept only when E drops. @since 0.2 */
    CVM_OPT_QUAD_RELOCATIONS = 808,
    /** The distance of the energy's Voronoi cells: 0 Euclidean; 1 the metric
     *  m0 = gbar / sqrt(det gbar), gbar the mean of g over the initial interior sites (unit
     *  determinant, so the same cell areas): the sites are optimised in the coordinates
     *  z = M0 x (M0^T M0 = m0), where a constant metric becomes isotropic and its quads
     *  square; 2 (default) as 1 when the metric is a constant tensor
     *  (cvm_sizing_set_metric_constant(), where the map is exact), else as 0. Nothing
     *  changes when gbar is a multiple of the identity. The energy, its value and the
     *  outputs stay in x (|grad E| is reported in z). Integer, bounds [0, 2]. @since 0.2 */
    CVM_OPT_QUAD_MEAN_METRIC_VORONOI = 809,
    /** The initial interior sites, integer, bounds [0, 1]: 0 (default) an advancing front
     *  in metric space, unit metric steps along the metric's eigenvectors (along the
     *  nearest domain edge where the metric is isotropic) from the boundary sites, so the
     *  optimisation starts near a lattice of metric squares; 1 the metric density sampled
     *  by rejection on a Halton sequence rotated by CVM_OPT_SEED.
     *  @since 0.2 */
    CVM_OPT_QUAD_INITIAL_SITES = 810,
    /** Sweeps of smoothing after the recombination, integer, default 200 (0: none),
     *  bounds [0, 1000]; the sweeps stop early once nothing moves. Each interior vertex
     *  with a quad moves to the mean of its quad-edge neighbours, or else part of the way
     *  to the mean of the points that would make its quads parallelograms (affine
     *  invariant, so a lattice of metric squares is left as it is); a move is kept only
     *  when every cell around it stays strictly convex (exact) and the cost of its quads
     *  drops: squared metric corner deviations from 90 degrees plus squared angles of
     *  their edges to the metric's eigenvectors weighted by the anisotropy
     *  (lam1 - lam2) / (lam1 + lam2). The sites are then triangulated again, so the
     *  triangles stay the Delaunay triangulation of the final sites; the quads and
     *  triangles of the mixed cells keep their vertices. @since 0.2 */
    CVM_OPT_QUAD_SMOOTH = 811,
    /** All-quad output, integer, default 0, bounds [0, 1]: 1 runs the Lp-CVT and the
     *  recombination in the metric g / 4 (cells twice the size), then splits each quad
     *  into 4 and each remaining triangle into 3 quads through its vertex centroid and
     *  its edge midpoints, so every cell is a quad of about unit metric size. The new
     *  points join the sites and the triangles (CVM_ENT_TRIANGLE) are their Delaunay
     *  triangulation; smoothing (CVM_OPT_QUAD_SMOOTH) then applies to the split cells.
     *  Needs a recombination (CVM_OPT_QUAD_RECOMBINE 0 or 1; 2 gives CVM_E_ARGUMENT).
     *  @since 0.2 */
    CVM_OPT_QUAD_ALL_QUAD = 812,
    /** Insertion/removal cycles after the optimisation, integer, default 3, bounds
     *  [0, 20]: while fewer than 95 % of the sides among the Delaunay edges of the sites
     *  (an edge with a moving end that is not the longest of every triangle beside it,
     *  so quad diagonals do not count) have a metric length in [1/sqrt 2, sqrt 2], each
     *  shorter side loses its moving end with the larger spread of edge lengths, each
     *  longer one gets a site at its midpoint, and the sites are optimised again. Stops
     *  when nothing changes. @since 0.2 */
    CVM_OPT_QUAD_CYCLES = 813
    /* ---- 1000 and up: experimental (include/cvmesh_experimental.h) ---- */
} cvm_option;

/** Values of CVM_OPT_GEN3_FREESPACE. */
typedef enum cvm_gen3_freespace {
    CVM_GEN3_FREESPACE_LATTICE = 0, /**< body-centred cubic lattice (implemented) */
    CVM_GEN3_FREESPACE_OCTREE = 1,  /**< centroids of a 2:1-balanced octree (implemented) */
    CVM_GEN3_FREESPACE_REFINE = 2   /**< Delaunay refinement by circumcentres (implemented) */
} cvm_gen3_freespace;

/** Values of CVM_OPT_GEN3_SURFACE. */
typedef enum cvm_gen3_surface {
    CVM_GEN3_SURFACE_AS_GIVEN = 0,      /**< the surface's triangles are used as read */
    CVM_GEN3_SURFACE_REMESH_PLANAR = 1, /**< planar facets re-meshed in 2D at the 3D size */
    /** The whole surface re-meshed with near-equilateral triangles (edge splits, collapses,
     *  Delaunay flips and smoothing projected back onto the input): target edge length the
     *  least of the size, the user sizing and 0.3 / curvature (radians of normal turn per
     *  edge), graded by CVM_OPT_GEN3_GRADING along the surface; edges between facets of
     *  different markers or sharper than 35 degrees are kept as feature lines (split, never
     *  flipped; their bends never move). New points lie on the input triangles. For
     *  surfaces whose triangles are needles (a wing with fine chordwise and coarse spanwise
     *  spacing). @since 0.2 */
    CVM_GEN3_SURFACE_REMESH_ALL = 2
} cvm_gen3_surface;

/** Values of CVM_OPT_VTU_ENCODING. */
typedef enum cvm_vtu_encoding {
    CVM_VTU_ASCII = 0,  /**< text data arrays */
    CVM_VTU_BINARY = 1, /**< raw appended binary data */
    CVM_VTU_ZLIB = 2,   /**< raw appended binary data in zlib-compressed blocks */
    CVM_VTU_AUTO = 3    /**< the default: ASCII up to CVM_VTU_AUTO_MAX_ASCII_POINTS
                             vertices, CVM_VTU_BINARY above */
} cvm_vtu_encoding;

/** The most vertices of a .vtu that CVM_VTU_AUTO writes as ASCII. */
#define CVM_VTU_AUTO_MAX_ASCII_POINTS 1000000

/** Bounds of an option; the one frozen struct of the ABI. */
typedef struct cvm_bounds {
    double lo;          /**< smallest accepted value */
    double hi;          /**< largest accepted value */
    double def;         /**< default */
    int32_t is_integer; /**< 1: value must be a whole number */
} cvm_bounds;

/**
 * Bounds and default of option @p key.
 * Thread-safety: callable from any thread.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_OPTION_KEY
 * @since 0.1
 */
CVM_API cvm_status cvm_option_bounds(cvm_bounds *out, cvm_option key);

/**
 * Set option @p key of @p m. Values are never clamped.
 * @return CVM_OK
 *         CVM_E_NULL_ARG, CVM_E_OPTION_KEY
 *         CVM_E_OPTION_RANGE  value outside the bounds, NaN, or not whole for an integer option
 *                             (the message quotes the bounds)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_option(cvm_mesh *m, cvm_option key, double value);

/**
 * Read option @p key of @p m.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_OPTION_KEY
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_get_option(double *out, const cvm_mesh *m, cvm_option key);

/** Stages reported to a progress callback. */
typedef enum cvm_stage {
    CVM_STAGE_READ = 1,
    CVM_STAGE_SORT = 2,
    CVM_STAGE_INSERT = 3,
    CVM_STAGE_RECOVER_SEGMENTS = 4,
    CVM_STAGE_CARVE = 5,
    CVM_STAGE_WRITE = 6,
    CVM_STAGE_REFINE = 7,
    CVM_STAGE_SMOOTH = 8,
    CVM_STAGE_OPTIMISE_DUAL = 9,
    CVM_STAGE_QUAD_OPTIMISE = 10 /**< the Lp-CVT optimisation of cvm_mesh_quadmesh() @since 0.2 */
} cvm_stage;

/**
 * Progress callback: @p fraction in [0, 1] of the current stage. Return 0 to
 * go on, non-zero to stop the run (CVM_INCOMPLETE_CANCELLED). It must not call
 * any function on the handle that called it.
 */
typedef int (*cvm_progress_fn)(void *payload, cvm_stage stage, double fraction);

/**
 * Install a progress callback, called about every @p every_n elementary
 * operations (point insertions, segment recoveries, holes and regions carved
 * (CVM_STAGE_CARVE, a hole counting the triangles it removes), segment splits
 * planned before refinement, values written) of long calls; cvm_mesh_read()
 * calls it every 64 KiB read. The time limit CVM_OPT_TIME_LIMIT_S is checked at
 * the same points (every 1024 operations when no callback is set), except in
 * reads and writes. fn NULL or every_n < 1 removes it.
 * What a stop leaves is documented by each long call.
 * @return CVM_OK, CVM_E_NULL_ARG (m NULL)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_progress(cvm_mesh *m, cvm_progress_fn fn, int64_t every_n,
                                         void *payload);

/* ------------------------------------------------------------------------ */
/* Meshing                                                                   */
/* ------------------------------------------------------------------------ */

/**
 * Triangulate the input: the Delaunay triangulation of the points, or with
 * segments the constrained Delaunay triangulation of the PSLG with exterior
 * and holes removed and regional attributes assigned. Duplicate points are
 * merged (vertex ids then skip them; see cvm_mesh_copy_input_map()). An input
 * point lying exactly in the interior of a segment splits it. Replaces any
 * previous triangulation.
 *
 * Rounded crossings: two segments that cross (CVM_OPT_SPLIT_INTERSECTIONS = 1)
 * are split at a new vertex, their crossing point rounded to doubles, so it
 * may lie off both by a few units in the last place (ulps) of the coordinates.
 * Where that double cannot split the crossed piece, it is moved up to 64 ulps
 * across the piece; where it lies within 16 ulps of an end of the piece (a
 * third segment through the same point), or no nearby double can split the
 * piece (nearly coincident segments), the segment passes through that end
 * instead. A piece from a rounded vertex may also pass exactly through an
 * input point near the segment, which then joins its chain. Every inner
 * vertex of a segment's chain lies on the segment or within 2^-40 (M + L) of
 * it, M the largest absolute coordinate of the segment's ends and L its
 * length; cvm_mesh_check() accepts exactly that. CVM_OK implies that every
 * segment is such a chain of constrained edges (verified before returning,
 * in linear time).
 *
 * On a 3D handle (cvm_mesh_dim() 3): without facets, the Delaunay
 * tetrahedralisation of the points (regular once weights are set), decided by
 * exact predicates with symbolic perturbation by input index, so cospherical
 * input (lattices) has one answer and the output is the same for every seed
 * and thread count; vertices are the points less duplicates, in input order;
 * tetrahedra are positively oriented and listed in a canonical order. With a
 * surface (cvm_mesh_read() of .off/.stl/.poly/.smesh): the surface is
 * validated (closed, manifold, consistently oriented, not self-intersecting;
 * internal facets between regions allowed), then its inside is tetrahedralised
 * with the surface's triangles as faces (CVM_ENT_TRIANGLE, with the facets'
 * markers), hole points emptied and region points' attributes flooded. Without
 * hole or region points the triangles' orientation tells the holes: a triangle
 * faces (right-hand rule) out of the domain, so a closed shell whose triangles
 * face into it (a sphere inside a box in the usual .off/.stl convention) is
 * left empty, Steiner points inside it included; when the orientation
 * contradicts itself (internal facets, or shells facing other ways) nothing is
 * emptied beyond the outside of the outer surface. A build
 * with TetGen (cvm_build_string()) recovers the boundary with it (inserting
 * Steiner points inside only when it must: CVM_MEASURE_RECOVERY_STEINER); a
 * build without it requires every surface triangle to be a face of the
 * Delaunay tetrahedralisation of the surface's points and otherwise returns
 * CVM_E_UNSUPPORTED naming the first that is not.
 *
 * Stops: triangulation cannot stop half-way; on a time limit or cancellation
 * the mesh is left empty (count 0) and CVM_INCOMPLETE_* is returned.
 * @return CVM_OK
 *         CVM_E_NULL_ARG
 *         CVM_E_INPUT_EMPTY        no points, or carving left no triangle
 *         CVM_E_INPUT_DEGENERATE   fewer than 3 distinct points, all points collinear, a
 *                                  zero-length segment (message gives segment k), or a nonzero
 *                                  coordinate more than 2^180 times smaller than the largest
 *                                  (beyond what the exact predicates can span; message gives
 *                                  the point)
 *         CVM_E_INPUT_INDEX        a segment names a point that does not exist
 *         CVM_E_INPUT_DUPLICATE    duplicate points with CVM_OPT_REJECT_DUPLICATES
 *         CVM_E_INPUT_INTERSECTING crossing segments with CVM_OPT_SPLIT_INTERSECTIONS = 0
 *         CVM_E_INPUT_NOT_CLOSED   removing the exterior or a hole removed every triangle
 *                                  (the boundary does not close)
 *         CVM_E_INPUT_OUTSIDE      a hole point lies outside the convex hull
 *         CVM_E_NOMEM
 *         CVM_E_INTERNAL           a kernel fault, e.g. a segment left without its chain
 *                                  (message names the input segment), or a crossing that
 *                                  no double can split: segments crossing beside a sliver
 *                                  thinner than an ulp, with no piece end near the crossing
 *                                  (message names the vertex); the mesh is left empty
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 *         3D: CVM_E_INPUT_DEGENERATE (fewer than 4 distinct points, all coplanar, a
 *         degenerate or non-planar face), CVM_E_INPUT_NOT_CLOSED (an open edge or a
 *         flipped face), CVM_E_INPUT_INTERSECTING (faces that cross, a non-manifold edge
 *         or vertex), CVM_E_UNSUPPORTED (a non-convex facet polygon, a facet with holes;
 *         without TetGen a surface triangle that is no Delaunay face); messages name the
 *         faces in the file's numbering
 * @since 0.1 (3D since 0.2)
 */
CVM_API cvm_status cvm_mesh_triangulate(cvm_mesh *m);

/**
 * Insert points into the current triangulation (Bowyer-Watson cavity,
 * respecting segments: a cavity never crosses a constrained edge). A point
 * outside the domain, on an existing vertex, or closer than @p min_dist to an
 * existing vertex is rejected; with weights set (cvm_mesh_set_weights()) new
 * points get weight 0, and a point whose power cell would be empty is rejected
 * too. A point exactly on a segment splits it. A 3D mesh takes its points
 * through cvm_mesh_insert_points_nd() (this call gives CVM_E_UNSUPPORTED there).
 * min_dist rule: the squared distance, rounded to double as (dx^2 + dy^2),
 * against min_dist^2, to every vertex of a triangle of the domain, also one
 * behind a segment (a vertex only in holes or outside the domain is not seen).
 *
 * @param ids_out  count entries: the new vertex id of each point, or CVM_REJECTED;
 *                 may be NULL.
 * @param xy       2*count coordinates. Ownership: read only during the call.
 * @param min_dist reject a point closer than this to an existing vertex; 0 rejects only
 *                 exact coincidence. Units: length.
 * Stops: points inserted before a stop stay; the rest get CVM_REJECTED.
 * @return CVM_OK
 *         CVM_E_NULL_ARG, CVM_E_STATE (no triangulation yet)
 *         CVM_E_INPUT_NONFINITE  a coordinate (message gives the point) or min_dist is not finite
 *         CVM_E_ARGUMENT         min_dist < 0
 *         CVM_E_NOMEM  (points inserted before it stay; their ids are written)
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xy,
                                          size_t count, double min_dist);

/**
 * cvm_mesh_insert_points() in the mesh's dimension: dim coordinates per point,
 * the same rules, stops and statuses.
 *
 * 3D (a mesh made by cvm_mesh_triangulate() from 3D points or a surface): each
 * point is inserted by a Bowyer-Watson cavity, the tetrahedra whose circumsphere
 * (orthosphere with weights) contains it by the exact predicates with symbolic
 * perturbation by vertex id, grown from the tetrahedron holding it and never
 * across a constrained face (a face of the surface, internal facets included).
 * - Rejected (CVM_REJECTED): a point strictly outside the convex hull of a
 *   point set's tetrahedralisation (as in 2D; a point on the hull is inserted
 *   and splits the hull face), outside a surface's mesh or in one of its
 *   holes, on a constrained face or edge (a surface's, which is never split),
 *   on an existing vertex, closer than @p min_dist to a vertex (rule below),
 *   with weights a point whose power cell would be empty or that would empty
 *   the power cell of a vertex (no vertex ever leaves the mesh).
 * - min_dist rule: the squared distance to every vertex of the mesh, rounded
 *   to double as (dx^2 + dy^2 + dz^2), against min_dist^2 (the 2D rule). In a
 *   Delaunay tetrahedralisation the nearest vertex is always a vertex of the
 *   point's cavity, which is all that is tested; in a regular or constrained
 *   mesh the test also covers the vertices of every tetrahedron near the ball
 *   of radius min_dist (behind a constrained face, say). A vertex in no
 *   tetrahedron (its power cell vanished) is not seen.
 * - Result: new vertices take the ids nv, nv + 1, ... in input order (rejected
 *   points take none) with weight 0; the tetrahedra come back in the canonical
 *   order of cvm_mesh_triangulate() (deterministic). On a point set's Delaunay
 *   tetrahedralisation the result is the Delaunay tetrahedralisation of the
 *   vertices and the inserted points, byte for byte what cvm_mesh_triangulate()
 *   makes of them; with weights, the regular one (cvm_mesh_check() verifies
 *   both). On a surface's mesh, every surface triangle and internal facet stays
 *   a face with its marker, a new tetrahedron takes the region attribute of the
 *   region it is in, each face between a new tetrahedron and an old one is
 *   locally Delaunay (the old one does not conflict with the point), and a mesh
 *   that was constrained Delaunay with the same perturbation stays so (it then
 *   becomes the constrained Delaunay tetrahedralisation with the points). A mesh
 *   that is not (TetGen's recovery breaks cospherical ties its own way) can
 *   need a smaller cavity: tetrahedra are left out of it until every face of
 *   its boundary sees the point strictly (new tetrahedra always positive).
 *   cvm_mesh_check() checks orientation, adjacency and every surface face; the
 *   Delaunay property it checks only on a point set's mesh.
 * - Cost: the mesh is loaded into the kernel's store once per call (linear
 *   in its size): insert many points per call.
 *
 * @param ids_out  count entries (new vertex id or CVM_REJECTED); may be NULL.
 * @param m        mesh handle, triangulated; not NULL.
 * @param coords   dim*count coordinates. Ownership: read only during the call.
 * @param count    number of points.
 * @param dim      the mesh's dimension, 2 or 3 (cvm_mesh_dim()).
 * @param min_dist as cvm_mesh_insert_points(). Units: length.
 * Stops: points inserted before a stop stay (ids written); the rest get CVM_REJECTED.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * @return those of cvm_mesh_insert_points(), and
 *         CVM_E_ARGUMENT     dim is neither 2 nor 3, or not the mesh's (nothing inserted)
 *         CVM_E_UNSUPPORTED  dim 3 on a 2D mesh (nothing inserted; message says so)
 *         3D: CVM_E_INPUT_NONFINITE names the point and its coordinate (nothing
 *         inserted); CVM_E_INPUT_DEGENERATE a nonzero coordinate more than 2^100
 *         below the largest magnitude of the mesh and the points (beyond the exact
 *         predicates; nothing inserted); CVM_E_TOO_LARGE more than 60 million
 *         vertices; CVM_E_NOMEM: the points before it stay, except when memory
 *         ran out while the mesh was written back: then nothing is inserted and
 *         every id is CVM_REJECTED
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_insert_points_nd(cvm_index *ids_out, cvm_mesh *m, const double *coords,
                                             size_t count, int dim, double min_dist);

/**
 * Re-verify @p m with exact predicates: every triangle counter-clockwise,
 * adjacency symmetric, each edge in at most two triangles, every input segment
 * a chain of constrained mesh edges from end to end, through vertices on it or
 * within 2^-40 (M + L) of it (rounded crossings, see cvm_mesh_triangulate();
 * meshing uses it only to route a chain, or with cvm_mesh_refine() a hull
 * edge, through a vertex within rounding of it, see cvm_mesh_refine())
 * (segments of a chain re-discretised by CVM_OPT_KEEP_SEGMENT_VERTICES = 0,
 * whose inner ends are gone, are replaced by its new pieces, checked as
 * constrained edges), every interior
 * non-constrained edge locally Delaunay (in-circle, or the power test with
 * weights), the domain bounded by constrained edges or the convex hull.
 * On a 3D mesh: every tetrahedron positively oriented (exact orient3d), each
 * face shared by at most two tetrahedra that see it from opposite sides, every
 * listed boundary face a face of the mesh, and for a point set's
 * tetrahedralisation every interior face locally Delaunay (insphere, or the
 * power test with weights, with the symbolic perturbation of the kernel).
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_STATE (nothing triangulated),
 *         CVM_E_INTERNAL (message names the failed check and the triangle or edge)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_check(cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* Sizing and refinement                                                     */
/* ------------------------------------------------------------------------ */

/**
 * Opaque sizing handle: the target edge length h(x, y) for cvm_mesh_refine(), or
 * h(x, y, z) for cvm_mesh_generate3_sized().
 * Sources combine by taking the minimum: h = min(uniform, every point source,
 * every line source, every triangle source, the background, the callback). A
 * handle with no source sets no size bound.
 * Dimension: a handle holds positional sources (point, line, triangle,
 * background) of one dimension, 2 or 3, fixed by the first one added; adding one
 * of the other dimension fails with CVM_E_ARGUMENT naming it and the handle's
 * first source (the handle is unchanged). The uniform size, the boundary grading
 * and the cvm_sizing_set_callback_nd() function serve both; the (x, y) and batch
 * callbacks and the automatic sizing are 2D only.
 * The handle has its own messages (cvm_sizing_errmsg()) and may be used by any
 * number of refinements, one call at a time.
 */
typedef struct cvm_sizing cvm_sizing;

/**
 * User sizing function: the target edge length at (x, y), positive and finite.
 * It must not call any function on the mesh being refined.
 */
typedef double (*cvm_sizing_fn)(void *payload, double x, double y);

/**
 * Create an empty sizing handle (no size bound).
 *
 * @param out  receives the handle; set to NULL on failure.
 * Ownership:  the caller owns *out and releases it with cvm_sizing_free().
 * Thread-safety: callable from any thread.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  out is NULL
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_create(cvm_sizing **out);

/**
 * Free a sizing handle. NULL is a no-op. Meshes refined with it are not affected.
 * @since 0.1
 */
CVM_API void cvm_sizing_free(cvm_sizing *s);

/**
 * Message describing the last failing call on @p s, naming the offending source,
 * e.g. "point source 2 has size -1 (must be positive and finite)".
 * Ownership: owned by @p s; valid until the next call on @p s.
 * @return "" when the last call succeeded; "no sizing handle" when s is NULL.
 * @since 0.1
 */
CVM_API const char *cvm_sizing_errmsg(const cvm_sizing *s);

/**
 * Set a uniform target edge length (replaces an earlier uniform size).
 *
 * @param s  sizing handle; not NULL.
 * @param h  target edge length; positive and finite.
 * Units:    length.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  h is NaN or infinite (message names "uniform size")
 *         CVM_E_ARGUMENT         h <= 0 (message names "uniform size")
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_set_uniform(cvm_sizing *s, double h);

/**
 * Add a point source: h(p) = h + growth * |p - (x, y)|.
 *
 * @param x, y    source position.
 * @param h       size at the source; positive and finite.
 * @param growth  size increase per unit distance (dimensionless), finite and >= 0;
 *                0 gives h everywhere. Typical: 0.1 .. 0.5.
 * Units:    lengths; growth dimensionless.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (message names point source k)
 *         CVM_E_ARGUMENT         h <= 0 or growth < 0 (message names point source k)
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_add_point_source(cvm_sizing *s, double x, double y, double h,
                                               double growth);

/**
 * Add a line source on the segment (x0, y0)-(x1, y1): h(p) = h + growth * dist(p, segment).
 * Parameters, units and atomicity as cvm_sizing_add_point_source(); the two ends may coincide.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (message names line source k)
 *         CVM_E_ARGUMENT         h <= 0 or growth < 0 (message names line source k)
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_add_line_source(cvm_sizing *s, double x0, double y0, double x1,
                                              double y1, double h, double growth);

/**
 * cvm_sizing_add_point_source() with the position in the mesh's dimension:
 * h(p) = h + growth * |p - x|.
 *
 * @param s       sizing handle; not NULL.
 * @param x       dim coordinates of the source.
 * @param dim     2 or 3 (the handle's dimension, see cvm_sizing).
 * @param h, growth  as cvm_sizing_add_point_source().
 * Units: lengths; growth dimensionless. Ownership: x is copied.
 * Thread-safety: one call at a time on @p s.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s or x is NULL
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3; h <= 0 or growth < 0 (names point source k);
 *                                the handle holds sources of the other dimension (names both)
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (names point source k)
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_add_point_source_nd(cvm_sizing *s, const double *x, int dim,
                                                  double h, double growth);

/**
 * cvm_sizing_add_line_source() with the ends in the mesh's dimension:
 * h(p) = h + growth * dist(p, segment).
 *
 * @param s       sizing handle; not NULL.
 * @param ends    2*dim coordinates: the first end, then the second (they may coincide).
 * @param dim     2 or 3 (the handle's dimension, see cvm_sizing).
 * @param h, growth  as cvm_sizing_add_point_source().
 * Units, ownership, thread-safety and atomicity as cvm_sizing_add_point_source_nd().
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s or ends is NULL
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3; h <= 0 or growth < 0 (names line source k);
 *                                the handle holds sources of the other dimension (names both)
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (names line source k)
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_add_line_source_nd(cvm_sizing *s, const double *ends, int dim,
                                                 double h, double growth);

/**
 * Add a triangle source: h(p) = h + growth * dist(p, triangle), the distance to the
 * nearest point of the (closed, filled) triangle; in 3D a surface patch, in 2D an
 * area. A degenerate triangle (collinear corners) acts as the union of its edges.
 *
 * @param s        sizing handle; not NULL.
 * @param corners  3*dim coordinates: the three corners one after the other.
 * @param dim      2 or 3 (the handle's dimension, see cvm_sizing).
 * @param h, growth  as cvm_sizing_add_point_source().
 * Units, ownership, thread-safety and atomicity as cvm_sizing_add_point_source_nd().
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s or corners is NULL
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3; h <= 0 or growth < 0 (names triangle
 *                                source k); the handle holds sources of the other dimension
 *         CVM_E_INPUT_NONFINITE  a value is NaN or infinite (names triangle source k)
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_add_triangle_source_nd(cvm_sizing *s, const double *corners,
                                                     int dim, double h, double growth);

/**
 * cvm_sizing_set_background() in the mesh's dimension: sizes at the nodes of a
 * background triangulation (dim 2: triangles, exactly cvm_sizing_set_background())
 * or tetrahedral mesh (dim 3), interpolated linearly inside its cells (the least
 * value where cells overlap); outside them this source sets no bound. Replaces an
 * earlier background of the same dimension.
 *
 * @param s        sizing handle; not NULL.
 * @param xh       npoints nodes, dim + 1 doubles each: the coordinates and the size
 *                 there (positive and finite).
 * @param npoints  node count; npoints = ncells = 0 removes the background of that
 *                 dimension (then the pointers may be NULL).
 * @param dim      2 or 3 (the handle's dimension, see cvm_sizing).
 * @param cells    ncells cells, dim + 1 node indices each (0-based), either orientation.
 * @param ncells   cell count.
 * Ownership: copied. Units: length.
 * Thread-safety: one call at a time on @p s.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          s, or xh or cells (with ncells > 0) is NULL
 *         CVM_E_ARGUMENT          dim is neither 2 nor 3; a size is not positive (names node k);
 *                                 the handle holds sources of the other dimension
 *         CVM_E_INPUT_NONFINITE   a coordinate or size is NaN or infinite (names node k)
 *         CVM_E_INPUT_INDEX       a cell names a node outside [0, npoints) (names the cell)
 *         CVM_E_INPUT_DEGENERATE  a cell has zero area or volume, by the exact orientation
 *                                 test (names the cell)
 *         CVM_E_TOO_LARGE         more than INT32_MAX/4 nodes or cells
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_background_nd(cvm_sizing *s, const double *xh, size_t npoints,
                                                int dim, const cvm_index *cells, size_t ncells);

/**
 * Set (or, with fn NULL, remove) a user sizing function.
 *
 * @param fn       called with @p payload and a position; must return a positive finite
 *                 size and be deterministic (same answer for the same position).
 * @param payload  passed unchanged to fn; may be NULL.
 * Ownership: fn and payload must stay valid while the handle is used.
 * Errors of fn: a non-positive or non-finite value stops cvm_mesh_refine() (or
 *               cvm_sizing_eval()) with CVM_E_ARGUMENT / CVM_E_INPUT_NONFINITE naming
 *               "the sizing callback" and the position.
 * @return CVM_OK, CVM_E_NULL_ARG (s is NULL)
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_set_callback(cvm_sizing *s, cvm_sizing_fn fn, void *payload);

/**
 * User sizing function in the mesh's dimension: the target edge length at the
 * point @p x (@p dim coordinates, dim = the dimension of the mesh being refined or
 * generated: 2 for cvm_mesh_refine(), 3 for cvm_mesh_generate3_sized()),
 * positive and finite, deterministic. It must not call any function on the mesh
 * being refined.
 */
typedef double (*cvm_sizing_nd_fn)(void *payload, const double *x, int dim);

/**
 * Set (or, with fn NULL, remove) a user sizing function that takes the position
 * as an array. A handle has one user function: this replaces one set by
 * cvm_sizing_set_callback() and the other way round.
 *
 * @param s        sizing handle; not NULL.
 * @param fn       as cvm_sizing_nd_fn; NULL removes the user function.
 * @param payload  passed unchanged to fn; may be NULL.
 * Ownership: fn and payload must stay valid while the handle is used.
 * Errors of fn: as cvm_sizing_set_callback() (a value <= 0: CVM_E_ARGUMENT, NaN or
 *               infinite: CVM_E_INPUT_NONFINITE, naming "the sizing callback" and the
 *               position).
 * Thread-safety: one call at a time on @p s.
 * @return CVM_OK, CVM_E_NULL_ARG (s is NULL)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_callback_nd(cvm_sizing *s, cvm_sizing_nd_fn fn, void *payload);

/**
 * User sizing function asked for many points in one call: write the target
 * edge length at each of the @p n points @p xy (x0, y0, x1, y1, ...; 2n
 * doubles) into @p h_out[0 .. n-1], positive and finite. The size at a point
 * must depend on that point alone (deterministic, whatever the batch), so the
 * mesh is the one a cvm_sizing_fn of the same sizes gives. Return 0; any other
 * value stops the run that asked. It must not call any function on the mesh
 * being refined.
 */
typedef int (*cvm_sizing_batch_fn)(void *payload, const double *xy, size_t n, double *h_out);

/**
 * Set (or, with fn NULL, remove) a user sizing function that is asked for a
 * batch of points per call, for callers where one call costs much more than
 * one point (an interpreted language). cvm_mesh_refine() asks for the sizes at
 * every vertex of the mesh it starts from in batches of up to 1024 points, and
 * for each Steiner point it inserts one at a time (n = 1: each decides where
 * the next goes); every other evaluation (cvm_sizing_eval(), segment marching,
 * cvm_mesh_optimise_dual()) asks one point at a time. A handle has one user
 * function: this replaces one set by cvm_sizing_set_callback() or
 * cvm_sizing_set_callback_nd(), and they replace this one.
 *
 * @param s        sizing handle; not NULL.
 * @param fn       as cvm_sizing_batch_fn; NULL removes the user function.
 * @param payload  passed unchanged to fn; may be NULL.
 * Ownership: fn and payload must stay valid while the handle is used; @p xy
 *            is valid during the call only.
 * Errors of fn: a non-zero return stops the run with CVM_E_ARGUMENT naming "the
 *               sizing callback", the batch size and its first point; a size <= 0
 *               with CVM_E_ARGUMENT, NaN or infinite with CVM_E_INPUT_NONFINITE,
 *               naming "the sizing callback" and the position.
 * Thread-safety: one call at a time on @p s.
 * @return CVM_OK, CVM_E_NULL_ARG (s is NULL)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_batch_callback(cvm_sizing *s, cvm_sizing_batch_fn fn,
                                                 void *payload);

/**
 * Metric (tensor) function: at the point @p x (@p dim coordinates) write the
 * symmetric positive definite metric g into @p g as its dim*(dim+1)/2
 * upper-triangle entries, row by row (2D: g11, g12, g22; 3D: g11, g12, g13, g22,
 * g23, g33). An edge e has the metric length sqrt(e^T g e); an isotropic size h is
 * g = I / h^2. When @p dg is not NULL (only for a function installed with
 * has_derivatives = 1) also write the derivatives of those entries: dim blocks of
 * dim*(dim+1)/2 values, the block for d/dx_1 first. Return 0 when the point is
 * accepted, non-zero when the metric is not defined there. Deterministic; it must
 * not call any function on the mesh being meshed.
 */
typedef int (*cvm_metric_fn)(void *payload, const double *x, int dim, double *g, double *dg);

/**
 * Set (or, with fn NULL, remove) the metric (tensor) source of @p s, kept beside the
 * scalar sources. cvm_mesh_quadmesh() meshes to it (it needs has_derivatives = 1);
 * no other meshing call uses a metric, and none ignores it silently:
 * cvm_mesh_refine() and cvm_mesh_optimise_dual() given a sizing with a metric
 * return CVM_E_UNSUPPORTED and change nothing. cvm_sizing_eval() and
 * cvm_sizing_eval_nd() give the scalar size and do not read the metric;
 * cvm_sizing_eval_metric() evaluates it.
 *
 * @param s                sizing handle; not NULL.
 * @param fn               as cvm_metric_fn; NULL removes the metric.
 * @param has_derivatives  1: fn fills dg when it is given; 0: it is always called with
 *                         dg NULL (a user of derivatives then differentiates itself).
 * @param payload          passed unchanged to fn; may be NULL.
 * Ownership: fn and payload must stay valid while the handle is used.
 * Thread-safety: one call at a time on @p s.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  s is NULL
 *         CVM_E_ARGUMENT  has_derivatives is neither 0 nor 1 (handle unchanged)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_metric_fn(cvm_sizing *s, cvm_metric_fn fn, int has_derivatives,
                                            void *payload);

/** Built-in metric fields of cvm_sizing_set_metric_builtin(), each g(x, y) times a scale. */
typedef enum cvm_metric_builtin {
    CVM_METRIC_IDENTITY = 1, /**< g = I */
    CVM_METRIC_STRETCH = 2,  /**< g = diag(1, 1 + 4 y^2) (Ekelschot et al.'s case on [0,5]x[0,1.3]) */
    CVM_METRIC_SADDLE = 3,   /**< g = I + grad f grad f^T, f = x^2 - y^2 (on [-1.3,1.3]^2) */
    CVM_METRIC_SSHOCK = 4    /**< |Hessian| of 3/4 tanh(2 (sin 5y - 3x)), eigen-sizes clamped to
                                  [0.005, 0.2], aspect ratio <= 50 (on [-1,1]^2) */
} cvm_metric_builtin;

/**
 * Set the metric source of @p s to a built-in field times @p scale, with exact
 * derivatives (as cvm_sizing_set_metric_fn() with has_derivatives = 1; it replaces any
 * metric source). scale = 1/h^2 gives edges of length h where g = I.
 *
 * @param s      sizing handle; not NULL.
 * @param kind   a cvm_metric_builtin.
 * @param scale  > 0 and finite.
 * Ownership:    the handle keeps the field's parameters; nothing to keep for the caller.
 * Thread-safety: one call at a time on @p s; the field itself is reentrant.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  s is NULL
 *         CVM_E_ARGUMENT  an unknown kind, or scale not finite and positive (handle unchanged)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_metric_builtin(cvm_sizing *s, cvm_metric_builtin kind,
                                                 double scale);

/**
 * Set the metric source of @p s to the constant tensor (g11, g12, g22) (derivatives 0;
 * it replaces any metric source). An isotropic size h is (1/h^2, 0, 1/h^2).
 *
 * @param s  sizing handle; not NULL.
 * Thread-safety: one call at a time on @p s.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  an entry is NaN or infinite (handle unchanged)
 *         CVM_E_ARGUMENT         the tensor is not positive definite (handle unchanged)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_set_metric_constant(cvm_sizing *s, double g11, double g12,
                                                  double g22);

/**
 * Automatic sizing from the geometry of the domain being refined:
 *   LS(p) = min(lfs_c(p)/R, min over boundary points q of LS(q) + |q - p|/G).
 * lfs is the local feature size at a boundary point q: the distance from q to the
 * nearest feature (domain boundary or constrained edge, or an input point on none)
 * not incident to q (Ruppert's definition). Curved polylines: edges reached from q
 * along a chain of degree-2 vertices before it turns by 60 degrees in total count as
 * the same curve and are ignored, and lfs_c = min(lfs, radius of curvature), the
 * radius at a chain vertex with turning angle theta <= 30 degrees estimated as
 * (l1 + l2) / (2 theta) from its two edges. The field is sampled at the boundary
 * vertices and inside boundary edges (bisected until a piece is shorter than
 * min(1/2, G/R) of the local lfs), and is graded with slope 1/G away from them; the
 * lfs of interior points enters only through that grading.
 * The field is built by each cvm_mesh_refine() from its mesh (cost about that of a
 * nearest-feature query per sample); cvm_sizing_eval() has no domain and ignores it.
 * Combined with the other sources of the handle by the minimum.
 *
 * @param R  refinement parameter: edges per local feature size, positive and finite
 *           (e.g. 2-4).
 * @param G  grading: the size may grow by 1/G per unit of distance, positive and
 *           finite (e.g. 2-10; larger G grades more gently).
 *           R = G = 0 turns the automatic size off again.
 * Thread-safety: one call at a time on @p s.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  R or G is not finite
 *         CVM_E_ARGUMENT         R or G is not positive (message names it)
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_set_automatic(cvm_sizing *s, double R, double G);

/**
 * Grade the size away from the domain's own boundary spacing:
 *   h(p) <= min over boundary and constrained edges e of ( l(e) + g * dist(p, e) ),
 * with l(e) the length of e in the mesh being refined or optimised (input segments,
 * their pieces, hull edges). Short input segments (a finely spaced wall) then grow
 * into the interior at slope g instead of meeting the rest of the sizing within a
 * layer or two, which gives better-shaped triangles there (and, after
 * cvm_mesh_optimise_dual(), a larger smallest angle) for a few more vertices; Gmsh's
 * Mesh.MeshSizeExtendFromBoundary is the same idea. The field is sampled at the
 * edges' vertices (l = the shortest incident edge) and at about one point per l
 * inside longer edges (l = the edge's length), and is built by each
 * cvm_mesh_refine() and cvm_mesh_optimise_dual() from its mesh; cvm_sizing_eval()
 * has no domain and ignores it. Combined with the other sources by the minimum;
 * alone it bounds the size near the boundary only.
 *
 * @param g  slope (length per unit distance), finite and > 0, e.g. 0.3-0.5 (smaller
 *           grades more gently); 0 turns it off again.
 * Thread-safety: one call at a time on @p s.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         s is NULL
 *         CVM_E_INPUT_NONFINITE  g is not finite
 *         CVM_E_ARGUMENT         g < 0
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_set_boundary_grading(cvm_sizing *s, double g);

/**
 * Sizes given at the nodes of a background triangulation: inside its triangles the
 * size is interpolated linearly (the least value where triangles overlap); outside
 * them this source sets no bound. Replaces an earlier background of the handle.
 *
 * @param xyh      npoints nodes, 3 doubles each: x, y and the size there (positive
 *                 and finite).
 * @param npoints  node count; npoints = ntri = 0 removes the background (then the
 *                 pointers may be NULL).
 * @param tri      ntri triangles, 3 node indices each (0-based), either orientation.
 * Ownership: copied. Units: length.
 * Thread-safety: one call at a time on @p s.
 * Atomicity: on error the handle is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          s, or xyh or tri (with ntri > 0) is NULL
 *         CVM_E_INPUT_NONFINITE   a coordinate or size is NaN or infinite (message names node k)
 *         CVM_E_ARGUMENT          a size is not positive (message names node k)
 *         CVM_E_INPUT_INDEX       a triangle names a node outside [0, npoints) (names triangle k)
 *         CVM_E_INPUT_DEGENERATE  a triangle has zero area, by the exact orientation test
 *                                 (names triangle k)
 *         CVM_E_TOO_LARGE         more than INT32_MAX/4 nodes or triangles
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_set_background(cvm_sizing *s, const double *xyh, size_t npoints,
                                             const cvm_index *tri, size_t ntri);

/**
 * Evaluate the sizing at (x, y).
 *
 * @param out  receives the size; +infinity when the handle has no source (no bound).
 * Thread-safety: one call at a time on @p s (it records the message of a failure).
 * @return CVM_OK
 *         CVM_E_NULL_ARG         out or s is NULL
 *         CVM_E_INPUT_NONFINITE  x or y is not finite, or the callback returned NaN/Inf
 *         CVM_E_ARGUMENT         the callback returned a value <= 0, or the handle holds 3D
 *                                sources
 * @since 0.1
 */
CVM_API cvm_status cvm_sizing_eval(double *out, cvm_sizing *s, double x, double y);

/**
 * Evaluate the scalar sizing at the point @p x of @p dim coordinates (the
 * metric source is not read; see cvm_sizing_eval_metric()).
 *
 * @param out  receives the size; +infinity when the handle has no scalar source.
 * @param s    sizing handle; not NULL.
 * @param x    dim coordinates.
 * @param dim  2 or 3. As with cvm_sizing_eval(), the fields built from a domain
 *             (automatic sizing, boundary grading) are not read.
 * Thread-safety: one call at a time on @p s (it records the message of a failure).
 * @return CVM_OK
 *         CVM_E_NULL_ARG         out, s or x is NULL
 *         CVM_E_ARGUMENT         dim is neither 2 nor 3, or the callback returned a value <= 0;
 *                                the handle holds sources of the other dimension, or (dim 3) its
 *                                callback is a 2D one (cvm_sizing_set_callback() or
 *                                cvm_sizing_set_batch_callback())
 *         CVM_E_INPUT_NONFINITE  a coordinate is not finite, or the callback returned NaN/Inf
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_eval_nd(double *out, cvm_sizing *s, const double *x, int dim);

/**
 * Evaluate the metric source of @p s at the point @p x and check it: every entry
 * finite and the tensor positive definite (2D: g11 > 0 and g11 g22 - g12^2 > 0).
 *
 * @param dst      receives dim*(dim+1)/2 entries (see cvm_metric_fn); NULL only with
 *                 dst_len 0.
 * @param dst_len  capacity of dst in doubles.
 * @param s        sizing handle; not NULL.
 * @param x        dim coordinates.
 * @param dim      2; 3 gives CVM_E_UNSUPPORTED (no 3D kernel yet).
 * Units: 1 / length^2.
 * Thread-safety: one call at a time on @p s (it records the message of a failure).
 * @return CVM_OK
 *         CVM_E_NULL_ARG          s or x is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_ARGUMENT          dim is neither 2 nor 3, or the metric is not positive
 *                                 definite (message gives the position and the entries)
 *         CVM_E_UNSUPPORTED       dim is 3 (message says so)
 *         CVM_E_STATE             the handle has no metric (cvm_sizing_set_metric_fn())
 *         CVM_E_BUFFER_TOO_SMALL  dst_len < dim*(dim+1)/2 (nothing written)
 *         CVM_E_INPUT_NONFINITE   a coordinate, or an entry the function wrote, is not finite
 *         CVM_E_INPUT_OUTSIDE     the function refused the point (non-zero return)
 * @since 0.2
 */
CVM_API cvm_status cvm_sizing_eval_metric(double *dst, size_t dst_len, cvm_sizing *s,
                                          const double *x, int dim);

/** Refinement algorithms of cvm_mesh_refine(). Values never change. */
typedef enum cvm_algorithm {
    CVM_ALGO_DELAUNAY = 1, /**< Delaunay refinement (Ruppert, Shewchuk): circumcentres or
                                Ungor off-centres, the shortest shortest edge first */
    CVM_ALGO_FRONTAL = 2,  /**< frontal-Delaunay (Rebay): near-equilateral points grown from the boundary */
    CVM_ALGO_AFLR = 3      /**< advancing-front local reconnection (Marcum): layers grown from
                                front segments, see cvm_mesh_set_front_markers() */
} cvm_algorithm;

/**
 * Refine the triangulation of @p m by inserting Steiner points until every
 * triangle meets CVM_OPT_MIN_ANGLE_DEG, CVM_OPT_MAX_AREA and the @p sizing
 * (circumradius at most the mean size at its vertices). CVM_ALGO_DELAUNAY splits
 * too-large triangles first (largest circumradius/size first), then bad shapes
 * with the shortest shortest edge first, each at its circumcentre or, when nearer
 * to the shortest edge, at Ungor's off-centre (the new triangle on that edge a
 * little above the bound); in practice this terminates up to about 34.5
 * degrees. CVM_ALGO_FRONTAL first grows
 * triangles from the segments and from accepted triangles (circumradius at most
 * 0.707 x the mean size, smallest angle at least CVM_OPT_MIN_ANGLE_DEG), largest
 * circumradius first, each new point on the bisector of a front edge where it makes
 * a near-equilateral triangle of the local size (Rebay 1993). CVM_ALGO_AFLR (every
 * edge below 1.5 x the mean size at its ends) advances fronts layer
 * by layer from the segments chosen by cvm_mesh_set_front_markers() (every segment
 * by default), one point per front edge on its bisector (the nearest to the edge of
 * the equilateral point at the local size, the circumcentre and two off-centres; a
 * point closer than 0.7 x the edge to a vertex is skipped), and records a layer index
 * per triangle (cvm_mesh_copy_layer_index()); with neither a sizing nor CVM_OPT_MAX_AREA
 * its pass stops after 4 points per vertex it started with. Both finish with a Delaunay-refinement
 * pass, so all three algorithms meet the same bounds; after the frontal and the AFLR
 * passes the clean-ups, swaps and smoothing also keep frontal's acceptance bound, so
 * their triangles end with a circumradius of at most 0.707 x the mean size (unless a
 * Steiner or time limit stopped the run, or a segment split was refused: see the
 * limitation below; the report lists every triangle over 0.707 x the size as
 * CVM_UNMET_SIZE). Segments are split
 * where encroached (concentric shells near small input angles, as Triangle does), so
 * every input segment stays a union of mesh edges; with no segments, or with
 * CVM_OPT_KEEP_CONVEX_HULL, the convex hull edges become segments (with marker 0),
 * a hull edge passing within 2^-40 (M + L) of a vertex (the tolerance of a
 * segment's chain, see cvm_mesh_triangulate()) through that vertex: the sliver
 * between them leaves the mesh (also for a hull edge on an input segment, when
 * the vertex is within that tolerance of the input segment too: its chain then
 * passes through the vertex). Inside the domain, a segment's chain is routed the
 * same way through the apex of a triangle beside one of its pieces when the apex
 * lies strictly between the piece's ends within that tolerance of the piece and
 * of the input segment (the flat triangle goes to the other side): before
 * refining, and again where a split of a piece is refused (no rounded point lies
 * inside the triangles beside it). An end of a segment within that tolerance of
 * another segment's interior is a join of the two, as an end exactly on it is,
 * for the small-input-angle exemption.
 * Before refining, with CVM_OPT_KEEP_SEGMENT_VERTICES = 0 smooth chains of segments
 * are re-discretised with the sizing and the triangulation rebuilt (see that option:
 * inner input vertices of such chains disappear, the input map gives -1 for them);
 * then segments are marched with the sizing (CVM_OPT_MARCH_SEGMENTS).
 * The result stays a constrained Delaunay triangulation. New vertices get the marker
 * of the segment they lie on (else 0) and attributes interpolated along it (else 0).
 * The report (CVM_MEASURE_REFINE_*) says what was asked and what was met.
 * Limitation (0.1): a segment on the convex hull that is not axis-parallel is
 * left unsplit where no rounded split point keeps the hull exactly convex; and a
 * triangle whose three corners lie on one input segment (a rounded crossing or
 * split point a few ulps off its line, see cvm_mesh_triangulate()) cannot be split
 * away; the triangles these leave below the bounds are counted in the report.
 *
 * @param m       mesh handle, triangulated (cvm_mesh_triangulate()); not NULL.
 * @param sizing  target sizes; may be NULL (angle and area bounds only). Read only
 *                during the call; not kept.
 * @param algo    CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL or CVM_ALGO_AFLR.
 * Options:  CVM_OPT_MIN_ANGLE_DEG, CVM_OPT_MAX_AREA, CVM_OPT_ENCROACH_LENS,
 *           CVM_OPT_KEEP_SEGMENT_VERTICES, CVM_OPT_MARCH_SEGMENTS, CVM_OPT_MAX_STEINER, CVM_OPT_TIME_LIMIT_S; the
 *           progress callback (stage CVM_STAGE_REFINE) can cancel. CVM_ALGO_FRONTAL
 *           and CVM_ALGO_AFLR then post-process (when refinement completed): CVM_OPT_SWAP, then
 *           CVM_OPT_SMOOTH_SWEEPS (smoothing moves Steiner points), then
 *           CVM_OPT_RESTORE_DELAUNAY. CVM_ALGO_AFLR: CVM_OPT_AFLR_SMOOTH_LAYERS
 *           also smooths during the pass.
 * Stops:    on the Steiner limit, the time limit or cancellation (checked during the
 *           smoothing too) the mesh is valid (conforming, constrained Delaunay) with the
 *           points inserted so far.
 * Determinism: same input, options and sizing give bit-identical output (except
 *           where the time limit stops the run).
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL
 *         CVM_E_STATE             nothing triangulated; or CVM_OPT_KEEP_SEGMENT_VERTICES = 0
 *                                 with a sizing on a mesh that is not as cvm_mesh_triangulate()
 *                                 left it (refined, points inserted, weights; mesh unchanged)
 *         CVM_E_ARGUMENT          unknown algo, or the sizing callback returned a value <= 0
 *                                 (message names the callback and the position)
 *         CVM_E_INPUT_NONFINITE   the sizing callback returned NaN or infinity (message
 *                                 names the callback and the position)
 *         CVM_E_UNSUPPORTED       CVM_OPT_KEEP_SEGMENT_VERTICES = 0 without a sizing (NULL
 *                                 or empty; the error item is that option; mesh unchanged)
 *                                 or CVM_OPT_AFLR_SMOOTH_LAYERS != 0 with an algo other
 *                                 than CVM_ALGO_AFLR (the error item is that option; mesh
 *                                 unchanged), or the sizing has a metric source
 *                                 (cvm_sizing_set_metric_fn(): no refiner of this version
 *                                 meshes to a metric; mesh unchanged)
 *         CVM_E_NOMEM             (the mesh keeps the points inserted before it and is valid)
 *         CVM_INCOMPLETE_STEINER_LIMIT, CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_refine(cvm_mesh *m, const cvm_sizing *sizing, cvm_algorithm algo);

/** Reasons of cvm_mesh_copy_refine_unmet(), combined as bits. */
#define CVM_UNMET_ANGLE 1             /**< an angle below CVM_OPT_MIN_ANGLE_DEG */
#define CVM_UNMET_SIZE 2              /**< too big for the sizing (after CVM_ALGO_FRONTAL and
                                           CVM_ALGO_AFLR: circumradius over 0.707 x the mean
                                           size) or CVM_OPT_MAX_AREA */
#define CVM_UNMET_SMALL_INPUT_ANGLE 4 /**< subtended by a small input angle (left alone on
                                           purpose, counted in CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE) */

/**
 * Where the last cvm_mesh_refine() left triangles unmet (the report's "where"):
 * per such triangle, 3 doubles: its centroid x, y and its reasons (CVM_UNMET_* bits,
 * a whole number), in the order of the triangles at the end of that run. Count them
 * with cvm_mesh_count(&n, m, CVM_ENT_REFINE_UNMET) (0 before any refinement, after
 * cvm_mesh_triangulate(), and when everything was met). The positions stay valid
 * after later calls; they are a snapshot of that run.
 * @param dst_len  capacity in doubles; must be >= 3 x the count.
 * Units: length (x, y).
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_refine_unmet(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Choose which segment markers start fronts (for CVM_ALGO_AFLR): the segments whose
 * marker is in @p markers (a segment's marker is 1 when no segment markers are set).
 * count 0 (the default) means every segment, and the convex-hull edges that become
 * segments too. Kept until changed; read by the next cvm_mesh_refine().
 *
 * @param markers  count marker values. Ownership: copied.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  m is NULL, or markers is NULL while count > 0
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_front_markers(cvm_mesh *m, const int32_t *markers, size_t count);

/* ------------------------------------------------------------------------ */
/* Output                                                                    */
/* ------------------------------------------------------------------------ */
/* The count, copy and view functions take a const handle: they leave the last
 * error and its message alone (the status says what failed). A dst of NULL is
 * accepted with dst_len 0. Before cvm_mesh_triangulate() output counts are 0. */

/**
 * Number of entities of a kind: vertices, triangles, edges, segments (of the
 * output), input points/segments, holes, regions, merged duplicates.
 * On a 3D mesh: CVM_ENT_VERTEX, CVM_ENT_TETRAHEDRON (= CVM_ENT_CELL),
 * CVM_ENT_TRIANGLE (boundary faces, and internal facets of a surface's mesh),
 * CVM_ENT_INPUT_POINT, CVM_ENT_FACET (input facets), holes, regions and
 * duplicates; edges and segments count 0.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT (kind has no count)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_count(size_t *out, const cvm_mesh *m, cvm_entity kind);

/**
 * Copy vertex coordinates: 2 doubles per vertex.
 * @param dst_len  capacity of dst in doubles; must be >= 2 * vertex count.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_points(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy vertex coordinates in the mesh's dimension: dim doubles per vertex.
 *
 * @param dst      receives dim * vertex count doubles; NULL only with dst_len 0.
 * @param dst_len  capacity of dst in doubles.
 * @param dim      the dimension the caller expects; must equal cvm_mesh_dim() (2 or 3), so
 *                 code written for one dimension cannot misread another.
 * @param m        mesh handle; not NULL.
 * Units: length. Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_UNSUPPORTED       dim is 3 (no 3D meshes yet; later a dim that differs from
 *                                 the mesh's is CVM_E_ARGUMENT)
 *         CVM_E_ARGUMENT          dim is neither 2 nor 3
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 * (A const handle: no message is recorded; the status says what failed.)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_points_nd(double *dst, size_t dst_len, int dim, const cvm_mesh *m);

/**
 * Copy connectivity: CVM_ENT_TRIANGLE (3 ids each, counter-clockwise),
 * CVM_ENT_EDGE (2 ids, sorted by (lower, higher) id), CVM_ENT_SEGMENT (2 ids).
 * On a 3D mesh: CVM_ENT_TETRAHEDRON or CVM_ENT_CELL (4 ids, positively
 * oriented: cvm's orient3d of the four corners > 0) and CVM_ENT_TRIANGLE (the
 * boundary faces, 3 ids, counter-clockwise seen from outside the tetrahedron
 * they bound).
 * Order is deterministic for given input and options.
 * @param dst_len capacity in cvm_index entries.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT (kind), CVM_E_BUFFER_TOO_SMALL, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_cells(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                       cvm_entity kind);

/**
 * Cell type codes of cvm_mesh_copy_cells_mixed(). The values are VTK's cell type
 * numbers, so the arrays go to VTK, meshio or PyVista unchanged. Values never change.
 */
typedef enum cvm_cell_type {
    CVM_CELL_TRIANGLE = 5,     /**< 3 vertex ids, counter-clockwise */
    CVM_CELL_POLYGON = 7,      /**< n vertex ids, counter-clockwise (reserved: dual cells) */
    CVM_CELL_QUAD = 9,         /**< 4 vertex ids, counter-clockwise (reserved: quad meshing) */
    CVM_CELL_TETRAHEDRON = 10, /**< 4 vertex ids, positively oriented (3D meshes) */
    CVM_CELL_POLYHEDRON = 42   /**< reserved: 3D dual cells; their connectivity will be
                                    documented with them */
} cvm_cell_type;

/**
 * Sizes of the arrays of cvm_mesh_copy_cells_mixed().
 *
 * @param ncells_out  receives the number of cells (offsets need ncells + 1 entries, types ncells).
 * @param nconn_out   receives the total number of vertex ids over all cells.
 * @param m           mesh handle; not NULL.
 * @param kind        CVM_ENT_CELL: the cells of the mesh's dimension (its triangles, in
 *                    CVM_ENT_TRIANGLE order, or tetrahedra; after cvm_mesh_quadmesh() its
 *                    quad-dominant cells).
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK (counts 0 before triangulation)
 *         CVM_E_NULL_ARG  a pointer is NULL
 *         CVM_E_ARGUMENT  kind is not CVM_ENT_CELL
 *         CVM_E_TOO_LARGE the ids exceed what cvm_index offsets can address
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_count_cells_mixed(size_t *ncells_out, size_t *nconn_out,
                                              const cvm_mesh *m, cvm_entity kind);

/**
 * Copy cells of several types in compressed form (as the dual cells are): cell c has
 * type types[c] (a cvm_cell_type) and the vertex ids conn[offsets[c] .. offsets[c+1]-1];
 * offsets[0] = 0 and offsets[ncells] = nconn (cvm_mesh_count_cells_mixed()). The cells
 * are the CVM_CELL_TRIANGLEs in CVM_ENT_TRIANGLE order (CVM_CELL_TETRAHEDRON for a 3D
 * mesh), or after cvm_mesh_quadmesh() its CVM_CELL_QUADs and CVM_CELL_TRIANGLEs (until a
 * call changes the mesh); cvm_mesh_copy_cell_neighbors() and
 * cvm_mesh_copy_cell_attributes() with CVM_ENT_CELL follow the same cells.
 *
 * @param offsets      ncells + 1 entries; NULL only with offsets_len 0.
 * @param offsets_len  capacity of offsets.
 * @param types        ncells entries; NULL only with types_len 0.
 * @param types_len    capacity of types.
 * @param conn         nconn entries; NULL only with conn_len 0.
 * @param conn_len     capacity of conn.
 * @param m            mesh handle; not NULL.
 * @param kind         CVM_ENT_CELL.
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or an array is NULL while its capacity > 0
 *         CVM_E_ARGUMENT          kind is not CVM_ENT_CELL
 *         CVM_E_BUFFER_TOO_SMALL  an array is too short (nothing written to any)
 *         CVM_E_TOO_LARGE         as cvm_mesh_count_cells_mixed()
 * (A const handle: no message is recorded; the status says what failed.)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_cells_mixed(cvm_index *offsets, size_t offsets_len,
                                             int32_t *types, size_t types_len, cvm_index *conn,
                                             size_t conn_len, const cvm_mesh *m, cvm_entity kind);

/**
 * Copy the neighbours of each triangle: 3 per triangle, neighbour k lies
 * across the edge opposite vertex k, -1 on the domain boundary.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the neighbours of the cells of kind @p kind, -1 on the domain boundary.
 * CVM_ENT_TRIANGLE: 3 per triangle, neighbour k across the edge opposite vertex k
 * (as cvm_mesh_copy_neighbors()). CVM_ENT_CELL: one per face of each cell, in
 * the layout of cvm_mesh_copy_cells_mixed() (the same offsets, since a triangle,
 * quad, tetrahedron or polygon has as many faces as vertices), neighbours given as
 * cell indices in that order; face k of a triangle or tetrahedron is opposite its
 * vertex k, face k of a quad or polygon joins its vertices k and k+1 (mod n).
 * CVM_ENT_TETRAHEDRON is reserved for the 3D kernel.
 *
 * @param dst      receives the neighbours; NULL only with dst_len 0.
 * @param dst_len  capacity in entries; >= 3 x the triangle count (CVM_ENT_TRIANGLE), or
 *                 nconn of cvm_mesh_count_cells_mixed() (CVM_ENT_CELL).
 * @param m        mesh handle; not NULL.
 * @param kind     CVM_ENT_TRIANGLE or CVM_ENT_CELL.
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_ARGUMENT          another kind
 *         CVM_E_UNSUPPORTED       kind is CVM_ENT_TETRAHEDRON (no 3D kernel yet)
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_cell_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                                cvm_entity kind);

/**
 * Copy integer markers: CVM_ENT_VERTEX (the input marker; a vertex whose
 * marker is 0 and that lies on a segment, input point or Steiner point, takes
 * that segment's marker, as Triangle does; else 0), CVM_ENT_SEGMENT (marker of the
 * input segment each output segment lies on, in CVM_ENT_SEGMENT order; 1 when
 * no segment markers were set, as Triangle's default boundary marker).
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT, CVM_E_BUFFER_TOO_SMALL, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_markers(int32_t *dst, size_t dst_len, const cvm_mesh *m,
                                         cvm_entity kind);

/**
 * Copy the regional attribute of each triangle (0 outside every region).
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_triangle_attributes(double *dst, size_t dst_len,
                                                     const cvm_mesh *m);

/**
 * Copy the regional attribute of each cell of kind @p kind (0 outside every
 * region): CVM_ENT_TRIANGLE as cvm_mesh_copy_triangle_attributes(); CVM_ENT_CELL in
 * the order of cvm_mesh_copy_cells_mixed().
 *
 * @param dst      one value per cell; NULL only with dst_len 0.
 * @param dst_len  capacity in doubles.
 * @param m        mesh handle; not NULL.
 * @param kind     CVM_ENT_TRIANGLE or CVM_ENT_CELL.
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_ARGUMENT          another kind
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_cell_attributes(double *dst, size_t dst_len, const cvm_mesh *m,
                                                 cvm_entity kind);

/**
 * Copy the advancing-front layer index of each triangle (in CVM_ENT_TRIANGLE
 * order) after a CVM_ALGO_AFLR refinement: max + 0.1 x min of the layer indices
 * of its three edges. A front segment's edges have layer 0; an edge made by
 * inserting a point has one more than the lowest layer on the boundary of that
 * point's cavity; an edge made after the fronts stopped (clean-up, swaps) has one
 * more than the lowest layer at its two ends. So a triangle on a front segment
 * has 0.x or 1.0, the next layer 1.x or 2.x, and so on; -1 where no front reached.
 * Every value is -1 when the last cvm_mesh_refine() was not CVM_ALGO_AFLR (or
 * none ran, or it failed), and after any later call that changes the triangles
 * (cvm_mesh_set_weights(), cvm_mesh_insert_points(), cvm_mesh_optimise_dual()):
 * the values belong to the mesh as refined.
 *
 * @param dst      count(CVM_ENT_TRIANGLE) doubles; NULL only with dst_len 0.
 * @param dst_len  entries available in dst.
 * @param m        mesh handle; not NULL.
 * Ownership:    written into the caller's buffer; nothing kept.
 * Units:        none (layer counts).
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_BUFFER_TOO_SMALL dst_len < the triangle count (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_layer_index(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the point attributes of each vertex: nattr per vertex (see
 * cvm_mesh_set_point_attributes()); *nattr_out receives nattr.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_point_attributes(double *dst, size_t dst_len, size_t *nattr_out,
                                                  const cvm_mesh *m);

/**
 * For each input point, the mesh vertex it became (a duplicate maps to the
 * vertex of its first occurrence), or -1 for an inner vertex of a chain that
 * CVM_OPT_KEEP_SEGMENT_VERTICES = 0 re-discretised. count = CVM_ENT_INPUT_POINT.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_STATE, CVM_E_BUFFER_TOO_SMALL
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_input_map(cvm_index *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Read-only view of the vertex coordinates (2 doubles per vertex), without a copy.
 * Ownership: owned by @p m; valid until the next call that modifies @p m, or cvm_mesh_free().
 * @return CVM_OK, CVM_E_NULL_ARG
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_view_points(const double **ptr_out, size_t *count_out,
                                        const cvm_mesh *m);

/**
 * Read-only view of the vertex coordinates in the mesh's dimension, without a copy.
 *
 * @param ptr_out    receives *dim_out doubles per vertex (NULL when there is none).
 * @param count_out  receives the vertex count.
 * @param dim_out    receives the mesh's dimension (cvm_mesh_dim(): 2 or 3).
 * @param m          mesh handle; not NULL.
 * Ownership: owned by @p m; valid until the next call that modifies @p m, or cvm_mesh_free().
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK, CVM_E_NULL_ARG (a pointer is NULL)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_view_points_nd(const double **ptr_out, size_t *count_out,
                                           int32_t *dim_out, const cvm_mesh *m);

/**
 * Write the mesh; the format follows the extension of @p path:
 * .vtu (VTK XML unstructured grid: the triangles, then the segments as line
 * cells; point data "marker", "weight" when weights are set, "attribute";
 * cell data "marker" (segment marker of a line, 0 on a triangle), "attribute"
 * (regional, with regions) and "min_angle_deg" (0 on a line); ASCII, or
 * binary appended data as CVM_OPT_VTU_ENCODING says; cvm_mesh_read()
 * reads it back), .msh (Gmsh 4.1 ASCII, segments tagged by
 * marker as physical groups, named from the marker names (see "Marker
 * names")), .node (writes PREFIX.node, PREFIX.ele and
 * PREFIX.edge beside each other, 0-based), .svg (a picture).
 * A 3D mesh: .vtu (VTK_TETRA cells, cell data "attribute" with regions, and
 * point data "weight" when the mesh has power weights), .msh (Gmsh 4.1:
 * tetrahedra in one volume per regional attribute, boundary triangles in one
 * surface per marker, physical group m "marker_m" for m > 0), .node (TetGen's
 * PREFIX.node, PREFIX.ele and PREFIX.face, 0-based; the weight, when set, as the
 * one point attribute, where TetGen's -w reads it); not .svg.
 * Every file is written to a temporary name and renamed, so a failure never
 * leaves a partial file; the three files of .node replace their old versions
 * together (cvm_mesh_commit_writes()). A replaced file keeps its permissions
 * (and its owner where the process may set it); a new file gets the umask's.
 * A target that exists and is not a regular file (/dev/null, a FIFO) is
 * written in place.
 * Stops: the progress callback (stage CVM_STAGE_WRITE, fraction about the
 * share written) is asked about every every_n values written (at least 64)
 * and can cancel; the time limit does not apply. A cancelled write leaves
 * every file as it was.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_STATE (nothing triangulated),
 *         CVM_E_UNSUPPORTED (extension), CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM
 *         CVM_INCOMPLETE_CANCELLED  the progress callback stopped it: nothing written
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_write(cvm_mesh *m, const char *path);

/* ------------------------------------------------------------------------ */
/* Marker names                                                              */
/* ------------------------------------------------------------------------ */
/* A handle keeps a table of names for its markers, as Gmsh's physical names:
 * key (dim, marker), dim 0 for point markers, 1 for segment markers, 2 for
 * regional attributes (an integer attribute), 3 for volumes. cvm_mesh_read()
 * of a .msh fills it from the file's $PhysicalNames (a repeated key keeps its
 * first name; names longer than 127 bytes are cut); any other successful
 * cvm_mesh_read() empties it. Triangulation, refinement and optimisation keep
 * it. cvm_mesh_write() to a 2D .msh writes it back in $PhysicalNames: segment
 * marker m > 0 is physical curve group m named by (1, m) (else "marker_m"), the
 * surface of regional attribute A is named by (2, A) (else "region_A"), the one
 * surface of a mesh without regional attributes by (2, 1) (else "domain");
 * names of groups the file does not have are not written. */

/**
 * Name marker @p marker of dimension @p dim, or remove its name.
 *
 * @param m       mesh handle; not NULL.
 * @param dim     0 (points), 1 (segments), 2 (regions) or 3 (volumes).
 * @param marker  the marker (or integer regional attribute).
 * @param name    1 to 127 bytes without control characters or double quotes (a
 *                .msh file holds it in quotes); NULL removes the name.
 * Ownership:    @p name is copied.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on error the table is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  m is NULL
 *         CVM_E_ARGUMENT  dim out of range, or the name is empty, too long or holds a
 *                         control character or a double quote (message says which)
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_set_marker_name(cvm_mesh *m, int dim, int32_t marker,
                                            const char *name);

/**
 * The name of marker @p marker of dimension @p dim, or NULL when it has none
 * (or m is NULL). The string belongs to @p m and stays valid until the next
 * call that changes the table (cvm_mesh_set_marker_name(), cvm_mesh_read()) or
 * cvm_mesh_free(m).
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @since 0.2
 */
CVM_API const char *cvm_mesh_get_marker_name(const cvm_mesh *m, int dim, int32_t marker);

/**
 * Count the named markers of @p m.
 * @return CVM_OK, CVM_E_NULL_ARG (out or m is NULL)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_count_marker_names(size_t *out, const cvm_mesh *m);

/**
 * Copy the keys of the named markers, 2 entries each (dim, marker), sorted by
 * dim, then marker; cvm_mesh_get_marker_name() gives each name.
 * @param dst_len  capacity in entries; must be >= 2 * cvm_mesh_count_marker_names().
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_marker_name_keys(int32_t *dst, size_t dst_len,
                                                  const cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* Weights and the power (Voronoi) dual                                      */
/* ------------------------------------------------------------------------ */
/* Each vertex i carries a power weight w_i (squared length units, default 0);
 * the power distance of a point x to vertex i is |x - p_i|^2 - w_i. The mesh is
 * then the regular (weighted Delaunay) triangulation of the weighted vertices
 * (constrained by the segments), and its dual is the power diagram: the power
 * vertex (orthocentre) of a triangle has equal power distance to its three
 * corners; with all weights 0 it is the circumcentre and the dual is the
 * Voronoi diagram. Decisions (regularity, containment) use exact predicates;
 * positions, lengths and areas are plain doubles. */

/**
 * Set the power weight of every vertex and make the triangulation regular
 * again: every non-constrained edge inside the domain (and outside it, never
 * across its boundary or a region border) is flipped while it fails the exact
 * power test and its quadrilateral is convex (Lawson flips; ties broken by
 * symbolic perturbation by vertex index). A vertex whose power cell is empty
 * (its weight is too small beside its neighbours') would vanish from the
 * regular triangulation; cvmesh never drops it silently: it stays in the mesh
 * beside the illegal edges that hold it (their flip would need it removed),
 * and CVM_MEASURE_VANISHED_VERTICES counts such vertices. When that count is 0
 * the mesh is the (constrained) regular triangulation and cvm_mesh_check()
 * verifies it with the exact power test; otherwise cvm_mesh_check() reports
 * the illegal edges (CVM_E_INTERNAL). cvm_mesh_optimise_dual() removes such
 * vertices when they are removable Steiner points (CVM_OPT_DUAL_TOPOLOGY).
 *
 * @param m      mesh handle, triangulated; not NULL.
 * @param w      count weights, one per vertex in CVM_ENT_VERTEX order; NULL with
 *               count 0 removes the weights (all 0, the mesh becomes Delaunay again).
 * @param count  must equal the vertex count (cvm_mesh_count(&n, m, CVM_ENT_VERTEX)).
 * Ownership:    @p w is copied.
 * Units:        squared length.
 * Lifetime:     cvm_mesh_triangulate() drops the weights. Vertices added later by
 *               cvm_mesh_insert_points() get weight 0 (a point whose power cell
 *               would be empty is rejected); set the weights after the last
 *               cvm_mesh_refine().
 * 3D:           on the Delaunay tetrahedralisation of a point set, the regular
 *               tetrahedralisation of its vertices with these weights (vertex ids
 *               kept; a vertex whose power cell vanishes is in no tetrahedron and is
 *               counted by CVM_MEASURE_VANISHED_VERTICES); on a surface's mesh
 *               CVM_E_UNSUPPORTED.
 * Output:       cvm_mesh_write() to .node writes the weight as the first attribute
 *               of each vertex (before the point attributes).
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on error the weights and the triangulation are unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG         m is NULL, or w is NULL while count > 0
 *         CVM_E_STATE            nothing triangulated
 *         CVM_E_ARGUMENT         count is not the vertex count (message gives both)
 *         CVM_E_INPUT_NONFINITE  a weight is NaN or infinite (message names vertex k;
 *                                cvm_mesh_error_item() gives CVM_ENT_VERTEX, k)
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_set_weights(cvm_mesh *m, const double *w, size_t count);

/**
 * Take a tetrahedral mesh made elsewhere (TetGen, Gmsh, a solver's own) as the
 * handle's mesh, on the handle's 3D points, so that the 3D measures, checks,
 * outputs and cvm_mesh_optimise_dual3() work on it ("bring your own mesh").
 *
 * @param m      a 3D handle with points (cvm_mesh_set_points() with dim 3, or
 *               cvm_mesh_read() of a 3D .node); every point must be a corner of
 *               some tetrahedron.
 * @param tets   4 * count point ids (0-based), any orientation: a negatively
 *               oriented tetrahedron gets two corners swapped.
 * @param count  the number of tetrahedra, at least 1.
 * @param tet_attr  count region attributes (finite), or NULL. Faces between
 *               tetrahedra of different attributes become internal facets, which
 *               the optimiser keeps, as it keeps the boundary.
 * Checks (exact orient3d): ids in range and distinct per tetrahedron, no flat
 * tetrahedron, each face shared by at most two tetrahedra and then from
 * opposite sides, and the boundary (the faces of one tetrahedron, with the
 * internal facets) a closed, manifold, consistently oriented surface without
 * self-intersections, as cvm_mesh_triangulate() demands of a surface. The
 * vertices are the points in order (no duplicate merging); the mesh is not
 * assumed Delaunay (cvm_mesh_check() checks conformity and the boundary, not
 * the Delaunay property; cvm_mesh_optimise_dual3() first flips the faces that
 * are not locally regular). The holes and regions of the input are not used.
 * Ownership:    @p tets and @p tet_attr are copied.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on error the handle's mesh and input are unchanged.
 * Cost:         O(count log count), plus the surface's intersection test (a grid).
 * @return CVM_OK
 *         CVM_E_NULL_ARG            m is NULL, or tets is NULL while count > 0
 *         CVM_E_STATE               no 3D points on the handle
 *         CVM_E_INPUT_EMPTY         count is 0
 *         CVM_E_TOO_LARGE           count above INT32_MAX / 4
 *         CVM_E_INPUT_INDEX         a tetrahedron names a point that does not exist
 *         CVM_E_INPUT_DEGENERATE    a tetrahedron repeats a point or is flat, a face
 *                                   belongs to three or more tetrahedra, or a point
 *                                   is in no tetrahedron (message names it;
 *                                   cvm_mesh_error_item() gives the tetrahedron or point)
 *         CVM_E_INPUT_NONFINITE     an attribute is NaN or infinite
 *         CVM_E_INPUT_INTERSECTING  two tetrahedra overlap (on one side of their shared
 *                                   face), or the boundary is not manifold or
 *                                   intersects itself (message names the faces)
 *         CVM_E_INPUT_NOT_CLOSED    the boundary is not closed or not consistently oriented
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_set_tetrahedra(cvm_mesh *m, const cvm_index *tets, size_t count,
                                           const double *tet_attr);

/**
 * Copy the weight of each vertex (0 for every vertex when none were set).
 * On a 3D handle (since 0.2): the weights of the tetrahedral mesh's vertices
 * (cvm_mesh_set_weights(), cvm_mesh_optimise_dual3()); before 0.2 a 3D handle
 * returned CVM_E_UNSUPPORTED.
 * @param dst_len  capacity in doubles; must be >= the vertex count.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_weights(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the power vertex (orthocentre) of each triangle: 2 doubles per triangle,
 * in CVM_ENT_TRIANGLE order. A construction: plain doubles, possibly inexact.
 * @param dst_len  capacity in doubles; must be >= 2 * triangle count.
 * Units:  length.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_vertices(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * cvm_mesh_copy_dual_vertices() in the mesh's dimension: dim doubles per cell
 * (the power vertex of each triangle, in CVM_ENT_TRIANGLE order).
 *
 * @param dst      NULL only with dst_len 0.
 * @param dst_len  capacity in doubles; >= dim x the cell count.
 * @param dim      must equal cvm_mesh_dim() (see cvm_mesh_copy_points_nd()).
 * @param m        mesh handle; not NULL.
 * Units: length. A construction: plain doubles.
 * 3D:           on a 3D mesh with dim 3, the power vertex (circumcentre without
 *               weights) of each tetrahedron, 3 doubles per tetrahedron in
 *               CVM_ENT_TETRAHEDRON order (since 0.2).
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_UNSUPPORTED       dim is 3 on a 2D mesh
 *         CVM_E_ARGUMENT          dim is not the mesh's dimension
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual_vertices_nd(double *dst, size_t dst_len, int dim,
                                                  const cvm_mesh *m);

/**
 * Copy, per triangle in CVM_ENT_TRIANGLE order, 1 when the triangle contains its
 * power vertex (on an edge counts as inside) and 0 when not. Decided exactly
 * from the input coordinates and weights: the power vertex of triangle (a, b, c)
 * lies on c's side of edge ab iff |B|^2 (|C|^2 + w_a - w_c) - (B.C)(|B|^2 + w_a - w_b)
 * >= 0 with B = b - a, C = c - a; without weights: iff the angle at c is at most
 * 90 degrees.
 * @param dst_len  capacity in entries; must be >= the triangle count.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_inside(int32_t *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the dual (power) cell area of each vertex, restricted to the domain, by
 * the co-volume decomposition: each triangle gives vertex p of its edge pq the
 * signed area of the triangle (p, M, V), with V its power vertex and M the
 * power-bisector foot of pq (the point of line pq with equal power distance to
 * p and q). Exact (in real arithmetic) for meshes whose triangles contain their
 * power vertices; otherwise some pieces are negative, and the areas still sum
 * to the domain area. A measure: plain doubles.
 * @param dst_len  capacity in doubles; must be >= the vertex count.
 * Units:  squared length.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_areas(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the dual edge length of each edge, in CVM_ENT_EDGE order: for an edge
 * with a domain triangle on both sides, the distance between their power
 * vertices; on the domain boundary, the distance from the power vertex of its
 * triangle to the edge's power-bisector foot (see cvm_mesh_copy_dual_areas()).
 * Lengths are unsigned. A measure: plain doubles.
 * @param dst_len  capacity in doubles; must be >= the edge count.
 * Units:  length.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_edge_lengths(double *dst, size_t dst_len,
                                                   const cvm_mesh *m);

/**
 * Dual cells, part 1: the offsets of the cell polygons of
 * cvm_mesh_copy_dual_cells() in CSR form. Vertex v's cell has the corners
 * offsets[v] .. offsets[v+1]-1; offsets[0] = 0 and offsets[nv] is the total
 * number of corners (a vertex without a domain triangle has an empty cell).
 * @param dst_len  capacity in entries; must be >= vertex count + 1 (1 before
 *                 triangulation, when the single entry is 0).
 * Thread-safety: must not run concurrently with a call that modifies @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 *         CVM_E_TOO_LARGE         more than INT32_MAX corners
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_cell_offsets(cvm_index *dst, size_t dst_len,
                                                   const cvm_mesh *m);

/**
 * Dual cells, part 2: the corners of the power (Voronoi) cell polygon of every
 * vertex, 2 doubles per corner, cell after cell in vertex order (offsets from
 * cvm_mesh_copy_dual_cell_offsets()), counter-clockwise. An interior vertex's
 * cell is the chain of the power vertices of its triangles. A vertex on the
 * domain boundary has, for each fan of domain triangles around it (one, unless
 * the domain pinches at it), the corners: the vertex itself, the
 * power-bisector foot of the fan's first boundary edge, the power vertices of
 * the fan's triangles, the foot of its last boundary edge; so the cell is
 * closed along the boundary, restricted to the domain. When every triangle
 * contains its power vertex (cvm_mesh_copy_dual_inside()) the polygons are
 * simple, tile the domain, and their areas equal cvm_mesh_copy_dual_areas();
 * otherwise a power vertex outside its triangle makes a polygon fold over
 * (not clipped), and its signed shoelace area still equals
 * cvm_mesh_copy_dual_areas(). Constructions: plain doubles.
 * @param dst_len  capacity in doubles; must be >= 2 * the total corner count.
 * Units:  length.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 *         CVM_E_TOO_LARGE         more than INT32_MAX corners
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_cells(double *dst, size_t dst_len, const cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* The power dual as a finite-volume mesh                                   */
/* ------------------------------------------------------------------------ */
/* The cells of cvm_mesh_copy_dual_cells() on shared points, with the faces
 * between them, as a finite-volume or co-volume code wants them. Points, each
 * once: first the power vertex of every triangle (CVM_ENT_TRIANGLE order, the
 * doubles of cvm_mesh_copy_dual_vertices()), then the power-bisector foot of
 * every boundary edge (an edge with a domain triangle on one side only, in
 * CVM_ENT_EDGE order), then every vertex on a boundary edge (vertex order).
 * Triangles with the same power vertex (cocircular corners) keep a point each;
 * their face then has length 0 (up to rounding). Cell v is vertex v's polygon: the offsets of
 * cvm_mesh_copy_dual_cell_offsets(), the corners as point ids
 * (cvm_mesh_copy_dual_polygons()); point polygons[k] is the same double pair
 * as corner k of cvm_mesh_copy_dual_cells(). Faces: first one per edge in
 * CVM_ENT_EDGE order (face k is the dual of edge k; its length is
 * cvm_mesh_copy_dual_edge_lengths()[k]), between the cells of the edge's two
 * vertices; on a boundary edge it joins the power vertex of the edge's
 * triangle and the edge's foot. Then, per boundary edge (s, h), s -> h
 * counter-clockwise around the domain (the domain on its left), in
 * CVM_ENT_EDGE order, two boundary faces on the edge: s to the foot (cell s),
 * the foot to h (cell h). Cell areas (cvm_mesh_copy_dual_areas()) sum to the
 * domain area; the cells tile the domain, without overlap, when every triangle
 * contains its power vertex (cvm_mesh_copy_dual_inside()); otherwise a cell
 * folds over as cvm_mesh_copy_dual_cells() says (not clipped). A vertex where
 * the domain pinches lists its own point once per fan. Each call builds the
 * dual afresh (linear time). A 3D mesh: CVM_E_UNSUPPORTED.
 * Thread-safety: must not run concurrently with a call that modifies @p m. */

/**
 * Count the points, corners and faces of the finite-volume dual (0, 0, 0
 * before triangulation). The corner count is also the last entry of
 * cvm_mesh_copy_dual_cell_offsets().
 * @return CVM_OK
 *         CVM_E_NULL_ARG     m or an output is NULL
 *         CVM_E_UNSUPPORTED  a 3D mesh
 *         CVM_E_TOO_LARGE    more than INT32_MAX points or corners
 *         CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_count_dual(size_t *points_out, size_t *corners_out,
                                       size_t *faces_out, const cvm_mesh *m);

/**
 * Copy the points of the finite-volume dual, 2 doubles each. Constructions:
 * plain doubles.
 * @param dst_len  capacity in doubles; must be >= 2 * the point count.
 * Units:  length.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_UNSUPPORTED       a 3D mesh
 *         CVM_E_BUFFER_TOO_SMALL  (nothing written)
 *         CVM_E_TOO_LARGE, CVM_E_NOMEM
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual_points(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the corners of every cell as point ids (0-based, into
 * cvm_mesh_copy_dual_points()), cell after cell in vertex order,
 * counter-clockwise; cell v has the corners offsets[v] .. offsets[v+1]-1 of
 * cvm_mesh_copy_dual_cell_offsets().
 * @param dst_len  capacity in entries; must be >= the corner count.
 * @return as cvm_mesh_copy_dual_points()
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual_polygons(cvm_index *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the face table of the finite-volume dual, 6 entries per face: cell a,
 * cell b (-1 on a boundary face), the two vertex ids of the primal edge the
 * face crosses (a boundary face: of the boundary edge it lies on, its own
 * cell's vertex first), and the face's two point ids p, q (into
 * cvm_mesh_copy_dual_points()), cell a on the left of p -> q: (q - p) turned
 * clockwise by 90 degrees points from cell a to cell b (out of the domain on
 * a boundary face). Cells are vertex ids; on an interior face a < b are the
 * primal edge's vertices.
 * @param dst_len  capacity in entries; must be >= 6 * the face count.
 * @return as cvm_mesh_copy_dual_points()
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual_faces(cvm_index *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy per face of cvm_mesh_copy_dual_faces() 2 doubles: the length of its
 * primal edge and the face's own length |q - p| (the dual edge length). The
 * co-volume flux across a face is (dual length / primal length) x the
 * difference of the two cells' values. Measures: plain doubles.
 * @param dst_len  capacity in doubles; must be >= 2 * the face count.
 * Units:  length.
 * @return as cvm_mesh_copy_dual_points()
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual_face_lengths(double *dst, size_t dst_len,
                                                   const cvm_mesh *m);

/**
 * Write the dual cells as a VTK XML unstructured grid (.vtu, ASCII) that a
 * finite-volume code reads directly: the points of the finite-volume dual
 * (cvm_mesh_copy_dual_points(), z = 0, each once), one VTK_POLYGON (type 7)
 * per vertex with a non-empty cell, its corners as point ids
 * (cvm_mesh_copy_dual_polygons()), so VTK and ParaView see one polygon mesh
 * whose neighbouring cells share points. The cells go by corner count, then
 * vertex id, so meshio (which splits polygons into blocks of consecutive
 * cells of one size) reads one "polygon" block per corner count; cell data "vertex"
 * (Int32, the vertex id), "area" (Float64, cvm_mesh_copy_dual_areas()) and
 * "weight" (Float64, the vertex weight); and the face table of
 * cvm_mesh_copy_dual_faces() as field data of nface tuples of 2: "face_cells"
 * (Int32, the file's cell numbers of cells a and b, -1 on the boundary),
 * "face_edge" (Int32, the primal edge's vertex ids), "face_points" (Int32, the
 * face's two point ids) and "face_lengths" (Float64, primal edge length and
 * face length). Since 0.2 the corners are shared and the field data is new;
 * before, each cell repeated its own corner points. CVM_OPT_VTU_ENCODING does
 * not apply. The file is written to a temporary name and renamed, so a
 * failure never leaves a partial file.
 * @param path  must end in .vtu.
 * 3D:    on a 3D mesh, the bounded cells of the 3D power dual (see
 *        cvm_mesh_count_dual3()): one VTK_POLYHEDRON (type 42) per interior
 *        vertex, with VTK's "faces" and "faceoffsets" arrays; the points are
 *        the dual vertices, each once and shared by the cells, with point data
 *        "tetrahedron" (Int32, a tetrahedron whose power vertex it is); each
 *        face is a dual face oriented outwards (a face that vanished in a tie
 *        is left out); cell data "vertex", "volume"
 *        (cvm_mesh_copy_dual3_volumes()) and "weight"; field data "edge"
 *        (Int32 x 2) with "dual_face_area", and "face" (Int32 x 3) with
 *        "dual_edge_length" (cvm_mesh_copy_dual3_face_areas(),
 *        cvm_mesh_copy_dual3_edge_lengths()). Boundary vertices have no cell.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG      m or path is NULL
 *         CVM_E_STATE         nothing triangulated
 *         CVM_E_UNSUPPORTED   path does not end in .vtu
 *         CVM_E_TOO_LARGE     more than INT32_MAX corners
 *         CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_write_dual(cvm_mesh *m, const char *path);

/*
 * The 3D power dual (a 3D mesh only; since 0.2). Each tetrahedron has a dual
 * vertex, its power vertex (circumcentre without weights); tetrahedra whose
 * power vertices coincide exactly (the exact power test across their shared
 * face ties, as in the tetrahedra of one cube of a cubic lattice) share one.
 * An interior edge (its ring of tetrahedra closes) has a dual face, the polygon
 * of the power vertices around it, on the power bisector plane of its ends; an
 * interior face (shared by two tetrahedra) has a dual edge joining their power
 * vertices. An interior vertex (on no boundary face) has a bounded cell; the
 * cells of boundary vertices are unbounded for a point set (and would need
 * clipping for a surface's mesh): these calls leave them out. Constructions
 * and measures in plain doubles, the ties decided exactly. Each call computes
 * the dual afresh: O(tetrahedra log tetrahedra).
 * Thread-safety: may run concurrently with other read-only calls on @p m (a
 * const handle: the last error and its message are left alone).
 * Common statuses: CVM_E_NULL_ARG (m NULL, or an output NULL while its length
 * is > 0), CVM_E_UNSUPPORTED (a 2D mesh), CVM_E_STATE (nothing triangulated),
 * CVM_E_BUFFER_TOO_SMALL (nothing written), CVM_E_NOMEM.
 */

/**
 * Count the interior edges (each with a dual face) and the interior faces
 * (each with a dual edge) of a 3D mesh.
 * @return CVM_OK or a common status of the 3D dual (above)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_count_dual3(size_t *edges_out, size_t *faces_out, const cvm_mesh *m);

/**
 * Copy the volume of the dual (power) cell of each vertex, in CVM_ENT_VERTEX
 * order: for an interior vertex v, the sum over its edges vu of area(face of
 * vu) x h / 3, h = (|u - v|^2 + w_v - w_u) / (2 |u - v|) the distance from v
 * to the power bisector plane (the co-volume decomposition: the true volume
 * when every tetrahedron contains its power vertex, a signed sum otherwise);
 * -1 for a vertex on the boundary (or in no tetrahedron).
 * @param dst_len  capacity in doubles; >= the vertex count.
 * Units:  cubed length.
 * @return CVM_OK or a common status of the 3D dual (above)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual3_volumes(double *dst, size_t dst_len, const cvm_mesh *m);

/**
 * Copy the interior edges (2 vertex ids each, the smaller first, sorted) and
 * the signed area of each one's dual face: the vector area of the polygon of
 * power vertices, turning positively about the edge from its first to its
 * second vertex, dotted with the unit edge (positive when the power vertices
 * lie inside their tetrahedra).
 * @param edges_len  capacity in entries; >= 2 x the interior edge count.
 * @param areas_len  capacity in doubles; >= the interior edge count.
 * Units:  squared length.
 * @return CVM_OK or a common status of the 3D dual (above)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual3_face_areas(cvm_index *edges, size_t edges_len,
                                                  double *areas, size_t areas_len,
                                                  const cvm_mesh *m);

/**
 * Copy the interior faces (3 vertex ids each, counter-clockwise seen from
 * outside the tetrahedron of smaller index, in the order of that tetrahedron
 * and its face) and the length of each one's dual edge (0 for a tie).
 * @param faces_len    capacity in entries; >= 3 x the interior face count.
 * @param lengths_len  capacity in doubles; >= the interior face count.
 * Units:  length.
 * @return CVM_OK or a common status of the 3D dual (above)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual3_edge_lengths(cvm_index *faces, size_t faces_len,
                                                    double *lengths, size_t lengths_len,
                                                    const cvm_mesh *m);

/**
 * Merged 3D dual cells: copy, per tetrahedron in CVM_ENT_TETRAHEDRON order,
 * the index (in that order) of the smallest tetrahedron of its kept merged
 * group; a tetrahedron that is not merged gets its own index.
 * The rule (CVM_OPT_DUAL3_MERGE_TOL): a face shared by two tetrahedra is
 * mergeable when it is not constrained (boundary or internal facet), both
 * tetrahedra have the same region attribute, and their power vertices
 * coincide (exact power test) or lie closer than tol x 0.38 x l (l the mean
 * over the face's corners of the mean length of each corner's edges, each
 * edge once). Groups are the connected sets of tetrahedra joined across
 * mergeable faces. A group of 2 or more is kept only when it is one convex
 * polyhedron star-shaped about its dual vertex: for each of its boundary
 * faces, every vertex of the group and the group's dual vertex (the power
 * vertex of its smallest tetrahedron, in doubles) lie on the inner side or on
 * the face's plane (exact orient3d of those doubles: non-strict), and no
 * constrained face lies between two of its tetrahedra. Other groups are
 * dissolved: their tetrahedra are not merged (CVM_MEASURE_DUAL3_MERGE_DISSOLVED
 * counts them). A kept group is one polyhedral dual cell: its power vertices
 * are treated as one. A tetrahedron whose power vertex lies outside it (exact,
 * as CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT) counts as compliant when it lies
 * outside only beyond faces that are mergeable within a kept group
 * (CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT).
 * @param dst_len  capacity in entries; must be >= the tetrahedron count.
 * Determinism: depends only on the mesh, its weights, its region attributes and
 * CVM_OPT_DUAL3_MERGE_TOL. Cost: O(tetrahedra log tetrahedra), plus for each
 * group its boundary faces x its vertices.
 * Thread-safety: as the other 3D dual copies (a const handle).
 * @return CVM_OK, CVM_E_NULL_ARG (m NULL, or dst NULL with tetrahedra),
 *         CVM_E_UNSUPPORTED (a 2D mesh, as the other 3D dual calls),
 *         CVM_E_STATE (nothing triangulated),
 *         CVM_E_BUFFER_TOO_SMALL (nothing written), CVM_E_NOMEM (nothing written)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_copy_dual3_merge_groups(cvm_index *dst, size_t dst_len,
                                                    const cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* Several output files as one                                               */
/* ------------------------------------------------------------------------ */
/* A program that writes several files (a mesh, its picture, its dual) can
 * make them appear together or not at all: stage each write, then commit.
 *
 *   if (cvm_mesh_stage_write(m, "out.vtu") == CVM_OK &&
 *       cvm_mesh_stage_write(m, "out.svg") == CVM_OK &&
 *       cvm_mesh_stage_write_dual(m, "dual.vtu") == CVM_OK)
 *       s = cvm_mesh_commit_writes(m);  // all three replace their targets
 *
 * A staged file is complete on disk under a temporary name beside its target
 * (TARGET.tmp.XXXXXX); no target changes before the commit. A failed or
 * cancelled stage discards every staged file, so after any failure every
 * target is as it was. */

/**
 * Write the mesh as cvm_mesh_write() does, to temporary files that replace
 * their targets only at cvm_mesh_commit_writes().
 *
 * @param m     mesh handle; not NULL.
 * @param path  as for cvm_mesh_write(); a .node path stages .node, .ele and .edge.
 * Ownership:    @p path is copied. The staged files belong to @p m until the
 *               commit; cvm_mesh_discard_writes() and cvm_mesh_free() remove them.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * Atomicity:    on any error or cancellation every file staged on @p m so far is
 *               removed too, and no target is touched. A target that is not a
 *               regular file (/dev/null, a FIFO) is written at once, in place.
 *               Later calls that change @p m do not change what was staged.
 * Stops: as cvm_mesh_write(): the progress callback (CVM_STAGE_WRITE) can cancel.
 * @return CVM_OK
 *         CVM_E_NULL_ARG, CVM_E_STATE (nothing triangulated), CVM_E_UNSUPPORTED (extension)
 *         CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM
 *         CVM_INCOMPLETE_CANCELLED  the progress callback stopped it
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_stage_write(cvm_mesh *m, const char *path);

/**
 * Write the dual cells as cvm_mesh_write_dual() does, to a temporary file that
 * replaces its target only at cvm_mesh_commit_writes(). Ownership, atomicity
 * and stops as cvm_mesh_stage_write().
 * @return CVM_OK
 *         CVM_E_NULL_ARG, CVM_E_STATE, CVM_E_UNSUPPORTED (path does not end in .vtu)
 *         CVM_E_TOO_LARGE, CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM
 *         CVM_INCOMPLETE_CANCELLED
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_stage_write_dual(cvm_mesh *m, const char *path);

/**
 * Rename every staged file of @p m over its target, in the order staged, and
 * forget them. Nothing staged: CVM_OK. The renames come last and together; if
 * one fails (the target was made immutable or replaced by a directory since),
 * the targets already replaced are put back as they were (from a hard link
 * taken before the first rename; on a file system without hard links such a
 * target stays replaced) and the remaining staged files are removed.
 * Thread-safety: must not run concurrently with any other call on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG
 *         CVM_E_IO_WRITE  a rename failed (message names the file)
 *         CVM_E_NOMEM     nothing renamed, staged files removed
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_commit_writes(cvm_mesh *m);

/**
 * Remove every staged file of @p m; no target changes. Nothing staged: a no-op.
 * @return CVM_OK, CVM_E_NULL_ARG
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_discard_writes(cvm_mesh *m);

/**
 * Merged dual cells: copy, per triangle in CVM_ENT_TRIANGLE order, the index
 * (in that order) of the smallest triangle of its merged group; a triangle
 * that is not merged gets its own index. Groups are the connected sets of
 * triangles joined across mergeable edges (the rule of CVM_OPT_DUAL_MERGE_TOL).
 * A merged group is one polygonal dual cell: its power vertices are treated as
 * one. A triangle whose power vertex lies outside it counts as compliant when
 * every edge its power vertex lies beyond (exact test) is a mergeable edge, so
 * the triangle across it is in its group (CVM_MEASURE_DUAL_NONCOMPLIANT_PCT).
 * @param dst_len  capacity in entries; must be >= the triangle count.
 * Determinism: depends only on the mesh, its weights and CVM_OPT_DUAL_MERGE_TOL.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_BUFFER_TOO_SMALL (nothing written), CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_merge_groups(cvm_index *dst, size_t dst_len,
                                                   const cvm_mesh *m);

/**
 * Optimise the vertex positions and weights of @p m so that every triangle
 * contains its power vertex or is merged (CVM_OPT_DUAL_MERGE_TOL), and dual
 * edges are not tiny. Per triangle k the score is F_k = W_k L_k |C_k - V_k|
 * (centroid C, power vertex V; W_k = 0 when V lies in k, decided exactly, or k is
 * merged, else 1; L_k = 1 + c / (1 + layer_k), c = CVM_OPT_DUAL_LAYER_PRIORITY,
 * layer_k the breadth-first layer of k from the boundary, see there).
 * Each sweep sorts the triangles with F > 0 worst first (then the "weak" ones of
 * CVM_OPT_DUAL_TARGET_ANGLE_DEG) into min(20, N/25) bins, shuffled within a bin
 * (stream keyed by CVM_OPT_SEED and the sweep), and solves each of their vertices
 * once over (x, y, w): interior vertices move freely, vertices on a segment slide
 * along it, corners, segment ends and vertices of unconstrained convex-hull edges
 * stay (see also CVM_OPT_DUAL_KEEP_INPUT_POINTS); every weight is free. The local
 * objective is a smooth penalty on the vertex's star: the distance by which each power vertex falls short of lying
 * CVM_OPT_DUAL_MARGIN x the edge length inside each edge, squared, plus a small
 * centroid-to-power-vertex term, over squared edge lengths. A candidate is
 * rejected when a star triangle would not be strictly counter-clockwise (exact
 * orient2d), an angle would drop below CVM_OPT_DUAL_MIN_ANGLE_DEG (see there), or
 * the vertex's power cell in its star would be empty. After each sweep, Lawson
 * flips under the exact power test restore the regular triangulation; a Steiner
 * vertex whose power cell vanished is removed (CVM_OPT_DUAL_TOPOLOGY, reported in
 * CVM_MEASURE_DUAL_OPT_REMOVED_VANISHED; the remaining vertices are renumbered in
 * order), any other gets its weight raised until none vanishes (after 8 rounds
 * every weight is reset to 0). No vertex is added, input points are never
 * removed, segments and regions are kept. The run stops when no triangle is
 * non-compliant or weak, a sweep moves nothing, or at CVM_OPT_DUAL_MAX_SWEEPS;
 * once every triangle is compliant, after 4 sweeps in which neither the
 * smallest angle rose by 0.05 degrees nor the weak triangles fell 1% below
 * their last low, the target angle is raised by 5 degrees (once, up to 60) and
 * the run ends at the next such stall. It returns the best state it met (fewest
 * non-compliant triangles, then the largest smallest angle): that state's
 * positions and weights and their regular triangulation. When that state is
 * compliant, the max-min-angle phase of CVM_OPT_DUAL_MAXMIN_ROUNDS follows (it
 * keeps every triangle compliant and never lowers the smallest angle; its
 * removal trials, CVM_OPT_DUAL_MAXMIN_TRIALS, may remove Steiner vertices,
 * renumbered as above). The
 * report of the run is CVM_MEASURE_DUAL_OPT_*.
 *
 * @param m       mesh handle, triangulated; not NULL. Existing weights are the start.
 * @param sizing  local size for the solver's step lengths; may be NULL: then the
 *                size at a vertex is the mean length of its edges. Its automatic and
 *                boundary-grading parts are built from the mesh at the start of the
 *                call (as cvm_mesh_refine() does). Read only during the call; not kept.
 * Options:  CVM_OPT_DUAL_*, CVM_OPT_SEED, CVM_OPT_TIME_LIMIT_S; the progress
 *           callback (stage CVM_STAGE_OPTIMISE_DUAL) gets the fraction of the
 *           initially non-compliant triangles made compliant so far, and can cancel.
 * Stops:    on the time limit or cancellation the mesh is a valid regular
 *           triangulation (positions and weights reached so far).
 * Threads:  the local problems of each batch (vertices no two of which are equal or
 *           adjacent, cut from the sweep order independently of the thread count)
 *           run on CVM_OPT_THREADS OpenMP threads; moves are applied in batch order,
 *           so the result does not depend on the thread count.
 * Determinism: same mesh, options and seed give bit-identical output (except
 *           where the time limit stops the run).
 * Atomicity: on CVM_E_NOMEM the mesh is conforming and counter-clockwise: usually the
 *           regular triangulation of the last completed sweep; when memory ran out
 *           between the flips that end a sweep, the new positions with their
 *           flips, where an edge may still fail the power test (cvm_mesh_check()
 *           says so; a new call with memory restores regularity).
 * @return CVM_OK
 *         CVM_E_NULL_ARG           m is NULL
 *         CVM_E_STATE              nothing triangulated
 *         CVM_E_UNSUPPORTED        CVM_OPT_DUAL_PREPASS or CVM_OPT_DUAL_MAXMIN_TRIALS set with
 *                                  CVM_OPT_DUAL_TOPOLOGY 0 (error item: that option; mesh unchanged),
 *                                  or the sizing has a metric source (cvm_sizing_set_metric_fn();
 *                                  mesh unchanged)
 *         CVM_E_ARGUMENT           the sizing callback returned a value <= 0 (message
 *                                  gives the position)
 *         CVM_E_INPUT_NONFINITE    the sizing callback returned NaN or infinity
 *         CVM_E_NOMEM
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_optimise_dual(cvm_mesh *m, const cvm_sizing *sizing);

/**
 * Generate a tetrahedral co-volume mesh inside the closed surface of @p m
 * (cvm_mesh_read() of .off/.stl/.poly/.smesh): points are placed, then
 * tetrahedralised with the surface as cvm_mesh_triangulate() does (hole points
 * emptied, regions' attributes kept). Walton, Hassan and Morgan's pipeline:
 *  - size: @p size everywhere (CVM_OPT_GEN3_SIZE_FROM_SURFACE 0), or by default
 *    min(size, l + g * distance) from each surface triangle (mean edge l,
 *    g = CVM_OPT_GEN3_GRADING), from the surface read; a 3D cvm_sizing lowers it
 *    further (cvm_mesh_generate3_sized());
 *  - surface: used as given (CVM_OPT_GEN3_SURFACE 0), or its planar facets re-meshed
 *    by the 2D frontal refiner at that size (1; CVM_REPORT_GEN3_FACETS_REMESHED);
 *    the mesh then holds the re-meshed surface and its points;
 *  - near field: surface triangles paired across edges by a maximum-cardinality
 *    matching; a pair ABC/BDC gets x = (c1 + c2 + delta (n1 + n2)) / 2, delta =
 *    1.1 max(R1, R2) (circumcentres, inward normals, circumradii); an unmatched
 *    triangle c + 1.1 R n; pairs whose well-centred regions may not meet are
 *    dropped first (a sufficient test: the edge is not reflex and x lies on the
 *    inner side of, and outside the diametral sphere of, both triangles);
 *  - free space (CVM_OPT_GEN3_FREESPACE): by default a body-centred cubic lattice,
 *    axis-aligned from the surface's bounding-box corner, cube edge size / 2^k
 *    where the size falls in (size / 2^(k+1), size / 2^k] (edges a and 0.866 a);
 *    or (1) an octree: the surface's bounding cube, an octant of edge e split while
 *    e > 2^(2/3) h(c) (h(c) the size at its centre: as many points per volume as
 *    the lattice), 2:1-balanced across faces, one point at each leaf's centroid
 *    (corners are not used); where the tree is uniform the points form a cubic
 *    lattice, whose cospherical tetrahedra the merged dual cells join
 *    (cvm_mesh_copy_dual3_merge_groups(); CVM_REPORT_GEN3_OCTREE_*); or (2) Delaunay
 *    refinement, the baseline: rounds of tetrahedralising the points so far and
 *    placing the circumcentre of each tetrahedron whose circumradius exceeds h there
 *    (its centroid when the circumcentre is outside the domain or at the surface),
 *    until a round places none (at most 100 rounds, and at most CVM_OPT_MAX_STEINER
 *    points when that is set; CVM_REPORT_GEN3_REFINE_*);
 *  - every placed point lies strictly inside the domain (exact ray parity) and
 *    farther than its rejection distance from every earlier point (half its
 *    near-field offset; 0.55 h(x) for a lattice point, h(x) the size there;
 *    0.55 min(h(x), e) for an octree centroid, which also keeps that far from
 *    every surface triangle; 0.55 h(x) for a refinement point, and half that from
 *    every surface triangle).
 * Without TetGen (cvm_build_string()), placed points that keep a surface
 * triangle from being a Delaunay face are removed again, a few rounds
 * (CVM_MEASURE_GEN3_RECOVERY_DROPPED). Not in this version: more than one
 * near-field layer, the octree's optional split of octants with face-hanging nodes,
 * splitting surface triangles in the refinement (the surface is kept as given), a
 * lattice grown in a local frame, internal facets between regions.
 * The report of the run: CVM_REPORT_GEN3_* (cvm_mesh_get_report()); the mesh's
 * measures as after cvm_mesh_triangulate(). Vertices: the surface's points,
 * then the near-field points, then the free-space points (lattice, octree or
 * refinement, in placement order).
 *
 * @param m     mesh handle holding a closed 3D surface; not NULL.
 * @param size  largest size (length unit of the coordinates), positive and finite.
 * Ownership:    the input is kept unchanged (a later cvm_mesh_triangulate() meshes the
 *               surface alone); the generated mesh replaces the previous output.
 * Thread-safety: one call at a time on @p m. The result does not depend on the seed or
 *               on the number of threads.
 * Stops:        the time limit and progress callback act in the tetrahedralisation only,
 *               as in cvm_mesh_triangulate() (a stop leaves the mesh empty). The
 *               refinement free space stops at CVM_OPT_MAX_STEINER points (0: no limit)
 *               with a valid mesh of the points so far: CVM_INCOMPLETE_STEINER_LIMIT.
 * @return CVM_OK
 *         CVM_E_NULL_ARG
 *         CVM_E_INPUT_NONFINITE   size is NaN or infinite (message gives it)
 *         CVM_E_ARGUMENT          size is zero or negative (message gives it)
 *         CVM_E_STATE             the handle holds no 3D surface (2D input, or a 3D point set)
 *         CVM_E_UNSUPPORTED       CVM_OPT_GEN3_LAYERS above 1, a surface with internal facets (an edge
 *                                 of other than two triangles; message names its points),
 *                                 or, without TetGen, a surface triangle that is no Delaunay
 *                                 face of the surface's own points (as in
 *                                 cvm_mesh_triangulate()) or stays none after generated
 *                                 points near it are removed (message names the face in the
 *                                 file's numbering)
 *         CVM_E_TOO_LARGE         size so small against the surface's extent that the
 *                                 lattice would pass 2^19 cells along an axis or about
 *                                 240,000,000 candidates, the octree (extent / size)^3 or
 *                                 its nodes 60,000,000, or the points would pass the 3D
 *                                 limit of 60,000,000, or the re-meshed surface
 *                                 (CVM_GEN3_SURFACE_REMESH_ALL) would pass 4,000,000
 *                                 triangles (message gives the numbers)
 *         the surface's statuses of cvm_mesh_triangulate() (not closed, self-intersecting, ...)
 *         CVM_E_INTERNAL          CVM_OPT_GEN3_SURFACE 1 made a surface that fails the
 *                                 input checks (a bug; the message says so), or 2 did so
 *                                 at the size, half and a quarter of it (a re-meshing
 *                                 that folds at a sharp corner is tried again finer; the
 *                                 generation keeps the size)
 *         CVM_E_NOMEM             (the handle keeps its input; the output is dropped)
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED (as cvm_mesh_triangulate())
 *         CVM_INCOMPLETE_STEINER_LIMIT the refinement free space met CVM_OPT_MAX_STEINER (the
 *                                 mesh is valid; the message gives the count)
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_generate3(cvm_mesh *m, double size);

/**
 * cvm_mesh_generate3() with the size given by a sizing handle as well: the size at
 * x is min(size, sizing(x), the surface-following field min over surface triangles
 * of l + g * distance when CVM_OPT_GEN3_SIZE_FROM_SURFACE is 1). The sizing's
 * boundary grading g_b (cvm_sizing_set_boundary_grading()) adds that
 * surface-following field with slope g_b (also when the option is 0); with both,
 * the smaller slope holds. The free-space lattice adds levels (cube edge size / 2^k)
 * down to the smallest size of the sizing's sources (a callback: while a level
 * meets points below its range, up to 2^-23 size) and visits, per level, only the
 * boxes where a source can reach that level's size (everywhere for a uniform size,
 * a zero growth or a callback). The octree goes down to the level whose edge is at
 * most 2^(2/3) times the sources' smallest size (a callback: 19 levels), and also
 * splits an octant of edge e that meets a bounded box where a point, line or
 * triangle source can reach e / 2^(2/3) (so none is missed; a background mesh and a
 * callback are read at the octants' centres only); the
 * refinement reads the size at each circumcentre. With @p sizing NULL or empty the call is
 * cvm_mesh_generate3(m, size), the same bytes.
 *
 * @param m       mesh handle holding a closed 3D surface; not NULL.
 * @param size    largest size, positive and finite (as cvm_mesh_generate3()).
 * @param sizing  3D sizing (sources added with dim 3, cvm_sizing_set_callback_nd(),
 *                uniform, boundary grading); may be NULL. Read only.
 * Ownership, thread-safety, stops: as cvm_mesh_generate3(); @p sizing must not be
 *               changed during the call (it may be shared by calls on other meshes
 *               only when it has no callback with state).
 * @return the statuses of cvm_mesh_generate3(), and
 *         CVM_E_ARGUMENT          the sizing holds 2D sources or a 2D callback (message
 *                                 says which), or its callback returned a value <= 0
 *                                 (message names "the sizing callback" and the position)
 *         CVM_E_INPUT_NONFINITE   the callback returned NaN or infinity (message as above)
 *         CVM_E_UNSUPPORTED       the sizing has an automatic size
 *                                 (cvm_sizing_set_automatic()) or a metric source
 *         CVM_E_TOO_LARGE         also when a finer level's candidates pass the limit of
 *                                 cvm_mesh_generate3()
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_generate3_sized(cvm_mesh *m, double size, const cvm_sizing *sizing);

/**
 * Optimise the vertex positions and power weights of the tetrahedral mesh of
 * @p m so that more tetrahedra contain their power vertex (the 3D form of
 * cvm_mesh_optimise_dual()). Sweeps visit
 * the vertices of the tetrahedra whose power vertex lies strictly outside them
 * (exact), worst score F_k = W_k L_k |C_k - V_k| first (centroid C, power
 * vertex V, W_k 1 when outside else 0, L_k 2 with a boundary face else 1), in
 * min(20, n/25 + 1) bins shuffled within by a stream keyed by CVM_OPT_SEED and
 * the sweep. Each vertex gets a compass search over (x, y, z, w) on a smooth
 * penalty of its tetrahedra (the distance by which each power vertex falls
 * short of lying CVM_OPT_DUAL3_MARGIN x the RMS edge inside each face,
 * squared, plus a small centroid term, over the squared RMS edge). A move is
 * kept only when the penalty drops and: every tetrahedron of the vertex stays
 * positively oriented (exact orient3d); every face there that is not on the
 * surface stays locally regular (exact power test; a face that failed before
 * may keep failing); the exactly counted outside tetrahedra there do not
 * increase; no dihedral angle there drops below min(CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG,
 * the smallest before). With CVM_OPT_DUAL3_FLIPS (default) the connectivity
 * changes instead of refusing a move for local regularity: exact 2-3, 3-2 and
 * 4-4 flips of unconstrained faces between tetrahedra of one region repair
 * every face the move left not locally regular (else the move and its flips
 * are undone), and the other rules are judged on the tetrahedra replaced
 * against those replacing them; a first pass flips the input's faces that are
 * not locally regular (when no new dihedral angle drops below min(10 degrees,
 * the smallest there)); a face that no flip repairs may keep failing only by the
 * perturbation (never with a vertex strictly inside an orthosphere). Flips
 * never remove a vertex or a surface triangle, but they renumber the
 * tetrahedra and change their count. Vertices on a boundary face (or an internal facet)
 * keep their position, except those inside an axis-aligned planar facet
 * (CVM_OPT_DUAL3_SLIDE_BOUNDARY), which move within its plane; every weight is free. So
 * the surface triangles stay faces, no power cell vanishes, and a locally
 * regular mesh stays the regular tetrahedralisation of its weighted vertices.
 * The run stops when nothing is outside, a sweep moves nothing, after 3 sweeps
 * without a new lowest count, or at CVM_OPT_DUAL3_MAX_SWEEPS. Not in this
 * version: flips of surface triangles, boundary vertices sliding on oblique or
 * curved surfaces, Modified Cuckoo Search, threads, merging into polyhedral cells.
 * The report: CVM_REPORT_DUAL3_* (cvm_mesh_get_report()).
 *
 * @param m  mesh handle holding a tetrahedral mesh (cvm_mesh_generate3(),
 *           cvm_mesh_triangulate() of 3D input, cvm_mesh_read() of a 3D mesh); not NULL.
 *           Existing weights are the start (none: all 0); the result has weights.
 * Options:  CVM_OPT_DUAL3_*, CVM_OPT_SEED, CVM_OPT_TIME_LIMIT_S; the progress callback
 *           (stage CVM_STAGE_OPTIMISE_DUAL) gets the fraction of the initially outside
 *           tetrahedra fixed so far, and can cancel. CVM_OPT_THREADS is not read.
 * Stops:    on the time limit or cancellation the mesh holds the moves (and flips) made
 *           so far, each of which kept it valid.
 * Determinism: same mesh, options and seed give bit-identical output (except where the
 *           time limit stops the run), whatever the number of threads.
 * Atomicity: on CVM_E_NOMEM (raised before any move) the mesh is unchanged. With flips
 *           the tetrahedra are renumbered: indices taken before (cells, their region
 *           attributes, merge groups, dual vertices) do not apply to the result.
 * @return CVM_OK
 *         CVM_E_NULL_ARG
 *         CVM_E_STATE            no tetrahedral mesh on the handle (a 2D handle: use
 *                                cvm_mesh_optimise_dual())
 *         CVM_E_NOMEM
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_optimise_dual3(cvm_mesh *m);

/* ------------------------------------------------------------------------ */
/* Quad-dominant meshing                                                    */
/* ------------------------------------------------------------------------ */

/**
 * Mesh the input domain of @p m with quadrilaterals (and a few triangles) of unit
 * size and right angles in the metric of @p metric: an Lp-CVT under the metric
 * (Levy and Liu 2010; Ekelschot et al., NASA Ames), then Blossom-Quad recombination
 * (Remacle et al. 2012). Steps:
 *   1. the input (cvm_mesh_set_points()/_set_segments() or cvm_mesh_read() of a .poly)
 *      is triangulated as by cvm_mesh_triangulate(); its boundary must be one closed
 *      convex polygon (collinear vertices allowed), every input point on it, no holes;
 *   2. each boundary edge is split into n = max(1, round(L_M)) pieces of equal metric
 *      length L_M (adaptive Gauss-Kronrod to 1e-12, Newton); those points stay fixed;
 *   3. interior sites are placed by an advancing front from the boundary points, one
 *      unit metric step at a time along the metric's eigenvectors (along the nearest
 *      domain edge where the metric is isotropic), or with CVM_OPT_QUAD_INITIAL_SITES = 1
 *      drawn from the density sqrt(det g) (N from the metric area; a Halton sequence
 *      rotated by CVM_OPT_SEED); both deterministic. They are then moved by L-BFGS
 *      (liblbfgs) to a minimum of E = sum_i Int_{cell i} |M(y)(y - x_i)|_p^p dy, g = M^T M,
 *      M = Lambda^(1/2) Q^T, with the exact gradient (the Voronoi diagram is rebuilt at
 *      every evaluation); sites that end outside the domain are dropped;
 *   4. the Delaunay triangulation of all sites becomes the triangles of @p m
 *      (CVM_ENT_TRIANGLE, cvm_mesh_copy_cells(); the input points keep their vertex
 *      numbers, then the boundary points, then the interior sites);
 *   5. pairs of triangles are recombined into quads (CVM_OPT_QUAD_RECOMBINE,
 *      CVM_OPT_QUAD_MIN_QUALITY). The quad-dominant cells are the mixed cells
 *      (cvm_mesh_count_cells_mixed()/cvm_mesh_copy_cells_mixed() with CVM_ENT_CELL:
 *      CVM_CELL_QUAD and CVM_CELL_TRIANGLE, counter-clockwise, in the order of their
 *      first triangle); cvm_mesh_write() writes them to .vtu and .msh (other formats:
 *      CVM_E_UNSUPPORTED).
 * The measures of the result are reports of the run (CVM_REPORT_QUAD_*, also readable
 * as cvm_mesh_get_measure() of the same number), since the metric is not kept.
 * Any later call that changes the mesh (triangulate, refine, insert, weights, dual
 * optimisation, read) drops the quads; the mixed cells are then the triangles again.
 *
 * @param m       mesh handle with 2D input; not NULL.
 * @param metric  sizing handle with a metric source that gives derivatives
 *                (cvm_sizing_set_metric_fn() with has_derivatives = 1,
 *                cvm_sizing_set_metric_builtin(), cvm_sizing_set_metric_constant());
 *                its scalar sources are not read. Outside the domain the metric is the
 *                callback's value when it accepts the point, else the value at the
 *                nearest boundary point. Read only during the call; not kept.
 * Options:  CVM_OPT_QUAD_*, CVM_OPT_SEED, CVM_OPT_TIME_LIMIT_S, CVM_OPT_THREADS (the energy
 *           and gradient assembly; the metric callback is then called from several
 *           threads at once and must be reentrant), and the triangulation options of
 *           cvm_mesh_triangulate().
 * Stops:    the progress callback (stage CVM_STAGE_QUAD_OPTIMISE, once per L-BFGS
 *           iteration when every_n is 1) can cancel, and CVM_OPT_TIME_LIMIT_S stops the
 *           optimisation; the sites reached so far are then triangulated and recombined,
 *           and the call returns CVM_INCOMPLETE_* with a valid quad-dominant mesh.
 * Threads:  the result does not depend on CVM_OPT_THREADS.
 * Determinism: same input, metric, options and seed give bit-identical output (except
 *           where the time limit stops the run).
 * Atomicity: on an error @p m holds no triangulation (as after a failed
 *           cvm_mesh_triangulate()); its input is unchanged.
 * @return CVM_OK
 *         CVM_E_NULL_ARG           m or metric is NULL
 *         CVM_E_STATE              metric has no metric source
 *         CVM_E_UNSUPPORTED        a 3D mesh; a domain that is not one convex polygon (holes,
 *                                  a concave corner: the message names the vertex), an input
 *                                  point inside the domain, segments that cross
 *         CVM_E_ARGUMENT           the metric is not finite or not positive definite at a
 *                                  point, refuses a point with no boundary to fall back on,
 *                                  or gives no derivatives (the message gives the point)
 *         CVM_E_INPUT_*            as cvm_mesh_triangulate()
 *         CVM_E_TOO_LARGE          the metric asks for more than 1e9 sites or 2^30 boundary points
 *         CVM_E_NOMEM
 *         CVM_E_INTERNAL
 *         CVM_INCOMPLETE_TIME_LIMIT, CVM_INCOMPLETE_CANCELLED
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_quadmesh(cvm_mesh *m, const cvm_sizing *metric);

/* ------------------------------------------------------------------------ */
/* Quality                                                                   */
/* ------------------------------------------------------------------------ */

/**
 * Scalar quality measures of cvm_mesh_get_measure(). Values never change.
 * Most are measures of the current mesh; 11-16, 40-49 and 60 are reports of the last
 * run (what it asked for and did), which cvm_mesh_get_report() reads under the
 * names of cvm_report. New measures of the mesh use the free numbers below 100;
 * 700-799 are reserved for 3D measures, 800-899 for quad measures.
 */
typedef enum cvm_measure {
    CVM_MEASURE_MIN_ANGLE_DEG = 1,      /**< smallest triangle angle, degrees */
    CVM_MEASURE_MAX_ANGLE_DEG = 2,      /**< largest triangle angle, degrees */
    CVM_MEASURE_REGULAR_PCT = 3,        /**< % of angles in [55, 65] degrees */
    CVM_MEASURE_OBTUSE_PCT = 4,         /**< % of triangles not containing their circumcentre
                                             (an angle > 90 degrees: not well-centred) */
    CVM_MEASURE_DEGREE6_PCT = 5,        /**< % of interior vertices of degree 6 (0 without
                                             interior vertices) */
    CVM_MEASURE_MIN_DUAL_EDGE_RATIO = 6,/**< smallest power-dual edge length (between the power
                                             vertices of the two triangles; the Voronoi edge
                                             without weights) over its primal edge length,
                                             over interior edges (0 without any) */
    CVM_MEASURE_MIN_EDGE = 7,           /**< shortest edge length */
    CVM_MEASURE_MAX_EDGE = 8,           /**< longest edge length */
    CVM_MEASURE_AREA = 9,               /**< total area */
    CVM_MEASURE_MIN_AREA = 10,          /**< smallest triangle area */
    /* Report of the last cvm_mesh_refine() on the handle (0 before any refinement,
       and after cvm_mesh_triangulate()): */
    CVM_MEASURE_REFINE_STEINER = 11,    /**< vertices added (segment marching included) */
    CVM_MEASURE_REFINE_UNMET_ANGLE = 12,/**< triangles left with an angle below the requested
                                             minimum (small input angles included) */
    CVM_MEASURE_REFINE_UNMET_SIZE = 13, /**< triangles left too big for the sizing or max area */
    CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE = 14, /**< of REFINE_UNMET_ANGLE, those left alone
                                             because a small input angle subtends them */
    CVM_MEASURE_REFINE_REQUESTED_ANGLE = 15, /**< the minimum angle the run asked for, degrees */
    CVM_MEASURE_REFINE_MET_ANGLE = 16,  /**< smallest angle over triangles not subtended by a
                                             small input angle, degrees */
    /* The power (weighted Voronoi) dual, see "Weights and the power (Voronoi) dual": */
    CVM_MEASURE_DUAL_OUTSIDE_PCT = 17,  /**< % of triangles not containing their power vertex
                                             (decided exactly; on an edge counts as inside) */
    CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT = 18, /**< the same % over the triangles with a vertex
                                             on the domain boundary (0 without any) */
    CVM_MEASURE_MIN_DUAL_EDGE = 19,     /**< smallest dual edge length over interior edges
                                             (length units; 0 without interior edges) */
    CVM_MEASURE_TIME_STEP_PROXY = 20,   /**< smallest min(primal, dual edge length) over interior
                                             edges: sets the stable explicit time step of a
                                             co-volume scheme (length units; 0 without any) */
    CVM_MEASURE_VANISHED_VERTICES = 21, /**< vertices the regular triangulation would drop
                                             (empty power cell): the blocking corner of each
                                             illegal edge that no flip can fix; cvmesh keeps
                                             them (see cvm_mesh_set_weights()) */
    /* Dual quality q1..q5 (see cvm_histogram for the definitions). "Boundary"
       triangles have a vertex on the domain boundary; "boundary" edges are
       interior edges with an endpoint on it. Values 22-24 and 40-59 are
       reserved for the dual optimiser's measures. */
    CVM_MEASURE_Q1_MEAN_DEG = 25,       /**< mean over triangles of the smallest angle, degrees */
    CVM_MEASURE_Q2_MAX = 26,            /**< largest q2 (|centroid - power vertex| / inradius) */
    CVM_MEASURE_Q2_MEAN = 27,           /**< mean q2 over triangles */
    CVM_MEASURE_Q3_MAX = 28,            /**< largest q3 over interior edges (0 without any) */
    CVM_MEASURE_Q4_MAX = 29,            /**< largest q4 over interior edges (0 without any) */
    CVM_MEASURE_Q5_MIN = 30,            /**< smallest q5 (dual edge / (l / sqrt 3)) over interior
                                             edges (0 without any) */
    CVM_MEASURE_Q5_MEAN = 31,           /**< mean q5 over interior edges (0 without any) */
    CVM_MEASURE_Q1_MIN_BOUNDARY_DEG = 32, /**< smallest angle over boundary triangles, degrees */
    CVM_MEASURE_Q2_MAX_BOUNDARY = 33,   /**< largest q2 over boundary triangles */
    CVM_MEASURE_Q5_MIN_BOUNDARY = 34,   /**< smallest q5 over interior edges with an endpoint on
                                             the boundary (0 without any) */
    /* Merging (CVM_OPT_DUAL_MERGE_TOL, cvm_mesh_copy_dual_merge_groups()): */
    CVM_MEASURE_DUAL_MERGED_PCT = 22,   /**< % of triangles in a merged group of 2 or more */
    CVM_MEASURE_DUAL_NONCOMPLIANT_PCT = 23, /**< % of triangles whose power vertex lies outside
                                             (exact) and not merged across each edge it lies
                                             beyond (see cvm_mesh_copy_dual_merge_groups()) */
    CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT = 24, /**< the same % over the triangles with
                                             a vertex on the domain boundary (0 without any) */
    /* Report of the last cvm_mesh_optimise_dual() on the handle (0 before any, and
       after cvm_mesh_triangulate()): */
    CVM_MEASURE_DUAL_OPT_SWEEPS = 40,   /**< sweeps run */
    CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_BEFORE_PCT = 41, /**< DUAL_NONCOMPLIANT_PCT at the start */
    CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_AFTER_PCT = 42,  /**< DUAL_NONCOMPLIANT_PCT at the end */
    CVM_MEASURE_DUAL_OPT_MOVES = 43,    /**< accepted local moves (a vertex per sweep at most) */
    CVM_MEASURE_DUAL_OPT_FLIPS = 44,    /**< flips restoring the regular triangulation */
    CVM_MEASURE_DUAL_OPT_WEIGHT_FIXES = 45, /**< weights raised so that no power cell vanished
                                             (vertices removed: always 0, none are) */
    CVM_MEASURE_DUAL_OPT_SECONDS = 46,  /**< wall time of the run, seconds (not deterministic) */
    CVM_MEASURE_DUAL_OPT_REMOVED_VANISHED = 47, /**< Steiner vertices removed because their
                                             power cell vanished (CVM_OPT_DUAL_TOPOLOGY) */
    CVM_MEASURE_DUAL_OPT_REMOVED_DEGREE = 48, /**< Steiner vertices removed by the degree
                                             repair (CVM_OPT_DUAL_TOPOLOGY) */
    CVM_MEASURE_DUAL_OPT_REMOVED_MAXMIN = 49, /**< Steiner vertices removed by the kept removal
                                             trials of the max-min-angle phase
                                             (CVM_OPT_DUAL_MAXMIN_ROUNDS) */
    /* Report of the last cvm_mesh_read() of a mesh file (.vtu, .vtk, .msh) on the
       handle (0 before any, and after cvm_mesh_triangulate()): */
    CVM_MEASURE_READ_FLIPS = 60,        /**< edge flips that made the file's triangles (constrained)
                                             Delaunay, or regular with weights; 0 when the mesh
                                             holds exactly the file's triangles */
    /* ---- 700-799: 3D meshes (cvm_mesh_dim() 3); MIN_EDGE, MAX_EDGE and
     * VANISHED_VERTICES apply to them too ---- */
    CVM_MEASURE_VOLUME = 700,           /**< total volume of the tetrahedra */
    CVM_MEASURE_MIN_DIHEDRAL_DEG = 701, /**< smallest dihedral angle, degrees */
    CVM_MEASURE_MAX_DIHEDRAL_DEG = 702, /**< largest dihedral angle, degrees */
    CVM_MEASURE_MAX_RADIUS_EDGE = 703,  /**< largest circumradius / shortest edge of a tetrahedron
                                             (1/sqrt(2) ~ 0.612 for the regular one) */
    CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT = 704, /**< % of tetrahedra whose circumcentre (power
                                             vertex, with weights) lies outside them, decided
                                             exactly from the coordinates and weights (the sign
                                             of each barycentric coordinate of the centre); a
                                             centre exactly on a face, edge or corner counts as
                                             inside (the Kuhn tetrahedra of a cube: 0) */
    CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT = 705, /**< the same (exact, on a face counts
                                             as inside) over the tetrahedra with a face on the
                                             boundary */
    CVM_MEASURE_RECOVERY_STEINER = 706, /**< points the boundary recovery added (0 for a point
                                             set's Delaunay tetrahedralisation) */
    /* 3D dual and shape (since 0.2). "Interior" face: a face shared by two
     * tetrahedra; its dual edge joins their power vertices, and a face whose two
     * power vertices coincide exactly (the exact power test ties, as for the
     * tetrahedra of one cube of a cubic lattice) has none and is skipped.
     * "Interior" vertex: on no boundary face. */
    CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D = 720, /**< smallest dual edge length over the mean edge
                                             length of its face, over interior faces (0 without
                                             any) */
    CVM_MEASURE_TIME_STEP_PROXY_3D = 721, /**< smallest min(dual edge length, shortest edge of
                                             its face) over interior faces: the explicit time
                                             step scale of a co-volume scheme (length units; 0
                                             without any) */
    CVM_MEASURE_VALENCE14_PCT = 722,    /**< % of interior vertices with 14 edges (the BCC
                                             lattice's valence; 0 without interior vertices) */
    CVM_MEASURE_MEAN_RADIUS_EDGE = 723, /**< mean circumradius / shortest edge over the
                                             tetrahedra (CVM_MEASURE_MAX_RADIUS_EDGE is the
                                             largest) */
    CVM_MEASURE_MIN_DUAL_EDGE_3D = 724, /**< smallest dual edge length over interior faces
                                             (length units; 0 without any) */
    /* Merged 3D dual cells (CVM_OPT_DUAL3_MERGE_TOL, cvm_mesh_copy_dual3_merge_groups()): */
    CVM_MEASURE_DUAL3_MERGED_PCT = 725, /**< % of tetrahedra in a kept merged group of 2 or
                                             more */
    CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT = 726, /**< % of tetrahedra whose power vertex lies
                                             outside (exact, as CIRCUMCENTRE_OUTSIDE_PCT) and
                                             not only beyond faces mergeable within a kept
                                             group (0 without tetrahedra) */
    CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT = 727, /**< the same % over the tetrahedra
                                             with a face on the boundary (0 without any) */
    CVM_MEASURE_DUAL3_MERGE_DISSOLVED = 728, /**< merged groups of 2 or more dissolved
                                             because they failed the convexity or star check */
    /* 740-769: the report of the last cvm_mesh_generate3() (0 before any) */
    CVM_MEASURE_GEN3_MATCHED_PAIRS = 740,   /**< pairs of surface triangles matched */
    CVM_MEASURE_GEN3_UNMATCHED_FACES = 741, /**< surface triangles left unmatched */
    CVM_MEASURE_GEN3_PAIRS_REJECTED = 742,  /**< adjacent pairs dropped before the matching
                                                 (their well-centred regions may not meet) */
    CVM_MEASURE_GEN3_NEAR_POINTS = 743,     /**< near-field points placed */
    CVM_MEASURE_GEN3_NEAR_REJECTED = 744,   /**< near-field points not placed (outside the
                                                 domain, or too close to a point) */
    CVM_MEASURE_GEN3_LATTICE_POINTS = 745,  /**< free-space lattice points placed */
    CVM_MEASURE_GEN3_LATTICE_LEVELS = 746,  /**< lattice levels (sizes h / 2^k) that placed a point */
    CVM_MEASURE_GEN3_RECOVERY_DROPPED = 747, /**< placed points removed again so that every
                                                 surface triangle is a Delaunay face (builds
                                                 without TetGen; 0 with it) */
    CVM_MEASURE_GEN3_SECONDS = 748,         /**< wall time of the run, seconds (not deterministic) */
    CVM_MEASURE_GEN3_FACETS_REMESHED = 757, /**< planar facets re-meshed (CVM_OPT_GEN3_SURFACE 1) */
    CVM_MEASURE_GEN3_SURFACE_TRIS_BEFORE = 758, /**< surface triangles read */
    CVM_MEASURE_GEN3_SURFACE_TRIS_AFTER = 759,  /**< surface triangles meshed (= before when
                                                     the surface is used as given) */
    CVM_MEASURE_GEN3_OCTREE_LEAVES = 761,   /**< leaves of the balanced octree
                                                 (CVM_GEN3_FREESPACE_OCTREE; else 0) */
    CVM_MEASURE_GEN3_OCTREE_POINTS = 762,   /**< octree centroids placed (else 0) */
    CVM_MEASURE_GEN3_REFINE_POINTS = 763,   /**< circumcentres placed by the Delaunay-refinement
                                                 free space (CVM_GEN3_FREESPACE_REFINE; else 0) */
    CVM_MEASURE_GEN3_REFINE_ROUNDS = 764,   /**< its rounds that had candidates (else 0) */
    /* ---- 800-899: the quad measures are reports of the last cvm_mesh_quadmesh() (the
     * metric is not kept with the mesh): cvm_mesh_get_measure() accepts the
     * CVM_REPORT_QUAD_* values (800-821) and gives the same numbers ---- */
} cvm_measure;

/**
 * Histograms of cvm_mesh_copy_histogram(); also the per-element values of
 * cvm_mesh_copy_dual_quality() for CVM_HIST_Q1 .. CVM_HIST_Q5.
 *
 * The dual quality measures of the power dual. All are plain
 * doubles (measures, not decisions). For an edge pq, l = |pq| is the local
 * size (cvmesh does not keep the sizing of a refinement, so the primal edge
 * stands for it) and M is the power-bisector foot of pq (the point of line pq
 * with equal power distance to p and q). The dual edge of an interior edge
 * joins the power vertices V1, V2 of its two triangles; both lie on the power
 * bisector of p and q, which is perpendicular to pq through M, so the line
 * V1V2 crosses the line pq exactly at M ("the crossing"). On a boundary edge
 * the dual edge is the half edge from the power vertex V of its triangle to M.
 *  q1 (per triangle): smallest angle, degrees.
 *  q2 (per triangle): |C - V| / r, C the centroid, V the power vertex, r the
 *     inradius (0 for an equilateral triangle without weights).
 *  q3 (per edge): |M - (p + q)/2| / l, offset of the crossing from the
 *     primal edge midpoint (0 without weights).
 *  q4 (per edge): |M - (V1 + V2)/2| / l, offset of the crossing from the dual
 *     edge midpoint; on a boundary edge |V - M| / (2 l).
 *  q5 (per edge): |V1 - V2| / (l / sqrt 3), dual edge length over the ideal
 *     (1 on an equilateral lattice); on a boundary edge |V - M| / (l / (2 sqrt 3)).
 * Histograms of q1, q2 count triangles; those of q3, q4, q5 count interior
 * edges only (a boundary edge's dual half edge ends at the crossing by
 * construction). Bin edges are given per value; the last bin of q2..q5 is
 * open (it counts every larger value).
 */
typedef enum cvm_histogram {
    CVM_HIST_ANGLE_DEG = 1, /**< 18 bins of 10 degrees: [0,10), ..., [170,180] */
    CVM_HIST_DEGREE = 2,    /**< 16 bins: interior vertex degree 0..14, and >= 15 */
    CVM_HIST_Q1 = 3,        /**< 12 bins of 5 degrees: [0,5), ..., [55,60] */
    CVM_HIST_Q2 = 4,        /**< 20 bins of 0.25: [0,0.25), ..., [4.5,4.75), [4.75,inf) */
    CVM_HIST_Q3 = 5,        /**< 20 bins of 0.05: [0,0.05), ..., [0.9,0.95), [0.95,inf) */
    CVM_HIST_Q4 = 6,        /**< 20 bins of 0.05: [0,0.05), ..., [0.9,0.95), [0.95,inf) */
    CVM_HIST_Q5 = 7,        /**< 20 bins of 0.1: [0,0.1), ..., [1.8,1.9), [1.9,inf) */
    /* 3D meshes (since 0.2) */
    CVM_HIST_DIHEDRAL_DEG = 720, /**< 18 bins of 10 degrees over the six dihedral angles of
                                      every tetrahedron: [0,10), ..., [170,180] */
    CVM_HIST_VALENCE_3D = 721    /**< 32 bins: number of edges at an interior vertex (on no
                                      boundary face) 0..30, and >= 31 */
} cvm_histogram;

/**
 * Compute measure @p which of the current mesh.
 * Cost:         the measures fall into groups (triangle angles, edges and area;
 *               vertex degrees; the power dual) that are each computed in one
 *               O(triangles) pass on the first request after a call that may
 *               change @p m, and kept with @p m; later requests of the same
 *               group are O(1) and give identical values. cvm_mesh_copy_histogram()
 *               shares the same passes.
 * Range:        angles and ratios stay finite and accurate when coordinates come
 *               near the largest or smallest doubles (vectors are scaled by powers
 *               of two before they are multiplied); a length or area whose value
 *               exceeds the largest double is +inf, one below the smallest is 0.
 * Thread-safety: must not run concurrently with any other call on @p m (it keeps
 *               the values it computes in @p m).
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT (unknown measure), CVM_E_STATE (no triangles),
 *         CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_get_measure(double *out, cvm_mesh *m, cvm_measure which);

/**
 * Reports of the last run of a meshing call on the handle, read with
 * cvm_mesh_get_report(): what a run asked for and did, as opposed to the
 * measures of the mesh (cvm_measure), which depend only on the current mesh.
 * The values equal those of the CVM_MEASURE_* of the same name, which
 * cvm_mesh_get_measure() keeps accepting. Blocks: 11-16, 40-49 and 60-69 as below,
 * 700-799 reserved for the 3D kernel's runs, 800-899 for quad meshing.
 * Values never change.
 */
typedef enum cvm_report {
    /* the last cvm_mesh_refine() (0 before any refinement, and after cvm_mesh_triangulate()) */
    CVM_REPORT_REFINE_STEINER = 11,           /**< = CVM_MEASURE_REFINE_STEINER */
    CVM_REPORT_REFINE_UNMET_ANGLE = 12,       /**< = CVM_MEASURE_REFINE_UNMET_ANGLE */
    CVM_REPORT_REFINE_UNMET_SIZE = 13,        /**< = CVM_MEASURE_REFINE_UNMET_SIZE */
    CVM_REPORT_REFINE_SMALL_INPUT_ANGLE = 14, /**< = CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE */
    CVM_REPORT_REFINE_REQUESTED_ANGLE = 15,   /**< = CVM_MEASURE_REFINE_REQUESTED_ANGLE */
    CVM_REPORT_REFINE_MET_ANGLE = 16,         /**< = CVM_MEASURE_REFINE_MET_ANGLE */
    /* the last cvm_mesh_optimise_dual() (0 before any, and after cvm_mesh_triangulate()) */
    CVM_REPORT_DUAL_OPT_SWEEPS = 40,          /**< = CVM_MEASURE_DUAL_OPT_SWEEPS */
    CVM_REPORT_DUAL_OPT_NONCOMPLIANT_BEFORE_PCT = 41, /**< = CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_BEFORE_PCT */
    CVM_REPORT_DUAL_OPT_NONCOMPLIANT_AFTER_PCT = 42,  /**< = CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_AFTER_PCT */
    CVM_REPORT_DUAL_OPT_MOVES = 43,           /**< = CVM_MEASURE_DUAL_OPT_MOVES */
    CVM_REPORT_DUAL_OPT_FLIPS = 44,           /**< = CVM_MEASURE_DUAL_OPT_FLIPS */
    CVM_REPORT_DUAL_OPT_WEIGHT_FIXES = 45,    /**< = CVM_MEASURE_DUAL_OPT_WEIGHT_FIXES */
    CVM_REPORT_DUAL_OPT_SECONDS = 46,         /**< = CVM_MEASURE_DUAL_OPT_SECONDS (wall time:
                                                   the one report that is not deterministic) */
    CVM_REPORT_DUAL_OPT_REMOVED_VANISHED = 47,/**< = CVM_MEASURE_DUAL_OPT_REMOVED_VANISHED */
    CVM_REPORT_DUAL_OPT_REMOVED_DEGREE = 48,  /**< = CVM_MEASURE_DUAL_OPT_REMOVED_DEGREE */
    CVM_REPORT_DUAL_OPT_REMOVED_MAXMIN = 49,  /**< = CVM_MEASURE_DUAL_OPT_REMOVED_MAXMIN */
    /* the last cvm_mesh_read() of a mesh file (0 before any, and after cvm_mesh_triangulate()) */
    CVM_REPORT_READ_FLIPS = 60,               /**< = CVM_MEASURE_READ_FLIPS */
    /* the last cvm_mesh_generate3() (0 before any) */
    CVM_REPORT_GEN3_MATCHED_PAIRS = 740,      /**< = CVM_MEASURE_GEN3_MATCHED_PAIRS */
    CVM_REPORT_GEN3_UNMATCHED_FACES = 741,    /**< = CVM_MEASURE_GEN3_UNMATCHED_FACES */
    CVM_REPORT_GEN3_PAIRS_REJECTED = 742,     /**< = CVM_MEASURE_GEN3_PAIRS_REJECTED */
    CVM_REPORT_GEN3_NEAR_POINTS = 743,        /**< = CVM_MEASURE_GEN3_NEAR_POINTS */
    CVM_REPORT_GEN3_NEAR_REJECTED = 744,      /**< = CVM_MEASURE_GEN3_NEAR_REJECTED */
    CVM_REPORT_GEN3_LATTICE_POINTS = 745,     /**< = CVM_MEASURE_GEN3_LATTICE_POINTS */
    CVM_REPORT_GEN3_LATTICE_LEVELS = 746,     /**< = CVM_MEASURE_GEN3_LATTICE_LEVELS */
    CVM_REPORT_GEN3_RECOVERY_DROPPED = 747,   /**< = CVM_MEASURE_GEN3_RECOVERY_DROPPED */
    CVM_REPORT_GEN3_SECONDS = 748,            /**< = CVM_MEASURE_GEN3_SECONDS */
    /* the last cvm_mesh_optimise_dual3() (0 before any, and after cvm_mesh_generate3());
       "outside": the power vertex lies strictly outside its tetrahedron (exact), as
       CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT; "boundary": tetrahedra with a boundary face */
    CVM_REPORT_DUAL3_SWEEPS = 750,            /**< sweeps run @since 0.2 */
    CVM_REPORT_DUAL3_OUTSIDE_BEFORE_PCT = 751, /**< % of tetrahedra outside at the start */
    CVM_REPORT_DUAL3_OUTSIDE_AFTER_PCT = 752,  /**< % outside at the end */
    CVM_REPORT_DUAL3_OUTSIDE_BOUNDARY_BEFORE_PCT = 753, /**< % of boundary tetrahedra outside, start */
    CVM_REPORT_DUAL3_OUTSIDE_BOUNDARY_AFTER_PCT = 754,  /**< ... at the end */
    CVM_REPORT_DUAL3_MOVES = 755,             /**< vertex moves accepted */
    CVM_REPORT_DUAL3_SECONDS = 756,           /**< wall time of the run (not deterministic) */
    /* the last cvm_mesh_generate3() again: its surface (CVM_OPT_GEN3_SURFACE) */
    CVM_REPORT_GEN3_FACETS_REMESHED = 757,    /**< = CVM_MEASURE_GEN3_FACETS_REMESHED */
    CVM_REPORT_GEN3_SURFACE_TRIS_BEFORE = 758, /**< = CVM_MEASURE_GEN3_SURFACE_TRIS_BEFORE */
    CVM_REPORT_GEN3_SURFACE_TRIS_AFTER = 759, /**< = CVM_MEASURE_GEN3_SURFACE_TRIS_AFTER */
    /* the last cvm_mesh_optimise_dual3() again */
    CVM_REPORT_DUAL3_FLIPS = 760,             /**< flips kept (CVM_OPT_DUAL3_FLIPS), the first
                                                   pass over the input's faces included */
    /* the last cvm_mesh_generate3() again: its octree (CVM_GEN3_FREESPACE_OCTREE) */
    CVM_REPORT_GEN3_OCTREE_LEAVES = 761,      /**< = CVM_MEASURE_GEN3_OCTREE_LEAVES @since 0.2 */
    CVM_REPORT_GEN3_OCTREE_POINTS = 762,      /**< = CVM_MEASURE_GEN3_OCTREE_POINTS @since 0.2 */
    /* ... and its Delaunay refinement (CVM_GEN3_FREESPACE_REFINE) */
    CVM_REPORT_GEN3_REFINE_POINTS = 763,      /**< = CVM_MEASURE_GEN3_REFINE_POINTS @since 0.2 */
    CVM_REPORT_GEN3_REFINE_ROUNDS = 764,      /**< = CVM_MEASURE_GEN3_REFINE_ROUNDS @since 0.2 */
    /* the last cvm_mesh_quadmesh() (0 before any, and after any call that drops the quads).
       Corner angles and edge lengths are measured in the metric: a corner's angle with g at
       its quad's centroid, an edge's metric length sqrt(e^T g e) with g at its midpoint. */
    CVM_REPORT_QUAD_PCT = 800,                /**< % of the cells that are quads */
    CVM_REPORT_QUAD_AREA_PCT = 801,           /**< % of the area covered by quads */
    CVM_REPORT_QUAD_ANGLE_DEV_MEAN_DEG = 802, /**< mean |corner - 90| over quad corners, metric */
    CVM_REPORT_QUAD_ANGLE_DEV_P95_DEG = 803,  /**< its 95th percentile */
    CVM_REPORT_QUAD_ANGLE_DEV_MAX_DEG = 804,  /**< its largest value */
    CVM_REPORT_QUAD_EUCLID_ANGLE_DEV_MEAN_DEG = 805, /**< mean |corner - 90|, Euclidean */
    CVM_REPORT_QUAD_EUCLID_ANGLE_DEV_P95_DEG = 806,  /**< its 95th percentile */
    CVM_REPORT_QUAD_CORNERS_80_100_PCT = 807, /**< % of quads with all corners in [80, 100] deg
                                                   (metric) */
    CVM_REPORT_QUAD_ALIGNMENT_MEAN_DEG = 808, /**< mean angle between a quad edge and the nearest
                                                   eigenvector of g at its midpoint, in [0, 45]
                                                   (isotropic g: the axes) */
    CVM_REPORT_QUAD_ALIGNMENT_P95_DEG = 809,  /**< its 95th percentile */
    CVM_REPORT_QUAD_UNIT_EDGE_PCT = 810,      /**< % of the edges of the cells with metric length
                                                   in [1/sqrt 2, sqrt 2] */
    CVM_REPORT_QUAD_EDGE_DEV_MEAN = 811,      /**< mean |L_M - 1| over those edges */
    CVM_REPORT_QUAD_MIN_SCALED_JACOBIAN = 812,/**< smallest scaled Jacobian of a quad (corner
                                                   sine, Euclidean; 1 for a rectangle) */
    CVM_REPORT_QUAD_ENERGY = 813,             /**< the Lp-CVT energy E at the end */
    CVM_REPORT_QUAD_GRADIENT_INF = 814,       /**< |grad E|_inf at the end */
    CVM_REPORT_QUAD_ITERATIONS = 815,         /**< L-BFGS iterations, over every run */
    CVM_REPORT_QUAD_EVALUATIONS = 816,        /**< energy and gradient evaluations */
    CVM_REPORT_QUAD_SECONDS = 817,            /**< wall time of the call (not deterministic) */
    CVM_REPORT_QUAD_QUADS = 818,              /**< number of quads */
    CVM_REPORT_QUAD_TRIANGLES = 819,          /**< number of triangles left */
    CVM_REPORT_QUAD_INTERIOR_SITES = 820,     /**< interior sites kept */
    CVM_REPORT_QUAD_BOUNDARY_SITES = 821      /**< boundary points (corners included) */
} cvm_report;

/**
 * Read report @p which of the last run (see cvm_report). Reports are kept with
 * the handle; reading one computes nothing and needs no triangles.
 *
 * @param out    receives the value.
 * @param m      mesh handle; not NULL.
 * @param which  a cvm_report value.
 * Thread-safety: may run concurrently with other read-only calls on @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG  out or m is NULL
 *         CVM_E_ARGUMENT  which is not a report (a measure of the mesh is read with
 *                         cvm_mesh_get_measure())
 * @since 0.2
 */
CVM_API cvm_status cvm_mesh_get_report(double *out, const cvm_mesh *m, cvm_report which);

/**
 * Copy histogram @p which as counts (doubles, so one typemap serves all outputs).
 * Computed and kept as cvm_mesh_get_measure() describes (same cost, same
 * thread-safety).
 * @param dst_len  capacity; CVM_HIST_ANGLE_DEG needs 18, CVM_HIST_DEGREE 16,
 *                 CVM_HIST_Q1 12, CVM_HIST_Q2 .. CVM_HIST_Q5 20; on a 3D mesh
 *                 CVM_HIST_DIHEDRAL_DEG 18 and CVM_HIST_VALENCE_3D 32 (the 2D
 *                 histograms are CVM_E_ARGUMENT there, the 3D ones on a 2D mesh).
 * 3D:             computed afresh on each call (O(tetrahedra log tetrahedra)), as
 *                 are the 3D measures 720-724.
 * @return CVM_OK, CVM_E_NULL_ARG, CVM_E_ARGUMENT, CVM_E_STATE, CVM_E_BUFFER_TOO_SMALL, CVM_E_NOMEM
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_histogram(double *dst, size_t dst_len, cvm_mesh *m,
                                           cvm_histogram which);

/**
 * Copy the per-element values of dual quality measure @p which (see
 * cvm_histogram): for CVM_HIST_Q1 and CVM_HIST_Q2 one value per triangle in
 * CVM_ENT_TRIANGLE order; for CVM_HIST_Q3, CVM_HIST_Q4 and CVM_HIST_Q5 one
 * value per edge in CVM_ENT_EDGE order (boundary edges included, with the
 * half-edge definitions). Fresh each call; O(triangles + edges log edges).
 *
 * @param dst      receives the values.
 * @param dst_len  capacity in doubles: >= the triangle count (q1, q2) or the
 *                 edge count (q3..q5).
 * @param m        mesh handle; not NULL.
 * @param which    CVM_HIST_Q1 .. CVM_HIST_Q5.
 * Units:          q1 degrees; q2..q5 dimensionless.
 * Thread-safety:  must not run concurrently with a call that modifies @p m.
 * @return CVM_OK
 *         CVM_E_NULL_ARG          m is NULL, or dst is NULL while dst_len > 0
 *         CVM_E_ARGUMENT          which is not CVM_HIST_Q1 .. CVM_HIST_Q5
 *         CVM_E_BUFFER_TOO_SMALL  dst_len too short (nothing written)
 *         CVM_E_NOMEM
 * (A const handle: the last error and its message are left alone.)
 * @since 0.1
 */
CVM_API cvm_status cvm_mesh_copy_dual_quality(double *dst, size_t dst_len, const cvm_mesh *m,
                                              cvm_histogram which);

#ifdef __cplusplus
}
#endif
#endif /* CVMESH_H */
