"""
Compare with a reference, fit to a measurement
==============================================

Two things a researcher does with a result: hold it against independent numbers, and estimate a parameter from
data. First the contact model's pure-spin characteristics of a Hertz circle are compared with Kalker's exact theory
(a reference table shipped in ``docs/examples/``); then the friction coefficient is estimated back from a
simulated stand-A measurement with ``rig.fit.fit_data``, with its uncertainty.

Run it from the repository root (a few tens of seconds)::

    python experiments/compare_and_fit.py
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import rig
from rig.fit import fit_data

work = Path(tempfile.mkdtemp(prefix="compare-and-fit-"))
# the reference tables shipped in docs/examples/ (from the repository root, or from experiments/ where the gallery runs)
examples = next(folder for folder in (Path("docs/examples"), Path("../docs/examples")) if folder.is_dir())

# %%
# Compare with Kalker's exact theory
# ----------------------------------
# The built-in scene ``pure_spin`` sweeps alpha' for pure spin of a Hertz circle with the kinematic model
# (n = 32). ``Run.compare`` does what ``rig compare`` does: it interpolates the result at the reference's points
# and reports the deviations in the units of the reference's y axis ([Koziarski] eqs. (26)-(28): nu_v, nu_0).

spin = rig.run(rig.load_scene("pure_spin"), work / "pure_spin")
metrics = spin.compare(examples / "exact_pure_spin_circle.csv")
print(metrics[["dataset", "model", "n_compared", "rmse", "max_abs_dev", "x_at_max_abs_dev"]].round(4).to_string())

# %%
# The characteristics themselves (``Run.table`` is the result table as written): nu_0 falls with alpha', nu_v has
# a single maximum (Equations §1.10(c)).

table = spin.table
fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
ax.semilogx(table["alpha"], table["nu_v"], label="nu_v, kinematic model (n = 32)")
ax.semilogx(table["alpha"], table["nu_0"], label="nu_0, kinematic model (n = 32)")
ax.set(xlabel="alpha' [1], eq. (21)", ylabel="nu [1]", title="pure spin of a Hertz circle")
ax.legend()
plt.show()

# %%
# Fit mu to a measurement
# -----------------------
# A stand-A sweep simulated with mu = 0.45 plays the measurement. ``fit_data`` estimates mu from its
# ``reduced.csv`` (the same as ``rig fit out/.../reduced.csv --params mu``): the value, its standard uncertainty
# and a 95 % profile interval.

measured = rig.run(rig.load_scene("default").with_(mu=0.45), work / "measured")
report = fit_data(measured.folder / "reduced.csv", ["mu"])
for estimate in report.full.estimates:
    print(f"{estimate.name} = {estimate.value:.4f} +- {estimate.u:.4f} {estimate.unit}, "
          f"95 % interval [{estimate.lo95:.4f}, {estimate.hi95:.4f}]")

# %%
# The data and the fitted value: the reduced mu_T of each point and the estimate with its interval.

reduced = measured.reduced
best = report.full.estimates[0]
fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
ax.errorbar(reduced["l_over_a"], reduced["mu_T"], yerr=2 * reduced["u_mu_T"], fmt="o", capsize=3,
            label="reduced mu_T, +-2u")
ax.axhspan(best.lo95, best.hi95, color="C1", alpha=0.3, label="fitted mu, 95 % interval")
ax.axhline(0.45, color="grey", ls="--", label="mu of the simulation")
ax.set(xlabel="rolling point l/a [1]", ylabel="mu [1]", title="rig.fit.fit_data on a simulated stand-A sweep")
ax.legend()
plt.show()
