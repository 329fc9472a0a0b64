"""Coverage of `rig fit`'s 95 % intervals for mu and Psi on stand-B twin runs at Psi = 2.5.

For each seed the stand-B scene (default tests/fit/data/stand_b_psi25.toml: 60 N, mu = 0.6, Psi = 2.5,
seven points) is run with that seed - new noise and new calibration-weight errors - without the
reduction (the fit reads the readings), then `rig fit --params mu,psi` is run on the log; the
script counts how often each profile-likelihood interval contains the truth, and how often the
model choice prefers mu + Psi (AIC) with its LR p-value. Coverage is stated with the number of
seeds and its binomial 95 % interval (Clopper-Pearson).

    python benchmarks/bench_fit_coverage_standb.py --seeds 20 [--scene FILE] [--out DIR]

Cost: about 1-2 min of one core per seed on the default scene (direct solves on n = 8).
tests/fit/test_stand_b_coverage.py runs the same function on one seed.
"""

from __future__ import annotations

import argparse
import re
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from scipy.stats import beta

from rig.fit import fit_data
from rig.runner import run_scene
from rig.scenes.load import parse_scene

DEFAULT_SCENE = Path(__file__).resolve().parents[1] / "tests" / "fit" / "data" / "stand_b_psi25.toml"
TRUTH = {"mu": 0.6, "psi": 2.5}


@dataclass(frozen=True)
class SeedResult:
    """One seed: estimates and 95 % intervals of mu and Psi, whether they cover the truth, the model chosen."""

    seed: int
    estimates: dict[str, tuple[float, float, float]]
    covered: dict[str, bool]
    best: str
    lr_p: float


def scene_with_seed(text: str, seed: int) -> str:
    """The scene text with ``seed = <seed>`` and no reduction (the fit needs the log only)."""
    text = re.sub(r"(?m)^seed\s*=\s*\d+", f"seed = {seed}", text)
    return text + "\n[outputs]\nreduce = false\nfigures = false\n"


def one_seed(scene_text: str, seed: int, folder: Path, truth: dict[str, float] = TRUTH,
             profile: bool = True) -> SeedResult:
    """Run the scene with ``seed`` into ``folder`` and fit mu, psi to its log (profile: the profile-likelihood
    intervals, as `rig fit` reports them; False: +-1.96 u from the covariance, faster)."""
    scene = parse_scene(scene_with_seed(scene_text, seed), name=f"coverage_seed_{seed}", source="coverage")
    run_scene(scene, folder, progress=False)
    report = fit_data(folder / "log.h5", ["mu", "psi"], profile=profile)
    estimates, covered = {}, {}
    for name, true in truth.items():
        e = report.full.estimate(name)
        estimates[name] = (e.value, e.lo95, e.hi95)
        covered[name] = e.lo95 <= true <= e.hi95
    return SeedResult(seed, estimates, covered, report.best.label, report.models[-1].lr_p)


def clopper_pearson(k: int, n: int, level: float = 0.95) -> tuple[float, float]:
    """Exact binomial interval of a proportion k/n [1]."""
    a = (1.0 - level) / 2.0
    lo = 0.0 if k == 0 else float(beta.ppf(a, k, n - k + 1))
    hi = 1.0 if k == n else float(beta.ppf(1.0 - a, k + 1, n - k))
    return lo, hi


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=20, help="number of seeds (default 20)")
    parser.add_argument("--first-seed", type=int, default=1000)
    parser.add_argument("--scene", type=Path, default=DEFAULT_SCENE)
    parser.add_argument("--out", type=Path, default=None, help="keep the runs here (default: a temporary folder)")
    args = parser.parse_args(argv)
    text = args.scene.read_text(encoding="utf-8")
    results = []
    with tempfile.TemporaryDirectory() as scratch:
        base = args.out or Path(scratch)
        for seed in range(args.first_seed, args.first_seed + args.seeds):
            r = one_seed(text, seed, base / f"seed_{seed}")
            results.append(r)
            line = "  ".join(f"{k} {v[0]:.4f} [{v[1]:.4f}, {v[2]:.4f}]{'' if r.covered[k] else ' MISSED'}"
                             for k, v in r.estimates.items())
            print(f"seed {seed}: {line}  best: {r.best} (LR p {r.lr_p:.2g})", flush=True)
    n = len(results)
    print(f"\nstand B, {args.scene.name}: truth mu = {TRUTH['mu']}, Psi = {TRUTH['psi']}; {n} seeds")
    for name in TRUTH:
        k = sum(r.covered[name] for r in results)
        lo, hi = clopper_pearson(k, n)
        print(f"coverage of the 95 % interval of {name}: {k}/{n} = {k / n:.0%} (binomial 95 %: {lo:.0%}-{hi:.0%})")
    chosen = sum(r.best == "mu + psi" for r in results)
    print(f"mu + psi ranked first (AIC): {chosen}/{n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
