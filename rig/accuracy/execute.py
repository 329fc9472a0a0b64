"""One study run: the shortened scene at one setting, timed in CPU time of this process.

A run is what ``rig run`` does for a stand scene (rig.runner.run_stand_scene: simulate, write
log.h5, reduce to reduced.csv) into a temporary folder, without figures, serially in this
process. Its cost is the process CPU time of that call (time.process_time: every thread of this
process, not the wall clock, so other jobs on the machine do not count directly). Runs of one
setting are identical (same seed); rig.accuracy.schedule keeps the first run's reduced table and
checks the others against it.
"""

from __future__ import annotations

import dataclasses
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.accuracy.design import Setting
from rig.accuracy.metrics import lab_time
from rig.accuracy.profiler import Profile, StackSampler
from rig.runner import LOG_NAME, run_stand_scene
from rig.runner.reduction import REDUCED_CSV, read_truth_if_any
from rig.runner.sweep import SETTLE_TRUTH
from rig.scenes.procedure import Procedure
from rig.scenes.stand_scene import Outputs, StandScene


def study_scene(scene: StandScene, procedure: Procedure, setting: Setting) -> StandScene:
    """The scene as one study run simulates it: the setting's contact, drive, ODE tolerance factor
    (the stand parameter ode_tolerance_factor), gate and effects, the shortened procedure, no figures."""
    effects = {k: v for k, v in scene.effects.items() if k not in setting.dropped_effects}
    parameters = dict(scene.parameters)
    if setting.tolerance_factor != 1.0:
        parameters["ode_tolerance_factor"] = setting.tolerance_factor * parameters.get("ode_tolerance_factor", 1.0)
    return dataclasses.replace(
        scene, contact=setting.contact, drive=setting.drive, effects=effects, parameters=parameters,
        procedure=dataclasses.replace(procedure, gate_time_s=setting.gate_time_s),
        outputs=Outputs(reduce=True, figures=False, paper_figure=None),
    )


@dataclass(frozen=True)
class Run:
    """One run: CPU time [s], reduced table (index: point), operator (lab) time [s], points planned,
    points that did not settle, and the profile when the run was sampled (else None)."""

    cpu_s: float
    reduced: pd.DataFrame
    lab_time_s: float
    planned: int
    failures: int
    profile: Profile | None = None


def run_once(scene: StandScene, procedure: Procedure, setting: Setting, *, profile: bool = False) -> Run:
    """Run ``setting`` of ``scene`` with ``procedure`` once in this process (sampled if ``profile``)."""
    variant = study_scene(scene, procedure, setting)
    sampler = StackSampler() if profile else None
    with tempfile.TemporaryDirectory(prefix="rig-accuracy-") as folder:
        out = Path(folder)
        start = time.process_time()
        if sampler is None:
            report = run_stand_scene(variant, out, jobs=1, progress=False)
        else:
            with sampler:
                report = run_stand_scene(variant, out, jobs=1, progress=False)
        cpu = time.process_time() - start
        reduced = pd.read_csv(out / REDUCED_CSV, index_col=0)
        truth = read_truth_if_any(out / LOG_NAME)
    column = f"{SETTLE_TRUTH}_s"
    settle = np.array([]) if truth is None or column not in truth else truth[column].dropna().to_numpy()
    failures = len(report.failures)
    lab = lab_time(settle, setting.gate_time_s, failures, procedure.settle_timeout_s)
    return Run(cpu, reduced, lab, report.planned, failures, None if sampler is None else sampler.profile())
