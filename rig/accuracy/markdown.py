"""The study's report as markdown: how it was run, one table per axis, the front, where the time goes."""

from __future__ import annotations

import math
from collections.abc import Sequence

import pandas as pd

from rig.accuracy.design import Axis, StudyDesign
from rig.accuracy.profiler import Profile

DASH = "-"


def number(x: float, digits: int = 4) -> str:
    """``x`` with ``digits`` decimals; '-' for NaN."""
    return DASH if x is None or not math.isfinite(float(x)) else f"{float(x):.{digits}f}"


def _label(row) -> str:
    tags = [t for t, on in (("scene", row.scene_choice), ("reference", row.reference)) if on]
    return f"**{row.setting}** ({', '.join(tags)})" if row.scene_choice else (
        f"{row.setting} ({', '.join(tags)})" if tags else row.setting)


def _cpu(row) -> str:
    return f"{number(row.cpu_median_s, 2)} ({number(row.cpu_min_s, 2)}-{number(row.cpu_max_s, 2)})"


def _front(row) -> str:
    if isinstance(row.unavailable, str) and row.unavailable:
        return f"no: unavailable ({row.unavailable})"
    return "yes" if row.on_front else "no"


def _d(row, q: str) -> str:
    """RMS d of quantity q, or 'unavailable' when the setting cannot give it."""
    missing = row.unavailable.split(", ") if isinstance(row.unavailable, str) and row.unavailable else []
    return "unavailable" if q in missing else number(getattr(row, f"d_{q}"))


def cpu_axis_table(rows: pd.DataFrame) -> list[str]:
    """Markdown lines of a CPU-cost axis (contact, table, drive)."""
    lines = ["| # | setting | runs | CPU median (range) [s] | first run [s] | RMS d l/a | RMS d mu_v | RMS d mu_T "
             "| RMS d true l/a | truth error l/a, mu_v, mu_T | failed | on front |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for k, row in enumerate(rows.itertuples(), start=1):
        truth = ", ".join(number(getattr(row, f"err_{q}")) for q in ("l_over_a", "mu_v", "mu_T"))
        lines.append(f"| {k} | {_label(row)} | {row.runs} | {_cpu(row)} | {number(row.cpu_first_s, 2)} | "
                     f"{_d(row, 'l_over_a')} | {_d(row, 'mu_v')} | {_d(row, 'mu_T')} | "
                     f"{number(row.d_true_l_over_a)} | {truth} | {row.failed} | {_front(row)} |")
    return lines


def reference_lines(plan, rows: pd.DataFrame, table: pd.DataFrame) -> list[str]:
    """What the axis's errors are measured against, and how far that reference is from convergence."""
    if plan.axis is Axis.GATE:
        return ["Error: the stated uncertainty itself (no reference run).", ""]
    info = table.attrs.get("references", {}).get(plan.axis.value)
    if info is None:
        label = plan.entries[plan.reference].label
        what = ("the finest setting, not a converged value (no grids N/4, N/2, N to extrapolate from)"
                if plan.axis is Axis.CONTACT else "the finest setting")
        return [f"Reference: {label}, {what}; its own error is not known.", ""]
    parts = []
    for q, name in (("l_over_a", "l/a"), ("mu_v", "mu_v"), ("mu_T", "mu_T"), ("true_l_over_a", "true l/a")):
        if q in info.uncertainty:
            done, total = info.trusted[q]
            order = "-" if not math.isfinite(info.order[q]) else f"{info.order[q]:.1f}"
            parts.append(f"{name} {info.uncertainty[q]:.4f} (order {order} at {done} of {total} points)")
    finest = rows.iloc[plan.extrapolated[-1]]
    return [f"Reference: the converged model - {', '.join(info.grids)} extrapolated point by point to zero cell size "
            "(Richardson with the observed order; where the order is not between 0.5 and 3 the finest value with "
            "three times its last step as uncertainty: rig.contact.numerical_error.richardson). Its own "
            f"uncertainty (RMS over the points): {'; '.join(parts)}. The finest setting, {finest.setting}, is "
            f"{number(finest.error)} from it (largest RMS d); errors below the reference's own uncertainty are not "
            "resolved.", ""]


def choice_sentence(rows: pd.DataFrame, axis: str) -> str:
    """One sentence: which setting on the axis's front to choose for which error. The front is walked
    from the cheapest setting; it stops at the first whose error is below the reference's own
    uncertainty (u_reference), since the study cannot tell the rest apart."""
    front = rows[rows["on_front"]].sort_values("cost_s")
    if front.empty:
        return f"{axis}: no setting gives every reduced quantity."
    cost = "lab time" if axis == Axis.GATE.value else (
        "build + first run" if axis in (Axis.CONTACT.value, Axis.TABLE.value) else "per run")
    u_reference = float(rows["u_reference"].max()) if "u_reference" in rows else 0.0
    steps, unresolved = [], False
    for row in front.itertuples():
        steps.append(f"{row.setting} for an error down to {number(row.error)} ({cost} {number(row.cost_s, 1)} s)")
        if u_reference > 0.0 and row.error <= u_reference:
            unresolved = True
            break
    text = f"{axis}: choose " + ("; ".join(steps[:-1]) + "; else " if len(steps) > 1 else "") + steps[-1]
    if unresolved:
        text += (f" - below the reference's own uncertainty ({number(u_reference)}) the settings cannot be told "
                 "apart, so a costlier one buys nothing measurable")
    return text + "."


def gate_axis_table(rows: pd.DataFrame) -> list[str]:
    """Markdown lines of the gate-time axis (cost: lab time; error: stated uncertainty)."""
    lines = ["| setting | lab time [s] | CPU median [s] | median u l/a | median u mu_T | truth error l/a, mu_T "
             "| on front |", "|---|---|---|---|---|---|---|"]
    for row in rows.itertuples():
        lines.append(f"| {_label(row)} | {number(row.lab_time_s, 1)} | {number(row.cpu_median_s, 2)} | "
                     f"{number(row.u_l_over_a)} | {number(row.u_mu_T)} | {number(row.err_l_over_a)}, "
                     f"{number(row.err_mu_T)} | {_front(row)} |")
    return lines


def profile_lines(profile: Profile | None, cpu_s: float) -> list[str]:
    """'Where the time goes' for the scene's own setting: share of samples x median CPU time [s]."""
    if profile is None or profile.samples == 0:
        return ["(no profile: the run was too short to sample)"]
    weighting = "weighted by the thread's CPU time" if profile.cpu_weighted else "equal weights (no thread CPU clock)"
    lines = [f"Stack samples of one extra, untimed run of the scene's own setting ({profile.samples} samples, "
             f"{weighting}; rig.accuracy.profiler); the shares are applied to its median CPU time of {cpu_s:.2f} s:",
             "",
             "| part | share | CPU [s] |", "|---|---|---|"]
    for part, share in profile.fractions().items():
        lines.append(f"| {part.value} | {share:.0%} | {share * cpu_s:.2f} |")
    return lines


def front_sentence(table: pd.DataFrame) -> str:
    """Whether the scene's own setting is on each axis's front, in words."""
    own = table[table["scene_choice"]]
    on = [a for a, f in zip(own["axis"], own["on_front"]) if f]
    off = [a for a, f in zip(own["axis"], own["on_front"]) if not f]
    text = "The scene's own setting is on the front of: " + (", ".join(on) if on else "no axis")
    return text + ("; not on the front of: " + ", ".join(off) + "." if off else ".")


def report_markdown(title: str, header: Sequence[str], design: StudyDesign, table: pd.DataFrame,
                    profile: Profile | None, scene_cpu_s: float) -> str:
    """The whole report: title, header lines, the axes' tables, the front, where the time goes."""
    lines = [f"## {title}", "", *header, ""]
    choices = []
    for plan in design.axes:
        rows = table[table["axis"] == plan.axis.value]
        lines += [f"### {plan.axis.value}", "", *reference_lines(plan, rows, table)]
        lines += gate_axis_table(rows) if plan.axis is Axis.GATE else cpu_axis_table(rows)
        lines.append("")
        choices.append(f"* {choice_sentence(rows, plan.axis.value)}")
    lines += ["### Which setting to choose", "", *choices, "", front_sentence(table), "", "### Where the time goes", "", *profile_lines(profile, scene_cpu_s), ""]
    return "\n".join(lines)


__all__ = ["choice_sentence", "cpu_axis_table", "front_sentence", "reference_lines", "gate_axis_table", "number", "profile_lines",
           "report_markdown"]
