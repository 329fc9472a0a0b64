"""The Pareto front of (cost, error), checked against fronts worked out by hand."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.accuracy.pareto import pareto_front
from rig.errors import ParameterError


def test_front_worked_by_hand():
    # (1, 5) cheapest; (2, 3) better error; (3, 4) beaten by (2, 3); (4, 1); (5, 1) beaten by (4, 1)
    costs = [1.0, 2.0, 3.0, 4.0, 5.0]
    errors = [5.0, 3.0, 4.0, 1.0, 1.0]
    assert pareto_front(costs, errors).tolist() == [True, True, False, True, False]


def test_equal_points_are_both_on_the_front_and_zero_error_counts():
    assert pareto_front([1.0, 1.0, 2.0], [0.5, 0.5, 0.0]).tolist() == [True, True, True]
    assert pareto_front([1.0, 2.0], [0.0, 0.0]).tolist() == [True, False]


def test_nan_is_not_on_the_front_and_beats_nothing():
    assert pareto_front([1.0, np.nan, 3.0], [2.0, 0.0, 1.0]).tolist() == [True, False, True]
    assert pareto_front([np.nan], [np.nan]).tolist() == [False]


def test_unequal_lengths_are_a_named_error():
    with pytest.raises(ParameterError, match="costs, errors"):
        pareto_front([1.0, 2.0], [1.0])


@given(st.lists(st.tuples(st.floats(0, 10), st.floats(0, 10)), min_size=1, max_size=12))
def test_front_points_are_not_dominated_and_the_rest_are(points):
    c = np.array([p[0] for p in points])
    e = np.array([p[1] for p in points])
    front = pareto_front(c, e)
    assert front.any()  # the cheapest of the lowest errors is always on it
    for i in range(len(points)):
        dominated = np.any((c <= c[i]) & (e <= e[i]) & ((c < c[i]) | (e < e[i])))
        assert front[i] == (not dominated)
