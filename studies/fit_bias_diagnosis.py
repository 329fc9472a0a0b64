"""Where `rig fit`'s mu goes on stand-A recovery runs: the error chain taken apart.

    python studies/fit_bias_diagnosis.py --psi 1.6 RUN_DIR [RUN_DIR ...]
    python studies/fit_bias_diagnosis.py --calibrations 1000

RUN_DIR: runs kept by ``experiments/fit_recovery.py --keep DIR`` (truth mu = 0.35, Psi as given).
Per run, (mu, Psi) and mu alone (Psi at the truth) are fitted as ``rig fit`` does (engine.fit,
scatter estimated) to the data with its errors added one at a time, from the log's truth (gate
means of the true signals) and the dynamometer's own true sensitivity and drift path:

* model: the true F_y/F_N at the true l/a (the forward model against the simulation);
* + l/a: the true F_y/F_N at the reduced l/a;
* + drift: the gate-mean reading converted with the true sensitivity and the zero the calibration
  saw (the drift since then and the noise stay in);
* + calibration: the measured F_y/F_N at the reduced l/a (what rig fit fits).

Printed per run: the calibration's relative sensitivity error dS/S and the estimates; then per
variant the mean of the estimates over the runs and that mean corrected for the runs' own
calibration draws (the intercept of mu - 0.35 regressed on dS/S, with its standard error): a
study of 40 repeats shares 40 calibration draws whose mean has a standard error of
1.35 %/sqrt(40) = 0.21 % in S. --calibrations N: dS/S over N seeded calibrations alone (is the
calibration unbiased, and is its stated u honest?). Never imported by rig.
"""

from __future__ import annotations

import argparse
from importlib import resources
from pathlib import Path

import numpy as np
import pandas as pd

from rig.fit import parameters as P
from rig.fit.data import Observations
from rig.fit.engine import fit
from rig.fit.forward import ForwardModel
from rig.fit.run import load_data
from rig.logbook.reader import read_calibration, read_metadata, read_settings
from rig.logbook.truth import read_truth
from rig.scenes.load import parse_scene
from rig.stands.yoke import instruments

MU = 0.35
VARIANTS = ("model", "+ l/a", "+ drift", "+ calibration")


def variants(run: Path, obs: Observations) -> tuple[dict[str, Observations], float]:
    """The four data variants of a run (module docstring) and its calibration's dS/S."""
    log = run / "log.h5"
    reduced = pd.read_csv(run / "reduced.csv").set_index("point")
    points = reduced.index[np.isfinite(reduced[["l_over_a", "F_y_N", "i_k"]]).all(axis=1)].to_numpy()
    truth = read_truth(log).loc[points]
    f_n = read_settings(log).loc[points, "normal_force_N"].to_numpy()
    scene = parse_scene(read_metadata(log).scene_toml, name="run", source=str(run))
    g = scene.build_stand().params.geometry
    lever = g.dynamometer_lever / g.yoke_lever
    cal = read_calibration(log).loc[points]
    sensitivity = cal["dynamometer_10_sensitivity_V_N"].iloc[0]
    offset = cal["dynamometer_10_offset_V"].iloc[0]
    dynamometer = instruments.dynamometer(scene.effects, scene.seed, scene.seed)
    amplifier = dynamometer.amplifier
    t_calibration = np.arange(0.0, instruments.calibration_duration_s(), 1.0 / instruments.CALIBRATION_RATE_HZ)
    zero = amplifier.gain * float(np.mean(amplifier.drift.sample(t_calibration))) if amplifier.drift else 0.0
    reading = reduced.loc[points, "F_y_N"].to_numpy() / lever * sensitivity + offset  # gate mean [V] (eq. 33)
    y_true = truth["F_y_N"].to_numpy() / f_n
    y_drift = (reading - zero) / dynamometer.nominal_sensitivity_V_per_N * lever / f_n
    exact = np.zeros(obs.size)

    def data(y, l, u_l):
        return Observations(**{**obs.__dict__, "y": y, "l": l, "u_l": u_l})

    out = dict(zip(VARIANTS, (data(y_true, truth["l_over_a"].to_numpy(), exact), data(y_true, obs.l, obs.u_l),
                              data(y_drift, obs.l, obs.u_l), obs)))
    return out, sensitivity / dynamometer.nominal_sensitivity_V_per_N - 1


def diagnose(runs: list[Path], psi: float) -> pd.DataFrame:
    """One row per run: dS/S and per variant mu (Psi free), Psi, and mu (Psi fixed at the truth)."""
    rows = []
    for run in runs:
        data, ds = variants(run, load_data(run / "reduced.csv"))
        row = {"run": run.name, "dS/S": ds}
        memo: dict = {}
        for name, obs in data.items():
            both = fit(ForwardModel(obs, [P.PARAMETERS["mu"], P.PARAMETERS["psi"]], {}, memo), [0.4, 1.3],
                       profile=False, polish="never", scatter=None)
            alone = fit(ForwardModel(obs, [P.PARAMETERS["mu"]], {"psi": psi}, memo), [0.4], profile=False,
                        polish="never", scatter=None)
            row.update({f"mu {name}": both.estimates[0].value, f"psi {name}": both.estimates[1].value,
                        f"mu|psi {name}": alone.estimates[0].value})
        rows.append(row)
        print("  ".join(f"{k} {v:.5g}" if isinstance(v, float) else f"{k} {v}" for k, v in row.items()), flush=True)
    return pd.DataFrame(rows)


def summarise(table: pd.DataFrame) -> None:
    x = np.column_stack([np.ones(len(table)), table["dS/S"]])
    print(f"{len(table)} runs; the calibrations' mean dS/S {table['dS/S'].mean():+.4%} "
          f"+- {table['dS/S'].std(ddof=1) / np.sqrt(len(table)):.4%}")
    print(f"{'estimate':22s} {'mean':>8s} {'mean - 0.35':>12s} {'at dS/S = 0':>12s} {'+-':>8s}")
    for column in table.columns[2:]:
        if column.startswith("psi"):
            continue
        coef, *_ = np.linalg.lstsq(x, table[column] - MU, rcond=None)
        rest = table[column] - MU - x @ coef
        se = np.sqrt(rest.var(ddof=2) / len(table))
        print(f"{column:22s} {table[column].mean():8.5f} {table[column].mean() - MU:+12.5f} {coef[0]:+12.5f} "
              f"{se:8.5f}")


def calibrations(count: int) -> None:
    text = resources.files("rig.scenes.builtin").joinpath("fig10.toml").read_text(encoding="utf-8")
    scene = parse_scene(text, name="fig10", source="fig10.toml")
    params = scene.build_stand().params
    ds, z = [], []
    for seed in range(10_000, 10_000 + count):
        record = instruments.calibrate(params, scene.effects, seed)
        true = instruments.dynamometer(scene.effects, seed, seed).nominal_sensitivity_V_per_N
        ds.append(record.sensitivity / true - 1)
        z.append((record.sensitivity - true) / record.u_sensitivity)
    ds, z = np.array(ds), np.array(z)
    print(f"{count} calibrations (fig10's effects, seeds 10000-{10_000 + count - 1}): mean dS/S {ds.mean():+.4%} "
          f"+- {ds.std(ddof=1) / np.sqrt(count):.4%}, spread {ds.std(ddof=1):.3%}, rms of (S - S_true)/u(S) "
          f"{np.sqrt(np.mean(z**2)):.3f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="*", type=Path)
    parser.add_argument("--psi", type=float, default=1.6, help="the runs' true Psi")
    parser.add_argument("--calibrations", type=int, default=0, help="check N seeded calibrations instead")
    args = parser.parse_args()
    if args.calibrations:
        calibrations(args.calibrations)
    if args.runs:
        summarise(diagnose(args.runs, args.psi))


if __name__ == "__main__":
    main()
