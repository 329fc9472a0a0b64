"""Optional effects of the contact model, one module each; an effect that is off is ``None``.

Each effect is built only when a caller names it (``solve(..., psi=2.0)``), and the model calls
into it only when it is built: an effect left off computes nothing (tests/contact/test_effects.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig.contact.effects.plastic_slip import PlasticSlip
from rig.contact.effects.pressure_friction import PressureDependentFriction
from rig.contact.effects.rolling_resistance import RollingResistance
from rig.contact.effects.static_friction import StaticFriction, StaticFrictionAfterFirstStick
from rig.contact.effects.surface_inertia import SurfaceInertia
from rig.errors import ParameterError

# keyword of solve() -> effect component built from its value
EFFECT_KEYWORDS = {
    "psi": PlasticSlip,
    "static_ratio": StaticFriction,
    "static_ratio_after_first_stick": StaticFrictionAfterFirstStick,
    "inertia_number": SurfaceInertia,
    "rolling_length": RollingResistance,
    "pressure_exponent": PressureDependentFriction,
}
# keyword -> the ContactEffects field its component fills (one field per kind of effect)
_FIELDS = {"psi": "plastic_slip", "static_ratio": "static_friction", "static_ratio_after_first_stick": "static_friction",
           "inertia_number": "surface_inertia", "rolling_length": "rolling_resistance",
           "pressure_exponent": "pressure_friction"}


@dataclass(frozen=True)
class ContactEffects:
    """The effects a solve uses; ``None`` means off (no object, no call, no cost)."""

    plastic_slip: PlasticSlip | None = None
    static_friction: StaticFriction | None = None
    surface_inertia: SurfaceInertia | None = None
    rolling_resistance: RollingResistance | None = None
    pressure_friction: PressureDependentFriction | None = None

    def traction_bound(self, p: np.ndarray) -> np.ndarray:
        """The traction bound per point [mu0 p0] for pressures p [p0]: p, or mu(p) p/mu0 with the
        pressure-dependent coefficient (rig.contact.effects.pressure_friction) when it is on."""
        return p if self.pressure_friction is None else self.pressure_friction.bound(p)

    def plastic_rate(self, poisson: float) -> float:
        """Plastic slip per unit traction, eq. (25) (rig.contact.effects.plastic_slip): 0 when it is off."""
        return 0.0 if self.plastic_slip is None else self.plastic_slip.rate(poisson)

    @classmethod
    def from_keywords(cls, **values: float) -> ContactEffects:
        """Build the named effects from solve() keywords (already checked to be known names)."""
        if "static_ratio" in values and "static_ratio_after_first_stick" in values:
            raise ParameterError("static_ratio_after_first_stick", values["static_ratio_after_first_stick"],
                                 "not together with static_ratio (two conventions of one effect)")
        return cls(**{_FIELDS[name]: EFFECT_KEYWORDS[name](values[name]) for name in values})

    def names(self) -> list[str]:
        """Keywords of the effects that are on."""
        return [k for k, field in _FIELDS.items()
                if (f := getattr(self, field)) is not None and type(f) is EFFECT_KEYWORDS[k]]
