"""
What accuracy costs in the lab: the gate time
=============================================

One stand-A operating point from raw counts and bridge voltages to mu_T with its uncertainty budget, and the
uncertainty of l/a and mu_T versus the gate time.

Run it from the repository root::

    python experiments/gate_time.py [--out DIR] [--model kinematic|rigid]

[Koziarski] section 3.1.2 promises "arbitrarily high accuracy ... provided that measurement time was
sufficiently long". This script measures how true that is on the digital twin of stand A
(rig.stands.yoke, quasi-static drive, instruments from sensors/ with noise and the calibration
weights' errors on): for each gate time T it simulates the point, reduces it (rig.reduction) and
records the stated uncertainties and their budget. Outputs in DIR (default ./gate_time_out):
walkthrough.md (the point at T = 20 s, step by step), gate_time.csv (one row per T) and
gate_time.png (u(l/a) and u(mu_T) versus T, with the 1/T line of counting). Runtime < 1 min
(kinematic model n = 16 called directly, no surrogate table). Page: docs/measurement-method.md;
the lesson itself is rig.teaching.gate_time.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rig.teaching.gate_time import MODELS, run


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="What accuracy costs in the lab: the gate time")
    parser.add_argument("--out", type=Path, default=Path("gate_time_out"), help="output folder")
    parser.add_argument("--model", choices=sorted(MODELS), default="kinematic", help="contact model (n = 16)")
    args = parser.parse_args(argv)
    text, frame = run(args.out, MODELS[args.model])
    print(text)
    print()
    shown = ["gate_time_s", "N1_count", "u_l_over_a", "u_mu_T", "U95_mu_T", "error_l_over_a", "error_mu_T"]
    print(frame[shown].to_string(index=False, float_format=lambda x: f"{x:.3g}"))
    print(f"\nwritten: {', '.join(str(args.out / n) for n in ('walkthrough.md', 'gate_time.csv', 'gate_time.png'))}")
    return 0


# %%
# Simulate the point at each gate time, reduce it, and write the walkthrough, the table and the figure: the
# counting part of u(l/a) falls as 1/T, until the dynamometer's and the balance's resolutions dominate u(mu_T).

if __name__ == "__main__":
    main()
