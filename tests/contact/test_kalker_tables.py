"""Kalker's table (independent source) against the stored table derived with this package's full-stick
solver (a file comparison; tests/contact/test_linear_tables.py re-runs the solver itself)."""

import csv
from importlib import resources

import numpy as np
import pytest

from rig.contact.kalker import creep_coefficients, kalker_coefficients


def _rows(name):
    text = resources.files("rig.contact.data").joinpath(name).read_text()
    return list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))


KALKER = _rows("kalker_linear_coefficients.csv")


def test_koziarski_b_over_a_reads_kalkers_a_over_b_row():
    """b/a = 2 (contact long in the rolling direction) is Kalker's a/b = 2 row: C11 = 4.37 at nu = 0."""
    assert kalker_coefficients(2.0, 0.0).C11 == pytest.approx(4.37)
    assert kalker_coefficients(0.5, 0.0).C11 == pytest.approx(2.88)


@pytest.mark.parametrize("row", KALKER, ids=lambda r: f"a/b={r['a_over_b']},nu={r['nu']}")
def test_interpolation_returns_the_table_at_its_nodes(row):
    c = kalker_coefficients(float(row["a_over_b"]), float(row["nu"]))
    assert (c.C11, c.C22, c.C23) == pytest.approx((float(row["C11"]), float(row["C22"]), float(row["C23"])), rel=1e-4)


@pytest.mark.parametrize("row", KALKER, ids=lambda r: f"a/b={r['a_over_b']},nu={r['nu']}")
def test_derived_full_stick_coefficients_reproduce_kalkers_table(row):
    """The derived table (our solver, extrapolated to zero cell size) vs Kalker: C11, C22 within
    1 % (1.5 % at b/a = 10, the most elongated row), C23 within 3 % (issue 2's tolerances)."""
    b, nu = float(row["a_over_b"]), float(row["nu"])
    ours = creep_coefficients("ellipse", b, nu)  # C11..C23 are Kalker's; compare the derived file's
    derived = [r for r in _rows("derived_linear_coefficients.csv")
               if r["shape"] == "ellipse" and np.isclose(float(r["b_over_a"]), b) and float(r["nu"]) == nu][0]
    tolerance = {"C11": 0.015 if b > 5 else 0.01, "C22": 0.015 if b > 5 else 0.01, "C23": 0.03}
    for name, rel in tolerance.items():
        assert float(derived[name]) == pytest.approx(float(row[name]), rel=rel), name
    assert ours.C33 > 0.0


def test_interpolation_between_rows_and_poisson_values_is_monotone_where_the_table_is():
    values = [kalker_coefficients(b, 0.3).C11 for b in np.linspace(0.1, 10.0, 60)]
    assert np.all(np.diff(values) > 0), "C11 grows with b/a (Kalker's table)"
    assert kalker_coefficients(1.0, 0.1).C11 == pytest.approx(3.40 + (4.12 - 3.40) * 0.4, rel=0.02)
