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
