"""
Step 2: the inclined plane
==========================

A body on an inclined plane ([Zhao] slides 15-16 and 20-21).

At rest iff tan(alpha) <= mu_s, whatever the mass; sliding down, a = g (sin(alpha) - mu_k cos(alpha)),
less than the frictionless g sin(alpha). The left panel places the pairs of [Zhao]'s table on
the rest/slide map; the right panel shows the acceleration against the inclination.

Run it from the repository root::

    python experiments/tutorial/step02_inclined_plane.py [-o out/tutorial]

Writes step02_inclined_plane.png and step02_inclined_plane.csv (acceleration versus angle).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from rig.teaching.script import argument_parser, write_step
from rig.teaching.friction_table import table_row
from rig.teaching.inclined_plane import at_rest, critical_angle, sliding_acceleration

STEM = "step02_inclined_plane"
MU_S = 0.8  # steel-steel dry, slide 19 [1]
PAIRS = (("steel", "PTFE"), ("wood", "wood"), ("steel", "steel"), ("concrete", "rubber"))  # slide 19, dry
MU_K_VALUES = (0.0, 0.15, 0.3, 0.6)  # kinetic coefficients drawn [1]; 0.15-0.6: slide 18's steel-steel range


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    alpha_deg = np.linspace(0.0, 90.0, 181)
    alpha = np.radians(alpha_deg)
    columns = {"alpha_deg": alpha_deg, f"at_rest_mu_s_{MU_S:g}": [at_rest(a, MU_S) for a in alpha]}
    for mu_k in MU_K_VALUES:
        columns[f"a_mu_k_{mu_k:g}_m_s2"] = [sliding_acceleration(a, mu_k) for a in alpha]
    table = pd.DataFrame(columns)

    fig = Figure(figsize=(11, 4.4), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    ax1.plot(alpha_deg[alpha_deg < 60], np.tan(alpha[alpha_deg < 60]), color="k", label=r"tan $\alpha$")
    for index, pair in enumerate(PAIRS):
        row = table_row(*pair)
        mu_s = row.dry.high
        star = math.degrees(critical_angle(mu_s))
        color = f"C{index}"
        ax1.axhline(mu_s, color=color, ls="--", lw=1)
        ax1.plot([star, star], [0.0, mu_s], color=color, lw=1)
        ax1.plot(star, mu_s, "o", color=color,
                 label=rf"{row.material_1}-{row.material_2}: $\mu_s$ = {mu_s:g}, $\alpha^*$ = {star:.1f} deg")
    ax1.set(xlabel=r"inclination $\alpha$ [deg]", ylabel=r"tan $\alpha$, $\mu_s$ [1]", xlim=(0, 60), ylim=(0, 1.2),
            title=r"at rest while tan $\alpha \leq \mu_s$ (any mass)")
    ax1.legend(fontsize=7, loc="upper left")
    g_sin = table[f"a_mu_k_{0.0:g}_m_s2"]
    for mu_k in MU_K_VALUES:
        label = "frictionless g sin(alpha)" if mu_k == 0.0 else rf"$\mu_k$ = {mu_k:g}"
        values = table[f"a_mu_k_{mu_k:g}_m_s2"]
        ax2.plot(alpha_deg, np.where(values >= 0.0, values, np.nan), label=label, ls="--" if mu_k == 0.0 else "-")
    ax2.axvspan(0.0, math.degrees(critical_angle(MU_S)), color="C2", alpha=0.15,
                label=rf"at rest if started at rest ($\mu_s$ = {MU_S:g})")
    ax2.set(xlabel=r"inclination $\alpha$ [deg]", ylabel=r"acceleration down the plane a [m/s$^2$]",
            title=r"sliding: a = g (sin $\alpha$ - $\mu_k$ cos $\alpha$)", ylim=(0, 1.05 * g_sin.max()))
    ax2.legend(fontsize=8, loc="upper left")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    return write_step(fig, table, args.output, STEM)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# Left: the critical inclination alpha* = atan(mu_s) where tan(alpha) meets mu_s: 2.3 deg for steel-PTFE, 26.6
# deg for wood-wood (upper value), 38.7 deg for steel-steel, 45 deg for concrete-rubber. Right: every friction
# curve lies below the frictionless one and starts at alpha = atan(mu_k), where sliding is steady (a = 0); the
# shaded band is where a body placed at rest stays at rest for mu_s = 0.8.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

