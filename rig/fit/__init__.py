"""``rig fit``: calibrate the contact model to measurements (docs/fit.md).

    from rig.fit import fit_data
    report = fit_data("docs/examples/exact_pure_spin_circle.csv", params=["psi"], sigma=0.01)
    report.best.estimate("psi"), report.models
"""

from rig.fit.run import FitReport, fit_data

__all__ = ["FitReport", "fit_data"]
