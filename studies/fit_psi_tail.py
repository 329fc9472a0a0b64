"""Why `rig fit`'s Psi scatters in whole-chain (twin) coverage runs twice as widely as in a draw of F_y's errors alone.

    python studies/fit_psi_tail.py --seeds 40 --profile 5012 5000 5021

Each seed's stand-A scene is benchmarks/bench_fit_coverage.py's (R_x = 20 mm, loads 150 and 300 N,
8 points per load, 5 s gates, n = 16, mu = 0.5, Psi = 1.3); it is simulated and reduced
(rig.runner.run_scene) and its reduced.csv, whose truth columns give each point's true l/a, is
fitted for mu and Psi as rig fit does it (rank_models; table law, no polish, no profile: the
estimate bench_fit_coverage.py's twin mode reports) in five variants that take the error chain apart:

* twin: the reduced data as they are (measured l/a and F_y);
* true l/a: the measured F_y at the true l/a (the rolling point's error removed);
* l/a error only: noise-free F_y = f(mu, Psi) at the true l/a, fitted at the measured l/a;
* model: F_y drawn from the fit's own error model (independent u, calibration, zero drift:
  bench_fit_coverage.py's draw_errors) at the true l/a, fitted at the true l/a;
* model + l/a draw: the same, fitted at l/a = true + u(l/a) z, z ~ N(0, 1), the error the
  fit's effective variance assumes (rig.fit.engine), as bench_fit_coverage.py's model mode draws it.
Printed per seed, then per variant the median, standard deviation and the seeds above 1.34, and
the measured l/a errors in units of the reduction's u(l/a); --coverage adds, for the two model
variants, how often Psi = 1.3 is inside the 95 % profile interval. --profile SEED ...: chi2(Psi) - min
(mu minimised) over Psi = 1-1.6 for those seeds, twin and true l/a, with Psi held at each value
(the stand's table at that exact Psi, no interpolation between the fit's Psi nodes). Uses public names of rig
only; --keep DIR keeps (and reuses) the runs.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.util
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.optimize import minimize_scalar

from rig.fit.choice import rank_models
from rig.fit.engine import Objective
from rig.fit.forward import ForwardModel
from rig.fit.parameters import parse_names
from rig.fit.run import load_data
from rig.runner import run_scene
from rig.scenes.load import parse_scene

MU, PSI = 0.5, 1.3
TAIL = 1.34
FREE = parse_names(["mu", "psi"])
VARIANTS = ("twin", "true l/a", "l/a error only", "model", "model + l/a draw")


def bench_module():
    """benchmarks/bench_fit_coverage.py (its scene and its model-mode error draw), loaded from the checkout."""
    path = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_fit_coverage.py"
    spec = importlib.util.spec_from_file_location("bench_fit_coverage", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def reduced_run(bench, seed: int, root: Path) -> Path:
    out = root / f"run_{seed}"
    if not (out / "reduced.csv").exists():
        text = bench.scene_text(mu=MU, psi=PSI, seed=seed, radius_x=0.02, loads=(150.0, 300.0), points=8,
                                gate_s=5.0, n=16)
        run_scene(parse_scene(text, name=f"coverage_{seed}", source="fit_psi_tail"), out, progress=False)
    return out / "reduced.csv"


def psi_of(obs, intervals: bool = False) -> tuple[float, float, bool | None]:
    """(Psi, chi2, Psi inside its 95 % profile interval or None) of the mu + Psi fit as rig fit does
    it (rig.fit.choice.rank_models: the better of two starts, the default one and the mu-only
    optimum at Psi = 1), without polish; the profile only when ``intervals``."""
    models = rank_models(obs, FREE, {}, {p.name: p.start for p in FREE}, profile=intervals, polish="never")
    e = models[-1].result.estimate("psi")
    return e.value, models[-1].result.chi2, (e.lo95 <= PSI <= e.hi95) if intervals else None


def profile(obs, memo, grid: np.ndarray) -> np.ndarray:
    """chi2(Psi) with mu minimised (the fit's objective: effective variance, common errors); Psi is
    held, so each value is the stand's table at that exact Psi (rig.fit.forward)."""
    out = []
    for psi in grid:
        model = ForwardModel(obs, parse_names(["mu"]), {"psi": float(psi)}, memo)
        objective = Objective(model, 0.0)
        res = minimize_scalar(lambda mu: float(np.sum(objective.residual(np.array([mu])) ** 2)),
                              bounds=(0.4, 0.6), method="bounded", options={"xatol": 1e-7})
        out.append(res.fun)
    return np.array(out)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=40)
    parser.add_argument("--first-seed", type=int, default=5000)
    parser.add_argument("--keep", type=Path, help="directory for the runs (reused when there)")
    parser.add_argument("--profile", type=int, nargs="*", default=[], help="seeds whose Psi profile to print")
    parser.add_argument("--coverage", action="store_true",
                        help="also count Psi inside its 95 %% profile interval for the two model variants (slower)")
    args = parser.parse_args()
    bench = bench_module()
    with tempfile.TemporaryDirectory(prefix="fit_psi_tail_") as tmp:
        root = args.keep or Path(tmp)
        root.mkdir(parents=True, exist_ok=True)
        estimates = {v: [] for v in VARIANTS}
        chi2s = {v: [] for v in VARIANTS}
        covered = {v: [] for v in VARIANTS}
        dofs = []
        z_all, z_means = [], []
        seeds = sorted(set(range(args.first_seed, args.first_seed + args.seeds)) | set(args.profile))
        print("seed   " + "  ".join(f"{v:>16s}" for v in VARIANTS) + "   (Psi (chi2))")
        for seed in seeds:
            path = reduced_run(bench, seed, root)
            obs = load_data(path)
            obs = dataclasses.replace(obs, fixed_effects={k: v for k, v in obs.fixed_effects.items() if k != "psi"})
            true_l = pd.read_csv(path)["true_l_over_a"].to_numpy(dtype=float)
            at_true = dataclasses.replace(obs, l=true_l, x=true_l)
            memo: dict = {}
            exact = ForwardModel(at_true, FREE, {}, memo).predict([MU, PSI])
            rng = np.random.default_rng(seed)
            drawn = exact + bench.draw_errors(at_true, exact, rng)
            l_drawn = true_l + obs.u_l * rng.standard_normal(obs.size)
            variants = {
                "twin": obs,
                "true l/a": at_true,
                "l/a error only": dataclasses.replace(obs, y=exact),
                "model": dataclasses.replace(at_true, y=drawn),
                "model + l/a draw": dataclasses.replace(at_true, y=drawn, l=l_drawn, x=l_drawn),
            }
            row = {v: psi_of(o, args.coverage and v.startswith("model")) for v, o in variants.items()}
            z = (obs.l - true_l) / obs.u_l
            if seed in range(args.first_seed, args.first_seed + args.seeds):
                for v in VARIANTS:
                    estimates[v].append(row[v][0])
                    chi2s[v].append(row[v][1])
                    covered[v].append(row[v][2])
                dofs.append(obs.size - len(FREE))
                z_all.extend(z)
                z_means.append(z.mean())
            print(f"{seed}  " + "  ".join(f"{row[v][0]:7.4f} ({row[v][1]:5.2f})" for v in VARIANTS)
                  + f"   mean l/a error {z.mean():+.2f} u", flush=True)
            if seed in args.profile:
                grid = np.round(np.arange(1.0, 1.6001, 0.025), 4)
                for label, o in (("twin", obs), ("true l/a", at_true)):
                    chi2 = profile(o, memo, grid)
                    print(f"  profile chi2(Psi) - min, {label}: "
                          + " ".join(f"{p:.3f}:{c:.1f}" for p, c in zip(grid, chi2 - chi2.min())), flush=True)
        print(f"\n{len(estimates['twin'])} seeds from {args.first_seed}; true mu = {MU}, Psi = {PSI}")
        for v in VARIANTS:
            e = np.array(estimates[v])
            if e.size:
                print(f"{v:>16s}: median {np.median(e):.4f}, mean {e.mean():.4f}, sd {e.std(ddof=1) if e.size > 1 else float('nan'):.4f}, "
                      f"{np.sum(e > TAIL)} above {TAIL}, max {e.max():.4f}; mean chi2 {np.mean(chi2s[v]):.1f} "
                      f"(mean dof {np.mean(dofs):.1f})"
                      + (f"; Psi inside its 95 % interval {sum(covered[v])}/{e.size}" if None not in covered[v] else ""))
        z_all = np.array(z_all)
        if z_all.size:
            print(f"l/a error / u(l/a), all points: mean {z_all.mean():+.3f}, sd {z_all.std(ddof=1):.3f}; "
                  f"per-seed means: sd {np.std(z_means, ddof=1) if len(z_means) > 1 else float('nan'):.3f} (independent errors: {1 / np.sqrt(16):.3f})")


if __name__ == "__main__":
    main()
