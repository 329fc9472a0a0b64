"""The stand constants against [Koziarski]'s own numbers (Equations §3.1, 3.2) and their provenance."""

from __future__ import annotations

import math

import pytest

from rig.reduction.geometry import StandAGeometry, StandBGeometry, provenance
from rig.wheel_kinematics import c_for_l

A, B = StandAGeometry(), StandBGeometry()
# text: 240 rpm, 1.03 m/s, w0/w1 = 1.77; mean lining radius (OD 104.4, ID 97.6 mm)
W1, V, SPIN_RATIO, R2 = 2 * math.pi * 240 / 60, 1.03, 1.77, 50.5e-3


def test_stand_a_constants_follow_from_the_text():
    assert A.r1 == pytest.approx(V / W1, rel=1e-3)
    ratio = A.r1 / R2  # l = 0: w1 r1 = w2 r2
    assert ratio == pytest.approx(0.8115, abs=1e-4)
    assert math.sin(A.alpha_1) == pytest.approx(SPIN_RATIO - ratio, abs=1e-3)
    assert A.l1 == pytest.approx(A.r1 / math.sin(A.alpha_1), rel=1e-3)
    assert A.l2 == -R2
    assert A.radius_x == pytest.approx(A.r1 / math.cos(A.alpha_1), rel=3e-3)
    assert A.l1 - A.l2 == pytest.approx(87.7 * A.delta_h, rel=4e-3)  # Fig. 11 caption
    assert c_for_l(0.0, A.l1, A.l2, A.delta_h) / A.a == pytest.approx(0.4, abs=1e-3)  # "c/a = 0.4"
    assert A.balance_arm * A.balance_half_width == pytest.approx(0.0196)
    assert A.b_over_a(96.2) == 1.0 and A.b_over_a(385.0) == pytest.approx(2.0, abs=1e-3)


@pytest.mark.parametrize("geometry", [A, B])
def test_every_constant_is_tagged_with_a_source(geometry):
    rows = provenance(geometry)
    assert {row["tag"] for row in rows} <= {"text", "computed", "assumed"}
    assert all(row["source"] and row["unit"] for row in rows)
    assert len(rows) == len({row["name"] for row in rows})


def test_stand_b_constants():
    assert B.spin_radius / B.radius_x == pytest.approx(2.661, abs=1e-3)  # R_c/R_r, Equations §3.2
    assert B.pivot_distance * math.sin(math.radians(6.54)) == pytest.approx(8e-3, abs=5e-6)
