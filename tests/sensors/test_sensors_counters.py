"""Stroboscope discs, photocells, pulse amplifiers and counters on a common gate."""

from __future__ import annotations

import math
from unittest import mock

import numpy as np
import pytest
import simpy
from hypothesis import example, given, settings
from hypothesis import strategies as st
from simpy.events import URGENT

from sensors.counters import (
    COUNT_QUANTISATION_STD,
    CounterChannel,
    Photocell,
    PulseAmplifier,
    SpeedCounters,
    count_quantisation_variance,
    stand_a_counters,
)
from sensors.errors import InstrumentParameterError
from sensors.noise import WhiteNoise
from sensors.strobe import StrobeDisc


def _ramp(omega, t_end, theta0=0.0):
    """Constant-speed angle: two samples suffice (the trajectory is linear between samples)."""
    t = np.array([0.0, t_end])
    return t, theta0 + omega * t


def _one(marks, phase=0.0, **kw):
    return SpeedCounters({"w": CounterChannel(StrobeDisc(marks, phase), **kw)})


@settings(max_examples=60, deadline=None)
@example(rev_per_s=1.0, marks=1, phase=0.0, gate_open=0.0, gate=1.0)  # a mark in the light path as the gate opens
@given(
    rev_per_s=st.floats(0.05, 8.0),
    marks=st.integers(1, 120),
    phase=st.floats(0.0, 2 * np.pi),
    # 0 or a real instant: a subnormal opening (2e-311 s) rounds away in open + gate, shifting the gate
    gate_open=st.one_of(st.just(0.0), st.floats(1e-9, 3.0)),
    gate=st.floats(0.01, 5.0),
)
def test_constant_speed_counts_are_floor_or_ceil(rev_per_s, marks, phase, gate_open, gate):
    omega = 2 * np.pi * rev_per_s
    reading = _one(marks, phase).measure({"w": _ramp(omega, 10.0)}, gate_open, gate)
    expected = rev_per_s * marks * gate  # analytic number of marks passing in the gate
    n = reading.counts["w"]
    assert isinstance(n, int)
    assert math.floor(expected) - 1e-9 <= n <= math.ceil(expected) + 1e-9 or abs(n - expected) <= 1e-6


def test_counts_equal_the_exact_mark_count():
    # marks at u = (theta - phase) z/(2 pi) integer; count = #integers in [u(open), u(close))
    rng = np.random.default_rng(21)
    for _ in range(200):
        f, z, ph = rng.uniform(0.5, 5.0), int(rng.integers(5, 90)), rng.uniform(0, 2 * np.pi)
        t0, gate = rng.uniform(0, 2), rng.uniform(0.1, 3)
        u0 = (2 * np.pi * f * t0 - ph) * z / (2 * np.pi)
        u1 = (2 * np.pi * f * (t0 + gate) - ph) * z / (2 * np.pi)
        n = _one(z, ph).measure({"w": _ramp(2 * np.pi * f, 6.0)}, t0, gate).counts["w"]
        assert n == math.ceil(u1) - math.ceil(u0)


def test_gate_is_half_open():
    # 1 rev/s, 4 marks: crossings at t = 0, 0.25, 0.5, ... (exact binary numbers).
    # Gate [0.5, 1.5): pulses at 0.5, 0.75, 1.0, 1.25 count; the one at 1.5 does not.
    t = np.linspace(0.0, 2.0, 9)
    n = _one(4).measure({"w": (t, 2 * np.pi * t)}, 0.5, 1.0).counts["w"]
    assert n == 4


def test_common_gate_and_angular_speed():
    counters = stand_a_counters()
    omega1, i_k = 2 * np.pi * 4.0, 0.8115  # 240 rpm on wheel 1 (Equations §3.1)
    traj = {"wheel_1": _ramp(omega1, 25.0), "wheel_2": _ramp(i_k * omega1, 25.0)}
    r = counters.measure(traj, 1.0, 20.0)
    assert r.gate_time_s == 20.0 and dict(r.marks) == {"wheel_1": 60, "wheel_2": 60}
    assert r.counts["wheel_1"] == 4800  # 240 pulses/s * 20 s, marks and gate both aligned
    assert abs(r.counts["wheel_2"] - 0.8115 * 4800) <= 1
    assert r.angular_speed_rad_s("wheel_1") == pytest.approx(omega1)
    assert r.angular_speed_rad_s("wheel_2") == pytest.approx(i_k * omega1, abs=2 * np.pi / (60 * 20))


def test_quantisation_model_over_random_phases():
    # f T = 12.3 marks: N is 12 or 13, P(13) = r = 0.3, Var N = r (1 - r) = 0.21
    rng = np.random.default_rng(7)
    counts = []
    for _ in range(1500):
        ch = _one(10, rng.uniform(0, 2 * np.pi))
        counts.append(ch.measure({"w": _ramp(2 * np.pi * 1.23, 4.0)}, rng.uniform(0, 1), 1.0).counts["w"])
    counts = np.array(counts)
    assert set(counts.tolist()) == {12, 13}
    assert counts.mean() == pytest.approx(12.3, abs=3 * np.sqrt(0.21 / counts.size))
    assert counts.var() == pytest.approx(count_quantisation_variance(0.3), rel=0.1)
    assert count_quantisation_variance() == pytest.approx(1 / 6) and COUNT_QUANTISATION_STD == pytest.approx(0.4082, abs=1e-4)


def test_u_of_ik_falls_as_one_over_gate_time():
    """Acceptance: std of i_k from counts ~ 1/T within 10 % over a decade of gate times.

    Random disc phases and gate opening; the common drive speed is drawn per repeat from
    U[0.75, 1.25] x nominal (i_k fixed), which spreads the fractional part of f T over [0, 1) as in
    a series of operating points. Model: Var(di/i) = (1/6) E[1/N1^2 + 1/N2^2], E[1/k^2] = 1/(0.75 1.25).
    """
    rng = np.random.default_rng(2024)
    i_k, z, f1 = 0.8115, 10, 1.0  # wheel 1 at 1 rev/s with 10 marks: 10 pulses/s
    stds = {}
    for gate in (1.0, np.sqrt(10.0), 10.0):
        rel = []
        for _ in range(700):
            k = rng.uniform(0.75, 1.25)
            counters = SpeedCounters({"1": CounterChannel(StrobeDisc(z, rng.uniform(0, 2 * np.pi))),
                                      "2": CounterChannel(StrobeDisc(z, rng.uniform(0, 2 * np.pi)))})
            w1 = 2 * np.pi * f1 * k
            traj = {"1": _ramp(w1, gate + 2), "2": _ramp(i_k * w1, gate + 2)}
            r = counters.measure(traj, rng.uniform(0, 1), gate)
            rel.append(r.counts["2"] / r.counts["1"] / i_k - 1.0)  # i_k = N2 z1/(N1 z2), z1 = z2
        model = np.sqrt((1 / 6) * (1 + 1 / i_k**2) / (z * f1 * gate) ** 2 / (0.75 * 1.25))
        stds[gate] = (np.std(rel), model)
    products = [s * g for g, (s, _) in stds.items()]
    assert max(products) / min(products) < 1.10
    for s, model in stds.values():
        assert s == pytest.approx(model, rel=0.10)


def test_reversing_wheel_counts_every_crossing():
    # u = 3.3 sin(2 pi t) + 0.5 (10 marks, phase -0.5 mark): per period 3 + 6 + 3 = 12 crossings
    t = np.linspace(0.0, 6.0, 60_001)
    theta = 3.3 * np.sin(2 * np.pi * t) * 2 * np.pi / 10
    ch = _one(10, phase=-0.5 * 2 * np.pi / 10)
    r = ch.measure({"w": (t, theta)}, 0.1, 5.0)  # five whole periods from t = 0.1 (no mark there)
    assert r.counts["w"] == 60


def test_forward_then_back_counts_both_ways():
    t = np.array([0.0, 1.0, 2.0])
    theta = np.array([0.0, 2 * np.pi, 0.0]) + 0.01  # one revolution forward, one back
    assert _one(20).measure({"w": (t, theta)}, 0.0, 2.0).counts["w"] == 40


def test_stalled_wheel_reads_zero():
    t = np.linspace(0.0, 10.0, 11)
    r = stand_a_counters().measure({"wheel_1": (t, np.full(11, 1.234)), "wheel_2": (t, np.full(11, -3.0))}, 1.0, 5.0)
    assert dict(r.counts) == {"wheel_1": 0, "wheel_2": 0}


def test_wheel_that_stops_mid_gate():
    t = np.array([0.0, 2.0, 10.0])
    theta = np.array([0.0, 2 * np.pi * 2.0, 2 * np.pi * 2.0]) + 0.001  # 1 rev/s for 2 s, then stalls
    assert _one(60).measure({"w": (t, theta)}, 1.0, 5.0).counts["w"] == 60  # only the last turn is in the gate


def test_slow_wheel_short_gate_reads_zero_not_error():
    r = _one(4).measure({"w": _ramp(0.01, 10.0, theta0=0.2)}, 1.0, 0.5)
    assert r.counts["w"] == 0
    assert r.angular_speed_rad_s("w") == 0.0


def test_amplitude_noise_off_makes_no_call_and_misses_nothing():
    with mock.patch.object(WhiteNoise, "sample", side_effect=AssertionError("noise called")):
        r = stand_a_counters().measure({"wheel_1": _ramp(25.0, 3.0, 0.5), "wheel_2": _ramp(20.0, 3.0)}, 0.0, 2.0)
    u0, u1 = 0.5 * 60 / (2 * np.pi), (0.5 + 50.0) * 60 / (2 * np.pi)
    assert r.counts["wheel_1"] == math.ceil(u1) - math.ceil(u0)  # every mark in the gate is counted


def test_amplitude_noise_on_misses_pulses():
    rng = np.random.default_rng(5)
    noisy = CounterChannel(StrobeDisc(60), Photocell(amplitude_noise=WhiteNoise(0.025, rng)))
    ideal = CounterChannel(StrobeDisc(60))
    traj = _ramp(2 * np.pi * 4.0, 12.0, theta0=1e-3)
    n_noisy = SpeedCounters({"w": noisy}).measure({"w": traj}, 0.5, 10.0).counts["w"]
    n_ideal = SpeedCounters({"w": ideal}).measure({"w": traj}, 0.5, 10.0).counts["w"]
    # amplified 5 V +- 2.5 V against a 2.5 V threshold: P(miss) = Phi(-1) = 15.9 %
    assert n_ideal == 2400
    assert n_noisy == pytest.approx(2400 * (1 - 0.1587), abs=4 * np.sqrt(2400 * 0.1587 * 0.8413))


def test_channel_that_could_never_count_is_rejected():
    with pytest.raises(InstrumentParameterError, match="threshold_V"):
        CounterChannel(StrobeDisc(10), Photocell(0.01), PulseAmplifier(gain=100.0, threshold_V=2.5))


def test_gate_outside_samples_and_missing_channel_raise():
    c = stand_a_counters()
    traj = {"wheel_1": _ramp(1.0, 5.0), "wheel_2": _ramp(1.0, 5.0)}
    with pytest.raises(InstrumentParameterError, match="gate"):
        c.measure(traj, 1.0, 10.0)
    with pytest.raises(InstrumentParameterError, match="trajectories"):
        c.measure({"wheel_1": traj["wheel_1"]}, 1.0, 1.0)
    with pytest.raises(InstrumentParameterError, match="gate_time_s"):
        c.measure(traj, 1.0, 0.0)
    with pytest.raises(InstrumentParameterError, match=r"t_s\[1\]"):
        c.measure({"wheel_1": (np.array([0.0, 0.0, 5.0]), np.zeros(3)), "wheel_2": traj["wheel_2"]}, 1.0, 1.0)


def test_crossing_times_vectorised_match_analytic():
    # accelerating wheel theta = 3 t^2 [rad]; mark n (phase 0.1 rad, 8 marks) at 3 t^2 = 0.1 + 2 pi n/8,
    # marks 0..3 lie below theta(1 s) = 3 rad
    disc = StrobeDisc(8, phase_rad=0.1)
    t = np.linspace(0.0, 1.0, 1001)
    times = disc.crossing_times(t, 3.0 * t**2)
    analytic = np.sqrt((0.1 + 2 * np.pi * np.arange(4) / 8) / 3.0)
    np.testing.assert_allclose(times, analytic, atol=2e-4)  # chord interpolation error ~ dt^2 theta''/8


def _event_driven_count(channel, t, theta, t_open, duration):
    """Reference: the event-driven counter of earlier versions (one simpy event per pulse, gate
    edges URGENT so that they act before a pulse at a tie), for the same channel and draws."""
    env = simpy.Environment(initial_time=t_open)
    state = {"open": False, "count": 0}

    def edge(at):
        event = simpy.events.Event(env)
        event._ok, event._value = True, None
        env.schedule(event, URGENT, max(at - env.now, 0.0))
        return event

    def gate():
        yield edge(t_open)
        state["open"] = True
        yield edge(t_open + duration)
        state["open"] = False

    times = channel.disc.crossing_times(t, theta)
    window = times[np.searchsorted(times, t_open, "left"):np.searchsorted(times, t_open + duration, "right")]
    fires = channel.amplifier.fires(channel.photocell.amplitudes_V(window.size))

    def pulses():
        for at, fire in zip(window.tolist(), fires.tolist()):
            yield env.timeout(max(at - env.now, 0.0))
            state["count"] += bool(fire and state["open"])

    env.process(gate())
    env.process(pulses())
    env.run()
    return state["count"]


@settings(max_examples=80, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    marks=st.integers(1, 120),
    noise_std_V=st.sampled_from([None, 0.00625, 0.025]),
    accelerating=st.booleans(),
    t_open=st.floats(0.0, 2.0),
    duration=st.floats(0.05, 4.0),
)
def test_counts_equal_the_event_driven_reference(seed, marks, noise_std_V, accelerating, t_open, duration):
    # Same pulses, same amplitude draws (same generator state), same half-open gate: same count,
    # with the amplitude-noise effect on or off, for a constant or an accelerating/reversing wheel.
    t = np.linspace(0.0, 6.5, 400)
    theta = 25.0 * t + (3.0 * np.sin(2.0 * t) if accelerating else 0.0) + 0.1
    if accelerating:
        theta = theta - 2.0 * t ** 2  # slows down, stops and reverses within the samples
    counts = []
    for _ in range(2):
        noise = None if noise_std_V is None else WhiteNoise(noise_std_V, np.random.default_rng(seed))
        counts.append(CounterChannel(StrobeDisc(marks, 0.3), Photocell(amplitude_noise=noise)))
    fast = SpeedCounters({"w": counts[0]}).measure({"w": (t, theta)}, t_open, duration).counts["w"]
    assert fast == _event_driven_count(counts[1], t, theta, t_open, duration)


def test_aligned_pulses_at_both_gate_edges_against_reference():
    # crossings at exact binary instants, gate edges on pulses: the tie rule of both models
    t = np.linspace(0.0, 4.0, 17)
    theta = 2 * np.pi * t
    for t_open, duration in ((0.5, 1.0), (0.25, 2.75), (0.0, 0.25)):
        fast = _one(4).measure({"w": (t, theta)}, t_open, duration).counts["w"]
        assert fast == _event_driven_count(CounterChannel(StrobeDisc(4)), t, theta, t_open, duration)
