"""The parameters a fit can free: mu and the contact effects' parameters, with units and ranges.

Each parameter has a valid range (a start value or an interval end outside it is a
ParameterError), a default start value and its "off" value: the value at which the effect
computes the same forces as the model without it (psi = 1, static_ratio = 1, inertia_number = 0,
rolling_length = 0, pressure_exponent = 0), used for the nested model sets of the model choice. Ranges of the effects
are the fit's search ranges (inside each effect's own valid range, rig.contact.effects).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from rig import validate
from rig.errors import ParameterError


@dataclass(frozen=True)
class FitParameter:
    """One free-able parameter: name, unit, search range [lo, hi], default start, off value."""

    name: str
    unit: str
    lo: float
    hi: float
    start: float
    off: float | None
    description: str

    @property
    def is_effect(self) -> bool:
        """True for a contact-effect keyword of rig.contact.solve (False for mu)."""
        return self.name != "mu"

    def check(self, value: object, what: str = "") -> float:
        """``value`` as a float inside [lo, hi] (ParameterError naming the parameter otherwise)."""
        label = f"{what}{self.name}" if what else self.name
        return validate.number(label, value, self.lo, self.hi)


PARAMETERS: dict[str, FitParameter] = {
    p.name: p
    for p in (
        FitParameter("mu", "1", 0.05, 1.5, 0.4, None, "coefficient of friction (eqs. 26-28)"),
        FitParameter("psi", "1", 1.0, 3.0, 1.3, 1.0, "plastic-slip ratio Psi = v0/v_el (eq. 25)"),
        FitParameter("static_ratio", "1", 1.0, 2.0, 1.1, 1.0, "static-to-kinetic friction ratio mu0/mu"),
        FitParameter("inertia_number", "1", 0.0, 1.0, 0.1, 0.0, "surface-inertia number (rig.contact.effects)"),
        FitParameter("rolling_length", "1", -0.5, 0.5, 0.05, 0.0, "rolling-resistance length f/a"),
        FitParameter("pressure_exponent", "1", 0.0, 1.0, 0.1, 0.0,
                     "exponent k of a pressure-dependent mu(p) = mu_ref (p/p_ref)^-k (mu: its value at p0)"),
    )
}


def lookup(name: object) -> FitParameter:
    """The FitParameter called ``name`` (UnknownNameError with a "did you mean" otherwise)."""
    return PARAMETERS[validate.choice("parameter", name, PARAMETERS)]


def parse_names(names: Iterable[object]) -> tuple[FitParameter, ...]:
    """The free parameters, in the order given (unknown or repeated names are errors; >= 1)."""
    chosen = [lookup(name) for name in names]
    if not chosen:
        raise ParameterError("params", [], "at least one of " + ", ".join(PARAMETERS))
    seen = [p.name for p in chosen]
    if len(set(seen)) != len(seen):
        raise ParameterError("params", seen, "each parameter at most once")
    return tuple(chosen)


def check_values(values: Mapping[str, object], what: str) -> dict[str, float]:
    """{name: value} with known names and values in range; ``what`` prefixes the names in errors."""
    return {lookup(name).name: lookup(name).check(value, what) for name, value in values.items()}
