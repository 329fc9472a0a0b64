"""Coulomb's laws ([Zhao] slides 14-17, 21): the stick inequality, the kinetic force, the power."""

from __future__ import annotations

import math

import pytest

from rig.errors import ParameterError
from rig.teaching.coulomb import friction_power, kinetic_friction, static_and_kinetic, static_friction_holds


def test_static_friction_holds_up_to_mu_s_n_in_either_direction():
    assert static_friction_holds(40.0, 100.0, 0.4)  # |T| = mu_s N: still sticks (ineq. 5.1 is "<=")
    assert static_friction_holds(-40.0, 100.0, 0.4)
    assert not static_friction_holds(40.001, 100.0, 0.4)
    assert not static_friction_holds(-40.001, 100.0, 0.4)
    assert not static_friction_holds(1e-9, 0.0, 0.8)  # no normal force, no friction


def test_kinetic_friction_opposes_the_sliding_velocity_with_mu_k_n():
    assert kinetic_friction(50.0, 0.3, 2.0) == pytest.approx(-15.0)
    assert kinetic_friction(50.0, 0.3, -1e-6) == pytest.approx(15.0)
    with pytest.raises(ParameterError, match="sliding_velocity"):
        kinetic_friction(50.0, 0.3, 0.0)


def test_friction_power_is_mu_k_n_v():
    assert friction_power(100.0, 0.3, -2.0) == pytest.approx(60.0)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: static_and_kinetic(0.3, 0.4), "mu_k"),
        (lambda: static_friction_holds(1.0, -1.0, 0.5), "normal_force"),
        (lambda: static_friction_holds(math.nan, 1.0, 0.5), "tangential_force"),
        (lambda: friction_power(1.0, -0.1, 1.0), "mu_k"),
        (lambda: kinetic_friction(1.0, 5.0, 1.0), "mu_k"),
    ],
)
def test_bad_input_names_the_parameter_and_range(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name and "valid" in str(info.value)
