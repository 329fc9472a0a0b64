"""Acceptance (3): simulate -> log -> reduce; M_C = T_Mo + R_c F_T and mu recovered within u."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rig.errors import ParameterError
from rig.logbook import LogWriter, RunMetadata, check_log, utc_timestamp
from rig.logbook.truth import read_truth
from rig.stands.base import DriveMode
from tests.stands.disc_roller.conftest import make_stand, settings

MU = 0.8
L_SWEEP_MM = (-20.0, -10.0, -3.2, 0.0, 3.2, 10.0, 20.0)  # Equations §3.2 (l/a = 0, +-0.8, +-2.5, +-5)


def simulate(stand, points, path, seed=11, gate=2.0):
    """Run the points as the operator would (calibration once, each from the previous steady state)."""
    writer = LogWriter(path, RunMetadata("# test scene\n", seed, "disc_roller", utc_timestamp()))
    stand.calibrate(seed)
    previous = None
    for index, point_settings in enumerate(points):
        simulation = stand.start_point(index, point_settings, previous, seed)
        simulation.settle(20.0)
        outcome = simulation.read(simulation.gate(gate))
        writer.write_point(outcome.record, outcome.truth)
        previous = point_settings
    return writer.finalize()


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    """F_T, F_V, T_Mo versus l at c = 0, 36 N, dynamic drive with the loop compliance and noise."""
    stand = make_stand({"loop_compliance": {}, "recorder_noise": {}, "dynamometer_drift": {}})
    points = [settings(l_m=l * 1e-3) for l in L_SWEEP_MM]
    path = simulate(stand, points, tmp_path_factory.mktemp("sweep") / "log.h5")
    return stand, path, stand.reduce_log(path), read_truth(path)


def test_log_has_the_stand_schema(sweep):
    stand, path, _, _ = sweep
    assert check_log(path, stand.LOG_SCHEMA) == list(range(len(L_SWEEP_MM)))


def test_forces_and_moment_versus_l_have_the_expected_shape(sweep):
    _, _, _, truth = sweep
    f_t = truth["F_T_N"].to_numpy()
    assert np.all(np.diff(f_t) < 0)  # F_x on the disc falls through l (nu_T <= 0 for l > 0)
    assert f_t[3] == pytest.approx(0.0, abs=1e-4)  # l = 0, c = 0: no peripheral force (1e-7 of mu F_N)
    # T_Mo = -(M_C + R_c F_x): the transfer R_c F_T dominates away from l = 0 (hard case 6)
    assert np.all(np.abs(truth["T_Mo_N_m"].to_numpy()[[0, -1]]) > 5 * truth["M_C_N_m"].to_numpy()[[0, -1]])


def test_pivoting_moment_recovered_within_its_uncertainty(sweep):
    _, _, reduced, truth = sweep
    error = reduced["M_C_N_m"].to_numpy() - truth["M_C_N_m"].to_numpy()
    u = reduced["u_M_C_N_m"].to_numpy()
    assert np.all(np.isfinite(u)) and np.all(u > 0)
    assert np.all(np.abs(error) <= 2.5 * u), (error, u)
    # the transfer R_c F_T is ~25 N m x 0.17 m here: u(M_C) is dominated by it, not by M_C itself
    assert np.all(u < 0.5 * truth["M_C_N_m"].to_numpy().max())


def test_rolling_point_and_mu_recovered(sweep):
    _, _, reduced, truth = sweep
    assert reduced["l_over_a"].to_numpy() == pytest.approx(np.array(L_SWEEP_MM) / 4.0)
    assert reduced["c_over_a"].to_numpy() == pytest.approx(0.0)
    for name in ("mu_T", "mu_v", "mu_M"):
        value, u = reduced[name].to_numpy(), reduced[f"u_{name}"].to_numpy()
        ok = np.isfinite(value)
        assert ok.sum() >= 6, name  # mu_T is not reportable at l = 0 (nu_T = 0, hard case 8)
        assert np.all(np.abs(value[ok] - MU) <= 3 * u[ok] + 1e-9), (name, value, u)
    assert math.isnan(reduced["mu_T"].iloc[3]) and "nu_T" in reduced["reason"].iloc[3]


def test_reverse_running_and_twist_are_reduced_in_the_canonical_frame(tmp_path):
    stand = make_stand({"loop_compliance": {}}, drive=DriveMode.QUASI_STATIC)
    sigma = math.asin(8.0 / 70.2)  # c = 8 mm, c/a = 2 (eq. 36)
    points = [settings(l_m=10e-3, sigma_rad=sigma), settings(l_m=10e-3, sigma_rad=sigma, direction=-1),
              settings(l_m=-10e-3, sigma_rad=-sigma, direction=-1)]
    path = simulate(stand, points, tmp_path / "log.h5", gate=0.5)
    reduced, truth = stand.reduce_log(path), read_truth(path)
    assert reduced["c_over_a"].to_numpy() == pytest.approx([2.0, -2.0, 2.0], rel=1e-9)  # mirror x in reverse
    assert reduced["c_over_a"].to_numpy() == pytest.approx(truth["c_over_a"].to_numpy(), rel=1e-9)
    for name in ("mu_v", "mu_T", "mu_M"):
        assert np.all(np.abs(reduced[name].to_numpy() - MU) <= 3 * reduced[f"u_{name}"].to_numpy()), name
    assert np.all(np.abs(reduced["M_C_N_m"] - truth["M_C_N_m"]) <= 2.5 * reduced["u_M_C_N_m"])


def test_disc_bearing_friction_biases_the_pivoting_moment_by_its_torque(tmp_path):
    """A systematic error of the method: the momentometer also carries the disc bearing's friction."""
    torque = 0.05
    stand = make_stand({"bearing_friction": {"disc_torque_N_m": torque, "roller_torque_N_m": 0.0}},
                       drive=DriveMode.QUASI_STATIC)
    path = simulate(stand, [settings(), settings(direction=-1)], tmp_path / "log.h5", gate=0.5)
    bias = stand.reduce_log(path)["M_C_N_m"].to_numpy() - read_truth(path)["M_C_N_m"].to_numpy()
    assert bias == pytest.approx([torque, torque], abs=5e-3)


def test_swinging_logs_are_refused(tmp_path):
    stand = make_stand({"swinging_drive": {}, "contact_relaxation": {}})
    with pytest.raises(ParameterError, match="steady operating point"):
        stand.reduce_log(tmp_path / "missing.h5")
