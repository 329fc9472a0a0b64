"""Stand A's campaigns: [Koziarski] Figs. 10 and 11, laid out like the paper's, with the checks they state.

Fig. 10: c = 0 (Delta h = 0); Fig. 11: Delta h = 1.06 mm, c/a = 0.4 - l/(87.7 a) (the caption).
Both: F_y [N], mu_T and mu_v [1] and T2 [N m] versus l/a for b/a = 1 and 2 (F_N = 96.2 and 385 N),
from a sweep of the brake set-point ([Koziarski] section 3.1.2). Reduced points (eqs. 29-35, the stand's
reduce_log) are drawn with error bars of k = 2 expanded uncertainty, the simulation's truth as lines.

Per point the campaign joins the reduced table with the log: settings (F_N, Delta h), the balance
reading T2 [N m], and the truth (F_y, T2, mu) when the log has one. b/a comes from F_N through the
reduction's own StandAGeometry.b_over_a (Equations §3.1); u(F_N) is the stand's normal_force_u_N
(read from the scene stored in the log); u(T2) is the reduced table's ``u_T2_N_m`` if it has one,
else the reduction's reading of the balance, +-0.0196 N m as a rectangular half width (docs/stand-a.md
section 7) - [R] our choice for the T2 error bars only (no check depends on it).

Checks (summary lines, numbers in them):
* agreement per b/a: the fraction of points with |reduced - true| <= 2u, per quantity;
* the paper's claim, "F_y is significantly affected by ... b/a" ([Koziarski] section 3.1.2): F_y and the
  load-normalised F_y/F_N of the largest b/a against the smallest at matched l/a - the smaller
  b/a's curve is interpolated linearly (in reduced l/a) to each point of the other; u adds the
  interpolated u, the point's u and slope x u(l/a) in quadrature (correlations between the two
  curves are ignored - conservative for the shared calibration, which scales both the same way);
  z = difference/u; the claim holds when |difference| > 2u (k = 2) at every matched l/a. F_y in N
  also carries the factor 4 in load; F_y/F_N isolates b/a [R];
* Fig. 11 only: c/a along the sweep against the caption's line 0.4 - l/(87.7 a), reduced (in units
  of u(c/a)) and true, with the straight line fitted to the truth.
"""

from __future__ import annotations

import math
import textwrap
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.campaigns import CampaignOutcome
from rig.errors import LogFormatError
from rig.logbook import read_metadata, read_readings, read_settings
from rig.logbook.truth import read_truth
from rig.stands.yoke.parameters import YokeParameters, resolve

K = 2.0  # coverage factor of the error bars and of the agreement test [1]
CAPTION_C_OVER_A_AT_L0 = 0.4  # Fig. 11 caption: c/a = 0.4 - l/(87.7 a) [1]
CAPTION_L_SCALE = 87.7  # [1] (Equations §2: l1 - l2 = 87.7 Delta h)
QUANTITIES = {  # column -> label in the summary (each with u_<column>; truth as true_<column>)
    "l_over_a": "l/a", "c_over_a": "c/a", "F_y_N": "F_y", "mu_v": "mu_v", "mu_T": "mu_T", "T2_N_m": "T2",
}
TRUTH_FROM_LOG = {"F_y_N": "F_y_N", "T2_N_m": "T2_N_m"}  # campaign column -> truth column of the log


def _scene_parameters(log_path: Path) -> YokeParameters:
    """The stand's resolved parameters of the run (the scene text stored in the log)."""
    scene = tomllib.loads(read_metadata(log_path).scene_toml)
    return resolve(scene.get("parameters", {}))


def _truth(log_path: Path) -> pd.DataFrame | None:
    try:
        return read_truth(log_path)
    except LogFormatError:
        return None  # a real stand's log: no truth


def campaign_points(reduced: pd.DataFrame, log_path: Path) -> pd.DataFrame:
    """One row per reduced point (index ``point``): F_N [N], Delta h [m], b/a [1], the reduced
    quantities with u, T2 [N m] with u, F_y/F_N [1] with u, and ``true_*`` where the log has truth."""
    params = _scene_parameters(log_path)
    settings = read_settings(log_path).reindex(reduced.index)
    readings = read_readings(log_path).reindex(reduced.index)
    points = reduced.copy()
    points["normal_force_N"] = settings["normal_force_N"].to_numpy(dtype=float)
    points["delta_h_m"] = settings["delta_h_m"].to_numpy(dtype=float)
    points["b_over_a"] = [params.geometry.b_over_a(f) for f in points["normal_force_N"]]
    if not {"T2_N_m", "u_T2_N_m"} <= set(reduced.columns):  # the balance reading, the reduction's convention
        points["T2_N_m"] = readings["T2_N_m"].to_numpy(dtype=float)
        points["u_T2_N_m"] = params.geometry.balance_moment_half_width / math.sqrt(3.0)
    f_n, u_fn = points["normal_force_N"], params.normal_force_u_N
    points["F_y_per_F_N"] = points["F_y_N"] / f_n
    points["u_F_y_per_F_N"] = np.hypot(points["u_F_y_N"] / f_n, points["F_y_N"] * u_fn / f_n**2)
    truth = _truth(log_path)
    if truth is not None:
        for column, source in TRUTH_FROM_LOG.items():
            points[f"true_{column}"] = truth[source].reindex(reduced.index).to_numpy(dtype=float)
        points["true_F_y_per_F_N"] = points["true_F_y_N"] / f_n
    return points


def _groups(points: pd.DataFrame) -> list[tuple[float, pd.DataFrame]]:
    """(b/a, its points sorted by reduced l/a), b/a ascending."""
    rounded = points["b_over_a"].round(6)
    return [(float(b), points[rounded == b].sort_values("l_over_a")) for b in sorted(rounded.unique())]


def agreement_line(b_over_a: float, group: pd.DataFrame) -> str:
    """'b/a = 1, within 2u of the truth: l/a 24/24, F_y 24/24, ...' - per quantity, the points with
    |reduced - true| <= K u out of those with a finite value, truth and u > 0."""
    parts = []
    for column, label in QUANTITIES.items():
        if f"true_{column}" not in group or f"u_{column}" not in group:
            continue
        value, u, true = (group[c].to_numpy(dtype=float) for c in (column, f"u_{column}", f"true_{column}"))
        usable = np.isfinite(value) & np.isfinite(true) & np.isfinite(u) & (u > 0)
        if not usable.any():
            continue
        within = int((np.abs(value[usable] - true[usable]) <= K * u[usable]).sum())
        left = int((~usable).sum())
        parts.append(f"{label} {within}/{int(usable.sum())}" + (f" ({left} NaN or u = 0)" if left else ""))
    if not parts:
        return f"b/a = {b_over_a:g}: no truth in the log, agreement not checked"
    return f"b/a = {b_over_a:g}, within {K:g}u of the truth: " + ", ".join(parts)


@dataclass(frozen=True)
class Contrast:
    """A quantity of the larger b/a minus the smaller one's at matched l/a.

    n: matched points; l_range: their reduced l/a span [1]; high, low: medians of the two values;
    difference, u: median difference and its median standard uncertainty (unit of ``column``);
    z_median, z_min: of z = difference/u over the matched points, signed so that the median
    difference counts positive (z_min > K: the same sign and beyond K u at every matched l/a).
    """

    column: str
    b_low: float
    b_high: float
    n: int
    l_range: tuple[float, float]
    high: float
    low: float
    difference: float
    u: float
    z_median: float
    z_min: float

    @property
    def beyond_uncertainty(self) -> bool:
        """|difference| > K u at every matched l/a (one sign throughout)."""
        return self.n > 0 and self.z_min > K


def matched_contrast(low: pd.DataFrame, high: pd.DataFrame, column: str, b_low: float,
                     b_high: float) -> Contrast | None:
    """``column`` of ``high`` (points at b/a = b_high) minus ``low``'s (b/a = b_low), interpolated at
    each high point's l/a (module docstring); None when no point of ``high`` lies inside ``low``'s
    l/a span."""
    cols = ["l_over_a", "u_l_over_a", column, f"u_{column}"]
    low = low[cols].dropna().sort_values("l_over_a").drop_duplicates("l_over_a")
    high = high[cols].dropna()
    x, u_x, y, u_y = (low[c].to_numpy(dtype=float) for c in cols)
    if x.size < 2:
        return None
    inside = high[(high["l_over_a"] >= x[0]) & (high["l_over_a"] <= x[-1])]
    if inside.empty:
        return None
    xh, u_xh, yh, u_yh = (inside[c].to_numpy(dtype=float) for c in cols)
    right = np.clip(np.searchsorted(x, xh), 1, x.size - 1)
    left = right - 1
    w = (xh - x[left]) / (x[right] - x[left])
    slope = (y[right] - y[left]) / (x[right] - x[left])
    y_low = (1.0 - w) * y[left] + w * y[right]
    u_low = np.hypot((1.0 - w) * u_y[left], w * u_y[right])
    u_l = np.hypot(u_xh, np.hypot((1.0 - w) * u_x[left], w * u_x[right]))
    diff = yh - y_low
    u = np.sqrt(u_yh**2 + u_low**2 + (slope * u_l) ** 2)
    sign = 1.0 if np.median(diff) >= 0 else -1.0
    z = sign * diff / u
    return Contrast(column, b_low, b_high, int(xh.size), (float(xh.min()), float(xh.max())), float(np.median(yh)),
                    float(np.median(y_low)), float(np.median(diff)), float(np.median(u)),
                    float(np.median(z)), float(z.min()))


def contrast_lines(points: pd.DataFrame) -> tuple[list[str], list[Contrast]]:
    """Summary lines of the b/a contrast of F_y and F_y/F_N, and the contrasts themselves."""
    groups = _groups(points)
    if len(groups) < 2:
        found = ", ".join(f"{b:g}" for b, _ in groups) or "none"
        return [f"b/a contrast of F_y: needs two b/a values, the run has {found}"], []
    (b_low, low), (b_high, high) = groups[0], groups[-1]
    lines, found = [], []
    for column, unit, fmt in (("F_y_N", " N", ".3g"), ("F_y_per_F_N", "", ".4f")):
        c = matched_contrast(low, high, column, b_low, b_high)
        if c is None:
            lines.append(f"{column}: no point of b/a = {b_high:g} inside the l/a span of b/a = {b_low:g}")
            continue
        found.append(c)
        lines.append(
            f"{column} at matched l/a ({c.n} points, l/a {c.l_range[0]:.2f} .. {c.l_range[1]:.2f}): b/a = "
            f"{b_high:g} {c.high:{fmt}}{unit} vs b/a = {b_low:g} {c.low:{fmt}}{unit}, difference "
            f"{c.difference:{fmt}} +- {c.u:.2g}{unit} (u, k = 1), z median {c.z_median:.1f}, min {c.z_min:.1f}")
    normalised = next((c for c in found if c.column == "F_y_per_F_N"), None)
    if normalised is not None:
        verdict = "holds" if normalised.beyond_uncertainty else "is NOT shown"
        lines.append(f"paper's claim (F_y depends strongly on b/a at fixed c/a) {verdict}: F_y/F_N differs by more "
                     f"than {K:g}u at {'every' if normalised.beyond_uncertainty else 'not every'} matched l/a "
                     f"(ratio {normalised.high / normalised.low:.2f}; F_y itself {_ratio(found):.2f}x at "
                     f"{b_high / b_low:.0f}x b/a and {(b_high / b_low) ** 2:.0f}x load)")
    return lines, found


def _ratio(found: list[Contrast]) -> float:
    force = next((c for c in found if c.column == "F_y_N"), None)
    return math.nan if force is None or force.low == 0 else force.high / force.low


def caption_line(l_over_a):
    """Fig. 11 caption: c/a = 0.4 - l/(87.7 a) [1] at l/a [1]."""
    return CAPTION_C_OVER_A_AT_L0 - np.asarray(l_over_a, dtype=float) / CAPTION_L_SCALE


def caption_lines(points: pd.DataFrame) -> list[str]:
    """c/a along the sweep against the caption's line: reduced (|dev|, in u) and true (|dev|, fit)."""
    lines = []
    red = points[["l_over_a", "c_over_a", "u_c_over_a"]].dropna()
    if not red.empty:
        dev = np.abs(red["c_over_a"] - caption_line(red["l_over_a"]))
        u = red["u_c_over_a"]
        in_u = f" (max {(dev[u > 0] / u[u > 0]).max():.2f} u)" if (u > 0).any() else ""
        lines.append(f"c/a vs caption 0.4 - l/(87.7 a), reduced: {len(red)} points, max |dev| {dev.max():.2g}{in_u}, "
                     f"c/a {red['c_over_a'].min():.4f} .. {red['c_over_a'].max():.4f}")
    if {"true_l_over_a", "true_c_over_a"} <= set(points.columns):
        true = points[["true_l_over_a", "true_c_over_a"]].dropna()
        dev = true["true_c_over_a"] - caption_line(true["true_l_over_a"])
        text = f"c/a vs caption, truth: max |dev| {np.abs(dev).max():.2g}"
        if len(true) >= 2 and np.ptp(true["true_l_over_a"]) > 0:
            slope, intercept = np.polyfit(true["true_l_over_a"], true["true_c_over_a"], 1)
            text += f"; fit c/a = {intercept:.4f} - l/({-1.0 / slope:.2f} a) (caption: 0.4, 87.7)"
        lines.append(text)
    return lines


MU_SERIES = (("mu_T", "s", r"$\mu_T$"), ("mu_v", "o", r"$\mu_v$"))  # (column, marker, label) of the mu panel


def _truth_series(group: pd.DataFrame, column: str) -> list[tuple[str, str]]:
    """(column, label) of the truth lines of a panel; one line when mu_T and mu_v are the same truth."""
    if "true_l_over_a" not in group:
        return []
    if column != "mu":
        return [(column, "")] if f"true_{column}" in group else []
    names = [name for name, _, _ in MU_SERIES if f"true_{name}" in group]
    if len(names) == 2 and np.allclose(group["true_mu_T"], group["true_mu_v"], equal_nan=True):
        return [("mu_T", r"$\mu_T = \mu_v$")]
    return [(name, label) for name, _, label in MU_SERIES if name in names]


def _draw(points: pd.DataFrame, path: Path, title: str, with_c_over_a: bool) -> None:
    """The figure: panels F_y, mu_T and mu_v, T2 (and c/a) versus l/a; one colour per b/a."""
    from rig.plotting import colors, new_figure

    panels = [("F_y_N", "$F_y$ [N]"), ("mu", r"$\mu_T$, $\mu_v$ [1]"), ("T2_N_m", "$T_2$ [N m]")]
    if with_c_over_a:
        panels.append(("c_over_a", "$c/a$ [1]"))
    fig = new_figure(figsize=(6.4, 2.6 * len(panels) + 0.8))
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)
    axes = axes[:, 0]
    colors = colors()
    for k, (b, group) in enumerate(_groups(points)):
        color, tag = colors[k % len(colors)], f"b/a = {b:g} ($F_N$ = {group['normal_force_N'].iloc[0]:g} N)"
        x, ux = group["l_over_a"].to_numpy(dtype=float), group["u_l_over_a"].to_numpy(dtype=float)
        order = group["true_l_over_a"].argsort().to_numpy() if "true_l_over_a" in group else None
        for ax, (column, _) in zip(axes, panels):
            series = MU_SERIES if column == "mu" else ((column, "o", ""),)
            for name, marker, label in series:
                y, u = group[name].to_numpy(dtype=float), group[f"u_{name}"].to_numpy(dtype=float)
                ax.errorbar(x, y, xerr=K * np.nan_to_num(ux), yerr=K * np.nan_to_num(u), fmt=marker, ms=3.5,
                            capsize=2, color=color, mfc="none" if name == "mu_T" else color, lw=0.8,
                            label=f"{label} reduced, {tag}".lstrip(" ,"))
            for name, label in _truth_series(group, column):
                ax.plot(group["true_l_over_a"].to_numpy()[order], group[f"true_{name}"].to_numpy()[order], "-",
                        color=color, alpha=0.6, lw=1.2, label=f"{label} truth, {tag}".lstrip(" ,"))
    if with_c_over_a:
        span = np.linspace(np.nanmin(points["l_over_a"]), np.nanmax(points["l_over_a"]), 2)
        axes[-1].plot(span, caption_line(span), "k--", lw=1, label="caption: 0.4 - l/(87.7 a)")
    mu_scale = (points["true_mu_T"] if "true_mu_T" in points else points["mu_v"]).dropna()
    mu_top = 2.5 * float(mu_scale.median()) if not mu_scale.empty else math.nan
    if math.isfinite(mu_top) and mu_top > 0:
        axes[1].set_ylim(0.0, mu_top)  # mu_T near l = 0 is not identifiable (D of eq. 35 -> 0): bars run off
    for ax, (_, label) in zip(axes, panels):
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=6, loc="best", title=f"error bars: {K:g}u (k = {K:g})" if ax is axes[0] else None,
                  title_fontsize=6)
    axes[-1].set_xlabel("$l/a$ [1]")
    fig.suptitle(textwrap.fill(title, 95), fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def _campaign(name: str, caption: str, reduced: pd.DataFrame, log_path, out_dir, title: str,
              with_c_over_a: bool) -> CampaignOutcome:
    log_path, out_dir = Path(log_path), Path(out_dir)
    points = campaign_points(reduced, log_path)
    figure = f"{name}.png"
    _draw(points, out_dir / figure, f"{title}\n[Koziarski] {caption}", with_c_over_a)
    groups = _groups(points)
    lines = [f"{name} ([Koziarski] {caption}): " + "; ".join(
        f"b/a = {b:g} (F_N = {g['normal_force_N'].iloc[0]:g} N): {len(g)} points, l/a "
        f"{g['l_over_a'].min():.2f} .. {g['l_over_a'].max():.2f}" for b, g in groups)]
    lines += [agreement_line(b, g) for b, g in groups]
    lines += contrast_lines(points)[0]
    if with_c_over_a:
        lines += caption_lines(points)
    return CampaignOutcome((figure,), tuple(lines))


def fig10(reduced: pd.DataFrame, log_path, out_dir, title: str) -> CampaignOutcome:
    """Fig. 10 (c = 0): ``out_dir``/fig10.png and the summary lines (rig.campaigns contract)."""
    return _campaign("fig10", "Fig. 10, c = 0", reduced, log_path, out_dir, title, False)


def fig11(reduced: pd.DataFrame, log_path, out_dir, title: str) -> CampaignOutcome:
    """Fig. 11 (Delta h = 1.06 mm): ``out_dir``/fig11.png with a c/a panel, and the summary lines."""
    return _campaign("fig11", "Fig. 11, c/a = 0.4 - l/(87.7 a)", reduced, log_path, out_dir, title, True)
