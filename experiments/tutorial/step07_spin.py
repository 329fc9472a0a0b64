"""
Step 7: spin: slip that turns about the rolling point
=====================================================

Spin - the contact also turns about its normal ([Koziarski] eqs. 1 and 7).

Two wheels whose axes are inclined to the contact plane spin relative to each other with
w0 = w1 sin(alpha1) + w2 sin(alpha2) (eq. 1; axes on opposite sides, as on stand A). The rigid
slip is then a rotation w0 about the rolling point C (eq. 7): zero at C, growing with the
distance from it. In full sliding the friction opposes the slip everywhere and the contact
carries a pivoting moment, nu_0 = 3 pi/16 for a Hertz circle with C at its centre (Equations
§1.10); an elastic contact (track deformability alpha', eq. 21) adheres near C, loses pivoting
moment, and - the paper's theme - produces a lateral force F_y from spin alone.

Run it from the repository root::

    python experiments/tutorial/step07_spin.py [-o out/tutorial] [--n 16]

Writes step07_spin.png and step07_spin.csv (nu_v, nu_0, adhesion fraction versus alpha').
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.patches import Circle

from rig.contact.solve import solve
from rig.teaching.script import argument_parser, write_step
from rig.reduction.geometry import StandAGeometry
from rig.wheel_kinematics import AxisSides, pair_spin, ratio_for_l

STEM = "step07_spin"
POISSON = 0.3  # [1]
ALPHA_MAP = 30.0  # alpha' of the traction map (adhesion near C) [1]
OMEGA_1 = 25.13  # stand A wheel 1, 240 rpm [rad/s] (Equations §3.1)


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    parser.add_argument("--n", type=int, default=16, help="cells across 2a of the kinematic model (default 16)")
    return parser.parse_args(argv)


def stand_a_spin() -> tuple[float, float, float]:
    """Stand A at l = 0: (w1 sin(alpha1), w2, w0) [rad/s] from eq. (1) and eq. (30) inverted."""
    g = StandAGeometry()
    ratio = ratio_for_l(0.0, g.alpha_1, g.l1, g.l2)
    w2 = ratio * OMEGA_1
    return OMEGA_1 * math.sin(g.alpha_1), w2, pair_spin(OMEGA_1, g.alpha_1, w2, math.pi / 2, AxisSides.OPPOSITE)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    alphas = np.logspace(-1, 3, 13)
    rows = []
    for alpha in alphas:
        r = solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=float(alpha), c_over_a=0.0, l_over_a=0.0,
                  poisson=POISSON, n=args.n)
        rows.append(dict(alpha_prime=alpha, nu_T=r.nu_T, nu_v=r.nu_v, nu_0=r.nu_0, stick_fraction=r.stick_fraction))
    rigid = solve("rigid", shape="ellipse", b_over_a=1.0, alpha=0.0, c_over_a=0.0, l_over_a=0.0, poisson=POISSON)
    rows.append(dict(alpha_prime=0.0, nu_T=rigid.nu_T, nu_v=rigid.nu_v, nu_0=rigid.nu_0, stick_fraction=0.0))
    table = pd.DataFrame(rows)

    w01, w02, w0 = stand_a_spin()
    fig = Figure(figsize=(14, 4.6), layout="constrained")
    ax1, ax2, ax3 = fig.subplots(1, 3)
    grid = np.linspace(-1.0, 1.0, 201)
    x, y = np.meshgrid(grid, grid)
    inside = x**2 + y**2 <= 1.0
    shade = ax1.contourf(x, y, np.where(inside, np.hypot(x, y), np.nan), levels=10, cmap="Blues")
    fig.colorbar(shade, ax=ax1, label=r"|slip| / ($\omega_0$ a)")
    xs, ys = np.meshgrid(np.linspace(-0.9, 0.9, 10), np.linspace(-0.9, 0.9, 10))
    keep = xs**2 + ys**2 <= 1.0
    ax1.quiver(xs[keep], ys[keep], -ys[keep], xs[keep], color="k", angles="xy")
    ax1.plot(0.0, 0.0, "r*", ms=12, label="rolling point C = O")
    ax1.set(xlabel="x/a (material flows in +x)", ylabel="y/a (contact line)", aspect="equal",
            title=r"rigid slip: rotation $\omega_0$ about C" + "\n" +
                  rf"stand A: $\omega_0$ = {w01:.1f} + {w02:.1f} = {w0:.1f} rad/s (eq. 1)")
    ax1.legend(fontsize=8, loc="lower right")
    r = solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=ALPHA_MAP, c_over_a=0.0, l_over_a=0.0,
              poisson=POISSON, n=max(args.n, 8))
    m = r.maps
    ax2.scatter(m.x[m.stick], m.y[m.stick], s=30, marker="s", color="C2", alpha=0.4, label="adhesion (stick)")
    ax2.quiver(m.x, m.y, m.traction[0], m.traction[1], angles="xy", color="C3")
    ax2.add_patch(Circle((0.0, 0.0), 1.0, fill=False))
    ax2.set(xlabel="x/a", ylabel="y/a", aspect="equal", xlim=(-1.1, 1.1), ylim=(-1.1, 1.1),
            title=rf"tractions q/($\mu p_0$), kinematic model, $\alpha'$ = {ALPHA_MAP:g}" + "\n" +
                  rf"$\nu_v$ = {r.nu_v:.3f}, $\nu_0$ = {r.nu_0:.3f}")
    ax2.legend(fontsize=8, loc="lower right")
    kin = table[table.alpha_prime > 0]
    ax3.semilogx(kin.alpha_prime, kin.nu_0, "o-", label=r"$\nu_0$ (pivoting moment, eq. 26)")
    ax3.semilogx(kin.alpha_prime, kin.nu_v, "s-", label=r"$\nu_v$ (lateral force, eq. 28)")
    ax3.semilogx(kin.alpha_prime, kin.stick_fraction, "^-", label="adhesion area fraction")
    ax3.axhline(3 * math.pi / 16, color="grey", ls="--", label=r"full sliding: $\nu_0$ = 3$\pi$/16")
    ax3.set(xlabel=r"track deformability $\alpha'$ (eq. 21)", ylabel="[1]",
            title=f"pure spin of a Hertz circle (n = {args.n})")
    ax3.legend(fontsize=8)
    ax3.grid(alpha=0.3, which="both")
    return write_step(fig, table, args.output, STEM)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# Left: stand A at l = 0 spins at w0 = 24.1 + 20.4 = 44.5 rad/s (Equations §3.1: 44 rad/s); the slip circles C.
# Middle: at alpha' = 30 the tractions of the kinematic model (`rig.contact.solve`) and the adhesion zone, which
# sits on the leading side (x < 0) where the material has not yet slipped. Right: for pure spin of a Hertz
# circle nu_0 starts at 3 pi/16 and falls with alpha'; nu_v rises from 0, peaks near 0.58 at alpha' ~ 10 and
# falls like 1/alpha'; the adhesion area appears above alpha' ~ 10 and covers the contact at large alpha'.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

