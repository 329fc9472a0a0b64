"""How far a contact law's coefficients lie from the converged model at one state.

A stand's law samples a grid model on n cells across 2a, usually through a surrogate table
(rig.contact.surrogate) that also interpolates between its nodes, so a looked-up nu carries the
grid's discretisation error and the table's interpolation error. At a state (l/a, c/a, alpha')
the model is solved directly on n and 2n cells and extrapolated to zero cell size at first order:

    nu* = nu_2n + (nu_2n - nu_n) = 2 nu_2n - nu_n,          error = |law - nu*|          (per coefficient)

The kinematic solver converges monotonically at an order between 1 and 2 (nu_0 and most partial-
slip states about 2; nu_v of the circle and of narrow ellipses about 1.3, where the leading edge's
near field dominates: docs/contact-convergence.md). For any order
p >= 1 the error of nu_n is at most 2 |nu_n - nu_2n|, which this bound is; the second-order
extrapolation (nu_2n - nu_n)/3 used until 2026-11 underestimated nu_v's error by up to 1.8x.

The reduction carries this error as a rectangular component of its uncertainty budget at every
reduced point when the scene asks for it ([contact] error_budget; rig.reduction.coefficients),
so that coefficients from a coarse grid or table are not taken for exact theory. Linear theory
has no grid: its error is zero. Cost: two solves per state (about 25 ms for n = 16).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig.contact.solve import N_RANGE, solve


def converged_error(law_values: np.ndarray, model: str, fixed: dict, n: int, state: tuple[float, float, float]) -> np.ndarray:
    """|law_values - nu*| (3,) of nu_T, nu_v, nu_0 [1] at ``state`` = (l/a, c/a, alpha').

    law_values: the law's (nu_T, nu_v, nu_0) there; fixed: solve()'s other arguments (shape,
    b_over_a, poisson and the effects); n: the law's grid (cells across 2a).
    """
    if model == "linear":
        return np.zeros(3)
    l, c, a = state
    coarse, fine = (np.array(_coefficients(solve(model, alpha=a, c_over_a=c, l_over_a=l, n=m, **fixed)))
                    for m in (n, min(2 * n, N_RANGE[1])))
    return np.abs(np.asarray(law_values, dtype=float) - (2.0 * fine - coarse))


def _coefficients(result) -> tuple[float, float, float]:
    return result.nu_T, result.nu_v, result.nu_0


# --- converged references for accuracy statements --------------------------------------------------

SAFETY_FACTOR = 1.25
"""Roache's factor of safety for a grid-convergence estimate from three grids with the observed
order (ASME V&V 20-2009, section 2-4): the reference's uncertainty is (SAFETY_FACTOR - 1) times the
correction Richardson's extrapolation makes [1]."""
ORDER_RANGE = (0.5, 3.0)
"""Observed orders trusted for the extrapolation [1]; outside it, or with steps of opposite sign or
growing, the sequence is not asymptotic and the reference falls back to the finest value with an
uncertainty of UNSETTLED_FACTOR times the last step."""
UNSETTLED_FACTOR = 3.0
"""Roache's factor for an estimate without a trusted order (two grids) [1]."""
REFERENCE_GRIDS = (32, 64, 128)
"""Nominal grids n, 2n, 4n of the converged reference (rig.contact.grid: cells across 2a)."""


@dataclass(frozen=True)
class Extrapolation:
    """A converged value from three grids h, h/2, h/4 (arrays broadcast alike).

    limit: the extrapolated value; uncertainty: its own standard-like error band [unit of the
    values]; order: the observed order log2((f1 - f2)/(f2 - f3)) [1] (NaN where the steps change
    sign); trusted: the order lies in ORDER_RANGE and the extrapolation used it.
    """

    limit: np.ndarray
    uncertainty: np.ndarray
    order: np.ndarray
    trusted: np.ndarray


def richardson(coarse, medium, fine) -> Extrapolation:
    """Richardson's extrapolation of f(h), f(h/2), f(h/4) to h = 0 with the observed order.

    p = log2((f_h - f_h/2)/(f_h/2 - f_h/4)); where p lies in ORDER_RANGE, limit = f_h/4 + (f_h/4 -
    f_h/2)/(2^p - 1) with uncertainty (SAFETY_FACTOR - 1) |limit - f_h/4| (Roache's grid convergence
    index); elsewhere (steps of opposite sign, growing, or an order outside the range) limit = f_h/4
    with uncertainty UNSETTLED_FACTOR |f_h/4 - f_h/2|. A floor of 1e-6 stands for the solver's own
    tolerance (Newton 1e-6, rig.contact.newton).
    """
    f1, f2, f3 = (np.asarray(v, dtype=float) for v in (coarse, medium, fine))
    s1, s2 = f1 - f2, f2 - f3
    with np.errstate(divide="ignore", invalid="ignore"):
        order = np.where(s1 * s2 > 0.0, np.log2(s1 / s2), np.nan)
    trusted = np.isfinite(order) & (order >= ORDER_RANGE[0]) & (order <= ORDER_RANGE[1])
    p = np.where(trusted, order, 1.0)
    correction = np.where(trusted, (f3 - f2) / (2.0**p - 1.0), 0.0)
    uncertainty = np.where(trusted, (SAFETY_FACTOR - 1.0) * np.abs(correction), UNSETTLED_FACTOR * np.abs(s2))
    return Extrapolation(f3 + correction, np.maximum(uncertainty, 1e-6), order, trusted)


def converged_reference(model: str, fixed: dict, state: tuple[float, float, float],
                        grids: tuple[int, int, int] = REFERENCE_GRIDS) -> Extrapolation:
    """The converged (nu_T, nu_v, nu_0) [1] of ``model`` at ``state`` = (l/a, c/a, alpha'):
    :func:`richardson` on three doubled grids (default n = 32 / 64 / 128). fixed: solve()'s other
    arguments (shape, b_over_a, poisson, effects)."""
    l, c, a = state
    values = [np.array(_coefficients(solve(model, alpha=a, c_over_a=c, l_over_a=l, n=m, **fixed))) for m in grids]
    return richardson(*values)


FULL_SLIDING_SPIN_MOMENT_CIRCLE = 3.0 * np.pi / 16.0
"""nu_0 of rigid sliding about the centre of a Hertz circle, |M_z|/(mu a F_N) = 3 pi/16 [1]
(the integral of r p over the contact, p Hertzian: [Koziarski] eq. (26) with the slip direction
tangential everywhere; docs: Equations)."""
