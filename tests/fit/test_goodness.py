"""Goodness of fit against the instruments' own noise: a model that misses an effect in the data warns.

The small stand-A run of conftest.py has static_ratio = 1.4 in its contact; fitted with the
static ratio held at 1 (--effects static_ratio=1) and only mu and Psi free, Psi absorbs part of
it but not all: chi2 against the instruments' stated u is far above its degrees of freedom
(measured: 42 for 8). The same run fitted with the effect it has is not flagged.
"""

from __future__ import annotations

from scipy.stats import chi2 as chi2_dist

from rig.cli import main as rig_main
from rig.fit.run import GOF_ALPHA, MISFIT_WARNING


def test_a_missing_effect_prints_the_misfit_warning_first(static_ratio_run, tmp_path, capsys):
    out = tmp_path / "out"
    status = rig_main(["fit", str(static_ratio_run / "reduced.csv"), "--params", "mu,psi", "--effects",
                       "static_ratio=1", "--no-plot", "-o", str(out)])
    printed = capsys.readouterr().out.splitlines()
    assert status == 0
    assert printed[1].startswith("WARNING: " + MISFIT_WARNING)
    summary = (out / "summary.txt").read_text().splitlines()
    assert summary[1].startswith("WARNING: " + MISFIT_WARNING)
    assert any("do not read it as evidence" in line for line in summary)


def test_the_right_model_is_not_flagged(static_ratio_run):
    """The threshold itself: p < 0.01 of chi2 with dof degrees of freedom (scipy, independent)."""
    from rig.fit import fit_data

    report = fit_data(static_ratio_run / "reduced.csv", ["mu"])  # the scene's static_ratio 1.4 is in the model
    g = report.goodness
    assert g.p == chi2_dist.sf(g.chi2, g.dof)
    assert g.p > GOF_ALPHA and not g.misfit, g
    assert not any(MISFIT_WARNING in w for w in report.warnings)
    assert abs(report.full.estimate("mu").value - 0.35) < 3 * report.full.estimate("mu").u
