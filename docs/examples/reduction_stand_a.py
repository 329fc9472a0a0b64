"""Worked operating point of stand A, counts -> mu_T with its uncertainty budget (docs/reduction.md).

Run from the repository root:  python docs/examples/reduction_stand_a.py
The readings were produced by forward-simulating stand A with mu = 0.4 at l/a = 0.3 (kinematic
model, line contact b/a = 1, Poisson ratio 0.3, n = 16, with the first-order transport the solver
had until 2026-11), then rounded as the instruments would round them (counts are integers, 0.1 mV on the dynamometer, the balance steps by 0.0196 N m).
A single reading of a scale with step Delta carries the step's bias as u_step = Delta/sqrt(12)
(rectangular; rig.reduction.readings.Measured); the counts carry the counters' 1/sqrt(6).
"""

from __future__ import annotations

import functools
import math

from rig.contact.solve import solve
from rig.reduction import stand_a
from rig.reduction.geometry import StandAGeometry
from rig.reduction.readings import ForceCalibration, Measured

GEOMETRY = StandAGeometry()  # the Equations page's defaults, Delta h = 1.06 mm
NORMAL_FORCE = 96.2  # [N]
B_OVER_A = GEOMETRY.b_over_a(NORMAL_FORCE)  # 1.0
READINGS = stand_a.StandAReadings(
    counts_1=4800, counts_2=3834, marks_1=60, marks_2=60,  # 60 marks per disc [assumed], 20 s gate
    gate_time=Measured(20.0, 1e-4),  # [s]
    normal_force=Measured(NORMAL_FORCE, 0.5),  # [N], spring setting
    dynamometer_signal=Measured(0.0731, 0.0, 0.1e-3 / math.sqrt(12)),  # [V], one reading of a 0.1 mV display
    dynamometer=ForceCalibration(
        sensitivity=0.0100, offset=0.0020, u_sensitivity=1e-5, u_offset=1e-4, covariance=-0.5e-9,
        u_weights=GEOMETRY.weights_half_width / math.sqrt(3),  # +-10 gf weights (not in this fit), rectangular
    ),
    brake_moment=Measured(0.4508, 0.0, GEOMETRY.balance_moment_step / math.sqrt(12)),  # [N m], one reading
    b_over_a=B_OVER_A,
)


def kinematic_coefficients(l_over_a: float, c_over_a: float, alpha: float) -> tuple[float, float, float]:
    r = solve("kinematic", shape="line", b_over_a=B_OVER_A, alpha=alpha, c_over_a=c_over_a,
              l_over_a=l_over_a, poisson=0.3, n=16)
    return r.nu_T, r.nu_v, r.nu_0


def report(point) -> str:
    """The worked example as markdown tables."""
    lines = ["| input | value | u | unit | distribution | source |", "|---|---|---|---|---|---|"]
    for q in point.propagation.inputs.quantities:
        lines.append(f"| {q.name} | {q.value:.6g} | {q.u:.3g} | {q.unit} | {q.distribution.value} | {q.source} |")
    lines += ["", "| output | value | u | U95 |", "|---|---|---|---|"]
    for name, value in point.values.items():
        lines.append(f"| {name} | {value:.6g} | {point.uncertainties[name]:.3g} | {point.expanded[name]:.3g} |")
    lines += ["", f"mu <-> alpha' iterations: {point.iterations}; {point.driver} drives alpha'", ""]
    shown = ["l_over_a", "c_over_a", "alpha_prime", "mu_v", "mu_T"]
    table = point.budget.uncertainty_by_source()[shown]
    lines += ["| source | " + " | ".join(f"u({n})" for n in shown) + " |", "|---" * (len(shown) + 1) + "|"]
    for source, row in table.iterrows():
        lines.append(f"| {source} | " + " | ".join(f"{x:.2g}" for x in row) + " |")
    lines.append("| **total** | " + " | ".join(f"{point.uncertainties[n]:.2g}" for n in shown) + " |")
    return "\n".join(lines)


def main() -> str:
    return report(stand_a.reduce(READINGS, functools.partial(kinematic_coefficients)))


if __name__ == "__main__":
    print(main())
