"""The contact model as the reduction sees it: coefficients(l/a, c/a, alpha') -> (nu_T, nu_v, nu_0).

The caller binds the model, shape, b/a and Poisson ratio (e.g. functools.partial over
rig.contact.solve.solve, or a stand's surrogate law). A model that has no answer at a state -
a surrogate table asked outside its domain - raises :class:`OutsideModelDomain` naming the
coordinate, its value and the domain; the chains turn that (and any non-finite coefficient)
into NaN with the model's own words as the reason, instead of a guard message about the NaN
it produced (docs/reduction.md section 3).

A model whose coefficients are not converged exact theory (a coarse grid, a table) may offer
``coefficients.numerical_error(l/a, c/a, alpha') -> (3,)`` [1], its error against the converged
model there (rig.contact.numerical_error). The reduction then adds NU_ERRORS, three inputs of
value 0 with a rectangular distribution of that half width, to the coefficients at the reduced
point (rig.reduction.result.reduce_stand_point), so the budget carries the model's numerical
error as a source of its own (:data:`MODEL_SOURCE`). Without it (None or absent), nothing is
added: the coefficients count as exact.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from rig.errors import ParameterError
from rig.reduction.uncertainty import Distribution, InputQuantity, InputSet, rectangular_u

Coefficients = Callable[[float, float, float], tuple[float, float, float]]
"""coefficients(l_over_a, c_over_a, alpha_prime) -> (nu_T, nu_v, nu_0), all [1]."""

NU_ERRORS = ("nu_T_model_error", "nu_v_model_error", "nu_0_model_error")
MODEL_SOURCE = "contact model (grid and table)"


def with_model_error(inputs: InputSet, bound) -> InputSet:
    """``inputs`` plus the NU_ERRORS for an error ``bound`` (3,) of (nu_T, nu_v, nu_0) [1] (a
    zero bound adds no input)."""
    extra = tuple(InputQuantity(name, 0.0, rectangular_u(float(b)), "1", MODEL_SOURCE, Distribution.RECTANGULAR)
                  for name, b in zip(NU_ERRORS, bound) if b > 0.0)
    return InputSet(inputs.quantities + extra, inputs.covariances)


def corrected(nu: tuple[float, float, float], values) -> tuple[float, float, float]:
    """The coefficients plus the model-error inputs' values (0 at the point, perturbed in the
    propagation); inputs that are not there count as 0."""
    get = values.get
    return nu[0] + get(NU_ERRORS[0], 0.0), nu[1] + get(NU_ERRORS[1], 0.0), nu[2] + get(NU_ERRORS[2], 0.0)


class OutsideModelDomain(ParameterError):
    """The contact model is not defined at this (l/a, c/a, alpha') (e.g. outside a table's domain)."""


def call_model(coefficients: Coefficients, l_over_a: float, c_over_a: float,
               alpha: float) -> tuple[tuple[float, float, float] | None, str]:
    """((nu_T, nu_v, nu_0), "") or (None, reason) when the model has no finite answer there."""
    try:
        nu_t, nu_v, nu_0 = coefficients(l_over_a, c_over_a, alpha)
    except OutsideModelDomain as error:
        return None, f"contact model: {error}"
    nu = (float(nu_t), float(nu_v), float(nu_0))
    if not (math.isfinite(nu[0]) and math.isfinite(nu[1]) and math.isfinite(nu[2])):
        return None, (f"contact model gave no coefficients at l/a = {l_over_a:.6g}, c/a = {c_over_a:.6g}, "
                      f"alpha' = {alpha:.6g} (nu_T, nu_v, nu_0 = {', '.join(f'{x:.3g}' for x in nu)})")
    return nu, ""
