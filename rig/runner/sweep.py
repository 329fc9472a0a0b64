"""The sweep: run the planned points that are not yet in the log, logging each as it finishes.

:func:`run_sweep` runs the operator in this process on one simpy clock and writes every point
into the log's journal (rig.logbook.LogWriter: points already in an interrupted run's staging
folder are skipped, and since every point is simulated from its own arguments the resumed log
equals an uninterrupted one). :func:`run_sharded_sweep` runs chunks of points on a local process
pool (rig.runner.pool), a Dask cluster (rig.runner.dask_pool) or this process
(rig.runner.chunks), storing each chunk's shard as it arrives, in point order. A tqdm progress
bar counts the points; it is silent when stderr is not a terminal (or when ``progress`` is
False).

Each point's truth gets one entry from the operator: ``operator_settle_time`` [s], the
simulated time the point took to settle as ``settle`` reported it (read back for the summary,
also after a resume).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd
from tqdm import tqdm

from rig.logbook import LogWriter, RunMetadata
from rig.logbook.shards import LogColumns, Shard, store_shard
from rig.runner.chunks import SETTLE_TRUTH, ChunkResult, ReduceTask, logged_truth, run_task, simulate_tasks
from rig.runner.dask_pool import run_dask_tasks
from rig.runner.figures import import_in_background
from rig.runner.operator import PointResult, run_operator
from rig.runner.pool import run_pool_tasks
from rig.runner.reduction import FormattedRows
from rig.scenes.procedure import PlannedPoint, TimeoutPolicy
from rig.scenes.stand_scene import StandScene
from rig.stands.base import Stand

__all__ = ["SETTLE_TRUTH", "Failure", "ShardedSweep", "SweepResult", "run_sharded_sweep", "run_sweep", "show_progress"]



@dataclass(frozen=True)
class Failure:
    """A point that did not settle: its index, settings {name: value} and the error message."""

    index: int
    settings: dict[str, float]
    message: str


@dataclass
class SweepResult:
    """What this invocation simulated: indices written, failures, whether the run stopped early,
    and the operator time [s] of the serial clock (None with a process pool or a Dask cluster)."""

    written: list[int] = field(default_factory=list)
    failures: list[Failure] = field(default_factory=list)
    stopped: bool = False
    operator_time_s: float | None = None


def show_progress(progress: bool | None) -> bool:
    """Progress bar on? ``None``: only when stderr is a terminal."""
    return sys.stderr.isatty() if progress is None else bool(progress)


def run_sweep(scene: StandScene, stand: Stand, points: Sequence[PlannedPoint], writer: LogWriter, *,
              progress: bool | None) -> SweepResult:
    """Simulate ``points`` in this process with the calibrated ``stand`` on one simpy clock and
    write each finished one into ``writer`` (its journal: resumable point by point)."""
    result = SweepResult()
    with tqdm(total=len(points), desc=f"scene {scene.name}", unit="point", disable=not show_progress(progress),
              file=sys.stderr) as bar:

        def deliver(finished: PointResult) -> None:
            point = finished.point
            if finished.outcome is None:
                result.failures.append(Failure(point.index, dict(point.settings), finished.failure or ""))
                result.stopped = scene.procedure.on_settle_timeout is TimeoutPolicy.STOP
            else:
                writer.write_point(finished.outcome.record, logged_truth(finished))
                result.written.append(point.index)
            bar.update(1)

        result.operator_time_s = run_operator(stand, points, scene.procedure, scene.seed, deliver)
    return result


@dataclass
class ShardedSweep(SweepResult):
    """A sweep whose points were logged in shards (rig.runner.chunks): besides SweepResult's facts,
    the shards stored now and the reduced rows by the first point index of their shard (of the
    shards stored now and of those an earlier attempt left), the per-point columns of the shards
    stored now (by the same key), the point that stopped the sweep, the workers' CPU time [s] and
    the reduced rows as lines of reduced.csv gathered in point order (None: not gathered, or not
    every chunk's)."""

    stored: list[Shard] = field(default_factory=list)
    tables: dict[int, pd.DataFrame] = field(default_factory=dict)
    columns: dict[int, LogColumns] = field(default_factory=dict)
    stopped_at: int | None = None
    workers_cpu_s: float = 0.0
    rows: FormattedRows | None = None


class _RowsGatherer:
    """Appends each chunk's rows (ChunkResult.rows) to ``path`` as the chunks arrive; gives up (and
    removes the file) at a chunk without rows, with other columns, or out of point order."""

    def __init__(self, path: Path) -> None:
        self.path, self.columns, self.last = path, None, -1
        self.handle = open(path, "wb")  # noqa: SIM115 - closed by result()

    def add(self, first: int, table: pd.DataFrame, rows: str | None) -> None:
        if self.handle is None:
            return
        if rows is None or first <= self.last or self.columns not in (None, tuple(table.columns)):
            self.result()
            self.path.unlink(missing_ok=True)
            return
        self.handle.write(rows.encode())
        self.columns, self.last = tuple(table.columns), int(table.index[-1])

    def result(self) -> FormattedRows | None:
        """The gathered rows (the file closed); None when given up or empty."""
        if self.handle is None:
            return None
        self.handle.close()
        self.handle = None
        return None if self.columns is None else FormattedRows(self.path, self.columns)


def run_sharded_sweep(scene: StandScene, stand: Stand, points: Sequence[PlannedPoint], earlier: Sequence[Shard],
                      folder, metadata: RunMetadata, *, jobs: int, progress: bool | None,
                      scheduler: str | None = None, rows: Path | None = None) -> ShardedSweep:
    """Simulate, log and reduce ``points`` in chunks on the workers (``jobs`` processes, the Dask
    scheduler at ``scheduler``, or this process with ``stand`` when ``jobs`` is 1), storing each
    chunk's shard in ``folder`` as its result arrives (in plan order); the shards ``earlier`` (of an
    interrupted attempt) are reduced on the workers too when the scene reduces. A point's error is
    raised as a serial run raises it, after the chunks before it are stored. ``rows``: a file to
    gather the chunks' rows into as lines of reduced.csv (when there are no ``earlier`` shards: the
    chunks then arrive in point order)."""
    result = ShardedSweep()
    reduce = scene.outputs.reduce
    earlier_tasks = [ReduceTask(shard.indices[0], shard.path.read_bytes()) for shard in earlier] if reduce else []

    def make_tasks(workers: int) -> list:
        return [*earlier_tasks, *simulate_tasks(points, metadata, reduce, workers)]

    preload = scene.outputs.figures and (scheduler is not None or jobs > 1)  # this process only waits meanwhile
    importing: list = []
    gatherer = _RowsGatherer(rows) if rows is not None and reduce and not earlier else None
    with tqdm(total=len(points), desc=f"scene {scene.name}", unit="point", disable=not show_progress(progress),
              file=sys.stderr) as bar:

        def deliver(done: ChunkResult) -> bool:
            if preload and not importing:  # at the first result: the workers are up, this process waits
                importing.append(import_in_background())
            result.workers_cpu_s += done.cpu_s
            if done.shard is not None:
                path = store_shard(folder, done.written[0], done.written[-1], done.shard)
                result.stored.append(Shard(path, done.written))
                result.written.extend(done.written)
                if done.columns is not None:
                    result.columns[done.written[0]] = done.columns
            if done.error is not None:
                raise done.error.error()
            for index, settings, message in done.failures:
                result.failures.append(Failure(index, settings, message))
            if done.table is not None:
                first = done.written[0] if done.written else done.first
                result.tables[first] = done.table
                if gatherer is not None:
                    gatherer.add(first, done.table, done.rows)
            bar.update(len(done.written) + len(done.failures))
            if done.stopped:
                result.stopped, result.stopped_at = True, done.failures[-1][0]
            return done.stopped

        try:
            if scheduler is not None:
                run_dask_tasks(scene, make_tasks, scheduler, deliver)
            elif jobs > 1:
                run_pool_tasks(scene, make_tasks, jobs, deliver)
            else:
                tasks = make_tasks(1)
                if any(not isinstance(task, ReduceTask) for task in tasks):
                    stand.calibrate(scene.seed)
                for task in tasks:
                    if deliver(run_task(stand, scene, task)):
                        break
        finally:
            if gatherer is not None:
                result.rows = gatherer.result()
    return result
