"""Time integration of stand B's drive train: implicit, finite-difference Jacobian, settle detection.

Radau IIA (order 5, L-stable) through scipy.integrate (the system is stiff: Equations §4.2,
hard case 10) with a forward-difference Jacobian from one vectorised call of the right-hand
side; single states (the Newton iterations) go through its scalar form. Radau rather than BDF:
with the contact relaxation the disc sits between the loop spring and the contact's tangential
stiffness in a lightly damped ~70 Hz mode, on which BDF of order > 2 (not A-stable) is forced
to steps of ~3 ms over a whole gate (measured: 3157 steps for a 10 s gate against 10 with
Radau). Absolute tolerances are scaled per state (speeds, twist, loads), so the momentometer
torque - from which M_C = T_Mo + R_c F_T is a small difference - is resolved to ~1e-6 of
mu a F_N.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from rig.errors import ConvergenceError
from rig.stands.disc_roller.drive_train import DriveTrain

RTOL = 1e-7  # relative tolerance of the integrator [1]
METHOD = "Radau"


def absolute_tolerances(train: DriveTrain, speed_scale: float) -> np.ndarray:
    """Per-state absolute tolerance: speeds [rad/s], twist [rad], loads [N, N, N m]."""
    lay = train.layout
    force = train.contact.mu * train.contact.normal_force
    atol = np.empty(lay.size)
    if lay.roller is not None:
        atol[lay.roller] = 1e-9 * speed_scale
    if lay.twist is not None:
        atol[lay.twist] = 1e-9 * force * train.contact.a / train.loop.stiffness
        atol[lay.disc] = 1e-9 * speed_scale / train.gear_ratio
    if lay.loads is not None:
        atol[lay.loads] = 1e-9 * force * np.array([1.0, 1.0, train.contact.a])
    return atol


@dataclass(frozen=True)
class Integrator:
    """Integrates one drive train from a state over a time span."""

    train: DriveTrain
    atol: np.ndarray
    max_step: float
    tolerance_factor: float = 1.0  # multiplies RTOL (parameter ode_tolerance_factor)

    @property
    def rtol(self) -> float:
        return RTOL * self.tolerance_factor

    def jacobian(self, t: float, y: np.ndarray) -> np.ndarray:
        """Forward-difference Jacobian d(dy/dt)/dy [1/s and mixed units] from one vectorised call.

        Step per state h_j = 1e-7 max(|y_j|, s_j), s_j = atol_j/1e-9 its scale (a speed, a twist,
        a load); the integrator evaluates single states with the scalar right-hand side.
        """
        h = 1e-7 * np.maximum(np.abs(y), self.atol / 1e-9)
        columns = y[:, None] + np.diag(h)
        f = self.train.evaluate(t, np.column_stack([y, columns]))["derivative"]
        return (f[:, 1:] - f[:, :1]) / h

    def run(self, t0: float, t1: float, y0: np.ndarray, dense: bool = False):
        """solve_ivp result from (t0, y0) to t1 [s]; ConvergenceError if the integrator fails."""
        from scipy.integrate import solve_ivp  # imported here: ~0.3 s, for integrated drives only

        sol = solve_ivp(
            self.train.rhs, (t0, t1), y0, method=METHOD, jac=self.jacobian, rtol=self.rtol, atol=self.atol,
            dense_output=dense, max_step=self.max_step,
        )
        if sol.status < 0 or not np.all(np.isfinite(sol.y[:, -1])):
            raise ConvergenceError(f"stand B drive train: {METHOD} failed between t = {t0:g} s and {t1:g} s: "
                                   f"{sol.message}")
        return sol


@dataclass(frozen=True)
class SettleResult:
    """Time [s] and state where the integration stopped, the residual there [1], settled or not."""

    t: float
    y: np.ndarray
    residual: float
    settled: bool


def settle(
    integrator: Integrator, y0: np.ndarray, residual: Callable[[float, np.ndarray], float], tolerance: float,
    interval: float, timeout: float,
) -> SettleResult:
    """Integrate (one solver, no restarts) until residual(t, y) < tolerance at two consecutive
    checks ``interval`` [s] apart (it stayed below for a whole interval), or stop at ``timeout`` [s]."""
    y0 = np.asarray(y0, dtype=float)
    value = residual(0.0, y0)
    below = value < tolerance
    train = integrator.train
    from scipy.integrate import Radau  # imported here: ~0.3 s, for integrated drives only

    solver = Radau(train.rhs, 0.0, y0, timeout, jac=integrator.jacobian, rtol=integrator.rtol, atol=integrator.atol,
                   max_step=integrator.max_step)
    check = interval
    t, y = 0.0, y0
    while solver.status == "running":
        solver.step()
        if solver.status == "failed" or not np.all(np.isfinite(solver.y)):
            raise ConvergenceError(f"stand B drive train: Radau failed at t = {solver.t:g} s while settling")
        if solver.t < min(check, timeout) - 1e-12:
            continue
        dense = solver.dense_output()
        while check <= solver.t + 1e-12:
            t, y = check, dense(check)
            value = residual(t, y)
            if value < tolerance and below:
                return SettleResult(t, y, value, True)
            below = value < tolerance
            check += interval
    return SettleResult(float(solver.t), solver.y.copy(), residual(float(solver.t), solver.y), False)
