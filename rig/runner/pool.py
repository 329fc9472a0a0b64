"""Chunks of operating points on a local process pool (``--jobs N``), results identical to a serial run.

Each worker process builds its own stand from the scene and runs the stand's calibration once
(a pure function of the run seed by the contract, so every worker holds the records the
serial run holds); then it does one chunk per task (rig.runner.chunks: simulate, log as a
shard, reduce). Results come back in point order, so the log, the failures and the
STOP policy are the same as in a serial run. Processes are started with "spawn" (no inherited
state; the stand class must be importable by its module path).

The logbook's records are read-only mappings (``types.MappingProxyType``), which pickle cannot
handle; a reducer registered on multiprocessing's pickler (only there) sends them as dicts.
An error inside a worker comes back as :class:`PointFailure`: a named error (rig.errors.RigError)
is raised in the parent as it was raised in the worker, as a serial run raises it; any other
comes back as text with its traceback and is raised as :class:`WorkerError` naming the point.
Workers ignore Ctrl-C (the parent reports it). :class:`PointFailure` and :class:`WorkerError` are shared
with the Dask path (rig.runner.dask_pool).
"""

from __future__ import annotations

import collections
import multiprocessing
import signal
import traceback
import types
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from multiprocessing.reduction import ForkingPickler

from rig.errors import RigError
from rig.scenes.procedure import PlannedPoint
from rig.scenes.stand_scene import StandScene


class WorkerError(RigError):
    """A point failed with an error inside a worker process (message: point, error type, text)."""


def _mapping_proxy(content: dict) -> types.MappingProxyType:
    return types.MappingProxyType(content)


ForkingPickler.register(types.MappingProxyType, lambda proxy: (_mapping_proxy, (dict(proxy),)))


@dataclass(frozen=True)
class PointFailure:
    """An exception raised while simulating a point in a worker, as text (picklable)."""

    point: PlannedPoint
    kind: str
    message: str
    trace: str
    named: RigError | None = None

    @classmethod
    def of(cls, point: PlannedPoint, error: BaseException) -> PointFailure:
        named = error if isinstance(error, RigError) and not isinstance(error, WorkerError) else None
        return cls(point, type(error).__name__, str(error), "".join(traceback.format_exception(error)), named)

    def error(self) -> RigError:
        """The named error itself (raised as in a serial run), else a WorkerError with the traceback."""
        if self.named is not None:
            return self.named
        return WorkerError(f"point {self.point.index} {dict(self.point.settings)}: {self.kind}: "
                           f"{self.message}\n{self.trace}")


MAX_WORKERS = 256
"""Most worker processes of a run [1]: a local pool's ``--jobs``, a study_cluster's workers
(rig.runner.dask_pool)."""

_worker: dict = {}

TASKS_AHEAD = 3
"""Chunks queued per process of the pool [1] (one running, the next ones ready)."""


def _start_worker(scene: StandScene) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle (one line, exit 130)
    stand = scene.build_stand()
    stand.calibrate(scene.seed)
    _worker.update(scene=scene, stand=stand)


def _run_task(task):
    from rig.runner.chunks import run_task

    return run_task(_worker["stand"], _worker["scene"], task)


def run_pool_tasks(scene: StandScene, make_tasks: Callable[[int], Sequence], jobs: int,
                   deliver: Callable[[object], bool]) -> None:
    """Do the tasks ``make_tasks(jobs)`` (rig.runner.chunks) on ``jobs`` processes; ``deliver`` gets
    each result in task order and returns True to end the sweep there (the tasks after it are
    cancelled). At most ``TASKS_AHEAD`` tasks per process are queued, so that results waiting for
    an earlier one to be delivered never pile up."""
    context = multiprocessing.get_context("spawn")
    pool = ProcessPoolExecutor(max_workers=jobs, mp_context=context, initializer=_start_worker, initargs=(scene,))
    try:
        tasks = iter(make_tasks(jobs))
        futures: collections.deque = collections.deque()
        while True:
            while len(futures) < TASKS_AHEAD * jobs:
                task = next(tasks, None)
                if task is None:
                    break
                futures.append(pool.submit(_run_task, task))
            if not futures:
                break
            try:
                result = futures.popleft().result()
            except BrokenProcessPool as error:  # a worker died, e.g. the stand failed to build or calibrate
                raise WorkerError(f"a worker process of the pool failed ({error}); run with --jobs 1 to see the "
                                  "error of the stand, and from a Python script put the run under "
                                  "`if __name__ == \"__main__\":` (each worker process starts by importing the "
                                  "script)") from None
            if deliver(result):
                break
    finally:
        pool.shutdown(wait=True, cancel_futures=True)

