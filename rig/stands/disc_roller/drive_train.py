"""Stand B's drive train as an ODE (Equations §4.2): roller shaft, gear loop, momentometer, disc.

States (only those of the built components; layout in :class:`StateLayout`):
    w_r   roller shaft 16 speed [rad/s]        (continuous drive; the swinging drive imposes it)
    phi   loop twist theta_r/i_g - theta_d [rad] (loop_compliance: momentometer 8 torsion)
    w_d   disc speed [rad/s]                    (loop_compliance; rigid loop: w_d = w_r/i_g)
    q     contact loads F_x [N], F_y [N], M_O [N m] (contact_relaxation)
Equations (i_g = R_c/R_r, J_R = roller + reflected motor inertia, signs: rig.stands.disc_roller.contact):
    J_R w_r' = T_w(w_r) - T_Mo/i_g - R_r F_x - T_fr(w_r)
    phi'     = w_r/i_g - w_d
    J_d w_d' = T_Mo + M_D - T_fd(w_d),   M_D = M_O - c F_y + (l_set + R_c) F_x
    T_Mo     = k dz(phi) + d dz'(phi) phi'
The contact acts on the roller with -F_x at radius R_r and on the disc with M_D about its axis
(F_y and the moment about z go into bearings). The disc shaft 3 is driven through the clutch 9,
which transmits torque only, so the bearing 4 (dynamometers 5) carries the contact force: the
true F_T, F_V signals are F_x, F_y. Rigid loop (no loop_compliance): w_d = w_r/i_g, one
equation with J_R + J_d/i_g^2, and T_Mo = J_d w_d' - M_D + T_fd from the disc's balance.
Stiff (Equations §4.2: disc mode ~0.1-0.4 ms, loop ~30-200 ms): integrate with an implicit
method; the right-hand side is vectorised for solve_ivp's finite-difference Jacobian.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from rig.errors import ParameterError
from rig.stands.disc_roller.components import BearingFriction, ContactRelaxation, LoopCompliance, WormDrive
from rig.stands.disc_roller.contact import ContactPoint
from rig.stands.disc_roller.swinging_drive import SwingingDrive


@dataclass(frozen=True)
class StateLayout:
    """Index of each state in y (None where the state does not exist)."""

    roller: int | None
    twist: int | None
    disc: int | None
    loads: slice | None
    size: int

    @classmethod
    def build(cls, continuous: bool, compliant: bool, relaxing: bool) -> StateLayout:
        """Layout for a motor drive (continuous) or an imposed motion, loop compliance, relaxation."""
        k = 0
        roller = twist = disc = None
        if continuous:
            roller, k = k, k + 1
        if compliant:
            twist, disc, k = k, k + 1, k + 2
        loads = slice(k, k + 3) if relaxing else None
        return cls(roller, twist, disc, loads, k + (3 if relaxing else 0))


@dataclass(frozen=True)
class DriveTrain:
    """The drive train of one operating point.

    contact: the point's ContactPoint; radius_c, roller_radius [m]; disc_inertia [kg m^2];
    worm: motor + worm (continuous drive) or None with ``swinging`` the imposed motion;
    set_speed: signed no-load roller speed [rad/s] (continuous drive); loop, bearings,
    relaxation: optional effects (None = not built).
    """

    contact: ContactPoint
    radius_c: float
    roller_radius: float
    disc_inertia: float
    worm: WormDrive | None
    set_speed: float
    swinging: SwingingDrive | None = None
    loop: LoopCompliance | None = None
    bearings: BearingFriction | None = None
    relaxation: ContactRelaxation | None = None
    layout: StateLayout = field(init=False)

    def __post_init__(self) -> None:
        if (self.worm is None) == (self.swinging is None):
            raise ParameterError("drive", (self.worm, self.swinging), "exactly one of a worm drive and a swinging drive")
        layout = StateLayout.build(self.worm is not None, self.loop is not None, self.relaxation is not None)
        object.__setattr__(self, "layout", layout)

    @property
    def gear_ratio(self) -> float:
        """i_g = R_c/R_r [1]."""
        return self.radius_c / self.roller_radius

    def _roller(self, t, y) -> tuple[np.ndarray, np.ndarray | None]:
        """Roller speed [rad/s] and, for the imposed motion, its acceleration [rad/s^2]."""
        if self.swinging is not None:
            t = np.broadcast_to(t, y.shape[1:])
            return self.swinging.speed(t), self.swinging.acceleration(t)
        return y[self.layout.roller], None

    def evaluate(self, t, y: np.ndarray) -> dict[str, np.ndarray]:
        """Derivatives and signals at times t [s] (scalar or per column) and states y (n, k)."""
        lay = self.layout
        i_g = self.gear_ratio
        w_r, acc_r = self._roller(t, y)
        gear = w_r / i_g
        w_d = y[lay.disc] if lay.disc is not None else gear
        v = w_r * self.roller_radius
        steady = self.contact.loads(v, w_d)
        loads = y[lay.loads] if lay.loads is not None else steady
        f_x, f_y, m_o = loads
        m_d = m_o - self.contact.c * f_y + (self.contact.l_set + self.radius_c) * f_x
        t_fd = self.bearings.disc(w_d) if self.bearings is not None else 0.0
        t_fr = self.bearings.roller(w_r) if self.bearings is not None else 0.0
        t_w = self.worm.torque(w_r, self.set_speed) if self.worm is not None else 0.0
        out = dict(roller_speed=w_r, disc_speed=w_d, rolling_speed=v, force_x=f_x, force_y=f_y, moment_o=m_o)
        dy = np.zeros_like(y)
        if self.loop is not None:
            rate = gear - w_d
            t_mo = self.loop.torque(y[lay.twist], rate)
            dy[lay.twist] = rate
            dy[lay.disc] = (t_mo + m_d - t_fd) / self.disc_inertia
            if self.worm is not None:
                dy[lay.roller] = (t_w - t_mo / i_g - self.roller_radius * f_x - t_fr) / self.worm.inertia
        else:
            inertia = self.disc_inertia / i_g**2
            if self.worm is not None:
                acc_r = (t_w - self.roller_radius * f_x + (m_d - t_fd) / i_g - t_fr) / (self.worm.inertia + inertia)
                dy[lay.roller] = acc_r
            t_mo = self.disc_inertia * acc_r / i_g - m_d + t_fd
        if lay.loads is not None:
            dy[lay.loads] = self.relaxation.rate(v) * (steady - loads)
        out.update(momentometer_torque=t_mo * np.ones_like(w_r), derivative=dy)
        return out

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        """dy/dt for solve_ivp (vectorised: y of shape (n,) or (n, k))."""
        if y.ndim == 1:
            return self.rhs_one(t, y)
        return self.evaluate(t, y)["derivative"]

    def rhs_one(self, t: float, y: np.ndarray) -> np.ndarray:
        """dy/dt of one state in Python floats (same equations as :meth:`evaluate`; the implicit
        integrator's Newton iterations call it one state at a time - tested equal)."""
        lay = self.layout
        i_g = self.gear_ratio
        c = self.contact
        w_r = float(self.swinging.speed(t)) if self.swinging is not None else float(y[lay.roller])
        gear = w_r / i_g
        w_d = float(y[lay.disc]) if lay.disc is not None else gear
        v = w_r * self.roller_radius
        steady = c.loads_one(v, w_d)
        f_x, f_y, m_o = (float(x) for x in y[lay.loads]) if lay.loads is not None else steady
        m_d = m_o - c.c * f_y + (c.l_set + self.radius_c) * f_x
        t_fd = float(self.bearings.disc(w_d)) if self.bearings is not None else 0.0
        t_fr = float(self.bearings.roller(w_r)) if self.bearings is not None else 0.0
        t_w = float(self.worm.torque(w_r, self.set_speed)) if self.worm is not None else 0.0
        dy = np.empty(lay.size)
        if self.loop is not None:
            rate = gear - w_d
            t_mo = float(self.loop.torque(y[lay.twist], rate))
            dy[lay.twist] = rate
            dy[lay.disc] = (t_mo + m_d - t_fd) / self.disc_inertia
            if self.worm is not None:
                dy[lay.roller] = (t_w - t_mo / i_g - self.roller_radius * f_x - t_fr) / self.worm.inertia
        elif self.worm is not None:
            inertia = self.worm.inertia + self.disc_inertia / i_g**2
            dy[lay.roller] = (t_w - self.roller_radius * f_x + (m_d - t_fd) / i_g - t_fr) / inertia
        if lay.loads is not None:
            k = float(self.relaxation.rate(v))
            dy[lay.loads] = (k * (steady[0] - f_x), k * (steady[1] - f_y), k * (steady[2] - m_o))
        return dy
