"""Write a run's log point by point, resumably, never leaving a half-written file.

Design (O(total size), crash-safe):

* ``log.h5.parts/`` next to ``log.h5`` is the staging folder. ``run.h5`` in it holds the run
  metadata; each finished point is its own small file ``point_NNNNNN.h5`` (the point's
  measurements and its truth), written under a temporary name, fsynced and renamed
  (:mod:`rig.logbook.atomic`). A part therefore exists only when its point is complete.
* :meth:`LogWriter.finalize` copies the parts, in index order, into a new log (again temporary
  file + rename over ``log.h5``) and then removes the staging folder.
* Opening a writer on a path whose staging folder exists resumes: complete parts are kept,
  temporary leftovers of a killed process are removed, and :attr:`LogWriter.done` tells the
  caller which point indices to skip. The resumed log equals an uninterrupted one.

A process killed at any moment leaves the previous ``log.h5`` (or none) plus a consistent
staging folder. Two writers on the same path at the same time are not supported.
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Mapping
from pathlib import Path

import h5py

from rig.errors import LogFormatError, ParameterError, RigError
from rig.logbook import atomic, h5format
from rig.logbook import layout as L
from rig.logbook.content import PointRecord, Quantity, RunMetadata, quantities
from rig.logbook.opening import as_path, check_format
from rig.logbook.truth import write_truth

RUN_PART = "run.h5"
_PART_NAME = re.compile(r"point_(\d{6})\.h5")
_SAME_RUN_FIELDS = ("scene_toml", "seed", "stand", "package_version")


def staging_dir(path: Path) -> Path:
    """The staging folder of the log ``path``: ``<path>.parts`` next to it."""
    return path.with_name(path.name + ".parts")


def _part_path(folder: Path, index: int) -> Path:
    return folder / f"{L.point_group_name(index)}.h5"


def _copy_part(part: h5py.File, log: h5py.File, index: int) -> None:
    """Copy one part's point and truth groups into the log being assembled."""
    name = L.point_group_name(index)
    for container in (L.POINTS_GROUP, L.TRUTH_GROUP):
        part.copy(part[f"{container}/{name}"], log[container], name=name)


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
        self.parts = staging_dir(self.path)
        self._finalized = False
        if (self.parts / RUN_PART).is_file():
            self._remove_leftovers()
            self.metadata = self._resume(metadata)
            self._done = self._scan_parts()
        else:
            self.parts.mkdir(exist_ok=True)
            self._clear_staging(keep_folder=True)
            with atomic.new_hdf5(self.parts / RUN_PART) as handle:
                h5format.write_metadata(handle, metadata)
            self.metadata = metadata
            self._done = set()

    @property
    def done(self) -> frozenset[int]:
        """Indices of the points already written (skip these when resuming)."""
        return frozenset(self._done)

    def write_point(self, point: PointRecord, truth: Mapping[str, Quantity]) -> None:
        """Store a complete point and the simulation's ``truth`` {name: Quantity} for it."""
        self._check_open()
        if not isinstance(point, PointRecord):
            raise ParameterError("point", point, "a PointRecord")
        truth = quantities("truth", truth)
        if point.index in self._done:
            raise ParameterError("point.index", point.index, "an index not yet written",
                                 hint=f"done: {sorted(self._done)}")
        with atomic.new_hdf5(_part_path(self.parts, point.index)) as handle:
            h5format.write_point(handle.create_group(L.POINTS_GROUP), point)
            write_truth(handle, point.index, truth)
        self._done.add(point.index)

    def finalize(self) -> Path:
        """Assemble ``path`` from the parts (atomically), remove the staging folder, return ``path``."""
        self._check_open()
        with atomic.new_hdf5(self.path, tmp_folder=self.parts) as log:
            with h5py.File(self.parts / RUN_PART, "r") as run:
                h5format.write_metadata(log, h5format.read_metadata(run))
            log.create_group(L.POINTS_GROUP)
            log.create_group(L.TRUTH_GROUP)
            for index in sorted(self._done):
                with h5py.File(_part_path(self.parts, index), "r") as part:
                    _copy_part(part, log, index)
        self._finalized = True
        self._clear_staging()
        return self.path

    def discard(self) -> None:
        """Remove the staging folder (the points written so far) without touching ``path``: for a
        run that ended in an error a rerun would meet again."""
        self._finalized = True
        self._clear_staging()

    # ------------------------------------------------------------------------- internals

    def _check_open(self) -> None:
        if self._finalized:
            raise RigError(f"{self.path}: the log is finalized; open a new LogWriter to write another run")

    def _clear_staging(self, *, keep_folder: bool = False) -> None:
        """Remove the staging files: ``run.h5`` first (the folder then no longer counts as a
        resumable run, whatever else a kill leaves), then parts and temporary files."""
        (self.parts / RUN_PART).unlink(missing_ok=True)
        atomic.fsync_dir(self.parts)
        for part in self.parts.iterdir():
            if _PART_NAME.fullmatch(part.name) or part.name.endswith(atomic.TMP_SUFFIX):
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
        for name in _SAME_RUN_FIELDS:
            if getattr(given, name) != getattr(stored, name):
                shown = getattr(stored, name)
                raise ParameterError(
                    f"metadata.{name}", getattr(given, name),
                    f"{shown!r}, as in the interrupted run staged in {self.parts}",
                    hint=f"delete {self.parts} to start the run over",
                )
        return stored

    def _scan_parts(self) -> set[int]:
        done = set()
        for part in self.parts.iterdir():
            match = _PART_NAME.fullmatch(part.name)
            if match is None:
                continue
            index = int(match.group(1))
            name = L.point_group_name(index)
            try:
                with h5py.File(part, "r") as handle:
                    complete = f"{L.POINTS_GROUP}/{name}" in handle and f"{L.TRUTH_GROUP}/{name}" in handle
            except OSError as err:
                raise LogFormatError(f"{part}: damaged part ({err}); delete it to rewrite point {index}") from None
            if not complete:
                raise LogFormatError(f"{part}: part without point {index} or its truth; delete it to rewrite the point")
            done.add(index)
        return done
