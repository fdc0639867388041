"""Exceptions of cvmesh: one base class, one subclass per status family.

The C layer (cvmesh.i) turns every error status into an instance made by
_from_status(), carrying the library's message (cvm_mesh_errmsg), the status
code and the input item the message names.
"""

from __future__ import annotations

from typing import Type


class Error(Exception):
    """Base class of every error reported by the cvmesh library.

    Attributes:
        message: the library's message, naming the offending input.
        status: the cvm_status code (an int; see cvmesh.Status).
        item_kind: the kind of entity the message names (see cvmesh.Entity),
            0 when none.
        item_index: its 0-based index (a file line is 1-based), -1 when none.
    """

    def __init__(self, message: str, status: int = 0, item_kind: int = 0,
                 item_index: int = -1) -> None:
        super().__init__(message)
        self.message = message
        self.status = status
        self.item_kind = item_kind
        self.item_index = item_index

    @property
    def status_name(self) -> str:
        """Name of the status code, e.g. 'E_INPUT_INDEX'."""
        from . import Status  # late: the enum is built from the compiled module
        try:
            return Status(self.status).name
        except ValueError:
            return str(self.status)

    def __str__(self) -> str:
        return self.message


class ArgumentError(Error, ValueError):
    """A NULL or out-of-domain argument, or a buffer that is too small."""


class OptionError(Error, ValueError):
    """Unknown option key, or a value outside the option's bounds."""


class InputError(Error, ValueError):
    """Bad input: non-finite coordinate, bad index, duplicate, degenerate,
    intersecting or open geometry, empty input, too large."""


class StateError(Error, RuntimeError):
    """A call made in the wrong order (e.g. insert_points before triangulate)."""


class UnsupportedError(Error, NotImplementedError):
    """A feature not available in this build or version."""


class FileError(Error, OSError):
    """A file could not be opened, read, written or parsed."""


class NoMemoryError(Error, MemoryError):
    """The library ran out of memory; the mesh stays usable."""


class InternalError(Error, RuntimeError):
    """An internal consistency check failed: a bug, please report it."""


class IncompleteWarning(UserWarning):
    """A long call stopped early (time limit, Steiner limit, cancellation);
    its result is valid but incomplete."""


# Status families (STYLE.md section 4); codes outside every range map to Error.
_FAMILIES = (
    (1, 2, ArgumentError),      # CVM_E_NULL_ARG, CVM_E_ARGUMENT
    (3, 4, OptionError),        # CVM_E_OPTION_KEY, CVM_E_OPTION_RANGE
    (5, 5, StateError),         # CVM_E_STATE
    (6, 6, UnsupportedError),   # CVM_E_UNSUPPORTED
    (10, 29, InputError),       # CVM_E_INPUT_*
    (30, 39, FileError),        # CVM_E_IO_*
    (40, 40, NoMemoryError),    # CVM_E_NOMEM
    (41, 41, ArgumentError),    # CVM_E_BUFFER_TOO_SMALL
    (42, 42, InputError),       # CVM_E_TOO_LARGE
    (99, 99, InternalError),    # CVM_E_INTERNAL
)


for _cls in (Error, ArgumentError, OptionError, InputError, StateError, UnsupportedError,
             FileError, NoMemoryError, InternalError, IncompleteWarning):
    _cls.__module__ = "cvmesh"  # shown as cvmesh.InputError in tracebacks
del _cls


def error_class(status: int) -> Type[Error]:
    """The exception class for an error status code."""
    for lo, hi, cls in _FAMILIES:
        if lo <= status <= hi:
            return cls
    return Error


def _from_status(status: int, message: str, item_kind: int, item_index: int) -> Error:
    """Called from C: the exception instance for an error status."""
    return error_class(status)(message, status, item_kind, item_index)
