"""Which friction estimate drives alpha': chosen once per point, from the significance of its reading.

alpha' (eq. 21) contains mu, so one of the friction estimates (stand A: mu_v, then mu_T; stand
B: mu_v, mu_T, mu_M) feeds the mu <-> alpha' iteration (Equations §2). An estimate whose
reading - the force or moment in its numerator - lies within ``significance`` standard
uncertainties of zero measures nothing but noise (hard case 8: F_V at c = 0), and would drive
alpha' anywhere. So, at the nominal readings and before any perturbation, the candidates are
filtered by |reading| > significance u(reading) (u from a first-order propagation of the
numerator alone - cheap, no contact model); the chain then uses the first candidate that gives a
fixed point and keeps it for every evaluation of the Jacobian (rig.reduction.result).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

from rig.reduction.uncertainty import InputSet, first_order

Numerator = tuple[str, Callable[[Mapping[str, float]], float]]
"""(label of the reading, e.g. "F_y", function of the input values giving it [N or N m])."""


def significant_drivers(inputs: InputSet, numerators: Mapping[str, Numerator],
                        significance: float) -> tuple[tuple[str, ...], str]:
    """(candidates in order whose reading is significant, why the others are not)."""
    names = tuple(numerators)
    propagation = first_order(lambda values: {n: numerators[n][1](values) for n in names}, inputs, names)
    chosen, notes = [], []
    for i, name in enumerate(names):
        value, u = float(propagation.values[i]), float(propagation.uncertainties[i])
        if math.isfinite(value) and math.isfinite(u) and abs(value) > significance * u:
            chosen.append(name)
        elif not (math.isfinite(value) and math.isfinite(u)):  # a NaN never passes for "within" (issue 14)
            notes.append(f"{numerators[name][0]} = {value:.3g} with u = {u:.3g} is not a finite reading, so {name} "
                         "cannot drive alpha'")
        else:
            notes.append(f"{numerators[name][0]} = {value:.3g} is within {significance:g} u = {significance * u:.3g} "
                         f"of 0, so {name} cannot drive alpha'")
    return tuple(chosen), "; ".join(notes)
