"""Deviation of a simulated curve from digitised reference points (pure functions).

The simulation is interpolated onto the digitised x values (the digitised points are the
reference, as in Cantera's profile comparison, which interpolates the tested profile onto
the reference coordinates) and never extrapolated: points outside the simulated x range are
skipped and counted. Deviation = simulated - digitised, in the units of the y axis.

x shift (digitising error): with a tolerance ``tol`` the digitised x values are moved by the
shift s in [-tol, tol] that minimises the RMSE; linear axis: x + s (s in x units); log axis:
x (1 + s) (s relative, tol < 1). The points compared are those inside the simulated range
for *every* shift in the band, so that all shifts are judged on the same points.
Choices of this project, documented in docs/compare.md.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.optimize import minimize_scalar

from rig import validate
from rig.compare.sidecar import AxisScale
from rig.errors import ParameterError

SHIFT_GRID_POINTS = 101  # coarse scan of [-tol, tol] before the bounded refinement


class Interpolation(Enum):
    """How the simulated curve is interpolated between its samples (in log x / log y on log axes)."""

    LINEAR = "linear"
    PCHIP = "pchip"  # monotone piecewise-cubic Hermite (Fritsch-Carlson); no overshoot


@dataclass(frozen=True)
class CurveMetrics:
    """Summary of one comparison, deviations in the units of the y axis.

    n_compared / n_skipped: digitised points used / outside the simulated x range;
    rmse, max_abs_dev: root-mean-square and largest |simulated - digitised|;
    max_rel_dev: largest |simulated - digitised| / |digitised| over points with digitised y != 0
    (NaN if there is none); x_at_max_abs_dev: digitised x of the worst point (unshifted);
    x_shift: the best shift (None when no tolerance was given).
    """

    n_compared: int
    n_skipped: int
    rmse: float
    max_abs_dev: float
    max_rel_dev: float
    x_at_max_abs_dev: float
    x_shift: float | None


@dataclass(frozen=True)
class CurveComparison:
    """Point-by-point comparison: digitised x, y; mask of compared points; simulated y there (NaN elsewhere).

    x_scale: the x axis scale (it defines how the shift moves x).
    """

    x_ref: np.ndarray
    y_ref: np.ndarray
    compared: np.ndarray
    y_sim: np.ndarray
    metrics: CurveMetrics
    x_scale: AxisScale

    @property
    def deviation(self) -> np.ndarray:
        """simulated - digitised at every digitised point [y units] (NaN where skipped)."""
        return self.y_sim - self.y_ref

    @property
    def x_compared(self) -> np.ndarray:
        """Digitised x moved by the best shift (the abscissae the simulation was evaluated at)."""
        shift = self.metrics.x_shift or 0.0
        return shift_x(self.x_ref, shift, self.x_scale)


def shift_x(x: np.ndarray, shift: float, scale: AxisScale) -> np.ndarray:
    """x moved by ``shift``: x + shift on a linear axis, x (1 + shift) on a log axis."""
    return x * (1.0 + shift) if scale is AxisScale.LOG else x + shift


def interpolate(
    x_sim: np.ndarray,
    y_sim: np.ndarray,
    x: np.ndarray,
    *,
    x_scale: AxisScale = AxisScale.LINEAR,
    y_scale: AxisScale = AxisScale.LINEAR,
    method: Interpolation = Interpolation.LINEAR,
) -> np.ndarray:
    """Simulated y at ``x``; NaN outside [x_sim[0], x_sim[-1]] (no extrapolation).

    On a log axis x and y are interpolated in their logarithm.

    Parameters
    ----------
    x_sim, y_sim : numpy.ndarray
        The simulated curve, x strictly increasing [units of the figure's axes].
    x : numpy.ndarray
        Where to evaluate it (any shape) [x units].
    x_scale, y_scale : AxisScale, optional
        Linear (default) or logarithmic axes.
    method : Interpolation, optional
        Linear (default) or PCHIP.

    Returns
    -------
    numpy.ndarray
        y at ``x`` [y units], shaped like ``x``.
    """
    u_sim = np.log(x_sim) if x_scale is AxisScale.LOG else np.asarray(x_sim, dtype=float)
    v_sim = np.log(y_sim) if y_scale is AxisScale.LOG else np.asarray(y_sim, dtype=float)
    x = np.asarray(x, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.log(x) if x_scale is AxisScale.LOG else x
    inside = (x >= x_sim[0]) & (x <= x_sim[-1])
    if method is Interpolation.PCHIP:
        v = PchipInterpolator(u_sim, v_sim, extrapolate=False)(np.where(inside, u, u_sim[0]))
    else:
        v = np.interp(np.where(inside, u, u_sim[0]), u_sim, v_sim)
    v = np.where(inside, v, np.nan)
    return np.exp(v) if y_scale is AxisScale.LOG else v


def compare_curve(
    x_sim: np.ndarray,
    y_sim: np.ndarray,
    x_ref: np.ndarray,
    y_ref: np.ndarray,
    *,
    x_scale: AxisScale = AxisScale.LINEAR,
    y_scale: AxisScale = AxisScale.LINEAR,
    method: Interpolation = Interpolation.LINEAR,
    shift_tolerance: float | None = None,
) -> CurveComparison:
    """Compare a simulated curve with digitised points.

    Parameters
    ----------
    x_sim, y_sim : numpy.ndarray
        The simulated curve, x strictly increasing [units of the figure's axes].
    x_ref, y_ref : numpy.ndarray
        The digitised points [same units].
    x_scale, y_scale : AxisScale, optional
        Linear (default) or logarithmic axes.
    method : Interpolation, optional
        Linear (default) or PCHIP interpolation of the simulation.
    shift_tolerance : float, optional
        None (no shift) or the largest x shift tried, >= 0 [x units on a linear axis, relative (< 1)
        on a log axis].

    Returns
    -------
    CurveComparison
        The deviations at the comparable points and their metrics (RMSE, max |dev|, max relative dev).

    Raises
    ------
    ParameterError
        Bad curves, or no digitised point inside the simulated x range.
    """
    x_sim, y_sim = _simulated(x_sim, y_sim, x_scale, y_scale)
    x_ref = np.asarray(x_ref, dtype=float)
    y_ref = np.asarray(y_ref, dtype=float)
    if x_ref.shape != y_ref.shape or x_ref.ndim != 1 or not np.all(np.isfinite(x_ref) & np.isfinite(y_ref)):
        raise ParameterError("digitised points", f"{x_ref.size} x, {y_ref.size} y", "equal numbers of finite values")
    if x_scale is AxisScale.LOG and np.any(x_ref <= 0.0):
        raise ParameterError("digitised x", float(x_ref.min()), "> 0 on a log-scaled x axis")
    tol = 0.0
    if shift_tolerance is not None:
        hi = 1.0 if x_scale is AxisScale.LOG else None
        tol = validate.number("x_shift_tolerance", shift_tolerance, 0.0, hi, hi_open=hi is not None)
    compared = (shift_x(x_ref, -tol, x_scale) >= x_sim[0]) & (shift_x(x_ref, tol, x_scale) <= x_sim[-1])
    if not compared.any():
        raise ParameterError(
            "digitised x range",
            f"[{x_ref.min():g}, {x_ref.max():g}]",
            f"overlapping the simulated range [{x_sim[0]:g}, {x_sim[-1]:g}]"
            + (f" by more than the shift tolerance {tol:g}" if tol else "")
            + " (no extrapolation)",
        )

    def simulated_at(shift: float) -> np.ndarray:
        x = shift_x(x_ref[compared], shift, x_scale)
        return interpolate(x_sim, y_sim, x, x_scale=x_scale, y_scale=y_scale, method=method)

    def rmse(shift: float) -> float:
        return float(np.sqrt(np.mean((simulated_at(shift) - y_ref[compared]) ** 2)))

    shift = best_shift(rmse, tol) if shift_tolerance is not None else 0.0
    y_at = np.full_like(y_ref, np.nan)
    y_at[compared] = simulated_at(shift)
    metrics = _metrics(x_ref, y_ref, y_at, compared, shift if shift_tolerance is not None else None)
    return CurveComparison(x_ref=x_ref, y_ref=y_ref, compared=compared, y_sim=y_at, metrics=metrics, x_scale=x_scale)


def best_shift(rmse, tolerance: float) -> float:
    """The shift in [-tolerance, tolerance] minimising ``rmse(shift)``: a grid scan, then Brent refinement.

    Ties go to the smallest |shift| (0 when the curve does not depend on the shift).
    """
    if tolerance == 0.0:
        return 0.0
    grid = np.linspace(-tolerance, tolerance, SHIFT_GRID_POINTS)
    values = np.array([rmse(s) for s in grid])
    order = np.lexsort((np.abs(grid), values))
    k = int(order[0])
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    refined = minimize_scalar(rmse, bounds=(lo, hi), method="bounded", options={"xatol": tolerance * 1e-9})
    if refined.success and refined.fun < values[k]:
        return float(refined.x)
    return float(grid[k])


def _simulated(x_sim, y_sim, x_scale: AxisScale, y_scale: AxisScale) -> tuple[np.ndarray, np.ndarray]:
    x_sim = np.asarray(x_sim, dtype=float)
    y_sim = np.asarray(y_sim, dtype=float)
    if x_sim.ndim != 1 or x_sim.shape != y_sim.shape or x_sim.size < 2:
        raise ParameterError("simulated curve", f"{x_sim.size} x, {y_sim.size} y", "at least 2 points, equal numbers")
    if not np.all(np.isfinite(x_sim) & np.isfinite(y_sim)):
        raise ParameterError("simulated curve", "non-finite values", "finite x and y")
    if np.any(np.diff(x_sim) <= 0.0):
        raise ParameterError("simulated x", "not strictly increasing", "strictly increasing sample points")
    if x_scale is AxisScale.LOG and x_sim[0] <= 0.0:
        raise ParameterError("simulated x", float(x_sim[0]), "> 0 on a log-scaled x axis")
    if y_scale is AxisScale.LOG and np.any(y_sim <= 0.0):
        raise ParameterError("simulated y", float(y_sim.min()), "> 0 on a log-scaled y axis")
    return x_sim, y_sim


def _metrics(x_ref, y_ref, y_at, compared, shift: float | None) -> CurveMetrics:
    dev = np.abs(y_at[compared] - y_ref[compared])
    ref = np.abs(y_ref[compared])
    nonzero = ref > 0.0
    worst = int(np.argmax(dev))
    return CurveMetrics(
        n_compared=int(compared.sum()),
        n_skipped=int((~compared).sum()),
        rmse=float(np.sqrt(np.mean(dev**2))),
        max_abs_dev=float(dev[worst]),
        max_rel_dev=float(np.max(dev[nonzero] / ref[nonzero])) if nonzero.any() else float("nan"),
        x_at_max_abs_dev=float(x_ref[compared][worst]),
        x_shift=shift,
    )
