"""Stand B's numerical effect law_mu_range: one contact-law domain for every mu of a range (rig lab)."""

import math

import pytest

from rig.errors import ParameterError
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.disc_roller.stand import DiscRollerStand

B_OVER_A = 1.0  # 36 N
ALPHA_PER_MU = 10.0 * B_OVER_A * 0.1663 / 0.0625  # eq. (21) with R_c = 166.3 mm, R_r = 62.5 mm


def _stand(mu: float, effects: dict) -> DiscRollerStand:
    return DiscRollerStand({"mu": mu}, effects, ContactSpec("rigid", None, 0.5), DriveMode.QUASI_STATIC)


def test_without_the_effect_the_domain_is_around_the_scenes_mu_as_before():
    """alpha' in [alpha/4, 4 alpha] widened to 1.25 past alpha'(mu_start = 0.3) (docs/stand-b.md)."""
    domain = _stand(0.8, {}).law_domain(B_OVER_A)
    assert domain.alpha == pytest.approx((min(0.8 / 4, 0.3 / 1.25) * ALPHA_PER_MU, 4 * 0.8 * ALPHA_PER_MU), rel=1e-12)
    assert _stand(0.6, {}).law_domain(B_OVER_A).alpha != domain.alpha


def test_with_the_effect_every_mu_of_the_range_gets_the_same_domain_covering_the_range():
    effect = {"law_mu_range": {"mu_low": 0.5, "mu_high": 1.0}}
    domains = {_stand(mu, effect).law_domain(B_OVER_A) for mu in (0.5, 0.63, 0.8, 1.0)}
    assert len(domains) == 1
    (domain,) = domains
    assert domain.alpha == pytest.approx((0.5 / 4 * ALPHA_PER_MU, 4.0 * ALPHA_PER_MU), rel=1e-12)  # alpha'(0.5)/4 .. 4 alpha'(1)
    assert domain.l_over_a == (-8.0, 8.0) and domain.c_over_a[1] == pytest.approx(70.2 * math.sin(0.2) / 4.0)


@pytest.mark.parametrize("mu, effect, field", [
    (0.4, {"mu_low": 0.5, "mu_high": 1.0}, "mu"),
    (1.1, {"mu_low": 0.5, "mu_high": 1.0}, "mu"),
    (0.8, {"mu_low": 0.9, "mu_high": 0.7}, "law_mu_range.mu_high"),
    (0.8, {"mu_low": 0.01}, "law_mu_range.mu_low"),
])
def test_a_mu_outside_the_range_or_a_reversed_range_is_a_named_error(mu, effect, field):
    with pytest.raises(ParameterError) as caught:
        _stand(mu, {"law_mu_range": effect})
    assert caught.value.name == field
