"""
Step 4: rolling without slipping, and when it stops
===================================================

A wheel pulled at its centre - rolling without slipping, then with slipping.

[Zhao] slides 22-24 and 33-40: while abs(T) <= mu_s N (ineq. 5.10) the contact point is the
instantaneous centre (v = omega r) and a = (F - f_v N)/(m + J/r^2), T = J a/r^2 + f_v N;
beyond F_max the wheel slips, T = mu_k N and the centre outruns the rim (a > omega' r).
A solid rubber-tyred disc on concrete: mu_s = 1.0 (slide 19, concrete-rubber dry).

Run it from the repository root::

    python experiments/tutorial/step04_rolling_wheel.py [-o out/tutorial]

Writes step04_rolling_wheel.png and step04_rolling_wheel.csv (a, omega' r, T versus the pull F).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from rig.teaching.script import argument_parser, write_step
from rig.teaching.coulomb import STANDARD_GRAVITY
from rig.teaching.friction_table import static_coefficient
from rig.teaching.rolling_wheel import Wheel, max_rolling_pull, pulled_wheel

STEM = "step04_rolling_wheel"
WHEEL = Wheel.solid_disc(mass_kg=10.0, radius_m=0.3)  # J = m r^2/2
MU_S = static_coefficient("concrete", "rubber").high  # 1.0, slide 19
MU_K = 0.8  # [assumed] kinetic < static (slide 10); the slides give no kinetic value for this pair
F_V = 0.015  # tyre-road, middle of slide 36's 1-2e-2 [1]


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    normal = WHEEL.mass_kg * STANDARD_GRAVITY
    f_max = max_rolling_pull(WHEEL, normal, F_V, MU_S)
    pulls = np.linspace(0.0, 1.6 * f_max, 321)
    motions = [pulled_wheel(WHEEL, f, normal, F_V, MU_S, MU_K) for f in pulls]
    table = pd.DataFrame(dict(
        pull_N=pulls,
        acceleration_m_s2=[m.acceleration_m_s2 for m in motions],
        rim_acceleration_m_s2=[m.angular_acceleration_rad_s2 * WHEEL.radius_m for m in motions],
        friction_N=[m.friction_N for m in motions],
        rolls=[m.rolls for m in motions],
    ))

    fig = Figure(figsize=(11, 4.3), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    ax1.plot(pulls, table.friction_N, lw=2, label="friction T at the contact")
    ax1.axhline(MU_S * normal, color="C3", ls="--", label=rf"$\mu_s N$ = {MU_S * normal:.0f} N (ineq. 5.10)")
    ax1.axhline(MU_K * normal, color="C2", ls="--", label=rf"$\mu_k N$ = {MU_K * normal:.0f} N")
    ax1.axvline(f_max, color="grey", lw=0.8)
    ax1.annotate(rf"$F_{{max}}$ = {f_max:.0f} N" + "\n" + r"($\approx 3\mu_s N$ for a disc)", (f_max, 40),
                 xytext=(5, 0), textcoords="offset points", fontsize=8)
    ax1.set(xlabel="pull at the centre F [N]", ylabel="T [N]",
            title=rf"T = J a/r$^2$ + $f_v$N while rolling ($f_v$ = {F_V:g})")
    ax1.legend(fontsize=8, loc="lower right")
    ax2.plot(pulls, table.acceleration_m_s2, lw=2, label="centre: a")
    ax2.plot(pulls, table.rim_acceleration_m_s2, "--", lw=2, label=r"rim: $\dot\omega$ r")
    ax2.axvspan(f_max, pulls[-1], color="C3", alpha=0.1, label="rolling with slipping")
    ax2.set(xlabel="pull at the centre F [N]", ylabel=r"acceleration [m/s$^2$]",
            title=r"rolling: a = $\dot\omega$ r = (F - $f_v$N)/(m + J/r$^2$)")
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
# Left: T grows with F (T = (F - f_v N)/3 + f_v N for a disc) until it reaches mu_s N at F_max = 3 mu_s N - 2
# f_v N = 291 N, then drops to mu_k N. Right: below F_max the centre and the rim accelerate together (a = omega'
# r); above it the centre outruns the rim - the wheel skids.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

