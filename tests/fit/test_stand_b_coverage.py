"""The stand-B coverage study (benchmarks/bench_fit_coverage_standb.py) on one seed: run, fit, intervals."""

from __future__ import annotations


def load_script():
    from benchmarks import bench_fit_coverage_standb

    return bench_fit_coverage_standb


def test_one_seed_covers_mu_and_psi(tmp_path):
    bench = load_script()
    text = bench.DEFAULT_SCENE.read_text(encoding="utf-8")
    assert "seed = 3" in bench.scene_with_seed(text, 3) and "reduce = false" in bench.scene_with_seed(text, 3)
    result = bench.one_seed(text, 1000, tmp_path / "seed", profile=False)
    assert not (tmp_path / "seed" / "reduced.csv").exists()  # the fit reads the log only
    assert result.covered == {"mu": True, "psi": True}, result.estimates
    assert result.best == "mu + psi"


def test_clopper_pearson_matches_the_binomial_tables():
    bench = load_script()
    lo, hi = bench.clopper_pearson(19, 20)  # 19/20: 75.1 % - 99.9 % (exact binomial interval)
    assert round(lo, 3) == 0.751 and round(hi, 3) == 0.999
    assert bench.clopper_pearson(0, 10)[0] == 0.0 and bench.clopper_pearson(10, 10)[1] == 1.0
