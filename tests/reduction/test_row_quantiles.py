"""U95's quantile: rig.reduction.coverage.row_quantiles gives np.quantile's numbers, bit for bit.

row_quantiles selects among a prefiltered tail instead of the whole row (issue 12); it must
return exactly what np.quantile(rows, p, axis=1) returns (the default "linear" method), for
spreads like the reduction's (|normal|, heavy tails), for ties, for rows whose tail is too short
for the prefilter (the fallback), and for NaN.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.reduction.coverage import row_quantiles

PROBABILITIES = (0.95, 0.5, 0.99, 0.9999, 0.01)


def _rows(kind: str, shape: tuple[int, int], rng: np.random.Generator) -> np.ndarray:
    if kind == "normal":
        return np.abs(rng.standard_normal(shape))
    if kind == "cauchy":
        return np.abs(rng.standard_cauchy(shape))
    if kind == "ties":
        return rng.integers(0, 5, shape).astype(float)
    rows = np.abs(rng.standard_normal(shape))  # "half zero": a long run of equal values below the tail
    rows[:, : shape[1] // 2] = 0.0
    return rows


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(("normal", "cauchy", "ties", "half_zero")), st.integers(1, 5), st.integers(100, 9000),
       st.integers(0, 2**32 - 1))
def test_row_quantiles_equal_numpy_bit_for_bit(kind, n_rows, n_draws, seed):
    rows = _rows(kind, (n_rows, n_draws), np.random.default_rng(seed))
    for p in PROBABILITIES:
        np.testing.assert_array_equal(row_quantiles(rows, p), np.quantile(rows, p, axis=1))


def test_a_row_with_nan_gives_nan_as_numpy_does():
    rows = np.abs(np.random.default_rng(1).standard_normal((2, 2000)))
    rows[1, 1990] = np.nan
    result = row_quantiles(rows, 0.95)
    assert result[0] == np.quantile(rows[0], 0.95) and np.isnan(result[1])


@pytest.mark.parametrize("p", PROBABILITIES)
def test_the_fallback_for_a_short_tail_is_numpy_itself(p):
    """A tail longer than the prefilter keeps (p = 0.01: nearly every value is needed)."""
    rows = np.abs(np.random.default_rng(2).standard_normal((3, 8192)))
    np.testing.assert_array_equal(row_quantiles(rows, p), np.quantile(rows, p, axis=1))
