"""Weighted least squares with effective variance, profile-likelihood intervals, correlations.

chi2(theta) = r^T V(theta)^-1 r, r = y - f(theta), V = diag(u_eff^2) + C: u_eff^2 = u_i^2 +
(df/dl u_l)^2 + s^2 with u_i the independent part of the stated u, and C the covariance of errors
shared between points (a calibration, a zero drift; rig.fit.common_errors), its calibration's
relative part at the values the points are adjusted to (Objective.weights). The rolling point l/a is
itself measured: minimising over the true l/a of every point (orthogonal distance regression)
with f linearised in l gives exactly this chi2 with df/dl taken *at theta* (Orear's effective
variance; Deming's regression for a straight line). df/dl therefore moves with theta inside the
minimisation: held fixed, the weights do not see that a larger slope also spreads the data, and
the estimate is attenuated like a least-squares slope on a noisy regressor (measured on stand-A
runs: mu 0.13 % low, docs/fit.md). The residuals are whitened by a linear map W with
|W r|^2 = r^T V^-1 r (Weights: V's O(N) structured form, rig.fit.covariance, so no N x N matrix is
formed; the Cholesky factor of V where a dense common covariance is given) and minimised with
scipy.optimize.least_squares (trust-region reflective, bounds = the ranges).

95 % interval of a parameter: the values where the profile chi2 (minimised over the others)
rises 3.84 (chi2 with 1 degree of freedom) above the minimum; an end that does not rise that far
within the parameter's range is the range's end and is flagged open. Standard uncertainty and
correlations: from the Gauss-Newton covariance (J^T J)^-1 at the optimum, with J the Jacobian of
the weighted residuals. The data's u is taken as stated; where it is a guess (a digitised
curve) and chi2 has p < MISFIT_ALPHA, u and the intervals are widened by the Birge ratio
sqrt(chi2/dof) (widen_misfit); the goodness of fit is reported by rig.fit.run either way.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_triangular
from scipy.optimize import brentq, least_squares
from scipy.stats import chi2 as chi2_dist

from rig.errors import ConvergenceError, ParameterError
from rig.fit.forward import ForwardModel

DELTA_CHI2_95 = 3.841458820694124  # chi2 quantile 0.95, 1 degree of freedom
MISFIT_ALPHA = 0.01  # chi2 p-value below which the data scatter more than their u explains
CORRELATION_LIMIT = 0.95
DL_STEP = 1e-3  # [units of a] finite-difference step of df/dl
DIRECT_CHECK_POINTS = 200  # at most this many points get direct solves for the table check (no polish beyond)
TABLE_ERROR_FRACTION = 0.2  # table-vs-direct error, as a fraction of a point's u, above which the fit warns
COVARIANCE_FORM = "structured"  # "dense": the N x N Cholesky form (tests compare the two on small data)
RETRY_NFEV_PER_PARAMETER = 1000  # evaluations of a second attempt when the first's 100 a parameter ran out
PROFILE_STEPS = 6  # profile values tried between the estimate and a range's end (2, 4, ... 64 u)


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
    scatter: float = 0.0
    table_error_ratio: float = float("nan")
    birge: float = 1.0
    direct_checked: int = 0  # points whose table value was checked against direct solves
    profiles: dict | None = None  # name -> (k, 2) array of (value, profile chi2 - minimum) [in Birge-scaled chi2]
    u_point: np.ndarray | None = None  # the point-to-point part of u_eff (without the shared errors)

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
        polish_ratio: float = 0.2, label: str = "", scatter: float | None = 0.0,
        widen_misfit: bool = False) -> FitResult:
    """Fit ``model`` to its observations from ``start``; see the module docstring.

    polish: "auto" (direct-solve refit of the estimate when max |table - direct| at the
    optimum exceeds polish_ratio * min u; the table's profile intervals and covariance are then
    moved to the polished estimate), "check" (report table - direct, never refit), "never" or
    "always". scatter: independent scatter s added to every point's u (u_eff^2 += s^2)
    [units of y]; None estimates it (see estimate_scatter). widen_misfit: where chi2 of the
    fit has p < MISFIT_ALPHA against its degrees of freedom, widen u and the intervals by the Birge
    ratio R = sqrt(chi2/dof) (every u scaled by R: u times R, the profile threshold 3.84 R^2;
    FitResult.birge says so) - for data whose u is a guess (a digitised curve's --sigma).
    """
    obs = model.obs
    free = model.free
    if obs.size <= len(free):
        raise ParameterError("data points", obs.size, f"> {len(free)} (the number of free parameters)")
    lo = np.array([p.lo for p in free])
    hi = np.array([p.hi for p in free])
    x0 = np.array([p.check(v, "start value of ") for p, v in zip(free, start)])
    x0 = np.clip(x0, lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo))
    objective = Objective(model, 0.0 if scatter is None else float(scatter))
    res = _minimise(objective.residual, x0, lo, hi, label)
    for _ in range(3 if scatter is None else 0):
        objective = Objective(model, estimate_scatter(model, res.x, obs.size - len(free)))
        res = _minimise(objective.residual, res.x, lo, hi, label)
    s = objective.scatter
    weights = objective.weights(res.x)
    predict = model.predict
    chi2 = float(np.sum(res.fun**2))
    slopes = _slopes(predict, res.x, lo, hi)
    jac = np.column_stack([-weights(column) for column in slopes.T]) if slopes.size else slopes
    cov, corr = _covariance(jac)
    x_table, chi2_table = res.x, chi2
    table_error = float("nan")
    polished = False
    table_error_ratio = float("nan")
    checked = obs.size
    if polish != "never":
        if obs.size > DIRECT_CHECK_POINTS:  # direct solves at a spread sample of the points
            at = np.unique(np.linspace(0, obs.size - 1, DIRECT_CHECK_POINTS).round().astype(int))
            difference = np.abs(model.direct(res.x, at=at) - model.predict(res.x)[at])
            u_at = weights.u_total[at]
            checked = at.size
        else:
            difference = np.abs(model.direct(res.x) - model.predict(res.x))
            u_at = weights.u_total
        table_error = float(np.max(difference))
        table_error_ratio = float(np.max(difference / u_at))
        if obs.size > DIRECT_CHECK_POINTS:
            pass  # a direct-solve refit of this many points is out of reach: the check is reported, never applied
        elif polish == "always" or (polish == "auto" and table_error > polish_ratio * float(np.min(obs.u))):
            res = _minimise(Objective(model, s, model.direct).residual, res.x, lo, hi, label,
                            max_nfev=20 * (len(free) + 1))
            chi2 = float(np.sum(res.fun**2))
            polished = True
    dof = obs.size - len(free)
    birge = 1.0
    if widen_misfit and dof > 0 and chi2 > dof and chi2_dist.sf(chi2, dof) < MISFIT_ALPHA:
        birge = float(np.sqrt(chi2 / dof))  # of the final chi2 (after a polish)
        cov = cov * birge**2
    u = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    warnings = []
    if table_error_ratio > TABLE_ERROR_FRACTION and not polished:
        warnings.append(f"the table/node interpolation errs by up to {table_error:.2g} at the optimum, "
                        f"{table_error_ratio:.2g} of a point's u (> {TABLE_ERROR_FRACTION:g}): the estimates may "
                        "carry it; refit with --polish always (direct solves at the optimum) or a finer --n")
    intervals = []
    profiles = {}
    for i, p in enumerate(free):
        if profile:
            visited = [(float(x_table[i]), chi2_table)]
            interval = _profile_interval(objective.residual, x_table, lo, hi, i, chi2_table, label, u[i],
                                         DELTA_CHI2_95 * birge**2, visited)
            shift = res.x[i] - x_table[i]  # polished: the table's profile moved to the direct optimum
            points = np.array(sorted(visited))
            profiles[p.name] = np.column_stack([points[:, 0] + shift, (points[:, 1] - chi2_table) / birge**2])
            interval = (max(lo[i], interval[0] + shift), min(hi[i], interval[1] + shift), *interval[2:])
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
    band = np.sqrt(np.clip(np.einsum("ij,jk,ik->i", slopes, cov, slopes), 0, None))
    return FitResult(
        names=tuple(p.name for p in free), estimates=estimates, correlation=corr, chi2=chi2, n_points=obs.size,
        prediction=(model.direct if polished else predict)(res.x), band=band, u_eff=weights.u_total,
        warnings=tuple(warnings), evaluations=model.evaluations, message=str(res.message), table_error=table_error,
        polished=polished, scatter=s, table_error_ratio=table_error_ratio, birge=birge, profiles=profiles,
        direct_checked=checked if polish != "never" else 0,
        u_point=weights.u_eff,
    )


class Objective:
    """Whitened residuals L(theta)^-1 (y - f(theta)) of a model, with V(theta) = L L^T from the
    effective u and the common errors at the same theta (module docstring); scatter s [units of
    y]; predict: f (default the model's table prediction; the polish passes the direct solves,
    df/dl stays the table's)."""

    def __init__(self, model: ForwardModel, scatter: float, predict=None) -> None:
        self.model = model
        self.scatter = scatter
        self.predict = model.predict if predict is None else predict

    def weights(self, theta: np.ndarray, prediction: np.ndarray | None = None) -> Weights:
        """V at theta; prediction: f(theta) when the caller has it already.

        The calibration's relative error multiplies the true y, estimated by the values the
        linearised orthogonal distance regression adjusts the points to, f + (df/dl u_l)^2 V*^-1 r
        (V*: V without that error): their error is uncorrelated with r. Taking f at the measured
        l/a instead (error df/dl dl) or the measured y (error the y noise) correlates them with r
        and biases the fit (Peelle's pertinent puzzle, rig.fit.common_errors).
        """
        obs = self.model.obs
        from_l = regressor_variance(self.model, theta)
        u_eff = np.sqrt(obs.u_independent**2 + from_l + self.scatter**2)
        if obs.common is None:
            return Weights(u_eff, None)
        prediction = self.predict(theta) if prediction is None else prediction
        adjusted = prediction
        if np.any(from_l > 0):
            residual = obs.y - prediction
            if COVARIANCE_FORM == "dense" or obs.common.fixed is not None:
                others = obs.common.covariance(None) + np.diag(u_eff**2)
                adjusted = prediction + from_l * np.linalg.solve(others, residual)
            else:
                floor = np.maximum(u_eff**2, 1e-9 * obs.common.variance(None) + 1e-300)
                adjusted = prediction + from_l * obs.common.structured(None, floor).solve(residual)
        if COVARIANCE_FORM == "dense" or obs.common.fixed is not None:
            return Weights(u_eff, obs.common.covariance(adjusted))
        return Weights(u_eff, obs.common, adjusted)

    def residual(self, theta: np.ndarray) -> np.ndarray:
        prediction = self.predict(theta)
        return self.weights(theta, prediction)(self.model.obs.y - prediction)


class Weights:
    """Whitening of residuals: a linear map W with |W r|^2 = r^T V^-1 r, V = diag(u_eff^2) + C.

    u_eff: the independent u per point; common: None (V diagonal, W r = r / u_eff), C as an
    (N, N) matrix (W = L^-1 with V = L L^T), or CommonErrors with the values ``at`` its
    sensitivity's part is taken (W: rig.fit.covariance.StructuredCovariance.whiten, O(N) memory;
    W r is then N + K + m long). The diagonal is kept at least (1 + 1e-9) diag C so that V stays
    positive definite when u_eff is 0.
    """

    def __init__(self, u_eff: np.ndarray, common, at: np.ndarray | None = None) -> None:
        self.u_eff = u_eff
        self.factor = None
        self.structured = None
        if common is None:
            self.u_total = u_eff
        elif isinstance(common, np.ndarray):
            v = common.copy()
            v[np.diag_indices_from(v)] = np.maximum(u_eff**2, 1e-9 * np.diag(common)) + np.diag(common)
            self.factor = np.linalg.cholesky(v)
            self.u_total = np.sqrt(np.diag(v))
        else:
            shared = common.variance(at)
            self.structured = common.structured(at, np.maximum(u_eff**2, 1e-9 * shared))
            self.u_total = np.sqrt(self.structured.diagonal())

    def __call__(self, r: np.ndarray) -> np.ndarray:
        if self.structured is not None:
            return self.structured.whiten(r)
        if self.factor is None:
            return r / self.u_eff
        return solve_triangular(self.factor, r, lower=True, check_finite=False)


def regressor_variance(model: ForwardModel, theta: np.ndarray) -> np.ndarray:
    """(df/dl u_l)^2 per point [units of y^2]: the measured rolling point's error carried to y."""
    obs = model.obs
    if not np.any(obs.u_l > 0):
        return np.zeros(obs.size)
    slope = (model.predict(theta, dl=DL_STEP) - model.predict(theta, dl=-DL_STEP)) / (2 * DL_STEP)
    return (slope * obs.u_l) ** 2


def estimate_scatter(model: ForwardModel, theta: np.ndarray, dof: int) -> float:
    """Independent scatter s [units of y] that makes chi2(theta) = dof; 0 when chi2 <= dof already.

    For run data whose stated u misses an independent part (e.g. the dynamometer's noise and
    drift when u is all calibration): the usual Birge-type estimate, applied to the independent
    part only, so that the common calibration error keeps its stated size.
    """

    def excess(log_s: float) -> float:
        return float(np.sum(Objective(model, float(np.exp(log_s))).residual(theta) ** 2)) - dof

    lo = np.log(1e-6 * float(np.median(model.obs.u)))
    if dof <= 0 or excess(lo) <= 0:
        return 0.0
    hi = np.log(10.0 * float(np.max(np.abs(model.obs.y - model.predict(theta)))) + 1e-300)
    return float(np.exp(brentq(excess, lo, hi, xtol=1e-3)))


def _minimise(residual, x0, lo, hi, label, max_nfev=None):
    def solve(start, budget):
        return least_squares(residual, start, bounds=(lo, hi), x_scale=hi - lo, diff_step=1e-4, max_nfev=budget,
                             xtol=1e-8, ftol=1e-8)

    try:
        res = solve(x0, max_nfev)
        if res.status == 0 and max_nfev is None:
            # out of evaluations while still descending (seen in a profile at a range end, where the
            # correlated drift covariance makes chi2 ~ 1e6 and the step crawls): go on once from there
            res = solve(res.x, RETRY_NFEV_PER_PARAMETER * np.size(x0))
    except ValueError as error:
        raise FitConvergenceError(f"fit {label}: the least-squares solver stopped: {error}") from None
    if not np.all(np.isfinite(res.fun)) or (res.status <= 0 and max_nfev is None):
        raise FitConvergenceError(f"fit {label} did not converge: {res.message}")
    return res


def _slopes(predict, x, lo, hi) -> np.ndarray:
    """df/dtheta (N, k) by central differences kept inside the bounds."""
    columns = []
    for k in range(x.size):
        h = 1e-4 * (hi[k] - lo[k])
        xp, xm = x.copy(), x.copy()
        xp[k] = min(hi[k], x[k] + h)
        xm[k] = max(lo[k], x[k] - h)
        columns.append((predict(xp) - predict(xm)) / (xp[k] - xm[k]))
    return np.column_stack(columns) if columns else np.zeros((0, 0))


def _covariance(jac: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    cov = np.linalg.pinv(jac.T @ jac)
    d = np.sqrt(np.clip(np.diag(cov), 1e-300, None))
    corr = cov / np.outer(d, d)
    np.fill_diagonal(corr, 1.0)
    return cov, np.clip(corr, -1.0, 1.0)


def _profile_chi2(residual, x_best, lo, hi, i, value, label) -> float:
    others = [k for k in range(x_best.size) if k != i]

    def full(sub):
        theta = x_best.copy()
        theta[i] = value
        theta[others] = sub
        return theta

    if not others:
        return float(np.sum(residual(full(np.empty(0))) ** 2))
    res = _minimise(lambda sub: residual(full(sub)), x_best[others], lo[others], hi[others], label)
    return float(np.sum(res.fun**2))


def _profile_interval(residual, x_best, lo, hi, i, chi2_min, label, scale, delta=DELTA_CHI2_95, visited=None):
    """(lo95, hi95, open_lo, open_hi): where the profile chi2 crosses chi2_min + 3.84 (delta).

    scale: the parameter's standard uncertainty; the crossings are found to 1e-3 of it.
    visited: a list that receives every (value, profile chi2) evaluated (for the profile plot).
    """
    visited = [] if visited is None else visited
    target = chi2_min + delta

    def excess(value):
        chi2 = _profile_chi2(residual, x_best, lo, hi, i, value, label)
        visited.append((float(value), chi2))
        return chi2 - target

    ends = []
    for bound in (lo[i], hi[i]):
        inner = x_best[i]
        for trial in _outward_steps(x_best[i], bound, scale):
            if excess(trial) >= 0:
                ends.append((brentq(excess, *sorted((inner, trial)), xtol=_xtol(scale, hi[i] - lo[i])), False))
                break
            inner = trial
        else:
            ends.append((bound, True))
    return ends[0][0], ends[1][0], ends[0][1], ends[1][1]


def _outward_steps(start: float, bound: float, scale: float) -> list[float]:
    """Where the profile is tried on the way from the estimate ``start`` to ``bound``: 2, 4, 8, ...
    64 standard uncertainties ``scale`` out (at most PROFILE_STEPS values), the bound last (only
    the bound when scale is not a positive number; none when start is the bound). The crossing is
    then bracketed between the last value below the threshold and the first above it, close to
    the estimate: the profile is not evaluated far out in the range (each value far out costs the
    forward model's node tables there, rig.fit.forward) when it has crossed within a few u, as it
    does where the parameter is identifiable (chi2 rises by (x/u)^2: 4 at 2u)."""
    if bound == start:
        return []
    steps = []
    if np.isfinite(scale) and scale > 0:
        distance = 2.0 * scale
        while distance < abs(bound - start) and len(steps) < PROFILE_STEPS:
            steps.append(start + np.copysign(distance, bound - start))
            distance *= 2.0
    return steps + [bound]


def _xtol(scale: float, span: float) -> float:
    return 1e-4 * span if not np.isfinite(scale) or scale <= 0 else min(1e-4 * span, 1e-3 * scale)
