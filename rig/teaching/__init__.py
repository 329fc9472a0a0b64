"""Teaching: small, pure physics functions for the tutorial (docs/tutorial.md).

From [Zhao]'s basics (lecture notes "Mutual actions in machinery elements") towards the
paper's measurement method; every function states its units and the slide or equation it
implements (Equations §6).

| module | content |
|---|---|
| coulomb | static/kinetic friction, ineq. (5.1), friction power |
| pull_test | the "slowly increasing force" experiment, drop mu_s -> mu_k |
| inclined_plane | at rest iff tan(alpha) <= mu_s, a = g (sin(alpha) - mu_k cos(alpha)) |
| friction_table | slide 19's coefficients as data, slide 18's ranges, the steel-PTFE contradiction |
| rolling_wheel | a wheel pulled at its centre: rolling without / with slipping, ineq. (5.10) |
| rolling_resistance | u = f_v r, moment N u, power f_v N v, measuring f_v by pulling |
| hysteresis | Kelvin-Voigt rim on a rigid plane: p(xi), the p-eps loop, the shift u |
| gate_time | the gate-time lesson: stand A simulated and reduced per gate time, u(l/a) and u(mu_T) vs T |

The later tutorial steps (spin, rolling point, stand A) use rig.contact, rig.wheel_kinematics
and rig.runner directly; the scripts are in experiments/tutorial/ (never imported by rig).
"""

from __future__ import annotations
