"""Every fixed point of mu = g(mu) in a bracket: a scan in ln mu, then Brent's method on each sign change.

The mu <-> alpha' iteration (rig.reduction.iteration) finds *a* fixed point, the one its start
leads to. Where the measured ratio is not monotone in mu - with plastic slip (Psi > 1, eq. 25)
stand B's F_V/F_N = mu nu_v(alpha'(mu)) rises, peaks and falls again (docs/stand-b.md, "Two
roots") - eqs. (33)-(35) have more than one solution, and which one the iteration returns
depends on its start. :func:`fixed_points` finds them all: h(y) = ln g(e^y) - y is evaluated on
``points`` equally spaced y = ln mu over the bracket, and every sign change between neighbours
(or an exact zero) is refined with Brent's method to ``xtol`` in ln mu.

Limits (stated, not hidden): two roots closer than one scan step (ln(hi/lo)/(points - 1), 7.8 %
in mu for the default 48 points over [0.05, 2]) cancel and are both missed, and so is a root
where h touches zero without crossing it (a double root at the peak of the ratio); there
mu is not identifiable anyway (rig.reduction.iteration: |1 - d ln g/d ln mu| -> 0).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import brentq

from rig import validate

SCAN_POINTS = 48  # scan nodes over the bracket in ln mu [1]
XTOL = 1e-10  # Brent's tolerance in ln mu [1]


def log_residual(estimate: Callable[[float], float], y: float) -> float:
    """h(y) = ln g(e^y) - y [1]; NaN where g has no positive finite value."""
    g = estimate(math.exp(y))
    return math.log(g) - y if math.isfinite(g) and g > 0.0 else math.nan


def fixed_points(estimate: Callable[[float], float], lo: float, hi: float, points: int = SCAN_POINTS,
                 xtol: float = XTOL) -> tuple[float, ...]:
    """The fixed points mu = estimate(mu) in [lo, hi] [1], ascending (module docstring).

    estimate(mu) -> g(mu) [1] or NaN (no estimate there: that scan interval is skipped).
    """
    lo = validate.number("lo", lo, 0.0, lo_open=True)
    hi = validate.number("hi", hi, lo, lo_open=True)
    points = validate.integer("points", points, 2)
    ys = np.linspace(math.log(lo), math.log(hi), points)
    hs = [log_residual(estimate, float(y)) for y in ys]
    roots: list[float] = []
    for k, (y, h) in enumerate(zip(ys, hs)):
        if h == 0.0:
            roots.append(float(y))
            continue
        if k + 1 == points:
            break
        h_next = hs[k + 1]
        if math.isfinite(h) and math.isfinite(h_next) and h_next != 0.0 and (h < 0.0) != (h_next < 0.0):
            roots.append(brentq(lambda t: log_residual(estimate, t), float(y), float(ys[k + 1]), xtol=xtol))
    return tuple(math.exp(y) for y in roots)
