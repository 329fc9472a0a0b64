"""Error measures of the study: differences between runs, truth error, stated uncertainty, lab time.

All quantities compared are dimensionless reduced outputs (l_over_a, mu_v, mu_T; columns of
reduced.csv, rig.reduction.table), indexed by the log's point index. Points are matched by that
index; a point enters a measure only where every value it needs is finite (a point the reduction
could not reduce, or that did not settle, is left out - the table says how many points entered).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

QUANTITIES = ("l_over_a", "mu_v", "mu_T")
"""Reduced quantities the study compares [1]."""


def _aligned(a: pd.Series, b: pd.Series) -> tuple[np.ndarray, np.ndarray]:
    """Values of a and b at their common index where both are finite."""
    joined = pd.concat([a.rename("a"), b.rename("b")], axis=1, join="inner").astype(float)
    joined = joined[np.isfinite(joined["a"]) & np.isfinite(joined["b"])]
    return joined["a"].to_numpy(), joined["b"].to_numpy()


def rms_difference(values: pd.Series, reference: pd.Series) -> float:
    """RMS over the common points of (values - reference) [unit of the values]; NaN if none."""
    a, b = _aligned(values, reference)
    return float(np.sqrt(np.mean((a - b) ** 2))) if a.size else math.nan


def common_points(values: pd.Series, reference: pd.Series) -> int:
    """How many points both series have finite values at."""
    return int(_aligned(values, reference)[0].size)


def weighted_truth_error(values: pd.Series, truth: pd.Series, uncertainty: pd.Series) -> float:
    """Inverse-variance weighted RMS of (values - truth): sqrt(sum w e^2 / sum w), w = 1/u^2.

    The weights keep an ill-conditioned point from dominating: mu_T is undetermined at l = 0
    (D -> 0 in eq. (35); the reduction states u_mu_T ~ 0.2 there) [our choice]. Points with a
    non-finite or non-positive u are left out. NaN if no point is left.
    """
    frame = pd.concat([values.rename("x"), truth.rename("t"), uncertainty.rename("u")], axis=1, join="inner")
    frame = frame.astype(float)
    frame = frame[np.isfinite(frame).all(axis=1) & (frame["u"] > 0.0)]
    if frame.empty:
        return math.nan
    weights = 1.0 / frame["u"].to_numpy() ** 2
    errors = (frame["x"] - frame["t"]).to_numpy()
    return float(np.sqrt(np.sum(weights * errors**2) / np.sum(weights)))


def median_uncertainty(uncertainty: pd.Series) -> float:
    """Median over the points of a stated standard uncertainty [its unit] (finite values); NaN if none.

    The median, not the RMS: mu_T's u at l ~ 0 is two orders above the rest and would hide the
    dependence on the gate time [our choice]."""
    u = uncertainty.astype(float).to_numpy()
    u = u[np.isfinite(u)]
    return float(np.median(u)) if u.size else math.nan


def lab_time(settle_times_s: np.ndarray, gate_time_s: float, failures: int, timeout_s: float) -> float:
    """Operator (lab) time of a run [s]: settle + gate per logged point, the timeout per failed point
    (rig.runner.operator's clock)."""
    settle = np.asarray(settle_times_s, dtype=float)
    return float(np.sum(settle) + settle.size * gate_time_s + failures * timeout_s)
