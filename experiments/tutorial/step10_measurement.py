"""
Step 10: the measurement method
===============================

The paper's measurement method on stand A ([Koziarski] section 3.1.2, eqs. 29-35).

Runs the stand-A scene (default: the built-in `default` scene, as `rig run` does): the brake
moment T2 on wheel 2 moves the rolling point along the contact line; at each set-point the
counters give i_k, the dynamometer F_y, the tangent balance T2. The reduction turns them into
l/a (eq. 30), alpha' (eq. 21), the model's nu_T, nu_v, nu_0 at that state (eqs. 26-28) and
finally mu_v = F_y/(F_N nu_v) (eq. 33) and mu_T (eq. 35), each with its uncertainty - to be held
against the mu = 0.4 the virtual stand was built with.

Run it from the repository root::

    python experiments/tutorial/step10_measurement.py [-o out/tutorial] [--scene default]

Writes the run (log.h5, reduced.csv, summary.txt, ...) into <output>/step10_run_<scene>/ and
step10_measurement.png and step10_measurement.csv (readings and reduced values per point).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from matplotlib.figure import Figure

import rig
from rig.teaching.script import argument_parser, write_step

STEM = "step10_measurement"
TEX = {"nu_T": r"$\nu_T$", "nu_v": r"$\nu_v$", "nu_0": r"$\nu_0$", "mu_v": r"$\mu_v$ (eq. 33)",
       "mu_T": r"$\mu_T$ (eq. 35)"}


def arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argument_parser(__doc__)
    parser.add_argument("--scene", default="default",
                        help="stand-A scene: built-in name or .toml path (default: default; fast: "
                             "experiments/tutorial/stand_a_quick.toml)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> list[Path]:
    args = arguments(argv)
    scene = rig.load_scene(args.scene)
    result = rig.run(scene, args.output / f"step10_run_{scene.name}")  # simulate, log and reduce, as `rig run`
    # what the operator set and the balance read at each point (the log's groups), next to the reduction
    readings = result.log["settings"][["brake_setpoint_N_m"]].join(result.log["readings"][["T2_N_m"]])
    table = readings.join(result.reduced, how="inner")
    columns = ["brake_setpoint_N_m", "T2_N_m", "i_k", "F_y_N", "l_over_a", "u_l_over_a", "true_l_over_a",
               "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "u_mu_v", "mu_T", "u_mu_T", "true_mu_v", "true_mu_T"]

    fig = Figure(figsize=(15, 4.4), layout="constrained")
    ax1, ax2, ax3, ax4 = fig.subplots(1, 4)
    ax1.plot(table.T2_N_m, table.i_k, "o-", label=r"counters: $i_k = N_2 z_1/(N_1 z_2)$")
    ax1.set(xlabel="balance: brake moment T2 [N m]", ylabel=r"$i_k$ [1]", title="1. what the instruments read")
    force = ax1.twinx()
    force.plot(table.T2_N_m, table.F_y_N, "s--", color="C1", label=r"dynamometer: $F_y$")
    force.set_ylabel(r"$F_y$ [N]", color="C1")
    handles = ax1.get_legend_handles_labels()[0] + force.get_legend_handles_labels()[0]
    ax1.legend(handles, [h.get_label() for h in handles], loc="lower center", fontsize=8)
    ax2.errorbar(table.T2_N_m, table.l_over_a, yerr=table.u_l_over_a, fmt="o", capsize=3, label="l/a from i_k (eq. 30)")
    ax2.plot(table.T2_N_m, table.true_l_over_a, "k-", lw=0.8, label="truth (simulation)")
    ax2.set(xlabel="brake moment T2 [N m]", ylabel="l/a [1]", title="2. the brake moves the rolling point")
    ax2.legend(fontsize=8)
    for index, key in enumerate(("nu_T", "nu_v", "nu_0")):
        ax3.plot(table.l_over_a, table[key], "o-", color=f"C{index}", label=TEX[key])
    ax3.set(xlabel="l/a", ylabel="[1]",
            title=rf"3. model at the measured state ($\alpha'$ = {table.alpha_prime.median():.2f})")
    ax3.legend(fontsize=8)
    for index, key in enumerate(("mu_v", "mu_T")):
        ax4.errorbar(table.l_over_a, table[key], yerr=table[f"u_{key}"], fmt="os"[index], capsize=3,
                     color=f"C{index + 3}", label=TEX[key])
    ax4.plot(table.l_over_a, table.true_mu_T, "k-", lw=0.8, label=r"truth $\mu$")
    ax4.set(xlabel="l/a", ylabel=r"$\mu$ [1]", ylim=(0.0, 0.8), title="4. friction coefficients recovered")
    ax4.legend(fontsize=8)
    for ax in (ax1, ax2, ax3, ax4):
        ax.grid(alpha=0.3)
    fig.suptitle(f"scene {scene.name}: {len(table)} points, {int(table.mu_v.isna().sum())} without mu_v", fontsize=10)
    return write_step(fig, table[columns], args.output, STEM, index=True)


# %%
# Run the step: it writes the figure and the numbers behind it (a CSV with units in the column
# names) into its output folder, ``out/tutorial`` unless ``-o`` says otherwise.

if __name__ == "__main__":
    print("wrote", *main())

# %%
# **What to look at.**
# Panel 1: what the instruments read - the brake moment changes the speed ratio (and F_y). Panel 2: the rolling
# point from the counts follows the simulation's truth within its uncertainty over l/a = -1 ... 1. Panel 3: the
# model coefficients at the measured states. Panel 4: mu_v and mu_T agree with the mu = 0.4 the stand was built
# with.
#
# The questions that go with this step, and their answers, are on the tutorial page of the user guide.

