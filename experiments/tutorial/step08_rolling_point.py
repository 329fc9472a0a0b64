"""
Step 8: moving the rolling point
================================

The rolling point C moves - and the force components follow (eqs. 26-28).

Stand A's contact is a line contact with b/a = 1 at 96.2 N and alpha' ~ 0.64 (Equations §3.1:
nearly full sliding). Moving C = (c, l) away from the centre turns the rigid slip (a rotation
about C) into a nearly uniform slide: the peripheral force nu_T (C along the contact line, l),
the lateral force nu_v (C across it, c) saturate at 1, the pivoting moment about C grows like
abs(C)/a. Full sliding (rigid model) and the paper's kinematic model at stand A's alpha' and at a
stiffer alpha' = 10 are drawn.

Run it from the repository root::

    python experiments/tutorial/step08_rolling_point.py [-o out/tutorial] [--n 16]

Writes step08_rolling_point.png and step08_rolling_point.csv (nu_T, nu_v, nu_0 per model and C).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from rig.contact.kinematics import rigid_slip_direction
from rig.teaching.script import argument_parser, write_step
from rig.contact.solve import solve
from rig.reduction.equations import alpha_prime_line_contact
from rig.reduction.geometry import StandAGeometry
from rig.wheel_kinematics import ratio_for_l

STEM = "step08_rolling_point"
POISSON, MU, B_OVER_A = 0.3, 0.4, 1.0  # laminate on steel, stand A at 96.2 N (Equations §3.1)
L_VALUES = np.linspace(-3.0, 3.0, 25)  # l/a, C along the contact line (c = 0)
C_VALUES = np.linspace(0.0, 2.0, 11)  # c/a, C across it (l = 0)
TEX = {"nu_T": r"$\nu_T$", "nu_v": r"$\nu_v$", "nu_0": r"$\nu_0$"}
ALPHA_STIFF = 10.0  # a stiffer contact, the low end of stand B's alpha' (Equations §0: 10.6-42.6) [1]
MAP_POINTS = ((0.0, 0.5), (0.4, 2.5))  # (c/a, l/a) of the two slip maps


def stand_a_alpha_prime() -> float:
    """alpha' of stand A at l = 0 (eq. 21, line contact): 10 mu (b/a)(v/w0)/R_x [1]."""
    g = StandAGeometry()
    ratio = ratio_for_l(0.0, g.alpha_1, g.l1, g.l2)
    v_over_spin = g.r1 / (math.sin(g.alpha_1) + ratio)  # v/w0 = w1 r1/(w1 (sin(alpha1) + i_k)) [m]
    return alpha_prime_line_contact(MU, B_OVER_A, v_over_spin, g.radius_x)


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    parser.add_argument("--n", type=int, default=16, help="cells across 2a of the kinematic model (default 16)")
    return parser.parse_args(argv)


def sweep(alpha: float, n: int) -> pd.DataFrame:
    rows = []
    for model, a in (("rigid", 0.0), ("kinematic", alpha), ("kinematic", ALPHA_STIFF)):
        for name, points in (("l", [(0.0, l) for l in L_VALUES]), ("c", [(c, 0.0) for c in C_VALUES])):
            for c, l in points:
                r = solve(model, shape="line", b_over_a=B_OVER_A, alpha=a, c_over_a=float(c), l_over_a=float(l),
                          poisson=POISSON, n=n)
                rows.append(dict(model=model, sweep=name, alpha_prime=a, c_over_a=c, l_over_a=l,
                                 nu_T=r.nu_T, nu_v=r.nu_v, nu_0=r.nu_0))
    return pd.DataFrame(rows)


def slip_map(ax, c: float, l: float) -> None:
    """Rigid slip directions over the line contact (|x| <= b, |y| <= a) for C = (c, l)."""
    xs, ys = np.meshgrid(np.linspace(-0.9, 0.9, 7), np.linspace(-0.9, 0.9, 7))
    d = rigid_slip_direction(xs, ys, c, l)
    ax.add_patch(Rectangle((-B_OVER_A, -1.0), 2 * B_OVER_A, 2.0, fill=False))
    ax.quiver(xs, ys, d[0], d[1], angles="xy", scale=12, color="k")
    ax.quiver(xs, ys, -d[0], -d[1], angles="xy", scale=12, color="C3", alpha=0.6)
    ax.plot(c, l, "r*", ms=12)
    ax.set(xlim=(-1.3, 1.3), ylim=(-1.3, 3.0), aspect="equal", xlabel="x/a", ylabel="y/a",
           title=f"C = ({c:g}a, {l:g}a): slip (black),\nfull-sliding traction (red)")


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    alpha = stand_a_alpha_prime()
    table = sweep(alpha, args.n)

    fig = Figure(figsize=(15, 4.6), layout="constrained")
    axes = fig.subplots(1, 4, width_ratios=[1, 1, 1.5, 1.5])
    for ax, (c, l) in zip(axes[:2], MAP_POINTS):
        slip_map(ax, c, l)
    for ax, name, x in ((axes[2], "l", "l_over_a"), (axes[3], "c", "c_over_a")):
        for a, style in ((0.0, "--"), (alpha, "-"), (ALPHA_STIFF, ":")):
            part = table[(table.alpha_prime == a) & (table.sweep == name)]
            label = "full sliding" if a == 0.0 else f"kinematic, alpha' = {a:.2f}"
            for index, key in enumerate(("nu_T", "nu_v", "nu_0")):
                ax.plot(part[x], part[key], style, color=f"C{index}", label=f"{TEX[key]} ({label})", lw=1.5)
        where = "the contact line (c = 0)" if name == "l" else "x (l = 0)"
        ax.set(xlabel=f"{name}/a", ylabel="[1]", title=f"C moved along {where}")
        ax.grid(alpha=0.3)
    axes[3].legend(fontsize=6, loc="center right")
    return write_step(fig, table, args.output, STEM)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# Left two panels: rigid slip (black) and full-sliding traction (red) for C inside and outside the contact.
# Right: full sliding (dashed) and the kinematic model at stand A's alpha' = 0.64 (solid) nearly coincide -
# except nu_v at c = 0, which only the elastic model has; a stiffer contact (alpha' = 10, dotted, the range of
# stand B) lowers nu_0 and raises nu_v. Checks (tested): full sliding gives nu_T = -0.446, nu_0 = 0.824 at l =
# 0.5a and nu_v = 0.400, nu_0 = 0.793 at c = 0.4a, the values of Equations §1.10(a).
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

