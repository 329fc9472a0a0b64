"""The operator and the sweep: run a scene into a folder of outputs.

``run_scene(scene, out_dir, jobs=1, scheduler=None)`` runs a stand scene (simpy operator, log.h5
written point by point and resumable - the points on a process pool or a Dask cluster if asked -,
reduced.csv, reduced_vs_truth.png, summary.txt) or a contact characteristics scene
(characteristics.csv/.png, summary.txt); ``reduce_log_file(log)`` reduces a finished log again.
See docs/scenes.md.
"""

from __future__ import annotations

from pathlib import Path

from rig import validate
from rig.errors import ParameterError
from rig.runner.characteristics_run import run_characteristics_scene
from rig.runner.oscillation_run import run_oscillation_scene
from rig.runner.operator import PointResult, Step, run_operator
from rig.runner.outputs import SUMMARY_NAME
from rig.runner.reduce_file import reduce_log_file
from rig.runner.stand_run import LOG_NAME, MAX_JOBS, RunReport, run_stand_scene
from rig.scenes import CharacteristicsScene, OscillationScene, Scene


def run_scene(scene: Scene, out_dir: Path, *, jobs: int = 1, scheduler: str | None = None,
              progress: bool | None = None) -> RunReport:
    """Run a validated scene (rig.scenes.load_scene) into ``out_dir``; ``jobs`` > 1 uses a process pool
    for stand scenes, ``scheduler`` (a Dask scheduler's address, with ``jobs`` = 1) a Dask cluster;
    ``progress``: tqdm bar (None: only on a terminal)."""
    jobs = validate.integer("jobs", jobs, 1, MAX_JOBS)
    if scheduler is not None and isinstance(scene, (CharacteristicsScene, OscillationScene)):
        raise ParameterError("scheduler", scheduler, "None for a contact-characteristics or oscillation scene "
                             "(only a stand scene's points run on a Dask cluster)")
    if isinstance(scene, CharacteristicsScene):
        return run_characteristics_scene(scene, out_dir, progress=progress)
    if isinstance(scene, OscillationScene):
        return run_oscillation_scene(scene, out_dir, progress=progress)
    return run_stand_scene(scene, out_dir, jobs=jobs, scheduler=scheduler, progress=progress)


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
