"""Noise and drift components, seeded streams."""

from __future__ import annotations

import numpy as np
import pytest

from sensors.noise import LinearDrift, RandomWalkDrift, WhiteNoise
from sensors.streams import effect_rng


def test_white_noise_std():
    x = WhiteNoise(2.5e-6, np.random.default_rng(1)).sample(100_000)
    assert x.std() == pytest.approx(2.5e-6, rel=0.01)
    assert abs(x.mean()) < 4 * 2.5e-6 / np.sqrt(x.size)


def test_random_walk_variance_grows_linearly():
    # Var W(t) = D^2 t for a Wiener process (grid points are exact samples of it)
    d = 0.3
    t = np.array([0.0, 25.0, 100.0, -64.0])
    values = np.array([RandomWalkDrift(d, np.random.default_rng(i)).sample(t) for i in range(2000)])
    assert np.all(values[:, 0] == 0.0)
    for j in (1, 2, 3):
        assert values[:, j].var() == pytest.approx(d**2 * abs(t[j]), rel=0.1)


def test_random_walk_does_not_depend_on_call_order():
    t = np.linspace(-30.0, 500.0, 777)
    once = RandomWalkDrift(1e-6, np.random.default_rng(9)).sample(t)
    split = RandomWalkDrift(1e-6, np.random.default_rng(9))
    late, early = split.sample(t[400:]), split.sample(t[:400])
    np.testing.assert_array_equal(np.concatenate([early, late]), once)


def test_linear_drift_is_linear():
    drift = LinearDrift(1e-3, np.random.default_rng(3), t0_s=10.0)
    v = drift.sample(np.array([10.0, 20.0, 30.0]))
    assert v[0] == 0.0 and v[2] == pytest.approx(2 * v[1]) and v[1] == pytest.approx(10 * drift.rate)


def test_streams_reproducible_and_independent():
    a = effect_rng(42, "dynamometer_10", "noise").normal(size=5)
    b = effect_rng(42, "dynamometer_10", "noise").normal(size=5)
    c = effect_rng(42, "dynamometer_10", "drift").normal(size=5)
    d = effect_rng(43, "dynamometer_10", "noise").normal(size=5)
    np.testing.assert_array_equal(a, b)
    assert not np.allclose(a, c) and not np.allclose(a, d)
