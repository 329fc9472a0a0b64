"""The study's result table: one row per axis entry, errors against the axis's reference, costs, front.

Columns (dimensionless quantities keep their bare name, the rest carry their unit):

* ``axis``, ``setting`` (label), ``scene_choice`` (the scene's own setting), ``reference``;
* ``runs`` (timed runs), ``cpu_median_s``, ``cpu_min_s``, ``cpu_max_s`` (CPU time of a timed run
  [s]: median, smallest, largest), ``cpu_first_s`` (the untimed first run, which also builds or
  loads the surrogate tables [s]), ``lab_time_s``
  (operator time of a run [s]), ``points``, ``failed`` (did not settle), ``compared`` (points in
  the error measures);
* ``d_l_over_a``, ``d_mu_v``, ``d_mu_T``: RMS over the points of (reduced - reference's reduced)
  (same seed); ``d_true_l_over_a``: the same for the simulation's true l/a (no instruments). On the
  contact axis the reference is, where the design gives three grids N/4, N/2, N of the finest
  model, their reduced outputs extrapolated point by point to zero cell size
  (rig.contact.numerical_error.richardson, observed order); ``u_reference``: that reference's own
  uncertainty, the largest over the quantities of its RMS over the points (0 for a setting taken
  as the reference);
* ``unavailable``: the quantities the reference reduces that this setting cannot give at any
  point (e.g. ``mu_v`` of the rigid law, which has no lateral force coefficient); such a setting
  has no error and is never on the front;
* ``err_l_over_a``, ``err_mu_v``, ``err_mu_T``: weighted RMS of (reduced - truth)
  (rig.accuracy.metrics.weighted_truth_error);
* ``u_l_over_a``, ``u_mu_T``: median stated standard uncertainty;
* ``error``: what the front is drawn on - max(d_l_over_a, d_mu_v, d_mu_T) on the CPU axes,
  max(u_l_over_a, u_mu_T) on the gate axis [our choice]; ``cost_s``: what a user pays for the
  setting - on the contact and table axes of a scene with surrogate tables the first run's CPU
  time (it builds the setting's tables: the study runs with a cache of its own, so they are always
  built), elsewhere the CPU median, and lab time on the gate axis; ``on_front``: Pareto front of
  (cost_s, error) within the axis.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pandas as pd

from rig.accuracy.design import Axis, AxisPlan, StudyDesign
from rig.accuracy.schedule import Measurement
from rig.accuracy.metrics import (QUANTITIES, common_points, median_uncertainty, rms_difference,
                                  weighted_truth_error)
from rig.accuracy.pareto import pareto_front
from rig.contact.numerical_error import richardson

COLUMNS = ("axis", "setting", "scene_choice", "reference", "runs", "cpu_median_s", "cpu_min_s", "cpu_max_s",
           "cpu_first_s", "lab_time_s", "points", "failed", "compared", "d_l_over_a", "d_mu_v", "d_mu_T",
           "d_true_l_over_a", "err_l_over_a", "err_mu_v", "err_mu_T", "u_l_over_a", "u_mu_T", "u_reference",
           "unavailable", "error", "cost_s", "on_front")
EXTRAPOLATED = ("l_over_a", "mu_v", "mu_T", "true_l_over_a")
"""Reduced columns the contact axis's reference extrapolates to zero cell size."""


def _column(table: pd.DataFrame, name: str) -> pd.Series:
    return table[name] if name in table else pd.Series(math.nan, index=table.index, dtype=float)


def _row(plan: AxisPlan, k: int, m: Measurement, ref: Measurement | None, u_reference: float) -> dict:
    r = m.reduced
    is_reference = k == plan.reference and plan.extrapolated is None
    row = dict(axis=plan.axis.value, setting=plan.entries[k].label, scene_choice=k == plan.scene_choice,
               reference=is_reference, runs=len(m.cpu_s), cpu_median_s=m.median_cpu_s,
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
    row["u_reference"] = 0.0 if is_reference else u_reference
    missing = [] if ref is None else [q for q in QUANTITIES if np.isfinite(_column(ref.reduced, q)).any()
                                      and common_points(_column(r, q), _column(ref.reduced, q)) == 0]
    row["unavailable"] = ", ".join(missing)
    if plan.axis is Axis.GATE:
        row["error"], row["cost_s"] = _largest([row["u_l_over_a"], row["u_mu_T"]]), m.lab_time_s
    else:
        tables = any(e.setting.contact.surrogate for e in plan.entries)
        build = plan.axis in (Axis.CONTACT, Axis.TABLE) and tables
        row["error"] = math.nan if missing else _largest([row[f"d_{q}"] for q in QUANTITIES])
        row["cost_s"] = m.cpu_first_s if build else m.median_cpu_s
    return row


@dataclasses.dataclass(frozen=True)
class ExtrapolatedReference:
    """The contact axis's converged reference: which grids, the observed orders and the own uncertainty.

    grids: the three settings' labels (coarse to fine); order: median observed order over the
    points where it was trusted, per column (NaN if nowhere); trusted: points with a trusted order
    / points, per column; uncertainty: RMS over the points of the reference's uncertainty, per
    column [1].
    """

    grids: tuple[str, str, str]
    order: dict[str, float]
    trusted: dict[str, tuple[int, int]]
    uncertainty: dict[str, float]

    def largest_uncertainty(self) -> float:
        """The largest RMS uncertainty over the compared quantities (l/a, mu_v, mu_T) [1]."""
        return _largest([self.uncertainty.get(q, math.nan) for q in QUANTITIES])


def extrapolated_reference(plan: AxisPlan, found: list[Measurement]) -> tuple[Measurement, ExtrapolatedReference]:
    """The reduced outputs of the plan's three grids extrapolated point by point to zero cell size
    (rig.contact.numerical_error.richardson: observed order, Roache's uncertainty), as a Measurement
    like the finest one's but with those reduced values, and how the extrapolation went."""
    coarse, medium, fine = (found[i].reduced for i in plan.extrapolated)
    reduced = fine.copy()
    order, trusted, uncertainty = {}, {}, {}
    for column in EXTRAPOLATED:
        if not all(column in t for t in (coarse, medium, fine)):
            continue
        joined = pd.concat([coarse[column], medium[column], fine[column]], axis=1, join="inner").astype(float)
        joined = joined[np.isfinite(joined).all(axis=1)]
        limit = pd.Series(np.nan, index=fine.index, dtype=float)
        if joined.empty:
            reduced[column] = limit
            continue
        e = richardson(*(joined.iloc[:, j].to_numpy() for j in range(3)))
        limit.loc[joined.index] = e.limit
        reduced[column] = limit
        order[column] = float(np.median(e.order[e.trusted])) if e.trusted.any() else math.nan
        trusted[column] = (int(e.trusted.sum()), int(e.trusted.size))
        uncertainty[column] = float(np.sqrt(np.mean(e.uncertainty**2)))
    labels = tuple(plan.entries[i].label for i in plan.extrapolated)
    return dataclasses.replace(found[plan.extrapolated[-1]], reduced=reduced), ExtrapolatedReference(
        labels, order, trusted, uncertainty)


def _largest(values: list[float]) -> float:
    """The largest finite value (NaN if none)."""
    finite = [v for v in values if math.isfinite(v)]
    return max(finite) if finite else math.nan


def result_table(design: StudyDesign, measurements: dict[tuple, Measurement]) -> pd.DataFrame:
    """The study's table (COLUMNS), axis by axis in design order."""
    blocks, references = [], {}
    for plan in design.axes:
        found = [measurements[e.setting.key()] for e in plan.entries]
        ref, u_reference = None if plan.reference is None else found[plan.reference], 0.0
        if plan.extrapolated is not None:
            ref, info = extrapolated_reference(plan, found)
            references[plan.axis.value] = info
            u_reference = info.largest_uncertainty()
        block = pd.DataFrame([_row(plan, k, m, ref, u_reference) for k, m in enumerate(found)], columns=list(COLUMNS))
        block["on_front"] = pareto_front(block["cost_s"], block["error"])
        blocks.append(block)
    table = pd.concat(blocks, ignore_index=True)
    table.attrs["units"] = {c: ("s" if c.endswith("_s") else "1") for c in table.columns if c != "unavailable"}
    table.attrs["references"] = references
    return table


def scene_on_front(table: pd.DataFrame) -> dict[str, bool]:
    """Per axis: is the scene's own setting on that axis's front?"""
    own = table[table["scene_choice"]]
    return {str(axis): bool(on) for axis, on in zip(own["axis"], own["on_front"])}
