"""Stand B's alpha' option "paper_alpha_range" (issue 15, item 3): the paper's stated alpha' on the contact."""

import math

import numpy as np
import pytest

from rig.errors import ParameterError
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.disc_roller.paper_alpha import PARAMETERS, paper_alpha_prime
from rig.stands.disc_roller.stand import DiscRollerStand

DEFAULTS = {name: value for name, (value, _unit) in PARAMETERS.items()}


def _alpha_law(l_over_a, c_over_a, alpha):
    """A stand-in law that returns alpha' itself (so the test sees what alpha' the contact gets)."""
    alpha = np.asarray(alpha, dtype=float)
    return np.stack([alpha, 0.0 * alpha, 0.0 * alpha])


def _stand(effects):
    return DiscRollerStand({}, effects, ContactSpec("rigid", None, 0.5), DriveMode.QUASI_STATIC,
                           law_factory=lambda b_over_a: _alpha_law)


def test_the_paper_range_ends_are_the_texts():
    """[Koziarski] section 3.2: alpha' ca. 100 at 9 N and ca. 1500 at 144 N; in between a power law, k = ln 15/ln 16."""
    assert paper_alpha_prime(DEFAULTS, 9.0) == pytest.approx(100.0)
    assert paper_alpha_prime(DEFAULTS, 144.0) == pytest.approx(1500.0)
    assert paper_alpha_prime(DEFAULTS, 36.0) == pytest.approx(100.0 * 4.0 ** (math.log(15) / math.log(16)))


def test_the_contact_runs_at_the_paper_alpha_with_the_effect_and_at_eq_21_without():
    """Equations §3.2: eq. (21) gives 10.6 / 42.6 at 9 / 144 N (mu = 0.8); the effect turns them into 100 / 1500,
    through the law, so the stand and the reduction (which computes eq. 21's alpha') evaluate the same thing."""
    hertz, paper = _stand({}), _stand({"paper_alpha_range": {}})
    for force, expected_hertz, expected_paper in ((9.0, 10.6, 100.0), (144.0, 42.6, 1500.0)):
        b_over_a = hertz.params.b_over_a(force)
        alpha = hertz.params.alpha_prime(force)
        assert alpha == pytest.approx(expected_hertz, abs=0.05)
        assert np.asarray(hertz.law(b_over_a)(0.0, 0.0, alpha))[0] == pytest.approx(alpha)
        assert np.asarray(paper.law(b_over_a)(0.0, 0.0, alpha))[0] == pytest.approx(expected_paper, rel=1e-9)
        assert paper.law(b_over_a).value_one(0.0, 0.0, alpha)[0] == pytest.approx(expected_paper, rel=1e-9)


def test_reversed_ends_are_a_named_error():
    with pytest.raises(ParameterError, match="force_high_N"):
        _stand({"paper_alpha_range": {"force_low_N": 144.0, "force_high_N": 9.0}})
