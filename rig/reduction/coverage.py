"""Expanded uncertainty U95: the half width of the reported 95 % interval, value +- U95.

A coverage factor of 1.96 is right for a normal output only. The reduced quantities are sums of
a few dominant terms of known shape - the counters' triangular quantisation, the balance's
rectangular step bias, normal calibration and scatter terms - and the 95 % half width of such a
sum lies between 1.65 u (one rectangular term dominates) and 1.96 u (normal). We take it from the
distribution of the *linearised* model y - y0 = J (x - x0) with each input deviation drawn from
its own distribution (GUM Supplement 1's Monte Carlo applied to the first-order model: no chain
evaluations, only the Jacobian already computed): U95 = the 95 % quantile of |y - y0|. The
draws come from a fixed seed, so a reduction is reproducible; 8192 of them give U95 to about
1 % (the quantile's standard error; tested against 10^6 draws). Outputs with a NaN
uncertainty get a NaN U95.
"""

from __future__ import annotations

import functools

import numpy as np

from rig import validate
from rig.reduction.uncertainty import HALF_WIDTH_PER_U, UNIT_DRAWS, Distribution, InputSet, Propagation

DRAWS = 8_192  # Monte-Carlo draws of the linearised model [1]
SEED = 95  # fixed: the interval of a point does not change between reductions


def standard_draws(draws: int, normal: int, bounded: tuple[Distribution, ...],
                   rng: np.random.Generator) -> tuple[np.ndarray, tuple[np.ndarray, ...]]:
    """The unscaled draws, in the order the generator gives them: standard normals (draws, normal)
    if ``normal`` > 0, then one unit draw on [-1, 1] of each bounded kind in turn."""
    z = rng.standard_normal((draws, normal)) if normal else np.empty((draws, 0))
    return z, tuple(UNIT_DRAWS[kind](rng, draws) for kind in bounded)


@functools.lru_cache(maxsize=8)
def _seeded_draws(draws: int, normal: int, bounded: tuple[Distribution, ...]):
    """standard_draws from a generator seeded with SEED: every point of a reduction has the same
    inputs' kinds and so the same unscaled draws, computed once (read-only)."""
    z, units = standard_draws(draws, normal, bounded, np.random.default_rng(np.random.SeedSequence(SEED)))
    for array in (z, *units):
        array.setflags(write=False)
    return z, units


def input_deviations(inputs: InputSet, draws: int, rng: np.random.Generator | None) -> tuple[np.ndarray, np.ndarray]:
    """(indices of the inputs with u > 0, deviations x - x0 drawn for them (draws, k)) [input units]:
    the correlated normal block through the square root of its covariance, the bounded inputs
    from their own distributions (half width HALF_WIDTH_PER_U u). ``rng`` None: the generator
    seeded with SEED (its draws are remembered between calls)."""
    u = inputs.uncertainties
    active = np.flatnonzero(u > 0)
    kinds = [inputs.quantities[i].distribution for i in active]
    out = np.empty((draws, active.size))
    normal = np.array([k is Distribution.NORMAL for k in kinds], dtype=bool)
    bounded = tuple(kind for kind in kinds if kind in UNIT_DRAWS)
    if rng is None:
        z, units = _seeded_draws(draws, int(normal.sum()), bounded)
    else:
        z, units = standard_draws(draws, int(normal.sum()), bounded, rng)
    if normal.any():
        v = inputs.covariance_matrix()[np.ix_(active[normal], active[normal])]
        w, q = np.linalg.eigh(v)
        root = q * np.sqrt(np.clip(w, 0.0, None))
        out[:, normal] = np.einsum("dk,jk->dj", z, root)
    unit = iter(units)
    for j, kind in enumerate(kinds):
        if kind in UNIT_DRAWS:
            out[:, j] = next(unit) * HALF_WIDTH_PER_U[kind] * u[active[j]]
    return active, out


def expanded_uncertainty(propagation: Propagation, probability: float = 0.95, draws: int = DRAWS) -> np.ndarray:
    """Half widths U_p [output units] of the symmetric probability-p intervals about the outputs."""
    p = validate.number("probability", probability, 0.0, 1.0, lo_open=True, hi_open=True)
    validate.integer("draws", draws, 100)
    u_out = propagation.uncertainties
    result = np.full(u_out.shape, np.nan)
    ok = np.isfinite(u_out)
    if not ok.any():
        return result
    active, deviations = input_deviations(propagation.inputs, draws, None)
    if active.size == 0:
        result[ok] = 0.0
        return result
    jac = propagation.jacobian[np.ix_(ok, active)]
    # einsum, not @: a multithreaded BLAS call this small costs more in threads than in arithmetic
    spread = np.abs(np.einsum("dk,ok->do", deviations, np.where(np.isfinite(jac), jac, 0.0)))
    result[ok] = np.quantile(spread, p, axis=0)
    return result
