"""Wheatstone bridge of strain gauges: strain [1] -> bridge output voltage [V].

The bridge has two voltage dividers fed by the excitation V_ex; arms a (top) and b (bottom) on
the left, c (top) and d (bottom) on the right; V_out = V_ex [R_b/(R_a + R_b) - R_d/(R_c + R_d)].
A strain gauge changes its resistance by dR/R = k eps (k = gauge factor). Gauge placement
[standard practice, assumed for the stands' instruments]:

* QUARTER - one active gauge (+eps) in arm b, three fixed resistors:
  V_out = V_ex k eps / (4 + 2 k eps)   (slightly non-linear);
* HALF - two active gauges with opposite strains (+eps in b, -eps in a; bending beam or
  +-45 deg torsion gauges): V_out = V_ex k eps / 2   (exactly linear);
* FULL - four active gauges (+eps in b and c, -eps in a and d): V_out = V_ex k eps.

The small-strain form is V_out = V_ex k eps n/4 with n = 1, 2, 4 active gauges. Lead-wire
resistance, temperature compensation and transverse sensitivity are not modelled.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError


class BridgeConfiguration(Enum):
    """How many arms of the bridge carry active strain gauges (value = number of active gauges)."""

    QUARTER = 1
    HALF = 2
    FULL = 4


# Relative strain sign of the gauge in arms (a, b, c, d); 0 = fixed completion resistor.
_ARM_SIGNS = {
    BridgeConfiguration.QUARTER: (0.0, 1.0, 0.0, 0.0),
    BridgeConfiguration.HALF: (-1.0, 1.0, 0.0, 0.0),
    BridgeConfiguration.FULL: (-1.0, 1.0, 1.0, -1.0),
}

DEFAULT_GAUGE_FACTOR = 2.0
"""Gauge factor k of metal-foil gauges [1] (assumed: the usual value for constantan foil)."""
DEFAULT_EXCITATION_V = 5.0
"""Bridge excitation [V] (assumed: a common DC/carrier bridge supply)."""


@dataclass(frozen=True)
class Bridge:
    """A strain-gauge Wheatstone bridge: configuration, gauge factor [1], excitation [V]."""

    configuration: BridgeConfiguration
    gauge_factor: float = DEFAULT_GAUGE_FACTOR
    excitation_V: float = DEFAULT_EXCITATION_V

    def __post_init__(self) -> None:
        if not isinstance(self.configuration, BridgeConfiguration):
            raise InstrumentParameterError(
                "bridge_configuration", self.configuration,
                "one of " + ", ".join(f"BridgeConfiguration.{c.name}" for c in BridgeConfiguration),
            )
        validate.number("gauge_factor", self.gauge_factor, 0.5, 10.0)
        validate.number("excitation_V", self.excitation_V, 0.0, 30.0, lo_open=True)

    @property
    def active_gauges(self) -> int:
        """Number of active gauges n [1]."""
        return self.configuration.value

    def output_V(self, strain: np.ndarray | float) -> np.ndarray:
        """Exact bridge output [V] for the gauge strain ``strain`` [1] (array or scalar).

        Valid for |strain| < 0.05 (foil gauges fail long before); the check is left to the
        instrument that produces the strain.
        """
        eps = np.asarray(strain, dtype=float)
        sa, sb, sc, sd = _ARM_SIGNS[self.configuration]
        x = self.gauge_factor * eps
        # rb/(ra+rb) - rd/(rc+rd) = (rb rc - ra rd)/((ra+rb)(rc+rd)), numerator expanded in x
        # (r = 1 + s x) so that small strains do not cancel: (sb+sc-sa-sd) x + (sb sc - sa sd) x^2
        numerator = (sb + sc - sa - sd) * x + (sb * sc - sa * sd) * x * x
        denominator = (2.0 + (sa + sb) * x) * (2.0 + (sc + sd) * x)
        return self.excitation_V * numerator / denominator

    def sensitivity_V(self) -> float:
        """Small-strain sensitivity dV_out/d(eps) = V_ex k n/4 [V per unit strain]."""
        return self.excitation_V * self.gauge_factor * self.active_gauges / 4.0
