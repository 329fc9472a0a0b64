"""The FAG 7208 angular-contact ball bearing of [Oscillating] (Table 1) and its load cases (Table 2).

Table 1 [T]: D = 80 mm, d = 40 mm, ball radius r_RE = 5.93 mm, contact angle 40 deg,
osculation 96.0 % (IR) / 93.8 % (OR), steel E = 210 GPa, nu = 0.3 (text). Assumed [A]:
d_m = (D + d)/2, osculation = r_RE/r_groove (rig.bearing.ball_raceway).
Table 2 [T]: contact force per ball and the published maximum pressures and e = 1, e = 1.5
double amplitudes on the inner ring (from the authors' FE model). The number of balls is not
in Table 1; the quoted theta_crit = 51.42 deg equals 720 deg/14, i.e. Z = 14 with gamma
neglected (Equations §5.1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pandas as pd

from rig.bearing.amplitude import KinematicAssumption, amplitude_for_stroke_ratio
from rig.bearing.ball_raceway import BearingGeometry, Ring, raceway_contact
from rig.contact.materials import Material

BEARING_STEEL = Material(E=210e9, nu=0.3, rho=7850.0, name="bearing steel", source="E, nu [T] [Oscillating]; rho [A]")

FAG_7208 = BearingGeometry(
    outer_diameter=0.080,
    inner_diameter=0.040,
    ball_radius=5.93e-3,
    contact_angle=math.radians(40.0),
    osculation_inner=0.960,
    osculation_outer=0.938,
    material=BEARING_STEEL,
)

THETA_CRIT_PUBLISHED_DEG = 51.42  # [Oscillating] sec. 7, "out of range for this investigation"


@dataclass(frozen=True)
class LoadCase:
    """One row of [Oscillating] Table 2: force_N per ball, published pressures [Pa] and amplitudes [deg]."""

    force_N: float
    p_inner_Pa: float
    p_outer_Pa: float
    theta_e1_deg: float
    theta_e15_deg: float


TABLE_2 = (
    LoadCase(1270.0, 2.05e9, 2.00e9, 1.5, 2.2),
    LoadCase(790.0, 1.76e9, 1.71e9, 1.2, 1.9),
    LoadCase(3170.0, 2.79e9, 2.72e9, 2.0, 3.0),
)


def reproduce_table_2(
    bearing: BearingGeometry = FAG_7208, assumption: KinematicAssumption = KinematicAssumption.K3
) -> pd.DataFrame:
    """Table 2 recomputed with Hertz theory and the stated kinematic assumption, beside the published values.

    Columns carry units: force_N, p_inner_GPa(_published), p_outer_GPa(_published), a/b of both
    contacts in mm, theta_e1_deg(_published), theta_e15_deg(_published).
    """
    rows = []
    for case in TABLE_2:
        inner = raceway_contact(bearing, Ring.INNER, case.force_N)
        outer = raceway_contact(bearing, Ring.OUTER, case.force_N)
        rows.append(
            {
                "force_N": case.force_N,
                "p_inner_GPa": inner.p0 / 1e9,
                "p_inner_GPa_published": case.p_inner_Pa / 1e9,
                "p_outer_GPa": outer.p0 / 1e9,
                "p_outer_GPa_published": case.p_outer_Pa / 1e9,
                "a_inner_mm": inner.a * 1e3,
                "b_inner_mm": inner.b * 1e3,
                "a_outer_mm": outer.a * 1e3,
                "b_outer_mm": outer.b * 1e3,
                "theta_e1_deg": math.degrees(amplitude_for_stroke_ratio(bearing, 1.0, inner.b, assumption)),
                "theta_e1_deg_published": case.theta_e1_deg,
                "theta_e15_deg": math.degrees(amplitude_for_stroke_ratio(bearing, 1.5, inner.b, assumption)),
                "theta_e15_deg_published": case.theta_e15_deg,
            }
        )
    return pd.DataFrame(rows)
