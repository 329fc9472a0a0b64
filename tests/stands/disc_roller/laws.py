"""Fast closed-form contact laws for stand-B tests (independent of the surrogate tables).

``smooth_law`` has the model's sign conventions (nu_T <= 0 for l > 0, nu_v > 0 for c >= 0,
w0 > 0: the spin pushes along +y even at c = 0, like the kinematic model), |nu_T|, |nu_v| < 1,
saturation far from the contact and nu_0 ~ |C|/a there, and a weak alpha' dependence (the
forces grow with alpha', so mu stays identifiable in the reduction's mu <-> alpha' iteration).
"""

from __future__ import annotations

import numpy as np


def smooth_law(l_over_a, c_over_a, alpha):
    """(nu_T, nu_v, nu_0) arrays of a smooth stand-in law (vectorised)."""
    l, c, a = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (l_over_a, c_over_a, alpha)))
    r = np.sqrt(l * l + c * c + 1.0)
    gain = 1.0 - 0.4 / (1.0 + a)
    lateral = c + 0.25
    return -l / r * gain, lateral / np.sqrt(l * l + lateral * lateral + 1.0) * gain, np.sqrt(l * l + c * c + 0.5)


def smooth_factory(b_over_a: float):
    """b/a -> smooth_law (the law does not depend on b/a)."""
    return smooth_law
