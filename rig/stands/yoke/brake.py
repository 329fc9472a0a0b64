"""Shoe brake 12 on drum 11 with mechanical feedback ([Koziarski] section 3.1.1: "automatic stabilization of
the value of loading moment T2"), and the brake-lining friction fluctuation it has to reject.

Model [reconstructed; the paper gives no details of the mechanism, Equations §4.1]: the brake's
reaction moment T_B swings a lever against the set-point spring; the lever deflection tightens
the shoe. Lever, shoe linkage and lining build-up are three first-order lags, so with the error
e = r - T_B (moment units [N m])

    tau_1 x1' = e - x1,   tau_2 x2' = x1 - x2,   tau_3 x3' = x2 - x3,   T_B = g (mu_b/mu_b0) x3

Loop gain g = mu_b r_d K_f (lining friction x drum radius x lever ratio) at the nominal lining
friction mu_b0. Proportional feedback leaves the static error 1/(1 + g); the set-point scale is
marked at the nominal lining friction, i.e. the lever spring is set to r = T_set (1 + g)/g, so
that T_B = T_set in steady state at mu_b0, and a slow change of mu_b by a fraction f moves T_B by
about f/(1 + g) (disturbance rejection).

Stability (Routh-Hurwitz): the characteristic polynomial of the loop is
    tau_1 tau_2 tau_3 s^3 + (tau_1 tau_2 + tau_1 tau_3 + tau_2 tau_3) s^2 + (tau_1 + tau_2 + tau_3) s + 1 + g,
stable for -1 < g < g_max = (sum tau_i)(sum tau_i tau_j)/(tau_1 tau_2 tau_3) - 1 (31.5 for the
default lags 0.1/0.02/0.005 s; 8 for three equal lags). A gain outside that range is a
ParameterError naming the gain and the range, never a simulation of an unstable brake.
"""

from __future__ import annotations

import math

import numpy as np

from rig import validate
from rig.errors import ParameterError

N_SINES = 8
"""Number of sines of the fluctuation (their sum, scaled to unit rms, is the disturbance shape)."""


def critical_gain(taus: tuple[float, float, float]) -> float:
    """Routh-Hurwitz limit g_max [1] of the three-lag loop with time constants ``taus`` [s]."""
    t1, t2, t3 = (validate.number(f"tau_{i + 1}", t, 0.0, lo_open=True) for i, t in enumerate(taus))
    return (t1 + t2 + t3) * (t1 * t2 + t1 * t3 + t2 * t3) / (t1 * t2 * t3) - 1.0


def characteristic_roots(gain: float, taus: tuple[float, float, float]) -> np.ndarray:
    """Closed-loop poles [1/s] of the brake loop (roots of the polynomial above)."""
    t1, t2, t3 = taus
    return np.roots([t1 * t2 * t3, t1 * t2 + t1 * t3 + t2 * t3, t1 + t2 + t3, 1.0 + gain])


class BrakeFrictionFluctuation:
    """mu_b(t)/mu_b0 = 1 + rms * n(t), n = sqrt(2/K) sum_k sin(2 pi f_k t + phi_k) (unit rms).

    relative_rms [1] in (0, 0.2] (|rms n| <= 0.8, so mu_b stays positive); frequencies f_k
    uniform in [f_min_Hz, f_max_Hz] [Hz], phases uniform, both from ``rng`` (seeded).
    [assumed: slow lining friction changes (temperature, drum run-out); smooth, so the implicit
    integrator is not forced to tiny steps]
    """

    def __init__(self, relative_rms: float, f_min_Hz: float, f_max_Hz: float, rng: np.random.Generator) -> None:
        self.relative_rms = validate.number("relative_rms", relative_rms, 0.0, 0.2, lo_open=True)
        lo = validate.number("f_min_Hz", f_min_Hz, 0.0, lo_open=True)
        hi = validate.number("f_max_Hz", f_max_Hz, lo)
        self._omega = 2.0 * math.pi * rng.uniform(lo, hi, N_SINES)
        self._phase = rng.uniform(0.0, 2.0 * math.pi, N_SINES)
        self._amplitude = relative_rms * math.sqrt(2.0 / N_SINES)

    def factor(self, t):
        """mu_b/mu_b0 [1] at times t [s] (scalar or array)."""
        t = np.asarray(t, dtype=float)
        return 1.0 + self._amplitude * np.sin(np.multiply.outer(t, self._omega) + self._phase).sum(axis=-1)


class BrakeLoop:
    """The feedback loop (effect "brake_dynamics"): gain g [1], lags (lever, shoe, lining) [s],
    set-point T_set [N m], optional lining friction fluctuation (None = off)."""

    n_states = 3

    def __init__(self, gain: float, taus: tuple[float, float, float], setpoint: float,
                 fluctuation: BrakeFrictionFluctuation | None = None) -> None:
        self.taus = tuple(float(t) for t in taus)
        self.g_max = critical_gain(self.taus)
        g = validate.number("brake_loop_gain", gain, 0.0, lo_open=True)
        if g >= self.g_max:
            raise ParameterError(
                "brake_loop_gain", gain,
                f"(0, {self.g_max:.4g}): Routh-Hurwitz limit of the three-lag brake loop with lags "
                f"{self.taus[0]:g}/{self.taus[1]:g}/{self.taus[2]:g} s",
            )
        self.gain = g
        self.setpoint = validate.number("brake_setpoint_N_m", setpoint)
        self.reference = setpoint * (1.0 + g) / g
        self.fluctuation = fluctuation

    def moment_per_state(self, t):
        """dT_B/dx3 = g mu_b(t)/mu_b0 [1] at time t [s]."""
        if self.fluctuation is None:
            return self.gain
        return self.gain * self.fluctuation.factor(t)

    def moment(self, t, x3):
        """Brake moment T_B [N m] from the shoe state x3 [N m] at time t [s]."""
        return self.moment_per_state(t) * x3

    def derivatives(self, x1, x2, x3, measured):
        """(x1', x2', x3') [N m/s] for the measured reaction moment [N m] on the brake body."""
        t1, t2, t3 = self.taus
        return (self.reference - measured - x1) / t1, (x1 - x2) / t2, (x2 - x3) / t3

    def steady_states(self, moment: float) -> tuple[float, float, float]:
        """(x1, x2, x3) [N m] holding the brake moment [N m] at the nominal lining friction."""
        x = moment / self.gain
        return x, x, x


class IdealBrake:
    """Effect "brake_dynamics" off: the brake moment is the set-point T_set [N m] at every instant."""

    n_states = 0

    def __init__(self, setpoint: float) -> None:
        self.setpoint = validate.number("brake_setpoint_N_m", setpoint)
