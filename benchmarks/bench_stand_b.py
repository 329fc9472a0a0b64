"""Stand B speed: simulated seconds per wall second, with the surrogate contact law.

    python benchmarks/bench_stand_b.py [--model fastsim] [--n 16] [--gate 10] [--repeats 3]

For each configuration (rigid loop; momentometer loop compliance; loop + backlash + bearing
friction + contact relaxation; quasi-static) with the recorder on and its noise and drift:
one operating point at 36 N, l = 10 mm, sigma = 0.1 rad, 24 rpm, started from the steady state
of l = 0 - the median over repeats of the settle time (simulated / wall), the gate of
``--gate`` seconds (simulated / wall) and the instrument read. Target (brief): a 10 s gate at a
few hundred Hz in < 0.5 s with the surrogate. The table is built once (cached on disk,
RIG_CACHE_DIR) and its build is not timed. Also: the swinging drive over two periods.
"""

from __future__ import annotations

import argparse
import statistics
import time

from rig.stands.base import ContactSpec, DriveMode
from rig.stands.disc_roller.stand import DiscRollerStand

INSTRUMENTS = {"recorder_noise": {}, "dynamometer_drift": {}}
CONFIGURATIONS = {
    "rigid loop": ({}, DriveMode.DYNAMIC),
    "loop compliance": ({"loop_compliance": {}}, DriveMode.DYNAMIC),
    "loop + backlash + friction + relaxation": (
        {"loop_compliance": {}, "gear_backlash": {}, "bearing_friction": {}, "contact_relaxation": {}},
        DriveMode.DYNAMIC,
    ),
    "quasi-static": ({"loop_compliance": {}}, DriveMode.QUASI_STATIC),
}
POINT = dict(normal_force_N=36.0, l_m=0.010, sigma_rad=0.1, speed_step=1, direction=1)
PREVIOUS = dict(POINT, l_m=0.0)


def measure(stand: DiscRollerStand, gate_time: float) -> tuple[float, float, float, float, float]:
    """(settle simulated [s], settle wall [s], gate wall [s], read wall [s]) of one point."""
    point = stand.start_point(0, POINT, PREVIOUS, 1)
    t0 = time.perf_counter()
    report = point.settle(30.0)
    t1 = time.perf_counter()
    gate = point.gate(gate_time)
    t2 = time.perf_counter()
    point.read(gate)
    t3 = time.perf_counter()
    return report.duration_s, t1 - t0, t2 - t1, t3 - t2, gate.t_s.size


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="fastsim")
    parser.add_argument("--n", type=int, default=16)
    parser.add_argument("--gate", type=float, default=10.0)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    spec = ContactSpec(args.model, args.n, 0.5)
    print(f"stand B, {args.model} n = {args.n} surrogate table {spec.table_points}, gate {args.gate:g} s, "
          f"median of {args.repeats}")
    print(f"{'configuration':42s} {'settle sim/wall':>16s} {'gate wall [s]':>14s} {'gate sim/wall':>14s} "
          f"{'read [s]':>9s} {'samples':>8s}")
    for name, (effects, drive) in CONFIGURATIONS.items():
        stand = DiscRollerStand({}, effects | INSTRUMENTS, spec, drive)
        stand.law(stand.params.b_over_a(POINT["normal_force_N"]))  # build or load the table (not timed)
        stand.calibrate(1)
        runs = [measure(stand, args.gate) for _ in range(args.repeats)]
        settle_sim, settle_wall, gate_wall, read_wall, samples = (statistics.median(r[i] for r in runs)
                                                                   for i in range(5))
        settle_rate = settle_sim / settle_wall if settle_sim > 0 else float("nan")
        print(f"{name:42s} {settle_rate:16.2f} {gate_wall:14.4f} {args.gate / gate_wall:14.0f} "
              f"{read_wall:9.4f} {samples:8.0f}")
    swing = DiscRollerStand({}, {"swinging_drive": {}, "contact_relaxation": {}} | INSTRUMENTS, spec,
                            DriveMode.DYNAMIC)
    point = swing.start_point(0, POINT, None, 1)
    point.settled = True  # time two periods from the start, without the settle search
    period = 1.0 / swing.effects["swinging_drive"]["frequency_Hz"]
    t0 = time.perf_counter()
    point.gate(2.0 * period)
    wall = time.perf_counter() - t0
    print(f"{'swinging drive (rigid loop), 2 periods':42s} {'':16s} {wall:14.4f} {2.0 * period / wall:14.1f}")


if __name__ == "__main__":
    main()
