"""Write a run's log point by point, resumably, never leaving a half-written file.

Design (O(total size), crash-safe, a few hundred microseconds of bookkeeping per point):

* ``log.h5.parts/`` next to ``log.h5`` is the staging folder. ``run.h5`` in it holds the run
  metadata (written atomically, :mod:`rig.logbook.atomic`); ``points.journal`` gets one
  checksummed frame per finished point (the point's measurements and its truth,
  :mod:`rig.logbook.journal`), appended with one write. A point is in the journal exactly when
  its frame is complete; a torn last frame of a killed process is cut off when the run resumes.
  The journal is fsynced at most every FSYNC_INTERVAL_S seconds and before the log is assembled,
  so a power cut costs at most the last moments' points (their frames fail the checksum and are
  simulated again), never a wrong point.
* :meth:`LogWriter.finalize` lays the points out, in index order, as the columnar log
  (:mod:`rig.logbook.columnar`; temporary file + rename over ``log.h5``) and then removes the
  staging folder (``run.h5`` first).
* Opening a writer on a path whose staging folder has ``run.h5`` resumes: the complete frames
  are kept and :attr:`LogWriter.done` tells the caller which point indices to skip. Opening it on
  a path that holds a finished columnar log of the same run (scene, seed, stand, version) and no
  staging folder counts that log's points as done too: :meth:`finalize` then leaves the log as it
  is when nothing new was written, or lays out its points together with the new ones. The
  result equals an uninterrupted run's log, byte for byte.

A process killed at any moment leaves the previous ``log.h5`` (or none) plus a consistent
staging folder. One writer per path at a time: the runner holds the folder's lock
(rig.runner.folder_lock).
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Iterator, Mapping
from pathlib import Path

import h5py

from rig.errors import LogFormatError, ParameterError, RigError
from rig.logbook import atomic, h5format, journal
from rig.logbook import layout as L
from rig.logbook.columnar import ColumnarLog, write_columnar
from rig.logbook.content import PointRecord, Quantity, RunMetadata, quantities
from rig.logbook.opening import as_path, check_format, open_log

RUN_PART = "run.h5"
JOURNAL = "points.journal"
FSYNC_INTERVAL_S = 1.0
"""Longest time [s] between two fsyncs of the journal."""
_SAME_RUN_FIELDS = ("scene_toml", "seed", "stand", "package_version")


def staging_dir(path: Path) -> Path:
    """The staging folder of the log ``path``: ``<path>.parts`` next to it."""
    return path.with_name(path.name + ".parts")


def same_run(given: RunMetadata, stored: RunMetadata) -> str | None:
    """The first field (scene text, seed, stand, version) in which two runs differ, or None."""
    return next((name for name in _SAME_RUN_FIELDS if getattr(given, name) != getattr(stored, name)), None)


class LogWriter:
    """Writes the log ``path`` of one run; resumes an interrupted run of the same scene.

    ``metadata`` describes the run. When resuming, its scene text, seed, stand and package
    version must equal the interrupted run's (else ParameterError); the stored ``created_utc``
    of the first attempt is kept.
    """

    def __init__(self, path: object, metadata: RunMetadata) -> None:
        self.path = as_path("path", path)
        if not isinstance(metadata, RunMetadata):
            raise ParameterError("metadata", metadata, "a RunMetadata")
        if not self.path.parent.is_dir():
            raise ParameterError("path", str(self.path), "a file in an existing folder")
        if self.path.exists() and not self.path.is_file():
            raise ParameterError("path", str(self.path), "a log file, or a name not yet taken",
                                 hint="a folder (or another non-file) of that name is in the way; move it")
        self.parts = staging_dir(self.path)
        self._finalized = False
        for leftover in self.path.parent.glob(f".{self.path.name}.*{atomic.TMP_SUFFIX}"):
            leftover.unlink()  # of a write_reduced killed half-way (never read)
        if (self.parts / RUN_PART).is_file():
            self._remove_leftovers()
            self.metadata = self._resume(metadata)
            self._frames = self._scan_journal()
        else:
            self.parts.mkdir(exist_ok=True)
            self._clear_staging(keep_folder=True)
            with atomic.new_hdf5(self.parts / RUN_PART) as handle:
                h5format.write_metadata(handle, metadata)
            self.metadata = metadata
            self._frames = {}
        self._base = self._finished_points()
        self._end = sum(frame.length for frame in self._frames.values())
        self._synced = time.monotonic()

    @property
    def done(self) -> frozenset[int]:
        """Indices of the points already written (skip these when resuming)."""
        return frozenset(self._frames) | frozenset(self._base)

    def write_point(self, point: PointRecord, truth: Mapping[str, Quantity]) -> None:
        """Store a complete point and the simulation's ``truth`` {name: Quantity} for it."""
        self._check_open()
        if not isinstance(point, PointRecord):
            raise ParameterError("point", point, "a PointRecord")
        truth = quantities("truth", truth)
        if point.index in self.done:
            raise ParameterError("point.index", point.index, "an index not yet written",
                                 hint=f"done: {sorted(self.done)}")
        frame = journal.encode(journal.entry_of(point, truth))
        with atomic.naming(self.parts / JOURNAL), open(self.parts / JOURNAL, "ab", buffering=0) as handle:
            if handle.tell() != self._end:  # the torn frame of a write that failed half-way
                handle.truncate(self._end)
            view = memoryview(frame)
            while view:  # a full disk may take part of the frame before it refuses the rest
                view = view[handle.write(view):]
            if time.monotonic() - self._synced >= FSYNC_INTERVAL_S:
                self._sync(handle)
        self._frames[point.index] = journal.Frame(point.index, self._end, len(frame))
        self._end += len(frame)

    def finalize(self) -> Path:
        """Assemble ``path`` from the journal (atomically), remove the staging folder, return ``path``."""
        self._check_open()
        with atomic.naming(self.parts / JOURNAL), open(self.parts / JOURNAL, "ab") as handle:
            self._sync(handle)
        if self._frames or not self._base:
            with atomic.new_hdf5(self.path, tmp_folder=self.parts) as log:
                with h5py.File(self.parts / RUN_PART, "r") as run:
                    h5format.write_metadata(log, h5format.read_metadata(run))
                write_columnar(log, self._entries)
        self._finalized = True
        self._clear_staging()
        return self.path

    def discard(self) -> None:
        """Remove the staging folder (the points written so far) without touching ``path``: for a
        run that ended in an error a rerun would meet again."""
        self._finalized = True
        self._clear_staging()

    # ------------------------------------------------------------------------- internals

    def _sync(self, handle) -> None:
        handle.flush()
        os.fsync(handle.fileno())
        self._synced = time.monotonic()

    def _entries(self) -> Iterator[journal.Entry]:
        """Every point in index order: the journal's frames and the finished log's points."""
        order = sorted(set(self._frames) | set(self._base))
        with contextlib.ExitStack() as stack:
            handle = stack.enter_context(open(self.parts / JOURNAL, "rb"))
            base = None
            if self._base:
                base = ColumnarLog(stack.enter_context(open_log(self.path)))
                truth = {name: rows for name, rows in base.quantities(None, L.TRUTH_GROUP).items()}
                records = base.records(self._base[k] for k in order if k not in self._frames)
            for index in order:
                if index in self._frames:
                    yield journal.read_frame(handle, self._frames[index])
                    continue
                found, record = next(records)
                if isinstance(record, LogFormatError):
                    raise record
                row = self._base[found]
                values = {n: Quantity(float(v[row]), u) for n, (v, u) in truth.items() if v[row] == v[row]}
                yield journal.entry_of(record, values)

    def _finished_points(self) -> dict[int, int]:
        """{index: row} of the undamaged points of a finished columnar log of this same run at
        ``path`` (else empty). Every point is read (its checksums checked): a damaged point is
        simulated again, and a log damaged as a whole is written anew."""
        if not self.path.is_file():
            return {}
        try:
            with open_log(self.path) as handle:
                if handle.attrs.get(L.ATTR_FORMAT_VERSION) != L.FORMAT_VERSION:
                    return {}
                if same_run(self.metadata, h5format.read_metadata(handle)) is not None:
                    return {}
                log = ColumnarLog(handle)
                log.quantities(None, L.TRUTH_GROUP)  # the truth is laid out again with the points
                good = [int(k) for k, record in log.records() if not isinstance(record, LogFormatError)]
                rows = {int(k): row for row, k in enumerate(log.index)}
        except (LogFormatError, ParameterError):  # a damaged log: written anew
            return {}
        return {k: rows[k] for k in good}

    def _check_open(self) -> None:
        if self._finalized:
            raise RigError(f"{self.path}: the log is finalized; open a new LogWriter to write another run")

    def _clear_staging(self, *, keep_folder: bool = False) -> None:
        """Remove the staging files: ``run.h5`` first (the folder then no longer counts as a
        resumable run, whatever else a kill leaves), then the journal and temporary files."""
        (self.parts / RUN_PART).unlink(missing_ok=True)
        atomic.fsync_dir(self.parts)
        for part in self.parts.iterdir():
            if part.name == JOURNAL or part.name.endswith(atomic.TMP_SUFFIX):
                part.unlink()
        if not keep_folder:
            with contextlib.suppress(OSError):  # a foreign file in it: leave the folder
                self.parts.rmdir()
            atomic.fsync_dir(self.path.parent)

    def _remove_leftovers(self) -> None:
        for leftover in self.parts.glob("*" + atomic.TMP_SUFFIX):
            leftover.unlink()

    def _resume(self, given: RunMetadata) -> RunMetadata:
        run = self.parts / RUN_PART
        try:
            with h5py.File(run, "r") as handle:
                check_format(handle, what="friction-rig staging part")
                stored = h5format.read_metadata(handle)
        except OSError as err:
            raise LogFormatError(f"{run}: damaged staging part ({err}); delete {self.parts} to start over") from None
        differs = same_run(given, stored)
        if differs is not None:
            raise ParameterError(
                f"metadata.{differs}", getattr(given, differs),
                f"{getattr(stored, differs)!r}, as in the interrupted run staged in {self.parts}",
                hint=f"delete {self.parts} to start the run over",
            )
        return stored

    def _scan_journal(self) -> dict[int, journal.Frame]:
        """The complete frames; a torn tail (a killed writer's last frame) is cut off."""
        path = self.parts / JOURNAL
        if not path.is_file():
            return {}
        frames, end = journal.scan(path)
        if end != path.stat().st_size:
            os.truncate(path, end)
        return {frame.index: frame for frame in frames}
