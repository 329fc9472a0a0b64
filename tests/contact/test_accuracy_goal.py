"""The default grid's accuracy goal, |d nu_v| <= 0.002 and |d nu_0| <= 0.004, on a few states against
independent values (the whole sweep, against converged values: benchmarks/bench_contact_sweep.py and
docs/accuracy-contact-sweep.md).

Independent values: Kalker's exact theory as CONTACT computes it, extrapolated to zero element size
with its own uncertainty (tests/contact/data/contact_fortran_pure_spin.toml); rigid sliding about the
centre of a Hertz circle, nu_0 = 3 pi/16; linear theory with Kalker's C23 (Table E.3, 3 digits) for
pure spin near full stick. The reference's uncertainty is added to the error.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from rig.contact.numerical_error import FULL_SLIDING_SPIN_MOMENT_CIRCLE
from rig.contact.solve import DEFAULT_N, solve

GOAL_V, GOAL_0 = 0.002, 0.004
CONTACT = tomllib.loads((Path(__file__).parent / "data" / "contact_fortran_pure_spin.toml").read_text())["extrapolation"]


def _pure_spin(b_over_a, alpha, model="kinematic"):
    return solve(model, shape="ellipse", b_over_a=b_over_a, alpha=alpha, c_over_a=0.0, l_over_a=0.0,
                 poisson=0.28, n=DEFAULT_N)


@pytest.mark.parametrize("key, alpha", [("a3", 3.0), ("a20_5", 20.5), ("a102_313", 102.313)])
def test_circle_pure_spin_against_kalkers_exact_theory(key, alpha):
    """Measured at n = 32: d nu_v +0.0013 / +0.0014 / -0.0003, d nu_0 -0.0000 / +0.0006 / -0.0002 (CONTACT's
    uncertainties 0.0005 / 0.0004 / 0.0003 and 0.00005 / 0.001 / 0.0004)."""
    r = _pure_spin(1.0, alpha)
    v, o = CONTACT[f"{key}_nu_v"], CONTACT[f"{key}_nu_0"]
    assert abs(r.nu_v - v["limit"]) + v["uncertainty"] <= GOAL_V, (r.nu_v, v)
    assert abs(r.nu_0 - o["limit"]) + o["uncertainty"] <= GOAL_0, (r.nu_0, o)


def test_circle_in_rigid_sliding_gives_three_pi_over_sixteen():
    """alpha' = 1e-3 (nu_0 moves from rigid sliding at O(alpha'^2)): 0.58937 at n = 32, 3 pi/16 = 0.58905."""
    assert abs(_pure_spin(1.0, 1e-3).nu_0 - FULL_SLIDING_SPIN_MOMENT_CIRCLE) <= GOAL_0


@pytest.mark.parametrize("b_over_a", [0.1, 10.0])
def test_near_full_stick_the_lateral_force_is_kalkers_linear_theory(b_over_a):
    """alpha' = 1e4 (the nonlinear part is below 1e-4 relative there): nu_v at n = 32 against linear theory
    with Kalker's C23, whose 3 digits are 0.5 % of it: 0.000106 / 0.03239 against 0.000106 / 0.03249."""
    linear = _pure_spin(b_over_a, 1e4, "linear").nu_v
    assert abs(_pure_spin(b_over_a, 1e4).nu_v - linear) <= min(GOAL_V, 5e-3 * abs(linear) + 1e-4)
