"""The operator and the sweep: run a scene into a folder of outputs.

``run_scene(scene, out_dir, jobs=1, scheduler=None)`` runs a stand scene (simpy operator, log.h5
written point by point and resumable - the points on a process pool or a Dask cluster if asked -,
reduced.csv, reduced_vs_truth.png, summary.txt) or a contact characteristics scene
(characteristics.csv/.png, summary.txt); ``reduce_log_file(log)`` reduces a finished log again.
See docs/scenes.md.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import TYPE_CHECKING

from rig import validate
from rig.errors import ParameterError
from rig.scenes.stand_scene import StandScene

if TYPE_CHECKING:
    from rig.runner.stand_run import RunReport
    from rig.scenes import Scene

_LAZY = {
    "LOG_NAME": "rig.runner.stand_run",
    "MAX_JOBS": "rig.runner.stand_run",
    "RunReport": "rig.runner.stand_run",
    "run_stand_scene": "rig.runner.stand_run",
    "SUMMARY_NAME": "rig.runner.outputs",
    "PointResult": "rig.runner.operator",
    "Step": "rig.runner.operator",
    "run_operator": "rig.runner.operator",
    "reduce_log_file": "rig.runner.reduce_file",
}
"""Names of the package imported from their modules on first use: a worker process that only runs
chunks (rig.runner.chunks) then never imports the parent's outputs (the figure, the summary's
statistics, the characteristics and oscillation runs), about half of the package's import time."""


def __getattr__(name: str):
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def run_scene(scene: Scene, out_dir: Path, *, jobs: int = 1, scheduler: str | None = None,
              progress: bool | None = None) -> RunReport:
    """Run a validated scene (rig.scenes.load_scene) into ``out_dir``; ``jobs`` > 1 uses a process pool
    for stand scenes, ``scheduler`` (a Dask scheduler's address, with ``jobs`` = 1) a Dask cluster;
    ``progress``: tqdm bar (None: only on a terminal)."""
    from rig.runner.stand_run import MAX_JOBS, run_stand_scene

    jobs = validate.integer("jobs", jobs, 1, MAX_JOBS)
    if isinstance(scene, StandScene):
        return run_stand_scene(scene, out_dir, jobs=jobs, scheduler=scheduler, progress=progress)
    if scheduler is not None:
        raise ParameterError("scheduler", scheduler, "None for a contact-characteristics or oscillation scene "
                             "(only a stand scene's points run on a Dask cluster)")
    # the other kinds' modules (the contact solver, the bearing) are imported only for those scenes
    from rig.scenes.characteristics_scene import CharacteristicsScene

    if isinstance(scene, CharacteristicsScene):
        from rig.runner.characteristics_run import run_characteristics_scene

        return run_characteristics_scene(scene, out_dir, progress=progress)
    from rig.runner.oscillation_run import run_oscillation_scene

    return run_oscillation_scene(scene, out_dir, progress=progress)


__all__ = [
    "LOG_NAME",
    "SUMMARY_NAME",
    "PointResult",
    "RunReport",
    "Step",
    "reduce_log_file",
    "run_operator",
    "run_scene",
    "run_stand_scene",
]
