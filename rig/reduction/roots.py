"""Every fixed point of mu = g(mu) in a bracket: a scan in ln mu, then Brent's method on each sign change.

The mu <-> alpha' iteration (rig.reduction.iteration) finds *a* fixed point, the one its start
leads to. Where the measured ratio is not monotone in mu - with plastic slip (Psi > 1, eq. 25)
stand B's F_V/F_N = mu nu_v(alpha'(mu)) rises, peaks and falls again (docs/stand-b.md, "Two
roots") - eqs. (33)-(35) have more than one solution, and which one the iteration returns
depends on its start. :func:`fixed_points` finds them all: h(y) = ln g(e^y) - y is evaluated on
``points`` equally spaced y = ln mu over the bracket, and every sign change between neighbours
(or an exact zero) is refined with Brent's method to ``xtol`` in ln mu.

Two roots on either side of a peak or a trough of the ratio that lie within one scan step of each
other leave no sign change between the nodes. So at every node where |h| is smallest among its
neighbours (one neighbour at the ends of the bracket), with h of one sign at all of them (h turns
back towards zero there, or heads for zero at an end), the extremum of h between those neighbours
is located (bounded Brent minimisation to ``xtol``): if h crosses zero there, both crossings are
refined with Brent's method; if it touches zero exactly, the touching point is a (double) root.
Without this a pair of roots a fraction of a per cent apart - the true mu sitting next to a trough
of the ratio - was lost, and a root elsewhere in the bracket was reported as the only one. Where
the ratio is monotone, |h| has no such node between the ends and nothing is added to the scan.

An extremum of h that stays on one side of zero is a turning point of the ratio that the reading
misses - by a margin that may be smaller than the reading's uncertainty (a peak just below the
reading, a trough just above it): :func:`scan` returns those turning points with h there, for the
caller to weigh against the uncertainty (rig.reduction.stand_b: a turning point within
``significance`` u of the reading is a root as far as the readings can tell).

Limits (stated, not hidden): two extrema of h closer than about two scan steps (a step is
ln(hi/lo)/(points - 1), 7.8 % in mu for the default 48 points over [0.05, 2]), e.g. three roots
within two steps, are not all resolved; nor is a pair whose dip below zero is lost in rounding
(roots closer than about 1e-6 in ln mu).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from rig import validate

SCAN_POINTS = 48  # scan nodes over the bracket in ln mu [1]
XTOL = 1e-10  # Brent's tolerance in ln mu [1]


def log_residual(estimate: Callable[[float], float], y: float) -> float:
    """h(y) = ln g(e^y) - y [1]; NaN where g has no positive finite value."""
    g = estimate(math.exp(y))
    return math.log(g) - y if math.isfinite(g) and g > 0.0 else math.nan


@dataclass(frozen=True)
class TurningPoint:
    """An extremum of h strictly inside the bracket where h does not reach zero: mu there [1] and
    h = ln g(mu) - ln mu there [1] (its distance from a root, in ln of the estimate)."""

    mu: float
    residual: float


@dataclass(frozen=True)
class RootScan:
    """What :func:`scan` found: the fixed points [1], ascending, and the turning points of h that
    miss zero, ascending in mu."""

    roots: tuple[float, ...]
    turning_points: tuple[TurningPoint, ...]


def _near_extremum(h: Callable[[float], float], left: float, right: float, sign: float,
                   xtol: float) -> tuple[list[float], float, float]:
    """(roots of h [ln mu] strictly inside (left, right), where h has the sign ``sign`` at both ends
    and at the node between them: none, one (h touches zero) or two (h crosses zero and returns);
    y and h at the extremum)."""
    best = minimize_scalar(lambda t: sign * h(t), bounds=(left, right), method="bounded",
                           options={"xatol": xtol})
    y_star = float(best.x)
    h_star = h(y_star)
    if not math.isfinite(h_star) or (h_star != 0.0 and (h_star < 0.0) == (sign < 0.0)):
        return [], y_star, h_star
    if h_star == 0.0:
        return [y_star], y_star, h_star
    return [brentq(h, left, y_star, xtol=xtol), brentq(h, y_star, right, xtol=xtol)], y_star, h_star


def scan(estimate: Callable[[float], float], lo: float, hi: float, points: int = SCAN_POINTS,
         xtol: float = XTOL) -> RootScan:
    """The fixed points mu = estimate(mu) in [lo, hi] [1] and the turning points of h that miss
    zero (module docstring).

    estimate(mu) -> g(mu) [1] or NaN (no estimate there: that scan interval is skipped).
    """
    lo = validate.number("lo", lo, 0.0, lo_open=True)
    hi = validate.number("hi", hi, lo, lo_open=True)
    points = validate.integer("points", points, 2)
    ys = np.linspace(math.log(lo), math.log(hi), points)
    hs = [log_residual(estimate, float(y)) for y in ys]

    def h(t: float) -> float:
        return log_residual(estimate, t)

    roots: list[float] = []
    turning: list[TurningPoint] = []
    for k, (y, h_k) in enumerate(zip(ys, hs)):
        if h_k == 0.0:
            roots.append(float(y))
            continue
        if math.isfinite(h_k):
            window = (max(k - 1, 0), min(k + 1, points - 1))  # one step each side, inside the bracket
            near = [hs[j] for j in window if j != k]
            same_sign = all(math.isfinite(v) and v != 0.0 and (v < 0.0) == (h_k < 0.0) for v in near)
            if same_sign and abs(h_k) <= min(abs(v) for v in near) and abs(h_k) < max(abs(v) for v in near):
                found, y_star, h_star = _near_extremum(h, float(ys[window[0]]), float(ys[window[1]]),
                                                       math.copysign(1.0, h_k), xtol)
                roots.extend(found)
                # a turning point lies below both window ends; a minimum at a bracket end is none
                inside = abs(h_star) < min(abs(hs[window[0]]), abs(hs[window[1]]))
                if not found and inside and math.isfinite(h_star):
                    turning.append(TurningPoint(math.exp(y_star), h_star))
        if k + 1 == points:
            break
        h_next = hs[k + 1]
        if math.isfinite(h_k) and math.isfinite(h_next) and h_next != 0.0 and (h_k < 0.0) != (h_next < 0.0):
            roots.append(brentq(h, float(y), float(ys[k + 1]), xtol=xtol))
    roots.sort()
    unique = [y for k, y in enumerate(roots) if k == 0 or y - roots[k - 1] > 2.0 * xtol]  # windows overlap
    turning.sort(key=lambda t: t.mu)
    distinct = [t for k, t in enumerate(turning) if k == 0 or math.log(t.mu / turning[k - 1].mu) > 2.0 * xtol]
    return RootScan(tuple(math.exp(y) for y in unique), tuple(distinct))


def fixed_points(estimate: Callable[[float], float], lo: float, hi: float, points: int = SCAN_POINTS,
                 xtol: float = XTOL) -> tuple[float, ...]:
    """The fixed points mu = estimate(mu) in [lo, hi] [1], ascending (module docstring)."""
    return scan(estimate, lo, hi, points, xtol).roots
