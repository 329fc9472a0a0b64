"""Bad input raises a ValueError subclass naming the parameter, the value and the valid range."""

import math

import pytest

from rig.contact.solve import solve, solve_creepage
from rig.errors import ParameterError, UnknownNameError

GOOD = dict(shape="ellipse", b_over_a=1.0, alpha=10.0, c_over_a=0.0, l_over_a=0.0, poisson=0.28, n=16)


def _call(model="kinematic", **overrides):
    return solve(model, **{**GOOD, **overrides})


@pytest.mark.parametrize(
    "name, value",
    [
        ("b_over_a", 0.0), ("b_over_a", -1.0), ("b_over_a", 20.0), ("alpha", -1e-3), ("poisson", 0.6),
        ("n", 3), ("n", 16.5), ("c_over_a", math.nan), ("l_over_a", math.inf), ("alpha", math.nan),
        ("b_over_a", math.nan), ("poisson", math.nan), ("psi", 0.99), ("static_ratio", 0.5),
        ("inertia_number", -0.1), ("inertia_number", 0.3), ("psi", math.nan),
    ],
)
def test_out_of_range_values_name_parameter_value_and_range(name, value):
    with pytest.raises(ParameterError) as error:
        _call(**{name: value})
    assert isinstance(error.value, ValueError)
    assert error.value.name == name
    message = str(error.value)
    assert name in message and repr(value) in message and "valid" in message


@pytest.mark.parametrize(
    "kind, given, suggestion, call",
    [
        ("model", "kinematc", "kinematic", lambda: _call(model="kinematc")),
        ("shape", "elipse", "ellipse", lambda: _call(shape="elipse")),
        ("effect", "pzi", "psi", lambda: _call(pzi=2.0)),
        ("effect", "static_ration", "static_ratio", lambda: _call(static_ration=2.0)),
    ],
)
def test_unknown_names_are_errors_that_suggest_the_closest(kind, given, suggestion, call):
    with pytest.raises(UnknownNameError) as error:
        call()
    assert error.value.name == kind and error.value.value == given
    assert f"did you mean {suggestion!r}" in str(error.value)


def test_an_effect_a_model_cannot_represent_is_an_error_not_ignored():
    with pytest.raises(ParameterError, match="not available for model 'rigid'"):
        _call(model="rigid", psi=2.0)


def test_linear_theory_has_no_rigid_sliding_limit():
    with pytest.raises(ParameterError, match="alpha"):
        _call(model="linear", alpha=0.0)


def test_keyword_only_inputs_have_no_silent_defaults():
    with pytest.raises(TypeError):
        solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=1.0, poisson=0.3)  # no rolling point


def test_creepage_form_validates_too():
    with pytest.raises(ParameterError, match="phi"):
        solve_creepage("rigid", shape="ellipse", b_over_a=1.0, xi=0.0, eta=0.0, phi=math.nan, poisson=0.3)
