"""Errors common to a run's points (rig.fit.common_errors): the calibration's relative part at the true y's estimate.

Independent numbers. A common normalisation error cannot move the estimates of a model that can
scale itself (a constant, a straight line): fitting it as a nuisance parameter with its Gaussian
penalty (D'Agostini 1994; the same chi2 as the covariance built from the true values, Woodbury)
leaves it at 0, so the estimate is the one without it:
* Peelle's pertinent puzzle (two measurements 1.5 and 1.0 of one quantity, 10 % independent errors
  each and a 20 % common normalisation error): the weighted mean of the independent errors, 1.1538;
  the covariance built from the *measured* values gives 0.882, below both (Peelle 1987);
* a straight line with errors in x and y: Deming's closed form (tests/fit/test_engine.py); built
  from the model at the measured x, or from the measured y, the slope moves by 23 % or 5 %.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from rig.fit.common_errors import CommonErrors, read_common_errors
from rig.fit.engine import fit
from rig.reduction.geometry import StandAGeometry
from tests.fit.test_engine import LinearModel, LineWithNoisyX, deming_line, noisy_line

Y = np.array([1.5, 1.0])
INDEPENDENT = 0.1 * Y
NORMALISATION = 0.2


def _peelle_model(common: CommonErrors) -> LinearModel:
    model = LinearModel(np.ones((2, 1)), Y, np.sqrt(INDEPENDENT**2 + np.diag(common.covariance(Y))), names=("m",))
    model.obs.common = common
    model.obs.u_independent = INDEPENDENT
    return model


def test_peelles_puzzle_is_gone_with_the_relative_error_at_the_model():
    # a calibration with S = 1, u(S)/S = 20 %: C = 0.2^2 f f^T at the model's f
    at_model = fit(_peelle_model(CommonErrors(1.0, NORMALISATION, 0.0, 0.0, np.zeros(2), None)), [1.0],
                   polish="never", profile=False)
    weighted_mean = np.sum(Y / INDEPENDENT**2) / np.sum(1 / INDEPENDENT**2)
    assert weighted_mean == pytest.approx(1.1538, abs=1e-4)
    assert at_model.estimate("m").value == pytest.approx(weighted_mean, abs=1e-5)  # u(m) ~ 0.1
    # the same covariance built from the measured values (held fixed, as before): Peelle's 0.882
    measured = np.outer(Y, Y) * NORMALISATION**2
    at_data = fit(_peelle_model(CommonErrors(None, 0.0, 0.0, 0.0, np.zeros(2), measured)), [1.0],
                  polish="never", profile=False)
    assert at_data.estimate("m").value == pytest.approx(0.882, abs=1e-3)


def test_a_stated_normalisation_does_not_move_demings_line():
    x, y, u_x, u_y = noisy_line()
    model = LineWithNoisyX(x, y, np.full(x.size, u_y), np.full(x.size, u_x))
    model.obs.common = CommonErrors(1.0, 0.1, 0.0, 0.0, np.zeros(x.size), None)  # 10 % of the true y
    result = fit(model, [0.0, 0.0], polish="never", profile=False)
    intercept, slope = deming_line(x, y, u_x, u_y)
    assert result.estimate("b").value == pytest.approx(slope, abs=1e-5)  # -0.713 (at f(x): -0.876, at y: -0.678)
    assert result.estimate("a").value == pytest.approx(intercept, abs=1e-5)


def test_covariance_is_the_calibration_propagated_at_the_given_values():
    g = StandAGeometry()
    f_n = np.array([96.2, 385.0])
    sens, u_s, u_o, cov_so = 0.25, 0.0034, 0.0078, -1e-6
    cal = pd.DataFrame({"dynamometer_10_" + name: [value] * 2 for name, value in (
        ("sensitivity_V_N", sens), ("u_sensitivity_V_N", u_s), ("u_offset_V", u_o),
        ("cov_sensitivity_offset_V2_N", cov_so))})
    common, notes = read_common_errors(cal, pd.DataFrame(index=range(2)), f_n, [g, g])
    y = np.array([0.03, 0.05])
    a = -y / sens  # dy/dS of y = (s - s0)/S lever/F_N (eq. 33)
    b = -(g.dynamometer_lever / g.yoke_lever) / (sens * f_n)  # dy/ds0
    expected = np.outer(a, a) * u_s**2 + np.outer(b, b) * u_o**2 + (np.outer(a, b) + np.outer(b, a)) * cov_so
    assert common.covariance(y) == pytest.approx(expected, rel=1e-12)
    assert "calibration common to all points" in notes[0] and "does not record" in notes[1]
