"""Write an HDF5 file so that a crash leaves either the old file or the complete new one.

The file is written under a temporary name (``*.h5.tmp``) in the target's folder, flushed and
fsynced, then moved over the target with :func:`os.replace` (atomic on POSIX and Windows) and the
folder is fsynced. An exception removes the temporary file; a killed process may leave it behind
(``*.h5.tmp`` files are never read, and the writer removes those in its staging folder).
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Iterator
from pathlib import Path

import h5py

TMP_SUFFIX = ".h5.tmp"
LIBVER = ("v110", "v110")
"""HDF5 file-format features of the files written: those of HDF5 1.10 (2016; every h5py since 2.8
reads them), whose compact chunk indexes keep a dataset's fixed cost small (a log holds about
130 datasets)."""


def fsync_file(path: Path) -> None:
    """Force the file's data to disk."""
    fd = os.open(path, os.O_RDWR)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def fsync_dir(folder: Path) -> None:
    """Force a folder's entries (a rename) to disk; a no-op where folders cannot be opened."""
    if os.name != "posix":
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def temporary_path(folder: Path, stem: str) -> Path:
    """A new, empty, uniquely named ``.<stem>.<pid>-<random>.h5.tmp`` file in ``folder``.

    Created with mode 0o666 less the umask (as an ordinary new file), not mkstemp's 0o600, so
    that the renamed log has the permissions users expect.
    """
    while True:
        path = folder / f".{stem}.{os.getpid()}-{secrets.token_hex(4)}{TMP_SUFFIX}"
        try:
            fd = os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        return path


@contextlib.contextmanager
def replace_atomically(target: Path, tmp: Path) -> Iterator[Path]:
    """Yield ``tmp`` to be written (and closed) by the caller, then move it over ``target``.

    On an exception inside the block ``tmp`` is removed and ``target`` is untouched.
    """
    try:
        yield tmp
        fsync_file(tmp)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
        raise
    fsync_dir(target.parent)


@contextlib.contextmanager
def new_hdf5(target: Path, tmp_folder: Path | None = None) -> Iterator[h5py.File]:
    """Yield a new, writable HDF5 file that replaces ``target`` atomically when the block ends.

    The temporary file lives in ``tmp_folder`` (default: the target's folder; it must be on the
    same file system).
    """
    folder = target.parent if tmp_folder is None else tmp_folder
    with replace_atomically(target, temporary_path(folder, target.name)) as tmp:
        with h5py.File(tmp, "w", libver=LIBVER) as handle:
            yield handle
