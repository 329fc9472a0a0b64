"""A tiny closed-form stand-in for rig.stands.contact_law (vectorised, smooth, cheap).

Shaped like the line-contact models near full sliding (Equations §1.10, 3.1): nu_T ~ -l/|C|,
nu_v from c and from the spin (elastic part, grows with alpha'), nu_0 ~ |C|/a far out; the
elastic factor 1/(1 + alpha'/3) makes mu identifiable from alpha' (eq. 21).
"""

from __future__ import annotations

import numpy as np

CALLS = {"n": 0}


def coefficients(l, c, alpha):
    """(nu_T, nu_v, nu_0) [1] at l/a, c/a, alpha' (arrays)."""
    CALLS["n"] += 1
    l, c, alpha = (np.asarray(x, dtype=float) for x in (l, c, alpha))
    rho = np.sqrt(l * l + c * c + 0.6)
    f = 1.0 / (1.0 + alpha / 3.0)
    nu_t = -l / rho * f
    nu_v = (c + 0.25 * alpha / (1.0 + alpha)) / rho * f
    nu_0 = rho * (1.0 - 0.1 * alpha / (1.0 + alpha))
    return nu_t, nu_v, nu_0


def factory(spec, shape, b_over_a, domain):
    """Same signature as rig.stands.contact_law.make_contact_law."""
    return coefficients
