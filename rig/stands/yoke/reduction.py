"""Reduce a stand-A log: each point's record -> rig.reduction.stand_a readings -> eqs. (29)-(35).

Per point (read through rig.logbook's readers; the truth only through rig.logbook.truth, for the
``true_*`` columns), the input uncertainties come from what the log records about each
instrument, so that the simulated instrument and the reduction agree by construction
(sensors.quantisation for the step of a quantised reading):
* counters: counts and marks of the common gate; u = 1/sqrt(6) count (rig.reduction.stand_a);
* dynamometer 10: the mean of the gate's samples [V]; u^2 = V_b + s^2/n with the converter step
  from the calibration record (``reading_resolution``) and the noise sigma estimated from the
  samples' scatter s^2 (n ~ 10^3 samples); the calibration record's sensitivity, offset and
  covariance (which already hold the weights' +-0.098 N: ForceCalibration.u_weights = 0, not
  counted twice);
* tangent balance: the mean T2 of its readings, with the scale step ``balance_resolution`` and
  the noise ``balance_noise_std`` the balance states in the log: the step's bias V_b (rectangular,
  does not average out) and the scatter of the mean max(s^2, Delta^2/12 + sigma^2 - V_b)/n (the
  larger of what the readings show and what the instrument alone gives, so a moment that moves
  within the gate is covered); the step is the stated reading of the paper's "accuracy 0.049 N"
  (stand parameter balance_step_N: 0.098 N = the +-limit reading by default, sensors.balance);
* dynamometer 10's zero drift since the calibration: an input of value 0 and u = g sqrt(D^2 t) from
  the gain g, the random walk's variance rate D^2 and the zero's age t the point records
  (``dynamometer_gain``, ``dynamometer_drift_variance_rate``, ``dynamometer_zero_age``); a log
  without them (older logs) reduces as before, and the table's ``attrs["notes"]`` says so;
* F_N from the settings with the stand's ``normal_force_u_N``; b/a = StandAGeometry.b_over_a(F_N).
The contact law is the one the stand simulated with (rig.stands.yoke.laws), so a mu recovered
from a synthetic log tests the method, not a mismatch of models. Outside the law's domain the
coefficients raise OutsideModelDomain and the chain reports the point as not reducible with
that reason.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pandas as pd

from rig.errors import LogFormatError, ParameterError
from rig.logbook import PointRecord, read_points
from rig.logbook.damage import damage_reason
from rig.logbook.truth import read_truth
from rig.reduction import stand_a
from rig.reduction.geometry import StandAGeometry
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import ForceCalibration, Measured, converter_mean, scale_mean
from rig.reduction.table import TRUTH_COLUMNS, column_output, reduced_table, with_damaged
from rig.contact.surrogate import TableDomain
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.contact_forces import Law
from rig.stands.yoke.instruments import BALANCE, CHANNELS, DYNAMOMETER
from rig.stands.yoke.parameters import YokeParameters

UNITS = {"omega_1_rad_s": "rad/s", "spin_rad_s": "rad/s", "l_m": "m", "c_m": "m", "D_m": "m", "F_y_N": "N"}
"""Units of the dimensional outputs of rig.reduction.stand_a (and their u_, U95_ columns); the rest are "1"."""

LawFor = Callable[[float, StandAGeometry], tuple[Law, TableDomain]]
"""law_for(b_over_a, geometry) -> (law, its domain)."""


def _quantity(group, name: str, where: str) -> float:
    if name not in group:
        raise LogFormatError(f"{where}: {name!r} is missing (present: {', '.join(group) or 'none'})")
    return float(group[name].value)


def _samples(record: PointRecord, channel: str, where: str) -> np.ndarray:
    if channel not in record.channels:
        raise LogFormatError(f"{where}: channel {channel!r} is missing")
    return np.asarray(record.channels[channel].samples, dtype=float)


def point_readings(record: PointRecord, params: YokeParameters, geometry: StandAGeometry,
                   where: str) -> stand_a.StandAReadings:
    """The stand_a readings of one logged point (``where`` names it in errors)."""
    if record.counters is None:
        raise LogFormatError(f"{where}: no counters")
    counters = record.counters.counters
    for name in CHANNELS:
        if name not in counters:
            raise LogFormatError(f"{where}: counter {name!r} is missing")
    if DYNAMOMETER not in record.calibration:
        raise LogFormatError(f"{where}: calibration {DYNAMOMETER!r} is missing")
    cal = record.calibration[DYNAMOMETER]
    u_s, u_o = _quantity(cal, "u_sensitivity", where), _quantity(cal, "u_offset", where)
    step = _quantity(cal, "reading_resolution", where)
    if not step > 0.0:
        raise LogFormatError(f"{where}: calibration {DYNAMOMETER!r} has reading_resolution = {step!r}, "
                             "expected the converter's code width > 0 V")
    balance = scale_mean(_samples(record, BALANCE, where), _quantity(record.readings, "balance_resolution", where),
                           _quantity(record.readings, "balance_noise_std", where))
    f_n = _quantity(record.settings, "normal_force", where)
    return stand_a.StandAReadings(
        counts_1=counters["wheel_1"].count, counts_2=counters["wheel_2"].count,
        marks_1=counters["wheel_1"].marks_per_rev, marks_2=counters["wheel_2"].marks_per_rev,
        gate_time=Measured(record.counters.gate_time_s, params.timer_u_s),
        normal_force=Measured(f_n, params.normal_force_u_N),
        dynamometer_signal=converter_mean(_samples(record, DYNAMOMETER, where), step),
        dynamometer=ForceCalibration(
            sensitivity=_quantity(cal, "sensitivity", where), offset=_quantity(cal, "offset", where),
            u_sensitivity=u_s, u_offset=u_o,
            covariance=float(np.clip(_quantity(cal, "cov_sensitivity_offset", where), -u_s * u_o, u_s * u_o)),
            u_weights=0.0,  # inside the calibration record's covariance (sensors.calibration)
        ),
        brake_moment=Measured(_quantity(record.readings, "T2", where), balance.u, balance.u_step),
        b_over_a=geometry.b_over_a(f_n),
        zero_drift_u=zero_drift_u(record, where),
    )


ZERO_DRIFT_READINGS = ("dynamometer_gain", "dynamometer_drift_variance_rate", "dynamometer_zero_age")
NO_ZERO_DRIFT_NOTE = ("the log does not record dynamometer 10's zero drift (" + ", ".join(ZERO_DRIFT_READINGS)
                      + "): u(F_y) holds no drift since the calibration, as before")


def zero_drift_u(record: PointRecord, where: str) -> float:
    """Standard uncertainty [V] of the dynamometer's zero at this point: the input-referred random
    walk since the calibration took the zero, amplified, g sqrt(D^2 t) (sensors.noise.RandomWalkDrift,
    Var W(t) = D^2 t); 0 for a log that does not record it (rig.stands.yoke.instruments.zero_drift_readings)."""
    if not all(name in record.readings for name in ZERO_DRIFT_READINGS):
        return 0.0
    gain, rate, age = (_quantity(record.readings, name, where) for name in ZERO_DRIFT_READINGS)
    if not (gain > 0.0 and rate >= 0.0 and age >= 0.0):
        raise LogFormatError(f"{where}: dynamometer zero drift readings gain = {gain!r}, variance rate = {rate!r}, "
                             f"zero age = {age!r} s; expected gain > 0, rate >= 0, age >= 0")
    return gain * math.sqrt(rate * age)


def reduce_log(path, params: YokeParameters, law_for: LawFor,
               settings: ReductionSettings | None = None) -> pd.DataFrame:
    """Reduced table of a stand-A log, one row per point (index ``point`` = the log's point index),
    with ``true_*`` columns when the log has a truth group; ``attrs["units"]`` = {column: unit}.
    The log is read once (rig.logbook.read_points); a damaged point (a non-finite sample, a
    missing dataset) is a row of NaN whose ``reason`` names the dataset and the bad value."""
    settings = ReductionSettings() if settings is None else settings
    indices, reduced, points, out_of_range, damaged = [], [], [], [], {}
    drift_recorded = True
    for index, record in read_points(path):
        indices.append(index)
        where = f"point {index}"
        try:
            if isinstance(record, LogFormatError):
                raise record
            geometry = params.geometry_at(_quantity(record.settings, "delta_h", where))
            readings = point_readings(record, params, geometry, where)
            drift_recorded &= all(name in record.readings for name in ZERO_DRIFT_READINGS)
        except (LogFormatError, ParameterError) as error:  # a damaged point: NaN with the reason, the others go on
            damaged[index] = damage_reason(path, index, error, None if isinstance(record, LogFormatError) else record)
            continue
        law, domain = law_for(readings.b_over_a, geometry)
        points.append(stand_a.reduce(readings, LawCoefficients(law, domain), geometry, settings))
        reduced.append(index)
        out_of_range.append(_out_of_range(record))
    frame = reduced_table(points, _truth_rows(path, reduced))
    frame.index = pd.Index(reduced, name="point")
    for index, problems in zip(reduced, out_of_range):
        for columns, why in problems:
            frame.loc[index, [c for name in columns for c in (name, f"u_{name}", f"U95_{name}")]] = np.nan
            frame.loc[index, "reason"] = "; ".join(r for r in (frame.loc[index, "reason"], why) if r)
    frame = with_damaged(frame, indices, damaged)
    frame.attrs["units"] = {column: UNITS.get(column_output(column), "1") for column in frame.columns}
    if not drift_recorded:
        frame.attrs["notes"] = [NO_ZERO_DRIFT_NOTE]
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
    return table.reindex(indices)[columns].astype(float).to_dict("records")
