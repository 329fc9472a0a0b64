"""Invalid parameters raise InstrumentParameterError naming parameter, value and valid range;
the package does not import rig."""

from __future__ import annotations

import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sensors import (
    Adc,
    Amplifier,
    Bridge,
    BridgeConfiguration,
    CounterChannel,
    Lever,
    PulseAmplifier,
    Recorder,
    StrobeDisc,
    TangentBalance,
    WeightSet,
    WhiteNoise,
    effect_rng,
    stand_a_dynamometer,
)
from sensors.errors import InstrumentParameterError

REPO = pathlib.Path(__file__).resolve().parents[2]

non_positive = st.one_of(st.floats(max_value=0.0, allow_nan=False), st.just(math.nan), st.just(math.inf))
not_a_number = st.one_of(st.just(math.nan), st.just(-math.inf), st.just(True), st.text(max_size=3), st.none())


def _raises_named(name, build):
    with pytest.raises(InstrumentParameterError) as info:
        build()
    err = info.value
    assert isinstance(err, ValueError)
    assert err.name == name and name in str(err) and "valid" in str(err)


@given(x=non_positive)
def test_non_positive_parameters(x):
    _raises_named("excitation_V", lambda: Bridge(BridgeConfiguration.FULL, 2.0, x))
    _raises_named("amplifier_gain", lambda: Amplifier(x))
    _raises_named("sample_rate_Hz", lambda: Recorder(sample_rate_Hz=x))
    _raises_named("balance_arm_m", lambda: TangentBalance(arm_m=x))
    _raises_named("balance_resolution_N", lambda: TangentBalance(resolution_N=x))
    _raises_named("threshold_V", lambda: PulseAmplifier(threshold_V=x))
    _raises_named("noise_std", lambda: WhiteNoise(x, np.random.default_rng(0)))
    _raises_named("quantity_arm_m", lambda: Lever(0.1, 0.1, x))


@given(x=not_a_number)
def test_non_numbers(x):
    _raises_named("gauge_factor", lambda: Bridge(BridgeConfiguration.HALF, x))
    _raises_named("phase_rad", lambda: StrobeDisc(10, x))
    _raises_named("error_bound_N", lambda: WeightSet((1.0,), x))


@given(k=st.one_of(st.floats(max_value=0.49, allow_nan=False), st.floats(min_value=10.01, allow_infinity=False)))
def test_gauge_factor_range(k):
    _raises_named("gauge_factor", lambda: Bridge(BridgeConfiguration.QUARTER, k))


@given(bits=st.one_of(st.integers(max_value=3), st.integers(min_value=25), st.just(12.0), st.just(True)))
def test_adc_bits(bits):
    _raises_named("adc_bits", lambda: Adc(bits=bits))


@given(marks=st.one_of(st.integers(max_value=0), st.just(2.5), st.just(False)))
def test_strobe_marks(marks):
    _raises_named("marks", lambda: StrobeDisc(marks))


@given(seed=st.one_of(st.integers(max_value=-1), st.just(1.5), st.just("7")))
def test_seed(seed):
    _raises_named("seed", lambda: effect_rng(seed, "x", "noise"))


def test_other_named_errors():
    _raises_named("bridge_configuration", lambda: Bridge("full"))  # an Enum, not a string flag
    _raises_named("adc_v_max_V", lambda: Adc(1.0, -1.0))
    _raises_named("noise_rng", lambda: WhiteNoise(1.0, 42))
    _raises_named("nominal_N", lambda: WeightSet(()))
    dyn = stand_a_dynamometer()
    _raises_named("force_N", lambda: dyn.read(np.zeros(1), np.array([1e6])))
    _raises_named("force_N[1]", lambda: dyn.read(np.arange(2.0), np.array([0.0, np.nan])))
    _raises_named("force_N", lambda: dyn.read(np.zeros(3), np.ones(2)))
    _raises_named("threshold_V", lambda: CounterChannel(StrobeDisc(1), amplifier=PulseAmplifier(threshold_V=50.0)))


def test_sensors_does_not_import_rig():
    code = "import sys, sensors, sensors.counters, sensors.calibration; sys.exit(int('rig' in sys.modules))"
    done = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    for path in (REPO / "sensors").glob("*.py"):
        text = path.read_text()
        assert "import rig" not in text and "from rig" not in text, path
