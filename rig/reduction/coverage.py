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
import math
import threading

import numpy as np

from rig import validate
from rig.reduction.uncertainty import HALF_WIDTH_PER_U, UNIT_DRAWS, Distribution, InputSet, Propagation

DRAWS = 8_192  # Monte-Carlo draws of the linearised model [1]
SEED = 95  # fixed: the interval of a point does not change between reductions


def standard_draws(draws: int, normal: int, bounded: tuple[Distribution, ...],
                   rng: np.random.Generator) -> np.ndarray:
    """The unscaled draws as rows (normal + len(bounded), draws), in the order the generator gives
    them: ``normal`` rows of standard normals (drawn as one (draws, normal) block), then one row of
    unit draws on [-1, 1] for each bounded kind in turn."""
    z = rng.standard_normal((draws, normal)) if normal else np.empty((draws, 0))
    # C order: the products take blocks of columns (np.vstack would keep z.T's Fortran order)
    return np.ascontiguousarray(np.vstack([z.T, *(UNIT_DRAWS[kind](rng, draws) for kind in bounded)]))


@functools.lru_cache(maxsize=8)
def _seeded_draws(draws: int, normal: int, bounded: tuple[Distribution, ...]) -> np.ndarray:
    """standard_draws from a generator seeded with SEED: every point of a reduction has the same
    inputs' kinds and so the same unscaled draws, computed once (read-only)."""
    rows = standard_draws(draws, normal, bounded, np.random.default_rng(np.random.SeedSequence(SEED)))
    rows.setflags(write=False)
    return rows


def input_deviations(inputs: InputSet, draws: int,
                     rng: np.random.Generator | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(indices of the inputs with u > 0, unscaled draws ``rows`` (m, draws), ``scale`` (m, k)): the
    deviations x - x0 drawn for the k inputs are rows.T @ scale [input units] - the correlated
    normal block through the square root of its covariance, the bounded inputs from their own
    distributions (half width HALF_WIDTH_PER_U u). ``rng`` None: the generator seeded with SEED
    (its draws are remembered between calls)."""
    u = inputs.uncertainties
    active = np.flatnonzero(u > 0)
    kinds = [inputs.quantities[i].distribution for i in active]
    normal = np.array([k is Distribution.NORMAL for k in kinds], dtype=bool)
    bounded = tuple(kind for kind in kinds if kind in UNIT_DRAWS)
    n_normal = int(normal.sum())
    if rng is None:
        rows = _seeded_draws(draws, n_normal, bounded)
    else:
        rows = standard_draws(draws, n_normal, bounded, rng)
    scale = np.zeros((rows.shape[0], active.size))
    if normal.any():
        v = inputs.covariance_matrix()[np.ix_(active[normal], active[normal])]
        w, q = np.linalg.eigh(v)
        scale[:n_normal, normal] = (q * np.sqrt(np.clip(w, 0.0, None))).T
    row = n_normal
    for j, kind in enumerate(kinds):
        if kind in UNIT_DRAWS:
            scale[row, j] = HALF_WIDTH_PER_U[kind] * u[active[j]]
            row += 1
    return active, rows, scale


def expanded_uncertainty(propagation: Propagation, probability: float = 0.95, draws: int = DRAWS) -> np.ndarray:
    """Half widths U_p [output units] of the symmetric probability-p intervals about the outputs."""
    p = validate.number("probability", probability, 0.0, 1.0, lo_open=True, hi_open=True)
    validate.integer("draws", draws, 100)
    u_out = propagation.uncertainties
    result = np.full(u_out.shape, np.nan)
    ok = np.isfinite(u_out)
    if not ok.any():
        return result
    active, rows, scale = input_deviations(propagation.inputs, draws, None)
    if active.size == 0:
        result[ok] = 0.0
        return result
    jac = propagation.jacobian[np.ix_(ok, active)]
    # y - y0 = J (rows.T scale).T: the small product first, then (outputs, draws) rows that hold each
    # output's draws contiguously for the quantile
    left = np.where(np.isfinite(jac), jac, 0.0) @ scale.T
    moved = np.flatnonzero(left.any(axis=1))  # an output no input moves (e.g. c at Delta h = 0) has U = 0 exactly
    found = np.zeros(left.shape[0])
    if moved.size:
        spread = _product(left[moved], rows)
        found[moved] = row_quantiles(np.abs(spread, out=spread), p)  # in place: a second array costs page faults
    result[ok] = found
    return result


DRAW_BLOCK = 1_024
"""Draws per matrix product [1]: a product of (outputs, m) by (m, 8192) is small enough for one
core but above OpenBLAS's threshold for threads, and on a busy machine the threads cost more than
the arithmetic (measured at load average 2: U95 3.2 ms a point with them, 1.4 ms with
OPENBLAS_NUM_THREADS=1); products over blocks of 1 024 draws stay on one thread (0.06 ms a point)."""


_reused = threading.local()


def _reused_array(name: str, shape: tuple[int, int], dtype: type) -> np.ndarray:
    """An uninitialised array of ``shape`` in this thread's buffer ``name``, kept between calls (grown
    when too small). The product of a point is about 1 MB: allocated afresh for every point, it is
    mapped from the system and faulted in page by page whenever malloc's trim threshold is fixed -
    as a Dask nanny fixes it (MALLOC_TRIM_THRESHOLD_ = 65536) - which cost a Dask worker's reduction
    about 15 % more CPU time than a local process's; a reused buffer is faulted in once per thread."""
    size = shape[0] * shape[1]
    buffer = getattr(_reused, name, None)
    if buffer is None or buffer.size < size:
        buffer = np.empty(size, dtype=dtype)
        setattr(_reused, name, buffer)
    return buffer[:size].reshape(shape)


def _product(left: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """left @ rows, computed in blocks of DRAW_BLOCK columns, into this thread's reused buffer (valid
    until the next call in the thread)."""
    out = _reused_array("product", (left.shape[0], rows.shape[1]), np.float64)
    for start in range(0, rows.shape[1], DRAW_BLOCK):
        block = slice(start, start + DRAW_BLOCK)
        np.matmul(left, rows[:, block], out=out[:, block])
    return out


PREFILTER_STRIDE = 8  # every 8th draw estimates where the upper tail starts (row_quantiles)


def row_quantiles(rows: np.ndarray, p: float) -> np.ndarray:
    """np.quantile(rows, p, axis=1) (its default "linear" method), the same numbers, faster for an
    upper quantile of many draws: a selection over the whole row costs as much as the rest of a
    reduction, so each row's candidates are first cut to the values at or above a threshold
    taken from every PREFILTER_STRIDE-th draw (all rows' candidates in one flat selection, three
    times as fast as a mask per row); where fewer than the needed order statistics pass (or a row
    holds a NaN), that row is done by np.quantile itself. The order statistics and numpy's
    interpolation between them (Hyndman and Fan's method 7) are then exactly numpy's."""
    m, n = rows.shape
    virtual = (n - 1) * p  # numpy's virtual index of the method
    below = math.floor(virtual)
    gamma = virtual - below
    top = n - below  # the order statistics below..n-1: the values the quantile needs lie among them
    sample = rows[:, ::PREFILTER_STRIDE]
    rank = max(sample.shape[1] - 1 - 2 * (top * sample.shape[1]) // n, 0)  # about twice the tail's share
    thresholds = np.partition(sample, rank, axis=1)[:, rank]
    kept = np.flatnonzero(np.greater_equal(rows, thresholds[:, None], out=_reused_array("kept", rows.shape, bool)))
    candidates = rows.ravel().take(kept)
    ends = np.cumsum(np.bincount(kept // n, minlength=m)).tolist()
    has_nan = np.isnan(rows).any(axis=1)  # a NaN fails every comparison: it would slip past the cut
    result = np.empty(m)
    for i, (start, end) in enumerate(zip([0] + ends[:-1], ends)):
        if end - start < top or has_nan[i]:
            result[i] = np.quantile(rows[i], p)
            continue
        k = end - start - top  # position of order statistic ``below`` among the row's candidates
        nxt = min(k + 1, end - start - 1)
        part = np.partition(candidates[start:end], (k, nxt))
        a, b = part[k], part[nxt]
        diff = b - a  # numpy's _lerp
        result[i] = b - diff * (1.0 - gamma) if gamma >= 0.5 else a + diff * gamma
    return result
