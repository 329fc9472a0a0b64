"""Reduce a stand-A log: each point's record -> rig.reduction.stand_a readings -> eqs. (29)-(35).

Per point (read through rig.logbook's readers; the truth only through rig.logbook.truth, for the
``true_*`` columns): counts and marks of the common gate, the mean dynamometer signal [V] with
u = sqrt(s^2/n + LSB^2/12) (scatter of the mean over the gate, converter resolution), the
calibration record of dynamometer 10 (reading per N on the dynamometer; the weights' +-0.098 N are
inside the fit's covariance, so ForceCalibration.u_weights = 0 - not counted twice), the balance's
mean T2 with u = +-0.0196 N m as a rectangular half width (the reduction's convention), F_N from
the settings with the stand's normal_force_u_N, and b/a = StandAGeometry.b_over_a(F_N).
The contact law is the one the stand simulated with (rig.stands.yoke.laws), so a mu recovered
from a synthetic log tests the method, not a mismatch of models. Outside the law's domain the
coefficients are NaN (the chain reports the point as not reducible, with the reason).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pandas as pd

from rig.errors import LogFormatError
from rig.logbook import PointRecord, point_indices, read_point
from rig.logbook.truth import read_truth
from rig.reduction import stand_a
from rig.reduction.geometry import StandAGeometry
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import ForceCalibration, Measured
from rig.reduction.table import TRUTH_COLUMNS, reduced_table
from rig.stands.yoke.contact_forces import ContactDomain, Law
from rig.stands.yoke.instruments import CHANNELS, DYNAMOMETER
from rig.stands.yoke.parameters import YokeParameters
from sensors import Adc

UNITS = {"omega_1_rad_s": "rad/s", "spin_rad_s": "rad/s", "l_m": "m", "c_m": "m", "F_y_N": "N"}
"""Units of the dimensional outputs of rig.reduction.stand_a (and their u_ columns); the rest are "1"."""

LawFor = Callable[[float, StandAGeometry], tuple[Law, ContactDomain]]
"""law_for(b_over_a, geometry) -> (law, its domain)."""


def coefficients(law: Law, domain: ContactDomain) -> stand_a.Coefficients:
    """The reduction's scalar coefficients(l/a, c/a, alpha') from a vectorised law; NaN outside its domain."""

    def evaluate(l_over_a: float, c_over_a: float, alpha: float) -> tuple[float, float, float]:
        inside = all(lo <= x <= hi for x, (lo, hi) in
                     ((l_over_a, domain.l_over_a), (c_over_a, domain.c_over_a), (alpha, domain.alpha)))
        if not inside:
            return math.nan, math.nan, math.nan
        nu = law(np.array([l_over_a]), np.array([c_over_a]), np.array([alpha]))
        return tuple(float(np.asarray(x).ravel()[0]) for x in nu)

    return evaluate


def _quantity(group, name: str, where: str) -> float:
    if name not in group:
        raise LogFormatError(f"{where}: {name!r} is missing (present: {', '.join(group) or 'none'})")
    return float(group[name].value)


def point_readings(record: PointRecord, params: YokeParameters, geometry: StandAGeometry,
                   where: str) -> stand_a.StandAReadings:
    """The stand_a readings of one logged point (``where`` names it in errors)."""
    if record.counters is None:
        raise LogFormatError(f"{where}: no counters")
    counters = record.counters.counters
    for name in CHANNELS:
        if name not in counters:
            raise LogFormatError(f"{where}: counter {name!r} is missing")
    if DYNAMOMETER not in record.channels or DYNAMOMETER not in record.calibration:
        raise LogFormatError(f"{where}: channel or calibration {DYNAMOMETER!r} is missing")
    volts = record.channels[DYNAMOMETER].samples
    lsb = Adc().lsb_V
    spread = float(np.std(volts, ddof=1)) ** 2 / volts.size if volts.size > 1 else 0.0
    cal = record.calibration[DYNAMOMETER]
    u_s, u_o = _quantity(cal, "u_sensitivity", where), _quantity(cal, "u_offset", where)
    f_n = _quantity(record.settings, "normal_force", where)
    return stand_a.StandAReadings(
        counts_1=counters["wheel_1"].count, counts_2=counters["wheel_2"].count,
        marks_1=counters["wheel_1"].marks_per_rev, marks_2=counters["wheel_2"].marks_per_rev,
        gate_time=Measured(record.counters.gate_time_s, params.timer_u_s),
        normal_force=Measured(f_n, params.normal_force_u_N),
        dynamometer_signal=Measured(float(np.mean(volts)), math.sqrt(spread + lsb * lsb / 12.0)),
        dynamometer=ForceCalibration(
            sensitivity=_quantity(cal, "sensitivity", where), offset=_quantity(cal, "offset", where),
            u_sensitivity=u_s, u_offset=u_o,
            covariance=float(np.clip(_quantity(cal, "cov_sensitivity_offset", where), -u_s * u_o, u_s * u_o)),
            u_weights=0.0,
        ),
        brake_moment=Measured(_quantity(record.readings, "T2", where),
                              geometry.balance_moment_half_width / math.sqrt(3)),
        b_over_a=geometry.b_over_a(f_n),
    )


def reduce_log(path, params: YokeParameters, law_for: LawFor,
               settings: ReductionSettings | None = None) -> pd.DataFrame:
    """Reduced table of a stand-A log, one row per point (index ``point`` = the log's point index),
    with ``true_*`` columns when the log has a truth group; ``attrs["units"]`` = {column: unit}."""
    settings = ReductionSettings() if settings is None else settings
    indices = point_indices(path)
    points, out_of_range = [], []
    for index in indices:
        record = read_point(path, index)
        where = f"{path}: point {index}"
        geometry = params.geometry_at(_quantity(record.settings, "delta_h", where))
        readings = point_readings(record, params, geometry, where)
        law, domain = law_for(readings.b_over_a, geometry)
        points.append(stand_a.reduce(readings, coefficients(law, domain), geometry, settings))
        out_of_range.append(_out_of_range(record))
    truth = _truth_rows(path, indices)
    frame = reduced_table(points, truth)
    frame.index = pd.Index(indices, name="point")
    for index, problems in zip(indices, out_of_range):
        for columns, why in problems:
            frame.loc[index, [c for name in columns for c in (name, f"u_{name}")]] = np.nan
            frame.loc[index, "reason"] = "; ".join(r for r in (frame.loc[index, "reason"], why) if r)
    frame.attrs["units"] = {column: UNITS.get(column.removeprefix("u_"), "1") for column in frame.columns}
    return frame


def _out_of_range(record: PointRecord) -> list[tuple[tuple[str, ...], str]]:
    """Outputs an instrument's range problem invalidates: clipped converter, balance past full scale."""
    problems = []
    clipped = record.readings.get("dynamometer_clipped")
    if clipped is not None and clipped.value > 0:
        problems.append((("F_y_N", "mu_v", "mu_T"), f"F_y_N, mu_v, mu_T: dynamometer 10 clipped in "
                                                   f"{clipped.value:g} samples (converter range)"))
    over = record.readings.get("balance_over_range")
    if over is not None and over.value > 0:
        problems.append((("mu_T",), f"mu_T: tangent balance past full scale in {over.value:g} readings"))
    return problems


def _truth_rows(path, indices: list[int]) -> list[dict[str, float]] | None:
    try:
        table = read_truth(path)
    except LogFormatError:
        return None  # a log without truth (e.g. of a real stand)
    columns = [c for c in TRUTH_COLUMNS if c in table.columns]
    return [{c: float(table.loc[i, c]) for c in columns} for i in indices]
