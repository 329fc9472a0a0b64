"""Acceptance 3: Kalker's exact pure-spin curve (CONTACT, an independent program) needs no plastic slip.

Fitting Psi with the exact theory's nu_v(alpha') as data (u = 0.01, about the n = 16 grid error
of our model) must give a 95 % interval for Psi that contains 1 (elastic theory).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rig.fit import fit_data

REFERENCE = Path(__file__).resolve().parents[2] / "docs" / "examples" / "exact_pure_spin_circle.csv"


@pytest.fixture(scope="module")
def report():
    return fit_data(REFERENCE, ["psi"], sigma=0.01, datasets=["nu_v"])


def test_psi_interval_of_the_exact_theory_contains_one(report):
    psi = report.full.estimate("psi")
    assert psi.lo95 <= 1.0 <= psi.hi95
    assert psi.hi95 < 1.2  # and the data does bound it: Psi > 1.2 is excluded
    assert not report.full.warnings


def test_elastic_model_fits_the_exact_curve_within_u(report):
    full = report.full
    assert full.chi2 / full.dof < 1.5
    assert report.best.label.startswith("(all fixed")
    assert full.table_error < 0.2 * 0.01  # node interpolation checked against direct solves at the optimum
