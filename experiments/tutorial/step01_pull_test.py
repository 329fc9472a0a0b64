"""
Step 1: static and kinetic friction: the slowly increasing force
================================================================

Coulomb's "slowly increasing force" experiment ([Zhao] slides 13 and 17).

A 2 kg steel block on a steel plane is pulled by F = k t. It sticks (T = F) until F reaches
mu_s N, then the micro-welds shear, T drops to mu_k N and the block accelerates.

Run it from the repository root::

    python experiments/tutorial/step01_pull_test.py [-o out/tutorial]

Writes step01_pull_test.png (the F-T diagram and the time traces) and step01_pull_test.csv.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from rig.teaching.script import argument_parser, write_step
from rig.teaching.friction_table import QUOTED_RANGES, static_coefficient
from rig.teaching.pull_test import pull_test

STEM = "step01_pull_test"
MASS_KG = 2.0  # block [kg]
FORCE_RATE_N_S = 2.0  # k [N/s]: "slowly" increasing
DURATION_S = 12.0
MU_S = static_coefficient("steel", "steel").high  # 0.80, slide 19 (dry)
MU_K = QUOTED_RANGES[0].kinetic.high  # 0.6, upper end of slide 18's steel-steel mu_k range


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    parser.add_argument("--mu-s", type=float, default=MU_S, help="static coefficient [1] (default: steel-steel 0.80)")
    parser.add_argument("--mu-k", type=float, default=MU_K, help="kinetic coefficient [1] (default 0.6)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    trace = pull_test(MASS_KG, args.mu_s, args.mu_k, FORCE_RATE_N_S, np.linspace(0.0, DURATION_S, 1201))
    table = pd.DataFrame(dict(time_s=trace.time_s, pull_N=trace.pull_N, friction_N=trace.friction_N,
                              speed_m_s=trace.speed_m_s))

    fig = Figure(figsize=(11, 4.2), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    ax1.plot(trace.pull_N, trace.friction_N, lw=2, label="tangential reaction T")
    ax1.plot(trace.pull_N, trace.pull_N, ":", color="grey", label="T = F (adhesion)")
    ax1.axhline(trace.breakaway_force_N, ls="--", color="C3", label=rf"$\mu_s N$ = {trace.breakaway_force_N:.2f} N")
    ax1.axhline(trace.kinetic_force_N, ls="--", color="C2", label=rf"$\mu_k N$ = {trace.kinetic_force_N:.2f} N")
    ax1.set(xlabel="pull F [N]", ylabel="friction T [N]", title="F-T diagram (Fig. 5.3): the drop at breakaway")
    ax1.legend(fontsize=8)
    ax2.plot(trace.time_s, trace.pull_N, label="pull F")
    ax2.plot(trace.time_s, trace.friction_N, label="friction T")
    ax2.axvline(trace.breakaway_time_s, color="grey", lw=0.8)
    ax2.set(xlabel="time t [s]", ylabel="force [N]", title=f"F = {FORCE_RATE_N_S:g} N/s * t on a {MASS_KG:g} kg block")
    speed = ax2.twinx()
    speed.plot(trace.time_s, trace.speed_m_s, color="C4", label="speed v")
    speed.set_ylabel("speed v [m/s]", color="C4")
    ax2.legend(loc="upper left", fontsize=8)
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
# Left: T follows the dotted line T = F up to mu_s N = 15.7 N (2 kg block), then jumps down to mu_k N = 11.8 N
# and stays there however hard one pulls. Right: the block starts to move at t* = mu_s N/k = 7.8 s; the speed
# grows because F - mu_k N keeps growing.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

