"""Coverage of rig fit's 95 % intervals and the false "needs Psi" rate, on stand-A scenes unlike the built-in ones.

    python benchmarks/bench_fit_coverage.py --mode model --psi 1.3 --seeds 50
    python benchmarks/bench_fit_coverage.py --mode model --psi 1.0 --seeds 50
    python benchmarks/bench_fit_coverage.py --mode twin --psi 1.3 --seeds 20

Scene: stand A (the yoke, fig10's procedure) with R_x = --radius-x (default 20 mm, the smallest the
stand takes), loads --loads (default 150 and 300 N), --points per load, --gate [s], grid --n (default
16), true mu --mu (default 0.5: alpha' ~ 6-13, [Koziarski] eq. (21)) and Psi --psi. Two modes:
* twin: every seed is simulated and reduced (rig.runner.run_scene) and fitted from its reduced.csv:
  the whole chain, instruments, reduction and fit (minutes per seed);
* model: one twin run gives the points (l/a, loads, calibration record, zero-drift ages), then each
  seed draws y = f(theta_true) + e with e ~ N(0, V) from the fit's own error model (independent u,
  the calibration's sensitivity and offset, the random-walk drift) and fits it: the statistics
  alone (interval coverage, the LR decision's false-positive rate) at a fraction of the cost.
Each seed fits --params mu,psi; reported: mu and Psi inside their 95 % profile intervals, the LR
decision (mu + psi taken at p < 0.01), the misfit flag; totals with Clopper-Pearson 95 % bounds and
the number of seeds. Never imports a private name of rig; never asserts.
"""

from __future__ import annotations

import argparse
import re
import tempfile
import time
from importlib import resources
from pathlib import Path

import numpy as np
from scipy.stats import beta

from rig.fit import fit_data
from rig.fit.choice import decide, rank_models
from rig.fit.data import Observations
from rig.fit.engine import FitConvergenceError
from rig.fit.forward import ForwardModel
from rig.fit.parameters import parse_names
from rig.fit.run import goodness_of, load_data
from rig.runner import run_scene
from rig.scenes.load import parse_scene

MU = 0.5  # default true mu (--mu)


def scene_text(*, mu: float, psi: float, seed: int, radius_x: float, loads: tuple[float, float], points: int,
               gate_s: float, n: int) -> str:
    """fig10.toml with R_x, loads, mu, Psi, seed, points per load, gate and grid changed."""
    text = resources.files("rig.scenes.builtin").joinpath("fig10.toml").read_text(encoding="utf-8")
    effects = f"\neffects = {{ psi = {psi!r} }}" if psi != 1.0 else ""
    for pattern, new in (
        (r"(?m)^mu = [0-9.]+", f"radius_x_m = {radius_x!r}\nmu = {mu!r}"),
        (r"(?m)^seed = [0-9]+", f"seed = {seed}"),
        (r"(?m)^n = [0-9]+ ", f"n = {n} "),
        (r"(?m)^table_points = \[21, 3, 5\]", f"table_points = [21, 3, 5]{effects}"),
        (r"(?m)^gate_time_s = [0-9.]+", f"gate_time_s = {gate_s!r}"),
        (r"num = 24", f"num = {points}"),
        (r"normal_force_N = 96.2", f"normal_force_N = {loads[0]!r}"),
        (r"normal_force_N = 385.0", f"normal_force_N = {loads[1]!r}"),
    ):
        text, count = re.subn(pattern, new, text)
        if count < 1:
            raise RuntimeError(f"fig10.toml changed: {pattern!r} not found")
    return text


def draw_errors(obs: Observations, truth: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """One draw of e ~ N(0, V): independent u, the calibration (at the true y) and the zero drift."""
    e = obs.u_independent * rng.standard_normal(obs.size)
    common = obs.common
    if common is None:
        return e
    g = common.low_rank(truth)
    if g is not None:
        e = e + g @ rng.standard_normal(g.shape[1])
    if common.walk is not None and common.walk.rate > 0:
        ages = common.walk.ages
        levels, group = np.unique(ages, return_inverse=True)
        steps = np.diff(np.concatenate([[0.0], levels])) * common.walk.rate
        z = np.cumsum(np.sqrt(steps) * rng.standard_normal(levels.size))
        e = e + common.walk.loadings * z[group]
    return e


def one_model_seed(obs: Observations, truth: np.ndarray, seed: int, mu: float, psi: float, profile: bool) -> dict:
    """One seed of model mode: y = the truth at the run's rolling points l plus e ~ N(0, V)
    (draw_errors), fitted at rolling points measured as the reduction measures them, l + u_l N(0, 1)
    (the counters' error, which the fit counts as errors in l: a draw without it is quieter than the
    fit assumes)."""
    rng = np.random.default_rng(seed)
    y = truth + draw_errors(obs, truth, rng)
    measured_l = obs.l + obs.u_l * rng.standard_normal(obs.size)
    x = measured_l if np.array_equal(obs.x, obs.l) else obs.x
    drawn = Observations(**{**obs.__dict__, "y": y, "l": measured_l, "x": x})
    free = parse_names(["mu", "psi"])
    models = rank_models(drawn, free, {}, {p.name: p.start for p in free}, profile=profile, polish="never")
    return summarise(models, mu, psi)


def summarise(models, mu: float, psi: float) -> dict:
    full = models[-1].result
    mu_e, psi_e = full.estimate("mu"), full.estimate("psi")
    return dict(mu=mu_e.value, mu_covered=mu_e.lo95 <= mu <= mu_e.hi95, psi=psi_e.value,
                psi_covered=psi_e.lo95 <= psi <= psi_e.hi95, needs_psi="psi" in decide(models).label,
                lr_p=models[-1].lr_p, misfit=goodness_of(full).misfit)


def bounds(k: int, m: int) -> str:
    lo = beta.ppf(0.025, k, m - k + 1) if k > 0 else 0.0
    hi = beta.ppf(0.975, k + 1, m - k) if k < m else 1.0
    return f"{k}/{m} = {k / m:.1%} (95 % CI {lo:.1%}-{hi:.1%})"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", choices=("model", "twin"), default="model")
    parser.add_argument("--psi", type=float, default=1.3)
    parser.add_argument("--seeds", type=int, default=50)
    parser.add_argument("--first-seed", type=int, default=5000)
    parser.add_argument("--radius-x", type=float, default=0.02)
    parser.add_argument("--mu", type=float, default=MU)
    parser.add_argument("--loads", type=float, nargs=2, default=(150.0, 300.0))
    parser.add_argument("--points", type=int, default=12)
    parser.add_argument("--gate", type=float, default=10.0)
    parser.add_argument("--n", type=int, default=16)
    parser.add_argument("--no-profile", action="store_true", help="decision only (intervals from the covariance)")
    args = parser.parse_args()
    rows, failed = [], 0
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="bench_fit_coverage_") as tmp:
        kw = dict(mu=args.mu, psi=args.psi, radius_x=args.radius_x, loads=tuple(args.loads), points=args.points,
                  gate_s=args.gate, n=args.n)
        if args.mode == "model":
            text = scene_text(seed=args.first_seed - 1, **kw)
            run_scene(parse_scene(text, name="coverage_points", source="bench_fit_coverage"), Path(tmp) / "run",
                      progress=False)
            obs = load_data(Path(tmp) / "run" / "reduced.csv")
            held = {"psi": args.psi} if args.psi != 1.0 else {}
            truth = ForwardModel(obs, parse_names(["mu"]), held).predict([args.mu])
            alpha = args.mu * obs.alpha_per_mu
            print(f"points: {obs.size}, alpha' {alpha.min():.2f}-{alpha.max():.2f}, l/a {obs.x.min():.2f}-"
                  f"{obs.x.max():.2f}", flush=True)
        for k in range(args.seeds):
            seed = args.first_seed + k
            try:
                if args.mode == "model":
                    r = one_model_seed(obs, truth, seed, args.mu, args.psi, not args.no_profile)
                else:
                    out = Path(tmp) / f"run_{seed}"
                    run_scene(parse_scene(scene_text(seed=seed, **kw), name=f"coverage_{seed}",
                                          source="bench_fit_coverage"), out, progress=False)
                    report = fit_data(out / "reduced.csv", ["mu", "psi"], profile=not args.no_profile)
                    r = summarise(report.models, args.mu, args.psi)
            except FitConvergenceError as error:
                failed += 1
                print(f"seed {seed}: fit failed ({error}); counted as not covered", flush=True)
                continue
            rows.append(r)
            print(f"seed {seed}: mu {r['mu']:.4f} covered {r['mu_covered']}, psi {r['psi']:.3f} covered "
                  f"{r['psi_covered']}, needs psi {r['needs_psi']} (LR p {r['lr_p']:.2g}), misfit {r['misfit']}",
                  flush=True)
    m = len(rows) + failed
    print(f"stand A, R_x = {args.radius_x} m, loads {args.loads} N, {args.points} points per load, gate {args.gate} s, "
          f"n = {args.n}, mu = {args.mu}, Psi = {args.psi}; mode {args.mode}; {m} seeds ({failed} failed fits); "
          f"{time.perf_counter() - t0:.0f} s")
    if not args.no_profile:
        print(f"mu inside its 95 % interval:  {bounds(sum(r['mu_covered'] for r in rows), m)}")
        print(f"Psi inside its 95 % interval: {bounds(sum(r['psi_covered'] for r in rows), m)}")
    label = "false 'needs Psi' (null data)" if args.psi == 1.0 else "'needs Psi' found (power)"
    print(f"{label}: {bounds(sum(r['needs_psi'] for r in rows), m)}")
    print(f"misfit warnings: {bounds(sum(r['misfit'] for r in rows), m)}")


if __name__ == "__main__":
    main()
