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
    return "yes" if row.on_front else "no"


def cpu_axis_table(rows: pd.DataFrame) -> list[str]:
    """Markdown lines of a CPU-cost axis (contact, table, drive)."""
    lines = ["| setting | runs | CPU median (range) [s] | first run [s] | RMS d l/a | RMS d mu_v | RMS d mu_T "
             "| RMS d true l/a | truth error l/a, mu_v, mu_T | failed | on front |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows.itertuples():
        truth = ", ".join(number(getattr(row, f"err_{q}")) for q in ("l_over_a", "mu_v", "mu_T"))
        lines.append(f"| {_label(row)} | {row.runs} | {_cpu(row)} | {number(row.cpu_first_s, 2)} | "
                     f"{number(row.d_l_over_a)} | {number(row.d_mu_v)} | {number(row.d_mu_T)} | "
                     f"{number(row.d_true_l_over_a)} | {truth} | {row.failed} | {_front(row)} |")
    return lines


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
    for plan in design.axes:
        rows = table[table["axis"] == plan.axis.value]
        lines += [f"### {plan.axis.value}", ""]
        lines += gate_axis_table(rows) if plan.axis is Axis.GATE else cpu_axis_table(rows)
        lines.append("")
    lines += [front_sentence(table), "", "### Where the time goes", "", *profile_lines(profile, scene_cpu_s), ""]
    return "\n".join(lines)


__all__ = ["cpu_axis_table", "front_sentence", "gate_axis_table", "number", "profile_lines",
           "report_markdown"]
