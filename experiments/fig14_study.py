"""What would explain [Koziarski]'s Figs. 14-15? Plastic slip (Psi > 1) against a pressure-dependent mu
(issue 10, acceptance 5; the findings are docs/findings-fig14.md).

    python experiments/fig14_study.py [-o out/fig14_study] [--repeats 20]

1. Runs the built-in scenes fig14 and fig15 (stand B, dynamic drive, instruments on) once, for the
   campaign's settings and each point's stated u of F_T, F_V, T_Mo, and checks the forward model
   (experiments/fig14_forward.py) against those runs' truth.
2. Statements: for Psi = 1 ... 3 and k = 0 ... 1 (mu = 0.8; with k, at p_ref = 1 MPa), the
   forward model at the paper's settings judged with rig.campaigns.disc_roller_figures' checks
   (load exponents p of |X| ~ F_N^p, load steps beyond 2u, growth with the distance of C), each
   with the runs' u.
3. Can Figs. 14-15 data tell them apart? Each model fitted (mu free) to the other's noise-free
   campaign: the chi2 of the best wrong fit is what separates them (both have two parameters,
   so it is the AIC difference), split by load, position and instrument; and --repeats noisy
   campaigns (Gaussian, the runs' u, independent) per truth fitted with mu, mu + Psi, mu + k.
Outputs in -o: study.txt (every number the findings quote), statements.csv, crossfit.csv,
repeats.csv and three figures (copied to docs/figures/fig14_study_*.png with --docs).
Never imported by rig.
"""

from __future__ import annotations

import argparse
import shutil
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from scipy.optimize import least_squares  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fig14_forward import CHANNELS, LOADS_N, POSITIONS_M, Campaign, ForwardModel  # noqa: E402

from rig.campaigns import disc_roller_figures as F  # noqa: E402
from rig.logbook.reduced import read_reduced  # noqa: E402

MU_TRUE = 0.8
PSI_VALUES = (1.0, 1.5, 2.0, 3.0)
K_VALUES = (0.25, 0.5, 0.75, 1.0)
BOUNDS = {"mu": (0.2, 2.0), "psi": (1.0, 3.0), "k": (0.0, 1.0)}
START = {"mu": 0.7, "psi": 1.5, "k": 0.3}
MODELS = {"mu": ("mu",), "mu+psi": ("mu", "psi"), "mu+k": ("mu", "k")}
FIGURES = {14: 0.0, 15: -2.0}  # figure -> c/a


# ------------------------------------------------------------------------------------------ data

def campaign_frame(out: Path, log) -> pd.DataFrame:
    """Points of the fig14 and fig15 runs (campaign_points: settings, readings, u, truth), made once."""
    from rig.cli import main as rig_main

    frames = []
    for name in ("fig14", "fig15"):
        folder = out / "runs" / name
        if not (folder / "summary.txt").is_file():
            t0 = time.perf_counter()
            status = rig_main(["run", name, "-o", str(folder)])
            if status != 0:
                raise SystemExit(f"rig run {name} ended with status {status}")
            log(f"rig run {name}: {time.perf_counter() - t0:.0f} s")
        log_path = folder / "log.h5"
        frames.append(F.campaign_points(read_reduced(log_path), log_path).assign(figure=int(name[3:])))
    points = pd.concat(frames, ignore_index=True)
    points["c_mm"] = (points["c_over_a"] * 4.0).round(3)
    # the forward model's order: c = 0 then -8 mm, loads, positions (Campaign.paper)
    points = points.sort_values(["c_mm", "normal_force_N", "l_mm"], ascending=[False, True, True])
    return points.reset_index(drop=True)


def check_campaign(points: pd.DataFrame, model: ForwardModel) -> None:
    c = model.campaign
    same = (np.allclose(points["normal_force_N"], c.force) and np.allclose(points["l_mm"] * 1e-3, c.l)
            and np.allclose(points["c_mm"] * 1e-3, c.c, atol=1e-6))
    if not same:
        raise SystemExit("the runs' operating points are not the forward model's campaign")


def with_values(points: pd.DataFrame, loads: dict[str, np.ndarray]) -> pd.DataFrame:
    """The points with the forward model's loads as the values (truth columns dropped), u kept."""
    frame = points.drop(columns=[c for c in points if c.startswith("true_")]).copy()
    for column in CHANNELS + ("M_C_N_m",):
        frame[column] = loads[column]
    return frame


# ------------------------------------------------------------------------------------------ fits

def fit(model: ForwardModel, y: np.ndarray, u: np.ndarray, names: tuple[str, ...], mask=None) -> dict:
    """Least squares of (y - f)/u over the points in ``mask`` for the free ``names`` (others off)."""
    mask = np.ones(y.size, dtype=bool) if mask is None else mask

    def residual(theta):
        values = dict(zip(names, theta))
        return ((y - model.vector(values["mu"], values.get("psi", 1.0), values.get("k", 0.0))) / u)[mask]

    lo = [BOUNDS[n][0] for n in names]
    hi = [BOUNDS[n][1] for n in names]
    best = None
    for start_mu in (0.5, 0.8, 1.2):  # a few starts: the chi2 surface in (mu, k) is curved
        x0 = [start_mu] + [START[n] for n in names[1:]]
        res = least_squares(residual, x0, bounds=(lo, hi), x_scale="jac", xtol=1e-10, ftol=1e-12)
        if best is None or res.cost < best.cost:
            best = res
    return dict(zip(names, best.x)) | {"chi2": float(2.0 * best.cost), "residual": residual(best.x),
                                       "n": int(mask.sum())}


def truth_vector(model: ForwardModel, truth: dict) -> np.ndarray:
    return model.vector(truth["mu"], truth.get("psi", 1.0), truth.get("k", 0.0))


# ------------------------------------------------------------------------------------------ parts

def statements(points: pd.DataFrame, model: ForwardModel) -> pd.DataFrame:
    """Part 2: the paper's three statements for each variant, per figure."""
    rows = []
    variants = [("elastic", dict(mu=MU_TRUE))] + [(f"Psi = {p:g}", dict(mu=MU_TRUE, psi=p)) for p in PSI_VALUES[1:]]
    variants += [(f"k = {k:g}", dict(mu=MU_TRUE, k=k)) for k in K_VALUES]
    for label, truth in variants:
        frame = with_values(points, model.loads(truth["mu"], truth.get("psi", 1.0), truth.get("k", 0.0)))
        mu0 = model.friction(truth["mu"], truth.get("k", 0.0))
        for figure, c_over_a in FIGURES.items():
            part = frame[np.isclose(frame["c_over_a"], c_over_a)]
            steps = F.load_steps(part)
            p = {c: F.load_exponents(part, c) for c in CHANNELS}
            rows.append(dict(
                variant=label, figure=figure,
                p_F_T_min=min(p["F_T_N"].values()), p_F_T_max=max(p["F_T_N"].values()),
                p_T_Mo_min=min(p["T_Mo_N_m"].values()), p_T_Mo_max=max(p["T_Mo_N_m"].values()),
                p_F_V_min=min(p["F_V_N"].values()), p_F_V_max=max(p["F_V_N"].values()),
                rises=sum(s == "rises" for s in steps.values()), drops=sum(s == "drops" for s in steps.values()),
                positions=len(steps),
                F_T_distance_min=F.distance_factors(part, "F_T_N").min(),
                F_T_distance_max=F.distance_factors(part, "F_T_N").max(),
                M_C_distance_min=F.distance_factors(part, "M_C_N_m").min(),
                M_C_distance_max=F.distance_factors(part, "M_C_N_m").max(),
                mu0_9N=mu0[model.campaign.force == 9.0][0], mu0_144N=mu0[model.campaign.force == 144.0][0],
                **{f"p_F_T_l{l * 1e3:+g}": p["F_T_N"].get((1, 1, _sigma(part), l * 1e3), np.nan) for l in POSITIONS_M},
            ))
    return pd.DataFrame(rows)


def _sigma(part: pd.DataFrame) -> float:
    return float(part["sigma_rad"].iloc[0])


def cross_fits(model: ForwardModel, u: np.ndarray, n_points: int) -> tuple[pd.DataFrame, dict]:
    """Part 3a: each model fitted to the other's noise-free campaign; chi2 of the wrong fit, and by subset."""
    rows, residual_maps = [], {}
    truths = [("psi", p) for p in (1.25, 1.5, 2.0, 2.5, 3.0)] + [("k", k) for k in (0.1, 0.2, 1 / 3, 0.5, 0.75, 1.0)]
    quantity = np.repeat(np.arange(3), n_points)
    force = np.tile(model.campaign.force, 3)
    c_zero = np.tile(model.campaign.c == 0.0, 3)
    subsets = {"all": None, "Fig. 14 only (c = 0)": c_zero, "Fig. 15 only (c/a = -2)": ~c_zero,
               "F_T only": quantity == 0, "F_V only": quantity == 1, "T_Mo only": quantity == 2,
               "9 + 144 N": np.isin(force, (9.0, 144.0)), "21 + 36 N": np.isin(force, (21.0, 36.0)),
               "36 + 144 N": np.isin(force, (36.0, 144.0))}
    for name, value in truths:
        truth = {"mu": MU_TRUE, name: value}
        y = truth_vector(model, truth)
        other = ("mu", "k") if name == "psi" else ("mu", "psi")
        elastic = fit(model, y, u, ("mu",))
        for label, mask in subsets.items():
            wrong = fit(model, y, u, other, mask)
            rows.append(dict(truth=f"{'Psi' if name == 'psi' else 'k'} = {value:.3g}", subset=label,
                             points=wrong["n"], wrong_model="mu+" + other[1],
                             chi2_wrong=wrong["chi2"], mu_wrong=wrong["mu"], effect_wrong=wrong[other[1]],
                             chi2_elastic=elastic["chi2"] if mask is None else np.nan))
            if mask is None:
                residual_maps[(name, value)] = wrong["residual"].reshape(3, n_points)
    return pd.DataFrame(rows), residual_maps


def relative_u(model: ForwardModel, fraction: float) -> np.ndarray:
    """u (3N,) = fraction x the largest |X| of each curve (figure, load, instrument) of the elastic
    campaign at mu = 0.8: a scatter stated relative to the curve, as a reader of the paper's plots sees it."""
    loads = model.loads(MU_TRUE)
    c = model.campaign
    out = []
    for column in CHANNELS:
        x = np.abs(loads[column])
        scale = np.empty_like(x)
        for key in set(zip(c.c, c.force)):
            curve = (c.c == key[0]) & (c.force == key[1])
            scale[curve] = x[curve].max()
        out.append(fraction * scale)
    return np.concatenate(out)


def repeats(model: ForwardModel, u: np.ndarray, count: int, label: str, seed: int = 14) -> pd.DataFrame:
    """Part 3b: noisy campaigns (independent Gaussian errors of standard deviation u) per truth, three models each."""
    rng = np.random.default_rng(seed)
    rows = []
    for name, truth in (("Psi = 2", dict(mu=MU_TRUE, psi=2.0)), ("k = 1/3", dict(mu=MU_TRUE, k=1 / 3)),
                         ("k = 0.5", dict(mu=MU_TRUE, k=0.5)), ("elastic", dict(mu=MU_TRUE))):
        clean = truth_vector(model, truth)
        for r in range(count):
            y = clean + u * rng.standard_normal(u.size)
            fits = {m: fit(model, y, u, names) for m, names in MODELS.items()}
            aic = {m: f["chi2"] + 2 * len(MODELS[m]) for m, f in fits.items()}
            rows.append(dict(scatter=label, truth=name, repeat=r, first=min(aic, key=aic.get),
                             **{f"chi2 {m}": f["chi2"] for m, f in fits.items()},
                             **{f"aic {m}": a for m, a in aic.items()},
                             psi=fits["mu+psi"]["psi"], k=fits["mu+k"]["k"], mu_psi=fits["mu+psi"]["mu"],
                             mu_k=fits["mu+k"]["mu"]))
    return pd.DataFrame(rows)


# ------------------------------------------------------------------------------------------ figures

def draw_exponents(table: pd.DataFrame, path: Path) -> None:
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    l_mm = np.array(POSITIONS_M) * 1e3
    for ax, figure in zip(axes, FIGURES):
        for _, row in table[table["figure"] == figure].iterrows():
            style = "-" if row["variant"].startswith("k") else "--" if row["variant"].startswith("Psi") else "k-"
            ax.plot(l_mm, [row[f"p_F_T_l{l:+g}"] for l in l_mm], style, marker="o", ms=3, label=row["variant"])
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.axhspan(-0.1, 0.3, color="tab:green", alpha=0.12, lw=0)
        ax.set_title(f"Fig. {figure} settings (c/a = {FIGURES[figure]:g})")
        ax.set_xlabel("l [mm]")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("load exponent p of |F_T| ~ F_N^p, 9 -> 144 N")
    axes[1].legend(fontsize=7, ncol=2)
    axes[0].text(-19, 0.1, "paper: 'insensitive' (p < 0.3)", fontsize=8, color="tab:green")
    fig.suptitle("Stand B forward model, mu = 0.8 (with k: at 1 MPa): how fast |F_T| grows with the load")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def draw_curves(model: ForwardModel, points: pd.DataFrame, path: Path) -> None:
    variants = (("elastic (Psi = 1, k = 0)", dict(mu=MU_TRUE)), ("Psi = 3", dict(mu=MU_TRUE, psi=3.0)),
                ("k = 1", dict(mu=MU_TRUE, k=1.0)))
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.5), sharex=True)
    l_mm = np.array(POSITIONS_M) * 1e3
    n = len(POSITIONS_M)
    for col, (label, truth) in enumerate(variants):
        loads = model.loads(truth["mu"], truth.get("psi", 1.0), truth.get("k", 0.0))
        for row, column in enumerate(("F_T_N", "T_Mo_N_m")):
            ax = axes[row, col]
            for j, force in enumerate(LOADS_N):
                sl = slice(j * n, (j + 1) * n)  # Fig. 14 block (c = 0) comes first
                ax.plot(l_mm, loads[column][sl], "o-", ms=3, label=f"{force:g} N")
            ax.grid(alpha=0.3)
            ax.set_title(f"{label}: {'F_T [N]' if row == 0 else 'T_Mo [N m]'}", fontsize=9)
            if row == 1:
                ax.set_xlabel("l [mm]")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("Fig. 14's settings (c = 0): the forward model's F_T and T_Mo versus l per load")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def draw_crossfit(maps: dict, path: Path, n_points: int) -> None:
    cases = (("psi", 2.0, "data: Psi = 2; fitted: mu + k"), ("k", 1 / 3, "data: k = 1/3; fitted: mu + Psi"))
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.8), gridspec_kw=dict(hspace=0.35, wspace=0.08))
    n = len(POSITIONS_M)
    labels = [f"{f:g} N, c/a {c}" for c in ("0", "-2") for f in LOADS_N]
    for row, (name, value, title) in enumerate(cases):
        residual = maps[(name, value)]
        limit = max(3.0, float(np.abs(residual).max()))
        for q, channel in enumerate(("F_T", "F_V", "T_Mo")):
            ax = axes[row, q]
            image = ax.imshow(residual[q].reshape(8, n), cmap="RdBu_r", vmin=-limit, vmax=limit, aspect="auto")
            ax.set_xticks(range(n), [f"{l * 1e3:g}" for l in POSITIONS_M], fontsize=7)
            ax.set_yticks(range(8), labels if q == 0 else [], fontsize=7)
            ax.set_title(f"{title}: {channel}, (data - fit)/u", fontsize=8)
            ax.set_xlabel("l [mm]", fontsize=8)
        fig.colorbar(image, ax=axes[row].tolist(), shrink=0.8)
    fig.suptitle("Where Figs. 14-15 data separate plastic slip from a pressure-dependent mu (noise-free data; u = 1 % of each curve's largest |X|)")
    fig.savefig(path, dpi=120)
    plt.close(fig)


# ------------------------------------------------------------------------------------------ main

def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-o", "--out", type=Path, default=Path("out/fig14_study"))
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--docs", action="store_true", help="copy the figures to docs/figures/")
    args = parser.parse_args(argv)
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    lines: list[str] = []

    def log(text: str) -> None:
        print(text, flush=True)
        lines.append(text)

    t_start = time.perf_counter()
    points = campaign_frame(out, log)
    t0 = time.perf_counter()
    model = ForwardModel(Campaign.paper(), out / "coefficients.npz", log)
    log(f"forward model ready: {time.perf_counter() - t0:.1f} s")
    check_campaign(points, model)
    n = model.campaign.size
    u = np.concatenate([points[f"u_{c}"].to_numpy() for c in CHANNELS])
    elastic = model.loads(MU_TRUE)
    log("forward model vs the runs' truth (their surrogate table, 25 x 9 x 5 nodes) at mu = 0.8, in u:")
    for c in CHANNELS:
        dev = (elastic[c] - points[f"true_{c}"].to_numpy()) / points[f"u_{c}"].to_numpy()
        log(f"  {c}: max |forward - truth|/u = {np.abs(dev).max():.2f}, median {np.median(np.abs(dev)):.2f}")
    log("u of the runs: " + ", ".join(f"{c} {points[f'u_{c}'].min():.3g} .. {points[f'u_{c}'].max():.3g}"
                                      for c in CHANNELS))

    t0 = time.perf_counter()
    table = statements(points, model)
    table.to_csv(out / "statements.csv", index=False)
    log(f"\nstatements ({time.perf_counter() - t0:.1f} s): p = load exponent of |X| ~ F_N^p, 9 -> 144 N; "
        "rises = positions where |F_T| rises beyond 2u at every load step; distance = far/near |l|")
    with pd.option_context("display.width", 250, "display.max_columns", 30, "display.precision", 2):
        log(table.drop(columns=[c for c in table if c.startswith("p_F_T_l")]).to_string(index=False))
    draw_exponents(table, out / "fig14_study_exponents.png")
    draw_curves(model, points, out / "fig14_study_curves.png")

    t0 = time.perf_counter()
    u1 = relative_u(model, 0.01)
    crossfit, maps = cross_fits(model, u1, n)
    crossfit.to_csv(out / "crossfit.csv", index=False)
    log(f"\ncross fits, noise-free ({time.perf_counter() - t0:.1f} s), u = 1 % of each curve's largest |X|: chi2 of "
        "the wrong model's best fit (= its AIC excess over the true model, which fits exactly); it scales as "
        "1/u^2, so the scatter at which it falls to 10 (AIC excess 10: no longer a clear choice) is "
        "1 % x sqrt(chi2/10), given second in [%]")
    crossfit["scatter_limit_percent"] = np.sqrt(crossfit["chi2_wrong"] / 10.0)
    with pd.option_context("display.width", 250, "display.max_columns", 30, "display.precision", 3):
        log(crossfit.pivot(index="truth", columns="subset", values="chi2_wrong").to_string())
        log(crossfit.pivot(index="truth", columns="subset", values="scatter_limit_percent").to_string())
        log(crossfit[crossfit["subset"] == "all"][["truth", "wrong_model", "mu_wrong", "effect_wrong",
                                                   "chi2_elastic"]].to_string(index=False))
    for (name, value), residual in maps.items():
        contribution = residual**2
        by_load = {f: contribution[:, np.isclose(model.campaign.force, f)].sum() for f in LOADS_N}
        by_l = {l * 1e3: contribution[:, np.isclose(model.campaign.l, l)].sum() for l in POSITIONS_M}
        by_q = dict(zip(("F_T", "F_V", "T_Mo"), contribution.sum(axis=1)))
        log(f"  where chi2 of the wrong fit comes from, truth {name} = {value:.3g}: by load "
            + ", ".join(f"{f:g} N {v:.1f}" for f, v in by_load.items()) + "; by l [mm] "
            + ", ".join(f"{l:g} {v:.1f}" for l, v in by_l.items()) + "; by instrument "
            + ", ".join(f"{q} {v:.1f}" for q, v in by_q.items()))
    draw_crossfit(maps, out / "fig14_study_crossfit.png", n)

    for label, scale in (("the twin's instruments (the runs' u)", u), ("3 % of each curve's largest |X|", 3 * u1),
                         ("10 %", 10 * u1), ("30 %", 30 * u1)):
        wrong = [fit(model, truth_vector(model, t), scale, other)["chi2"] for t, other in
                 ((dict(mu=MU_TRUE, psi=2.0), ("mu", "k")), (dict(mu=MU_TRUE, k=1 / 3), ("mu", "psi")))]
        log(f"  scatter {label}: chi2 of the wrong fit, Psi = 2 data fitted with mu + k {wrong[0]:.4g}, "
            f"k = 1/3 data fitted with mu + Psi {wrong[1]:.4g}")

    t0 = time.perf_counter()
    noisy = pd.concat([repeats(model, scale, args.repeats, label) for label, scale in
                       (("3 %", 3 * u1), ("10 %", 10 * u1), ("30 %", 30 * u1))], ignore_index=True)
    noisy.to_csv(out / "repeats.csv", index=False)
    log(f"\nnoisy campaigns ({args.repeats} per truth and scatter, independent Gaussian, {time.perf_counter() - t0:.0f} s):"
        " model ranked first by AIC")
    for (scatter, label), rows in noisy.groupby(["scatter", "truth"], sort=False):
        counts = rows["first"].value_counts().reindex(list(MODELS), fill_value=0)
        log(f"  scatter {scatter}, truth {label}: " + ", ".join(f"{m} {int(v)}/{len(rows)}" for m, v in counts.items())
            + f"; Psi fitted {rows['psi'].mean():.3f} +- {rows['psi'].std():.3f}, k fitted "
            f"{rows['k'].mean():.3f} +- {rows['k'].std():.3f}; median chi2 " + ", ".join(
                f"{m} {rows[f'chi2 {m}'].median():.0f}" for m in MODELS) + f" (N = {3 * n})")
    log(f"\ntotal run time {time.perf_counter() - t_start:.0f} s (shared 2-core machine)")
    (out / "study.txt").write_text("\n".join(lines) + "\n")
    if args.docs:
        docs = Path(__file__).resolve().parents[1] / "docs" / "figures"
        for name in ("exponents", "curves", "crossfit"):
            shutil.copyfile(out / f"fig14_study_{name}.png", docs / f"fig14_study_{name}.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
