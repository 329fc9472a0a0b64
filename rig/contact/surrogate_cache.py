"""On-disk cache of surrogate tables (rig.contact.surrogate): one .npz file per input set.

Folder: ``$RIG_CACHE_DIR`` if set, else ``~/.cache/friction-rig``. File name and stored key are
the SHA-256 of every input of the table plus the package version and the table format version
(TableInputs.key), so a change of any of them is a cache miss, never a stale table.

A damaged cache file (unreadable, truncated, wrong key or shapes) is **rebuilt**, not an error:
the cache holds derived data only, and rebuilding gives the same table as a first build. The
caller learns it from the returned :class:`CacheOutcome` (status REBUILT and the reason), and
the module logs it at WARNING level (logging, not ``warnings``). Loading a named file directly
with :func:`load_table` raises :class:`TableFileError` instead. Files are written atomically
(temporary file + rename), so parallel runs that build the same table do not corrupt it.
"""

from __future__ import annotations

import enum
import json
import logging
import os
import sys
import tempfile
import threading
import zipfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from tqdm import tqdm

from rig.contact.surrogate import TABLE_FORMAT, SurrogateTable, TableInputs, build_table
from rig.errors import RigError

log = logging.getLogger(__name__)
ENV_VARIABLE = "RIG_CACHE_DIR"


class TableFileError(RigError, ValueError):
    """A surrogate-table file is damaged or belongs to other inputs: names the file and the fault."""


class CacheStatus(enum.Enum):
    """HIT: loaded from disk; BUILT: not cached, built and saved; REBUILT: the cached file was
    damaged (see CacheOutcome.reason), built again and replaced."""

    HIT = "hit"
    BUILT = "built"
    REBUILT = "rebuilt"


@dataclass(frozen=True)
class CacheOutcome:
    """What load_or_build did: status, the file, and why a file was rebuilt ("" otherwise)."""

    status: CacheStatus
    path: Path
    reason: str = ""


def cache_dir() -> Path:
    """The cache folder: $RIG_CACHE_DIR, else ~/.cache/friction-rig (not created here)."""
    value = os.environ.get(ENV_VARIABLE, "")
    return Path(value).expanduser() if value else Path.home() / ".cache" / "friction-rig"


def table_path(inputs: TableInputs, directory: Path | None = None) -> Path:
    """Cache file of the table for ``inputs`` in ``directory`` (default :func:`cache_dir`)."""
    folder = cache_dir() if directory is None else Path(directory)
    return folder / f"surrogate-{inputs.model}-{inputs.key()}.npz"


def save_table(table: SurrogateTable, path: Path) -> None:
    """Write ``table`` to ``path`` (.npz) atomically, with its inputs, key and format version."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    arrays = dict(
        values=table.values,
        has_sliding=np.array(table.sliding is not None),
        sliding=np.zeros((0,)) if table.sliding is None else table.sliding,
        key=np.array(table.inputs.key()),
        description=np.array(json.dumps(table.inputs.description(), sort_keys=True)),
        table_format=np.array(TABLE_FORMAT),
    )
    handle, temporary = tempfile.mkstemp(prefix=path.name, suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(handle, "wb") as stream:
            np.savez(stream, **arrays)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def load_table(path: Path, inputs: TableInputs) -> SurrogateTable:
    """Read the table for ``inputs`` from ``path``; TableFileError if damaged or for other inputs."""
    path = Path(path)
    try:
        with open(path, "rb") as stream, np.load(stream, allow_pickle=False) as data:  # we close the file
            fmt = int(data["table_format"])
            key = str(data["key"])
            values = np.array(data["values"], dtype=float)
            sliding = np.array(data["sliding"], dtype=float) if bool(data["has_sliding"]) else None
    except (OSError, EOFError, KeyError, ValueError, TypeError, zipfile.BadZipFile) as error:
        raise TableFileError(f"{path}: not a readable surrogate table ({type(error).__name__}: {error})") from None
    if fmt != TABLE_FORMAT:
        raise TableFileError(f"{path}: table format {fmt}, expected {TABLE_FORMAT}")
    if key != inputs.key():
        raise TableFileError(f"{path}: stored key {key[:12]}... belongs to other inputs than {inputs.key()[:12]}...")
    shape = tuple(inputs.points) + (3,)
    if values.shape != shape or (sliding is not None and sliding.shape != shape[:2] + (3,)):
        raise TableFileError(f"{path}: arrays of shape {values.shape}, expected {shape}")
    if not np.all(np.isfinite(values)) or (sliding is not None and not np.all(np.isfinite(sliding))):
        raise TableFileError(f"{path}: non-finite table values")
    return SurrogateTable(inputs, values, sliding)


def load_or_build(
    inputs: TableInputs,
    *,
    directory: Path | None = None,
    progress: Callable[[int, int], None] | None = None,
    workers: int = 1,
) -> tuple[SurrogateTable, CacheOutcome]:
    """The table for ``inputs`` from the cache, or built (build_table) and saved there.

    Threads of one process that ask for the same table at once build it once: the others wait
    and load it (rig lab prepares its exercises' tables in a thread while a student's first
    request may ask for the same one). Separate processes may each build it; the file is written
    atomically either way.
    """
    path = table_path(inputs, directory)
    with _building(path):
        return _load_or_build(inputs, path, progress, workers)


_LOCKS_GUARD = threading.Lock()
_LOCKS: dict[str, threading.Lock] = {}


def _building(path: Path) -> threading.Lock:
    """The lock held while the table of cache file ``path`` is loaded or built in this process."""
    with _LOCKS_GUARD:
        return _LOCKS.setdefault(str(Path(path).resolve()), threading.Lock())


def _load_or_build(inputs: TableInputs, path: Path, progress: Callable[[int, int], None] | None,
                   workers: int) -> tuple[SurrogateTable, CacheOutcome]:
    reason = ""
    if path.exists():
        try:
            return load_table(path, inputs), CacheOutcome(CacheStatus.HIT, path)
        except TableFileError as error:
            reason = str(error)
            log.warning("rebuilding the surrogate table: %s", reason)
    if progress is None:  # a build may take minutes: a progress line on a terminal (stderr), after 2 s
        with tqdm(total=int(np.prod(inputs.points)), desc="surrogate table", unit="node", delay=2.0, leave=False,
                  disable=not sys.stderr.isatty()) as bar:
            table = build_table(inputs, progress=lambda done, _: bar.update(done - bar.n), workers=workers)
    else:
        table = build_table(inputs, progress=progress, workers=workers)
    save_table(table, path)
    return table, CacheOutcome(CacheStatus.REBUILT if reason else CacheStatus.BUILT, path, reason)
