"""The contact law's numerical error at a state (rig.contact.numerical_error): an independent check
against the solver's converged value from a finer pair of grids, and the exact cases."""

from __future__ import annotations

import numpy as np
import pytest

from rig.contact.numerical_error import converged_error, richardson
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


# Stand A's regime: b/a 1 and 2, alpha' 0.5 - 3, rolling point on the contact line (c = 0) from the
# centre to the edge, nu = 0.3 (the fig10 scene). Measured at n = 32 against Richardson's extrapolation
# of 32 / 64 / 128 (32 states): nu_v 0.03-0.9 %
# high at c = l = 0 and l/a = 0.5, 1.1-2.2 % high at l/a = 1, where nu_v is smallest (0.02-0.12).
STAND_A_WITHIN = [(1.0, 1.0, 0.0, 0.0), (2.0, 1.0, 0.0, 0.5)]
STAND_A_BEYOND = (1.0, 0.5, 0.0, 1.0)  # 2.2 % (0.02206 against 0.02159); the budget's bound 0.00072


def _stand_a(state, with_bound=False):
    b, alpha, c, l = state
    fixed = dict(shape="ellipse", b_over_a=b, poisson=0.3)
    values = [np.array(_nu_all(solve("kinematic", n=n, alpha=alpha, c_over_a=c, l_over_a=l, **fixed)))
              for n in (32, 64, 128)]
    reference = richardson(*values)
    error = abs(values[0][1] - reference.limit[1]) + reference.uncertainty[1]
    bound = converged_error(values[0], "kinematic", fixed, 32, (l, c, alpha))[1] if with_bound else None
    return error, reference.limit[1], bound


def _nu_all(r):
    return r.nu_T, r.nu_v, r.nu_0


@pytest.mark.parametrize("state", STAND_A_WITHIN)
def test_stand_a_regime_nu_v_is_within_one_percent_of_converged_at_the_default_grid(state):
    """Centre and l/a = 0.5: 0.81 % (b/a 1, alpha' 1), 0.28 % (b/a 2, alpha' 1, l/a 0.5) measured, each
    with the reference's own uncertainty added."""
    error, limit, _ = _stand_a(state)
    assert error <= 0.01 * limit, (state, error / limit)


def test_where_stand_a_is_beyond_one_percent_the_reduction_budget_carries_the_error():
    """At the contact's edge (l/a = 1) nu_v is small and the default grid is more than 1 % off: there
    the reduction's budget (the scene's [contact] error_budget, on in fig10) carries the law's error as
    a rectangular source of half width converged_error (2 |nu_32 - nu_64|), which must cover it."""
    error, limit, bound = _stand_a(STAND_A_BEYOND, with_bound=True)
    assert error > 0.01 * limit  # the case is beyond 1 % (else this test checks nothing)
    assert bound >= error, (error, bound)
