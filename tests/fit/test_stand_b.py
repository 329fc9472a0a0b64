"""`rig fit` on a stand-B log (rig.fit.stand_b): Psi = 2.5 at 60 N, mu = 0.6, where eq. (33) has two roots.

The log (tests/fit/data/stand_b_psi25_log.h5) is the twin run of tests/fit/data/stand_b_psi25.toml
(seed 28, 0.5 s gates), stored so that the test needs the fit only; its truth group is the
simulation's, which the fit never reads.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import rig.cli
from rig.fit import fit_data
from rig.fit.run import load_data
from rig.fit.stand_b import QUANTITY, StandBObservations, load_stand_b_run
from rig.logbook.truth import read_truth

DATA = Path(__file__).parent / "data"
LOG = DATA / "stand_b_psi25_log.h5"
MU, PSI = 0.6, 2.5  # the scene's truth (its [parameters] and [contact] effects)


@pytest.fixture(scope="module")
def observations():
    return load_stand_b_run(LOG)


def test_readings_are_the_instruments_within_their_u_of_the_truth(observations):
    obs = observations
    assert isinstance(load_data(LOG), StandBObservations)  # rig fit's loading takes the log to stand B's loader
    assert obs.size == 3 * 7 and set(obs.quantity) == set(QUANTITY.values())
    truth = read_truth(LOG)
    a = 0.004  # roller half length [m] (docs/stand-b.md)
    for channel, quantity in QUANTITY.items():
        rows = obs.quantity == quantity
        points = obs.point[rows]
        f_n = 60.0
        true = truth.loc[points, f"{channel}_{'N_m' if channel == 'T_Mo' else 'N'}"].to_numpy()
        true = true / (a * f_n if channel == "T_Mo" else f_n)
        assert np.all(np.abs(obs.y[rows] - true) < 4 * obs.u[rows]), channel


def test_fit_recovers_mu_and_psi_within_their_intervals(tmp_path):
    # intervals +-1.96 u from the covariance (profile=False) to keep the test short: on this log the profile
    # intervals are mu [0.5893, 0.6104], psi [2.4754, 2.5308] (benchmarks/bench_fit_coverage_standb.py uses them)
    report = fit_data(LOG, ["mu", "psi"], profile=False)
    full = report.full
    for name, true in (("mu", MU), ("psi", PSI)):
        e = full.estimate(name)
        assert e.lo95 <= true <= e.hi95, (name, e)
        assert not (e.open_lo or e.open_hi)
    assert full.estimate("psi").hi95 - full.estimate("psi").lo95 < 0.5  # Psi is observable here
    assert report.best.label == "mu + psi" and report.models[-1].lr_p < 1e-6  # mu alone does not fit
    assert report.models[0].result.chi2 > 100 * full.chi2


def test_cli_fits_a_stand_b_reduced_csv_with_its_log(tmp_path, capsys):
    folder = tmp_path / "run"
    folder.mkdir()
    shutil.copyfile(LOG, folder / "log.h5")
    (folder / "reduced.csv").write_text("point\n0\n")  # the readings come from the log beside it
    code = rig.cli.main(["fit", str(folder / "reduced.csv"), "--params", "mu", "--no-plot", "-o",
                         str(tmp_path / "fit"), "--effects", f"psi={PSI}"])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "stand B" in out and math.isfinite(float(out.split("mu ")[1].split()[0]))
