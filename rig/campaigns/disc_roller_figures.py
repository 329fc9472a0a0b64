"""Stand B's campaigns, [Koziarski] Figs. 14 (c = 0) and 15 (c/a = -2): forces and moment versus l.

Layout [ours, after the brief and the paper's legend "x---x T_Mo, o---o F_T, ---- F_V"]: four
panels versus l [mm], one colour per load - F_T [N] (markers o), F_V [N] (s), T_Mo [N m] (x)
as in the paper, and M_C = T_Mo + R_c F_T [N m] (D), the pivoting moment the chain derives
(Equations §3.2). Points: the calibrated channel means of the log (rig.stands.disc_roller
.reduction.channel_reading; M_C from the reduced table) with error bars of +-2u (k = 2).
Lines: the simulation's truth - the quasi-static steady state of the logged stand (rebuilt from
the scene text in the log) on a fine l grid; the dynamic gate means equal it within the settle
tolerance (the summary states the largest deviation). Without the scene the lines join the
logged truth. All values are in the reduction's canonical frame (forward running: F_T, T_Mo
times the direction; docs/stand-b.md), so a reverse run at sigma > 0 is drawn at c/a < 0.

Summary: per load the fraction of points within 2u of the truth, M_C recovered, and the
observations of [Koziarski] section 3.2.3 checked with numbers (what the simulation shows) - for the
run's alpha' and, from the same stand's truth (dashed lines in the figure), for the other alpha'
option: eq. (21)'s Hertz estimate or the paper's stated range (effect paper_alpha_range,
rig.stands.disc_roller.paper_alpha).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from rig.campaigns import CampaignOutcome
from rig.errors import LogFormatError, ParameterError
from rig.logbook import read_metadata, read_point, read_settings
from rig.logbook.truth import read_truth

PAPER_C_OVER_A = {"fig14": 0.0, "fig15": -2.0}  # captions of Figs. 14 and 15 [1]
COVERAGE = 2.0  # coverage factor k of the error bars and of "within 2u" [1]
FINE_POINTS = 97  # l nodes of a truth line [1]
SETTINGS = ("normal_force_N", "speed_step", "direction", "sigma_rad")  # one curve per combination
QUANTITIES = {  # column -> (short name, axis label, marker after the paper's legend)
    "F_T_N": ("F_T", r"peripheral force $F_T$ [N]", "o"),
    "F_V_N": ("F_V", r"longitudinal force $F_V$ [N]", "s"),
    "T_Mo_N_m": ("T_Mo", r"moment $T_{Mo}$ [N m]", "x"),
    "M_C_N_m": ("M_C", r"$M_C = T_{Mo} + R_c F_T$ [N m]", "D"),
}
CHANNELS = {"F_T_N": "F_T", "F_V_N": "F_V", "T_Mo_N_m": "T_Mo"}  # column -> log channel
MIRRORED = ("F_T_N", "T_Mo_N_m")  # change sign with the running direction (mirror x -> -x)
TRUTH = ("F_T_N", "F_V_N", "T_Mo_N_m", "M_C_N_m", "b_over_a", "alpha_prime", "mu")


def campaign_points(reduced: pd.DataFrame, log_path: Path) -> pd.DataFrame:
    """One row per reduced point: settings, l_mm [mm], c_over_a [1], F_T_N, F_V_N [N], T_Mo_N_m,
    M_C_N_m [N m] with u_<column> (standard uncertainties) and true_<column> when the log has truth."""
    from rig.stands.disc_roller.reduction import channel_reading

    _require_stand_b(log_path)
    settings = read_settings(log_path).loc[reduced.index]
    frame = settings[list(SETTINGS)].copy()
    frame["l_mm"] = settings["l_m"] * 1e3
    frame["c_over_a"] = reduced["c_over_a"]
    direction = settings["direction"].to_numpy()
    records = {int(i): read_point(log_path, int(i)) for i in reduced.index}
    for column, channel in CHANNELS.items():
        readings = [channel_reading(records[i], channel, f"{log_path}: point {i}") for i in records]
        sign = direction if column in MIRRORED else 1.0
        frame[column] = sign * np.array([r.value for r in readings])
        frame[f"u_{column}"] = [r.u for r in readings]
    frame["M_C_N_m"], frame["u_M_C_N_m"] = reduced["M_C_N_m"], reduced["u_M_C_N_m"]
    truth = _truth(log_path)
    if truth is not None:
        for column in TRUTH:
            sign = direction if column in MIRRORED else 1.0
            frame[f"true_{column}"] = sign * truth[column].reindex(reduced.index).to_numpy()
    return frame


def _require_stand_b(log_path: Path) -> None:
    stand = read_metadata(log_path).stand
    if stand != "disc_roller":
        raise ParameterError("outputs.paper_figure", f"a log of stand {stand!r}", "a stand-B (disc_roller) run")


def _truth(log_path: Path) -> pd.DataFrame | None:
    try:
        truth = read_truth(log_path)
    except LogFormatError:  # a real stand's log has no truth
        return None
    return truth if all(column in truth for column in TRUTH) else None


def series(points: pd.DataFrame) -> list[tuple[tuple, pd.DataFrame]]:
    """(settings key, rows sorted by l) per curve: one per combination of SETTINGS."""
    return [(key if isinstance(key, tuple) else (key,), rows.sort_values("l_mm"))
            for key, rows in points.groupby(list(SETTINGS), sort=True)]


def truth_curves(points: pd.DataFrame, log_path: Path, stand=None) -> tuple[dict[tuple, pd.DataFrame], str]:
    """Truth lines per curve key - l_mm [mm] and the QUANTITIES columns [N, N m] of the logged
    stand's quasi-static steady state (canonical frame), or of ``stand`` if given - and a note
    ("" or why the lines join the logged truth instead)."""
    if "true_F_T_N" not in points:
        return {}, "no truth in the log"
    stand, note = (stand, "") if stand is not None else _logged_stand(log_path)
    curves = {}
    for key, rows in series(points):
        if stand is None:
            curves[key] = rows[["l_mm"] + [f"true_{c}" for c in QUANTITIES]].set_axis(
                ["l_mm", *QUANTITIES], axis=1).reset_index(drop=True)
            continue
        l_mm = np.union1d(np.linspace(rows["l_mm"].min(), rows["l_mm"].max(), FINE_POINTS), rows["l_mm"])
        curves[key] = pd.DataFrame([_steady(stand, dict(zip(SETTINGS, key)), l) for l in l_mm])
    return curves, note


def _logged_scene(log_path: Path):
    """The stand scene the log stores, or (None, reason)."""
    from rig.scenes.load import parse_scene
    from rig.scenes.stand_scene import StandScene

    try:
        scene = parse_scene(read_metadata(log_path).scene_toml, name="logged", source=f"{log_path} (scene)")
    except ParameterError as error:
        return None, f"the log's scene cannot be rebuilt ({error}); lines join the logged truth"
    if not isinstance(scene, StandScene):
        return None, "the log's scene is not a stand scene; lines join the logged truth"
    return scene, ""


def _logged_stand(log_path: Path):
    """The stand the log's scene describes, or (None, reason)."""
    scene, note = _logged_scene(log_path)
    return (None, note) if scene is None else (scene.build_stand(), "")


def other_alpha_stand(log_path: Path):
    """The logged stand with the other alpha' option (effect paper_alpha_range toggled), or None."""
    import dataclasses

    from rig.stands.disc_roller.paper_alpha import EFFECT, PARAMETERS

    scene, _ = _logged_scene(log_path)
    if scene is None:
        return None
    effects = dict(scene.effects)
    if EFFECT in effects:
        del effects[EFFECT]
    else:
        effects[EFFECT] = {name: default for name, (default, _unit) in PARAMETERS.items()}
    return dataclasses.replace(scene, effects=effects).build_stand()


def alpha_option(stand) -> str:
    """Which alpha' a stand's contact runs at, in words."""
    from rig.stands.disc_roller.paper_alpha import EFFECT

    if EFFECT in stand.effects:
        e = stand.effects[EFFECT]
        return (f"the paper's stated alpha' range ({e['alpha_low']:g} .. {e['alpha_high']:g} for "
                f"{e['force_low_N']:g} .. {e['force_high_N']:g} N; effect {EFFECT})")
    return "eq. (21) with Hertz line contact (effect paper_alpha_range off)"


def alpha_values(stand, loads) -> str:
    """alpha' the stand's contact runs at per load [1], e.g. '9 N: 10.6, 144 N: 42.6'."""
    p = stand.params
    return ", ".join(f"{f:g} N: {p.alpha_prime(f, stand.friction(f)) * stand.alpha_factor(p.b_over_a(f)):.1f}" for f in sorted(set(loads)))


def steady_points(stand, points: pd.DataFrame) -> pd.DataFrame:
    """The quasi-static truth of ``stand`` at the points' settings as a points frame (values = truth)
    with the points' own u, so that the observation checks judge it with what the run's instruments
    resolve (a step below 2u is 'unresolved', not a drop)."""
    rows = [_steady(stand, {k: row[k] for k in SETTINGS}, row["l_mm"]) for _, row in points.iterrows()]
    frame = points[list(SETTINGS) + ["c_over_a", "l_mm"] + [f"u_{c}" for c in QUANTITIES]].copy()
    for column in QUANTITIES:
        frame[column] = [r[column] for r in rows]
    return frame


def _steady(stand, settings: dict, l_mm: float) -> dict[str, float]:
    """Quasi-static truth at l [mm] (canonical frame): F_T_N, F_V_N, T_Mo_N_m, M_C_N_m (= T0)."""
    from rig.stands.disc_roller.parameters import point_settings
    from rig.stands.disc_roller.steady_state import steady_state

    point = point_settings({**settings, "l_m": l_mm * 1e-3})
    state = steady_state(stand.drive_train(point), point.direction)
    d = point.direction
    return dict(l_mm=l_mm, F_T_N=d * state.contact.force_x, F_V_N=state.contact.force_y,
                T_Mo_N_m=d * state.momentometer_torque, M_C_N_m=state.contact.resisting_moment)


def _label(key: tuple, keys: list[tuple]) -> str:
    """Curve label: the load, plus the settings that differ between curves."""
    from rig.stands.disc_roller.parameters import ROLLER_SPEEDS_RPM

    varying = [i for i in range(1, len(SETTINGS)) if len({k[i] for k in keys}) > 1]
    extra = {1: lambda v: f"{ROLLER_SPEEDS_RPM[int(v) - 1]:g} rpm", 2: lambda v: f"direction {v:+g}",
             3: lambda v: f"sigma {v:.4g} rad"}
    return ", ".join([f"{key[0]:g} N"] + [extra[i](key[i]) for i in varying])


def _z(points: pd.DataFrame, column: str) -> np.ndarray:
    """|measured - true| / u per point (NaN where u is not positive or a value is missing)."""
    u = points[f"u_{column}"].to_numpy(dtype=float)
    error = np.abs(points[column].to_numpy(dtype=float) - points[f"true_{column}"].to_numpy(dtype=float))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(u > 0.0, error / u, np.nan)


def within(points: pd.DataFrame, column: str) -> tuple[int, int]:
    """(points within COVERAGE u of the truth, points with a finite z) for one quantity."""
    z = _z(points, column)
    ok = np.isfinite(z)
    return int(np.sum(z[ok] <= COVERAGE)), int(ok.sum())


def agreement_lines(points: pd.DataFrame) -> list[str]:
    """Per curve: how many points lie within 2u of the truth, per quantity, and the largest z."""
    if "true_F_T_N" not in points:
        return ["agreement with truth: the log has no truth"]
    groups = series(points)
    lines = [f"agreement with truth (points within {COVERAGE:g}u = the error bars; z = |measured - true|/u):"]
    for key, rows in groups:
        counts = ", ".join(f"{short} {'%d/%d' % within(rows, c)}" for c, (short, _, _) in QUANTITIES.items())
        z = np.concatenate([_z(rows, c) for c in QUANTITIES])
        largest = f"max z {np.nanmax(z):.2f}" if np.isfinite(z).any() else "no finite z"
        b_a, alpha = rows["true_b_over_a"].iloc[0], rows["true_alpha_prime"].iloc[0]
        lines.append(f"  {_label(key, [k for k, _ in groups])} (b/a {b_a:.2f}, alpha' of eq. (21) {alpha:.1f}): "
                     f"{counts}; {largest}")
    return lines


def moment_lines(points: pd.DataFrame) -> list[str]:
    """M_C = T_Mo + R_c F_T against the truth T0 per curve (range, largest error, u, share of R_c F_T)."""
    if "true_M_C_N_m" not in points:
        return []
    groups = series(points)
    lines = ["M_C = T_Mo + R_c F_T recovered (truth: the pivoting moment T0 = mu a F_N nu_0):"]
    for key, rows in groups:
        true, u = rows["true_M_C_N_m"], rows["u_M_C_N_m"]
        error = (rows["M_C_N_m"] - true).abs()
        transfer = (rows["T_Mo_N_m"] - rows["M_C_N_m"]).abs().max()  # R_c |F_T| [N m]
        lines.append(f"  {_label(key, [k for k, _ in groups])}: T0 {true.min():.3g} .. {true.max():.3g} N m, "
                     f"max |M_C - T0| {error.max():.2g} N m, u {u.min():.2g} .. {u.max():.2g} N m "
                     f"(R_c|F_T| up to {transfer:.3g} N m), within 2u {'%d/%d' % within(rows, 'M_C_N_m')}")
    return lines


def _families(points: pd.DataFrame):
    """Rows per (speed, direction, sigma): the loads of one operating family side by side."""
    return points.groupby(list(SETTINGS[1:]), sort=True)


def _value(rows: pd.DataFrame, column: str) -> pd.Series:
    """The truth of a column where the log has it, else the measured value."""
    return rows[f"true_{column}"] if f"true_{column}" in rows else rows[column]


def load_steps(points: pd.DataFrame, column: str = "F_T_N") -> dict[tuple, str]:
    """Per (speed step, direction, sigma [rad], l [mm]): 'rises' (|value| up at every load step by
    more than 2u combined), 'drops' (a step down beyond 2u) or 'unresolved' - measured values,
    loads in increasing order; positions with one load are left out."""
    found = {}
    for family_key, family in _families(points):
        for l_mm, rows in family.groupby("l_mm"):
            rows = rows.sort_values("normal_force_N")
            if len(rows) < 2:
                continue
            value, u = rows[column].abs().to_numpy(), rows[f"u_{column}"].to_numpy()
            step, limit = np.diff(value), COVERAGE * np.hypot(u[1:], u[:-1])
            found[(*family_key, float(l_mm))] = ("rises" if np.all(step > limit) else
                                                 "drops" if np.any(step < -limit) else "unresolved")
    return found


def load_exponents(points: pd.DataFrame, column: str) -> dict[tuple, float]:
    """Per (speed step, direction, sigma [rad], l [mm]): p [1] of |X| ~ F_N^p between the lightest
    and the heaviest load, where |X| is resolved (truth where logged, else measured; |X| > 1e-3
    of its largest value)."""
    found = {}
    for family_key, family in _families(points):
        scale = _value(family, column).abs().max()
        for l_mm, rows in family.groupby("l_mm"):
            rows = rows.sort_values("normal_force_N")
            x = _value(rows, column).abs().to_numpy()
            f = rows["normal_force_N"].to_numpy()
            if len(x) > 1 and f[-1] > f[0] and min(x[0], x[-1]) > 1e-3 * scale:
                found[(*family_key, float(l_mm))] = math.log(x[-1] / x[0]) / math.log(f[-1] / f[0])
    return found


def distance_factors(points: pd.DataFrame, column: str) -> np.ndarray:
    """Per curve: mean |X| at the largest |l| over mean |X| at the smallest non-zero |l| [1]
    (truth where logged, else measured)."""
    found = []
    for _, rows in series(points):
        reach = rows["l_mm"].abs().to_numpy()
        if not np.any(reach > 0.0):
            continue
        near, far = reach[reach > 0.0].min(), reach.max()
        x = _value(rows, column).abs().to_numpy()
        found.append(x[np.isclose(reach, far)].mean() / x[np.isclose(reach, near)].mean())
    return np.array(found)


def _span(values, fmt: str = ".2f") -> str:
    values = np.asarray(list(values), dtype=float)
    return "n/a" if values.size == 0 else f"{values.min():{fmt}} .. {values.max():{fmt}}"


def _extremes(by_l: dict[tuple, float]) -> str:
    """'min (l = ..) .. max (l = ..)' of values keyed (..., l [mm])."""
    if not by_l:
        return "n/a"
    lo, hi = min(by_l, key=by_l.get), max(by_l, key=by_l.get)
    return f"{by_l[lo]:.2f} (l = {lo[-1]:g} mm) .. {by_l[hi]:.2f} (l = {hi[-1]:g} mm)"


def _verdict_rises(steps: dict[tuple, str]) -> str:
    if not steps:
        return "not assessable (one load)"
    return "reproduced" if any(s == "drops" for s in steps.values()) else "not reproduced"


def _verdict_slow(smallest: float) -> str:
    if math.isnan(smallest):
        return "not assessable"
    if smallest < 0.3:
        return "reproduced"
    return "partly: sub-proportional at some positions, nowhere insensitive" if smallest < 0.9 else "not reproduced"


RISES = "peripheral forces do not always increase with the pressure force"
SLOW = "forces and moment grow much more slowly with F_N than elastic deformation implies"


def paper_verdicts(points: pd.DataFrame) -> dict[str, str]:
    """The two observations of [Koziarski] section 3.2.3 with a verdict: {statement: verdict}."""
    p = [v for c in CHANNELS for v in load_exponents(points, c).values()]
    return {RISES: _verdict_rises(load_steps(points)), SLOW: _verdict_slow(min(p, default=math.nan))}


def alpha_option_lines(points: pd.DataFrame, name: str, run_stand, other_stand) -> list[str]:
    """Which of the paper's statements each alpha' option reproduces (issue 15, item 3): the run's
    option from the measured points, the other from the same stand's truth at the same settings,
    judged with the run's u (steady_points)."""
    loads = points["normal_force_N"]
    other = steady_points(other_stand, points)
    lines = ["alpha' options (Equations §3.2: the paper's 100 .. 1500 vs eq. (21)'s estimate is unresolved):",
             f"  this run: {alpha_option(run_stand)}; alpha' {alpha_values(run_stand, loads)}",
             f"  other, dashed lines (truth only): {alpha_option(other_stand)}; alpha' {alpha_values(other_stand, loads)}"]
    for label, frame in (("this run", points), ("other", other)):
        verdicts = paper_verdicts(frame)
        lines.append(f"  {label}: " + "; ".join(f"'{s}' - {v}" for s, v in verdicts.items()))
    lines.append("  observations with the other alpha' (truth at the run's settings, judged with the run's u):")
    lines += [f"    {line}" for line in observation_lines(other, name, source="truth")[1:]]
    return lines


def observation_lines(points: pd.DataFrame, name: str, source: str = "measured") -> list[str]:
    """The paper's observations ([Koziarski] section 3.2.3) against what the simulation shows, with numbers;
    ``source`` names what the points' values are. The verdicts are our reading of the text:
    'insensitive' = p < 0.3, 'slower' = p < 0.9 [R]."""
    c_over_a = points["c_over_a"].to_numpy(dtype=float)
    paper = PAPER_C_OVER_A[name]
    lines = [f"rolling point: c/a = {_span(c_over_a, '.3f')} (paper, Fig. {name[3:]}: c/a = {paper:g})"
             + ("" if np.allclose(c_over_a, paper, atol=0.05) else " - NOT the paper's rolling point")]
    steps = load_steps(points)
    verdicts = paper_verdicts(points)
    others = []
    for key, state in steps.items():
        if state != "rises":
            largest = points.loc[np.isclose(points["l_mm"], key[-1]), "F_T_N"].abs().max()
            others.append(f"l = {key[-1]:g} mm {state} (|F_T| <= {largest:.2g} N)")
    lines.append(f"paper: 'peripheral forces do not always increase with the pressure force' - "
                 f"{verdicts[RISES]}: |F_T| rises at every load step (by > 2u) at "
                 f"{sum(s == 'rises' for s in steps.values())} of {len(steps)} positions"
                 + (f"; {', '.join(others)}" if others else ""))
    p = {c: load_exponents(points, c) for c in CHANNELS}
    loads = _span(points["normal_force_N"], ".0f")
    lines.append("paper: forces and moment grow much more slowly with F_N than elastic deformation implies, "
                 f"insensitive at some positions - {verdicts[SLOW]}: |X| ~ F_N^p ({loads} N),")
    lines.append(f"  p(F_T) {_extremes(p['F_T_N'])}, p(F_V) {_extremes(p['F_V_N'])}, "
                 f"p(T_Mo) {_extremes(p['T_Mo_N_m'])} (p = 1: proportional)")
    growth = {c: _span(distance_factors(points, c), ".1f") for c in ("F_T_N", "T_Mo_N_m", "M_C_N_m")}
    lines.append("paper: their values grow much faster with the distance of the rolling point from the centre - "
                 f"from the nearest l != 0 to the farthest: |F_T| x{growth['F_T_N']}, |T_Mo| x{growth['T_Mo_N_m']}, "
                 f"M_C x{growth['M_C_N_m']} (per load)")
    at_zero = points[np.isclose(points["l_mm"], 0.0)].sort_values("normal_force_N")
    lateral = ", ".join(f"{f:g} N: {v:+.3f}" for f, v in
                        zip(at_zero["normal_force_N"], at_zero["F_V_N"] / at_zero["normal_force_N"]))
    lines.append(f"F_V/F_N at l = 0: {lateral or 'n/a'}; F_V > 0 at {int((points['F_V_N'] > 0).sum())} "
                 f"of {len(points)} points ({source})")
    return lines


def draw(points: pd.DataFrame, curves: dict[tuple, pd.DataFrame], path: Path, title: str, caption: str,
         other: dict[tuple, pd.DataFrame] | None = None) -> None:
    """The four panels into ``path`` (PNG): points +-2u, truth lines, one colour per curve; ``other``:
    dashed truth lines of the other alpha' option."""
    from rig.plotting import colors, new_figure

    groups = series(points)
    keys = [k for k, _ in groups]
    colors = colors()
    fig = new_figure(figsize=(11.0, 8.0))
    axes = fig.subplots(2, 2, sharex=True)
    for ax, (column, (_, label, marker)) in zip(axes.flat, QUANTITIES.items()):
        for i, (key, rows) in enumerate(groups):
            color = colors[i % len(colors)]
            ax.errorbar(rows["l_mm"], rows[column], yerr=COVERAGE * rows[f"u_{column}"], fmt=marker, color=color,
                        ms=5, capsize=2, label=f"{_label(key, keys)}")
            if key in curves:
                ax.plot(curves[key]["l_mm"], curves[key][column], "-", color=color, lw=1.0)
            if other and key in other:
                ax.plot(other[key]["l_mm"], other[key][column], "--", color=color, lw=0.8)
        ax.axhline(0.0, color="0.7", lw=0.6)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("rolling-point offset $l$ [mm]")
    axes[0, 0].legend(fontsize=8, title="load $F_N$", title_fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.text(0.5, 0.01, caption, ha="center", va="bottom", fontsize=8, wrap=True)
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.12, top=0.9, wspace=0.22, hspace=0.08)  # fixed: no layout pass
    fig.savefig(path, dpi=120)


def _campaign(name: str, reduced: pd.DataFrame, log_path: Path, out_dir: Path, title: str) -> CampaignOutcome:
    _require_stand_b(Path(log_path))
    if reduced.empty:
        return CampaignOutcome((), (f"{name}.png not drawn: the run has no reduced point",))
    points = campaign_points(reduced, Path(log_path))
    run_stand, _ = _logged_stand(Path(log_path))
    curves, note = truth_curves(points, Path(log_path), run_stand)
    other_stand = None if note or run_stand is None else other_alpha_stand(Path(log_path))
    other = truth_curves(points, Path(log_path), other_stand)[0] if other_stand is not None else None
    caption = (f"points: measured, error bars +-{COVERAGE:g}u (k = {COVERAGE:g}); lines: the simulation's truth "
               f"(quasi-static steady state of the simulated stand); "
               + ("dashed: the same stand at the other alpha' option (summary); " if other else "")
               + f"canonical frame (forward running); "
               f"paper: [Koziarski] Fig. {name[3:]}, c/a = {PAPER_C_OVER_A[name]:g}" + (f"; {note}" if note else ""))
    figure = f"{name}.png"
    draw(points, curves, Path(out_dir) / figure, f"{title}\n{_conditions(points)}", caption, other)
    lines = [f"{figure}: {len(points)} points in {len(series(points))} curves; {caption}"]
    lines += [_line_check(points, curves)] if curves and not note else []
    lines += agreement_lines(points) + moment_lines(points) + observation_lines(points, name)
    if other_stand is not None:
        lines += alpha_option_lines(points, name, run_stand, other_stand)
    return CampaignOutcome((figure,), tuple(lines))


def _conditions(points: pd.DataFrame) -> str:
    """Subtitle: roller speeds [rpm], running directions and the simulated mu (when logged)."""
    from rig.stands.disc_roller.parameters import ROLLER_SPEEDS_RPM

    rpm = "/".join(f"{ROLLER_SPEEDS_RPM[int(k) - 1]:g}" for k in sorted(points["speed_step"].unique()))
    sense = "/".join({1: "forward", -1: "reverse"}[int(d)] for d in sorted(points["direction"].unique(), reverse=True))
    mu = f", simulated mu = {points['true_mu'].iloc[0]:g}" if "true_mu" in points else ""
    return f"roller {rpm} rpm, {sense} running{mu}"


def _line_check(points: pd.DataFrame, curves: dict[tuple, pd.DataFrame]) -> str:
    """Largest |logged truth - truth line| at the logged points, per quantity."""
    worst = dict.fromkeys(QUANTITIES, 0.0)
    for key, rows in series(points):
        line = curves[key].set_index("l_mm")
        for column in QUANTITIES:
            at = line[column].reindex(rows["l_mm"]).to_numpy()
            worst[column] = max(worst[column], float(np.nanmax(np.abs(at - rows[f"true_{column}"].to_numpy()))))
    return "truth lines vs the logged truth (gate means of the run): max deviation " + ", ".join(
        f"{QUANTITIES[c][0]} {v:.2g}" for c, v in worst.items()) + " [N, N m]"


def fig14(reduced: pd.DataFrame, log_path: Path, out_dir: Path, title: str) -> CampaignOutcome:
    """[Koziarski] Fig. 14 (c = 0): fig14.png in out_dir and the summary lines (see the module docstring)."""
    return _campaign("fig14", reduced, log_path, out_dir, title)


def fig15(reduced: pd.DataFrame, log_path: Path, out_dir: Path, title: str) -> CampaignOutcome:
    """[Koziarski] Fig. 15 (c/a = -2): fig15.png in out_dir and the summary lines (see the module docstring)."""
    return _campaign("fig15", reduced, log_path, out_dir, title)
