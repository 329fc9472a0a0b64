"""First-order and Monte-Carlo propagation, and the budget, on models with closed-form answers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rig.errors import ParameterError
from rig.reduction.budget import budget
from rig.reduction.uncertainty import (
    Covariance,
    Distribution,
    InputQuantity,
    InputSet,
    draw_inputs,
    first_order,
    monte_carlo,
    rectangular_u,
)


def rng(seed: int = 2024) -> np.random.Generator:
    return np.random.default_rng(np.random.SeedSequence(seed))


LINEAR_INPUTS = InputSet(
    (InputQuantity("x1", 1.0, 0.1, "m", "ruler"), InputQuantity("x2", 2.0, 0.2, "m", "ruler"),
     InputQuantity("x3", 5.0, 0.0, "m", "exact")),
    (Covariance("x1", "x2", 0.01),),
)


def linear(x):
    return {"y": 2 * x["x1"] - 3 * x["x2"] + x["x3"], "z": x["x1"]}


def test_linear_model_is_exact_with_correlation():
    prop = first_order(linear, LINEAR_INPUTS, ("y", "z"))
    assert prop.jacobian[0] == pytest.approx([2.0, -3.0, 0.0])
    var_y = 4 * 0.01 + 9 * 0.04 - 2 * 2 * 3 * 0.01  # GUM eq. (13)
    assert prop.u("y") == pytest.approx(math.sqrt(var_y), rel=1e-12)
    assert prop.covariance[0, 1] == pytest.approx(2 * 0.01 - 3 * 0.01)
    table = budget(prop)
    assert list(table.variance.index) == ["x1", "x2", "cov(x1, x2)"]  # the exact input is not listed
    assert table.variance["y"].tolist() == pytest.approx([0.04, 0.36, -0.12])
    assert table.total()["y"] == pytest.approx(var_y)
    assert table.shares()["y"].sum() == pytest.approx(1.0)
    assert table.by_source()["y"]["ruler"] == pytest.approx(var_y)  # same source: pair term joins it


def test_product_quotient_relative_uncertainties_add_in_quadrature():
    table = [("a", 3.0, 0.003), ("b", 4.0, 0.008), ("c", 2.0, 0.001)]
    inputs = InputSet(tuple(InputQuantity(n, v, u, "1", n) for n, v, u in table))
    prop = first_order(lambda x: {"y": x["a"] * x["b"] / x["c"]}, inputs, ("y",))
    rel = math.sqrt(0.001**2 + 0.002**2 + 0.0005**2)
    assert prop.u("y") / prop.value("y") == pytest.approx(rel, rel=1e-5)
    assert budget(prop).uncertainty_by_source()["y"]["b"] == pytest.approx(6.0 * 0.002, rel=1e-5)


def test_monte_carlo_agrees_with_first_order_for_a_mild_nonlinearity():
    inputs = InputSet((
        InputQuantity("a", 3.0, 0.03, "1", "s"),
        InputQuantity("n", 1000.0, rectangular_u(1.0), "1", "counter", Distribution.RECTANGULAR),
    ))

    def model(x):
        return {"y": math.sin(x["a"]) * x["n"] ** 2}

    fo = first_order(model, inputs, ("y",))
    mc = monte_carlo(model, inputs, ("y",), 4000, rng())
    assert mc.u("y") == pytest.approx(fo.u("y"), rel=0.06)
    assert mc.mean[0] == pytest.approx(fo.value("y"), rel=1e-3)


def test_draws_follow_the_declared_distributions():
    inputs = InputSet(
        (InputQuantity("s", 2.0, 0.5, "V/N", "cal"), InputQuantity("o", 1.0, 0.2, "V", "cal"),
         InputQuantity("n", 10.0, rectangular_u(1.0), "1", "counter", Distribution.RECTANGULAR)),
        (Covariance("s", "o", -0.08),),
    )
    x = draw_inputs(inputs, 20000, rng(7))
    assert np.all(np.abs(x[:, 2] - 10.0) <= 1.0)
    assert np.std(x[:, 2]) == pytest.approx(1 / math.sqrt(3), rel=0.03)
    assert np.cov(x[:, :2].T) == pytest.approx(inputs.covariance_matrix()[:2, :2], abs=0.006)


def test_nan_derivative_poisons_only_its_output():
    inputs = InputSet((InputQuantity("x", 1.0, 0.1, "1", "s"),))
    prop = first_order(lambda x: {"ok": 2 * x["x"], "bad": math.nan if x["x"] > 1.0 else x["x"]}, inputs, ("ok", "bad"))
    assert prop.u("ok") == pytest.approx(0.2)
    assert math.isnan(prop.u("bad"))


PAIR = (InputQuantity("x", 1, 1, "1", "s"), InputQuantity("y", 2, 1, "1", "s"))
RECT_PAIR = (InputQuantity("x", 1, 1, "1", "s", Distribution.RECTANGULAR), InputQuantity("y", 2, 1, "1", "s"))


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: InputSet((InputQuantity("x", 1, 1, "1", "s"), InputQuantity("x", 2, 1, "1", "s"))), "unique"),
        (lambda: InputSet(PAIR, (Covariance("x", "y", 2.0),)), r"cov\(x, y\)"),
        (lambda: InputSet(RECT_PAIR, (Covariance("x", "y", 0.5),)), "distribution of x"),
        (lambda: InputSet((InputQuantity("x", 1, 1, "1", "s"),), (Covariance("x", "z", 0.0),)), "input = 'z'"),
        (lambda: InputQuantity("x", 1.0, -0.1, "1", "s"), r"u\(x\)"),
        (lambda: InputQuantity("x", math.nan, 0.1, "1", "s"), "x = nan"),
    ],
)
def test_bad_inputs_raise_named_errors(make, match):
    with pytest.raises(ParameterError, match=match):
        make()
