"""
Step 3: the table of friction coefficients, and a contradiction
===============================================================

[Zhao]'s table of friction coefficients, and where the slides contradict it.

Static coefficients of slide 19 (dry and clean, lubricated, wet) as bars, slide 18's quoted
ranges of mu_s and mu_k on top; the pairs where the two slides cannot both be right
(rig.teaching.friction_table.contradictions: steel-PTFE) are marked in red.

Run it from the repository root::

    python experiments/tutorial/step03_friction_table.py [-o out/tutorial]

Writes step03_friction_table.png and step03_friction_table.csv (the table with its source).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from rig.teaching.script import argument_parser, write_step
from rig.teaching.friction_table import (
    QUOTED_RANGES,
    SOURCE_TABLE,
    STATIC_TABLE,
    Condition,
    contradictions,
)

STEM = "step03_friction_table"


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    return parser.parse_args(argv)


def table_frame() -> pd.DataFrame:
    """Slide 19 as a table: one row per pair, low/high per condition (dimensionless, NaN = blank)."""
    rows = []
    for row in STATIC_TABLE:
        record = {"material_1": row.material_1, "material_2": row.material_2}
        for condition in Condition:
            value = row.coefficient(condition)
            key = condition.name.lower()
            record[f"mu_s_{key}_low"] = np.nan if value is None else value.low
            record[f"mu_s_{key}_high"] = np.nan if value is None else value.high
        record["source"] = SOURCE_TABLE
        rows.append(record)
    return pd.DataFrame(rows)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    table = table_frame()
    flagged = {frozenset((c.material_1, c.material_2)) for c in contradictions()}
    table["contradiction"] = [frozenset((r.material_1, r.material_2)) in flagged for r in STATIC_TABLE]

    fig = Figure(figsize=(10, 6.5), layout="constrained")
    ax = fig.subplots()
    entries: list[tuple[str, object]] = []
    for row in STATIC_TABLE:
        entries.append(("table", row))
        pair = {row.material_1, row.material_2}
        entries += [("quoted", q) for q in QUOTED_RANGES if {q.material_1, q.material_2} == pair]
    y = np.arange(len(entries))[::-1]
    labels = []
    for yi, (kind, entry) in zip(y, entries):
        red = frozenset((entry.material_1, entry.material_2)) in flagged
        if kind == "quoted":
            labels.append(f"{entry.material_1} - {entry.material_2}, slide 18")
            ax.plot([entry.static.low, entry.static.high], [yi + 0.15] * 2, "-", color="k", lw=4,
                    label=r"slide 18: $\mu_s$ range")
            ax.plot([entry.kinetic.low, entry.kinetic.high], [yi - 0.15] * 2, "-", color="0.6", lw=4,
                    label=r"slide 18: $\mu_k$ range")
            if red:
                ax.annotate("(!) contradicts slide 19:\n" + "\n".join(c.reason for c in contradictions()),
                            (0.65, yi), fontsize=7, color="C3", va="center")
            continue
        labels.append(f"{entry.material_1} - {entry.material_2}" + ("  (!)" if red else ""))
        ax.barh(yi + 0.2, entry.dry.high, height=0.35, color="C3" if red else "C0", label="dry and clean")
        if entry.dry.low < entry.dry.high:
            ax.plot([entry.dry.low, entry.dry.high], [yi + 0.2] * 2, "k|-", lw=1.5, label="range given in the table")
        for condition, color in ((Condition.LUBRICATED, "C1"), (Condition.WET, "C2")):
            value = entry.coefficient(condition)
            if value is not None:
                ax.barh(yi - 0.2, value.high, height=0.35, color=color, label=condition.value)
    handles, names = ax.get_legend_handles_labels()
    unique = dict(zip(names, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=8, loc="upper right")
    ax.set_yticks(y, labels, fontsize=8)
    ax.set(xlabel=r"static friction coefficient $\mu_s$ [1]", xlim=(0, 1.6),
           title="Approximate coefficients of friction ([Zhao], slides 18-19)")
    top = ax.secondary_xaxis("top", functions=(lambda m: np.degrees(np.arctan(m)), lambda d: np.tan(np.radians(d))))
    top.set_xlabel(r"critical inclination $\alpha^* = \arctan\mu_s$ [deg]")
    ax.grid(axis="x", alpha=0.3)
    return write_step(fig, table, args.output, STEM)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# The red row: slide 18 gives steel-Teflon mu_s = 0.3-0.6 and mu_k = 0.1-0.2, the table 0.04 (dry and
# lubricated). Both cannot hold: the quoted static range misses the table's value, and the quoted *kinetic*
# coefficient would exceed the table's *static* one. For steel-steel the two slides agree (0.80 is the top of
# 0.3-0.8). The top axis converts mu_s into the critical inclination of step 2.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

