"""The contact law's numerical error at a state (rig.contact.numerical_error): an independent check
against the solver's converged value from a finer pair of grids, and the exact cases."""

from __future__ import annotations

import numpy as np
import pytest

from rig.contact.numerical_error import converged_error
from rig.contact.solve import solve

STATE = dict(alpha=20.5, c_over_a=0.0, l_over_a=0.0)  # pure spin, about half the area sticking
FIXED = dict(shape="ellipse", b_over_a=1.0, poisson=0.28)


@pytest.fixture(scope="module")
def nu():
    """n -> (nu_T, nu_v, nu_0) of the state on n cells, each grid solved once."""
    values = {}

    def at(n):
        if n not in values:
            r = solve("kinematic", n=n, **FIXED, **STATE)
            values[n] = np.array([r.nu_T, r.nu_v, r.nu_0])
        return values[n]

    return at


def test_estimate_at_n16_matches_the_error_against_the_n64_n128_extrapolation(nu):
    """The estimate uses n = 16 and 32; the reference here extrapolates n = 64 and 128 the same way
    (first order, the slower of the orders the solver shows; tests/contact/test_convergence.py), so
    the two share no grid. Measured: nu_v 0.45394/0.45316 at n = 16/32, 0.45256/0.45232 at 64/128,
    0.45222 at 256; estimate 0.00156, reference 0.00186 (with n = 256's value as the limit, 0.0017)."""
    estimate = converged_error(nu(16), "kinematic", FIXED, 16, (0.0, 0.0, 20.5))
    finer = 2.0 * nu(128) - nu(64)
    actual = np.abs(nu(16) - finer)
    assert actual[1] > 1e-3  # the case has a grid error worth estimating (nu_v about 0.0018 at n = 16)
    assert estimate[1] == pytest.approx(actual[1], rel=0.35)
    assert estimate[2] <= max(2.0 * actual[2], 2e-3)


def test_a_value_off_the_model_adds_its_offset_and_linear_theory_has_none(nu):
    base = converged_error(nu(16), "kinematic", FIXED, 16, (0.0, 0.0, 20.5))
    shifted = converged_error(nu(16) + np.array([0.0, 0.01, 0.0]), "kinematic", FIXED, 16, (0.0, 0.0, 20.5))
    assert shifted[1] == pytest.approx(base[1] + 0.01, abs=1e-12) or shifted[1] == pytest.approx(0.01 - base[1], abs=1e-12)
    assert not np.any(converged_error(np.zeros(3), "linear", FIXED, 16, (0.0, 0.0, 20.5)))
