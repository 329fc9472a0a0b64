"""Write an HDF5 file so that a crash leaves either the old file or the complete new one.

The file is written under a temporary name (``*.h5.tmp``) in the target's folder, flushed and
fsynced, then moved over the target with :func:`os.replace` (atomic on POSIX and Windows) and the
folder is fsynced. An exception removes the temporary file; a killed process may leave it behind
(``*.h5.tmp`` files are never read, and the writer removes those in its staging folder).

A write that fails - a full disk, a quota, an I/O error - raises an :class:`OSError` that names
the file being written (the target, not its temporary name) and the cause, and leaves the target
as it was. HDF5 itself never sees the failure: the library writes through a
:class:`FailureProofFile`, which records the first error and accepts the rest of the writes, so
that the library's state stays consistent and the file is closed normally (HDF5 left to handle a
failed write keeps a half-closed file that crashes the process when it exits); the recorded
error is raised once the file is closed and the temporary file removed.
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
import shutil
from collections.abc import Iterator
from pathlib import Path

import h5py

TMP_SUFFIX = ".h5.tmp"
LIBVER = ("v110", "v110")
"""HDF5 file-format features of the files written: those of HDF5 1.10 (2016; every h5py since 2.8
reads them), whose compact chunk indexes keep a dataset's fixed cost small (a log holds about
130 datasets)."""


WRITE_FAILURES = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO)
"""errno values of a write that failed for want of space or through the device (not a permission)."""
MAX_CAUSE_LENGTH = 160
"""Longest cause [characters] quoted from a library's error message."""


def write_error(path: Path, error: BaseException) -> OSError:
    """An OSError naming ``path`` and the cause of ``error`` in one line (errno kept when it has one)."""
    if isinstance(error, OSError) and error.errno is not None and error.strerror:
        return OSError(error.errno, error.strerror, str(path))
    cause = " ".join(str(error).split()) or type(error).__name__
    if len(cause) > MAX_CAUSE_LENGTH:
        cause = cause[:MAX_CAUSE_LENGTH - 3] + "..."
    return OSError(errno.EIO, f"writing failed ({cause})", str(path))


@contextlib.contextmanager
def naming(path: Path) -> Iterator[None]:
    """Give an OSError raised inside the block without a file name (a write, an fsync) the name ``path``."""
    try:
        yield
    except OSError as error:
        if error.filename is not None:
            raise
        raise write_error(path, error) from None


def fsync_file(path: Path) -> None:
    """Force the file's data to disk."""
    fd = os.open(path, os.O_RDWR)
    try:
        with naming(path):
            os.fsync(fd)
    finally:
        os.close(fd)


def fsync_dir(folder: Path) -> None:
    """Force a folder's entries (a rename) to disk; a no-op where folders cannot be opened."""
    if os.name != "posix":
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        with naming(folder):
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

    On an exception inside the block ``tmp`` is removed and ``target`` is untouched; an OSError
    without a file name (a write that found the disk full) or naming ``tmp`` is raised naming ``target``.
    """
    try:
        yield tmp
        fsync_file(tmp)
        os.replace(tmp, target)
    except BaseException as error:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
        if isinstance(error, OSError) and error.filename in (None, str(tmp), tmp):
            raise write_error(target, error) from None
        raise
    fsync_dir(target.parent)


class FailureProofFile:
    """The file HDF5 writes through (h5py's ``fileobj`` driver): a write that fails is recorded in
    :attr:`error` and reported to HDF5 as done, and the writes after it are kept in memory (up to
    OVERLAY_LIMIT bytes, so that what the library reads back is what it wrote) or dropped.
    The file is worthless once :attr:`error` is set; the caller removes it and raises the error."""

    OVERLAY_LIMIT = 64 << 20
    """Bytes [B] of failed writes kept for the library to read back."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.error: OSError | None = None
        self._fd = os.open(path, os.O_RDWR)
        self._pos = 0
        self._size = os.fstat(self._fd).st_size
        self._overlay: list[tuple[int, bytes]] = []
        self._held = 0

    def seek(self, offset: int, whence: int = os.SEEK_SET) -> int:
        base = {os.SEEK_SET: 0, os.SEEK_CUR: self._pos, os.SEEK_END: self._size}[whence]
        self._pos = base + offset
        return self._pos

    def tell(self) -> int:
        return self._pos

    def read(self, size: int) -> bytes:
        data = bytearray(os.pread(self._fd, size, self._pos))
        data.extend(bytes(size - len(data)))  # past the end: zeros, as HDF5's own driver reads
        for offset, blob in self._overlay:
            lo, hi = max(offset, self._pos), min(offset + len(blob), self._pos + size)
            if lo < hi:
                data[lo - self._pos:hi - self._pos] = blob[lo - offset:hi - offset]
        self._pos += size
        return bytes(data)

    def write(self, data) -> int:
        view = memoryview(data).cast("B")
        size, done = view.nbytes, 0
        if self.error is None:
            try:
                while done < size:
                    done += os.pwrite(self._fd, view[done:], self._pos + done)
            except OSError as error:
                self.error = error
        if done < size and self._held + size - done <= self.OVERLAY_LIMIT:
            self._overlay.append((self._pos + done, bytes(view[done:])))
            self._held += size - done
        self._pos += size
        self._size = max(self._size, self._pos)
        return size

    def truncate(self, size: int) -> int:
        if self.error is None:
            try:
                os.ftruncate(self._fd, size)
            except OSError as error:
                self.error = error
        self._size = size
        return size

    def flush(self) -> None:
        """Nothing to do: every write went to the operating system (fsync_file forces it to disk)."""

    def close(self) -> None:
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1


@contextlib.contextmanager
def writing_hdf5(path: Path, name: Path | None = None) -> Iterator[h5py.File]:
    """Yield a new HDF5 file at ``path`` (an existing, empty file: a temporary one) written through
    a :class:`FailureProofFile`; a write that fails (full disk, I/O error), or an HDF5 error
    inside the block, raises an OSError naming ``name`` (default ``path``) and the cause once the
    file is closed. Use it for every HDF5 file this package writes."""
    name = path if name is None else name
    sink = FailureProofFile(path)
    try:
        try:
            with h5py.File(sink, "w", libver=LIBVER) as handle:
                yield handle
        except (OSError, RuntimeError) as error:  # raised by HDF5 (h5py) inside the block
            if sink.error is None and isinstance(error, OSError) and error.filename is not None:
                raise  # about another file (one the block reads)
            raise write_error(name, sink.error or error) from None
        except BaseException:
            if sink.error is not None:
                raise write_error(name, sink.error) from None
            raise
        if sink.error is not None:
            raise write_error(name, sink.error)
    finally:
        sink.close()


@contextlib.contextmanager
def new_hdf5(target: Path, tmp_folder: Path | None = None, *, mode_of: Path | None = None) -> Iterator[h5py.File]:
    """Yield a new, writable HDF5 file that replaces ``target`` atomically when the block ends.

    The temporary file lives in ``tmp_folder`` (default: the target's folder; it must be on the
    same file system); ``mode_of``: a file whose permission bits the new file gets. A write that fails
    (full disk, I/O error), or an HDF5 error inside the block, raises an OSError naming ``target``
    and the cause (:func:`writing_hdf5`); ``target`` is then untouched.
    """
    folder = target.parent if tmp_folder is None else tmp_folder
    with replace_atomically(target, temporary_path(folder, target.name)) as tmp:
        if mode_of is not None:
            shutil.copymode(mode_of, tmp)
        with writing_hdf5(tmp, target) as handle:
            yield handle
