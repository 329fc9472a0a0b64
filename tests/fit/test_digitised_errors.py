"""A digitised curve's own errors: u of x carried to y (effective variance), a misfit widened by the Birge ratio."""

from __future__ import annotations

import numpy as np
import pytest

from rig.contact.solve import solve
from rig.fit import fit_data
from rig.fit.run import MISFIT_WARNING
from tests.fit.test_cli import _small_curve


def test_u_of_x_enters_as_df_dx_times_sigma_x(tmp_path):
    """u_eff^2 = sigma^2 + (dnu_v/dalpha' sigma_x)^2 with the slope from two direct solves at the fitted Psi."""
    data = _small_curve(tmp_path)
    sigma, sigma_x = 0.01, 0.5
    report = fit_data(data, ["psi"], sigma=sigma, sigma_x=sigma_x)
    obs, psi = report.obs, report.full.estimate("psi").value
    i = int(np.argmax(obs.x < 20))  # a point where nu_v still changes with alpha'
    kw = dict(shape=obs.contact.shape, b_over_a=1.0, c_over_a=0.0, l_over_a=0.0, poisson=obs.contact.poisson,
              n=obs.contact.n, **({"psi": psi} if psi != 1.0 else {}))
    h = 0.05
    up, down = (solve("kinematic", alpha=obs.x[i] + step, **kw).nu_v for step in (h, -h))
    slope = (up - down) / (2 * h)
    assert abs(slope) * sigma_x > 0.2 * sigma  # the test point has an x error that matters
    assert report.full.u_eff[i] ** 2 == pytest.approx(sigma**2 + (slope * sigma_x) ** 2, rel=0.05)


def test_a_misfit_of_a_guessed_u_is_widened_by_the_birge_ratio(tmp_path):
    data = _small_curve(tmp_path)
    report = fit_data(data, ["psi"], sigma=2e-4)  # far below the curve's own difference from the model
    full = report.full
    assert report.goodness.misfit and report.warnings[0].startswith(MISFIT_WARNING)
    assert full.birge == pytest.approx(np.sqrt(full.chi2 / full.dof), rel=1e-12) and full.birge > 1
    assert any("Birge ratio" in w for w in report.warnings)
    plain = fit_data(data, ["psi"], sigma=2e-4, extra_scatter=0.0)  # a named extra scatter: no widening
    assert plain.full.birge == 1.0
    e, p = full.estimate("psi"), plain.full.estimate("psi")
    assert e.u == pytest.approx(p.u * full.birge, rel=1e-6)
