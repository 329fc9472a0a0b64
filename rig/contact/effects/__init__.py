"""Optional effects of the contact model, one module each; an effect that is off is ``None``.

Each effect is built only when a caller names it (``solve(..., psi=2.0)``), and the model calls
into it only when it is built: an effect left off computes nothing (tests/contact/test_effects.py).
"""

from __future__ import annotations

from dataclasses import dataclass

from rig.contact.effects.plastic_slip import PlasticSlip
from rig.contact.effects.rolling_resistance import RollingResistance
from rig.contact.effects.static_friction import StaticFriction
from rig.contact.effects.surface_inertia import SurfaceInertia

# keyword of solve() -> effect component built from its value
EFFECT_KEYWORDS = {
    "psi": PlasticSlip,
    "static_ratio": StaticFriction,
    "inertia_number": SurfaceInertia,
    "rolling_length": RollingResistance,
}


@dataclass(frozen=True)
class ContactEffects:
    """The effects a solve uses; ``None`` means off (no object, no call, no cost)."""

    plastic_slip: PlasticSlip | None = None
    static_friction: StaticFriction | None = None
    surface_inertia: SurfaceInertia | None = None
    rolling_resistance: RollingResistance | None = None

    @classmethod
    def from_keywords(cls, **values: float) -> ContactEffects:
        """Build the named effects from solve() keywords (already checked to be known names)."""
        built = {name: EFFECT_KEYWORDS[name](values[name]) for name in values}
        return cls(
            plastic_slip=built.get("psi"),
            static_friction=built.get("static_ratio"),
            surface_inertia=built.get("inertia_number"),
            rolling_resistance=built.get("rolling_length"),
        )

    def names(self) -> list[str]:
        """Keywords of the effects that are on."""
        return [k for k, f in zip(EFFECT_KEYWORDS, (self.plastic_slip, self.static_friction,
                                                    self.surface_inertia, self.rolling_resistance)) if f is not None]
