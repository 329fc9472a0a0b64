"""Force and moment coefficients of a traction field, eqs. (26)-(28) of [Koziarski].

All models integrate their tractions with this one function, so the definitions (and the sign
convention of rig.contact.result) live in one place.
"""

from __future__ import annotations

import numpy as np

from rig.contact.kinematics import Creepage


def coefficients(x: np.ndarray, y: np.ndarray, q: np.ndarray, p: np.ndarray, creepage: Creepage) -> dict[str, float]:
    """nu_T, nu_v (eqs. 27-28), nu_Mo, nu_MC and nu_0 (eq. 26) of tractions on equal cells.

    x, y: sample points [a]; q: traction (2, N) [mu p0]; p: pressure (N,) [p0] at the same
    points (equal weights, so F_N is proportional to sum(p)). The moment about the rolling point
    is converted from the moment about the centre, M_C = M_O - c F_y + l F_x (Equations §1.1), and
    nu_0 = P_t/(mu a F_N |w0|) = -sign(w0) M_C/(mu a F_N); both are NaN for zero spin.
    """
    load = float(np.sum(p))
    nu_T = float(np.sum(q[0])) / load
    nu_v = float(np.sum(q[1])) / load
    nu_Mo = float(np.sum(x * q[1] - y * q[0])) / load
    if creepage.phi == 0.0:
        return dict(nu_T=nu_T, nu_v=nu_v, nu_Mo=nu_Mo, nu_MC=np.nan, nu_0=np.nan)
    c, l = creepage.rolling_point()
    nu_MC = nu_Mo - c * nu_v + l * nu_T
    return dict(nu_T=nu_T, nu_v=nu_v, nu_Mo=nu_Mo, nu_MC=nu_MC, nu_0=-np.sign(creepage.phi) * nu_MC)
