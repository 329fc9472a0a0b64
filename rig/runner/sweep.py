"""The sweep: run the planned points that are not yet in the log, writing each one as it finishes.

Points already in the log's staging folder (an interrupted run of the same scene) are skipped:
rig.logbook.LogWriter resumes, and since every point is simulated from its own arguments the
resumed log equals an uninterrupted one. ``jobs`` = 1 runs the operator in this process on one
simpy clock; ``jobs`` > 1 runs the points on a local process pool (rig.runner.pool), a
``scheduler`` address on a Dask cluster (rig.runner.dask_pool), both with identical results.
A tqdm progress bar counts the points; it is silent when stderr is not a terminal (or when
``progress`` is False).

Each point's truth gets one entry from the operator: ``operator_settle_time`` [s], the
simulated time the point took to settle as ``settle`` reported it (read back for the summary,
also after a resume).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import dataclass, field

from tqdm import tqdm

from rig.errors import ParameterError
from rig.logbook import LogWriter, Quantity
from rig.runner.dask_pool import run_dask
from rig.runner.operator import PointResult, run_operator
from rig.runner.pool import run_pool
from rig.scenes.procedure import PlannedPoint, TimeoutPolicy
from rig.scenes.stand_scene import StandScene
from rig.stands.base import Stand

SETTLE_TRUTH = "operator_settle_time"
"""Truth entry the operator adds to every point: settle time [s]."""


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


def run_sweep(scene: StandScene, stand: Stand | None, points: Sequence[PlannedPoint], writer: LogWriter, *,
              jobs: int, progress: bool | None, scheduler: str | None = None) -> SweepResult:
    """Simulate ``points`` and write each finished one into ``writer``.

    ``stand``: a calibrated stand for the serial path (``jobs`` == 1, no ``scheduler``); ignored
    with a pool or a cluster, whose workers build and calibrate their own. ``scheduler``: address
    of a Dask scheduler (rig.runner.dask_pool.check_scheduler; ``jobs`` is then 1), None: local.
    """
    result = SweepResult()
    with tqdm(total=len(points), desc=f"scene {scene.name}", unit="point", disable=not show_progress(progress),
              file=sys.stderr) as bar:

        def deliver(finished: PointResult) -> None:
            point = finished.point
            if finished.outcome is None:
                result.failures.append(Failure(point.index, dict(point.settings), finished.failure or ""))
                result.stopped = scene.procedure.on_settle_timeout is TimeoutPolicy.STOP
            else:
                truth = dict(finished.outcome.truth)
                if SETTLE_TRUTH in truth:
                    raise ParameterError("truth", SETTLE_TRUTH, "a name other than the operator's own entry")
                truth[SETTLE_TRUTH] = Quantity(finished.settle.duration_s, "s")
                writer.write_point(finished.outcome.record, truth)
                result.written.append(point.index)
            bar.update(1)

        if scheduler is not None:
            run_dask(scene, points, scheduler, deliver)
        elif jobs == 1:
            if stand is None:
                raise ParameterError("stand", None, "a calibrated stand for a serial sweep")
            result.operator_time_s = run_operator(stand, points, scene.procedure, scene.seed, deliver)
        else:
            run_pool(scene, points, jobs, deliver)
    return result
