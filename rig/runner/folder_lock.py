"""One run folder, one writer: an OS file lock on ``<folder>/rig.lock`` held while a run (or a
reduction) works in the folder.

The lock is the operating system's (``fcntl.flock`` on POSIX, ``msvcrt.locking`` on Windows): it
belongs to the open file, so it goes away with the process that holds it - a killed run never
leaves a stale lock, and the next run simply takes it and resumes. The file holds the pid and
start time of its holder, which the error of a second run quotes; the holder removes it when
it is done (a killed holder leaves the file, unlocked and harmless). A taker checks that the
file it locked is still the one at the path, so removing it never lets two runs in. A second
``rig run`` (or ``rig reduce``) on a locked folder does not wait: it raises
:class:`FolderLockedError` at once.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from pathlib import Path

from rig.errors import ParameterError, RigError
from rig.logbook import utc_timestamp

LOCK_NAME = "rig.lock"

if os.name == "posix":
    import fcntl

    def _try_lock(fd: int) -> bool:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
        return True
else:  # pragma: no cover - Windows
    import msvcrt

    def _try_lock(fd: int) -> bool:
        try:
            msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
        except OSError:
            return False
        return True


class FolderLockedError(RigError):
    """Another process holds the folder's lock (message: the folder, the holder's pid and start)."""


@contextlib.contextmanager
def folder_lock(folder: Path, what: str) -> Iterator[Path]:
    """Hold the lock of ``folder`` (created if needed) for the block; ``what`` says who holds it
    (e.g. ``"rig run fig10"``). Raises FolderLockedError naming the holder if another process has it."""
    folder = Path(folder)
    path = folder / LOCK_NAME
    while True:
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
        except OSError as error:
            raise ParameterError("output folder", str(folder), "a folder this user can write",
                                 hint=error.strerror or str(error)) from None
        try:
            locked = _try_lock(fd)
        except OSError as error:  # e.g. a file system without locks
            os.close(fd)
            raise RigError(f"{folder}: cannot lock {LOCK_NAME} ({error}); use a folder on a local file system") from None
        if not locked:
            holder = os.pread(fd, 4096, 0).decode("utf-8", "replace").strip() or "another process"
            os.close(fd)
            raise FolderLockedError(f"{folder} is in use by {holder}; wait for it to finish or stop it, "
                                    "or choose another output folder")
        if _same_file(fd, path):  # not a file its last holder removed meanwhile
            break
        os.close(fd)
    try:
        with contextlib.suppress(OSError):  # who holds it: only quoted (a full disk may refuse it)
            os.ftruncate(fd, 0)
            os.pwrite(fd, f"process {os.getpid()} ({what}, started {utc_timestamp()})\n".encode(), 0)
        yield path
    finally:
        with contextlib.suppress(OSError):
            path.unlink()  # before the lock goes: a run waiting on this file retries on a new one
        os.close(fd)  # releases the lock


def _same_file(fd: int, path: Path) -> bool:
    try:
        return os.path.samestat(os.fstat(fd), os.stat(path))
    except FileNotFoundError:
        return False
