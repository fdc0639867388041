/*
 * io_internal.h - file readers and writers. They work on plain arrays (a
 * cvm__pslg read in, a cvm__mesh_out written out), so io depends on common
 * only. Readers go through a cvm__reader so tests can inject read faults;
 * writers go through a cvm__writer that writes PATH.tmp.XXXXXX and renames it
 * over PATH only when everything succeeded.
 */
#ifndef CVM_IO_INTERNAL_H
#define CVM_IO_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

/* Where the items of one kind (points, segments, ...) were read, so that
 * messages about them can use the file's numbers and lines. Item k lies in the
 * last run that starts at or before it: its number and line are the run's
 * plus (k - first item of the run). A run starts wherever numbers or lines
 * stop being consecutive (comment lines, free segment numbers), so a plain
 * file needs one run per kind. */
typedef struct cvm__item_src {
    char *file;          /* owned copy of the file name; NULL: not read from a file */
    int64_t *run;        /* 3 per run: first item, its number in the file, its line */
    size_t nrun, cap;
    size_t n;            /* items recorded (0..n-1) */
    int64_t last_num, last_line;
} cvm__item_src;

/* Record item s->n (items are added in order) with the file's number num at
 * line line of file (copied on the first call). CVM_OK or CVM_E_NOMEM (no
 * message set). */
cvm_status cvm__item_src_add(cvm__ctx *ctx, cvm__item_src *s, const char *file, int64_t num,
                             int64_t line);
/* The file's number and line of item k: 1 when known. Else 0 with *num = k,
 * except that an index past the recorded items (a segment naming a point that
 * does not exist) keeps the file's offset of item 0: *num = k + number of
 * item 0, *line = 0. */
int cvm__item_src_get(const cvm__item_src *s, size_t k, int64_t *num, int64_t *line);
void cvm__item_src_free(cvm__ctx *ctx, cvm__item_src *s);

/* ---- input: a planar straight-line graph, arrays allocated through ctx ---- */
typedef struct cvm__pslg {
    double *xy;          /* 2*np */
    size_t np;
    int32_t *pmark;      /* np or NULL */
    double *pattr;       /* np*nattr or NULL */
    size_t nattr;
    int32_t *seg;        /* 2*nseg, 0-based */
    size_t nseg;
    int32_t *smark;      /* nseg or NULL */
    double *holes;       /* 2*nholes */
    size_t nholes;
    double *regions;     /* 4*nregions: x, y, attribute, max area */
    size_t nregions;
    /* origin of each kind of item when read from a file (file NULL otherwise) */
    cvm__item_src src_point, src_segment, src_hole, src_region;
} cvm__pslg;

/* Free every array of p (and its origins) through ctx and zero it. */
void cvm__pslg_free(cvm__ctx *ctx, cvm__pslg *p);

/* A byte source. read() returns bytes read (0 at end), or -1 on error. */
typedef struct cvm__reader {
    long (*read)(void *self, char *buf, size_t len);
    void *self;
} cvm__reader;

/* A cvm__reader over the file at path (self is its FILE). Returns CVM_OK or
 * CVM_E_IO_OPEN with the message "cannot open PATH: reason". Close it with
 * cvm__file_reader_close(), which accepts a reader that failed to open. */
cvm_status cvm__file_reader_open(cvm__ctx *ctx, cvm__reader *r, const char *path);
void cvm__file_reader_close(cvm__reader *r);

/* Thread-safe text of errno value err into buf. */
void cvm__strerror(int err, char *buf, size_t len);

/* Parse Triangle .poly (is_poly = 1) or .node (is_poly = 0) text from r.
 * name is used in messages ("square.poly:12: ..."). On error p is left zeroed
 * and the message gives name:line. Returns CVM_OK, CVM_E_IO_READ,
 * CVM_E_IO_FORMAT, CVM_E_INPUT_NONFINITE, CVM_E_NOMEM, CVM_E_TOO_LARGE, or
 * CVM_INCOMPLETE_CANCELLED when ctx's progress callback (stage
 * CVM_STAGE_READ, asked every 64 KiB; not the time limit) says stop. */
cvm_status cvm__read_triangle_format(cvm__ctx *ctx, cvm__reader *r, const char *name,
                                     int is_poly, cvm__pslg *p);

/* Open path and parse it by extension (.poly, .node). A .poly with 0 points
 * reads the points from the .node of the same stem. */
cvm_status cvm__read_file(cvm__ctx *ctx, const char *path, cvm__pslg *p);

/* A Gmsh physical group's name (read_msh.c). */
typedef struct cvm__phys_name {
    int32_t dim, tag;
    char name[128];      /* truncated to 127 bytes */
} cvm__phys_name;

/* A triangle mesh read from a VTK XML unstructured grid (read_vtu.c), a
 * legacy .vtk (read_vtk.c) or a Gmsh .msh (read_msh.c: markers and
 * attributes are the physical tags). */
typedef struct cvm__vtu_mesh {
    cvm__pslg p;      /* points, point markers and attributes; seg/smark: the line cells
                         (VTK type 3) and their cell data "marker" (smark NULL without it) */
    int32_t *tri;     /* 3*nt: the triangle cells (VTK type 5), as in the file */
    size_t nt;
    double *w;        /* np or NULL: point data "weight" */
    double *tattr;    /* nt or NULL: cell data "attribute" of the triangles */
    int has_lines;    /* 1 when the file has line cells */
    cvm__phys_name *names; /* nnames, or NULL: the physical names of a .msh */
    size_t nnames;
} cvm__vtu_mesh;

/* Parse a .vtu from r (name for messages "name:line: ..."; ASCII, base64,
 * appended raw or base64, zlib-compressed data). Returns CVM_OK,
 * CVM_E_IO_READ, CVM_E_IO_FORMAT (malformed; an index out of range), CVM_E_UNSUPPORTED
 * (another compressor, other cell types), CVM_E_INPUT_NONFINITE,
 * CVM_E_TOO_LARGE, CVM_E_NOMEM, CVM_INCOMPLETE_CANCELLED (as
 * cvm__read_triangle_format(), while the file is read); out is zeroed on error. */
cvm_status cvm__read_vtu(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out);
/* Parse a legacy VTK file (.vtk: ASCII or BINARY, UNSTRUCTURED_GRID or
 * POLYDATA) from r into the same mesh as cvm__read_vtu(); the same statuses
 * (messages give name:line, or the byte offset in a BINARY file). */
cvm_status cvm__read_vtk(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out);
/* Parse a Gmsh .msh (2.2 or 4.1, ASCII or binary) from r into the same mesh
 * as cvm__read_vtu(): nodes as points (point elements' physical tags as
 * markers), 2-node lines as line cells (smark: physical tag, 0 without),
 * 3-node triangles (tattr: physical tag, when some triangle has one), the
 * physical names. The same statuses; CVM_E_UNSUPPORTED for other element
 * types or versions. */
cvm_status cvm__read_msh(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__vtu_mesh *out);
/* The $PhysicalNames of a Gmsh .msh from r into a fresh array *names_out of
 * *n_out entries (NULL and 0 without names): the whole file is parsed by
 * cvm__read_msh(), so this succeeds exactly when it does (faults aside); its
 * statuses. */
cvm_status cvm__read_msh_names(cvm__ctx *ctx, cvm__reader *r, const char *name,
                               cvm__phys_name **names_out, size_t *n_out);
/* The same from the file at path (CVM_E_IO_OPEN too). */
cvm_status cvm__read_msh_names_file(cvm__ctx *ctx, const char *path, cvm__phys_name **names_out,
                                    size_t *n_out);
/* 1 when path names a mesh file that cvm__read_mesh_file() reads (.vtu,
 * .vtk, .msh, any case). */
int cvm__is_mesh_file(const char *path);
/* Open path and parse it by extension (.vtu, .vtk, .msh) into out: the
 * statuses of the reader, CVM_E_IO_OPEN, CVM_E_UNSUPPORTED (another extension). */
cvm_status cvm__read_mesh_file(cvm__ctx *ctx, const char *path, cvm__vtu_mesh *out);
/* Everything r gives into a fresh NUL-terminated buffer *out of *n_out bytes
 * (NULs inside are kept). CVM_OK, CVM_E_IO_READ ("name: read error"),
 * CVM_E_NOMEM, CVM_INCOMPLETE_CANCELLED (the progress callback, asked every
 * 64 KiB); *out is NULL on error. */
cvm_status cvm__slurp(cvm__ctx *ctx, cvm__reader *r, const char *name, char **out, size_t *n_out);
/* The same from the file at path (CVM_E_IO_OPEN too). */
cvm_status cvm__read_vtu_file(cvm__ctx *ctx, const char *path, cvm__vtu_mesh *out);
void cvm__vtu_mesh_free(cvm__ctx *ctx, cvm__vtu_mesh *vm);

/* ---- output: a finished mesh, borrowed arrays ---- */
typedef struct cvm__mesh_out {
    const double *xy;    /* 2*nv */
    size_t nv;
    const int32_t *vmark;/* nv or NULL */
    const double *vattr; /* nv*nattr or NULL */
    size_t nattr;
    const int32_t *tri;  /* 3*nt, counter-clockwise; with coff, the ids of nt mixed cells */
    size_t nt;
    const int32_t *coff; /* NULL, or nt+1 offsets into tri: cell t is tri[coff[t] .. coff[t+1]-1]
                            of VTK type ctype[t] (quad-dominant cells; .vtu and .msh write
                            them, the other writers read only triangles) */
    const int32_t *ctype;
    const char *tquality_name; /* the .vtu name of tquality; NULL: "min_angle_deg" */
    const double *tattr; /* nt or NULL (regional attribute) */
    const int32_t *edge; /* 2*ne or NULL: all edges (for .edge) */
    const int32_t *emark;/* ne or NULL: marker of each edge (0 interior) */
    size_t ne;
    const int32_t *seg;  /* 2*nseg: constrained edges */
    const int32_t *smark;/* nseg or NULL */
    size_t nseg;
    const double *tquality; /* nt or NULL: per-triangle value for SVG colouring (min angle, degrees) */
    const double *weight;   /* nv or NULL: vertex weights; when set, vattr's first column
                               holds them too (.node writes it; .vtu writes "weight" apart) */
    const double *tlayer;   /* nt or NULL: AFLR layer index per triangle (SVG colours by it) */
    double window[4];       /* SVG view xmin, ymin, xmax, ymax; unused unless xmax > xmin, ymax > ymin */
    const cvm__phys_name *names; /* nnames or NULL: .msh physical names by (dim, marker) */
    size_t nnames;
    int vtu_encoding;       /* .vtu data: cvm_vtu_encoding (3: by the vertex count) */
} cvm__mesh_out;

/* ---- output: the power cells of a mesh (polygons on shared points), borrowed arrays ---- */
typedef struct cvm__dual_out {
    const double *xy;      /* 2*npoint: the corner points, each once */
    size_t npoint;
    const int32_t *corner; /* off[ncell] point ids, cell after cell */
    const int32_t *off;    /* ncell+1: cell c has corners off[c] .. off[c+1]-1 */
    size_t ncell;
    const int32_t *vertex; /* ncell: the mesh vertex of each cell */
    const double *area;    /* ncell */
    const double *weight;  /* ncell */
    const int32_t *face;   /* 6*nface: cell a, cell b (-1: boundary), the primal edge's two
                              vertices, the face's two points (cell a left of p -> q) */
    const double *flen;    /* 2*nface: primal edge length, face length */
    size_t nface;
    const int32_t *cell_of;/* per mesh vertex: its cell's index, or -1 (no cell) */
} cvm__dual_out;

/* Output formats, chosen by the extension of a path (case-insensitive). */
typedef enum cvm__format {
    CVM__FMT_NONE = 0, /* unknown extension */
    CVM__FMT_VTU = 1,  /* .vtu: VTK XML unstructured grid, ASCII */
    CVM__FMT_MSH = 2,  /* .msh: Gmsh 4.1 ASCII */
    CVM__FMT_NODE = 3, /* .node: PREFIX.node + PREFIX.ele + PREFIX.edge (needs mo->edge) */
    CVM__FMT_SVG = 4   /* .svg: a picture (colours from mo->tquality when given) */
} cvm__format;

cvm__format cvm__format_of(const char *path);

/* 1 when path is longer than ext and ends in ext (a ".xxx" in lower case),
 * ignoring the case of path; else 0. */
int cvm__path_has_ext(const char *path, const char *ext);

/* A byte sink with atomic commit: the text goes to a new temporary file
 * PATH.tmp.XXXXXX beside PATH, which cvm__writer_commit() renames over PATH.
 * A replaced file's permissions (and owner, where allowed) carry over; a new
 * file gets the umask's. When PATH (after symbolic links) exists and is not a
 * regular file (a device such as /dev/null, a FIFO), it is written in place
 * instead. Output errors are sticky: the put functions never fail by
 * themselves, the first error is reported by cvm__writer_finish() or
 * cvm__writer_commit(). Every few puts the ctx's progress callback is asked
 * (stage CVM_STAGE_WRITE; not the time limit): when it says stop, nothing more
 * is written and finish/commit return CVM_INCOMPLETE_CANCELLED. */
typedef struct cvm__writer cvm__writer;

/* Create the temporary file. Returns CVM_OK, CVM_E_IO_OPEN ("cannot create
 * PATH: reason") or CVM_E_NOMEM; *out is NULL on error. */
cvm_status cvm__writer_open(cvm__writer **out, cvm__ctx *ctx, const char *path);
void cvm__writer_puts(cvm__writer *w, const char *s);
/* n bytes of s (which may hold NULs). */
void cvm__writer_write(cvm__writer *w, const char *s, size_t n);
void cvm__writer_putc(cvm__writer *w, char c);
/* printf-like; use only for integers and strings (no %f/%g: locale). */
void cvm__writer_printf(cvm__writer *w, const char *fmt, ...) CVM__PRINTF(2, 3);
/* A double in the shortest of %.15g, %.16g, %.17g that reads back exactly,
 * '.' as decimal point (cvm__format_double()); "nan", "inf", "-inf" for the
 * non-finite. */
void cvm__writer_double(cvm__writer *w, double x);
/* For the progress fraction only: about how many puts the whole write takes
 * (total), of which before went to earlier files of the same write. */
void cvm__writer_expect(cvm__writer *w, uint64_t before, uint64_t total);
/* An integer in decimal, as "%lld" / "%llu" print it. */
void cvm__writer_long(cvm__writer *w, long long v);
void cvm__writer_ulong(cvm__writer *w, unsigned long long v);
/* Flush, sync and close the temporary file; CVM_OK, CVM_E_IO_WRITE or
 * CVM_INCOMPLETE_CANCELLED (the writer stays, to be committed or discarded).
 * Idempotent. */
cvm_status cvm__writer_finish(cvm__writer *w);
/* Finish if needed, then rename the temporary file over PATH and free w.
 * On error the temporary file is removed: CVM_E_IO_WRITE. */
cvm_status cvm__writer_commit(cvm__writer *w);
/* Close and remove the temporary file and free w; NULL is a no-op. */
void cvm__writer_discard(cvm__writer *w);

/* Finished writers whose temporary files replace their targets together.
 * The set allocates through ctx; it owns the writers added to it. */
typedef struct cvm__write_set {
    cvm__ctx *ctx;
    cvm__writer **w;
    size_t n, cap;
} cvm__write_set;

void cvm__write_set_init(cvm__write_set *ws, cvm__ctx *ctx);
/* Finish w and add it to ws. On error (those of cvm__writer_finish(),
 * CVM_E_NOMEM) w is discarded and ws is unchanged. */
cvm_status cvm__write_set_add(cvm__write_set *ws, cvm__writer *w);
/* Rename every temporary file of ws over its target, in the order added, and
 * empty ws. If a rename fails, the targets already replaced are put back as
 * they were (from hard links made before the first rename; a target that
 * cannot be linked stays replaced), the other temporary files are removed,
 * and CVM_E_IO_WRITE names the file ("cannot replace PATH: reason").
 * CVM_E_NOMEM before any rename changes nothing. */
cvm_status cvm__write_set_commit(cvm__write_set *ws);
/* Remove every temporary file of ws and empty it. */
void cvm__write_set_discard(cvm__write_set *ws);

/* Write the mesh to path in the format its extension names (.vtu, .msh,
 * .node -> PREFIX.node/.ele/.edge, .svg). Returns CVM_OK, CVM_E_UNSUPPORTED,
 * CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM, CVM_INCOMPLETE_CANCELLED (the
 * progress callback stopped it); on error or cancellation no file is left
 * and every target is as it was. */
cvm_status cvm__write_file(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo);
/* The same, but the finished files join ws instead of replacing their targets
 * (CVM_INCOMPLETE_CANCELLED too). On error the files of this call are removed
 * and ws is unchanged. */
cvm_status cvm__write_file_to_set(cvm__write_set *ws, const char *path, const cvm__mesh_out *mo);

/* ---- output: a tetrahedral mesh, arrays borrowed ---- */
/* Cells written to a .vtu instead of the tetrahedra (merged dual cells): cell c
 * is a VTK_TETRA (10, no faces) or a VTK_POLYHEDRON (42). */
typedef struct cvm__mesh3_cells {
    size_t ncell;
    const int32_t *tet;      /* ncell: the smallest tetrahedron of each cell */
    const uint8_t *type;     /* ncell: 10 or 42 */
    const int32_t *conn;     /* the cell's points: conn[conn_off[c] .. conn_off[c+1]-1] */
    const int64_t *conn_off; /* ncell + 1 */
    const int64_t *faces;    /* VTK face stream of the polyhedra: nfaces, then per face 3, ids */
    const int64_t *face_off; /* ncell + 1: cell c's stream is faces[face_off[c] .. face_off[c+1]-1]
                                (empty for a tetrahedron) */
} cvm__mesh3_cells;

typedef struct cvm__mesh3_out {
    const double *xyz;    /* 3*nv */
    size_t nv;
    const double *w;      /* nv or NULL: power weights (.vtu point data "weight", .node attribute) */
    const int32_t *tet;   /* 4*ntet, positively oriented */
    size_t ntet;
    const double *tattr;  /* ntet or NULL: regional attribute */
    const int32_t *face;  /* 3*nface boundary triangles */
    const int32_t *fmark; /* nface or NULL: their markers */
    size_t nface;
    const cvm__mesh3_cells *cells; /* NULL, or the cells a .vtu holds instead of the tetrahedra */
} cvm__mesh3_out;

/* Write a tetrahedral mesh to path as its extension names (.vtu, .msh,
 * .node -> PREFIX.node/.ele/.face), the files joining ws as
 * cvm__write_file_to_set() does. CVM_OK, CVM_E_UNSUPPORTED (another
 * extension), CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM,
 * CVM_INCOMPLETE_CANCELLED (write_mesh3.c). */
cvm_status cvm__write_file3_to_set(cvm__write_set *ws, const char *path, const cvm__mesh3_out *mo);
/* 3 when the first line of a Triangle/TetGen .node or .poly file at path
 * says dimension 3, else 2 (also when it cannot be read: the reader then
 * reports why). */
int cvm__file_dimension(const char *path);

/* Write the cells as VTK polygons to path (.vtu; the caller checks the
 * extension). CVM_OK, CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM; on error no
 * file is left. */
cvm_status cvm__write_dual_file(cvm__ctx *ctx, const char *path, const cvm__dual_out *d);
/* The same into ws, as cvm__write_file_to_set(). */
cvm_status cvm__write_dual_file_to_set(cvm__write_set *ws, const char *path, const cvm__dual_out *d);

/* ---- output: the bounded power cells of a tetrahedral mesh (polyhedra) ---- */
typedef struct cvm__dual3_out {
    const double *pts;       /* 3*npts: the dual vertices, each once */
    const int32_t *pt_tet;   /* npts: a tetrahedron whose power vertex it is */
    size_t npts;
    size_t ncell;
    const int32_t *conn;     /* the distinct points of each cell: cell c has */
    const int64_t *conn_off; /* conn[conn_off[c] .. conn_off[c+1]-1] (ncell+1 offsets) */
    const int64_t *faces;    /* VTK face stream: per cell nfaces, then per face n, ids */
    const int64_t *face_off; /* ncell+1: cell c's stream is faces[face_off[c] .. face_off[c+1]-1] */
    const int32_t *vertex;   /* ncell: the mesh vertex of each cell */
    const double *volume;    /* ncell */
    const double *weight;    /* ncell */
    const int32_t *edge;     /* 2*nedge: interior mesh edges */
    const double *edge_area; /* nedge: their signed dual face areas */
    size_t nedge;
    const int32_t *face;     /* 3*nface: interior mesh faces */
    const double *face_len;  /* nface: their dual edge lengths */
    size_t nface;
} cvm__dual3_out;

/* Write the cells as VTK_POLYHEDRON (42) cells of a .vtu into ws, as
 * cvm__write_file_to_set() (write_dual3.c; the caller checks the extension). */
cvm_status cvm__write_dual3_file_to_set(cvm__write_set *ws, const char *path,
                                        const cvm__dual3_out *d);

#endif
