"""Strain-gauge dynamometer: force [N] -> strain -> Wheatstone bridge -> amplifier -> ADC codes.

Stand A's dynamometer 10 holds the yoke of wheel 2 at 102 mm from the yoke axle 4 and so
measures F_y through the lever 102 mm / 42.5 mm (Equations §2, eq. (33), and 3.1); stand B's
dynamometers 5 hold bearing 4 of the disc shaft and measure F_T and F_V (Equations §3.2). The
instrument here is the transducer alone: its input is the force on the dynamometer itself [N];
lever ratios belong to the calibration (:mod:`sensors.calibration`) and to the stands.

The elastic element is linear: strain = strain_per_newton * force. The values of the
constants are not in the paper; the defaults below are assumed (one place per stand) and
chosen so that the largest expected force stays inside the +-10 V converter range:

* stand A: F_y <= ~20 N at 385 N (Equations §3.1: F_y ~ 4 N at 96 N, ~19 N at 385 N), i.e.
  F_dyn = F_y 42.5/102 <= ~8 N; 50 ue/N (1000 ue at 20 N), full bridge, k = 2, 5 V
  -> 0.5 mV/N, gain 500 -> 0.25 V/N, full scale ~ +-40 N;
* stand B: |F_T| <= mu F_N = 0.8 * 144 N ~ 115 N; 5 ue/N, full bridge -> 50 uV/N, gain 500
  -> 25 mV/N, full scale ~ +-400 N.

Noise 1 uV rms and a random-walk zero drift of 0.1 uV/sqrt(s) at the amplifier input (6 uV in
an hour) are assumed values typical of DC bridge amplifiers; both are off unless a generator is
given.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError
from sensors.adc import Adc, DigitalReading
from sensors.amplifier import Amplifier
from sensors.bridge import Bridge, BridgeConfiguration
from sensors.noise import RandomWalkDrift, WhiteNoise

DEFAULT_NOISE_STD_V = 1.0e-6
"""Input-referred white noise of the bridge amplifier [V rms] (assumed)."""
DEFAULT_DRIFT_DIFFUSION_V = 1.0e-7
"""Input-referred random-walk zero drift [V/sqrt(s)] (assumed: ~6 uV per hour)."""
STAND_A_STRAIN_PER_NEWTON = 5.0e-5
"""Stand A dynamometer 10: strain per newton on the dynamometer [1/N] (assumed, see module doc)."""
STAND_A_GAIN = 500.0
"""Stand A amplifier gain [V/V] (assumed)."""
STAND_B_STRAIN_PER_NEWTON = 5.0e-6
"""Stand B dynamometers 5: strain per newton [1/N] (assumed, see module doc)."""
STAND_B_GAIN = 500.0
"""Stand B bridge amplifier (AR 405C) gain [V/V] (assumed; the AR 405C data are not known)."""
MAX_STRAIN = 0.01
"""Largest strain accepted by a metal-foil gauge [1]; beyond it the input is rejected."""


@dataclass(frozen=True, eq=False)
class Dynamometer:
    """Force transducer: strain_per_newton [1/N], a bridge, an amplifier and a converter."""

    strain_per_newton: float
    bridge: Bridge
    amplifier: Amplifier
    adc: Adc

    def __post_init__(self) -> None:
        validate.number("strain_per_newton", self.strain_per_newton, 0.0, 1.0e-2, lo_open=True)

    @property
    def nominal_sensitivity_V_per_N(self) -> float:
        """Design sensitivity at the amplifier output [V/N] (small-strain; the true one, which
        a reduction must not use - it uses a :class:`~sensors.calibration.CalibrationRecord`)."""
        return self.strain_per_newton * self.bridge.sensitivity_V() * self.amplifier.gain

    def strain(self, force_N: np.ndarray) -> np.ndarray:
        """Gauge strain [1] for the force on the dynamometer [N]; rejects |strain| > MAX_STRAIN."""
        eps = self.strain_per_newton * np.asarray(force_N, dtype=float)
        if eps.size and np.max(np.abs(eps)) > MAX_STRAIN:
            worst = float(np.asarray(force_N, dtype=float).flat[int(np.argmax(np.abs(eps)))])
            limit = MAX_STRAIN / self.strain_per_newton
            raise InstrumentParameterError(
                "force_N", worst, f"[{-limit:g}, {limit:g}] N (overload of the elastic element)"
            )
        return eps

    def volts(self, t_s: np.ndarray, force_N: np.ndarray) -> np.ndarray:
        """Analogue output [V] (with noise/drift if on) for forces [N] sampled at times [s]."""
        t, f = validate.time_series("t_s", t_s, "force_N", force_N, min_length=1)
        return self.amplifier.output_V(t, self.bridge.output_V(self.strain(f)))

    def read(self, t_s: np.ndarray, force_N: np.ndarray) -> DigitalReading:
        """Digitised reading (codes, volts [V], clipped flags) of forces [N] at times [s]."""
        t = np.asarray(t_s, dtype=float)
        return self.adc.convert(t, self.volts(t, force_N))


def _effects(noise_rng: np.random.Generator | None, drift_rng: np.random.Generator | None):
    noise = None if noise_rng is None else WhiteNoise(DEFAULT_NOISE_STD_V, noise_rng)
    drift = None if drift_rng is None else RandomWalkDrift(DEFAULT_DRIFT_DIFFUSION_V, drift_rng)
    return noise, drift


def stand_a_dynamometer(
    *, noise_rng: np.random.Generator | None = None, drift_rng: np.random.Generator | None = None
) -> Dynamometer:
    """Stand A's dynamometer 10 with the assumed defaults.

    Parameters
    ----------
    noise_rng, drift_rng : numpy.random.Generator, optional
        Streams of the amplifier's noise and drift; None: that effect is off (not built).

    Returns
    -------
    Dynamometer
        Force [N] in, converter reading [V] out.
    """
    return _full_bridge_dynamometer(STAND_A_STRAIN_PER_NEWTON, STAND_A_GAIN, noise_rng, drift_rng)


def stand_b_dynamometer(
    *, noise_rng: np.random.Generator | None = None, drift_rng: np.random.Generator | None = None
) -> Dynamometer:
    """One of stand B's dynamometers 5 (F_T or F_V) with the assumed defaults.

    Parameters
    ----------
    noise_rng, drift_rng : numpy.random.Generator, optional
        Streams of the amplifier's noise and drift; None: that effect is off (not built).

    Returns
    -------
    Dynamometer
        Force [N] in, converter reading [V] out.
    """
    return _full_bridge_dynamometer(STAND_B_STRAIN_PER_NEWTON, STAND_B_GAIN, noise_rng, drift_rng)


def _full_bridge_dynamometer(strain_per_newton: float, gain: float, noise_rng: np.random.Generator | None,
                             drift_rng: np.random.Generator | None) -> Dynamometer:
    """A full-bridge dynamometer with the default converter and the amplifier's effects of _effects."""
    noise, drift = _effects(noise_rng, drift_rng)
    return Dynamometer(
        strain_per_newton=strain_per_newton,
        bridge=Bridge(BridgeConfiguration.FULL),
        amplifier=Amplifier(gain, noise=noise, drift=drift),
        adc=Adc(),
    )
