"""Acceptance: the text's speed data from the simulated counters, and simulate -> log -> reduce -> mu recovered."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rig.logbook import LogWriter, RunMetadata, utc_timestamp
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.yoke.stand import YokeStand
from tests.stands.yoke import helpers

SWEEP = (-1.2, -0.6, -0.2, 0.3, 0.6, 1.0, 1.3)  # set-points [N m] moving l/a over about -1 .. +1 (load_device)


def write_sweep(st, path, brakes, *, seed=11, gate_time=20.0, **setting):
    writer = LogWriter(path, RunMetadata("test sweep", seed, "yoke", utc_timestamp()))
    previous = None
    for k, brake in enumerate(brakes):
        s = helpers.settings(brake=brake, **setting)
        _, _, out = helpers.run_point(st, s, previous, index=k, seed=seed, gate_time=gate_time)
        writer.write_point(out.record, out.truth)
        previous = s
    return writer.finalize()


def test_text_speed_data_at_l_near_0_from_the_counters():
    # [Koziarski] section 3.1.1: 240 rpm of wheel 1, w0/w1 = 1.77, w0 = 44 rad/s (Equations §3.1: 1.77 x 25.13 = 44.5)
    st = helpers.stand(("drive_compliance", "brake_dynamics", "load_device"))  # l = 0 needs T_set ~ -0.03 N m
    w1 = 240 * 2 * math.pi / 60
    s0 = helpers.settings(omega=w1)
    g = st.params.geometry
    i_k0 = g.r1 / -g.l2  # at l = 0 the peripheral speeds are equal: w1 r1 = w2 r2 (Equations §3.1)
    brake = st.contact_for(s0).moments_scalar(w1, w1 * i_k0)[1]  # the set-point that puts C at l = 0
    s = helpers.settings(brake=brake, omega=w1)
    _, _, out = helpers.run_point(st, s, s, gate_time=20.0)
    counts = out.record.counters
    n1, n2 = counts.counters["wheel_1"].count, counts.counters["wheel_2"].count
    omega_1 = 2 * math.pi * n1 / (60 * counts.gate_time_s)
    spin_ratio = math.sin(g.alpha_1) + n2 / n1  # w0/w1 = sin(alpha1) + i_k, eq. (1)
    assert abs(out.truth["l_over_a"].value) < 0.01
    assert spin_ratio == pytest.approx(1.77, abs=0.005)
    assert omega_1 * spin_ratio == pytest.approx(44.0, abs=0.6)
    assert omega_1 * g.r1 == pytest.approx(1.03, abs=0.005)  # v = 1.03 m/s


def _agree(frame, name, k=3.0):
    """|reduced - true| <= k u for every finite reduced value; returns how many were checked."""
    finite = frame[name].notna()
    err = (frame.loc[finite, name] - frame.loc[finite, f"true_{name}"]).abs()
    bad = frame.loc[finite][err > k * frame.loc[finite, f"u_{name}"]]
    assert bad.empty, bad[[name, f"u_{name}", f"true_{name}"]]
    return int(finite.sum())


def test_brake_sweep_crosses_the_contact_and_mu_is_recovered(tmp_path):
    # acceptance (2): all dynamic and instrument effects except bearing friction (which biases mu_T, below)
    effects = tuple(e for e in helpers.EFFECTS_ALL if e != "bearing_friction")
    st = helpers.stand(effects)
    frame = st.reduce_log(write_sweep(st, tmp_path / "log.h5", SWEEP))
    assert frame["true_l_over_a"].min() < -0.8 and frame["true_l_over_a"].max() > 1.2
    assert _agree(frame, "l_over_a") == len(SWEEP)
    assert _agree(frame, "mu_v") == len(SWEEP)
    assert _agree(frame, "mu_T") >= len(SWEEP) - 1
    assert np.all(frame["true_mu_v"] == 0.4)


def test_with_a_real_surrogate_table_law(tmp_path, monkeypatch):
    # the same closed loop through rig.stands.contact_law (rigid model, small table cached in tmp_path)
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "cache"))
    spec = ContactSpec("rigid", None, 0.3, table_points=(21, 5, 5))
    st = YokeStand({}, {"balance_noise": {}, "dynamometer_noise": {}, "load_device": {}}, spec, DriveMode.QUASI_STATIC)
    frame = st.reduce_log(write_sweep(st, tmp_path / "log.h5", (-0.8, 0.4, 1.2), gate_time=20.0, force=385.0))
    assert _agree(frame, "l_over_a") == 3
    assert _agree(frame, "mu_v") == 3
    assert _agree(frame, "mu_T") == 3


def test_bearing_friction_of_wheel_2_biases_mu_t_as_predicted(tmp_path):
    # The balance reads the brake moment T_B = T2 - T_f2, so eq. (35) gives mu - T_f2/(F_N D)
    # with D = -(l - l2) nu_T - a nu_0: a real systematic error of the method (docs/stand-a.md).
    t_f2 = 0.1
    st = helpers.stand(("bearing_friction",), drive=DriveMode.QUASI_STATIC,
                       bearing_friction={"moment_1_N_m": 0.03, "moment_2_N_m": t_f2})
    frame = st.reduce_log(write_sweep(st, tmp_path / "log.h5", (0.6,)))
    row = frame.iloc[0]
    g = st.params.geometry
    d = -(row["l_m"] - g.l2) * row["nu_T"] - g.a * row["nu_0"]
    bias = -t_f2 / (96.2 * d)
    assert abs(bias) > 5 * row["u_mu_T"]  # large against the stated uncertainty ...
    assert row["mu_T"] - 0.4 == pytest.approx(bias, abs=2 * row["u_mu_T"])  # ... and as predicted
    assert row["mu_v"] == pytest.approx(0.4, abs=3 * row["u_mu_v"])  # mu_v does not see the bearings
