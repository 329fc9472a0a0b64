"""
Step 6: where the shift comes from: hysteresis
==============================================

Where rolling resistance comes from - hysteresis of a soft disc on a rigid plane.

[Zhao] slides 26-32 with our model (rig.teaching.hysteresis): the disc's rim is a layer of
Kelvin-Voigt elements. Elastic (v = 0): symmetric pressure, loading and unloading on one line,
no loss. Viscoelastic: the front carries more pressure, the p-epsilon path becomes a loop whose
area is the energy lost per unit volume and pass, the resultant N moves forward by u, and
f_v = u/R; for slow rolling u is the distance rolled in one relaxation time, v eta/E.

Run it from the repository root::

    python experiments/tutorial/step06_hysteresis.py [-o out/tutorial]

Writes step06_hysteresis.png and step06_hysteresis.csv (u, f_v, loop area and power versus speed).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from rig.teaching.script import argument_parser, write_step
from rig.teaching.hysteresis import KelvinVoigtLayer, cycle_work, roll_on_layer, strain_stress_loop
from rig.teaching.rolling_resistance import ROLLING_COEFFICIENTS

STEM = "step06_hysteresis"
LAYER = KelvinVoigtLayer(modulus_Pa=5e6, viscosity_Pa_s=1.5e4, thickness_m=0.01)  # rubber-like [assumed]
RADIUS_M, WIDTH_M, NORMAL_N = 0.1, 0.02, 200.0  # disc and load [assumed]
SPEEDS_DRAWN = (0.0, 1.0, 3.0)  # [m/s]


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    speeds = np.linspace(0.0, 6.0, 61)
    rows = []
    for v in speeds:
        contact = roll_on_layer(LAYER, RADIUS_M, WIDTH_M, NORMAL_N, v)
        rows.append(dict(speed_m_s=v, shift_m=contact.shift_m, f_v=contact.f_v,
                         loop_area_J_m3=cycle_work(*strain_stress_loop(contact)),
                         dissipation_J_m3=contact.dissipation_per_cycle(), power_W=contact.power_W,
                         contact_length_m=contact.front_m - contact.rear_m))
    table = pd.DataFrame(rows)

    fig = Figure(figsize=(14, 4.3), layout="constrained")
    ax1, ax2, ax3 = fig.subplots(1, 3)
    for index, v in enumerate(SPEEDS_DRAWN):
        contact = roll_on_layer(LAYER, RADIUS_M, WIDTH_M, NORMAL_N, v)
        xi = np.linspace(-1.1 * contact.front_m, 1.1 * contact.front_m, 801)
        p = contact.pressure(xi) / 1e6
        color = f"C{index}"
        ax1.plot(xi * 1e3, p, color=color, label=f"v = {v:g} m/s: u = {contact.shift_m * 1e3:.2f} mm")
        ax1.axvline(contact.shift_m * 1e3, color=color, ls=":", lw=1)
        strain, stress = strain_stress_loop(contact)
        area = max(cycle_work(strain, stress), 0.0)  # 0 up to round-off when elastic
        ax2.plot(strain, stress / 1e6, color=color, label=f"v = {v:g} m/s: area {area / 1e3:.1f} kJ/m$^3$")
        ax2.fill(strain, stress / 1e6, color=color, alpha=0.15)
    ax1.set(xlabel=r"$\xi$ along the travel [mm] (front > 0)", ylabel="contact pressure p [MPa]",
            title="asymmetric pressure; dotted: resultant N at u")
    ax1.legend(fontsize=8)
    ax2.set(xlabel=r"compression strain $\varepsilon$ [1]", ylabel="p [MPa]",
            title=r"p-$\varepsilon$ path of one rim element (Fig. 5.8)")
    ax2.legend(fontsize=8)
    ax3.plot(table.speed_m_s, table.f_v, lw=2, label=r"Kelvin-Voigt rim: $f_v$ = u/R")
    ax3.plot(table.speed_m_s, table.speed_m_s * LAYER.relaxation_time_s / RADIUS_M, "--", color="grey",
             label=r"slow rolling: u $\approx$ v $\eta$/E")
    tyre = ROLLING_COEFFICIENTS[0]
    ax3.axhspan(tyre.low, tyre.high, color="C1", alpha=0.25, label=f"{tyre.pair}, slide 36")
    ax3.set(xlabel="speed v [m/s]", ylabel=r"$f_v$ [1]", ylim=(0, 1.3 * table.f_v.max()),
            title=rf"E = {LAYER.modulus_Pa / 1e6:g} MPa, $\eta$ = {LAYER.viscosity_Pa_s / 1e3:g} kPa s, h = "
                  rf"{LAYER.thickness_m * 1e3:g} mm, R = {RADIUS_M * 1e3:g} mm, N = {NORMAL_N:g} N")
    ax3.title.set_fontsize(9)
    ax3.legend(fontsize=8)
    for ax in (ax1, ax2, ax3):
        ax.grid(alpha=0.3)
    return write_step(fig, table, args.output, STEM)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# Left: at v = 0 the pressure is symmetric and N acts under the centre; at 1 and 3 m/s the front carries more
# and N moves 2.5 and 5.3 mm forward. Middle: the p-eps path of one rim element - a single line when elastic, a
# loop of 25 and 53 kJ/m^3 at 1 and 3 m/s (slide 30: its area is the energy lost per unit volume). Right: f_v =
# u/R starts like v eta/(E R) and saturates; the tyre-road band of slide 36 is crossed near 0.5 m/s with these
# parameters.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

