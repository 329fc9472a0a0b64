"""Weighted least squares with effective variance, profile-likelihood intervals, correlations.

chi2(theta) = sum ((y - f(theta))/u_eff)^2 with u_eff^2 = u^2 + (df/dl u_l)^2 (Orear's effective
variance: the rolling point l/a is itself measured; df/dl from the model at the start and again
at the first optimum, then held while the fit is repeated). The minimiser is
scipy.optimize.least_squares (trust-region reflective, bounds = the parameters' ranges).

95 % interval of a parameter: the values where the profile chi2 (minimised over the others)
rises 3.84 (chi2 with 1 degree of freedom) above the minimum; an end that does not rise that far
within the parameter's range is the range's end and is flagged open. Standard uncertainty and
correlations: from the Gauss-Newton covariance (J^T J)^-1 at the optimum, with J the Jacobian of
the weighted residuals. No rescaling by chi2/dof: the data's u is taken as stated (the summary
gives chi2/dof so that a poor fit is visible).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq, least_squares

from rig.errors import ConvergenceError, ParameterError
from rig.fit.forward import ForwardModel

DELTA_CHI2_95 = 3.841458820694124  # chi2 quantile 0.95, 1 degree of freedom
CORRELATION_LIMIT = 0.95
DL_STEP = 1e-3  # [units of a] finite-difference step of df/dl


class FitConvergenceError(ConvergenceError):
    """The least-squares fit did not converge; names the effect set and the optimiser's reason."""


@dataclass(frozen=True)
class ParameterEstimate:
    """Value, standard uncertainty (covariance), 95 % profile interval and whether each end is open."""

    name: str
    unit: str
    value: float
    u: float
    lo95: float
    hi95: float
    open_lo: bool
    open_hi: bool


@dataclass(frozen=True)
class FitResult:
    """One fitted effect set: estimates, correlation, chi2, information criteria, diagnostics."""

    names: tuple[str, ...]
    estimates: tuple[ParameterEstimate, ...]
    correlation: np.ndarray
    chi2: float
    n_points: int
    prediction: np.ndarray
    band: np.ndarray
    u_eff: np.ndarray
    warnings: tuple[str, ...]
    evaluations: int
    message: str
    table_error: float = float("nan")
    polished: bool = False
    extra: dict = field(default_factory=dict)

    @property
    def k(self) -> int:
        return len(self.names)

    @property
    def aic(self) -> float:
        return self.chi2 + 2.0 * self.k

    @property
    def bic(self) -> float:
        return self.chi2 + self.k * np.log(self.n_points)

    @property
    def dof(self) -> int:
        return self.n_points - self.k

    def estimate(self, name: str) -> ParameterEstimate:
        return self.estimates[self.names.index(name)]


def fit(model: ForwardModel, start: Sequence[float], *, profile: bool = True, polish: str = "auto",
        polish_ratio: float = 0.2, label: str = "") -> FitResult:
    """Fit ``model`` to its observations from ``start``; see the module docstring.

    polish: "auto" (direct-solve refit when max |table - direct| at the optimum exceeds
    polish_ratio * min u), "never" or "always".
    """
    obs = model.obs
    free = model.free
    if obs.size <= len(free):
        raise ParameterError("data points", obs.size, f"> {len(free)} (the number of free parameters)")
    lo = np.array([p.lo for p in free])
    hi = np.array([p.hi for p in free])
    x0 = np.array([p.check(v, "start value of ") for p, v in zip(free, start)])
    x0 = np.clip(x0, lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo))
    u_eff = _effective_u(model, x0)
    res = _minimise(model.predict, obs.y, u_eff, x0, lo, hi, label)
    u_eff = _effective_u(model, res.x)
    res = _minimise(model.predict, obs.y, u_eff, res.x, lo, hi, label)
    predict = model.predict
    table_error = float("nan")
    polished = False
    if polish != "never":
        table_error = float(np.max(np.abs(model.direct(res.x) - model.predict(res.x))))
        if polish == "always" or table_error > polish_ratio * float(np.min(obs.u)):
            predict = model.direct
            res = _minimise(predict, obs.y, u_eff, res.x, lo, hi, label, max_nfev=20 * (len(free) + 1))
            polished = True
    chi2 = float(np.sum(res.fun**2))
    jac = _jacobian(predict, res.x, u_eff, lo, hi)
    cov, corr = _covariance(jac)
    u = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    warnings = []
    intervals = []
    for i, p in enumerate(free):
        if profile:
            interval = _profile_interval(predict, obs.y, u_eff, res.x, lo, hi, i, chi2, label, u[i])
        else:
            interval = (max(lo[i], res.x[i] - 1.96 * u[i]), min(hi[i], res.x[i] + 1.96 * u[i]), False, False)
        intervals.append(interval)
        if interval[2] and interval[3]:
            warnings.append(f"{p.name} is not identifiable from this data: its profile is flat (chi2 rises less "
                            f"than {DELTA_CHI2_95:.2f} over the whole range [{p.lo:g}, {p.hi:g}])")
    for i, j in zip(*np.triu_indices(len(free), 1)):
        if abs(corr[i, j]) > CORRELATION_LIMIT:
            warnings.append(f"{free[i].name} and {free[j].name} are not separately identifiable: correlation "
                            f"{corr[i, j]:+.3f} (|r| > {CORRELATION_LIMIT})")
    estimates = tuple(
        ParameterEstimate(p.name, p.unit, float(res.x[i]), float(u[i]), *map(float, intervals[i][:2]),
                          bool(intervals[i][2]), bool(intervals[i][3]))
        for i, p in enumerate(free)
    )
    band = np.sqrt(np.clip(np.einsum("ij,jk,ik->i", jac * u_eff[:, None], cov, jac * u_eff[:, None]), 0, None))
    return FitResult(
        names=tuple(p.name for p in free), estimates=estimates, correlation=corr, chi2=chi2, n_points=obs.size,
        prediction=predict(res.x), band=band, u_eff=u_eff, warnings=tuple(warnings),
        evaluations=model.evaluations, message=str(res.message), table_error=table_error, polished=polished,
    )


def _effective_u(model: ForwardModel, theta: np.ndarray) -> np.ndarray:
    obs = model.obs
    if not np.any(obs.u_l > 0):
        return obs.u.copy()
    slope = (model.predict(theta, dl=DL_STEP) - model.predict(theta, dl=-DL_STEP)) / (2 * DL_STEP)
    return np.hypot(obs.u, slope * obs.u_l)


def _minimise(predict, y, u, x0, lo, hi, label, max_nfev=None):
    def residual(theta):
        return (y - predict(theta)) / u

    try:
        res = least_squares(residual, x0, bounds=(lo, hi), x_scale=hi - lo, diff_step=1e-4, max_nfev=max_nfev,
                            xtol=1e-10, ftol=1e-10)
    except ValueError as error:
        raise FitConvergenceError(f"fit {label}: the least-squares solver stopped: {error}") from None
    if not np.all(np.isfinite(res.fun)) or (res.status <= 0 and max_nfev is None):
        raise FitConvergenceError(f"fit {label} did not converge: {res.message}")
    return res


def _jacobian(predict, x, u, lo, hi) -> np.ndarray:
    """d residual/d theta = -df/dtheta / u by central differences kept inside the bounds."""
    jac = np.empty((u.size, x.size))
    for k in range(x.size):
        h = 1e-4 * (hi[k] - lo[k])
        xp, xm = x.copy(), x.copy()
        xp[k] = min(hi[k], x[k] + h)
        xm[k] = max(lo[k], x[k] - h)
        jac[:, k] = -(predict(xp) - predict(xm)) / (xp[k] - xm[k]) / u
    return jac


def _covariance(jac: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    cov = np.linalg.pinv(jac.T @ jac)
    d = np.sqrt(np.clip(np.diag(cov), 1e-300, None))
    corr = cov / np.outer(d, d)
    np.fill_diagonal(corr, 1.0)
    return cov, np.clip(corr, -1.0, 1.0)


def _profile_chi2(predict, y, u, x_best, lo, hi, i, value, label) -> float:
    others = [k for k in range(x_best.size) if k != i]

    def full(sub):
        theta = x_best.copy()
        theta[i] = value
        theta[others] = sub
        return theta

    if not others:
        return float(np.sum(((y - predict(full(np.empty(0)))) / u) ** 2))
    res = _minimise(lambda sub: predict(full(sub)), y, u, x_best[others], lo[others], hi[others], label)
    return float(np.sum(res.fun**2))


def _profile_interval(predict, y, u, x_best, lo, hi, i, chi2_min, label, scale):
    """(lo95, hi95, open_lo, open_hi): where the profile chi2 crosses chi2_min + 3.84.

    scale: the parameter's standard uncertainty; the crossings are found to 1e-3 of it.
    """
    target = chi2_min + DELTA_CHI2_95

    def excess(value):
        return _profile_chi2(predict, y, u, x_best, lo, hi, i, value, label) - target

    ends = []
    for bound in (lo[i], hi[i]):
        if bound == x_best[i] or excess(bound) < 0:
            ends.append((bound, True))
            continue
        ends.append((brentq(excess, *sorted((x_best[i], bound)), xtol=_xtol(scale, hi[i] - lo[i])), False))
    return ends[0][0], ends[1][0], ends[0][1], ends[1][1]


def _xtol(scale: float, span: float) -> float:
    return 1e-4 * span if not np.isfinite(scale) or scale <= 0 else min(1e-4 * span, 1e-3 * scale)
