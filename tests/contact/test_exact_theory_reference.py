"""The kinematic model against Kalker's exact theory (CONTACT, an independent program).

Reference: tests/contact/data/exact_pure_spin_circle.csv (+ .toml): pure spin of a circular Hertz
contact, nu = 0.28, nu_v and nu_0 versus alpha' (issue 5, acceptance 2, at the model level; the
`rig compare` path is tested in tests/compare).
"""

from pathlib import Path

import numpy as np
import pytest

from rig.contact.solve import solve

DATA = Path(__file__).parent / "data" / "exact_pure_spin_circle.csv"


def _reference():
    rows = [line.split(",") for line in DATA.read_text().splitlines()[2:] if line.strip()]
    values = np.array([[float(v) for v in row] for row in rows])
    return values[:, 0], values[:, 1], values[:, 3]


@pytest.fixture(scope="module")
def deviations():
    alpha, nu_v, nu_0 = _reference()
    ours = [solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=a, c_over_a=0.0, l_over_a=0.0, poisson=0.28)
            for a in alpha]
    return (np.array([r.nu_v for r in ours]) - nu_v, np.array([r.nu_0 for r in ours]) - nu_0)


def test_longitudinal_force_within_0_03_of_exact_theory(deviations):
    assert np.max(np.abs(deviations[0])) <= 0.03


def test_pivoting_loss_within_0_02_of_exact_theory(deviations):
    assert np.max(np.abs(deviations[1])) <= 0.02
