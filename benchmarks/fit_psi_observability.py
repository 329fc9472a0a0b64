"""How much Psi moves what stand A measures, at a run's own points and grid: is Psi observable there?

    python benchmarks/fit_psi_observability.py [--scene fig10] [--psi 1.3 1.6] [--run-dir DIR]

Simulates the scene once (or reads --run-dir, a finished stand-A run folder), loads its reduced
points as rig fit does (F_y/F_N = mu nu_v, [Koziarski] eq. (28), at the reduced l/a, with the log's
calibration and drift), and evaluates the model by direct contact solves at the scene's own grid n
with mu = the scene's and Psi = 1 and each --psi. Reports per load the largest change of F_y/F_N,
the points' median u (with the shared calibration) and point-to-point u, the chi2 that change
alone would add (r^T V^-1 r with the fit's covariance), and the chi2 left when mu alone (Psi = 1)
is fitted to noise-free data with that Psi: the expected LR statistic lambda of the "needs Psi"
test, whose power at p < 0.01 is P(Z + sqrt(lambda) > sqrt(5.41)) (one-sided, Z standard normal). A Psi
whose lambda is below ~4 cannot be told from the instruments' errors.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from scipy.stats import norm

from rig.fit.data import Observations
from rig.fit.engine import Objective, fit
from rig.fit.forward import ForwardModel
from rig.fit.parameters import parse_names
from rig.fit.run import load_data


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="fig10")
    parser.add_argument("--psi", type=float, nargs="+", default=[1.3, 1.6])
    parser.add_argument("--run-dir", type=Path, default=None)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="psi_observability_") as tmp:
        run_dir = args.run_dir
        if run_dir is None:
            run_dir = Path(tmp) / "run"
            subprocess.run([sys.executable, "-m", "rig", "run", args.scene, "-o", str(run_dir)], check=True,
                           capture_output=True)
        obs = load_data(run_dir / "reduced.csv")
    mu = float(obs.stand.params.mu)
    base = ForwardModel(obs, parse_names(["mu"]), {})
    f1 = base.direct([mu])
    weights = Objective(base, 0.0).weights(np.array([mu]), f1)
    alpha = mu * obs.alpha_per_mu
    print(f"{obs.source}: {obs.size} points, n = {obs.contact.n}, mu = {mu}, alpha' {alpha.min():.3g}-{alpha.max():.3g}")
    for psi in args.psi:
        f = ForwardModel(obs, parse_names(["mu"]), {"psi": psi}).direct([mu])
        change = f - f1
        white = weights(change)
        table = base.predict([mu])  # noise-free data with Psi: the table at Psi = 1 plus the direct change
        data = Observations(**{**obs.__dict__, "y": table + change})
        lam = fit(ForwardModel(data, parse_names(["mu"]), {}), [mu], profile=False, polish="never").chi2
        threshold = 5.4119  # chi-bar-squared: 0.5 P(chi2_1 > t) = 0.01
        power = float(norm.sf(np.sqrt(threshold) - np.sqrt(max(lam, 0.0))))  # one-sided: Z + sqrt(lambda) > sqrt(t)
        print(f"Psi 1 -> {psi}: chi2 of the change alone {white @ white:.3g} (with the shared calibration and drift); "
              f"left after refitting mu (lambda) {lam:.3g}: power of the LR test at p < 0.01 ~ {power:.0%}")
        for series in dict.fromkeys(obs.series):
            at = obs.series == series
            print(f"  {series}: max |change of F_y/F_N| {np.max(np.abs(change[at])):.2g}; median u "
                  f"{np.median(weights.u_total[at]):.2g}, point-to-point u {np.median(weights.u_eff[at]):.2g}")


if __name__ == "__main__":
    main()
