"""Acceptance 5: ideal instruments (noise and drift off) reproduce the truth to the counting resolution,
and neither the simulation nor the reduction calls into the noise code.

Stand A, quasi-static, rigid law through a small surrogate table, no effect named: the weights are
exact, the dynamometer and the balance have no noise, the drift is off. What is left are the
resolutions - the counters' +-1 count, the converter's LSB, the balance's 0.0196 N m step - so
the reduced values must lie within the first-order resolution bound sum_i |dy/dx_i| h_i, with
h = 1 count for N1, N2, half a step for the balance and half an LSB for the dynamometer signal
(the calibration with exact weights adds ~2e-5 of the force: docs/instruments.md).
"""

from __future__ import annotations

import math
from unittest import mock

import numpy as np
import pytest

from rig.reduction import stand_a
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.reduction import point_readings
from rig.stands.yoke.stand import YokeStand
from rig.wheel_kinematics import dl_dratio
from sensors import Adc
from sensors.noise import LinearDrift, RandomWalkDrift, WhiteNoise

SETTINGS = dict(brake_setpoint_N_m=0.6, normal_force_N=96.2, delta_h_m=1.06e-3, omega_1_set_rad_s=25.13)
NOISE_CODE = (WhiteNoise, RandomWalkDrift, LinearDrift)


@pytest.fixture(scope="module")
def ideal(tmp_path_factory):
    """(stand, outcome, readings, reduced point) of one ideal point; any call into noise code raises."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("RIG_CACHE_DIR", str(tmp_path_factory.mktemp("cache")))
        stand = YokeStand({"mu": 0.4}, {}, ContactSpec("rigid", None, 0.3, table_points=(21, 5, 2)),
                          DriveMode.QUASI_STATIC)
        geometry = stand.params.geometry_at(SETTINGS["delta_h_m"])
        law = LawCoefficients(*stand.law(geometry.b_over_a(96.2), geometry))
        forbidden = [mock.patch.object(cls, "sample", side_effect=AssertionError(f"{cls.__name__} called"))
                     for cls in NOISE_CODE]
        for patch in forbidden:
            patch.start()
        try:
            stand.calibrate(3)
            point = stand.start_point(0, SETTINGS, None, 3)
            point.settle(30.0)
            outcome = point.read(point.gate(20.0))
            readings = point_readings(outcome.record, stand.params, geometry, "ideal point")
            reduced = stand_a.reduce(readings, law, geometry)
        finally:
            for patch in forbidden:
                patch.stop()
    return stand, outcome, readings, reduced


STEP_N_M = 0.098 * 0.400  # default balance_step_N at the 0.400 m arm [N m]


def resolution_bound(reduced, name: str) -> float:
    """sum_i |dy/dx_i| h_i over the inputs with a resolution (h: half step, or 1 count)."""
    p = reduced.propagation
    row = p.jacobian[p.output_names.index(name)]
    h = {"N1": 1.0, "N2": 1.0, "dyn_signal_V": Adc().lsb_V / 2, "T2_step_N_m": STEP_N_M / 2}  # T2 enters additively
    return float(sum(abs(row[p.inputs.names.index(k)]) * v for k, v in h.items()))


def test_the_log_states_an_ideal_balance_and_converter(ideal):
    _, outcome, readings, _ = ideal
    assert outcome.record.readings["balance_noise_std"].value == 0.0
    assert outcome.record.readings["balance_resolution"].value == pytest.approx(STEP_N_M, rel=1e-12)
    assert outcome.record.calibration["dynamometer_10"]["reading_resolution"].value == pytest.approx(20 / 2**16)
    # no noise: the balance's u is its step alone, as a rectangular bias of the scale (step/sqrt(12),
    # = 0.0196/sqrt(3) with the default step: the paper's accuracy read as a +-limit)
    assert readings.brake_moment.u_step == pytest.approx(0.0196 / math.sqrt(3), rel=1e-9)
    assert readings.brake_moment.u == 0.0  # every reading equal: nothing scatters, nothing averages out
    assert readings.dynamometer_signal.u == pytest.approx(Adc().lsb_V / math.sqrt(12), rel=1e-9)


@pytest.mark.parametrize("name", ["l_over_a", "c_over_a", "mu_v", "mu_T"])
def test_ideal_instruments_reproduce_the_truth_to_the_resolution(ideal, name):
    _, outcome, _, reduced = ideal
    error = reduced.values[name] - outcome.truth[name].value
    slack = 1e-4 * abs(outcome.truth[name].value) if name.startswith("mu") else 1e-12  # exact-weight calibration
    assert abs(error) <= resolution_bound(reduced, name) + slack, (name, error, resolution_bound(reduced, name))


def test_l_is_within_the_counting_resolution_of_the_equations_page_2(ideal):
    # Equations §2: delta l = |dl/di_k| delta i_k with delta i_k = i_k (1/N1 + 1/N2) for +-1 count
    stand, outcome, _, reduced = ideal
    g = stand.params.geometry
    n1, n2 = (outcome.record.counters.counters[k].count for k in ("wheel_1", "wheel_2"))
    i_k = reduced.values["i_k"]
    bound = abs(dl_dratio(i_k, g.alpha_1, g.l1, g.l2)) * i_k * (1 / n1 + 1 / n2)
    assert abs(reduced.values["l_m"] - outcome.truth["l"].value) <= bound
    assert 1e-6 < bound < 2e-5  # ~4800 counts: ~1 % of a (Equations §2: N >~ 4000 for delta(l/a) = 0.01)


def test_the_stated_uncertainty_is_the_resolution_alone(ideal):
    _, _, _, reduced = ideal
    sources = reduced.budget.by_source()
    assert "tangent balance" not in sources.index  # no scatter (u = 0): only the scale step remains
    assert sources.loc["tangent balance (scale step)", "mu_T"] > 0.0
    assert np.isfinite(reduced.expanded["mu_T"]) and reduced.driver == "mu_v"
