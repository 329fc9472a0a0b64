"""Hysteresis of a Kelvin-Voigt rim on a rigid plane ([Zhao] slides 26-32; model: rig.teaching.hysteresis).

Independent checks: the Winkler closed form of the elastic case, the small-speed limit u -> v eta/E,
and three routes to the energy lost per pass (loop area by path integration, dashpot dissipation,
rolling-resistance work M/R per unit travel).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from rig.errors import ParameterError
from rig.teaching.hysteresis import KelvinVoigtLayer, cycle_work, roll_on_layer, strain_stress_loop
from rig.teaching.rolling_resistance import dissipated_power

LAYER = KelvinVoigtLayer(5e6, 1.5e4, 0.01)
R, W, N = 0.1, 0.02, 200.0


@pytest.mark.parametrize("speed, layer", [(0.0, LAYER), (2.0, KelvinVoigtLayer(5e6, 0.0, 0.01))])
def test_elastic_limit_is_the_symmetric_winkler_contact(speed, layer):
    contact = roll_on_layer(layer, R, W, N, speed)
    c = (3.0 * N * R * layer.thickness_m / (2.0 * W * layer.modulus_Pa)) ** (1 / 3)  # N = w E/(2Rh) 4c^3/3
    assert contact.half_width_m == pytest.approx(c, rel=1e-12)
    assert contact.rear_m == pytest.approx(-c, rel=1e-12)
    assert contact.shift_m == pytest.approx(0.0, abs=1e-12 * c) and contact.power_W == pytest.approx(0.0, abs=1e-9)
    assert cycle_work(*strain_stress_loop(contact)) == pytest.approx(0.0, abs=1e-6)  # load and unload on one line


def test_slow_rolling_shifts_the_resultant_by_the_relaxation_length():
    for speed in (1e-3, 1e-4):
        contact = roll_on_layer(LAYER, R, W, N, speed)
        s = speed * LAYER.relaxation_time_s
        assert contact.relaxation_length_m == pytest.approx(s)
        assert abs(contact.shift_m / s - 1.0) <= s / contact.half_width_m  # u = s (1 + O(s/c))


@pytest.mark.parametrize("speed", [0.3, 1.0, 3.0, 30.0])
def test_three_routes_to_the_energy_per_cycle_agree(speed):
    contact = roll_on_layer(LAYER, R, W, N, speed)
    area = cycle_work(*strain_stress_loop(contact, samples=4001))
    assert area > 0.0
    assert area == pytest.approx(contact.dissipation_per_cycle(), rel=1e-5)  # loop area = dashpot loss
    # rolling-resistance work per metre of travel = loss per volume x rim volume per metre (h w)
    assert contact.resistance_force_N == pytest.approx(area * LAYER.thickness_m * W, rel=1e-5)
    assert contact.power_W == pytest.approx(dissipated_power(N, contact.f_v, speed), rel=1e-12)  # f_v N v


def test_pressure_carries_the_load_and_vanishes_where_the_rim_leaves():
    contact = roll_on_layer(LAYER, R, W, N, 1.0)
    load, _ = quad(lambda x: float(contact.pressure(x)), contact.rear_m, contact.front_m, epsabs=0, epsrel=1e-12)
    assert W * load == pytest.approx(N, rel=1e-9)
    moment, _ = quad(lambda x: float(contact.pressure(x)) * x, contact.rear_m, contact.front_m, epsrel=1e-12)
    assert W * moment == pytest.approx(contact.resisting_moment_N_m, rel=1e-9)
    assert contact.pressure(contact.rear_m) == pytest.approx(0.0, abs=1e-6 * contact.pressure(0.0))
    assert contact.pressure(contact.front_m) > 0.0  # the Kelvin-Voigt jump at the leading edge
    assert contact.pressure(contact.front_m * 1.001) == 0.0 and contact.pressure(contact.rear_m * 1.001) == 0.0
    assert np.all(contact.pressure(np.linspace(-2.0, 2.0, 401) * contact.front_m) >= 0.0)
    assert contact.pressure(0.5 * contact.front_m) > contact.pressure(-0.5 * contact.front_m)  # front > rear


@settings(max_examples=60, deadline=None)
@given(
    st.floats(1e5, 1e9), st.floats(0.0, 1e6), st.floats(1e-3, 0.05), st.floats(0.05, 1.0),
    st.floats(1e-3, 0.2), st.floats(1e-3, 1e5), st.floats(0.0, 100.0),
)
def test_results_are_finite_and_bounded_or_a_clear_error(modulus, viscosity, thickness, radius, width, load, speed):
    assume(thickness <= 0.5 * radius)
    layer = KelvinVoigtLayer(modulus, viscosity, thickness)
    try:
        contact = roll_on_layer(layer, radius, width, load, speed)
    except ParameterError as error:
        assert error.name == "normal_force" and "strain" in str(error)
        return
    c = contact.half_width_m
    assert math.isfinite(contact.shift_m) and -1e-12 * c <= contact.shift_m < c
    assert -c <= contact.rear_m <= 0.0 and contact.penetration_m <= 0.5 * thickness * (1 + 1e-9)
    assert 0.0 <= contact.f_v < 1.0 and contact.dissipation_per_cycle() >= 0.0


def test_more_viscous_rims_roll_harder():
    f_v = [roll_on_layer(KelvinVoigtLayer(5e6, eta, 0.01), R, W, N, 0.5).f_v for eta in (1e3, 5e3, 2e4)]
    assert f_v[0] < f_v[1] < f_v[2]


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: roll_on_layer(LAYER, R, W, N, -1.0), "speed"),
        (lambda: roll_on_layer(LAYER, 0.015, W, N, 1.0), "layer.thickness_m"),
        (lambda: roll_on_layer(LAYER, R, W, 1e5, 1.0), "normal_force"),
        (lambda: KelvinVoigtLayer(5e6, -1.0, 0.01), "viscosity_Pa_s"),
        (lambda: cycle_work(np.array([0.0, 1.0, 0.5]), np.array([0.0, 1.0, 2.0])), "strain, stress"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name
