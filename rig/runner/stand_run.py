"""A stand scene from start to outputs: log.h5, reduced.csv, the figure and summary.txt in one folder.

Order: lock the folder (rig.runner.folder_lock: a second run into it is refused by name) ->
build the stand with the scene's effects only (an error there leaves nothing) -> open the log
(resuming an interrupted run of the same scene; the points of a finished log of the same run are
not simulated again, so a run killed while writing its outputs only redoes those) -> sweep the
points not yet logged -> remove the previous run's outputs -> finalize log.h5 -> reduce
(reduced.csv and ``/reduced`` in the log) -> figures -> summary.txt, the outputs staged and moved
into the folder whole (rig.runner.outputs).

In this process (``jobs`` = 1) the stand is calibrated once and the points are written one by one
into the log's journal (rig.logbook.writer), then the log is reduced whole. On a local process
pool (``jobs`` > 1) or a Dask cluster (``scheduler``: a scheduler's address) the points run in
chunks (rig.runner.chunks): each worker simulates, logs (a shard, rig.logbook.shards) and reduces
its chunk; this process stores the shards in the log's staging folder, merges them into log.h5
and writes the reduced rows the workers sent (the log is reduced whole only where the chunks'
tables differ). An interrupted run with shards resumes in chunks, whatever ``jobs``. A point that
does not settle is reported (policy: rig.runner.operator). A named error of the scene (a
ParameterError, ConvergenceError, ... raised while calibrating or inside a point) removes the
staging folder - running the same scene again would meet it again - and propagates; any other
error (an interruption, a full disk, a worker lost: rig.runner.pool.WorkerError) propagates with
the staging folder intact, so running the scene again resumes.
"""

from __future__ import annotations

import contextlib
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from rig import validate
from rig.campaigns import paper_figure
from rig.errors import LogFormatError, RigError
from rig.logbook import LogWriter, RunMetadata, point_indices, read_metadata, read_point, staging_dir, utc_timestamp
from rig.logbook.shards import Shard, find_shards, merge_logs, remove_shards, shard_folder
from rig.logbook.writer import RUN_PART, same_run
from rig.runner.dask_pool import check_scheduler
from rig.runner.figures import reduced_vs_truth_figure
from rig.runner.folder_lock import folder_lock
from rig.runner.off_truth import off_truth_points
from rig.runner.outputs import (REDUCED_FIGURE, REDUCED_ROWS_NAME, STAND_KIND, SUMMARY_NAME, claim_folder,
                                output_folder, remove_stale, staged_outputs)
from rig.runner.pool import MAX_WORKERS, WorkerError
from rig.runner.reduction import (FormattedRows, Reduction, gathered_table, read_truth_if_any, reduce_to_files,
                                  table_to_files)
from rig.runner.summary import RunFacts, summary_text
from rig.runner.chunks import SETTLE_TRUTH
from rig.runner.sweep import Failure, ShardedSweep, run_sharded_sweep, run_sweep
from rig.scenes.procedure import PlannedPoint
from rig.scenes.stand_scene import StandScene
from rig.stands.base import Stand

LOG_NAME = "log.h5"
MAX_JOBS = MAX_WORKERS


@dataclass(frozen=True)
class RunReport:
    """What a run wrote: the folder, the files (names), points planned / in the log / resumed,
    the failures, whether it stopped early, the summary text, the damaged points of the log and the
    reduced points off their truth (rig.runner.off_truth; twin runs)."""

    out_dir: Path
    files: tuple[str, ...]
    planned: int
    in_log: int
    resumed: int
    failures: tuple[Failure, ...]
    stopped: bool
    summary: str
    damaged: tuple[int, ...] = ()
    off_truth: tuple[int, ...] = ()


def _settle_times(log_path: Path) -> list[float]:
    truth = read_truth_if_any(log_path)
    column = f"{SETTLE_TRUTH}_s"
    return [] if truth is None or column not in truth else truth[column].dropna().tolist()


def _calibration_names(log_path: Path) -> list[str]:
    indices = point_indices(log_path)
    return sorted(read_point(log_path, indices[0]).calibration) if indices else []


def run_stand_scene(scene: StandScene, out_dir: Path, *, jobs: int = 1, scheduler: str | None = None,
                    progress: bool | None = None) -> RunReport:
    """Run ``scene`` into ``out_dir`` (created if needed); ``jobs`` processes (1: this one), or the
    workers of the Dask scheduler at address ``scheduler`` (then ``jobs`` must be 1)."""
    jobs = validate.integer("jobs", jobs, 1, MAX_JOBS)
    if scheduler is not None:
        scheduler = check_scheduler(scheduler, jobs)
    out_dir = output_folder(out_dir)
    with folder_lock(out_dir, f"rig run {scene.name}"):
        claim_folder(out_dir, STAND_KIND)  # a characteristics or oscillation run's folder is refused
        rows = out_dir / REDUCED_ROWS_NAME
        rows.unlink(missing_ok=True)  # an interrupted run's
        try:
            return _run_locked(scene, out_dir, jobs, scheduler, progress)
        finally:
            rows.unlink(missing_ok=True)


def _run_locked(scene: StandScene, out_dir: Path, jobs: int, scheduler: str | None, progress: bool | None) -> RunReport:
    """The run, with the folder's lock held (a finished log of this run is reused: rig.logbook.LogWriter)."""
    log_path = out_dir / LOG_NAME
    stand = scene.build_stand()  # before the log is opened: a stand that cannot be built leaves nothing
    folder = shard_folder(log_path)
    if not (staging_dir(log_path) / RUN_PART).is_file():
        remove_shards(folder)  # not of a run that can be resumed
    writer = LogWriter(log_path, RunMetadata(scene.text, scene.seed, scene.stand, utc_timestamp()))
    finished = _finished_points(log_path, writer.metadata)
    earlier = []
    for shard in find_shards(folder, writer.metadata):
        if finished.issuperset(shard.indices):  # merged into the finished log before a kill
            shard.path.unlink()
        else:
            earlier.append(shard)
    plan = scene.procedure.points()
    done = set(writer.done).union(*(shard.indices for shard in earlier))
    todo = [point for point in plan if point.index not in done]
    sharded = bool(earlier) or (scheduler is not None and bool(todo)) or (jobs > 1 and len(todo) > 1)
    try:
        if sharded:
            sweep = run_sharded_sweep(scene, stand, todo, earlier, folder, writer.metadata, jobs=jobs,
                                      progress=progress, scheduler=scheduler,
                                      rows=None if writer.done else out_dir / REDUCED_ROWS_NAME)
        else:
            if todo:
                stand.calibrate(scene.seed)
            sweep = run_sweep(scene, stand, todo, writer, progress=progress)
    except RigError as error:
        if not isinstance(error, WorkerError):  # a named error of the scene: a rerun would meet it again
            _discard(writer, log_path)
        raise
    remove_stale(out_dir)  # the previous outputs describe the log about to be replaced
    table = _finalize(writer, log_path, earlier, sweep) if sharded else writer.finalize() and None
    facts = RunFacts(
        planned=len(plan), resumed=len(plan) - len(todo), written_now=len(sweep.written), failures=sweep.failures,
        stopped=sweep.stopped, jobs=jobs, scheduler=scheduler, settle_times_s=_settle_times(log_path),
        calibration=_calibration_names(log_path), operator_time_s=sweep.operator_time_s,
    )
    gathered = [table]  # handed over, not kept here: the parent's memory holds one reduced table at a time
    del table
    with staged_outputs(out_dir) as staging:
        files, text, reduction = _write_outputs(scene, stand, log_path, facts, staging, gathered, plan,
                                                sweep.rows if sharded else None)
    return RunReport(out_dir, tuple(files), len(plan), facts.resumed + facts.written_now, facts.resumed,
                     tuple(sweep.failures), sweep.stopped, text, () if reduction is None else reduction.damaged,
                     () if reduction is None else off_truth_points(reduction.table))


def _discard(writer: LogWriter, log_path: Path) -> None:
    """Remove the staging folder: ``run.h5`` first (the folder then holds no run to resume), the shards."""
    writer.discard()
    remove_shards(shard_folder(log_path))
    with contextlib.suppress(OSError):
        staging_dir(log_path).rmdir()


def _finished_points(log_path: Path, metadata: RunMetadata) -> set[int]:
    """The points of a finished log of this same run at ``log_path`` (else none)."""
    try:
        if same_run(metadata, read_metadata(log_path)) is not None:
            return set()
        return set(point_indices(log_path))
    except LogFormatError:
        return set()


def _finalize(writer: LogWriter, log_path: Path, earlier: list[Shard], sweep: ShardedSweep) -> pd.DataFrame | None:
    """Lay the run's points out as ``log_path`` from the shards (and the points the writer holds from a
    serial attempt or a finished log), remove the staging folder; returns the reduced table gathered
    from the shards when every point's rows are there and alike (None: the log is reduced whole)."""
    shards = [shard for shard in [*earlier, *sweep.stored]
              if sweep.stopped_at is None or shard.indices[0] < sweep.stopped_at]
    for shard in [*earlier, *sweep.stored]:
        if shard not in shards:  # past the point that stopped the sweep, as a serial run would not log them
            shard.path.unlink()
    shards.sort(key=lambda shard: shard.indices[0])
    folder = shard_folder(log_path)
    held = set(writer.done)
    if not shards:
        writer.finalize()
        remove_shards(folder)
        return None
    sources = [shard.path for shard in shards]
    if held:  # points of a serial attempt's journal or of a finished log: that log first, then the shards
        writer.finalize()
        merge_logs(log_path, writer.metadata, [log_path, *sources], tmp_folder=log_path.parent)
        remove_shards(folder)
        return None
    merge_logs(log_path, writer.metadata, sources, tmp_folder=staging_dir(log_path),
               columns=[sweep.columns.get(shard.indices[0]) for shard in shards])
    sweep.columns.clear()  # the parent's memory: the per-point columns are in the log now
    _discard(writer, log_path)
    tables = [sweep.tables.get(shard.indices[0]) for shard in shards]
    sweep.tables.clear()
    return gathered_table(tables)


def _write_outputs(scene: StandScene, stand: Stand, log_path: Path, facts: RunFacts, staging: Path,
                   gathered: list[pd.DataFrame | None], plan: Sequence[PlannedPoint], rows: FormattedRows | None
                   ) -> tuple[list[str], str, Reduction | None]:
    """Reduce the finalized log (unless ``gathered`` holds its reduced table gathered from the
    workers: taken out of the list, so that only the table with the off-truth flags stays in
    memory; ``rows``: its rows as the workers formatted them), draw the figures of the ``plan``'s
    points and write summary.txt into ``staging``; returns the names of the run's files, the
    summary text and the reduction (None when not reduced)."""
    files, problems = [LOG_NAME], []
    reduction: Reduction | None = None
    empty = not point_indices(log_path)
    if scene.outputs.reduce and empty:
        problems.append("not reduced: the log holds no operating point (every point failed)")
    if scene.outputs.reduce and not empty:
        if gathered and gathered[-1] is not None:  # popped into the call: no name here keeps the table
            reduction = table_to_files(gathered.pop(), log_path, staging, rows)
        else:
            reduction = reduce_to_files(stand, log_path, scene.contact, staging)
        files.append(reduction.csv.name)
        problems.extend(reduction.problems)
    campaign_lines: tuple[str, ...] = ()
    if scene.outputs.figures and reduction is not None:
        title = f"{scene.name}: {scene.description}"
        figure = reduced_vs_truth_figure(reduction.table, plan, scene.procedure,
                                         staging / REDUCED_FIGURE, title)
        if figure is not None:
            files.append(figure.name)
        if scene.outputs.paper_figure is not None:
            outcome = paper_figure(scene.outputs.paper_figure)(reduction.table, log_path, staging, title)
            files.extend(outcome.files)
            campaign_lines = outcome.summary
    files.append(SUMMARY_NAME)
    text = summary_text(scene, facts, None if reduction is None else reduction.table, problems, files, campaign_lines)
    (staging / SUMMARY_NAME).write_text(text, encoding="utf-8")
    return files, text, reduction
