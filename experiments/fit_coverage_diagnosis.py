"""Why `rig fit`'s Psi intervals miss on stand-A recovery runs (issue 10, acceptance 1-2): one run taken apart.

    python experiments/fit_coverage_diagnosis.py RUN_DIR [RUN_DIR ...]

RUN_DIR: a stand-A run made by experiments/fit_recovery.py's one_repeat (log.h5 + reduced.csv,
truth mu = 0.35, Psi = 1.6). For each run the fit (mu, Psi) is repeated with the data's errors
switched on one at a time, using the log's truth (the gate means of the true signals):

* model error only: y = the true F_y/F_N at the true l/a (no measurement error at all);
* l/a errors only: the true y at the reduced l/a;
* F_y errors only: the measured y at the true l/a;
* everything: the fit `rig fit` makes.
Then the measured-minus-true F_y is split into the calibration form the fit's common covariance
describes (a relative sensitivity error and an offset, eq. 33) and the rest, which is regressed
on the run's own dynamometer drift (rebuilt from the run's seed); and the fit is repeated with
the drift's random-walk covariance added (docs/fit.md, acceptance 1-2). Never imported by rig.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pandas as pd

from rig.fit import parameters as P
from rig.fit.data import Observations
from rig.fit.engine import fit
from rig.fit.forward import ForwardModel
from rig.fit.run import load_data
from rig.logbook.reader import read_settings
from rig.logbook.truth import read_truth

TRUTH = {"mu": 0.35, "psi": 1.6}


def diagnose(run: Path) -> None:
    obs = load_data(run / "reduced.csv")
    reduced = pd.read_csv(run / "reduced.csv")
    points = reduced.loc[np.isfinite(reduced[["l_over_a", "F_y_N", "i_k"]]).all(axis=1), "point"].to_numpy()
    truth = read_truth(run / "log.h5").loc[points]
    f_n = read_settings(run / "log.h5").loc[points, "normal_force_N"].to_numpy()
    y_true = truth["F_y_N"].to_numpy() / f_n  # the gate mean of the true F_y over F_N
    l_true = truth["l_over_a"].to_numpy()
    free = [P.PARAMETERS["mu"], P.PARAMETERS["psi"]]
    memo: dict = {}
    print(f"{run}: {obs.size} points")
    for label, y, l, exact_l in (("everything (rig fit)", obs.y, obs.l, False),
                                 ("model error only", y_true, l_true, True),
                                 ("l/a errors only", y_true, obs.l, False),
                                 ("F_y errors only", obs.y, l_true, True)):
        o = Observations(**{**obs.__dict__, "y": y, "l": l, "u_l": np.zeros(obs.size) if exact_l else obs.u_l})
        result = fit(ForwardModel(o, free, {}, memo), [0.4, 1.3], profile=True, polish="never", scatter=None)
        e = {x.name: x for x in result.estimates}
        hit = ["in" if e[n].lo95 <= TRUTH[n] <= e[n].hi95 else "OUT" for n in ("mu", "psi")]
        print(f"  {label:22s} mu {e['mu'].value:.4f} [{e['mu'].lo95:.4f}, {e['mu'].hi95:.4f}] {hit[0]:3s}  "
              f"Psi {e['psi'].value:.3f} [{e['psi'].lo95:.3f}, {e['psi'].hi95:.3f}] {hit[1]:3s}  s {result.scatter:.1e}")
    model = ForwardModel(obs, free, {}, memo)
    steps = [model.predict([TRUTH["mu"], psi]) for psi in (1.0, 1.6, 2.2)]
    print(f"  Psi's effect on F_y/F_N: 1 -> 1.6 up to {np.abs(steps[1] - steps[0]).max():.1e}, "
          f"1.6 -> 2.2 up to {np.abs(steps[2] - steps[1]).max():.1e}")
    error = obs.y - y_true
    calibration_form = np.column_stack([y_true, 1.0 / f_n])
    rest = error - calibration_form @ np.linalg.lstsq(calibration_form, error, rcond=None)[0]
    common = obs.common_cov
    independent = np.sqrt(np.clip(obs.u**2 - np.diag(common), 0.0, None)) if common is not None else obs.u
    drift = drift_path(run, points)
    with_path = np.column_stack([calibration_form, drift])
    after = error - with_path @ np.linalg.lstsq(with_path, error, rcond=None)[0]
    print(f"  measured - true F_y/F_N beyond the calibration form: rms {np.sqrt(np.mean(rest**2)):.1e}, "
          f"max {np.abs(rest).max():.1e} (stated independent u: median {np.median(independent):.1e}); "
          f"with the run's own drift path regressed out too: rms {np.sqrt(np.mean(after**2)):.1e}")
    for series in np.unique(obs.series):
        at = obs.series == series
        print(f"    {series}: " + " ".join(f"{v:+.1e}" for v in rest[at]))




def drift_path(run: Path, points: np.ndarray) -> np.ndarray:
    """The run's own zero drift in F_y/F_N units at each point: the dynamometer's seeded random walk
    (rig.stands.yoke.instruments.dynamometer) averaged over the point's gate, times gain, over S,
    times the eq. (33) lever, over F_N (the sign as the reduction reads it)."""
    from rig.logbook.reader import read_calibration, read_metadata
    from rig.scenes.load import parse_scene
    from rig.stands.yoke import instruments

    scene = parse_scene(read_metadata(run / "log.h5").scene_toml, name="run", source=str(run))
    stand = scene.build_stand()
    p = stand.params
    amplifier = instruments.dynamometer(scene.effects, scene.seed, scene.seed).amplifier
    sensitivity = read_calibration(run / "log.h5")["dynamometer_10_sensitivity_V_N"].iloc[0]
    f_n = read_settings(run / "log.h5").loc[points, "normal_force_N"].to_numpy()
    gate = scene.procedure.gate_time_s
    out = []
    for k, f in zip(points, f_n):
        t = instruments.calibration_duration_s() + k * p.point_period_s + np.arange(0.0, gate, 1.0 / p.dynamometer_rate_Hz)
        volts = amplifier.gain * float(np.mean(amplifier.drift.sample(t)))
        out.append(volts / sensitivity * p.geometry.dynamometer_lever / p.geometry.yoke_lever / f)
    return np.array(out)


def drift_covariance(run: Path, obs: Observations) -> np.ndarray:
    """Covariance of y = F_y/F_N from the dynamometer's zero drift, a random walk since the
    calibration: input-referred diffusion D [V/s^0.5] times the amplifier gain, so
    cov(V_i, V_j) = (g D)^2 min(t_i, t_j) with t the point's place in the run schedule [s]
    (rig.stands.yoke.instruments), converted with the calibrated sensitivity and the eq. (33) lever."""
    from rig.logbook.reader import read_calibration, read_metadata
    from rig.scenes.load import parse_scene
    from rig.stands.yoke import instruments
    from sensors.dynamometer import STAND_A_GAIN

    reduced = pd.read_csv(run / "reduced.csv")
    points = reduced.loc[np.isfinite(reduced[["l_over_a", "F_y_N", "i_k"]]).all(axis=1), "point"].to_numpy()
    scene = parse_scene(read_metadata(run / "log.h5").scene_toml, name="run", source=str(run))
    stand = scene.build_stand()
    diffusion = scene.effects["dynamometer_drift"]["diffusion_V_per_sqrt_s"] * STAND_A_GAIN
    t = instruments.calibration_duration_s() + points * stand.params.point_period_s + 0.5 * scene.procedure.gate_time_s
    sensitivity = read_calibration(run / "log.h5")["dynamometer_10_sensitivity_V_N"].iloc[0]
    g = stand.params.geometry
    f_n = read_settings(run / "log.h5").loc[points, "normal_force_N"].to_numpy()
    scale = g.dynamometer_lever / g.yoke_lever / sensitivity / f_n  # dy/dV
    return diffusion**2 * np.minimum.outer(t, t) * np.outer(scale, scale)


def with_drift(run: Path) -> None:
    """The fit with the drift's covariance added to the calibration's, and no fitted scatter."""
    obs = load_data(run / "reduced.csv")
    common = obs.common_cov + drift_covariance(run, obs)
    o = Observations(**{**obs.__dict__, "common_cov": common})
    free = [P.PARAMETERS["mu"], P.PARAMETERS["psi"]]
    result = fit(ForwardModel(o, free, {}), [0.4, 1.3], profile=True, polish="never", scatter=None)
    e = {x.name: x for x in result.estimates}
    hit = ["in" if e[n].lo95 <= TRUTH[n] <= e[n].hi95 else "OUT" for n in ("mu", "psi")]
    print(f"  with the drift covariance: mu {e['mu'].value:.4f} [{e['mu'].lo95:.4f}, {e['mu'].hi95:.4f}] {hit[0]}  "
          f"Psi {e['psi'].value:.3f} [{e['psi'].lo95:.3f}, {e['psi'].hi95:.3f}] {hit[1]}  s {result.scatter:.1e}  "
          f"chi2/dof {result.chi2 / result.dof:.2f}")


if __name__ == "__main__":
    for folder in sys.argv[1:]:
        diagnose(Path(folder))
        with_drift(Path(folder))
