"""Rolling-resistance length f of eq. (3): v_y = v_v + f w0 + v sin(sigma).

The forward shift f of the normal reaction adds f w0 to the lateral slip at the contact
centre, i.e. it moves the rolling point by f across the contact line: c -> c + f (eq. 2).
The rolling-resistance moment F_N f about the contact line ([Zhao]) is a normal-force effect;
the physical-units layer reports it (rig.contact.physical).
"""

from __future__ import annotations

from dataclasses import dataclass

from rig import validate
from rig.contact.kinematics import Creepage


@dataclass(frozen=True)
class RollingResistance:
    """Rolling-friction length over the half length, f/a (dimensionless)."""

    length: float

    def __post_init__(self) -> None:
        validate.number("rolling_length", self.length, -10.0, 10.0)

    def shift(self, creepage: Creepage | None, rolling_point: tuple[float, float] | None):
        """The rigid slip and rolling point (c/a, l/a) with the f w0 term of eq. (3) added.

        c -> c + f; in creepages eta = -phi c, so eta -> eta - phi f. Either may be None.
        """
        if rolling_point is not None:
            rolling_point = (rolling_point[0] + self.length, rolling_point[1])
        if creepage is not None:
            creepage = Creepage(xi=creepage.xi, eta=creepage.eta - creepage.phi * self.length, phi=creepage.phi)
        return creepage, rolling_point
