"""What accuracy costs in time, for a scene: ``rig accuracy`` (docs/accuracy.md).

For a stand scene, error versus cost of each contact model and grid, surrogate-table resolution,
drive mode and ODE tolerance (CPU time), and gate time (stated uncertainty versus lab time), with
errors against the converged contact model (its grids extrapolated to zero cell size) and the
finest setting of the other axes, settings that cannot give a reduced quantity marked unavailable,
the Pareto front (on the table-build cost for the contact and table axes), the scene's own choice
on it, which setting to choose for which error, and where the scene's time goes.

    from rig.accuracy import StudyOptions, run_accuracy
    report = run_accuracy(load_scene("fig10"), Path("out/accuracy/fig10"), options=StudyOptions(), jobs=2)
"""

from __future__ import annotations

from rig.accuracy.design import Axis, Setting, StudyDesign, StudyOptions, shorten, study_design
from rig.accuracy.pareto import pareto_front
from rig.accuracy.profiler import Part, Profile, StackSampler
from rig.accuracy.study import ACCURACY_CSV, ACCURACY_MD, PARETO_PNG, AccuracyReport, run_accuracy

__all__ = [
    "ACCURACY_CSV",
    "ACCURACY_MD",
    "PARETO_PNG",
    "AccuracyReport",
    "Axis",
    "Part",
    "Profile",
    "Setting",
    "StackSampler",
    "StudyDesign",
    "StudyOptions",
    "pareto_front",
    "run_accuracy",
    "shorten",
    "study_design",
]
