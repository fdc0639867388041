"""cvmesh: triangle meshes whose Delaunay primal and Voronoi dual are both of
high quality, from Python.

    >>> import numpy as np, cvmesh
    >>> square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    >>> mesh = cvmesh.Mesh.from_pslg(square, [[0, 1], [1, 2], [2, 3], [3, 0]])
    >>> mesh.triangulate()
    <Status.OK: 0>
    >>> mesh.triangles.shape
    (2, 3)

Arrays go in and come out as numpy arrays: coordinates float64 of shape
(n, 2), connectivity int32 with 0-based indices. Every error of the library
raises a subclass of cvmesh.Error carrying the library's message, which names
the offending input. The flat C API is available as cvmesh.capi.
"""

from __future__ import annotations

import contextlib
import dataclasses
import enum
import math
import os
import signal
import threading
import warnings
from collections import namedtuple
from typing import (TYPE_CHECKING, Any, Callable, Dict, Iterator, NamedTuple, Optional,
                    Tuple, TypeVar, Union)

import numpy as np
import numpy.typing as npt

from . import capi
from ._errors import (ArgumentError, Error, FileError, IncompleteWarning,
                      InputError, InternalError, NoMemoryError, OptionError,
                      StateError, UnsupportedError, error_class)

__all__ = [
    "Mesh", "Sizing", "Quality", "Bounds", "Status", "Option", "Entity", "Measure",
    "Report", "CellType", "Histogram", "Stage", "Algorithm", "option_bounds", "version",
    "DualMesh",
    "OptionKey", "PathLike", "ProgressCallback", "SizeCallback", "BatchSizeCallback", "Error",
    "ArgumentError",
    "OptionError", "InputError", "StateError", "UnsupportedError", "FileError",
    "NoMemoryError", "InternalError", "IncompleteWarning", "error_class",
]

__version__ = capi.cvm_version_string()

#: An option: an Option, its int value, or its name in lower case ("min_angle_deg").
OptionKey = Union[str, int]
#: A file name.
PathLike = Union[str, "os.PathLike[str]"]
#: progress(stage, fraction) -> stop?; called during long calls.
ProgressCallback = Callable[[Any, float], Any]
#: size(x, y) -> target edge length.
SizeCallback = Callable[[float, float], float]
#: size(xy) -> sizes: xy an (n, 2) float64 array, the result n sizes.
BatchSizeCallback = Callable[["npt.NDArray[np.float64]"], "npt.ArrayLike"]


def _constants(prefixes, strip):
    """{NAME: value} of the integer constants of capi whose names start with
    one of prefixes, the first `strip` characters removed, sorted by value."""
    found = {}
    for name in dir(capi):
        value = getattr(capi, name)
        if isinstance(value, int) and name.startswith(prefixes):
            found[name[strip:]] = value
    return dict(sorted(found.items(), key=lambda kv: (kv[1], kv[0])))


class _CodeEnum(enum.IntEnum):
    """An IntEnum of the header's constants that prints as its name
    (Status.E_INPUT_INDEX), not as its number; comparisons and arithmetic
    stay those of int."""

    def __str__(self) -> str:
        return "%s.%s" % (type(self).__name__, self.name)

    def __format__(self, spec: str) -> str:
        return str(self) if not spec else int.__format__(int(self), spec)


if TYPE_CHECKING:
    # The members come from the compiled header at import time; a type
    # checker sees each enum as a class whose every attribute is a member.
    _E = TypeVar("_E")

    class _MemberMeta(enum.EnumMeta):
        def __getattr__(cls: type[_E], name: str) -> _E: ...

    class Status(_CodeEnum, metaclass=_MemberMeta):
        @property
        def is_error(self) -> bool: ...
        @property
        def incomplete(self) -> bool: ...

    class Option(_CodeEnum, metaclass=_MemberMeta): ...
    class Entity(_CodeEnum, metaclass=_MemberMeta): ...
    class Measure(_CodeEnum, metaclass=_MemberMeta): ...
    class Report(_CodeEnum, metaclass=_MemberMeta): ...
    class CellType(_CodeEnum, metaclass=_MemberMeta): ...
    class Histogram(_CodeEnum, metaclass=_MemberMeta): ...
    class Stage(_CodeEnum, metaclass=_MemberMeta): ...
    class Algorithm(_CodeEnum, metaclass=_MemberMeta): ...
else:
    # Enumerations, built from the header's constants so new values appear
    # without a change here.
    Status = _CodeEnum("Status", _constants(("CVM_OK", "CVM_E_", "CVM_INCOMPLETE_"), 4),
                       module=__name__)
    Status.is_error = property(lambda self: 1 <= self.value < 100)
    Status.incomplete = property(lambda self: self.value >= 100)
    Option = _CodeEnum("Option", _constants(("CVM_OPT_",), 8), module=__name__)
    Entity = _CodeEnum("Entity", _constants(("CVM_ENT_",), 8), module=__name__)
    Measure = _CodeEnum("Measure", _constants(("CVM_MEASURE_",), 12), module=__name__)
    Report = _CodeEnum("Report", _constants(("CVM_REPORT_",), 11), module=__name__)
    CellType = _CodeEnum("CellType", _constants(("CVM_CELL_",), 9), module=__name__)
    Histogram = _CodeEnum("Histogram", _constants(("CVM_HIST_",), 9), module=__name__)
    Stage = _CodeEnum("Stage", _constants(("CVM_STAGE_",), 10), module=__name__)
    Algorithm = _CodeEnum("Algorithm", _constants(("CVM_ALGO_",), 9), module=__name__)
Status.__doc__ = "cvm_status codes: OK, errors E_* (1..99), INCOMPLETE_* (>= 100)."
Option.__doc__ = "Option keys (cvm_option); also usable as lower-case strings."
Entity.__doc__ = "Kinds of mesh entities (cvm_entity)."
Measure.__doc__ = "Scalar quality measures (cvm_measure)."
Report.__doc__ = "Reports of the last run of a meshing call (cvm_report; Mesh.report())."
CellType.__doc__ = ("Cell type codes of Mesh.cells_mixed() (cvm_cell_type); the values "
                    "are VTK's cell types.")
Histogram.__doc__ = "Quality histograms (cvm_histogram)."
Stage.__doc__ = "Stages reported to a progress callback (cvm_stage)."
Algorithm.__doc__ = "Refinement algorithms of Mesh.refine() (cvm_algorithm)."

REJECTED = -1
"""Id that insert_points() gives a point it rejected (CVM_REJECTED)."""



class Bounds(NamedTuple):
    """Bounds and default of an option (cvm_bounds)."""
    lo: float
    hi: float
    default: float
    is_integer: bool


class DualMesh(NamedTuple):
    """The power dual as a finite-volume mesh (Mesh.dual()); see there."""
    points: "npt.NDArray[np.float64]"
    offsets: "npt.NDArray[np.int32]"
    polygons: "npt.NDArray[np.int32]"
    faces: "npt.NDArray[np.int32]"
    face_lengths: "npt.NDArray[np.float64]"
    areas: "npt.NDArray[np.float64]"


# Histogram lengths (cvmesh.h: 18 angle bins, 16 degree bins, q1 12, q2..q5 20).
_HIST_BINS = {"ANGLE_DEG": 18, "DEGREE": 16, "Q1": 12, "Q2": 20, "Q3": 20, "Q4": 20, "Q5": 20,
              "DIHEDRAL_DEG": 18, "VALENCE_3D": 32}


def version() -> str:
    """Version string of the compiled library, e.g. '0.1.0'."""
    return capi.cvm_version_string()


def _option_key(key: OptionKey) -> int:
    """Option from an Option, an int, or a name like 'min_angle_deg'."""
    if isinstance(key, str):
        try:
            return Option[key.upper()]
        except KeyError:
            raise OptionError("unknown option %r; known: %s" % (
                key, ", ".join(o.name.lower() for o in Option)),
                Status.E_OPTION_KEY) from None
    return int(key)


def option_bounds(key: OptionKey) -> Bounds:
    """Bounds(lo, hi, default, is_integer) of an option key."""
    lo, hi, default, is_integer = capi.cvm_option_bounds(_option_key(key))
    return Bounds(float(lo), float(hi), float(default), bool(is_integer))


def _status(code):
    try:
        return Status(code)
    except ValueError:
        return code


def _stage(code):
    try:
        return Stage(code)
    except ValueError:
        return code


def _unsupported(message):
    return UnsupportedError(message, Status.E_UNSUPPORTED)


def _quality_fields():
    fields = [(m.name.lower(), float) for m in Measure]
    fields += [("hist_" + h.name.lower(), np.ndarray) for h in Histogram]
    return fields


# The headline of Quality.__str__: (format, fields); a line is left out when
# one of its fields is NaN (not computed by this build).
_QUALITY_HEADLINE = (
    ("angles %.4g..%.4g deg, %.3g%% obtuse", ("min_angle_deg", "max_angle_deg", "obtuse_pct")),
    ("regular %.3g%%, degree 6 %.3g%%", ("regular_pct", "degree6_pct")),
    ("edges %.4g..%.4g, area %.6g (smallest triangle %.4g)",
     ("min_edge", "max_edge", "area", "min_area")),
    ("dual: power vertex outside %.3g%% (boundary %.3g%%), dual edge/edge >= %.3g",
     ("dual_outside_pct", "dual_outside_boundary_pct", "min_dual_edge_ratio")),
)


def _quality_str(self: Any) -> str:
    """A few lines: the headline measures, then every other measure that is
    neither 0 nor NaN as "name value", then the angle histogram."""
    lines = ["Quality:"]
    shown: set = set()
    for fmt, names in _QUALITY_HEADLINE:
        values = [getattr(self, n, math.nan) for n in names]
        shown.update(names)
        if not any(math.isnan(v) for v in values):
            lines.append("  " + fmt % tuple(values))
    line = " "
    for f in dataclasses.fields(self):
        value = getattr(self, f.name)
        if (f.name in shown or f.name.startswith("hist_") or not isinstance(value, float)
                or math.isnan(value) or value == 0):
            continue
        item = " %s %.4g" % (f.name, value)
        if len(line) + len(item) > 78:
            lines.append(line)
            line = " "
        line += item
    if line.strip():
        lines.append(line)
    hist = getattr(self, "hist_angle_deg", None)
    if hist is not None and len(hist):
        lines.append("  angles per 10 degrees: " + " ".join(str(int(c)) for c in hist))
    return "\n".join(lines)


if TYPE_CHECKING:
    class Quality:
        def __getattr__(self, name: str) -> Any: ...
        def as_dict(self) -> Dict[str, Any]: ...
else:
    Quality = dataclasses.make_dataclass("Quality", _quality_fields(), frozen=True, eq=False,
                                         namespace={"__str__": _quality_str})
    Quality.__module__ = __name__
    Quality.__doc__ = (
        "Quality of a mesh (Mesh.quality()): one float per cvmesh.Measure, named\n"
        "in lower case (min_angle_deg, max_angle_deg, regular_pct, obtuse_pct,\n"
        "degree6_pct, min_dual_edge_ratio, min_edge, max_edge, area, min_area),\n"
        "and one array of counts per cvmesh.Histogram (hist_angle_deg: 18 bins\n"
        "of 10 degrees; hist_degree: interior vertex degree 0..14 and >= 15).\n"
        "NaN marks a measure this build cannot compute.")
    Quality.as_dict = lambda self: dataclasses.asdict(self)


class Mesh:
    """A cvmesh handle: input (points, segments, holes, regions), options,
    and the triangulation built from them.

    Create one with Mesh.from_pslg(), Mesh.from_points() or Mesh.read(), or
    Mesh(**options) and set the input. Options can be given as keywords
    (Mesh(seed=3), mesh.triangulate(time_limit_s=1.0)) or with set_option().

    One call at a time per mesh: calls from several threads are serialised
    (close() too: it waits for a running call), and a progress callback must
    not call methods of the mesh it reports on.
    Long calls (triangulate, insert_points, read, write, check) release the
    GIL, and Ctrl-C stops them with KeyboardInterrupt, leaving a valid mesh.
    """

    #: operations between two progress checks when no callback is set
    #: (keeps Ctrl-C working); None turns the checks off.
    interrupt_every = 4096

    def __init__(self, **options: float) -> None:
        self._m = None
        self._lock = threading.Lock()
        self._owner = None
        self._progress: Optional[ProgressCallback] = None
        self._progress_every = 0
        self.last_status = Status.OK
        self._m = capi.cvm_mesh_create()
        self.set_options(**options)

    # ---- construction ------------------------------------------------------

    @classmethod
    def from_points(cls, points: npt.ArrayLike, markers: Optional[npt.ArrayLike] = None,
                    attributes: Optional[npt.ArrayLike] = None, **options: float) -> Mesh:
        """A mesh whose input is a point set; triangulate() gives its Delaunay
        triangulation."""
        mesh = cls(**options)
        mesh.set_points(points, markers=markers, attributes=attributes)
        return mesh

    @classmethod
    def from_pslg(cls, points: npt.ArrayLike, segments: Optional[npt.ArrayLike] = None,
                  holes: Optional[npt.ArrayLike] = None, markers: Optional[npt.ArrayLike] = None,
                  regions: Optional[npt.ArrayLike] = None,
                  segment_markers: Optional[npt.ArrayLike] = None,
                  attributes: Optional[npt.ArrayLike] = None, **options: float) -> Mesh:
        """A mesh whose input is a planar straight-line graph.

        points: (n, 2) coordinates; segments: (m, 2) 0-based point indices;
        holes: (k, 2) seed points of holes; markers: (n,) point markers;
        regions: (r, 4) rows (x, y, attribute, max_area);
        segment_markers: (m,) segment markers; attributes: (n, a) point attributes.
        """
        mesh = cls.from_points(points, markers=markers, attributes=attributes, **options)
        if segments is not None:
            mesh.set_segments(segments, markers=segment_markers)
        if holes is not None:
            mesh.set_holes(holes)
        if regions is not None:
            mesh.set_regions(regions)
        return mesh

    @classmethod
    def read(cls, path: PathLike, **options: float) -> Mesh:
        """A mesh whose input is read from a Triangle .poly or .node file, or
        a triangulated mesh (with its weights) read from a .vtu file."""
        mesh = cls(**options)
        mesh.load(path)
        return mesh

    # ---- lifetime ----------------------------------------------------------

    def close(self) -> None:
        """Free the C handle now (also done when the object is collected).

        A call running on this mesh in another thread is waited for: the
        handle is never freed under it. Raises StateError from a progress
        callback of this mesh (the call it reports on is still running)."""
        if self._owner == threading.get_ident():
            raise StateError("a progress callback must not close the mesh that is "
                             "reporting to it", Status.E_STATE)
        with self._lock:
            m, self._m = self._m, None
            if m is not None and capi is not None:
                capi.cvm_mesh_free(m)

    def __del__(self) -> None:
        # No call can hold the lock of an unreachable mesh; should one still
        # do (a thread frozen at interpreter exit), leak rather than free
        # under it or block the finaliser.
        lock = getattr(self, "_lock", None)
        if getattr(self, "_m", None) is None or lock is None or not lock.acquire(False):
            return
        try:
            m, self._m = self._m, None
            if capi is not None:
                capi.cvm_mesh_free(m)
        finally:
            lock.release()

    def __enter__(self) -> Mesh:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        # Never raises and never waits: a repr from a debugger or a progress
        # callback must not block on a call running on this mesh.
        if self._m is None:
            return "<cvmesh.Mesh (closed)>"
        if self._owner is not None or not self._lock.acquire(False):
            return "<cvmesh.Mesh (busy)>"
        try:
            m = self._m
            if m is None:
                return "<cvmesh.Mesh (closed)>"
            n = {e: capi.cvm_mesh_count(m, e) for e in
                 (Entity.VERTEX, Entity.TRIANGLE, Entity.SEGMENT, Entity.INPUT_POINT,
                  Entity.INPUT_SEGMENT)}
        except Error:
            return "<cvmesh.Mesh>"
        finally:
            self._lock.release()
        if n[Entity.TRIANGLE]:
            return "<cvmesh.Mesh: %d vertices, %d triangles, %d segments>" % (
                n[Entity.VERTEX], n[Entity.TRIANGLE], n[Entity.SEGMENT])
        if n[Entity.INPUT_POINT]:
            return "<cvmesh.Mesh: input of %d points, %d segments; not triangulated>" % (
                n[Entity.INPUT_POINT], n[Entity.INPUT_SEGMENT])
        return "<cvmesh.Mesh: empty>"

    @contextlib.contextmanager
    def _handle(self):
        """The C handle, held for one call at a time."""
        me = threading.get_ident()
        if self._owner == me:
            raise StateError("a progress callback must not call methods of the mesh "
                             "that is reporting to it", Status.E_STATE)
        with self._lock:
            if self._m is None:
                raise StateError("the mesh is closed", Status.E_STATE)
            self._owner = me
            try:
                yield self._m
            finally:
                self._owner = None

    # ---- input -------------------------------------------------------------

    def set_points(self, points: npt.ArrayLike, markers: Optional[npt.ArrayLike] = None,
                   attributes: Optional[npt.ArrayLike] = None) -> None:
        """Set the input points ((n, 2) array-like, or (n, 3): the mesh becomes 3D
        and triangulate() tetrahedralises them); clears any triangulation."""
        with self._handle() as m:
            capi.cvm_mesh_set_points(m, points)
            if markers is not None:
                capi.cvm_mesh_set_point_markers(m, markers)
            if attributes is not None:
                attributes = np.asarray(attributes, dtype=np.float64)
                if attributes.ndim == 1:
                    attributes = attributes.reshape(-1, 1)
                capi.cvm_mesh_set_point_attributes(m, attributes)

    def set_segments(self, segments: npt.ArrayLike,
                     markers: Optional[npt.ArrayLike] = None) -> None:
        """Set the constraint segments ((m, 2) 0-based point indices)."""
        with self._handle() as m:
            capi.cvm_mesh_set_segments(m, segments)
            if markers is not None:
                capi.cvm_mesh_set_segment_markers(m, markers)

    def set_tetrahedra(self, tets: npt.ArrayLike,
                       attributes: Optional[npt.ArrayLike] = None) -> None:
        """Take a tetrahedral mesh made elsewhere ((m, 4) 0-based point indices, any
        orientation; optional (m,) region attributes) on the 3D points already set;
        see cvm_mesh_set_tetrahedra() (the checks, and CVMError on a bad mesh)."""
        t = np.ascontiguousarray(tets, dtype=np.int32)
        a = None
        if attributes is not None:
            a = np.ascontiguousarray(attributes, dtype=np.float64).reshape(-1)
            if t.ndim != 2 or a.shape[0] != t.shape[0]:
                raise ValueError("attributes: %d values for %d tetrahedra"
                                 % (a.shape[0], t.shape[0] if t.ndim == 2 else -1))
        with self._handle() as m:
            capi.cvm_mesh_set_tetrahedra(m, t, a)

    def set_holes(self, holes: npt.ArrayLike) -> None:
        """Set hole seed points ((k, 2))."""
        with self._handle() as m:
            capi.cvm_mesh_set_holes(m, holes)

    def set_regions(self, regions: npt.ArrayLike) -> None:
        """Set regions: (r, 4) rows (x, y, attribute, max_area)."""
        with self._handle() as m:
            capi.cvm_mesh_set_regions(m, regions)

    def set_holes_nd(self, holes: npt.ArrayLike) -> None:
        """Set hole seed points in the mesh's dimension ((k, dim) array-like;
        dim 2 in this version, 3 raises UnsupportedError)."""
        with self._handle() as m:
            capi.cvm_mesh_set_holes_nd(m, holes)

    def set_regions_nd(self, regions: npt.ArrayLike) -> None:
        """Set regions in the mesh's dimension: (r, dim + 2) rows (point,
        attribute, largest cell measure; <= 0 no bound)."""
        with self._handle() as m:
            capi.cvm_mesh_set_regions_nd(m, regions)

    def load(self, path: PathLike) -> Status:
        """Replace the input by a Triangle .poly or .node file; a .vtu file
        replaces the mesh too (triangulated, with its weights)."""
        with self._handle() as m, self._progress_installed(m, None, None):
            return self._finish(capi.cvm_mesh_read(m, os.fspath(path)))

    # ---- options -----------------------------------------------------------

    def set_option(self, key: OptionKey, value: float) -> None:
        """Set an option (an Option, or its name such as 'min_angle_deg')."""
        key = _option_key(key)
        with self._handle() as m:
            capi.cvm_mesh_set_option(m, key, float(value))

    def get_option(self, key: OptionKey) -> float:
        """Value of an option (a float)."""
        key = _option_key(key)
        with self._handle() as m:
            return capi.cvm_mesh_get_option(m, key)

    def set_options(self, **options: float) -> None:
        """Set several options by name: mesh.set_options(seed=3, time_limit_s=2)."""
        for key, value in options.items():
            self.set_option(key, value)

    @property
    def options(self) -> Dict[str, float]:
        """{name: value} of every option of this mesh."""
        return {o.name.lower(): self.get_option(o) for o in Option}

    # ---- progress ----------------------------------------------------------

    def set_progress(self, callback: Optional[ProgressCallback], every: int = 1000) -> None:
        """Call callback(stage, fraction) about every `every` operations of long
        calls; a true result stops the call (Status.INCOMPLETE_CANCELLED) and an
        exception stops it and propagates. None removes the callback."""
        self._progress = callback
        self._progress_every = int(every) if callback is not None else 0

    @contextlib.contextmanager
    def _progress_installed(self, m: Any, callback: Optional[ProgressCallback],
                            every: Optional[int],
                            stop: Optional[Callable[[], bool]] = None) -> Iterator[None]:
        """Install the progress callback of one long call: the given one, else
        the one of set_progress(), else a check for Ctrl-C alone; stop() true
        also stops the call. It stays installed after the call (uninstalling
        would clear the handle's error message) and is replaced by the next
        long call."""
        if callback is None:
            callback, every = self._progress, every or self._progress_every
        if callback is not None or stop is not None:
            def target(stage: int, fraction: float, _cb: Any = callback) -> Any:
                if stop is not None and stop():
                    return True
                return _cb is not None and _cb(_stage(stage), fraction)
            if callback is None:
                every = self.interrupt_every or 4096
            capi.cvm_mesh_set_progress(m, target, int(every or 1000))
        else:
            capi.cvm_mesh_set_progress(m, None, int(self.interrupt_every or 0))
        yield

    def _finish(self, code):
        """Record the status of a long call; warn when it stopped early on a
        limit (a cancellation the caller asked for is not warned about)."""
        status = _status(code)
        self.last_status = status
        if code >= 100 and code != Status.INCOMPLETE_CANCELLED:
            warnings.warn("%s: %s" % (status.name if isinstance(status, Status) else status,
                                      capi.cvm_status_str(code)),
                          IncompleteWarning, stacklevel=3)
        return status

    # ---- meshing -----------------------------------------------------------

    def triangulate(self, progress: Optional[ProgressCallback] = None, every: Optional[int] = None,
                    **options: float) -> Status:
        """(Constrained) Delaunay triangulation of the input.

        progress: callback(stage, fraction) -> bool for this call (see
        set_progress); options: set before the call. Returns the Status:
        OK, or INCOMPLETE_* when stopped (the mesh is then empty).
        """
        self.set_options(**options)
        with self._handle() as m, self._progress_installed(m, progress, every):
            return self._finish(capi.cvm_mesh_triangulate(m))

    def insert_points(self, xy: npt.ArrayLike, min_dist: float = 0.0,
                      progress: Optional[ProgressCallback] = None,
                      every: Optional[int] = None) -> npt.NDArray[np.int32]:
        """Insert (k, 2) points into the triangulation, or (k, 3) points into a
        3D mesh's tetrahedralisation (as insert_points_nd()); returns the int32
        vertex id of each point, or REJECTED (-1) for a point outside the
        domain, on a vertex (in 3D also on a surface face), or closer than
        min_dist to an existing vertex."""
        pts = np.asarray(xy, dtype=np.float64)
        if pts.ndim == 2 and pts.shape[1] == 3:
            return self.insert_points_nd(pts, min_dist, progress, every)
        with self._handle() as m, self._progress_installed(m, progress, every):
            code, ids = capi.cvm_mesh_insert_points(m, xy, float(min_dist))
            self._finish(code)
            return ids

    def insert_points_nd(self, points: npt.ArrayLike, min_dist: float = 0.0,
                         progress: Optional[ProgressCallback] = None,
                         every: Optional[int] = None) -> npt.NDArray[np.int32]:
        """insert_points() with (k, dim) points in the mesh's dimension."""
        with self._handle() as m, self._progress_installed(m, progress, every):
            code, ids = capi.cvm_mesh_insert_points_nd(m, points, float(min_dist))
            self._finish(code)
            return ids

    def generate3(self, size: float, sizing: Optional[Sizing] = None,
                  progress: Optional[ProgressCallback] = None, every: Optional[int] = None,
                  **options: float) -> Status:
        """Generate a tetrahedral co-volume mesh inside the closed 3D surface
        read into this mesh (cvm_mesh_generate3): size is the largest size;
        sizing (a Sizing of 3D sources, a callback_nd, uniform size or boundary
        grading) lowers it where smaller (cvm_mesh_generate3_sized). Returns
        the Status."""
        self.set_options(**options)
        with contextlib.ExitStack() as stack:
            s = stack.enter_context(sizing._handle()) if sizing is not None else None
            m = stack.enter_context(self._handle())
            stack.enter_context(self._progress_installed(m, progress, every))
            if s is None:
                return self._finish(capi.cvm_mesh_generate3(m, float(size)))
            return self._finish(capi.cvm_mesh_generate3_sized(m, float(size), s))

    def optimise_dual3(self, progress: Optional[ProgressCallback] = None,
                       every: Optional[int] = None, **options: float) -> Status:
        """Move the vertices of this tetrahedral mesh and set power weights so
        that more tetrahedra contain their power vertex (cvm_mesh_optimise_dual3;
        options such as dual3_max_sweeps, dual3_min_dihedral_deg, dual3_flips,
        seed, time_limit_s). With dual3_flips=1 (default) flips keep the mesh
        regular and the tetrahedra change (the vertices and surface faces stay);
        dual3_flips=0 keeps the connectivity.
        Returns the Status (INCOMPLETE_* after a time limit or a stop by the
        progress callback: the mesh is then valid with the moves made so far).
        The run's report: report("dual3_outside_after_pct") and the other
        dual3_* reports."""
        self.set_options(**options)
        with contextlib.ExitStack() as stack:
            m = stack.enter_context(self._handle())
            stack.enter_context(self._progress_installed(m, progress, every))
            return self._finish(capi.cvm_mesh_optimise_dual3(m))

    def refine(self, algorithm: Union[str, int] = "frontal",
               size: Union[float, SizeCallback, None] = None, min_angle: Optional[float] = None,
               max_area: Optional[float] = None, sizing: Optional[Sizing] = None,
               max_steiner: Optional[int] = None, progress: Optional[ProgressCallback] = None,
               every: Optional[int] = None, **options: float) -> Status:
        """Refine the triangulation with Steiner points until every triangle
        meets the minimum angle, the maximum area and the sizing.

        algorithm: "frontal" (off-centres grown from the boundary),
        "aflr" (advancing-front layers grown from the segments; see
        layer_index) or "delaunay"
        (circumcentres), or an Algorithm. size: target edge length,
        a number or a callable size(x, y) (shortcut for a Sizing); sizing: a
        Sizing. min_angle: degrees; max_area; max_steiner: limit on added
        points. Triangulates first when nothing is triangulated yet. Returns
        the Status (INCOMPLETE_* when a limit or the callback stopped it; the
        mesh is then valid with the points inserted so far).
        """
        if not hasattr(capi, "cvm_mesh_refine"):
            raise _unsupported(
                "mesh refinement is not available in this version of the cvmesh library "
                "(%s): cvm_mesh_refine() is not in cvmesh.h; use triangulate() and "
                "insert_points()" % version())
        if size is not None and sizing is not None:
            raise ValueError("give size or sizing, not both")
        if min_angle is not None:
            options["min_angle_deg"] = min_angle
        if max_area is not None:
            options["max_area"] = max_area
        if max_steiner is not None:
            options["max_steiner"] = max_steiner
        algo = _algorithm(algorithm)
        self.set_options(**options)
        if self.count(Entity.TRIANGLE) == 0:
            self.triangulate(progress=progress, every=every)
        own = None
        if size is not None:
            own = sizing = Sizing(callback=size) if callable(size) else Sizing(uniform=size)
        try:
            with contextlib.ExitStack() as stack:
                s = stack.enter_context(sizing._handle()) if sizing is not None else None
                m = stack.enter_context(self._handle())
                stack.enter_context(self._progress_installed(m, progress, every))
                return self._finish(capi.cvm_mesh_refine(m, s, algo))
        finally:
            if own is not None:
                own.close()

    def optimise_dual(self, size: Union[float, SizeCallback, None] = None,
                      sizing: Optional[Sizing] = None,
                      progress: Optional[ProgressCallback] = None, every: Optional[int] = None,
                      **options: float) -> Status:
        """Move the vertices and set their power weights so that every triangle
        contains its power vertex or is merged, and dual edges are not tiny
        (cvm_mesh_optimise_dual()). size / sizing: local size for the solver's
        steps (default: from the mesh). options: dual_solver, dual_max_sweeps,
        dual_margin, dual_merge_tol, ... (CVM_OPT_* names in lower case).
        Returns the Status (INCOMPLETE_* when the time limit or the callback
        stopped it; the mesh is then a valid regular triangulation)."""
        if not hasattr(capi, "cvm_mesh_optimise_dual"):
            raise _unsupported("dual optimisation is not available in this version of the "
                               "cvmesh library (%s)" % version())
        if size is not None and sizing is not None:
            raise ValueError("give size or sizing, not both")
        self.set_options(**options)
        own = None
        if size is not None:
            own = sizing = Sizing(callback=size) if callable(size) else Sizing(uniform=size)
        try:
            with contextlib.ExitStack() as stack:
                s = stack.enter_context(sizing._handle()) if sizing is not None else None
                m = stack.enter_context(self._handle())
                stack.enter_context(self._progress_installed(m, progress, every))
                return self._finish(capi.cvm_mesh_optimise_dual(m, s))
        finally:
            if own is not None:
                own.close()

    def quadmesh(self, metric: Sizing, progress: Optional[ProgressCallback] = None,
                 every: Optional[int] = None, **options: float) -> Status:
        """Quad-dominant mesh of the convex input domain aligned with the metric of
        the Sizing metric (set_metric(), set_metric_builtin() or
        set_metric_constant()): a frontal start, Lp-CVT sites by L-BFGS, then
        Blossom-Quad and smoothing (cvm_mesh_quadmesh()). options: quad_p,
        quad_recombine, quad_min_quality, quad_max_iterations, quad_smooth,
        quad_all_quad, ... (CVM_OPT_* names in lower case). The quads are
        cells_mixed(); triangles is the Delaunay triangulation of the final points;
        report('quad_pct') etc. give the quad measures. Returns the Status
        (INCOMPLETE_* when the time limit or the callback stopped the
        optimisation; the mesh of the sites so far is then valid)."""
        if not hasattr(capi, "cvm_mesh_quadmesh"):
            raise _unsupported("quad meshing is not available in this version of the "
                               "cvmesh library (%s)" % version())
        self.set_options(**options)
        with contextlib.ExitStack() as stack:
            s = stack.enter_context(metric._handle())
            m = stack.enter_context(self._handle())
            stack.enter_context(self._progress_installed(m, progress, every))
            return self._finish(capi.cvm_mesh_quadmesh(m, s))

    def check(self) -> bool:
        """Re-verify the mesh with exact predicates; raises InternalError
        naming the failed check, else returns True."""
        with self._handle() as m, self._progress_installed(m, None, None):
            self._finish(capi.cvm_mesh_check(m))
        return True

    # ---- output ------------------------------------------------------------

    def count(self, kind: Union[str, int]) -> int:
        """Number of entities of a kind (an Entity or its name, e.g. 'triangle')."""
        if isinstance(kind, str):
            kind = Entity[kind.upper()]
        with self._handle() as m:
            return capi.cvm_mesh_count(m, int(kind))

    @property
    def dim(self) -> int:
        """Dimension of the mesh: coordinates per point (2, or 3 after 3D points)."""
        with self._handle() as m:
            return capi.cvm_mesh_dim(m)

    @property
    def points_nd(self) -> npt.NDArray[np.float64]:
        """(n, dim) float64 vertex coordinates in the mesh's dimension (a copy)."""
        with self._handle() as m:
            return capi.cvm_mesh_view_points_nd(m)

    def cells_mixed(self, kind: Optional[int] = None) -> Tuple[npt.NDArray[np.int32], ...]:
        """Cells of several types as (offsets, types, conn) int32 arrays: cell c
        has type types[c] (a CellType, VTK's numbering) and the vertex ids
        conn[offsets[c]:offsets[c + 1]]. kind: Entity.CELL (the default)."""
        kind = Entity.CELL if kind is None else kind
        with self._handle() as m:
            nc, nconn = capi.cvm_mesh_count_cells_mixed(m, int(kind))
            return tuple(capi.cvm_mesh_copy_cells_mixed(nc + 1, nc, nconn, m, int(kind)))

    def cell_neighbors(self, kind: Optional[int] = None) -> npt.NDArray[np.int32]:
        """Neighbour of each cell across each face, -1 on the boundary, in the
        layout of cells_mixed() (kind Entity.CELL, the default: a flat int32
        array) or, for Entity.TRIANGLE, as the (m, 3) array of neighbors."""
        kind = Entity.CELL if kind is None else kind
        with self._handle() as m:
            nc, nconn = capi.cvm_mesh_count_cells_mixed(m, Entity.CELL)
            nb = capi.cvm_mesh_copy_cell_neighbors(nconn, m, int(kind))
        return nb.reshape(-1, 3) if kind == Entity.TRIANGLE else nb

    def cell_attributes(self, kind: Optional[int] = None) -> npt.NDArray[np.float64]:
        """(cells,) float64 regional attribute of each cell (kind as cell_neighbors)."""
        kind = Entity.CELL if kind is None else kind
        with self._handle() as m:
            nc, _ = capi.cvm_mesh_count_cells_mixed(m, Entity.CELL)
            return capi.cvm_mesh_copy_cell_attributes(nc, m, int(kind))

    def report(self, which: Union[str, int]) -> float:
        """Report of the last run (a Report or its name, e.g. 'refine_steiner')."""
        if isinstance(which, str):
            which = Report[which.upper()]
        with self._handle() as m:
            return capi.cvm_mesh_get_report(m, int(which))

    def reports(self) -> Dict[str, float]:
        """{name: value} of every Report of the last runs."""
        return {r.name.lower(): self.report(r) for r in Report}

    def _cells(self, kind, width):
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, kind)
            return capi.cvm_mesh_copy_cells(width * n, m, kind).reshape(n, width)

    @property
    def points(self) -> npt.NDArray[np.float64]:
        """(n, 2) float64 vertex coordinates (a copy); (n, 3) for a 3D mesh."""
        with self._handle() as m:
            if capi.cvm_mesh_dim(m) == 3:
                return capi.cvm_mesh_view_points_nd(m)
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            return capi.cvm_mesh_copy_points(2 * n, m).reshape(n, 2)

    @property
    def tetrahedra(self) -> npt.NDArray[np.int32]:
        """(m, 4) int32 vertex ids of the tetrahedra of a 3D mesh, positively
        oriented ((0, 4) for a 2D mesh)."""
        if self.dim != 3:
            return np.zeros((0, 4), dtype=np.int32)
        return self._cells(Entity.TETRAHEDRON, 4)

    @property
    def dual3_volumes(self) -> npt.NDArray[np.float64]:
        """(n,) float64 dual (power) cell volume of each vertex of a 3D mesh, -1
        for a vertex on the boundary (cvm_mesh_copy_dual3_volumes)."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            return capi.cvm_mesh_copy_dual3_volumes(n, m)

    @property
    def dual3_merge_groups(self) -> npt.NDArray[np.int32]:
        """(m,) int32: per tetrahedron of a 3D mesh, the smallest tetrahedron index
        of its kept merged dual cell (its own index when not merged); the rule is
        CVM_OPT_DUAL3_MERGE_TOL (option dual3_merge_tol); see
        cvm_mesh_copy_dual3_merge_groups()."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TETRAHEDRON)
            return capi.cvm_mesh_copy_dual3_merge_groups(n, m)

    @property
    def triangles(self) -> npt.NDArray[np.int32]:
        """(m, 3) int32 vertex ids of the triangles, counter-clockwise."""
        return self._cells(Entity.TRIANGLE, 3)

    @property
    def edges(self) -> npt.NDArray[np.int32]:
        """(e, 2) int32 vertex ids of the edges, sorted."""
        return self._cells(Entity.EDGE, 2)

    @property
    def segments(self) -> npt.NDArray[np.int32]:
        """(s, 2) int32 vertex ids of the constrained edges of the output."""
        return self._cells(Entity.SEGMENT, 2)

    @property
    def neighbors(self) -> npt.NDArray[np.int32]:
        """(m, 3) int32: neighbour of each triangle across the edge opposite
        vertex k, -1 on the boundary."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_neighbors(3 * n, m).reshape(n, 3)

    def _markers(self, kind):
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, kind)
            return capi.cvm_mesh_copy_markers(n, m, kind)

    @property
    def point_markers(self) -> npt.NDArray[np.int32]:
        """(n,) int32 marker of each vertex."""
        return self._markers(Entity.VERTEX)

    @property
    def segment_markers(self) -> npt.NDArray[np.int32]:
        """(s,) int32 marker of each output segment."""
        return self._markers(Entity.SEGMENT)

    @property
    def triangle_attributes(self) -> npt.NDArray[np.float64]:
        """(m,) float64 regional attribute of each triangle."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_triangle_attributes(n, m)

    @property
    def layer_index(self) -> npt.NDArray[np.float64]:
        """(m,) float64 advancing-front layer index of each triangle after an
        "aflr" refinement (max + 0.1 x min of its edges' layers; -1 where no
        front reached, and everywhere after another algorithm)."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_layer_index(n, m)

    @property
    def point_attributes(self) -> npt.NDArray[np.float64]:
        """(n, a) float64 point attributes of each vertex."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            nattr = 0
            while True:
                try:
                    values, nattr = capi.cvm_mesh_copy_point_attributes(n * nattr, m)
                    return values.reshape(n, nattr)
                except ArgumentError as e:
                    # The buffer size depends on nattr, which only a successful
                    # call reports: grow until it fits.
                    if e.status != Status.E_BUFFER_TOO_SMALL or nattr > 4096:
                        raise
                    nattr = max(1, 2 * nattr)

    @property
    def input_map(self) -> npt.NDArray[np.int32]:
        """(n_input,) int32: the vertex each input point became (-1: an inner vertex
        of a chain re-discretised with the option keep_segment_vertices = 0)."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.INPUT_POINT)
            return capi.cvm_mesh_copy_input_map(n, m)

    # ---- weights and the power (Voronoi) dual -------------------------------

    @property
    def weights(self) -> npt.NDArray[np.float64]:
        """(n,) float64 power weight of each vertex (0 when none were set).
        Setting it (an (n,) array, or None to remove) makes the triangulation
        regular for those weights; see cvm_mesh_set_weights()."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            return capi.cvm_mesh_copy_weights(n, m)

    @weights.setter
    def weights(self, w: Optional[npt.ArrayLike]) -> None:
        self.set_weights(w)

    def set_weights(self, w: Optional[npt.ArrayLike]) -> None:
        """Set the power weight of every vertex (None removes them)."""
        with self._handle() as m:
            capi.cvm_mesh_set_weights(m, np.zeros(0) if w is None else w)

    @property
    def dual_vertices(self) -> npt.NDArray[np.float64]:
        """(m, 2) float64 power vertex (circumcentre without weights) of each triangle."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_dual_vertices(2 * n, m).reshape(n, 2)

    @property
    def dual_vertices_nd(self) -> npt.NDArray[np.float64]:
        """(m, dim) float64 power vertex of each cell, in the mesh's dimension."""
        with self._handle() as m:
            d = capi.cvm_mesh_dim(m)
            n = capi.cvm_mesh_count(m, Entity.TETRAHEDRON if d == 3 else Entity.TRIANGLE)
            return capi.cvm_mesh_copy_dual_vertices_nd(d * n, d, m).reshape(n, d)

    @property
    def dual_inside(self) -> npt.NDArray[np.bool_]:
        """(m,) bool: whether each triangle contains its power vertex (exact)."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_dual_inside(n, m).astype(bool)

    @property
    def dual_areas(self) -> npt.NDArray[np.float64]:
        """(n,) float64 dual (power/Voronoi) cell area of each vertex, within the domain."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            return capi.cvm_mesh_copy_dual_areas(n, m)

    @property
    def dual_edge_lengths(self) -> npt.NDArray[np.float64]:
        """(e,) float64 dual edge length of each edge, in the order of `edges`."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.EDGE)
            return capi.cvm_mesh_copy_dual_edge_lengths(n, m)

    def dual_quality(self, which: Union[str, int]) -> npt.NDArray[np.float64]:
        """Per-element dual quality values (see cvm_histogram in cvmesh.h):
        which is a Histogram Q1..Q5 or its name ("q1".."q5"). q1 (min angle,
        degrees) and q2 (|centroid - power vertex| / inradius) give one value
        per triangle; q3, q4 (crossing offsets over the edge length) and q5
        (dual edge over l / sqrt 3) one per edge, in the order of `edges`."""
        if isinstance(which, str):
            which = Histogram[which.upper()]
        which = Histogram(which)
        with self._handle() as m:
            kind = Entity.TRIANGLE if which in (Histogram.Q1, Histogram.Q2) else Entity.EDGE
            n = capi.cvm_mesh_count(m, kind)
            return capi.cvm_mesh_copy_dual_quality(n, m, which)

    @property
    def dual_cells(self) -> Tuple[npt.NDArray[np.int32], npt.NDArray[np.float64]]:
        """The power (Voronoi) cell polygon of each vertex, restricted to the
        domain, as CSR arrays (offsets, corners): offsets (n + 1,) int32, and
        corners (k, 2) float64; vertex v's polygon is
        corners[offsets[v]:offsets[v + 1]], counter-clockwise."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            offsets = capi.cvm_mesh_copy_dual_cell_offsets(n + 1, m)
            k = int(offsets[-1])
            return offsets, capi.cvm_mesh_copy_dual_cells(2 * k, m).reshape(k, 2)

    @property
    def marker_names(self) -> Dict[Tuple[int, int], str]:
        """{(dim, marker): name}: the names of the markers (Gmsh physical names;
        dim 0 points, 1 segments, 2 regions), read from a .msh and written back
        to one. See cvm_mesh_set_marker_name()."""
        with self._handle() as m:
            n = capi.cvm_mesh_count_marker_names(m)
            keys = capi.cvm_mesh_copy_marker_name_keys(2 * n, m).reshape(n, 2)
            return {(int(d), int(k)): capi.cvm_mesh_get_marker_name(m, int(d), int(k))
                    for d, k in keys}

    def set_marker_name(self, dim: int, marker: int, name: Optional[str]) -> None:
        """Name marker `marker` of dimension `dim` (None removes the name)."""
        with self._handle() as m:
            capi.cvm_mesh_set_marker_name(m, dim, marker, name)

    def dual(self) -> "DualMesh":
        """The power (Voronoi) dual as a finite-volume mesh (cvm_mesh_copy_dual_points()
        and the calls after it in cvmesh.h): a DualMesh of numpy arrays. points
        (k, 2) float64, each once (power vertices of the triangles, then the
        feet of the boundary edges, then the boundary vertices); offsets (n + 1,)
        and polygons (c,) int32, vertex v's cell polygons[offsets[v]:offsets[v+1]]
        as point ids, counter-clockwise; faces (f, 6) int32: cell a, cell b (-1
        on the boundary), the primal edge's two vertices, the face's points p, q
        (cell a on the left of p -> q); face_lengths (f, 2) float64: primal edge
        length, face length; areas (n,) float64 the cell areas."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.VERTEX)
            npt_, ncorner, nface = capi.cvm_mesh_count_dual(m)
            return DualMesh(
                capi.cvm_mesh_copy_dual_points(2 * npt_, m).reshape(npt_, 2),
                capi.cvm_mesh_copy_dual_cell_offsets(n + 1, m),
                capi.cvm_mesh_copy_dual_polygons(ncorner, m),
                capi.cvm_mesh_copy_dual_faces(6 * nface, m).reshape(nface, 6),
                capi.cvm_mesh_copy_dual_face_lengths(2 * nface, m).reshape(nface, 2),
                capi.cvm_mesh_copy_dual_areas(n, m))

    def write_dual(self, path: PathLike) -> None:
        """Write the power cells as .vtu polygons (cell data vertex, area, weight)."""
        with self._handle() as m:
            capi.cvm_mesh_write_dual(m, os.fspath(path))

    @property
    def dual_merge_groups(self) -> npt.NDArray[np.int32]:
        """(m,) int32: per triangle, the smallest triangle index of its merged dual
        cell (its own index when not merged); see cvm_mesh_copy_dual_merge_groups()."""
        with self._handle() as m:
            n = capi.cvm_mesh_count(m, Entity.TRIANGLE)
            return capi.cvm_mesh_copy_dual_merge_groups(n, m)

    @property
    def last_error(self) -> str:
        """Message of the last failing call on this mesh ('' after success)."""
        with self._handle() as m:
            return capi.cvm_mesh_errmsg(m)

    def quality(self) -> Quality:
        """Quality measures and histograms of the current mesh (a Quality)."""
        values = {}
        with self._handle() as m:
            for meas in Measure:
                try:
                    values[meas.name.lower()] = capi.cvm_mesh_get_measure(m, meas)
                except (UnsupportedError, ArgumentError) as e:
                    if e.status not in (Status.E_UNSUPPORTED, Status.E_ARGUMENT):
                        raise
                    values[meas.name.lower()] = math.nan  # not in this build
            for hist in Histogram:
                bins = _HIST_BINS.get(hist.name, 64)
                try:
                    values["hist_" + hist.name.lower()] = capi.cvm_mesh_copy_histogram(bins, m,
                                                                                       hist)
                except (UnsupportedError, ArgumentError) as e:
                    if e.status not in (Status.E_UNSUPPORTED, Status.E_ARGUMENT):
                        raise
                    # a 2D histogram of a 3D mesh, or a 3D one of a 2D mesh
                    values["hist_" + hist.name.lower()] = np.zeros(0)
        return Quality(**values)

    def write(self, path: PathLike) -> None:
        """Write the mesh; the format follows the extension: .vtu, .msh,
        .node (with .ele and .edge), .svg.

        The files are written under temporary names and renamed over their
        targets at the end (cvm_mesh_stage_write, cvm_mesh_commit_writes).
        Ctrl-C (SIGINT, in the main thread with Python's default handler)
        stops the write: every target stays as it was, no temporary file is
        left, and KeyboardInterrupt is raised. A write that completed is never
        reported as interrupted: a Ctrl-C that lands during the final renames
        (microseconds) is ignored. A progress callback that cancels leaves the
        targets as they were too (last_status INCOMPLETE_CANCELLED)."""
        with self._handle() as m, _sigint_held() as interrupted, \
                self._progress_installed(m, None, None, stop=interrupted):
            try:
                code = capi.cvm_mesh_stage_write(m, os.fspath(path))
            except BaseException:
                capi.cvm_mesh_discard_writes(m)
                raise
            if code != Status.OK or interrupted():
                # the library removed its files on a cancellation; a Ctrl-C
                # after the last progress check lands here with the files staged
                capi.cvm_mesh_discard_writes(m)
                if interrupted():
                    raise KeyboardInterrupt
                self._finish(code)
                return
            capi.cvm_mesh_commit_writes(m)
            self._finish(code)

    # ---- interoperability --------------------------------------------------

    def to_meshio(self) -> Any:
        """A meshio.Mesh of the mesh (z = 0), in the layout of write() to .vtu:
        cell blocks "triangle" and, when there are segments, "line" (the
        constrained edges); point data "marker" and "weight" (the power weights,
        0 without them) and "attribute" (point attributes, when set); cell data
        "marker" (segment marker on a line, 0 on a triangle) and "attribute"
        (regional attribute of a triangle, 0 on a line). Needs meshio."""
        try:
            import meshio  # type: ignore
        except ImportError:
            raise ImportError("Mesh.to_meshio() needs meshio: pip install meshio") from None
        pts = self.points
        pts3 = np.zeros((len(pts), 3))
        pts3[:, :2] = pts
        tris, segs = self.triangles, self.segments
        cells = [("triangle", tris)]
        markers = [np.zeros(len(tris), dtype=np.int32)]
        attributes = [self.triangle_attributes]
        if len(segs):
            cells.append(("line", segs))
            markers.append(self.segment_markers)
            attributes.append(np.zeros(len(segs)))
        point_data = {"marker": self.point_markers, "weight": self.weights}
        pattr = self.point_attributes
        if pattr.shape[1]:
            point_data["attribute"] = pattr if pattr.shape[1] > 1 else pattr[:, 0]
        return meshio.Mesh(pts3, cells, point_data=point_data,
                           cell_data={"marker": markers, "attribute": attributes})

    #: cell data names from_meshio() takes segment markers from, in this order.
    MESHIO_MARKER_KEYS = ("marker", "gmsh:physical", "medit:ref", "cell_tags")

    @classmethod
    def from_meshio(cls, mesh: Any, marker: Optional[str] = None, **options: float) -> Mesh:
        """A cvmesh Mesh from a meshio.Mesh of triangles in the plane.

        mesh.points: (n, 2), or (n, 3) with every z = 0. Its "triangle" cells
        give the domain, its "line" cells the segments, with their markers from
        the cell data `marker` (default: the first of MESHIO_MARKER_KEYS that
        is there). Without line cells, the boundary edges of the triangles
        become the segments (marker 1). Holes (bounded regions the triangles do
        not cover) become hole seeds. Point data "marker" and "weight" are
        used when present. Other cell types (vertex cells aside) raise
        ArgumentError.

        The result is triangulated: the constrained Delaunay (with weights:
        regular) triangulation of the points and segments, carved to the
        triangles' domain. Its vertices are the points in order; its triangles
        are the given ones when those were (constrained) Delaunay, and
        otherwise a re-triangulation of the same points and boundary."""
        pts = np.asarray(mesh.points, dtype=np.float64)
        if pts.ndim != 2 or pts.shape[1] not in (2, 3):
            raise ArgumentError("from_meshio: points of shape %s; need (n, 2) or (n, 3)"
                                % (pts.shape,), Status.E_ARGUMENT)
        if pts.shape[1] == 3:
            off = np.flatnonzero(pts[:, 2] != 0)
            if off.size:
                raise InputError("from_meshio: point %d has z = %.17g; cvmesh meshes the plane "
                                 "z = 0" % (off[0], pts[off[0], 2]), Status.E_ARGUMENT,
                                 Entity.INPUT_POINT, int(off[0]))
            pts = np.ascontiguousarray(pts[:, :2])
        key = marker
        if key is None:
            key = next((k for k in cls.MESHIO_MARKER_KEYS if k in mesh.cell_data), None)
        tris, segs, seg_markers = [], [], []
        for k, block in enumerate(mesh.cells):
            data = np.asarray(block.data)
            if block.type == "triangle":
                tris.append(data)
            elif block.type == "line":
                segs.append(data)
                if key is not None and key in mesh.cell_data:
                    seg_markers.append(np.asarray(mesh.cell_data[key][k]).reshape(-1))
                else:
                    seg_markers.append(np.ones(len(data), dtype=np.int64))
            elif block.type != "vertex":
                raise ArgumentError("from_meshio: cell block %d has type %s; cvmesh takes "
                                    "triangle and line cells" % (k, block.type), Status.E_ARGUMENT)
        tri = np.concatenate(tris).astype(np.int64) if tris else np.zeros((0, 3), np.int64)
        if segs:
            seg = np.concatenate(segs).astype(np.int64)
            seg_mark = np.concatenate(seg_markers)
        else:
            seg = _boundary_edges(tri)
            seg_mark = np.ones(len(seg), dtype=np.int64)
        point_markers = mesh.point_data.get("marker")
        weights = mesh.point_data.get("weight")

        def build(holes: Optional[npt.NDArray[np.float64]]) -> Mesh:
            m = cls.from_pslg(pts, seg.astype(np.int32) if len(seg) else None,
                              holes=holes if holes is not None and len(holes) else None,
                              markers=None if point_markers is None
                              else np.asarray(point_markers).astype(np.int32).reshape(-1),
                              segment_markers=seg_mark.astype(np.int32) if len(seg) else None,
                              **options)
            m.triangulate()
            return m

        result = build(None)
        if len(tri):
            holes = _hole_seeds(result, tri)
            if len(holes):
                result.close()
                result = build(holes)
        if weights is not None:
            result.set_weights(np.asarray(weights, dtype=np.float64).reshape(-1))
        return result

    def triangle_min_angles(self) -> npt.NDArray[np.float64]:
        """(m,) float64 smallest angle of each triangle, degrees."""
        p = self.points[self.triangles]  # (m, 3, 2)
        angles = []
        for k in range(3):
            a = p[:, (k + 1) % 3] - p[:, k]
            b = p[:, (k + 2) % 3] - p[:, k]
            cross = np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
            angles.append(np.degrees(np.arctan2(cross, np.einsum("ij,ij->i", a, b))))
        return np.min(angles, axis=0) if angles[0].size else np.zeros(0)

    def plot(self, ax: Any = None, color_by: Optional[str] = "quality", **kwargs: Any) -> Any:
        """Draw the mesh with matplotlib (needs matplotlib); returns the Axes.

        color_by: "quality" (smallest angle of each triangle, degrees),
        "attribute" (regional attribute), or None (edges only).
        """
        try:
            import matplotlib.pyplot as plt  # type: ignore
            import matplotlib.tri as mtri  # type: ignore
        except ImportError:
            raise ImportError("Mesh.plot() needs matplotlib: pip install matplotlib") from None
        if ax is None:
            ax = plt.gca()
        pts, tris = self.points, self.triangles
        tri = mtri.Triangulation(pts[:, 0], pts[:, 1], tris)
        if color_by is None:
            ax.triplot(tri, **kwargs)
        else:
            if color_by == "quality":
                values, label = self.triangle_min_angles(), "min angle (deg)"
            elif color_by == "attribute":
                values, label = self.triangle_attributes, "attribute"
            else:
                raise ValueError("color_by must be 'quality', 'attribute' or None")
            kwargs.setdefault("edgecolors", "k")
            kwargs.setdefault("linewidth", 0.2)
            coll = ax.tripcolor(tri, facecolors=values, **kwargs)
            ax.figure.colorbar(coll, ax=ax, label=label)
        ax.set_aspect("equal")
        return ax


def _boundary_edges(tri: npt.NDArray[np.int64]) -> npt.NDArray[np.int64]:
    """(k, 2) edges used by one triangle of tri, directed as in their
    triangle (so the triangle lies on their left when tri is counter-clockwise)."""
    if not len(tri):
        return np.zeros((0, 2), dtype=np.int64)
    directed = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    key = np.sort(directed, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    return directed[counts[inverse.reshape(-1)] == 1]


def _hole_seeds(mesh: Mesh, tri: npt.NDArray[np.int64]) -> npt.NDArray[np.float64]:
    """Hole seeds for the triangles tri (vertex ids of mesh's points): one
    point inside each region of mesh's triangulation, bounded by its
    segments, that tri does not cover. A region is covered when it holds the
    triangle on the inner side of a boundary edge of tri: the side of the
    edge's triangle, found from the edge's direction in that triangle
    (topology), with the triangle's orientation from the sign of its area."""
    pts = mesh.points
    tri = mesh.input_map[tri].astype(np.int64)
    p = pts[tri]
    area2 = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
             - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
    cw = area2 < 0
    tri = tri.copy()
    tri[cw] = tri[cw][:, [0, 2, 1]]
    inner = {(int(a), int(b)) for a, b in _boundary_edges(tri)}   # domain on the left
    T, nb = mesh.triangles, mesh.neighbors
    segs = {tuple(sorted(map(int, s))) for s in mesh.segments}
    nt = len(T)
    region = np.full(nt, -1)
    covered = []
    for start in range(nt):
        if region[start] >= 0:
            continue
        r = len(covered)
        covered.append(False)
        stack = [start]
        region[start] = r
        while stack:
            t = stack.pop()
            for j in range(3):
                a, b = int(T[t, (j + 1) % 3]), int(T[t, (j + 2) % 3])
                if (a, b) in inner:            # t is left of a domain edge (a, b)
                    covered[r] = True
                u = nb[t, j]
                if u >= 0 and region[u] < 0 and (min(a, b), max(a, b)) not in segs:
                    region[u] = r
                    stack.append(u)
    seeds = [pts[T[np.flatnonzero(region == r)[0]]].mean(axis=0)
             for r in range(len(covered)) if not covered[r]]
    return np.array(seeds).reshape(-1, 2)


@contextlib.contextmanager
def _sigint_held() -> Iterator[Callable[[], bool]]:
    """Hold Ctrl-C while the block runs: yields interrupted(), true once a
    SIGINT has arrived. Only in the main thread and only over Python's default
    handler; otherwise SIGINT keeps its handler and interrupted() stays false
    (the progress callback then raises what the handler raises)."""
    hits: list = []
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        yield lambda: False
        return

    def hold(signum: int, frame: Any) -> None:
        hits.append(signum)

    old = signal.signal(signal.SIGINT, hold)
    try:
        yield lambda: bool(hits)
    finally:
        signal.signal(signal.SIGINT, old)


def _algorithm(name: Union[str, int]) -> int:
    """Algorithm from an Algorithm, an int, or a name like 'frontal'."""
    if isinstance(name, str):
        try:
            return Algorithm[name.upper()]
        except KeyError:
            raise ArgumentError("unknown refinement algorithm %r; known: %s" % (
                name, ", ".join(a.name.lower() for a in Algorithm)),
                Status.E_ARGUMENT) from None
    return int(name)


class Sizing:
    """Target edge length h(x, y) for Mesh.refine(): the minimum of a uniform
    size, point sources, line sources and a Python callback.

        sizing = cvmesh.Sizing(uniform=0.1)
        sizing.add_point_source(0.5, 0.5, h=0.01, growth=0.2)
        mesh.refine(sizing=sizing, min_angle=28)

    A callback size(x, y) -> float is called with the GIL taken from inside
    the refinement (slow for large meshes; prefer sources). A batch callback
    (set_batch_callback, or Sizing(batch=...)) takes an (n, 2) array of
    points and returns n sizes: numpy code runs once per batch instead of
    once per point. An exception either raises stops the refinement and
    propagates.
    """

    def __init__(self, uniform: Optional[float] = None,
                 callback: Optional[SizeCallback] = None,
                 batch: Optional[BatchSizeCallback] = None) -> None:
        self._s = None
        self._lock = threading.Lock()
        self._owner = None
        self._callback: Any = None
        self._metric: Any = None
        self._s = capi.cvm_sizing_create()
        if uniform is not None:
            self.set_uniform(uniform)
        if callback is not None and batch is not None:
            raise ValueError("give callback or batch, not both (one user function per sizing)")
        if callback is not None:
            self.set_callback(callback)
        if batch is not None:
            self.set_batch_callback(batch)

    def close(self) -> None:
        """Free the C handle now (also done when the object is collected).

        A call using this sizing in another thread (a Mesh.refine() or
        optimise_dual(), or an evaluation) is waited for: the handle is never
        freed under it. Raises StateError from this sizing's own callback."""
        if self._owner == threading.get_ident():
            raise StateError("a sizing callback must not close the sizing that calls it",
                             Status.E_STATE)
        with self._lock:
            s, self._s = self._s, None
            if s is not None and capi is not None:
                capi.cvm_sizing_free(s)

    def __del__(self) -> None:
        # As Mesh.__del__: never free under a call, never block a finaliser.
        lock = getattr(self, "_lock", None)
        if getattr(self, "_s", None) is None or lock is None or not lock.acquire(False):
            return
        try:
            s, self._s = self._s, None
            if capi is not None:
                capi.cvm_sizing_free(s)
        finally:
            lock.release()

    def __enter__(self) -> Sizing:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @contextlib.contextmanager
    def _handle(self):
        me = threading.get_ident()
        if self._owner == me:
            raise StateError("a sizing callback must not use the sizing that calls it",
                             Status.E_STATE)
        with self._lock:
            if self._s is None:
                raise StateError("the sizing is closed", Status.E_STATE)
            self._owner = me
            try:
                yield self._s
            finally:
                self._owner = None

    def set_uniform(self, h: float) -> None:
        """Uniform target edge length h > 0 (replaces an earlier one)."""
        with self._handle() as s:
            capi.cvm_sizing_set_uniform(s, float(h))

    def add_point_source(self, x: float, y: float, h: float, growth: float = 0.0) -> None:
        """h(p) = h + growth * |p - (x, y)|."""
        with self._handle() as s:
            capi.cvm_sizing_add_point_source(s, float(x), float(y), float(h), float(growth))

    def add_line_source(self, x0: float, y0: float, x1: float, y1: float, h: float,
                        growth: float = 0.0) -> None:
        """h(p) = h + growth * distance(p, segment (x0, y0)-(x1, y1))."""
        with self._handle() as s:
            capi.cvm_sizing_add_line_source(s, float(x0), float(y0), float(x1), float(y1),
                                            float(h), float(growth))

    def set_callback(self, callback: Optional[SizeCallback]) -> None:
        """Use callback(x, y) -> size as one more source (None removes it)."""
        with self._handle() as s:
            capi.cvm_sizing_set_callback(s, callback)
            self._callback = callback

    def set_batch_callback(self, callback: Optional[BatchSizeCallback]) -> None:
        """Use callback(xy) -> sizes as one more source, asked for many points
        at once: xy an (n, 2) float64 array, the result n positive sizes (e.g.
        lambda xy: 0.01 + 0.1 * xy[:, 0]). Mesh.refine() asks for all the
        vertices it starts from in batches of up to 1024 points and for each
        point it inserts on its own (n = 1), so the mesh is the one a
        callback(x, y) of the same sizes gives. Replaces a callback(x, y) or
        callback(x); None removes it (cvm_sizing_set_batch_callback)."""
        if not hasattr(capi, "cvm_sizing_set_batch_callback"):
            raise _unsupported("batch sizing callbacks need cvm_sizing_set_batch_callback(), "
                               "not in this version of the cvmesh library (%s)" % version())
        with self._handle() as s:
            capi.cvm_sizing_set_batch_callback(s, callback)
            self._callback = callback

    def add_point_source_nd(self, x: npt.ArrayLike, h: float, growth: float = 0.0) -> None:
        """h(p) = h + growth * |p - x|, x of the mesh's dimension (2 values)."""
        with self._handle() as s:
            capi.cvm_sizing_add_point_source_nd(s, x, float(h), float(growth))

    def add_line_source_nd(self, ends: npt.ArrayLike, h: float, growth: float = 0.0) -> None:
        """h(p) = h + growth * distance(p, segment); ends: (2, dim)."""
        with self._handle() as s:
            capi.cvm_sizing_add_line_source_nd(s, ends, float(h), float(growth))

    def add_triangle_source_nd(self, corners: npt.ArrayLike, h: float,
                               growth: float = 0.0) -> None:
        """h(p) = h + growth * distance(p, triangle); corners: (3, dim), dim
        2 or 3 (a sizing holds sources of one dimension)."""
        with self._handle() as s:
            capi.cvm_sizing_add_triangle_source_nd(s, corners, float(h), float(growth))

    def set_background_nd(self, points: npt.ArrayLike, cells: npt.ArrayLike,
                          sizes: npt.ArrayLike) -> None:
        """Sizes at the nodes of a background mesh in 2D (points (n, 2),
        triangles (m, 3)) or 3D (points (n, 3), tetrahedra (m, 4)),
        interpolated linearly inside its cells (no bound outside them)."""
        pts = np.asarray(points, dtype=np.float64)
        if pts.ndim != 2 or pts.shape[1] not in (2, 3):
            raise ValueError("set_background_nd: points must have shape (n, 2) or (n, 3)")
        h = np.asarray(sizes, dtype=np.float64).reshape(-1)
        if h.shape[0] != pts.shape[0]:
            raise ValueError("set_background_nd: %d sizes for %d points"
                             % (h.shape[0], pts.shape[0]))
        xh = np.ascontiguousarray(np.column_stack([pts, h]))
        cl = np.asarray(cells)
        if cl.ndim == 1 and cl.size % (pts.shape[1] + 1) == 0:
            cl = cl.reshape(-1, pts.shape[1] + 1)
        with self._handle() as s:
            capi.cvm_sizing_set_background_nd(s, xh, cl)

    def set_callback_nd(self, callback: Optional[Callable[[npt.NDArray[np.float64]], float]]
                        ) -> None:
        """Use callback(x) -> size, x a float64 array of the mesh's dimension,
        as one more source (replaces a callback(x, y); None removes it)."""
        with self._handle() as s:
            capi.cvm_sizing_set_callback_nd(s, callback)
            self._callback = callback

    def set_metric(self, callback: Optional[Callable[[npt.NDArray[np.float64]], Any]]) -> None:
        """Metric (tensor) source: callback(x) -> (g11, g12, g22), or None to
        refuse the point (None removes the source). No refiner of this version
        uses a metric: Mesh.refine() and optimise_dual() raise UnsupportedError
        with a sizing that has one."""
        with self._handle() as s:
            capi.cvm_sizing_set_metric_fn(s, callback)
            self._metric = callback

    def set_metric_builtin(self, name: Union[str, int], scale: float = 1.0) -> None:
        """Metric source: a built-in field ('identity', 'stretch', 'saddle',
        'sshock', or its number) times scale (1/h^2 gives edges of length h
        where g = I), with exact derivatives; replaces any metric source."""
        names = {"identity": 1, "stretch": 2, "saddle": 3, "sshock": 4}
        kind = names[name.lower()] if isinstance(name, str) else int(name)
        with self._handle() as s:
            capi.cvm_sizing_set_metric_builtin(s, kind, float(scale))
            self._metric = None

    def set_metric_constant(self, g11: float, g12: float, g22: float) -> None:
        """Metric source: the constant tensor (g11, g12, g22); replaces any
        metric source."""
        with self._handle() as s:
            capi.cvm_sizing_set_metric_constant(s, float(g11), float(g12), float(g22))
            self._metric = None

    def eval_nd(self, x: npt.ArrayLike) -> float:
        """The target size at the point x (inf when there is no scalar source)."""
        with self._handle() as s:
            return capi.cvm_sizing_eval_nd(s, x)

    def metric_at(self, x: npt.ArrayLike) -> Tuple[float, float, float]:
        """The metric at x as (g11, g12, g22), checked finite and positive definite."""
        with self._handle() as s:
            return capi.cvm_sizing_eval_metric(3, s, x)

    def set_automatic(self, R: float, G: float = 4.0) -> None:
        """Size from the geometry being refined: local feature size / R (R edges
        per feature, curvature-aware), growing by at most 1/G per unit of
        distance. Built by each Mesh.refine() from its domain; __call__ does
        not see it. R = G = 0 turns it off."""
        with self._handle() as s:
            capi.cvm_sizing_set_automatic(s, float(R), float(G))

    def set_boundary_grading(self, g: float) -> None:
        """Also cap the size by l(e) + g * distance from every boundary or
        constrained edge e of length l(e) of the mesh being refined or
        optimised, so a finely spaced wall grows into the interior at slope g
        (e.g. 0.3). Built by each Mesh.refine() / optimise_dual() from its
        domain; __call__ does not see it. g = 0 turns it off."""
        with self._handle() as s:
            capi.cvm_sizing_set_boundary_grading(s, float(g))

    def set_background(self, points: npt.ArrayLike, triangles: npt.ArrayLike,
                       sizes: npt.ArrayLike) -> None:
        """Sizes at the nodes of a background triangulation, interpolated
        linearly inside its triangles (no bound outside them): points (n, 2),
        triangles (m, 3) 0-based node indices (integers; floats raise
        TypeError, values beyond 32 bits OverflowError), sizes (n,) positive."""
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        h = np.asarray(sizes, dtype=np.float64).reshape(-1)
        if h.shape[0] != pts.shape[0]:
            raise ValueError("set_background: %d sizes for %d points" % (h.shape[0], pts.shape[0]))
        xyh = np.ascontiguousarray(np.column_stack([pts, h]))
        # no cast here: the binding refuses non-integer indices (TypeError) and
        # indices beyond 32 bits (OverflowError), as for segments
        tri = np.asarray(triangles)
        if tri.ndim == 1 and tri.size % 3 == 0:
            tri = tri.reshape(-1, 3)
        with self._handle() as s:
            capi.cvm_sizing_set_background(s, xyh, tri)

    def __call__(self, x: float, y: float) -> float:
        """The target size at (x, y) (inf when there is no source)."""
        with self._handle() as s:
            return capi.cvm_sizing_eval(s, float(x), float(y))
