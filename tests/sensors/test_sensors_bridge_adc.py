"""Wheatstone bridge against its closed forms; converter quantisation and clipping."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sensors.adc import Adc
from sensors.bridge import Bridge, BridgeConfiguration


def test_full_bridge_hand_number():
    # 1000 ue, k = 2, 5 V, four active gauges: V = V_ex k eps = 10 mV exactly
    assert Bridge(BridgeConfiguration.FULL).output_V(1.0e-3) == pytest.approx(10.0e-3, rel=1e-12)


def test_quarter_bridge_hand_number():
    # V = V_ex k eps/(4 + 2 k eps) = 5 * 2e-3/(4.004) = 2.497502... mV (slightly below the linear 2.5 mV)
    v = Bridge(BridgeConfiguration.QUARTER).output_V(1.0e-3)
    assert v == pytest.approx(0.01 / 4.004, rel=1e-12)
    assert v < 2.5e-3


@given(
    eps=st.floats(-5e-3, 5e-3),
    k=st.floats(1.0, 4.0),
    v_ex=st.floats(0.5, 15.0),
)
def test_bridge_matches_closed_forms(eps, k, v_ex):
    quarter = Bridge(BridgeConfiguration.QUARTER, k, v_ex).output_V(eps)
    half = Bridge(BridgeConfiguration.HALF, k, v_ex).output_V(eps)
    full = Bridge(BridgeConfiguration.FULL, k, v_ex).output_V(eps)
    assert quarter == pytest.approx(v_ex * k * eps / (4.0 + 2.0 * k * eps), rel=1e-9, abs=1e-15)
    assert half == pytest.approx(v_ex * k * eps / 2.0, rel=1e-9, abs=1e-15)
    assert full == pytest.approx(v_ex * k * eps, rel=1e-9, abs=1e-15)


@pytest.mark.parametrize("config, n", [(BridgeConfiguration.QUARTER, 1), (BridgeConfiguration.HALF, 2),
                                       (BridgeConfiguration.FULL, 4)])
def test_small_strain_sensitivity_is_slope(config, n):
    b = Bridge(config, 2.1, 10.0)
    h = 1e-7
    slope = (b.output_V(h) - b.output_V(-h)) / (2 * h)
    assert b.sensitivity_V() == pytest.approx(10.0 * 2.1 * n / 4.0)
    assert slope == pytest.approx(b.sensitivity_V(), rel=1e-6)


def test_adc_lsb_and_zero():
    adc = Adc()  # +-10 V, 16 bit
    assert adc.lsb_V == 20.0 / 65536  # 305.17578125 uV
    r = adc.convert(np.array([0.0]), np.array([0.0]))
    assert r.codes[0] == 32768 and r.volts[0] == 0.0 and r.n_clipped == 0


@given(v=st.floats(-10.0, 10.0 - 1.5 * 20.0 / 65536))
def test_adc_error_within_half_lsb_inside_range(v):
    adc = Adc()
    r = adc.convert(np.zeros(1), np.array([v]))
    assert r.n_clipped == 0
    assert abs(r.volts[0] - v) <= adc.lsb_V / 2 * (1 + 1e-9)


def test_adc_quantisation_error_std_is_lsb_over_sqrt12():
    adc = Adc(-1.0, 1.0, 8)
    v = np.random.default_rng(5).uniform(-0.9, 0.9, 200_000)
    err = adc.convert(np.zeros(v.size), v).volts - v
    assert err.std() == pytest.approx(adc.lsb_V / np.sqrt(12), rel=0.01)


def test_adc_clipping_is_reported():
    adc = Adc()
    v = np.array([-10.0, -10.001, 9.9997, 10.0, 25.0, np.nan])
    r = adc.convert(np.arange(v.size, dtype=float), v)
    assert r.clipped.tolist() == [False, True, False, True, True, True]
    assert r.n_clipped == 4
    assert r.codes.tolist()[:5] == [0, 0, 65535, 65535, 65535]
    assert r.volts[3] == pytest.approx(10.0 - adc.lsb_V)


def test_reading_arrays_are_read_only():
    r = Adc().convert(np.zeros(2), np.zeros(2))
    with pytest.raises(ValueError):
        r.codes[0] = 1
