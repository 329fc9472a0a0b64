"""What the simulation knew at an operating point of stand B (the log's /truth group).

mu is the coefficient the contact ran at (mu(p0) with a pressure-dependent mu).
Continuous drive: the steady contact (model coefficients nu_T, nu_v, nu_0 at the canonical
rolling point l/a, c' /a = direction c/a - the frame the reduction works in), mu, alpha', b/a,
and the gate means of the true signals F_T, F_V, T_Mo and the speeds. ``M_C`` is the pivoting
moment T0 = mu a F_N nu_0 >= 0 resisting the spin - the quantity the reduction's
M_C = T_Mo + R_c F_T estimates (docs/stand-b.md, signs); ``M_C_disc`` is the signed moment
about C on the disc in the stand frame. ``mu_v`` and ``mu_T`` repeat mu (the reduced table's
``true_`` columns). Swinging drive: mu, b/a, alpha', the settings, the stroke ratio e
([Oscillating] S15) and the amplitudes of the true signals over the gate.
"""

from __future__ import annotations

import numpy as np

from rig.logbook import Quantity
from rig.stands.base import GateData


def point_truth(point, gate: GateData) -> dict[str, Quantity]:
    """Truth of a DiscRollerPoint after its gate (units in the Quantities)."""
    p = point.stand.params
    s = point.settings
    c = s.offset_c(p.pivot_distance)
    contact = point.train.contact
    truth = dict(
        mu=Quantity(contact.mu, "1"), b_over_a=Quantity(contact.b / contact.a, "1"),
        alpha_prime=Quantity(contact.alpha, "1"), l=Quantity(s.l, "m"), c=Quantity(c, "m"),
        l_over_a=Quantity(s.l / p.half_length, "1"),
    )
    if point.swinging:
        truth["c_over_a"] = Quantity(c / p.half_length, "1")
        truth["stroke_ratio"] = Quantity(point.train.swinging.stroke_ratio(p.roller_radius, contact.b), "1")
        for name in ("F_T", "F_V", "T_Mo"):
            truth[f"{name}_amplitude"] = Quantity(float(np.max(np.abs(gate.signals[name]))), gate.units[name])
        return truth
    steady = point.target.contact
    truth.update(
        c_over_a=Quantity(s.direction * c / p.half_length, "1"),
        nu_T=Quantity(steady.nu_T, "1"), nu_v=Quantity(steady.nu_v, "1"), nu_0=Quantity(steady.nu_0, "1"),
        M_C=Quantity(steady.resisting_moment, "N m"), M_C_disc=Quantity(steady.moment_c, "N m"),
        mu_v=Quantity(contact.mu, "1"), mu_T=Quantity(contact.mu, "1"),
        spin=Quantity(float(np.mean(gate.signals["disc_speed"])), "rad/s"),
    )
    for name in ("F_T", "F_V", "T_Mo", "roller_speed", "disc_speed", "rolling_speed"):
        truth[name] = Quantity(float(np.mean(gate.signals[name])), gate.units[name])
    return truth
