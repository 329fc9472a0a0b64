"""Speed counters of stand A: lamp + photocell, pulse amplifier, electronic counter, common gate timer.

Chain ([Koziarski] section 3.1.1, Fig. 9: discs 13/14, photocells with lamps 15/16, pulse amplifiers 20/21,
counters 18/19, timer 22): each mark passing a photocell gives a light pulse of amplitude
``pulse_amplitude_V``; the pulse amplifier multiplies it by ``gain`` and its discriminator
emits one counting pulse when the amplified amplitude reaches ``threshold_V``; a counter adds
the counting pulses while its gate is open. One timer opens and closes *all* counters at the
same instants, so the counts N_k share the gate time T and omega_k = 2 pi N_k/(z_k T) (Equations §2). With the amplitude-noise effect off every pulse is counted (the nominal amplified
amplitude must reach the threshold, checked on construction); with it on, a pulse whose noisy
amplitude falls below the threshold is missed. Noise never creates extra pulses.

Counting without one event per pulse: the counting pulses of a channel are the mark-crossing
instants of the true trajectory (:mod:`sensors.strobe`) whose amplified amplitude reaches the
threshold; the timer opens every counter at the same instant and closes them together, so a
count is the number of firing pulses in the half-open gate [open, open + T) - a pulse exactly at
the opening counts, one exactly at the closing does not (the order an event-driven simulation
gives when the gate edges act before a pulse at a tie). That number is found with two binary
searches in the sorted crossing times, for any motion of the wheel (accelerating, stalling,
reversing: the crossings come from the sampled trajectory itself). The amplitudes are drawn for
the same pulses, in the same order, as the event-driven model of earlier versions drew them (the
pulses in [open, open + T]), so counts with the amplitude-noise effect on are unchanged too
(tests/sensors/test_sensors_counters.py holds them against an event-driven reference).

Counting quantisation (model, docs/instruments.md): with the marks' phase at the gate opening
random, N - f T = U_close - U_open with U uniform in [0, 1) at each edge, i.e. triangular on
(-1, 1), variance 1/6; for a known fractional part r of f T the variance is r (1 - r) <= 1/4.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError
from sensors.noise import WhiteNoise
from sensors.strobe import StrobeDisc

DEFAULT_PULSE_AMPLITUDE_V = 0.05
"""Photocell pulse amplitude [V] (assumed: tens of mV from a vacuum/semiconductor photocell)."""
DEFAULT_AMPLIFIER_GAIN = 100.0
"""Pulse amplifier gain [V/V] (assumed)."""
DEFAULT_THRESHOLD_V = 2.5
"""Discriminator threshold at the amplifier output [V] (assumed: half the nominal 5 V pulse)."""
DEFAULT_AMPLITUDE_NOISE_STD_V = 0.00625
"""Pulse-amplitude scatter at the photocell when that effect is on [V] (assumed: 12.5 % of nominal,
so the threshold lies 4 std below the nominal pulse: P(miss) = Phi(-4) = 3.2e-5 per pulse)."""

COUNT_QUANTISATION_STD = 1.0 / np.sqrt(6.0)
"""Standard uncertainty of a count from quantisation, random gate phase [counts]."""


def count_quantisation_variance(fraction: float | None = None) -> float:
    """Variance of a counter's quantisation N - f T [counts^2].

    Parameters
    ----------
    fraction : float, optional
        The fractional part r of f T in [0, 1) when known; None: unknown (uniform).

    Returns
    -------
    float
        r (1 - r) for a known r, else 1/6 [counts^2].
    """
    if fraction is None:
        return 1.0 / 6.0
    r = validate.number("fraction", fraction, 0.0, 1.0, hi_open=True)
    return r * (1.0 - r)


@dataclass(frozen=True, eq=False)
class Photocell:
    """Lamp + photocell: pulse amplitude [V] per mark and optional amplitude noise [V]."""

    pulse_amplitude_V: float = DEFAULT_PULSE_AMPLITUDE_V
    amplitude_noise: WhiteNoise | None = None

    def __post_init__(self) -> None:
        validate.number("pulse_amplitude_V", self.pulse_amplitude_V, 0.0, 100.0, lo_open=True)

    def amplitudes_V(self, n: int) -> np.ndarray:
        """Amplitudes [V] of ``n`` successive pulses."""
        nominal = np.full(n, self.pulse_amplitude_V)
        if self.amplitude_noise is None:
            return nominal
        return nominal + self.amplitude_noise.sample(n)


@dataclass(frozen=True)
class PulseAmplifier:
    """Pulse amplifier with discriminator: gain [V/V], threshold at its output [V]."""

    gain: float = DEFAULT_AMPLIFIER_GAIN
    threshold_V: float = DEFAULT_THRESHOLD_V

    def __post_init__(self) -> None:
        validate.number("pulse_gain", self.gain, 0.0, 1.0e6, lo_open=True)
        validate.number("threshold_V", self.threshold_V, 0.0, 1000.0, lo_open=True)

    def fires(self, amplitudes_V: np.ndarray) -> np.ndarray:
        """True where a photocell pulse [V] gives a counting pulse."""
        return self.gain * np.asarray(amplitudes_V, dtype=float) >= self.threshold_V


@dataclass(frozen=True, eq=False)
class CounterChannel:
    """One speed channel: strobe disc, photocell, pulse amplifier (its counter is built per gate)."""

    disc: StrobeDisc
    photocell: Photocell = field(default_factory=Photocell)
    amplifier: PulseAmplifier = field(default_factory=PulseAmplifier)

    def __post_init__(self) -> None:
        nominal = self.amplifier.gain * self.photocell.pulse_amplitude_V
        if nominal < self.amplifier.threshold_V:
            raise InstrumentParameterError(
                "threshold_V", self.amplifier.threshold_V,
                f"<= gain * pulse amplitude = {nominal:g} V (else no pulse is ever counted)",
            )


@dataclass(frozen=True)
class CountReading:
    """Counter totals over one common gate: counts [1] and marks per disc [1] by channel name,
    gate opening [s] and gate time [s]."""

    counts: Mapping[str, int]
    marks: Mapping[str, int]
    gate_open_s: float
    gate_time_s: float

    def angular_speed_rad_s(self, channel: str) -> float:
        """Mean angular speed over the gate, 2 pi N/(z T) [rad/s] (Equations §2)."""
        if channel not in self.counts:
            raise InstrumentParameterError("channel", channel, "one of " + ", ".join(sorted(self.counts)))
        return 2.0 * np.pi * self.counts[channel] / (self.marks[channel] * self.gate_time_s)


@dataclass(frozen=True, eq=False)
class SpeedCounters:
    """The counting system: named channels sharing one gate timer."""

    channels: Mapping[str, CounterChannel]

    def __post_init__(self) -> None:
        if not self.channels:
            raise InstrumentParameterError("channels", dict(self.channels), "at least one named CounterChannel")
        for name, ch in self.channels.items():
            if not isinstance(ch, CounterChannel):
                raise InstrumentParameterError(f"channels[{name!r}]", ch, "a CounterChannel")
        object.__setattr__(self, "channels", MappingProxyType(dict(self.channels)))

    def measure(
        self,
        trajectories: Mapping[str, tuple[np.ndarray, np.ndarray]],
        gate_open_s: float,
        gate_time_s: float,
    ) -> CountReading:
        """Count over the gate [gate_open_s, gate_open_s + gate_time_s) [s].

        ``trajectories[name] = (t [s], theta [rad])``: the wheel's true angle samples, which must
        cover the gate. A channel with no pulse in the gate reads 0.
        """
        missing = set(self.channels) - set(trajectories)
        if missing:
            raise InstrumentParameterError(
                "trajectories", sorted(trajectories), f"an entry for each channel {sorted(self.channels)}"
            )
        t_open = validate.number("gate_open_s", gate_open_s)
        duration = validate.number("gate_time_s", gate_time_s, 0.0, lo_open=True)
        t_close = t_open + duration
        counts = {}
        for name, channel in self.channels.items():
            t, theta = validate.time_series(
                f"trajectories[{name!r}].t_s", trajectories[name][0],
                f"trajectories[{name!r}].theta_rad", trajectories[name][1],
            )
            if t[0] > t_open or t[-1] < t_close:
                raise InstrumentParameterError(
                    "gate", f"[{t_open!r}, {t_close!r}] s",
                    f"inside the samples of channel {name!r}, [{t[0]!r}, {t[-1]!r}] s",
                )
            times = channel.disc.crossing_times(t, theta)
            first, last = np.searchsorted(times, t_open, "left"), np.searchsorted(times, t_close, "right")
            fires = channel.amplifier.fires(channel.photocell.amplitudes_V(last - first))
            inside = np.searchsorted(times[first:last], t_close, "left")  # the gate closes before a pulse at t_close
            counts[name] = int(np.count_nonzero(fires[:inside]))
        return CountReading(
            counts=MappingProxyType(counts),
            marks=MappingProxyType({n: ch.disc.marks for n, ch in self.channels.items()}),
            gate_open_s=t_open,
            gate_time_s=duration,
        )


def stand_a_counters(
    *,
    marks: tuple[int, int] = (60, 60),
    phases_rad: tuple[float, float] = (0.0, 0.0),
    amplitude_noise_rngs: tuple[np.random.Generator | None, np.random.Generator | None] = (None, None),
) -> SpeedCounters:
    """Stand A's speed counters: channels "wheel_1" (disc 13) and "wheel_2" (disc 14).

    Parameters
    ----------
    marks : tuple of (int, int), optional
        Marks per revolution of the two stroboscope discs (default 60 each, assumed).
    phases_rad : tuple of (float, float), optional
        Angular phase of each disc's first mark [rad] (default 0).
    amplitude_noise_rngs : tuple of two numpy.random.Generator or None, optional
        Stream of each channel's pulse-amplitude noise; None: that effect is off (not built).

    Returns
    -------
    SpeedCounters
        The two channels on a common gate timer [counts].
    """
    channels = {}
    for i, name in enumerate(("wheel_1", "wheel_2")):
        rng = amplitude_noise_rngs[i]
        noise = None if rng is None else WhiteNoise(DEFAULT_AMPLITUDE_NOISE_STD_V, rng)
        channels[name] = CounterChannel(StrobeDisc(marks[i], phases_rad[i]), Photocell(amplitude_noise=noise))
    return SpeedCounters(channels)
