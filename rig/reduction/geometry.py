"""Constants of the two test stands that the reduction needs, with their provenance.

The ONE place for the Equations page's defaults (Equations §3.1 stand A, 3.2 stand B). Every field
carries metadata: its unit, a tag ("text" = stated in [Koziarski], "computed" = derived in the
the Equations page's arithmetic, "assumed" = plausible, not in the text) and its source; see
:func:`provenance`. Lengths are SI [m], angles [rad]. Override a value with
dataclasses.replace (e.g. Delta h = 0 for the second yoke setting, or a = 1.7 mm).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import TypeVar

from rig import validate

G = TypeVar("G")


def with_inputs(geometry: G, values: Mapping[str, float]) -> G:
    """``geometry`` with the fields the reduction's inputs ``geom_<field>`` change (a perturbed evaluation)."""
    changed = {k[5:]: v for k, v in values.items() if k.startswith("geom_")}
    return dataclasses.replace(geometry, **changed) if changed else geometry


def _const(value: float, unit: str, tag: str, source: str):
    return field(default=value, metadata=dict(unit=unit, tag=tag, source=source))


def _b_over_a_for_load(anchors: tuple[tuple[float, float], ...], normal_force: float) -> float:
    """b/a at a load [N]: the text value at a listed load, else b ~ sqrt(F_N) from the nearest one.

    b ~ sqrt(F_N) at fixed a is Hertz line contact (Equations §1.1 item 3); the nearest listed
    load is the anchor (ratio of loads closest to 1).
    """
    f = validate.number("normal_force", normal_force, 0.0, lo_open=True)
    load, ratio = min(anchors, key=lambda pair: abs(math.log(f / pair[0])))
    return ratio * math.sqrt(f / load)


@dataclass(frozen=True)
class StandAGeometry:
    """Stand A (yoke/spring stand, [Koziarski] Figs. 8-9): constants of eqs. (29)-(35) and (21)."""

    l1: float = _const(42.76e-3, "m", "computed", "Equations §3.1 Derived: l1 = r1/sin(alpha1), r2 = 50.5 mm")
    l2: float = _const(-50.50e-3, "m", "computed", "Equations §3.1 Derived: l2 = -r2, mean lining radius")
    alpha_1: float = _const(math.radians(73.4), "rad", "computed", "Equations §3.1: sin(alpha1) = 1.77 - i_k")
    delta_h: float = _const(1.06e-3, "m", "text", "[Koziarski] section 3.1.2: yoke shift Delta h = 0 and 1.06 mm")
    a: float = _const(1.215e-3, "m", "computed", "Equations §3.1: c/a = 0.4 at l = 0 (annulus: 1.7 mm)")
    r1: float = _const(40.98e-3, "m", "computed", "Equations §3.1: r1 = v/w1 = 1.03/25.13")
    radius_x: float = _const(143.7e-3, "m", "computed", "Equations §3.1: R_x = r1/cos(alpha1)")
    dynamometer_lever: float = _const(0.102, "m", "text", "[Koziarski]: dynamometer 10 at 102 mm from axle 4")
    yoke_lever: float = _const(42.5e-3, "m", "text", "[Koziarski]: R_v = 42.5 mm (printed 42.2: misprint)")
    balance_arm: float = _const(0.400, "m", "computed", "Equations §3.1: 0.0196 N m / 0.049 N")
    weights_half_width: float = _const(0.098, "N", "text", "[Koziarski]: calibration weights +-10 gf")
    balance_half_width: float = _const(0.049, "N", "text",
                                       "[Koziarski]: tangent balance accuracy 5 gf, read as a +-limit "
                                       "(the simulated scale step is the stand parameter balance_step_N)")
    load_b_over_a: tuple[tuple[float, float], ...] = field(
        default=((96.2, 1.0), (385.0, 2.0)),
        metadata=dict(unit="N, 1", tag="text", source="[Koziarski]: b/a = 1, 2 at 96.2, 385 N (pairing: Equations §3.1)"),
    )

    def __post_init__(self) -> None:
        for name in ("a", "r1", "radius_x", "dynamometer_lever", "yoke_lever", "balance_arm"):
            validate.number(name, getattr(self, name), 0.0, lo_open=True)
        validate.number("l1", self.l1)
        validate.number("l2", self.l2, hi=self.l1, hi_open=True)
        validate.number("alpha_1", self.alpha_1, -math.pi / 2, math.pi / 2)
        validate.number("delta_h", self.delta_h)
        validate.number("weights_half_width", self.weights_half_width, 0.0)
        validate.number("balance_half_width", self.balance_half_width, 0.0)

    def b_over_a(self, normal_force: float) -> float:
        """b/a [1] at the pressing force F_N [N] (listed load: text value; else b ~ sqrt(F_N))."""
        return _b_over_a_for_load(self.load_b_over_a, normal_force)

    @property
    def balance_moment_step(self) -> float:
        """The paper's "accuracy" of the tangent balance in moment [N m] (0.049 N x 0.400 m = 0.0196 N m);
        the simulated balance's scale step is a stated parameter (sensors.balance, docs/reduction.md 4)."""
        return self.balance_half_width * self.balance_arm

    @property
    def balance_moment_half_width(self) -> float:
        """The same 0.0196 N m read as the paper's +-bound [N m] (u = bound/sqrt(3) = 0.0113 N m; the
        reduction takes u from the scale step the log records, step/sqrt(12), the same by default)."""
        return self.balance_moment_step

    @property
    def lateral_force_half_width(self) -> float:
        """Half width of F_y from the calibration weights [N] (0.098 N x 102/42.5 = 0.235 N)."""
        return self.weights_half_width * self.dynamometer_lever / self.yoke_lever


@dataclass(frozen=True)
class StandBGeometry:
    """Stand B (disc/roller stand, [Koziarski] Figs. 12-13): constants of eq. (36), M_C and (21)."""

    radius_c: float = _const(166.3e-3, "m", "text", "[Koziarski]: rolling-point radius on the disc R_c")
    roller_radius: float = _const(62.5e-3, "m", "text", "[Koziarski]: roller d = 125 mm")
    pivot_distance: float = _const(70.2e-3, "m", "text", "[Koziarski] eq. (36): c = 70.2 sin(sigma) mm")
    a: float = _const(4.0e-3, "m", "text", "[Koziarski]: track width 2a = 8 mm")
    load_b_over_a: tuple[tuple[float, float], ...] = field(
        default=((9.0, 0.5), (21.0, 0.75), (36.0, 1.0), (144.0, 2.0)),
        metadata=dict(unit="N, 1", tag="text", source="[Koziarski]: b/a = 0.5/0.75/1/2 at 9/21/36/144 N"),
    )

    def __post_init__(self) -> None:
        for name in ("radius_c", "roller_radius", "pivot_distance", "a"):
            validate.number(name, getattr(self, name), 0.0, lo_open=True)

    def b_over_a(self, normal_force: float) -> float:
        """b/a [1] at the load F_N [N] (listed load: text value; else b ~ sqrt(F_N))."""
        return _b_over_a_for_load(self.load_b_over_a, normal_force)

    @property
    def spin_radius(self) -> float:
        """v/w0 [m] = R_c: the disc spins at w0 = v/R_c under the rolling point (Equations §3.2)."""
        return self.radius_c

    @property
    def radius_x(self) -> float:
        """Effective radius across the line contact R_x [m] = roller radius (flat disc)."""
        return self.roller_radius


def provenance(geometry: StandAGeometry | StandBGeometry) -> list[dict[str, object]]:
    """Rows (name, value, unit, tag, source) of a geometry's constants, for docs and logs."""
    return [
        dict(name=f.name, value=getattr(geometry, f.name), unit=f.metadata["unit"], tag=f.metadata["tag"],
             source=f.metadata["source"])
        for f in fields(geometry)
    ]
