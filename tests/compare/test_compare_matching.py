"""Which RESULT rows belong to a digitised dataset: conditions, models, repeated x, units."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from rig.compare.matching import check_sidecar, select_curves, unit_suffix
from rig.compare.sidecar import parse_sidecar
from rig.errors import ParameterError, UnknownNameError


def _result() -> pd.DataFrame:
    alpha = np.array([1.0, 2.0, 4.0])
    rows = []
    for model, scale in (("kinematic", 1.0), ("fastsim", 2.0)):
        for b in (1.0, 2.0):
            for a in alpha:
                rows.append(dict(alpha=a, nu_v=-scale * b / a, b_over_a=b + 1e-9, shape="ellipse", model=model, n=32))
    return pd.DataFrame(rows)


def _sidecar(dataset: dict | None = None, conditions: dict | None = None, x: dict | None = None):
    data = {
        "figure": "f",
        "conditions": {"shape": "ellipse", "b_over_a": 2.0} if conditions is None else conditions,
        "x": x or {"quantity": "alpha'", "units": "1"},
        "datasets": {"d": dataset or {"quantity": "|F_y| / (mu F_N)", "units": "1"}},
    }
    sidecar = parse_sidecar(data)
    return sidecar, sidecar.datasets[0]


def test_conditions_select_rows_within_tolerance_and_each_model_is_a_curve():
    sidecar, spec = _sidecar()
    curves = select_curves(_result(), sidecar.x, spec)
    assert [c.model for c in curves] == ["fastsim", "kinematic"]
    fastsim, kinematic = curves
    np.testing.assert_array_equal(kinematic.x, [1.0, 2.0, 4.0])
    np.testing.assert_allclose(kinematic.y, [2.0, 1.0, 0.5])  # |nu_v| for b/a = 2 (stored 2 + 1e-9)
    np.testing.assert_allclose(fastsim.y, [4.0, 2.0, 1.0])


def test_model_option_and_model_condition():
    sidecar, spec = _sidecar()
    (only,) = select_curves(_result(), sidecar.x, spec, model="kinematic")
    assert only.model == "kinematic"
    with pytest.raises(UnknownNameError, match="did you mean 'kinematic'"):
        select_curves(_result(), sidecar.x, spec, model="kinematik")
    sidecar, spec = _sidecar(conditions={"shape": "ellipse", "b_over_a": 1.0, "model": "fastsim"})
    (pinned,) = select_curves(_result(), sidecar.x, spec)
    assert pinned.model == "fastsim"
    np.testing.assert_allclose(pinned.y, [2.0, 1.0, 0.5])


def test_result_without_model_column_gives_one_curve():
    sidecar, spec = _sidecar()
    result = _result().query("model == 'kinematic'").drop(columns="model")
    (curve,) = select_curves(result, sidecar.x, spec)
    assert curve.model is None
    with pytest.raises(ParameterError, match="no 'model' column"):
        select_curves(result, sidecar.x, spec, model="kinematic")


def test_repeated_x_names_the_column_to_pin():
    sidecar, spec = _sidecar(conditions={"shape": "ellipse"})
    with pytest.raises(ParameterError, match=r"alpha = 1 repeated.*pin the column\(s\) that vary \(b_over_a\)"):
        select_curves(_result(), sidecar.x, spec, model="kinematic")


@pytest.mark.parametrize(
    ("conditions", "error", "words"),
    [
        ({"b_over_a": 3.0}, ParameterError, "a value present in RESULT rows"),
        ({"shape": "line"}, ParameterError, "ellipse"),
        ({"poisson": 0.3}, UnknownNameError, "column of RESULT"),
        ({"shape": 1.0}, ParameterError, "a string (the RESULT column holds text)"),
        ({"b_over_a": "two"}, ParameterError, "a number (the RESULT column holds numbers)"),
    ],
)
def test_condition_errors(conditions, error, words):
    sidecar, spec = _sidecar(conditions=conditions)
    with pytest.raises(error) as info:
        select_curves(_result(), sidecar.x, spec)
    assert words in str(info.value)


def test_missing_result_column_is_suggested():
    sidecar, spec = _sidecar(dataset={"column": "nu_vv", "units": "1"})
    with pytest.raises(UnknownNameError, match="did you mean 'nu_v'"):
        select_curves(_result(), sidecar.x, spec)


def test_units_must_match_the_column_suffix():
    assert unit_suffix("1") == "" and unit_suffix("N m") == "N_m" and unit_suffix("rad/s") == "rad_s"
    result = _result().assign(F_y_N=lambda f: 10.0 * f.nu_v)
    sidecar, spec = _sidecar(dataset={"column": "F_y_N", "units": "N"})
    (curve, _) = select_curves(result, sidecar.x, spec)
    assert curve.y[0] == pytest.approx(-40.0)
    sidecar, spec = _sidecar(dataset={"column": "F_y_N", "units": "kN"})
    with pytest.raises(ParameterError, match="ends in '_kN'"):
        select_curves(result, sidecar.x, spec)


def test_non_finite_result_values_are_an_error():
    sidecar, spec = _sidecar()
    result = _result()
    result.loc[4, "nu_v"] = np.nan
    with pytest.raises(ParameterError, match="1 non-finite alpha/nu_v"):
        select_curves(result, sidecar.x, spec, model="kinematic")


def test_condition_on_a_compared_column_is_rejected():
    sidecar, _ = _sidecar(conditions={"alpha": 1.0})
    with pytest.raises(ParameterError, match="no condition on a compared"):
        check_sidecar(sidecar)
