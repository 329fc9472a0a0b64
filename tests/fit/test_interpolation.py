"""The forward model's interpolation between effect nodes (rig.fit.forward.hermite_stencil).

Independent numbers: a cubic Hermite interpolation with central-difference slopes reproduces
straight lines exactly (any value, any node count), its weights are a partition of unity, and
on a smooth function its error falls like h^3 (Catmull-Rom's order; the one-sided end slopes
are second order, so the order is measured inside).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.fit.forward import NODES_PER_EFFECT, hermite_stencil


def _interpolate(nodes, f, value):
    return sum(w * f(nodes[k]) for k, w in hermite_stencil(nodes, value).items())


@given(st.floats(1.0, 3.0), st.integers(3, 40), st.floats(-5.0, 5.0), st.floats(-5.0, 5.0))
def test_lines_are_reproduced_and_the_weights_sum_to_one(value, count, a, b):
    nodes = np.linspace(1.0, 3.0, count)
    weights = hermite_stencil(nodes, value)
    assert sum(weights.values()) == pytest.approx(1.0, abs=1e-12)
    assert len(weights) <= 4 and all(0 <= k < count for k in weights)
    assert _interpolate(nodes, lambda x: a + b * x, value) == pytest.approx(a + b * value, abs=1e-11)


def test_nodes_are_hit_exactly_and_the_error_is_third_order_inside():
    nodes = np.linspace(1.0, 3.0, NODES_PER_EFFECT)
    assert all(hermite_stencil(nodes, x).get(k) == 1.0 for k, x in enumerate(nodes))
    values = np.linspace(1.5, 2.5, 41)  # inside: no one-sided slope in the stencil

    def error(count):
        grid = np.linspace(1.0, 3.0, count)
        return max(abs(_interpolate(grid, np.sin, v) - np.sin(v)) for v in values)

    order = np.log2(error(17) / error(33))
    assert 2.7 < order < 3.3, order
