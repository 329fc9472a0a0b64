"""The coverage study in small (benchmarks/bench_fit_coverage.py, model mode): data drawn from the
fit's own error model at a small stand-A run's points with Psi = 1 (null data), fitted with mu and
Psi free. Two fixed seeds, without the profiles (intervals +-1.96 u; the profiles cost minutes
under load): mu's interval holds the truth, the decision does not call for Psi and the goodness of
fit does not flag a misfit. (The full study's numbers, with profiles: docs/fit.md.)"""

from __future__ import annotations

import pytest

from rig.fit.data import Observations
from rig.fit.forward import ForwardModel
from rig.fit.parameters import parse_names
from rig.fit.run import load_data
from tests.fit.conftest import SMALL_STATIC_RATIO_RUN

@pytest.fixture(scope="module")
def study():
    from benchmarks import bench_fit_coverage

    return bench_fit_coverage


def test_null_data_seeds(study, static_ratio_run):
    """The run's points (l/a, c/a, loads, u, shared errors) with its static ratio left out of the model:
    null data of the plain contact, as the benchmark draws them. Its Psi-node tables are then those of
    tests/fit/test_goodness.py's and test_recovery.py's fits (same R_x, grid and table, Psi the only
    effect): loaded from the session's cache folder, not built a second time with static_ratio 1.4."""
    run = load_data(static_ratio_run / "reduced.csv")
    obs = Observations(**{**run.__dict__, "fixed_effects": {}})
    mu = SMALL_STATIC_RATIO_RUN["mu"]
    truth = ForwardModel(obs, parse_names(["mu"]), {}).predict([mu])
    for seed in (1, 2):
        r = study.one_model_seed(obs, truth, seed, mu, 1.0, False)
        assert r["mu_covered"] and r["psi_covered"], r
        assert not r["needs_psi"] and not r["misfit"], r
