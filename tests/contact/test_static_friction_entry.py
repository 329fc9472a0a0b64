"""Static friction: the two conventions for material entering the contact (issue 15, item 5).

static_ratio: entering material holds mu0 p (it carries no slip yet); static_ratio_after_first_stick:
it is kinetic until it first sticks (the Equations page's memory table). Where the leading cells stick
anyway (alpha' = 100 here) they agree; where the kinetic law slides from the leading edge on
(alpha' = 1, 10 here: stick fraction 0) the second convention never reaches mu0 and stays the
kinetic law, while the first lets entering material hold mu0 p (measured at alpha' = 10, n = 16:
nu_v 0.5562 against 0.4937).
"""

import pytest

from rig.contact.effects import ContactEffects
from rig.contact.newton import TOLERANCE as NEWTON_TOL
from rig.contact.solve import solve
from rig.errors import ParameterError

BASE = dict(shape="ellipse", b_over_a=1.0, c_over_a=0.0, l_over_a=0.5, poisson=0.28, n=16)


@pytest.mark.parametrize("alpha", [1.0, 10.0, 100.0])
def test_both_conventions_bound_the_kinetic_case_and_order_the_adhesion(alpha):
    kinetic = solve("kinematic", alpha=alpha, **BASE)
    entering_static = solve("kinematic", alpha=alpha, static_ratio=2.0, **BASE)
    after_stick = solve("kinematic", alpha=alpha, static_ratio_after_first_stick=2.0, **BASE)
    assert kinetic.stick_fraction <= after_stick.stick_fraction <= entering_static.stick_fraction
    assert after_stick.info["effects"] == ["static_ratio_after_first_stick"]
    for r in (entering_static, after_stick):
        assert abs(r.nu_T) <= 2.0 and abs(r.nu_v) <= 2.0  # bounded by mu0/mu
    if kinetic.stick_fraction == 0.0:  # nothing ever sticks: never static after a first stick
        assert after_stick.nu_v == pytest.approx(kinetic.nu_v, abs=10 * NEWTON_TOL)  # same problem, two paths
        assert entering_static.nu_v > kinetic.nu_v + 0.01  # entering material held mu0 p
    elif after_stick.stick_fraction == entering_static.stick_fraction:  # the same cells stick: agree
        assert after_stick.nu_v == pytest.approx(entering_static.nu_v, abs=1e-6)
    else:  # material that slides on entry holds mu0 p under one convention only
        assert entering_static.nu_v > after_stick.nu_v


def test_ratio_one_is_the_kinetic_law_under_either_convention():
    kinetic = solve("kinematic", alpha=3.0, **BASE)
    for keyword in ("static_ratio", "static_ratio_after_first_stick"):
        r = solve("kinematic", alpha=3.0, **{keyword: 1.0}, **BASE)
        assert (r.nu_T, r.nu_v, r.nu_0) == pytest.approx((kinetic.nu_T, kinetic.nu_v, kinetic.nu_0), abs=1e-9)


def test_the_two_conventions_together_are_a_named_error():
    with pytest.raises(ParameterError, match="static_ratio_after_first_stick"):
        ContactEffects.from_keywords(static_ratio=2.0, static_ratio_after_first_stick=2.0)
