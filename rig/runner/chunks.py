"""Chunks of a study: consecutive points simulated, logged as a shard and reduced where they run.

A worker (a process of the local pool, a thread of a Dask worker, or this process) takes a chunk
of consecutive planned points, runs the operator over them (rig.runner.operator) with its stand -
built and calibrated once per worker and run, the calibration a pure function of the run seed -
writes the finished points as a shard (rig.logbook.shards: a complete columnar log of the chunk,
in a temporary file of the worker's machine) and reduces that shard with the stand's own
``reduce_log`` (the reduction of a point depends only on that point's record, so a chunk's rows are
the rows the whole log's reduction gives). It returns a :class:`ChunkResult`: the shard's bytes, the
reduced rows (also as lines of reduced.csv), the points that did not settle, an error. The parent
only stores the shard, keeps the rows and, at the end, merges the shards into ``log.h5``: its work
per point is a few copies, not a simulation, a reduction or the formatting of numbers. A task may
also be the reduction of a shard an interrupted run left (:class:`ReduceTask`), so that a resumed
run reduces those points on the workers too.

Each point's truth gets one entry from the operator: ``operator_settle_time`` [s], the simulated
time the point took to settle as ``settle`` reported it.
"""

from __future__ import annotations

import os
import tempfile
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from rig.errors import ParameterError
from rig.logbook import Quantity, RunMetadata
from rig.logbook import journal
from rig.logbook.content import PointRecord, quantities
from rig.logbook.shards import LogColumns, read_columns, write_shard
from rig.runner.operator import PointResult, run_operator
from rig.runner.pool import PointFailure
from rig.scenes.procedure import PlannedPoint, TimeoutPolicy
from rig.scenes.stand_scene import StandScene
from rig.stands.base import Stand

SETTLE_TRUTH = "operator_settle_time"
"""Truth entry the operator adds to every point: settle time [s]."""

MAX_CHUNK = 2048
"""Most points in one chunk [1]: a shard of ~4 MB, about 10 s of a worker's time (a killed run loses
at most that much per worker; the parent's cost of a shard, storing and merging it, is a few tens
of ms whatever its size). Larger chunks pay the fixed cost of a chunk (MIN_TAIL_CHUNK) less often:
a 10 000-point study on two workers ran about 6 % faster with 2 048 than with 512 (docs/scaling.md)."""

CHUNKS_PER_WORKER = 4
"""Chunks per worker [1] before the last, shrinking ones (chunk_sizes) share out the rest."""


def logged_truth(finished: PointResult) -> Mapping[str, Quantity]:
    """The truth a finished point is logged with: the stand's and the operator's settle time [s]."""
    truth = dict(finished.outcome.truth)
    if SETTLE_TRUTH in truth:
        raise ParameterError("truth", SETTLE_TRUTH, "a name other than the operator's own entry")
    truth[SETTLE_TRUTH] = Quantity(finished.settle.duration_s, "s")
    return quantities("truth", truth)


MIN_TAIL_CHUNK = 96
"""Fewest points in one of the last, shrinking chunks [1]: a chunk costs a worker about 0.1 s of
CPU beyond its points (its shard written and read back, the reduction's set-up), as much as
some 20 points of the default scene, so a chunk of the minimum spends about a sixth of its time on it."""


def chunk_size(points: int, workers: int) -> int:
    """Points per chunk: about CHUNKS_PER_WORKER chunks per worker, 1 to MAX_CHUNK points each."""
    return max(1, min(MAX_CHUNK, -(-points // (max(1, workers) * CHUNKS_PER_WORKER))))


def chunk_sizes(points: int, workers: int) -> list[int]:
    """Points of each chunk in plan order: chunk_size(points, workers) each, then, once fewer than
    two such chunks per worker are left, shrinking chunks (half a worker's share of what is left,
    at least MIN_TAIL_CHUNK points), so that the workers finish nearly together: the last chunk of
    one worker is no longer a full chunk of time while the other workers idle."""
    workers, first = max(1, workers), chunk_size(points, workers)
    sizes, left = [], points
    while left > 0:
        size = min(left, first, max(MIN_TAIL_CHUNK, -(-left // (2 * workers))))
        sizes.append(size)
        left -= size
    return sizes


@dataclass(frozen=True)
class SimulateTask:
    """Simulate, log and (if ``reduce``) reduce ``points`` (consecutive in the plan) of the run ``metadata``."""

    points: tuple[PlannedPoint, ...]
    metadata: RunMetadata
    reduce: bool


@dataclass(frozen=True)
class ReduceTask:
    """Reduce the shard ``data`` (the bytes of a shard file) an earlier attempt of the run left."""

    first: int
    data: bytes


@dataclass(frozen=True)
class ChunkResult:
    """What a worker sends back for a task.

    written: indices logged in the shard; failures: (index, settings, message) of the points that
    did not settle; stopped: a point did not settle under the STOP policy (the chunk ends there);
    error: a point raised (the chunk ends there); shard: the shard file's bytes (None: no point
    written, or a ReduceTask) and columns, its per-point columns (rig.logbook.shards.read_columns,
    read here so that the parent's merge need not); table: the reduced rows (None when not
    reduced), with each point's ``z_max`` (rig.runner.off_truth.with_z_max); cpu_s: the worker's
    CPU time for the task [s]; rows: those rows as lines of reduced.csv
    (rig.runner.reduction.csv_rows), formatted here so that the parent need not.
    """

    first: int
    written: tuple[int, ...]
    failures: tuple[tuple[int, dict, str], ...]
    stopped: bool
    error: PointFailure | None
    shard: bytes | None
    table: pd.DataFrame | None
    cpu_s: float
    columns: LogColumns | None = None
    rows: str | None = None


def run_task(stand: Stand, scene: StandScene, task: SimulateTask | ReduceTask) -> ChunkResult:
    """Do ``task`` with this worker's calibrated ``stand``; any error of a point comes back in the result."""
    start = time.process_time()
    if isinstance(task, ReduceTask):
        with _scratch() as path:
            path.write_bytes(task.data)
            table, rows = _reduce(stand, scene, path)
        return ChunkResult(task.first, (), (), False, None, None, table, time.process_time() - start, rows=rows)
    finished: list[PointResult] = []
    error = None
    try:
        run_operator(stand, task.points, scene.procedure, scene.seed, finished.append)
    except Exception as raised:  # noqa: BLE001 - sent back whole, raised in the parent in point order
        error = PointFailure.of(task.points[len(finished)], raised)
    entries, failures = [], []
    for result in finished:
        if result.outcome is None:
            failures.append((result.point.index, dict(result.point.settings), result.failure or ""))
            continue
        try:
            if not isinstance(result.outcome.record, PointRecord):
                raise ParameterError("point", result.outcome.record, "a PointRecord")
            entries.append(journal.entry_of(result.outcome.record, logged_truth(result)))
        except Exception as raised:  # noqa: BLE001 - as a serial run's writer would raise it
            error = PointFailure.of(result.point, raised)
            break
    stopped = error is None and _stops(scene) and bool(finished) and finished[-1].outcome is None
    shard = table = columns = rows = None
    if entries:  # the points before an error too: a rerun resumes after them
        with _scratch() as path:
            write_shard(path, task.metadata, entries)
            if task.reduce and error is None:
                table, rows = _reduce(stand, scene, path)
            shard, columns = path.read_bytes(), read_columns(path)
    return ChunkResult(task.points[0].index, tuple(e.index for e in entries), tuple(failures), stopped, error,
                       shard, table, time.process_time() - start, columns, rows)


def failed(task: SimulateTask | ReduceTask, error: Exception) -> ChunkResult:
    """The result of a task that could not start (the stand failed to build or calibrate, another
    version): ``error`` at the task's first point."""
    point = task.points[0] if isinstance(task, SimulateTask) else PlannedPoint(task.first, {}, None, 0)
    return ChunkResult(point.index, (), (), False, PointFailure.of(point, error), None, None, 0.0)


def _stops(scene: StandScene) -> bool:
    return scene.procedure.on_settle_timeout is TimeoutPolicy.STOP


def _reduce(stand: Stand, scene: StandScene, path: Path) -> tuple[pd.DataFrame, str | None]:
    """The shard's reduced table with each point's z_max, and its rows as lines of reduced.csv."""
    from rig.runner.off_truth import with_z_max
    from rig.runner.reduction import csv_rows, reduce_table

    table = with_z_max(reduce_table(stand, path, scene.contact))
    return table, csv_rows(table)


class _scratch:
    """A temporary ``.h5`` file on this machine for the block (removed after it)."""

    def __enter__(self) -> Path:
        fd, name = tempfile.mkstemp(prefix="rig-shard-", suffix=".h5")
        os.close(fd)
        self.path = Path(name)
        return self.path

    def __exit__(self, *exc) -> None:
        self.path.unlink(missing_ok=True)


def simulate_tasks(points: Sequence[PlannedPoint], metadata: RunMetadata, reduce: bool,
                   workers: int) -> list[SimulateTask]:
    """``points`` (in plan order) cut into chunks for ``workers`` workers (chunk_sizes)."""
    tasks, start = [], 0
    for size in chunk_sizes(len(points), workers):
        tasks.append(SimulateTask(tuple(points[start:start + size]), metadata, reduce))
        start += size
    return tasks
