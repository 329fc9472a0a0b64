"""The gate-time lesson (docs/measurement-method.md): one stand-A operating point from raw counts and
bridge voltages to mu_T with its uncertainty budget, and the uncertainty of l/a and mu_T versus the gate time.

[Koziarski] section 3.1.2 promises "arbitrarily high accuracy ... provided that measurement time was
sufficiently long". This lesson measures how true that is on the digital twin of stand A
(rig.stands.yoke, quasi-static drive, instruments from sensors/ with noise and the calibration
weights' errors on): for each gate time T it simulates the point, reduces it (rig.reduction,
[Koziarski] eqs. (29)-(35)) and records the stated uncertainties and their budget.
:func:`run` writes walkthrough.md (the point at T = 20 s, step by step), gate_time.csv (one row per
T) and gate_time.png (u(l/a) and u(mu_T) versus T, with the 1/T line of counting).
experiments/gate_time.py is its command line.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.reduction import stand_a
from rig.reduction.result import ReducedPoint
from rig.stands.base import ContactSpec, DriveMode, PointOutcome
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.reduction import point_readings
from rig.stands.yoke.stand import YokeStand
from sensors.dynamometer import STAND_A_GAIN

GATES_S = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0)  # gate times of the sweep [s]
WALKTHROUGH_GATE_S = 20.0  # the paper's order of magnitude: ~4800 counts at 240 rpm, 60 marks [s]
SETTINGS = dict(brake_setpoint_N_m=0.6, normal_force_N=96.2, delta_h_m=1.06e-3, omega_1_set_rad_s=25.13)
EFFECTS = ("dynamometer_noise", "balance_noise", "calibration_weight_error")
MODELS = {"kinematic": ContactSpec("kinematic", 16, 0.3, surrogate=False),
          "rigid": ContactSpec("rigid", None, 0.3, surrogate=False)}
SEED = 240


@dataclass(frozen=True)
class Measured:
    """One simulated and reduced gate: the log record and truth, the readings, the reduced point."""

    gate_time_s: float
    outcome: PointOutcome
    readings: stand_a.StandAReadings
    reduced: ReducedPoint


def make_stand(spec: ContactSpec) -> YokeStand:
    """Stand A at mu = 0.4, quasi-static, with the instrument effects the reduction's u covers."""
    return YokeStand({"mu": 0.4}, {name: {} for name in EFFECTS}, spec, DriveMode.QUASI_STATIC)


def measure(stand: YokeStand, gate_time_s: float, seed: int = SEED) -> Measured:
    """Simulate the operating point for one gate [s] and reduce it with the stand's own law."""
    geometry = stand.params.geometry_at(SETTINGS["delta_h_m"])
    law = LawCoefficients(*stand.law(geometry.b_over_a(SETTINGS["normal_force_N"]), geometry))
    stand.calibrate(seed)
    point = stand.start_point(0, SETTINGS, None, seed)
    point.settle(30.0)
    outcome = point.read(point.gate(gate_time_s))
    readings = point_readings(outcome.record, stand.params, geometry, f"gate {gate_time_s:g} s")
    return Measured(gate_time_s, outcome, readings, stand_a.reduce(readings, law, geometry))


def walkthrough(m: Measured) -> str:
    """The operating point from the raw readings to mu_T, as markdown (docs/measurement-method.md)."""
    rec, r, p = m.outcome.record, m.readings, m.reduced
    v, u, big_u = p.values, p.uncertainties, p.expanded
    cal = rec.calibration["dynamometer_10"]
    volts = np.asarray(rec.channels["dynamometer_10"].samples)
    balance = np.asarray(rec.channels["tangent_balance"].samples)
    truth = {k: q.value for k, q in m.outcome.truth.items()}
    lines = [
        f"Raw readings of one {m.gate_time_s:g} s gate:",
        "",
        "| instrument | raw reading | as the reduction takes it |",
        "|---|---|---|",
        f"| counters 18/19 ({r.marks_1} marks) | N1 = {r.counts_1}, N2 = {r.counts_2} | "
        "u = 1/sqrt(6) = 0.408 count each (triangular) |",
        f"| dynamometer 10 | {volts.size} samples, mean {volts.mean() * 1e3:.3f} mV at the converter = "
        f"{volts.mean() / STAND_A_GAIN * 1e6:.2f} uV at the bridge | u(mean) = {r.dynamometer_signal.u * 1e6:.2f} uV |",
        f"| calibration (weights) | S = {cal['sensitivity'].value:.5f} V/N, s0 = {cal['offset'].value * 1e3:.3f} mV, "
        f"u(S)/S = {cal['u_sensitivity'].value / cal['sensitivity'].value * 100:.2f} % | "
        "covariance holds the weights |",
        f"| tangent balance | {balance.size} readings, mean T2 = {r.brake_moment.value:.4f} N m "
        f"(step {rec.readings['balance_resolution'].value:.4g} N m) | "
        f"u(scatter) = {r.brake_moment.u * 1e3:.2f} mN m, u(step) = {r.brake_moment.u_step * 1e3:.2f} mN m |",
        f"| spring 5 | F_N = {r.normal_force.value:g} N | u = {r.normal_force.u:g} N (assumed) |",
        "",
        "The chain (eqs. 29-35), value +- u [U95], truth:",
        "",
        "| step | quantity | value | u | U95 | truth |",
        "|---|---|---|---|---|---|",
    ]
    steps = [("counts", "i_k = N2 z1/(N1 z2)", "i_k", "i_k"), ("(29)-(30)", "l/a", "l_over_a", "l_over_a"),
             ("(31)-(32)", "c/a", "c_over_a", "c_over_a"), ("(21)", "alpha'", "alpha_prime", "alpha_prime"),
             ("model", "nu_T", "nu_T", "nu_T"), ("model", "nu_v", "nu_v", "nu_v"), ("model", "nu_0", "nu_0", "nu_0"),
             ("(33) lever", "F_y [N]", "F_y_N", "F_y"), ("(35) lever", "D [mm]", "D_m", None),
             ("(33)", "mu_v", "mu_v", "mu_v"), ("(35)", "mu_T", "mu_T", "mu_T")]
    for step, label, name, true in steps:
        scale = 1e3 if name == "D_m" else 1.0
        t = f"{truth[true]:.5g}" if true in truth else "-"
        lines.append(f"| {step} | {label} | {v[name] * scale:.5g} | {u[name] * scale:.2g} | {big_u[name] * scale:.2g} "
                     f"| {t} |")
    by = p.budget.uncertainty_by_source()
    lines += ["", "Budget (the u each instrument alone would cause):", "",
              "| source | u(l/a) | u(mu_v) | u(mu_T) |", "|---|---|---|---|"]
    for source, row in by.iterrows():
        if row[["l_over_a", "mu_v", "mu_T"]].abs().max() > 0:
            lines.append(f"| {source} | {row['l_over_a']:.2g} | {row['mu_v']:.2g} | {row['mu_T']:.2g} |")
    lines.append(f"| **total** | {u['l_over_a']:.2g} | {u['mu_v']:.2g} | {u['mu_T']:.2g} |")
    return "\n".join(lines)


def sweep_row(m: Measured) -> dict[str, float]:
    """One row of the gate-time table: counts, reduced values, stated u, U95, errors against the truth,
    and u(mu_T) by source."""
    p, truth = m.reduced, m.outcome.truth
    row = {"gate_time_s": m.gate_time_s, "N1_count": m.readings.counts_1, "balance_readings": len(
        m.outcome.record.channels["tangent_balance"].samples)}
    for name in ("l_over_a", "mu_v", "mu_T"):
        row[name] = p.values[name]
        row[f"u_{name}"] = p.uncertainties[name]
        row[f"U95_{name}"] = p.expanded[name]
        row[f"error_{name}"] = p.values[name] - truth[name].value
    for source, u in p.budget.uncertainty_by_source()["mu_T"].items():
        row["u_mu_T_from_" + "_".join(source.replace("(", "").replace(")", "").split())] = float(u)
    return row


def plot(frame: pd.DataFrame, path: Path) -> Path:
    """u(l/a) and u(mu_T) versus T on log axes, with the counters' 1/T and the floor of mu_T."""
    from rig.plotting import new_figure

    t = frame["gate_time_s"].to_numpy()
    fig = new_figure(figsize=(10, 4))
    axes = fig.subplots(1, 2)
    counting = frame["u_l_over_a"].to_numpy()
    axes[0].loglog(t, counting, "o-", label="u(l/a), stated")
    axes[0].loglog(t, counting[0] * t[0] / t, "k--", lw=0.8, label="1/T (counting)")
    axes[0].loglog(t, np.abs(frame["error_l_over_a"]), "x", label="|error| (one run)")
    axes[0].set_title("rolling point l/a")
    axes[1].loglog(t, frame["u_mu_T"], "o-", label="u(mu_T), stated")
    floor_columns = [c for c in frame.columns if c.startswith("u_mu_T_from_") and "counter" not in c]
    floor = np.sqrt((frame[floor_columns].to_numpy() ** 2).sum(axis=1))
    axes[1].loglog(t, floor, "k--", lw=0.8, label="all but the counters")
    axes[1].loglog(t, np.abs(frame["error_mu_T"]), "x", label="|error| (one run)")
    axes[1].set_title("friction coefficient mu_T (eq. 35)")
    for ax in axes:
        ax.set_xlabel("gate time T [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    axes[0].set_ylabel("standard uncertainty [1]")
    fig.suptitle("Stand A, F_N = 96.2 N, l/a ~ 0.38, mu = 0.4: what a longer gate buys")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path


def run(out: Path, spec: ContactSpec, gates=GATES_S) -> tuple[str, pd.DataFrame]:
    """Walkthrough text and gate-time table; writes walkthrough.md, gate_time.csv and gate_time.png to out."""
    out.mkdir(parents=True, exist_ok=True)
    stand = make_stand(spec)
    measured = {t: measure(stand, t) for t in sorted(set(gates) | {WALKTHROUGH_GATE_S})}
    text = walkthrough(measured[WALKTHROUGH_GATE_S])
    frame = pd.DataFrame([sweep_row(measured[t]) for t in gates])
    (out / "walkthrough.md").write_text(text + "\n", encoding="utf-8")
    frame.to_csv(out / "gate_time.csv", index=False, float_format="%.6g")
    plot(frame, out / "gate_time.png")
    return text, frame
