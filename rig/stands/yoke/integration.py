"""Implicit integration of the drive train: settle detection and the gate (scipy.integrate).

The system is stiff (contact mode ~1-3 ms, coupling ~100 Hz, brake 0.1 s, tests ~10 s; Equations §4.1): an implicit method (Radau, L-stable) with the drive train's analytic Jacobian
(DriveTrain.jacobian). During the gate the state is near steady, so the step is limited only by
accuracy (max_step = gate time); the true signals (wheel angles for the counters, forces,
moments) are sampled from the dense output at GATE_SAMPLE_RATE_HZ.

Settling is detected on the step ends of a sliding window (SETTLE_WINDOW_S) against the known
steady state of the new settings (rig.stands.yoke.steady_state): a number <= 1 is settled.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig.errors import ConvergenceError
from rig.stands.yoke.drive_train import DriveTrain

GATE_SAMPLE_RATE_HZ = 100.0  # samples of the true signals [Hz]: the counters interpolate the angle linearly
#   between samples (2.4 marks per sample at 240 rpm, 60 marks: exact counts while the wheel does not reverse
#   within 10 ms); faster than the dynamometer (50 Hz) and the brake fluctuation (<= 0.5 Hz)
SETTLE_WINDOW_S = 0.25  # window over which the criterion must hold [s]
SPEED_TOLERANCE = 2e-4  # relative deviation of w1, w2 from the steady state [1] (~0.005 a in l)
BRAKE_TOLERANCE = 0.02  # deviation of the brake moment from its set-point, relative [1] (issue: 2 %)
BRAKE_FLOOR_N_M = 0.01  # moment below which the brake tolerance is absolute [N m]
RTOL = 1e-5  # settling (relative tolerance of the implicit integrator)
RTOL_GATE = 1e-4  # the gate: angles within ~1e-6 rad, w2 within ~2e-6 relative of a tight run (tested)


@dataclass(frozen=True)
class Target:
    """Steady state the settle criterion compares with: w1, w2 [rad/s], brake set-point [N m] and
    slope = d(T2 - T_f2)/d w2 [N m s/rad] there (steady_state.OperatingPoint.slope)."""

    omega_1: float
    omega_2: float
    brake_setpoint: float
    slope: float

    @property
    def criterion(self) -> str:
        return (f"max over {SETTLE_WINDOW_S:g} s of |w1 - w1*|/w1* and |w2 - w2*(T_B)|/w2* <= "
                f"{SPEED_TOLERANCE:g} (w* = quasi-static steady state, w2*(T_B) = w2* + (T_B - T_set)/slope "
                f"follows the actual brake moment) and |T_B - T_set| <= {BRAKE_TOLERANCE:.0%} of "
                f"max(|T_set|, {BRAKE_FLOOR_N_M:g} N m); residual = worst ratio to its tolerance")

    def residual(self, train: DriveTrain, t: np.ndarray, y: np.ndarray) -> float:
        """Worst ratio of a deviation to its tolerance over the samples (t [s], y (n, k))."""
        w1 = train.omega_1(t, y)
        brake = train.brake_moment(t, y)
        dev_1 = np.max(np.abs(w1 - self.omega_1)) / (SPEED_TOLERANCE * self.omega_1)
        quasi_static = self.omega_2 + (brake - self.brake_setpoint) / self.slope
        dev_2 = np.max(np.abs(y[2] - quasi_static)) / (SPEED_TOLERANCE * max(self.omega_2, 1e-9))
        scale = BRAKE_TOLERANCE * max(abs(self.brake_setpoint), BRAKE_FLOOR_N_M)
        dev_b = np.max(np.abs(brake - self.brake_setpoint)) / scale
        return float(max(dev_1, dev_2, dev_b))


def atol(train: DriveTrain) -> np.ndarray:
    """Absolute tolerances per state: angle deviations 1e-6 rad, speeds 1e-8 rad/s, twist/integrator 1e-10 rad,
    brake lags 1e-8 N m."""
    scale = {"psi_1": 1e-6, "psi_2": 1e-6, "omega_2": 1e-8, "phi": 1e-10, "omega_m": 1e-8,
             "omega_1": 1e-8, "z": 1e-10, "x1": 1e-8, "x2": 1e-8, "x3": 1e-8}
    return np.array([scale[name] for name in train.names])


def settle(train: DriveTrain, y0: np.ndarray, target: Target, timeout_s: float,
           tolerance_factor: float = 1.0) -> tuple[float, np.ndarray, float]:
    """Integrate from t = 0 until the criterion holds over a window; (t [s], y, residual).

    Returns with residual > 1 if the timeout [s] is reached first (the caller reports it);
    tolerance_factor multiplies the relative tolerance RTOL (parameter ode_tolerance_factor).
    """
    from scipy.integrate import Radau  # imported here: ~0.3 s, for integrated drives only

    solver = Radau(train.rhs, 0.0, y0, timeout_s, rtol=RTOL * tolerance_factor, atol=atol(train), jac=train.jacobian,
                   max_step=SETTLE_WINDOW_S / 3.0)
    times, states = [0.0], [np.array(y0, dtype=float)]
    residual = np.inf
    next_check = SETTLE_WINDOW_S
    while solver.status == "running":
        message = solver.step()
        if solver.status == "failed":
            raise ConvergenceError(f"stand A drive train: integration failed at t = {solver.t:.6g} s ({message})")
        times.append(solver.t)
        states.append(solver.y.copy())
        if solver.t >= next_check or solver.status == "finished":
            t = np.array(times)
            window = t >= solver.t - SETTLE_WINDOW_S
            if np.count_nonzero(window) >= 3 and t[0] <= solver.t - SETTLE_WINDOW_S:
                residual = target.residual(train, t[window], np.array(states)[window].T)
                if residual <= 1.0:
                    break
            next_check = solver.t + 0.5 * SETTLE_WINDOW_S
            keep = t >= solver.t - 2.0 * SETTLE_WINDOW_S
            times = list(t[keep])
            states = [s for s, k in zip(states, keep) if k]
    return float(solver.t), solver.y.copy(), float(residual)


def gate(train: DriveTrain, t0: float, y0: np.ndarray, duration: float,
         tolerance_factor: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Integrate over the gate [t0, t0 + duration] [s]; samples (t [s], y (n, k)) at GATE_SAMPLE_RATE_HZ;
    tolerance_factor multiplies RTOL_GATE."""
    n = max(int(np.ceil(duration * GATE_SAMPLE_RATE_HZ)), 2) + 1
    t_eval = np.linspace(t0, t0 + duration, n)
    from scipy.integrate import solve_ivp  # imported here: ~0.3 s, for integrated drives only

    sol = solve_ivp(train.rhs, (t0, t0 + duration), y0, method="Radau", t_eval=t_eval, rtol=RTOL_GATE * tolerance_factor,
                    atol=atol(train), jac=train.jacobian, max_step=duration)
    if sol.status != 0:
        raise ConvergenceError(f"stand A drive train: integration of the gate failed ({sol.message})")
    return sol.t, sol.y
