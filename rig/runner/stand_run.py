"""A stand scene from start to outputs: log.h5, reduced.csv, the figure and summary.txt in one folder.

Order: lock the folder (rig.runner.folder_lock: a second run into it is refused by name) ->
open the log (resuming an interrupted run of the same scene; the points of a finished log of
the same run are not simulated again, so a run killed while writing its outputs only redoes
those) -> build the stand with the
scene's effects only -> calibrate once -> sweep the points not yet logged, writing each as it
finishes -> finalize log.h5 -> reduce (reduced.csv and ``/reduced`` in the log) -> figure ->
summary.txt. The points run in this process, on a local process pool (``jobs`` > 1) or on a
Dask cluster (``scheduler``: a scheduler's address; rig.runner.dask_pool). A point that does
not settle is reported (policy: rig.runner.operator); any other error propagates with the
staging folder intact, so running the scene again resumes.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rig import validate
from rig.campaigns import paper_figure
from rig.logbook import LogWriter, RunMetadata, point_indices, read_point, utc_timestamp
from rig.runner.dask_pool import check_scheduler
from rig.runner.folder_lock import folder_lock
from rig.runner.figures import FIGURE_NAME, reduced_vs_truth_figure
from rig.runner.reduction import Reduction, read_truth_if_any, reduce_to_files
from rig.runner.summary import RunFacts, summary_text
from rig.runner.sweep import SETTLE_TRUTH, Failure, run_sweep
from rig.scenes.stand_scene import StandScene

LOG_NAME = "log.h5"
SUMMARY_NAME = "summary.txt"
MAX_JOBS = 256


@dataclass(frozen=True)
class RunReport:
    """What a run wrote: the folder, the files (names), points planned / in the log / resumed,
    the failures, whether it stopped early, the summary text and the damaged points of the log."""

    out_dir: Path
    files: tuple[str, ...]
    planned: int
    in_log: int
    resumed: int
    failures: tuple[Failure, ...]
    stopped: bool
    summary: str
    damaged: tuple[int, ...] = ()


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
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    with folder_lock(out_dir, f"rig run {scene.name}"):
        return _run_locked(scene, out_dir, jobs, scheduler, progress)


def _run_locked(scene: StandScene, out_dir: Path, jobs: int, scheduler: str | None, progress: bool | None) -> RunReport:
    """The run, with the folder's lock held (a finished log of this run is reused: rig.logbook.LogWriter)."""
    log_path = out_dir / LOG_NAME
    writer = LogWriter(log_path, RunMetadata(scene.text, scene.seed, scene.stand, utc_timestamp()))
    plan = scene.procedure.points()
    todo = [point for point in plan if point.index not in writer.done]
    serial = scheduler is None and (jobs == 1 or len(todo) <= 1)
    stand = scene.build_stand()
    if serial and todo:
        stand.calibrate(scene.seed)
    sweep = run_sweep(scene, stand if serial else None, todo, writer, jobs=1 if serial else jobs, progress=progress,
                      scheduler=scheduler)
    writer.finalize()

    files, problems = [LOG_NAME], []
    reduction: Reduction | None = None
    if scene.outputs.reduce:
        reduction = reduce_to_files(stand, log_path, scene.contact, out_dir)
        files.append(reduction.csv.name)
        problems.extend(reduction.problems)
    campaign_lines: tuple[str, ...] = ()
    if scene.outputs.figures and reduction is not None:
        figure = reduced_vs_truth_figure(reduction.table, plan, scene.procedure, out_dir / FIGURE_NAME,
                                         f"{scene.name}: {scene.description}")
        if figure is not None:
            files.append(figure.name)
        if scene.outputs.paper_figure is not None:
            outcome = paper_figure(scene.outputs.paper_figure)(reduction.table, log_path, out_dir,
                                                               f"{scene.name}: {scene.description}")
            files.extend(outcome.files)
            campaign_lines = outcome.summary
    files.append(SUMMARY_NAME)
    facts = RunFacts(
        planned=len(plan), resumed=len(plan) - len(todo), written_now=len(sweep.written), failures=sweep.failures,
        stopped=sweep.stopped, jobs=jobs, scheduler=scheduler, settle_times_s=_settle_times(log_path),
        calibration=_calibration_names(log_path), operator_time_s=sweep.operator_time_s,
    )
    text = summary_text(scene, facts, None if reduction is None else reduction.table, problems, files, campaign_lines)
    (out_dir / SUMMARY_NAME).write_text(text, encoding="utf-8")
    return RunReport(out_dir, tuple(files), len(plan), facts.resumed + facts.written_now, facts.resumed,
                     tuple(sweep.failures), sweep.stopped, text, () if reduction is None else reduction.damaged)
