"""Open a log for reading: refuse missing, non-HDF5, truncated and foreign files clearly."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from pathlib import Path

import h5py
import numpy as np

from rig.errors import LogFormatError, ParameterError, RigError
from rig.logbook import layout as L
from rig.logbook.h5format import shown


def as_path(name: str, path: object) -> Path:
    """``path`` as a :class:`Path`, or a ParameterError naming ``name``."""
    if not isinstance(path, str | os.PathLike) or str(path) == "":
        raise ParameterError(name, path, "a file path (str or os.PathLike)")
    return Path(path)


def check_format(handle: h5py.File, *, what: str = "friction-rig log") -> None:
    """Raise LogFormatError unless the root says ``format = friction-rig-log``, a readable version."""
    where = handle.filename
    if L.ATTR_FORMAT not in handle.attrs:
        raise LogFormatError(
            f"{where}: not a {what}: root attribute {L.ATTR_FORMAT!r} is missing "
            f"(expected {L.FORMAT_NAME!r}; a foreign HDF5 file?)"
        )
    name = handle.attrs[L.ATTR_FORMAT]
    if name != L.FORMAT_NAME:
        raise LogFormatError(f"{where}: not a {what}: root attribute 'format' = {shown(name)}, expected {L.FORMAT_NAME!r}")
    version = handle.attrs.get(L.ATTR_FORMAT_VERSION)
    if not isinstance(version, np.integer | int) or int(version) not in L.READABLE_VERSIONS:
        readable = " and ".join(map(str, L.READABLE_VERSIONS))
        raise LogFormatError(
            f"{where}: root attribute 'format_version' = {shown(version)}; this friction-rig reads versions {readable}"
        )


def format_version(handle: h5py.File) -> int:
    """The (checked) format version of an open log."""
    return int(handle.attrs[L.ATTR_FORMAT_VERSION])


def is_columnar(handle: h5py.File) -> bool:
    """True for a columnar log (version 2), False for one group per point (version 1)."""
    return format_version(handle) >= L.COLUMNAR_VERSION


@contextlib.contextmanager
def open_hdf5(path: object, *, what: str = "friction-rig log") -> Iterator[h5py.File]:
    """Open ``path`` read-only after checking it is an HDF5 file of our format.

    Any low-level read error inside the block (a damaged file) becomes a LogFormatError naming
    the file.
    """
    file = as_path("path", path)
    if file.is_dir():
        raise LogFormatError(f"{file}: is a folder, not a log file")
    if not file.is_file():
        raise LogFormatError(f"{file}: no such log file")
    try:
        handle = h5py.File(file, "r")
    except (OSError, RuntimeError, KeyError, ValueError) as err:
        kind = "a truncated or damaged HDF5 file" if _is_hdf5(file) else "not an HDF5 file"
        raise LogFormatError(f"{file}: {kind} ({cause(err)})") from None
    with handle:
        try:
            check_format(handle, what=what)
            yield handle
        except RigError:
            raise
        except DAMAGE as err:  # h5py's errors on damaged bytes: OSError, RuntimeError, KeyError, ...
            raise LogFormatError(f"{file}: damaged HDF5 file, reading failed ({cause(err)})") from None


DAMAGE = (OSError, RuntimeError, KeyError, ValueError, TypeError, IndexError, OverflowError, UnicodeDecodeError,
          AttributeError)
"""What h5py raises on a file whose bytes are damaged (a checksum, a bad object header or heap, a
wrong type or size read from the file); never shown as a traceback by a reader."""
MAX_CAUSE_LENGTH = 160


def cause(error: BaseException) -> str:
    """The library's message of ``error`` on one line, cut to MAX_CAUSE_LENGTH characters."""
    text = f"{type(error).__name__}: {' '.join(str(error).split())}"
    return text if len(text) <= MAX_CAUSE_LENGTH else text[:MAX_CAUSE_LENGTH - 3] + "..."


def _is_hdf5(file: Path) -> bool:
    try:
        return bool(h5py.is_hdf5(file))
    except Exception:  # noqa: BLE001 - a file h5py cannot even probe is not a readable HDF5 file
        return False


def open_log(path: object) -> contextlib.AbstractContextManager[h5py.File]:
    """Open a finished log read-only (see :func:`open_hdf5`)."""
    return open_hdf5(path)
