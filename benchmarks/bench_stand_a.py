"""Stand A speed: simulated seconds per wall second, with a surrogate-table contact law.

    python benchmarks/bench_stand_a.py [--model rigid] [--n N] [--points 5] [--gate 20] [--markdown FILE]

For each configuration (ideal drive; instruments on; every effect on; the quasi-static drive with
instruments) a sweep of brake set-points is run point by point as the operator would (start from
the previous point's steady state -> settle -> 20 s gate -> read instruments). Reported: the
median wall time of settle, gate and read per point, and the ratio simulated time (settle +
gate) / wall time. Target (issue 4): >= 50x real time for stand A with instruments on, and a
20 s gate well under 0.4 s. The contact-law table is built once (and cached, RIG_CACHE_DIR) before
timing; its build time is reported separately. Wall times depend on the machine's load: run it on
an idle machine.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

from rig.stands.base import ContactSpec, DriveMode
from rig.stands.yoke.stand import YokeStand

INSTRUMENTS = ("dynamometer_noise", "dynamometer_drift", "balance_noise", "counter_pulse_noise",
               "calibration_weight_error")
DYNAMICS = ("drive_compliance", "brake_dynamics", "bearing_friction", "brake_friction_fluctuation")
CONFIGURATIONS = {
    "dynamic, ideal": (DriveMode.DYNAMIC, ()),
    "dynamic, instruments on": (DriveMode.DYNAMIC, INSTRUMENTS),
    "dynamic, every effect on": (DriveMode.DYNAMIC, INSTRUMENTS + DYNAMICS),
    "quasi-static, instruments on": (DriveMode.QUASI_STATIC, INSTRUMENTS),
}


def settings(brake: float) -> dict[str, float]:
    return dict(brake_setpoint_N_m=brake, normal_force_N=96.2, delta_h_m=1.06e-3, omega_1_set_rad_s=25.13)


def run(spec: ContactSpec, drive: DriveMode, effects: tuple[str, ...], points: int, gate: float) -> dict:
    """Time a sweep; medians per point [s] and the real-time ratio [1]."""
    # the sweep crosses l = 0 from l < 0: negative set-points need the load device
    stand = YokeStand({}, {name: {} for name in (*effects, "load_device")}, spec, drive)
    stand.calibrate(1)
    brakes = [-1.0 + 2.2 * k / max(points - 1, 1) for k in range(points)]
    phases = {"settle": [], "gate": [], "read": []}
    simulated = wall = 0.0
    previous = settings(brakes[0] - 0.2)
    for k, brake in enumerate(brakes):
        s = settings(brake)
        t0 = time.perf_counter()
        point = stand.start_point(k, s, previous, 1)
        report = point.settle(60.0)
        t1 = time.perf_counter()
        data = point.gate(gate)
        t2 = time.perf_counter()
        point.read(data)
        t3 = time.perf_counter()
        phases["settle"].append(t1 - t0)
        phases["gate"].append(t2 - t1)
        phases["read"].append(t3 - t2)
        simulated += report.duration_s + gate
        wall += t3 - t0
        previous = s
    return {name: statistics.median(v) for name, v in phases.items()} | {"ratio": simulated / wall}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="rigid", help="contact model of the table (rigid builds fastest)")
    parser.add_argument("--n", type=int, default=None, help="grid cells across 2a (grid models)")
    parser.add_argument("--points", type=int, default=5)
    parser.add_argument("--gate", type=float, default=20.0, help="gate time [s]")
    parser.add_argument("--markdown", type=Path, help="also write the table to this markdown file")
    args = parser.parse_args()
    spec = ContactSpec(args.model, args.n, 0.3, surrogate=True)
    t0 = time.perf_counter()
    YokeStand({}, {}, spec, DriveMode.DYNAMIC).contact_for(settings(0.0))  # build or load the table
    build = time.perf_counter() - t0
    lines = [f"Stand A, {args.model} model table {spec.table_points}, {args.points} points, {args.gate:g} s gate; "
             f"table build/load {build:.2f} s", "",
             "| configuration | settle [s] | gate [s] | read [s] | simulated/wall |", "|---|---|---|---|---|"]
    for name, (drive, effects) in CONFIGURATIONS.items():
        r = run(spec, drive, effects, args.points, args.gate)
        lines.append(f"| {name} | {r['settle']:.3f} | {r['gate']:.3f} | {r['read']:.3f} | {r['ratio']:.0f}x |")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        args.markdown.write_text(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
