"""The mu <-> alpha' fixed point of the reduction (Equations §2, hard case 8) and its settings.

alpha' (eq. 21) contains mu, and the model coefficients nu_T, nu_v, nu_0 depend on alpha', so
the reduced mu solves mu = g(mu), g(mu) = the estimate from the readings with the coefficients
at alpha'(mu). With y = ln(mu), G = ln(g) we iterate y <- q y + (1 - q) G(y): the first step
uses the fixed damping q = 1 - damping (or Wegstein's with a slope known at the start), later
steps Wegstein's q = s/(s - 1) from the secant slope s of G, bounded to [Q_MIN, Q_MAX] (damping
when g falls with mu, acceleration when it rises). A cap on the iterations ends hopeless cases with NaN and a reason. At the fixed point
the slope s = d ln g/d ln mu is probed once: errors of the readings reach mu amplified by
1/|1 - s|, and s -> 1 where the measured ratio does not depend on mu - the linear regime (F_y
independent of mu), or the peak of a ratio that rises and then falls with mu (stand B with
plastic slip) - where mu is not identifiable (NaN with the reason). s > 1 (the ratio falls with mu)
is a fixed point like any other, amplified by 1/(s - 1).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

from rig import validate

State = TypeVar("State")
Q_MIN, Q_MAX = -5.0, 0.9  # bounds of Wegstein's q (the usual -5 <= q, and at least 10 % progress)
Q_FALLING_MAX = 21.0  # bound of q = s/(s - 1) where g rises faster than mu (s > 1): s >= 1.05 [1]
MAX_STEP_FACTOR = 10.0  # largest change of mu in one step [1]
MAX_LOG_STEP = math.log(MAX_STEP_FACTOR)


@dataclass(frozen=True)
class ReductionSettings:
    """Numerical settings of a reduction (no physical input lives here).

    mu_start: start of the mu <-> alpha' iteration [1] (the fixed point does not depend on it);
    damping: relaxation of the first step, in (0, 1]; tolerance: relative change of mu that
    ends the iteration; max_iterations: the cap; nu_min: |nu_v| (|nu_T| for stand B) below which
    mu_v (mu_T) is reported as NaN (hard case 8); denominator_min: |D|/a of eq. (35) below which
    mu_T is NaN; min_counts: fewest counts per channel accepted (fewer: NaN, hard case 2);
    relative_step: Jacobian step in standard uncertainties (rig.reduction.uncertainty);
    identifiability_min: smallest |1 - s| accepted at the fixed point, s = d ln g/d ln mu (errors
    in the readings are amplified by 1/|1 - s|; s -> 1 in the linear regime, hard case 8);
    significance: a reading or coefficient within this many of its own standard uncertainties of
    zero counts as zero - a friction reading that small does not drive alpha', a ratio with a
    denominator that small is not reported (hard case 8; 2 = the ~95 % level).
    """

    mu_start: float = 0.3
    damping: float = 0.5
    tolerance: float = 1e-9
    max_iterations: int = 100
    nu_min: float = 1e-3
    denominator_min: float = 1e-3
    min_counts: int = 1
    relative_step: float = 1.0
    identifiability_min: float = 0.05
    significance: float = 2.0

    def __post_init__(self) -> None:
        validate.number("mu_start", self.mu_start, 0.0, lo_open=True)
        validate.number("damping", self.damping, 0.0, 1.0, lo_open=True)
        validate.number("tolerance", self.tolerance, 0.0, 1e-2, lo_open=True)
        validate.integer("max_iterations", self.max_iterations, 1)
        validate.number("nu_min", self.nu_min, 0.0)
        validate.number("denominator_min", self.denominator_min, 0.0)
        validate.integer("min_counts", self.min_counts, 1)
        validate.number("relative_step", self.relative_step, 0.0, lo_open=True)
        validate.number("identifiability_min", self.identifiability_min, 0.0, 1.0)
        validate.number("significance", self.significance, 0.0)


@dataclass(frozen=True)
class FixedPoint(Generic[State]):
    """mu used in alpha' [1] (NaN on failure), the chain's state there, iterations, reason ('' if ok),
    and the slope d ln g/d ln mu probed there [1] (NaN when not probed)."""

    mu: float
    state: State | None
    iterations: int
    reason: str
    slope: float = math.nan


Estimate = Callable[[float], tuple[float, State, str]]


def solve_mu(estimate: Estimate, settings: ReductionSettings, probe: bool = True,
             mu_start: float | None = None, slope: float = math.nan) -> FixedPoint:
    """Solve mu = g(mu) from ``mu_start`` (None: settings.mu_start); estimate(mu) returns (g(mu) or
    NaN, state, reason for a NaN).

    The iteration runs on y = ln(mu): the coefficients are close to power laws of alpha' ~ mu,
    so the map is nearly linear in y (Wegstein then converges in a few steps) and mu stays
    positive; one step changes mu by at most a factor MAX_STEP_FACTOR. probe: check the
    identifiability at the fixed point (once per point, at the nominal readings; the perturbed
    evaluations of the Jacobian skip it). slope: d ln g/d ln mu known near the start (a perturbed
    evaluation restarts from the nominal fixed point, whose slope was probed): the first step is
    then Wegstein's with it - a Newton step - instead of the fixed damping (about one estimate
    fewer per perturbed evaluation).
    """
    y = math.log(settings.mu_start if mu_start is None else mu_start)
    y_prev = g_prev = math.nan
    for k in range(1, settings.max_iterations + 1):
        g, state, reason = estimate(math.exp(y))
        if not (math.isfinite(g) and g > 0.0):
            why = reason or f"non-positive friction estimate {g:.6g} for alpha'"
            return FixedPoint(math.nan, state, k, why)
        log_g = math.log(g)
        if abs(log_g - y) <= settings.tolerance:
            if not probe:
                return FixedPoint(math.exp(y), state, k, "")
            return _checked(estimate, math.exp(y), log_g, state, k, settings)
        if not math.isnan(y_prev):
            slope = (log_g - g_prev) / (y - y_prev)
        if math.isnan(slope):
            q = 1.0 - settings.damping
        else:
            q = wegstein_q(slope)
        step = min(max((1.0 - q) * (log_g - y), -MAX_LOG_STEP), MAX_LOG_STEP)
        y_prev, g_prev = y, log_g
        y += step
    return FixedPoint(
        math.nan, state, settings.max_iterations,
        f"mu <-> alpha' iteration did not converge in {settings.max_iterations} steps (last mu "
        f"{math.exp(y_prev):.6g} -> {math.exp(g_prev):.6g}); mu may not be identifiable from these readings "
        "(hard case 8)",
    )


def wegstein_q(slope: float) -> float:
    """Wegstein's relaxation q = s/(s - 1) for the secant slope s of G, bounded.

    s < 1 (g falls with mu, or rises more slowly than mu): q in [Q_MIN, Q_MAX]. s > 1 (g rises
    faster than mu: the measured ratio falls with mu, as on the far side of the peak of stand B's
    F_V/F_N with plastic slip): the plain iteration runs away from the fixed point, and q =
    s/(s - 1) > 1 (a secant-Newton step towards it) is kept, up to Q_FALLING_MAX. s = 1: Q_MAX.
    """
    if slope > 1.0:
        return min(slope / (slope - 1.0), Q_FALLING_MAX)
    return Q_MAX if slope == 1.0 else min(max(slope / (slope - 1.0), Q_MIN), Q_MAX)


PROBE = 1e-4  # relative step in mu for the slope of g at the fixed point [1]


def _checked(estimate: Estimate, mu: float, log_g: float, state, k: int, settings: ReductionSettings) -> FixedPoint:
    """Accept the fixed point only if g is not parallel to mu there (mu identifiable)."""
    g_probe, _, _ = estimate(mu * math.exp(PROBE))
    slope = (math.log(g_probe) - log_g) / PROBE if math.isfinite(g_probe) and g_probe > 0.0 else math.nan
    if not (abs(1.0 - slope) >= settings.identifiability_min):
        return FixedPoint(
            math.nan, state, k + 1,
            f"mu not identifiable: d ln g/d ln mu = {slope:.4g} at mu = {mu:.6g} (needs |1 - slope| >= "
            f"{settings.identifiability_min:g}; the measured ratio does not depend on mu there: the linear regime, "
            "or the peak of a ratio that is not monotone in mu, hard case 8)",
        )
    return FixedPoint(mu, state, k + 1, "", slope)


def solve_with_drivers(make_estimate: Callable[[str], Estimate], drivers: tuple[str, ...], mu_start: float,
                       probe: bool, settings: ReductionSettings, no_driver: str = "",
                       slope: float = math.nan) -> tuple[FixedPoint, str]:
    """The fixed point with the first driver (friction estimate feeding alpha') that gives one.

    make_estimate(driver) -> estimate(mu) as for :func:`solve_mu` (``slope`` too); returns (fixed
    point, driver) or, if none works, (the failure with the reasons, ""). no_driver: the reason
    when ``drivers`` is empty (rig.reduction.drivers).
    """
    tried = []
    fixed = FixedPoint(math.nan, None, 0, no_driver or "no friction estimate may drive alpha'")
    for driver in drivers:  # mu_start passed on, not replaced in settings: a replace validates, per evaluation
        fixed = solve_mu(make_estimate(driver), settings, probe, mu_start, slope)
        if not fixed.reason:
            return fixed, driver
        tried.append(f"{driver}: {fixed.reason}")
    if tried:
        fixed = dataclasses.replace(fixed, reason="; ".join(tried) if len(tried) > 1 else fixed.reason)
    return fixed, ""
