"""Measured inputs of the reduction as plain numbers with standard uncertainties.

The instrument package (sensors/) is not imported here; a thin adapter will turn its records
into these. A "+-" resolution from the seed is read as the half width of a rectangular
distribution, u = half width/sqrt(3) (GUM 4.3.7; rig.reduction.uncertainty.rectangular_u).
"""

from __future__ import annotations

from dataclasses import dataclass

from rig import validate


@dataclass(frozen=True)
class Measured:
    """A reading: value and its standard uncertainty u (same unit, stated by the field using it)."""

    value: float
    u: float

    def __post_init__(self) -> None:
        validate.number("value", self.value)
        validate.number("u", self.u, 0.0)


@dataclass(frozen=True)
class ForceCalibration:
    """Linear force calibration signal = sensitivity F + offset, fitted against reference weights.

    sensitivity [V/N], offset [V], their standard uncertainties and covariance [V^2/N] from the
    fit; u_weights [N]: standard uncertainty of the reference weights, added to the force as an
    independent term (it is common to all points calibrated with the same weights and is not in
    the fit's scatter). F = (signal - offset)/sensitivity + e_w, e_w = 0 +- u_weights.
    """

    sensitivity: float
    offset: float
    u_sensitivity: float
    u_offset: float
    covariance: float
    u_weights: float

    def __post_init__(self) -> None:
        validate.number("sensitivity", self.sensitivity, 0.0, lo_open=True)
        validate.number("offset", self.offset)
        validate.number("u_sensitivity", self.u_sensitivity, 0.0)
        validate.number("u_offset", self.u_offset, 0.0)
        bound = self.u_sensitivity * self.u_offset
        validate.number("covariance", self.covariance, -bound, bound)
        validate.number("u_weights", self.u_weights, 0.0)
