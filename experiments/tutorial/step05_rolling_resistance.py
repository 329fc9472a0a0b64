"""
Step 5: rolling resistance: the shifted normal reaction
=======================================================

Rolling resistance - the normal reaction shifted forward by u = f_v r.

[Zhao] slides 32-36: N acts a distance u ahead of the centre and resists with the moment
N u; the power lost is N u omega = f_v N v; f_v is measured by pulling a wheel at constant
speed (the pull then equals f_v N). The right panel simulates that measurement with a noisy
force gauge (seeded) and recovers f_v with its standard uncertainty.

Run it from the repository root::

    python experiments/tutorial/step05_rolling_resistance.py [-o out/tutorial]

Writes step05_rolling_resistance.png and step05_rolling_resistance.csv (the pull record).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.patches import Circle

from rig.teaching.script import argument_parser, write_step
from rig.teaching.rolling_resistance import (
    ROLLING_COEFFICIENTS,
    coefficient_from_pull,
    dissipated_power,
    normal_reaction_shift,
    steady_pull,
)

STEM = "step05_rolling_resistance"
NORMAL_N = 3000.0  # load on one wheel [N] (a car wheel, our example)
RADIUS_M = 0.3  # [m]
TRUE_F_V = 0.015  # the simulated wheel's coefficient [1]: tyre-road, slide 36
GAUGE_NOISE_N = 8.0  # standard deviation of one force reading [N] [assumed]
READINGS = 200  # one reading per 0.1 s over 20 s
SEED = 20240501


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    return parser.parse_args(argv)


def sketch(ax, u_drawn: float) -> None:
    """A wheel with the shifted normal reaction (u exaggerated for the eye)."""
    ax.add_patch(Circle((0.0, 1.0), 1.0, fill=False, lw=2))
    ax.plot([-1.6, 1.6], [0.0, 0.0], color="k", lw=2)
    ax.plot(0.0, 1.0, "k+", ms=10)
    ax.annotate("", xy=(u_drawn, 0.0), xytext=(u_drawn, -0.7), arrowprops=dict(arrowstyle="-|>", color="C3", lw=2))
    ax.text(u_drawn + 0.05, -0.55, "N", color="C3")
    ax.annotate("", xy=(1.5, 1.0), xytext=(0.0, 1.0), arrowprops=dict(arrowstyle="-|>", color="C0", lw=2))
    ax.text(1.2, 1.1, "F", color="C0")
    ax.annotate("", xy=(-0.6, 0.0), xytext=(0.0, 0.0), arrowprops=dict(arrowstyle="-|>", color="C2", lw=2))
    ax.text(-0.6, 0.08, "T", color="C2")
    ax.plot([0.0, u_drawn], [-0.15, -0.15], "k-|", lw=1)
    ax.text(u_drawn / 2, -0.35, "u", ha="center")
    ax.text(-1.6, 2.5, "v, direction of travel \u2192", fontsize=8)
    ax.text(-1.6, 2.25, r"resisting moment N u = N $f_v$ r", fontsize=8)
    ax.set(xlim=(-1.7, 1.7), ylim=(-0.9, 2.7), aspect="equal", title="the normal reaction is shifted forward")
    ax.axis("off")


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    rng = np.random.default_rng(np.random.SeedSequence(SEED))
    time_s = np.arange(READINGS) * 0.1
    pull = steady_pull(NORMAL_N, TRUE_F_V) + rng.normal(0.0, GAUGE_NOISE_N, READINGS)
    f_v = coefficient_from_pull(float(pull.mean()), NORMAL_N)
    u_f_v = float(pull.std(ddof=1)) / np.sqrt(READINGS) / NORMAL_N
    table = pd.DataFrame(dict(time_s=time_s, pull_N=pull))

    fig = Figure(figsize=(14, 4.3), layout="constrained")
    ax0, ax1, ax2 = fig.subplots(1, 3)
    sketch(ax0, 0.35)
    speed = np.linspace(0.0, 30.0, 61)
    for index, pair in enumerate(ROLLING_COEFFICIENTS):
        low = [dissipated_power(NORMAL_N, pair.low, v) for v in speed]
        high = [dissipated_power(NORMAL_N, pair.high, v) for v in speed]
        u_low, u_high = (normal_reaction_shift(f, RADIUS_M) * 1e3 for f in (pair.low, pair.high))
        ax1.fill_between(speed, low, high, color=f"C{index}", alpha=0.4,
                         label=rf"{pair.pair}: $f_v$ = {pair.low:g}-{pair.high:g}, u = {u_low:.1f}-{u_high:.1f} mm")
    ax1.set(xlabel="speed v [m/s]", ylabel="power lost P [W]",
            title=rf"P = $f_v$ N v (N = {NORMAL_N:g} N, r = {RADIUS_M:g} m)")
    ax1.legend(fontsize=8, loc="upper left")
    ax2.plot(time_s, pull, ".", ms=3, label="force gauge readings")
    ax2.axhline(pull.mean(), color="C3", label=rf"mean: $f_v$ = F/N = {f_v:.5f} $\pm$ {u_f_v:.5f}")
    ax2.axhline(steady_pull(NORMAL_N, TRUE_F_V), color="k", ls=":", label=rf"true $f_v$ N ($f_v$ = {TRUE_F_V:g})")
    ax2.set(xlabel="time [s]", ylabel="pull at constant speed F [N]", title="measuring f_v by pulling (slide 36)")
    ax2.legend(fontsize=8)
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
# Left: the forces on the wheel (u exaggerated). Middle: the power lost by a wheel carrying 3 kN grows linearly
# with speed; at the same load a tyre loses 2-20 times more than a steel wheel (the ratio of the f_v ranges).
# Right: a simulated pull measurement (a force gauge with 8 N noise, seeded) gives f_v = F/N = 0.01500 +-
# 0.00020 for a wheel built with 0.015.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

