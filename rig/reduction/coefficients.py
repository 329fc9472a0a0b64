"""The contact model as the reduction sees it: coefficients(l/a, c/a, alpha') -> (nu_T, nu_v, nu_0).

The caller binds the model, shape, b/a and Poisson ratio (e.g. functools.partial over
rig.contact.solve.solve, or a stand's surrogate law). A model that has no answer at a state -
a surrogate table asked outside its domain - raises :class:`OutsideModelDomain` naming the
coordinate, its value and the domain; the chains turn that (and any non-finite coefficient)
into NaN with the model's own words as the reason, instead of a guard message about the NaN
it produced (docs/reduction.md section 3).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from rig.errors import ParameterError

Coefficients = Callable[[float, float, float], tuple[float, float, float]]
"""coefficients(l_over_a, c_over_a, alpha_prime) -> (nu_T, nu_v, nu_0), all [1]."""


class OutsideModelDomain(ParameterError):
    """The contact model is not defined at this (l/a, c/a, alpha') (e.g. outside a table's domain)."""


def call_model(coefficients: Coefficients, l_over_a: float, c_over_a: float,
               alpha: float) -> tuple[tuple[float, float, float] | None, str]:
    """((nu_T, nu_v, nu_0), "") or (None, reason) when the model has no finite answer there."""
    try:
        nu = tuple(float(x) for x in coefficients(l_over_a, c_over_a, alpha))
    except OutsideModelDomain as error:
        return None, f"contact model: {error}"
    if not all(math.isfinite(x) for x in nu):
        return None, (f"contact model gave no coefficients at l/a = {l_over_a:.6g}, c/a = {c_over_a:.6g}, "
                      f"alpha' = {alpha:.6g} (nu_T, nu_v, nu_0 = {', '.join(f'{x:.3g}' for x in nu)})")
    return nu, ""
