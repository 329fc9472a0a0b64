"""Reduce a stand-B log: each point's record -> rig.reduction.stand_b readings -> mu, M_C.

Per point (rig.logbook readers; the truth is never read here):
* F_T, F_V, T_Mo: mean of the recorded channel [V] converted with the point's calibration
  record (sensors.CalibrationRecord), u from the calibration's covariance (it holds the
  weights' +-0.098 N: nothing is added for them) and the mean's own uncertainty V_b + s^2/n,
  with the converter step the calibration record logs (``reading_resolution``) and the noise
  estimated from the samples (rig.stands.yoke.reduction.converter_mean, sensors.quantisation);
* l, sigma, F_N from the settings with the stand's u_l_setting, u_twist, u_normal_force;
  b/a from the stand's Hertz line contact at F_N (the value the simulation used);
* direction -1 (reverse running) is mapped onto the canonical frame of the chain (forward,
  spin > 0) by the mirror x -> -x (rig.stands.disc_roller.contact): sigma, F_T and T_Mo change
  sign, l and F_V do not. The chain's M_C = T_Mo + R_c F_T is then T0 = mu a F_N nu_0 >= 0
  (plus the disc-bearing friction, if any: a systematic error of the method).
The law is the stand's (the one it simulated with); outside its domain the coefficients raise
OutsideModelDomain and the chain reports the point as not reducible, with that reason. Swinging-drive logs
have no steady operating point and are refused.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pandas as pd

from rig.contact.surrogate import TableDomain
from rig.errors import LogFormatError, ParameterError
from rig.logbook import PointRecord, read_points
from rig.logbook.damage import damage_reason
from rig.reduction import stand_b
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import Measured, converter_mean
from rig.reduction.table import column_output, reduced_table, with_damaged
from rig.stands.contact_law import LawCoefficients
from rig.stands.disc_roller.contact import Law
from rig.stands.disc_roller.instruments import CHANNELS, record_from_fields
from rig.stands.disc_roller.parameters import StandBParameters

CALIBRATION_FIELDS = ("sensitivity", "offset", "u_sensitivity", "u_offset", "cov_sensitivity_offset",
                      "residual_std", "n_steps")


def _value(group, name: str, where: str) -> float:
    if name not in group:
        raise LogFormatError(f"{where}: {name!r} is missing (present: {', '.join(group) or 'none'})")
    return float(group[name].value)


def channel_reading(record: PointRecord, channel: str, where: str) -> Measured:
    """Calibrated mean of a recorded channel [N or N m] with its standard uncertainty."""
    if channel not in record.channels or channel not in record.calibration:
        raise LogFormatError(f"{where}: channel or calibration {channel!r} is missing")
    volts = record.channels[channel].samples
    cal = record.calibration[channel]
    calibration = record_from_fields(channel, {f: _value(cal, f, where) for f in CALIBRATION_FIELDS})
    step = _value(cal, "reading_resolution", where)
    if not step > 0.0:
        raise LogFormatError(f"{where}: calibration {channel!r} has reading_resolution = {step!r}, "
                             "expected the converter's code width > 0 V")
    mean = converter_mean(volts, step)
    value = float(calibration.to_quantity(np.array([mean.value]))[0])
    u = float(calibration.quantity_standard_uncertainty(np.array([mean.value]), mean.u)[0])
    return Measured(value, u)


def point_readings(record: PointRecord, params: StandBParameters, where: str) -> stand_b.StandBReadings:
    """The stand_b readings of one logged point in the chain's canonical (forward) frame."""
    s = record.settings
    f_n = _value(s, "normal_force", where)
    direction = _value(s, "direction", where)
    if direction not in (-1.0, 1.0):
        raise LogFormatError(f"{where}: setting 'direction' = {direction!r}, expected +1 or -1")
    f_t, f_v, t_mo = (channel_reading(record, name, where) for name in CHANNELS)
    return stand_b.StandBReadings(
        l_setting=Measured(_value(s, "l", where), params.u_l_setting),
        twist=Measured(direction * _value(s, "sigma", where), params.u_twist),
        normal_force=Measured(f_n, params.u_normal_force),
        peripheral_force=Measured(direction * f_t.value, f_t.u),
        lateral_force=f_v,
        momentometer_torque=Measured(direction * t_mo.value, t_mo.u),
        b_over_a=params.b_over_a(f_n),
    )


def reduce_log(
    path, params: StandBParameters, law_for: Callable[[float], Law], domain_for: Callable[[float], TableDomain],
    settings: ReductionSettings | None = None,
) -> pd.DataFrame:
    """Reduced table of a stand-B log, one row per point (index ``point`` = the log's point index).

    law_for(b/a) -> law, domain_for(b/a) -> its TableDomain (the stand's); settings: the chain's.
    The log is read once; a damaged point is a row of NaN whose ``reason`` names what is wrong.
    """
    settings = ReductionSettings() if settings is None else settings
    indices, reduced, points, damaged = [], [], [], {}
    for index, record in read_points(path):
        indices.append(index)
        try:
            if isinstance(record, LogFormatError):
                raise record
            readings = point_readings(record, params, f"point {index}")
        except (LogFormatError, ParameterError) as error:  # a damaged point: NaN with the reason, the others go on
            damaged[index] = damage_reason(path, index, error, None if isinstance(record, LogFormatError) else record)
            continue
        law = LawCoefficients(law_for(readings.b_over_a), domain_for(readings.b_over_a))
        points.append(stand_b.reduce(readings, law, params.geometry, settings))
        reduced.append(index)
    frame = reduced_table(points)
    frame.index = pd.Index(reduced, name="point")
    frame = with_damaged(frame, indices, damaged)
    if "note" in frame:
        frame["note"] = frame["note"].fillna("").astype(str)
        frame.attrs["notes"] = root_notes(frame)
    frame.attrs["units"] = {name: _unit(name) for name in frame.columns}
    return frame


ROOT_NOTES = (
    ("roots:", "where the driving estimate's equation has more than one root in mu"),
    ("one root:", "whose only root in mu another estimate contradicts (a root could hide behind a turning point)"),
)
"""The summary's kinds of root notes (rig.reduction.stand_b): (what the note contains, what it means)."""


def root_notes(frame: pd.DataFrame) -> list[str]:
    """The summary's lines on points whose mu is not unique or whose only root is contradicted
    (rig.reduction.stand_b, ROOT_NOTES): how many, how many resolved by another reading, how many NaN
    (named); [] when every root was unique and uncontradicted."""
    lines = []
    for marker, what in ROOT_NOTES:
        noted = frame.index[frame["note"].str.contains(marker, regex=False).to_numpy()]
        if not len(noted):
            continue
        unresolved = [int(i) for i in noted if not np.isfinite(frame.loc[i, "mu_v"])]
        shown = ", ".join(map(str, unresolved[:20])) + (" ..." if len(unresolved) > 20 else "")
        lines.append(f"{len(noted)} point(s) {what} (reduced.csv's note names them): "
                     f"{len(noted) - len(unresolved)} resolved by another reading, {len(unresolved)} reduced to NaN"
                     + (f" (points {shown})" if unresolved else ""))
    return lines


def _unit(column: str) -> str:
    """Unit of a reduced column (u_<name>, U95_<name> have the unit of <name>): m, N m or 1."""
    return {"l_m": "m", "c_m": "m", "M_C_N_m": "N m"}.get(column_output(column), "1")
