"""Stand B chain: eq. (36), M_C = T_Mo + R_c F_T with its uncertainty, mu from forces and moment."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rig.reduction import stand_b
from rig.reduction.geometry import StandBGeometry
from rig.reduction.iteration import ReductionSettings
from rig.reduction.result import Start
from rig.reduction.uncertainty import monte_carlo
from tests.reduction.synthetic import analytic_coefficients, rigid_coefficients, stand_b_readings

B = StandBGeometry()
MU = 0.8
SIGMA_8MM = math.asin(8.0 / 70.2)  # eq. (36): c = 8 mm, sigma = 6.54 deg


@pytest.mark.parametrize("load, l_mm, sigma", [(144.0, 10.0, SIGMA_8MM), (36.0, -20.0, -SIGMA_8MM), (9.0, 3.2, 0.0)])
def test_rigid_forward_simulation_returns_mu(load, l_mm, sigma):
    b_over_a = B.b_over_a(load)
    coefficients = rigid_coefficients(b_over_a)
    readings, truth = stand_b_readings(MU, load, l_mm * 1e-3, sigma, coefficients, b_over_a=b_over_a)
    point = stand_b.reduce(readings, coefficients)
    v = point.values
    assert v["c_over_a"] == pytest.approx(math.sin(sigma) * 70.2 / 4.0, rel=1e-12)
    assert v["l_over_a"] == pytest.approx(l_mm / 4.0)
    assert v["alpha_prime"] == pytest.approx(26.6 * MU * b_over_a, rel=2e-3)  # Equations §3.2
    assert v["M_C_N_m"] == pytest.approx(truth["moment_c"], rel=1e-9)
    for name in ("mu_T", "mu_M") + (("mu_v",) if sigma != 0.0 else ()):
        assert v[name] == pytest.approx(MU, rel=1e-9), name
    if sigma == 0.0:
        assert math.isnan(v["mu_v"]) and "nu_v" in point.reasons["mu_v"]


def test_pivoting_moment_is_a_small_difference_of_large_numbers():
    coefficients = rigid_coefficients(2.0)
    readings, truth = stand_b_readings(MU, 144.0, 20e-3, SIGMA_8MM, coefficients, b_over_a=2.0)
    transfer = B.radius_c * truth["f_t"]
    assert abs(transfer) > 5 * abs(truth["moment_c"])  # 17.6 N m of transfer against 2.5 N m
    point = stand_b.reduce(readings, coefficients, geometry_u={"radius_c": 0.2e-3})
    u_t_mo, u_f_t = readings.momentometer_torque.u, readings.peripheral_force.u
    expected = math.sqrt(u_t_mo**2 + (B.radius_c * u_f_t) ** 2 + (truth["f_t"] * 0.2e-3) ** 2)
    assert point.uncertainties["M_C_N_m"] == pytest.approx(expected, rel=1e-9)
    by = point.budget.by_source()["M_C_N_m"]
    assert set(by[by > 0].index) == {"momentometer", "dynamometer F_T", "geometry"}
    # 0.2 mm on R_c = 0.12 % of the 17.6 N m transfer = 0.021 N m on M_C, i.e. 0.8 % of M_C
    assert by["geometry"] == pytest.approx((truth["f_t"] * 0.2e-3) ** 2)


def test_alpha_dependent_model_and_monte_carlo():
    readings, truth = stand_b_readings(0.5, 36.0, 10e-3, SIGMA_8MM, analytic_coefficients)
    point = stand_b.reduce(readings, analytic_coefficients, settings=ReductionSettings(mu_start=1.5))
    assert point.values["mu_v"] == pytest.approx(0.5, rel=1e-8)
    assert point.values["mu_T"] == pytest.approx(0.5, rel=1e-7)
    assert point.values["mu_M"] == pytest.approx(0.5, rel=1e-7)
    names = ("c_over_a", "M_C_N_m", "mu_v", "mu_T", "mu_M")

    def model(x):
        return stand_b.evaluate(x, Start(0.5, stand_b.MU_ORDER), readings=readings, geometry=B,
                                coefficients=analytic_coefficients,
                                settings=ReductionSettings()).values

    mc = monte_carlo(model, point.propagation.inputs, names, 3000, np.random.default_rng(np.random.SeedSequence(11)))
    for name in names:
        assert mc.u(name) == pytest.approx(point.uncertainties[name], rel=0.10), name


def test_b_over_a_per_load():
    assert [B.b_over_a(f) for f in (9, 21, 36, 144)] == [0.5, 0.75, 1.0, 2.0]  # text values
    assert B.b_over_a(72.0) == pytest.approx(math.sqrt(2))  # b ~ sqrt(F_N) between listed loads
