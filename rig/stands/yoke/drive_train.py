"""Stand A's drive train as a rigid-body ODE (Equations §4.1), vectorised for a finite-difference Jacobian.

States (those of an effect exist only when the effect is built):

    psi_1, psi_2 [rad] (angles minus carrier rotation), omega_2 [rad/s]   always
    phi [rad] (coupling twist), omega_m, omega_1 [rad/s], z [rad]         "drive_compliance"
    x1, x2, x3 [N m] (lever, shoe, lining lags)                           "brake_dynamics"

    J_2 omega_2' = T2(w1, w2) - T_B tanh(w2/eps) - T_f2 tanh(w2/eps)
    compliance:  phi' = w_m - w1,  z' = w_ref - w_m,  T_mot = K_p (w_ref - w_m) + K_i z     (PI motor)
                 J_m w_m' = T_mot - k_c phi - d_c (w_m - w1)
                 J_1 w1'  = k_c phi + d_c (w_m - w1) + T1(w1, w2) - T_f1 tanh(w1/eps)
    otherwise    w1 = w_ref(t) (ideal speed source on wheel 1)
    brake loop   see rig.stands.yoke.brake (T_B = set-point when "brake_dynamics" is off)

T1, T2: contact moments on the wheels in their senses of rotation (rig.stands.yoke.contact_forces;
the Equations page's T1,contact enters with the opposite sign there because it is defined as the
resisting moment). w_ref(t) ramps smoothly from the previous point's speed to the new set-point
over ``speed_ramp_s`` (start from rest: from 0). PI tuning [assumed]: K_p = (J_m + J_1) w_bw,
K_i = K_p w_bw/4; coupling damping d_c = 2 zeta sqrt(k_c J_m J_1/(J_m + J_1)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.stands.yoke.brake import BrakeLoop, IdealBrake
from rig.stands.yoke.contact_forces import StandAContact


@dataclass(frozen=True)
class SpeedReference:
    """Speed set-point of wheel 1 [rad/s]: from ``start`` to ``target`` over ``ramp_s`` [s] (smooth)."""

    start: float
    target: float
    ramp_s: float

    def __call__(self, t):
        """w_ref(t) [rad/s], t [s] (scalar or array); cosine ramp, constant after ramp_s."""
        x = np.clip(np.asarray(t, dtype=float) / self.ramp_s, 0.0, 1.0)
        return self.start + (self.target - self.start) * 0.5 * (1.0 - np.cos(np.pi * x))


@dataclass(frozen=True)
class BearingFriction:
    """Effect "bearing_friction": Coulomb moments [N m] of wheels 1 and 2, regularised over eps [rad/s]."""

    moment_1: float
    moment_2: float
    eps: float

    def moments(self, omega_1, omega_2):
        """(T_f1, T_f2) [N m] opposing the speeds w1, w2 [rad/s]."""
        return self.moment_1 * np.tanh(omega_1 / self.eps), self.moment_2 * np.tanh(omega_2 / self.eps)


@dataclass(frozen=True)
class Compliance:
    """Effect "drive_compliance": motor inertia J_m [kg m^2], coupling stiffness k_c [N m/rad] and
    damping d_c [N m s/rad], PI gains K_p [N m s/rad] and K_i [N m/rad]."""

    J_m: float
    k_c: float
    d_c: float
    K_p: float
    K_i: float

    @classmethod
    def from_effect(cls, values: dict[str, float], J_1: float) -> Compliance:
        """From the effect's parameters (see rig.stands.yoke.parameters.EFFECTS) and J_1 [kg m^2]."""
        J_m = values["J_m_kg_m2"]
        k_c = values["coupling_stiffness_N_m_per_rad"]
        d_c = 2.0 * values["coupling_damping_ratio"] * math.sqrt(k_c * J_m * J_1 / (J_m + J_1))
        w_bw = 2.0 * math.pi * values["motor_bandwidth_Hz"]
        K_p = (J_m + J_1) * w_bw
        return cls(J_m, k_c, d_c, K_p, K_p * w_bw / 4.0)


class DriveTrain:
    """The ODE of one operating point.

    The wheel angles are carried as deviations psi_k = theta_k - w_k* t from a rotation at the
    carrier speeds w_k* [rad/s] (the point's steady speeds): they stay small, so the integrator's
    relative tolerance does not loosen the angle accuracy the counters need as theta grows.
    ``rhs(t, y)`` takes y of shape (n,) (scalar fast path) or (n, k) (vectorised, e.g. for checks);
    ``jacobian(t, y)`` is analytic in the drive-train structure.
    """

    def __init__(self, contact: StandAContact, *, J_1: float, J_2: float, reference: SpeedReference,
                 brake: BrakeLoop | IdealBrake, brake_speed_eps: float, carrier: tuple[float, float],
                 compliance: Compliance | None = None, bearing: BearingFriction | None = None) -> None:
        self.contact = contact
        self.J_1 = validate.number("J_1_kg_m2", J_1, 0.0, lo_open=True)
        self.J_2 = validate.number("J_2_kg_m2", J_2, 0.0, lo_open=True)
        self.reference = reference
        self.brake = brake
        self.brake_speed_eps = brake_speed_eps
        self.carrier = (float(carrier[0]), float(carrier[1]))
        self.compliance = compliance
        self.bearing = bearing
        names = ["psi_1", "psi_2", "omega_2"]
        if compliance is not None:
            names += ["phi", "omega_m", "omega_1", "z"]
        if isinstance(brake, BrakeLoop):
            names += ["x1", "x2", "x3"]
        self.names = tuple(names)
        self.index = {name: i for i, name in enumerate(names)}
        self._loop = brake if isinstance(brake, BrakeLoop) else None

    @property
    def n_states(self) -> int:
        return len(self.names)

    def angles(self, t, y):
        """Wheel angles (theta_1, theta_2) [rad] at times t [s] from states y."""
        return y[0] + self.carrier[0] * t, y[1] + self.carrier[1] * t

    def omega_1(self, t, y):
        """Wheel 1 speed [rad/s]: a state with compliance, else the reference at t [s]."""
        if self.compliance is None:
            return self.reference(t) + 0.0 * y[0]  # broadcast to the shape of the states
        return y[self.index["omega_1"]]

    def brake_moment(self, t, y):
        """Moment of the brake on wheel 2 [N m] (positive resisting), regularised at w2 = 0."""
        if self._loop is not None:
            t_b = self._loop.moment(t, y[self.index["x3"]])
        else:
            t_b = self.brake.setpoint
        return t_b * np.tanh(y[2] / self.brake_speed_eps)

    def rhs(self, t, y):
        """dy/dt for states y [(n,) or (n, k)] at time t [s]."""
        y = np.asarray(y, dtype=float)
        if y.ndim == 1:
            return self._rhs_scalar(float(t), y)
        dy = np.empty_like(y)
        w1 = self.omega_1(t, y)
        w2 = y[2]
        t1, t2 = self.contact.moments(w1, w2)
        f1, f2 = (0.0, 0.0) if self.bearing is None else self.bearing.moments(w1, w2)
        brake = self.brake_moment(t, y)
        dy[0] = w1 - self.carrier[0]
        dy[1] = w2 - self.carrier[1]
        dy[2] = (t2 - brake - f2) / self.J_2
        self._auxiliary(t, y, dy, w1, t1, f1, brake)
        return dy

    def _rhs_scalar(self, t: float, y: np.ndarray) -> np.ndarray:
        dy = np.empty_like(y)
        w2 = float(y[2])
        w1 = float(self.reference(t)) if self.compliance is None else float(y[self.index["omega_1"]])
        t1, t2 = self.contact.moments_scalar(w1, w2)
        f1 = f2 = 0.0
        if self.bearing is not None:
            eps = self.bearing.eps
            f1, f2 = self.bearing.moment_1 * math.tanh(w1 / eps), self.bearing.moment_2 * math.tanh(w2 / eps)
        if self._loop is not None:
            t_b = float(self._loop.moment(t, y[self.index["x3"]]))
        else:
            t_b = self.brake.setpoint
        brake = t_b * math.tanh(w2 / self.brake_speed_eps)
        dy[0] = w1 - self.carrier[0]
        dy[1] = w2 - self.carrier[1]
        dy[2] = (t2 - brake - f2) / self.J_2
        self._auxiliary(t, y, dy, w1, t1, f1, brake)
        return dy

    def _auxiliary(self, t, y, dy, w1, t1, f1, brake) -> None:
        """Derivatives of the coupling/motor and brake-loop states (if built), in place."""
        cp = self.compliance
        i = self.index
        if cp is not None:
            phi, w_m, z = y[i["phi"]], y[i["omega_m"]], y[i["z"]]
            w_ref = self.reference(t)
            coupling = cp.k_c * phi + cp.d_c * (w_m - w1)
            motor = cp.K_p * (w_ref - w_m) + cp.K_i * z
            dy[i["phi"]] = w_m - w1
            dy[i["omega_m"]] = (motor - coupling) / cp.J_m
            dy[i["omega_1"]] = (coupling + t1 - f1) / self.J_1
            dy[i["z"]] = w_ref - w_m
        if self._loop is not None:
            d1, d2, d3 = self._loop.derivatives(y[i["x1"]], y[i["x2"]], y[i["x3"]], brake)
            dy[i["x1"]], dy[i["x2"]], dy[i["x3"]] = d1, d2, d3

    def jacobian(self, t, y) -> np.ndarray:
        """d(dy/dt)/dy [(n, n)]: analytic in the drive-train structure, with the contact's
        d(T1, T2)/d(w1, w2) from StandAContact.moments_jacobian."""
        y = np.asarray(y, dtype=float)
        i = self.index
        jac = np.zeros((self.n_states, self.n_states))
        cp = self.compliance
        w2 = float(y[2])
        w1 = float(self.reference(t)) if cp is None else float(y[i["omega_1"]])
        dt = self.contact.moments_jacobian(w1, w2)
        eps = self.brake_speed_eps
        th = math.tanh(w2 / eps)
        if self._loop is not None:
            per_state = float(self._loop.moment_per_state(t))  # dT_B/dx3 [1]
            t_b, db_dx3 = per_state * float(y[i["x3"]]), per_state * th
        else:
            t_b, db_dx3 = self.brake.setpoint, 0.0
        db_dw2 = t_b * (1.0 - th * th) / eps
        df1 = df2 = 0.0
        if self.bearing is not None:
            b = self.bearing
            df1 = b.moment_1 * (1.0 - math.tanh(w1 / b.eps) ** 2) / b.eps
            df2 = b.moment_2 * (1.0 - math.tanh(w2 / b.eps) ** 2) / b.eps
        jac[1, 2] = 1.0
        jac[2, 2] = (dt[1, 1] - db_dw2 - df2) / self.J_2
        if cp is not None:
            p, m, o, z = i["phi"], i["omega_m"], i["omega_1"], i["z"]
            jac[0, o] = 1.0
            jac[2, o] = dt[1, 0] / self.J_2
            jac[p, m], jac[p, o] = 1.0, -1.0
            jac[m, m] = (-cp.K_p - cp.d_c) / cp.J_m
            jac[m, o] = cp.d_c / cp.J_m
            jac[m, p] = -cp.k_c / cp.J_m
            jac[m, z] = cp.K_i / cp.J_m
            jac[o, p] = cp.k_c / self.J_1
            jac[o, m] = cp.d_c / self.J_1
            jac[o, o] = (-cp.d_c + dt[0, 0] - df1) / self.J_1
            jac[o, 2] = dt[0, 1] / self.J_1
            jac[z, m] = -1.0
        if self._loop is not None:
            x1, x2, x3 = i["x1"], i["x2"], i["x3"]
            t1, t2, t3 = self._loop.taus
            jac[2, x3] = -db_dx3 / self.J_2
            jac[x1, 2] = -db_dw2 / t1
            jac[x1, x3] = -db_dx3 / t1
            jac[x1, x1] = -1.0 / t1
            jac[x2, x1], jac[x2, x2] = 1.0 / t2, -1.0 / t2
            jac[x3, x2], jac[x3, x3] = 1.0 / t3, -1.0 / t3
        return jac

    def state(self, *, omega_1: float, omega_2: float, moment_1: float, brake_moment: float) -> np.ndarray:
        """The state at steady running (angles psi = 0): speeds [rad/s], the moment the motor must
        deliver to wheel 1 [N m] (coupling twist and PI integrator hold it), and the brake moment
        [N m] (the lags hold it)."""
        y = np.zeros(self.n_states)
        y[2] = omega_2
        cp = self.compliance
        i = self.index
        if cp is not None:
            y[i["phi"]] = moment_1 / cp.k_c
            y[i["omega_m"]] = omega_1
            y[i["omega_1"]] = omega_1
            y[i["z"]] = moment_1 / cp.K_i
        if self._loop is not None:
            y[i["x1"]], y[i["x2"]], y[i["x3"]] = self._loop.steady_states(brake_moment)
        return y
