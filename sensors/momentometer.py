"""Torque meter ("momentometer" 8 of stand B): torsion shaft with strain gauges -> bridge -> amplifier.

A solid circular shaft of diameter d carries the torque T [N m] between the clutch 9 and the
disc shaft 3 (Equations §3.2, 4.2). Elastic torsion: surface shear stress tau = 16 T/(pi d^3),
shear strain gamma = tau/G; gauges at +-45 deg to the axis see normal strains +-gamma/2 =
+-8 T/(pi d^3 G), wired as a full bridge (two +45, two -45 gauges) so that bending and axial
load cancel. The output goes to the signal recorder (:mod:`sensors.recorder`), which samples
and digitises it. The shaft's torsional stiffness G pi d^4/(32 L) is the loop compliance k_m
of the stand-B drive model (Equations §4.2: 2e3...1e4 N m/rad).

Defaults (assumed, none is in the paper): steel shaft d = 12 mm, G = 80 GPa, measuring length
L = 50 mm -> k_m = 3.26e3 N m/rad (inside the Equations page's range), 368 ue at 20 N m; full bridge,
k = 2, 5 V; amplifier gain 2000 -> 0.368 V/(N m), full scale of a +-10 V converter ~ +-27 N m,
above the largest expected |T_Mo| ~ R_c mu F_N ~ 19 N m. Noise and drift as the dynamometers.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate
from sensors.amplifier import Amplifier
from sensors.bridge import Bridge, BridgeConfiguration
from sensors.dynamometer import DEFAULT_DRIFT_DIFFUSION_V, DEFAULT_NOISE_STD_V, MAX_STRAIN
from sensors.errors import InstrumentParameterError
from sensors.noise import RandomWalkDrift, WhiteNoise

STAND_B_SHAFT_DIAMETER_M = 0.012
"""Diameter of the torsion shaft [m] (assumed)."""
STAND_B_SHEAR_MODULUS_PA = 80.0e9
"""Shear modulus of the steel shaft [Pa] (handbook value for steel)."""
STAND_B_GAUGE_LENGTH_M = 0.050
"""Length of the twisting section [m] (assumed)."""
STAND_B_GAIN = 2000.0
"""Bridge amplifier gain [V/V] (assumed; AR 405C data not known)."""


@dataclass(frozen=True, eq=False)
class Momentometer:
    """Torsion shaft (diameter [m], shear modulus [Pa], length [m]) with a gauge bridge and amplifier."""

    shaft_diameter_m: float
    shear_modulus_Pa: float
    gauge_length_m: float
    bridge: Bridge
    amplifier: Amplifier

    def __post_init__(self) -> None:
        validate.number("shaft_diameter_m", self.shaft_diameter_m, 1.0e-3, 0.5)
        validate.number("shear_modulus_Pa", self.shear_modulus_Pa, 1.0e9, 500.0e9)
        validate.number("gauge_length_m", self.gauge_length_m, 1.0e-3, 2.0)

    def shear_stress_Pa(self, torque_N_m: np.ndarray) -> np.ndarray:
        """Surface shear stress tau = 16 T/(pi d^3) [Pa] for the torque [N m]."""
        return 16.0 * np.asarray(torque_N_m, dtype=float) / (np.pi * self.shaft_diameter_m**3)

    def strain(self, torque_N_m: np.ndarray) -> np.ndarray:
        """Normal strain of a +45 deg gauge, tau/(2G) [1]; rejects |strain| > MAX_STRAIN."""
        eps = self.shear_stress_Pa(torque_N_m) / (2.0 * self.shear_modulus_Pa)
        if eps.size and np.max(np.abs(eps)) > MAX_STRAIN:
            worst = float(np.asarray(torque_N_m, dtype=float).flat[int(np.argmax(np.abs(eps)))])
            limit = MAX_STRAIN * 2.0 * self.shear_modulus_Pa * np.pi * self.shaft_diameter_m**3 / 16.0
            raise InstrumentParameterError("torque_N_m", worst, f"[{-limit:g}, {limit:g}] N m (shaft overload)")
        return eps

    @property
    def torsional_stiffness_N_m_per_rad(self) -> float:
        """k_m = G pi d^4/(32 L) [N m/rad]."""
        return self.shear_modulus_Pa * np.pi * self.shaft_diameter_m**4 / (32.0 * self.gauge_length_m)

    @property
    def nominal_sensitivity_V_per_N_m(self) -> float:
        """Design sensitivity at the amplifier output [V/(N m)] (small strain; not for reduction)."""
        per_torque = 8.0 / (np.pi * self.shaft_diameter_m**3 * self.shear_modulus_Pa)
        return per_torque * self.bridge.sensitivity_V() * self.amplifier.gain

    def volts(self, t_s: np.ndarray, torque_N_m: np.ndarray) -> np.ndarray:
        """Analogue output [V] (with noise/drift if on) for torques [N m] sampled at times [s]."""
        t, torque = validate.time_series("t_s", t_s, "torque_N_m", torque_N_m, min_length=1)
        return self.amplifier.output_V(t, self.bridge.output_V(self.strain(torque)))


def stand_b_momentometer(
    *, noise_rng: np.random.Generator | None = None, drift_rng: np.random.Generator | None = None
) -> Momentometer:
    """Stand B's momentometer 8 with the assumed defaults.

    Parameters
    ----------
    noise_rng, drift_rng : numpy.random.Generator, optional
        Streams of the noise and drift; None: that effect is off (not built).

    Returns
    -------
    Momentometer
        Torque [N m] in, reading [V] out.
    """
    noise = None if noise_rng is None else WhiteNoise(DEFAULT_NOISE_STD_V, noise_rng)
    drift = None if drift_rng is None else RandomWalkDrift(DEFAULT_DRIFT_DIFFUSION_V, drift_rng)
    return Momentometer(
        shaft_diameter_m=STAND_B_SHAFT_DIAMETER_M,
        shear_modulus_Pa=STAND_B_SHEAR_MODULUS_PA,
        gauge_length_m=STAND_B_GAUGE_LENGTH_M,
        bridge=Bridge(BridgeConfiguration.FULL),
        amplifier=Amplifier(STAND_B_GAIN, noise=noise, drift=drift),
    )
