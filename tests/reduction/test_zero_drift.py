"""The dynamometer's zero drift since the calibration: a named input of the stand-A budget, its size
from the log's readings, old logs without them, and the random-walk covariance ``rig fit`` uses.

Independent source of the sizes: a random walk W of input-referred diffusion D [V/s^0.5] has
Var W(t) = D^2 t and cov(W(t_i), W(t_j)) = D^2 min(t_i, t_j); amplified g times and read through
the calibration S [V/N] and the eq. (33) lever (102 mm/R_v), u(F_y) = g D sqrt(t)/S x 102 mm/R_v.
"""

from __future__ import annotations

import dataclasses
import math
import shutil
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from rig.fit.common_errors import drift_covariance
from rig.logbook import Quantity
from rig.reduction import stand_a
from rig.reduction.geometry import StandAGeometry
from rig.runner import reduce_log_file
from rig.stands.yoke.reduction import NO_ZERO_DRIFT_NOTE, zero_drift_u
from tests.reduction.synthetic import SENSITIVITY, rigid_coefficients, stand_a_readings, stand_a_truth

G = StandAGeometry()
GAIN, D = 500.0, 1e-7  # sensors.dynamometer.STAND_A_GAIN [V/V]; fig10's drift diffusion [V/s^0.5]
OLD_LOG = Path(__file__).resolve().parents[1] / "logbook" / "data" / "old_layout_v1.h5"


def _readings(age_s: float) -> dict[str, Quantity]:
    return {"dynamometer_gain": Quantity(GAIN, "1"), "dynamometer_drift_variance_rate": Quantity(D**2, "V^2/s"),
            "dynamometer_zero_age": Quantity(age_s, "s")}


def test_zero_u_is_the_amplified_random_walk_since_the_calibration():
    assert zero_drift_u(SimpleNamespace(readings=_readings(400.0)), "p") == pytest.approx(500 * 1e-7 * 20.0, rel=1e-12)
    assert zero_drift_u(SimpleNamespace(readings={}), "p") == 0.0  # an older log: no drift stated


def test_budget_names_the_drift_and_its_size_in_F_y():
    truth = stand_a_truth(0.4, 96.2, 0.98, rigid_coefficients(1.0))
    readings = stand_a_readings(96_000, 94_080, truth, 96.2)
    u_z = GAIN * D * math.sqrt(1_000.0)
    without = stand_a.reduce(readings, rigid_coefficients(1.0))
    point = stand_a.reduce(dataclasses.replace(readings, zero_drift_u=u_z), rigid_coefficients(1.0))
    expected = u_z / SENSITIVITY * G.dynamometer_lever / G.yoke_lever  # [N]
    budget = point.budget.variance
    assert budget.loc["dyn_zero_drift_V", "F_y_N"] == pytest.approx(expected**2, rel=1e-6)
    assert point.budget.sources["dyn_zero_drift_V"] == "dynamometer zero drift"
    assert point.uncertainties["F_y_N"] ** 2 == pytest.approx(without.uncertainties["F_y_N"] ** 2 + expected**2,
                                                              rel=1e-9)
    assert point.values["F_y_N"] == without.values["F_y_N"]  # an uncertainty, not a correction
    assert "dyn_zero_drift_V" not in without.budget.variance.index


def test_old_log_without_drift_readings_reduces_as_before_and_says_so(tmp_path, monkeypatch):
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "cache"))
    log = tmp_path / "log.h5"
    shutil.copyfile(OLD_LOG, log)
    reduction, _ = reduce_log_file(log)
    assert reduction.notes == (NO_ZERO_DRIFT_NOTE,) and NO_ZERO_DRIFT_NOTE in reduction.problems
    # the values are those of the reduction before the drift (tests/runner/test_damaged_points.py)


def test_fit_covariance_between_points_is_the_random_walk_min_structure():
    age = np.array([17.0, 77.0, 137.0, 1037.0])
    f_n = np.array([96.2, 96.2, 385.0, 385.0])
    readings = pd.DataFrame({"dynamometer_gain": GAIN, "dynamometer_drift_variance_rate_V2_s": D**2,
                             "dynamometer_zero_age_s": age})
    cal = pd.DataFrame({"dynamometer_10_sensitivity_V_N": np.full(4, 0.4)})
    cov, note = drift_covariance(readings, cal, f_n, [G] * 4)
    b = G.dynamometer_lever / G.yoke_lever / (0.4 * f_n)  # d(F_y/F_N)/d(zero) [1/V]
    for i in range(4):
        for j in range(4):
            assert cov[i, j] == pytest.approx((GAIN * D) ** 2 * min(age[i], age[j]) * b[i] * b[j], rel=1e-12)
    assert "min(t_i, t_j)" in note
    off = readings.assign(dynamometer_drift_variance_rate_V2_s=0.0)
    assert drift_covariance(off, cal, f_n, [G] * 4)[0] is None
    assert drift_covariance(readings.drop(columns="dynamometer_zero_age_s"), cal, f_n, [G] * 4)[0] is None
