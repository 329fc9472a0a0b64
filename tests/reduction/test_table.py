"""The reduced table: required columns in order, uncertainties beside values, truth columns."""

from __future__ import annotations

import math

import pytest

from rig.errors import ParameterError
from rig.reduction import stand_a
from rig.reduction.table import reduced_table
from rig.wheel_kinematics import ratio_for_l
from rig.reduction.geometry import StandAGeometry
from tests.reduction.synthetic import analytic_coefficients, stand_a_readings, stand_a_truth

G = StandAGeometry()


def points():
    out, truths = [], []
    for l_over_a, n2 in ((0.3, None), (0.5, 0)):
        ratio = ratio_for_l(l_over_a * G.a, G.alpha_1, G.l1, G.l2)
        truth = stand_a_truth(0.4, 96.2, ratio, analytic_coefficients)
        n1 = 4800
        readings = stand_a_readings(n1, round(n1 * ratio) if n2 is None else n2, truth, 96.2)
        out.append(stand_a.reduce(readings, analytic_coefficients))
        truths.append(dict(l_over_a=truth.l / G.a, c_over_a=truth.c / G.a, mu_v=0.4, mu_T=0.4))
    return out, truths


def test_columns_and_truth():
    reduced, truths = points()
    table = reduced_table(reduced, truths)
    assert list(table.columns[:8]) == [
        "l_over_a", "u_l_over_a", "c_over_a", "u_c_over_a", "mu_v", "u_mu_v", "mu_T", "u_mu_T"
    ]
    assert list(table.columns[-4:]) == ["true_l_over_a", "true_c_over_a", "true_mu_v", "true_mu_T"]
    assert "F_y_N" in table.columns and "u_F_y_N" in table.columns and "reason" in table.columns
    assert table.loc[0, "mu_v"] == pytest.approx(0.4, abs=3 * table.loc[0, "u_mu_v"])
    assert table.loc[0, "reason"] == "" and "min_counts" in table.loc[1, "reason"]
    assert math.isnan(table.loc[1, "mu_T"])
    assert "true_mu_v" not in reduced_table(reduced, [dict(l_over_a=0.3), dict(l_over_a=0.5)]).columns
    with pytest.raises(ParameterError, match="truth"):
        reduced_table(reduced, truths[:1])
