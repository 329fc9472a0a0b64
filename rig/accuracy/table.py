"""The study's result table: one row per axis entry, errors against the axis's reference, costs, front.

Columns (dimensionless quantities keep their bare name, the rest carry their unit):

* ``axis``, ``setting`` (label), ``scene_choice`` (the scene's own setting), ``reference``;
* ``runs`` (timed runs), ``cpu_median_s``, ``cpu_min_s``, ``cpu_max_s`` (CPU time of a timed run
  [s]: median, smallest, largest), ``cpu_first_s`` (the untimed first run, which also builds or
  loads the surrogate tables [s]), ``lab_time_s``
  (operator time of a run [s]), ``points``, ``failed`` (did not settle), ``compared`` (points in
  the error measures);
* ``d_l_over_a``, ``d_mu_v``, ``d_mu_T``: RMS over the points of (reduced - reference's reduced)
  (same seed); ``d_true_l_over_a``: the same for the simulation's true l/a (no instruments);
* ``err_l_over_a``, ``err_mu_v``, ``err_mu_T``: weighted RMS of (reduced - truth)
  (rig.accuracy.metrics.weighted_truth_error);
* ``u_l_over_a``, ``u_mu_T``: median stated standard uncertainty;
* ``error``: what the front is drawn on - max(d_l_over_a, d_mu_v, d_mu_T) on the CPU axes,
  max(u_l_over_a, u_mu_T) on the gate axis [our choice]; ``cost_s``: CPU median, or lab time on
  the gate axis; ``on_front``: Pareto front of (cost_s, error) within the axis.
"""

from __future__ import annotations

import math

import pandas as pd

from rig.accuracy.design import Axis, AxisPlan, StudyDesign
from rig.accuracy.schedule import Measurement
from rig.accuracy.metrics import (QUANTITIES, common_points, median_uncertainty, rms_difference,
                                  weighted_truth_error)
from rig.accuracy.pareto import pareto_front

COLUMNS = ("axis", "setting", "scene_choice", "reference", "runs", "cpu_median_s", "cpu_min_s", "cpu_max_s",
           "cpu_first_s", "lab_time_s", "points", "failed", "compared", "d_l_over_a", "d_mu_v", "d_mu_T",
           "d_true_l_over_a", "err_l_over_a", "err_mu_v", "err_mu_T", "u_l_over_a", "u_mu_T", "error", "cost_s",
           "on_front")


def _column(table: pd.DataFrame, name: str) -> pd.Series:
    return table[name] if name in table else pd.Series(math.nan, index=table.index, dtype=float)


def _row(plan: AxisPlan, k: int, m: Measurement, ref: Measurement | None) -> dict:
    r = m.reduced
    row = dict(axis=plan.axis.value, setting=plan.entries[k].label, scene_choice=k == plan.scene_choice,
               reference=k == plan.reference, runs=len(m.cpu_s), cpu_median_s=m.median_cpu_s,
               cpu_min_s=min(m.cpu_s), cpu_max_s=max(m.cpu_s), cpu_first_s=m.cpu_first_s, lab_time_s=m.lab_time_s,
               points=m.planned, failed=m.failures)
    for q in QUANTITIES:
        row[f"d_{q}"] = math.nan if ref is None else rms_difference(_column(r, q), _column(ref.reduced, q))
        row[f"err_{q}"] = weighted_truth_error(_column(r, q), _column(r, f"true_{q}"), _column(r, f"u_{q}"))
    truth = "true_l_over_a"
    row["d_true_l_over_a"] = math.nan if ref is None else rms_difference(_column(r, truth),
                                                                         _column(ref.reduced, truth))
    row["compared"] = len(r) if ref is None else common_points(_column(r, "l_over_a"), _column(ref.reduced, "l_over_a"))
    row["u_l_over_a"] = median_uncertainty(_column(r, "u_l_over_a"))
    row["u_mu_T"] = median_uncertainty(_column(r, "u_mu_T"))
    if plan.axis is Axis.GATE:
        row["error"], row["cost_s"] = _largest([row["u_l_over_a"], row["u_mu_T"]]), m.lab_time_s
    else:
        row["error"], row["cost_s"] = _largest([row[f"d_{q}"] for q in QUANTITIES]), m.median_cpu_s
    return row


def _largest(values: list[float]) -> float:
    """The largest finite value (NaN if none)."""
    finite = [v for v in values if math.isfinite(v)]
    return max(finite) if finite else math.nan


def result_table(design: StudyDesign, measurements: dict[tuple, Measurement]) -> pd.DataFrame:
    """The study's table (COLUMNS), axis by axis in design order."""
    blocks = []
    for plan in design.axes:
        found = [measurements[e.setting.key()] for e in plan.entries]
        ref = None if plan.reference is None else found[plan.reference]
        block = pd.DataFrame([_row(plan, k, m, ref) for k, m in enumerate(found)], columns=list(COLUMNS))
        block["on_front"] = pareto_front(block["cost_s"], block["error"])
        blocks.append(block)
    table = pd.concat(blocks, ignore_index=True)
    table.attrs["units"] = {c: ("s" if c.endswith("_s") else "1") for c in table.columns}
    return table


def scene_on_front(table: pd.DataFrame) -> dict[str, bool]:
    """Per axis: is the scene's own setting on that axis's front?"""
    own = table[table["scene_choice"]]
    return {str(axis): bool(on) for axis, on in zip(own["axis"], own["on_front"])}
