"""Errors a stand-A run shares between its points: the dynamometer's one calibration and its zero drift.

y = F_y/F_N = (s - s0)/S (lever_dyn/R_v)/F_N (eq. 33) at every point of a run is converted with
the same calibration record (sensitivity S, offset s0, their covariance) and reads a zero that
walks away from the calibrated one (an input-referred random walk, amplified g times). Both
errors are common to the points, so the fit needs their covariance (docs/fit.md, Estimate):

    cov(y) = a a^T u_S^2 + b b^T u_s0^2 + (a b^T + b a^T) cov(S, s0) + g^2 D^2 min(t_i, t_j) b b^T
    a = dy/dS = -y/S,  b = dy/ds0 = -(lever_dyn/R_v)/(S F_N),

with t the zero's age at each point. The sensitivity's part a is proportional to the true y,
which the data do not give exactly: built from the measured y, a point that happens to read low
(noise, drift) gets a smaller u and the fit follows it (Peelle's pertinent puzzle); built from
the model at the measured l/a, the l/a error does the same the other way. The fit takes the
values the points are adjusted to (rig.fit.engine.Objective.weights), whose error is
uncorrelated with the residuals; r^T V^-1 r is then the chi2 of fitting the calibration's error
as a nuisance parameter that scales those values, with its Gaussian penalty (Woodbury's
identity; D'Agostini's remedy).
Measured on the stand-A recovery runs (docs/fit.md): mu 0.04 % low from the measured y, 0.1 %
high from the model at the measured l/a, 0.00 % from the adjusted values.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from rig.errors import ParameterError
from rig.fit.covariance import RandomWalk, StructuredCovariance

CAL = "dynamometer_10_"
CALIBRATION_COLUMNS = ("sensitivity_V_N", "u_sensitivity_V_N", "u_offset_V", "cov_sensitivity_offset_V2_N")
DRIFT_COLUMNS = ("dynamometer_gain", "dynamometer_drift_variance_rate_V2_s", "dynamometer_zero_age_s")


@dataclass(frozen=True, eq=False)
class CommonErrors:
    """The covariance of y [1] shared between a run's points, as a function of the true y's estimate.

    sensitivity S [V/N], u_sensitivity [V/N], u_offset [V], cov_sensitivity_offset [V^2/N]: the
    calibration record (sensitivity None: no calibration part); offset_slope: b = dy/ds0 [1/V]
    per point; fixed: an (N, N) part that does not depend on y, or None; walk: the zero drift
    (rig.fit.covariance.RandomWalk), or None. Held in O(N) memory (:meth:`structured`) unless
    ``fixed`` is given.
    """

    sensitivity: float | None
    u_sensitivity: float
    u_offset: float
    cov_sensitivity_offset: float
    offset_slope: np.ndarray
    fixed: np.ndarray | None
    walk: RandomWalk | None = None

    def low_rank(self, y: np.ndarray | None) -> np.ndarray | None:
        """G (N, m) with G G^T the calibration's covariance at the values y (None: the offset's part only)."""
        if self.sensitivity is None:
            return None
        b = self.offset_slope
        if y is None:
            return (b * self.u_offset)[:, None]
        a = -np.asarray(y, dtype=float) / self.sensitivity
        sigma = np.array([[self.u_sensitivity**2, self.cov_sensitivity_offset],
                          [self.cov_sensitivity_offset, self.u_offset**2]])
        values, vectors = np.linalg.eigh(sigma)
        root = vectors * np.sqrt(np.clip(values, 0.0, None))  # Sigma = root root^T
        return np.column_stack([a, b]) @ root

    def variance(self, y: np.ndarray | None) -> np.ndarray:
        """The diagonal of :meth:`covariance` in O(N)."""
        out = np.zeros(self.offset_slope.size)
        if self.fixed is not None:
            out = out + np.diag(self.fixed)
        if self.walk is not None:
            out = out + self.walk.variance()
        g = self.low_rank(y)
        return out if g is None else out + np.sum(g**2, axis=1)

    def covariance(self, y: np.ndarray | None) -> np.ndarray:
        """(N, N) covariance [1] with the sensitivity's part at the values y (the true y's estimate);
        y None: without the sensitivity's part (the offset and the drift only). For small N and
        tests; the fit uses :meth:`structured`."""
        b = self.offset_slope
        out = np.zeros((b.size, b.size)) if self.fixed is None else self.fixed.copy()
        if self.walk is not None:
            out += self.walk.dense()
        g = self.low_rank(y)
        return out if g is None else out + g @ g.T

    def structured(self, y: np.ndarray | None, independent: np.ndarray) -> StructuredCovariance:
        """diag(independent) + this covariance at y, in O(N) form (``fixed`` must be None)."""
        if self.fixed is not None:
            raise ValueError("a dense common covariance has no structured form")
        return StructuredCovariance(independent, self.low_rank(y), self.walk)


def read_common_errors(cal: pd.DataFrame, readings: pd.DataFrame, f_n: np.ndarray,
                       geometries) -> tuple[CommonErrors | None, list[str]]:
    """The run's common errors from its calibration records and readings (one row per fitted point),
    the points' F_N [N] and geometries; with one note per part for the summary."""
    notes = []
    calibration = None
    if any(CAL + c not in cal.columns for c in CALIBRATION_COLUMNS):
        notes.append("no dynamometer calibration record in the log: errors treated as independent")
    else:
        values = cal[[CAL + c for c in CALIBRATION_COLUMNS]].to_numpy(dtype=float)
        if np.allclose(values, values[0], rtol=0, atol=0):
            calibration = values[0]
            notes.append(f"dynamometer calibration common to all points (u(S)/S = {values[0, 1] / values[0, 0]:.2%}, "
                         f"u(s0) = {values[0, 2]:.3g} V): generalised least squares with its covariance, the "
                         "sensitivity's part at the fitted F_y")
        else:
            notes.append("dynamometer calibrated more than once: calibration errors treated as independent")
    drift, note = drift_walk(readings, cal, f_n, geometries)
    notes.append(note)
    if calibration is None and drift is None:
        return None, notes
    if calibration is None:
        return CommonErrors(None, 0.0, 0.0, 0.0, np.zeros(f_n.size), None, drift), notes
    sensitivity, u_sensitivity, u_offset, cov_so = map(float, calibration)
    return CommonErrors(sensitivity, u_sensitivity, u_offset, cov_so, -_levers(geometries) / (sensitivity * f_n),
                        None, drift), notes


def drift_covariance(readings: pd.DataFrame, cal: pd.DataFrame, f_n: np.ndarray, geometries) -> tuple:
    """(N, N) covariance of y from the zero drift (or None) and the note: :func:`drift_walk` made dense
    (small N only; the fit keeps the walk in O(N) form)."""
    walk, note = drift_walk(readings, cal, f_n, geometries)
    return (None if walk is None else walk.dense()), note


def drift_walk(readings: pd.DataFrame, cal: pd.DataFrame, f_n: np.ndarray, geometries) -> tuple:
    """Covariance of y = F_y/F_N from the dynamometer's zero drift since the calibration took the zero
    (a RandomWalk, or None with the note saying why).

    The zero walks as an input-referred random walk (sensors.noise.RandomWalkDrift) amplified g
    times: cov(z_i, z_j) = g^2 D^2 min(t_i, t_j) [V^2] with t the zero's age at each point (the
    log's readings, rig.stands.yoke.instruments.zero_drift_readings); dy/dz = -(lever_dyn/R_v)/(S F_N)
    (eq. 33). Its diagonal is the reduction's ``dyn_zero_drift_V`` term, already inside u(F_y).
    """
    if any(c not in readings.columns for c in DRIFT_COLUMNS) or CAL + "sensitivity_V_N" not in cal.columns:
        return None, ("the log does not record dynamometer 10's zero drift: no covariance between points "
                      "beyond the calibration's")
    gain, rate, age = (readings[c].to_numpy(dtype=float) for c in DRIFT_COLUMNS)
    if not (np.allclose(gain, gain[0], rtol=0, atol=0) and np.allclose(rate, rate[0], rtol=0, atol=0)):
        raise ParameterError("dynamometer drift readings", f"gain {sorted(set(gain))}, rate {sorted(set(rate))}",
                             "one gain and one drift variance rate per run")
    if rate[0] == 0.0:
        return None, "dynamometer 10's zero drift is off in this log: no covariance between points from it"
    sens = cal[CAL + "sensitivity_V_N"].to_numpy(dtype=float)
    b = _levers(geometries) / (sens * f_n)
    walk = RandomWalk(float(gain[0] ** 2 * rate[0]), age, b)
    return walk, (f"dynamometer 10's zero drift since the calibration (random walk, g D = "
                 f"{gain[0] * math.sqrt(rate[0]):.3g} V/s^0.5): covariance g^2 D^2 min(t_i, t_j) between "
                 f"points (t = {age.min():.0f}-{age.max():.0f} s after the zero) added to the generalised "
                 "least squares")


def _levers(geometries) -> np.ndarray:
    """lever_dyn/R_v [1] per point: dynamometer 10's reading to F_y (eq. 33)."""
    return np.array([g.dynamometer_lever / g.yoke_lever for g in geometries])
