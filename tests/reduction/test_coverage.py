"""Acceptance 2: the stated uncertainty is honest - closed loop on synthetic signals of stand A.

A stand-A operating point (96.2 N, b/a = 1, Delta h = 1.06 mm, 240 rpm, mu = 0.4, rigid contact
law through a tiny surrogate table, quasi-static drive) is simulated REPEATS times with every
instrument effect the reduction's uncertainty model covers (dynamometer noise and drift, balance
noise, the calibration weights' errors); per repeat the instrument streams are re-drawn (seed =
repeat) and the operating point moves by a random fraction: brake set-point in [0.5, 0.7] N m,
wheel-1 speed in [24.9, 25.4] rad/s. That spread is needed: the counters' +-1 count and the
balance's scale step are deterministic functions of the true values, so a fixed truth would test
one draw of them; the uncertainty model (like GUM) treats the truth's position within a count or
a step as unknown and uniform, which is what the spread realises. The pressing force is read
with its stated u (0.5 N, the stand's normal_force_u_N): the twin sets F_N exactly, so the test
adds that reading error itself. Each repeat is reduced with rig.stands.yoke.reduction (the log
adapter) and rig.reduction.stand_a; the truth is the point's truth record.

Measured (REPEATS = 200, 5 s gates; docs/reduction.md section 4): the share of repeats whose
true value lies in value +- U95 is 94.5 % (l/a), 94.5 % (c/a), 96.0 % (mu_v), 94.0 % (mu_T); the
rms of error/u is 0.96-0.98. The counters' missed pulses (effect counter_pulse_noise) are not in
the model and are left out here: at 3.2e-5 misses per pulse they bias a 4800-count gate by
-0.15 count (l/a then covers 82 % at 20 s gates).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rig.reduction import stand_a
from rig.reduction.readings import Measured
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.reduction import point_readings
from rig.stands.yoke.stand import YokeStand

REPEATS = 200
GATE_S = 5.0  # [s]: 1200 counts per wheel, 5 balance readings (the counters' simulation costs ~ the counts)
SEED = 2024
NAMES = ("l_over_a", "c_over_a", "mu_v", "mu_T")
EFFECTS = ("dynamometer_noise", "dynamometer_drift", "balance_noise", "calibration_weight_error")


def operating_point(rng: np.random.Generator) -> dict[str, float]:
    return dict(brake_setpoint_N_m=float(rng.uniform(0.5, 0.7)), normal_force_N=96.2, delta_h_m=1.06e-3,
                omega_1_set_rad_s=float(rng.uniform(24.9, 25.4)))


@pytest.fixture(scope="module")
def repeats(tmp_path_factory):
    """(errors [repeat, quantity], u, U95) over REPEATS reduced repeats."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("RIG_CACHE_DIR", str(tmp_path_factory.mktemp("cache")))
        spec = ContactSpec("rigid", None, 0.3, table_points=(21, 5, 2))
        stand = YokeStand({"mu": 0.4}, {name: {} for name in EFFECTS}, spec, DriveMode.QUASI_STATIC)
        geometry = stand.params.geometry_at(1.06e-3)
        law = LawCoefficients(*stand.law(geometry.b_over_a(96.2), geometry))
        errors, u, expanded = (np.empty((REPEATS, len(NAMES))) for _ in range(3))
        for r in range(REPEATS):
            rng = np.random.default_rng(np.random.SeedSequence([SEED, r]))
            stand.calibrate(r)  # a new run: new weight errors, new drift path
            point = stand.start_point(0, operating_point(rng), None, r)
            point.settle(30.0)
            outcome = point.read(point.gate(GATE_S))
            readings = point_readings(outcome.record, stand.params, geometry, f"repeat {r}")
            f_n = readings.normal_force  # the operator reads the spring with error e ~ N(0, u)
            readings = dataclasses.replace(readings, normal_force=Measured(f_n.value + rng.normal(0.0, f_n.u), f_n.u))
            reduced = stand_a.reduce(readings, law, geometry)
            for k, name in enumerate(NAMES):
                errors[r, k] = reduced.values[name] - outcome.truth[name].value
                u[r, k], expanded[r, k] = reduced.uncertainties[name], reduced.expanded[name]
    return errors, u, expanded


@pytest.mark.parametrize("k, name", list(enumerate(NAMES)))
def test_95_percent_interval_holds_the_truth_in_90_to_99_percent_of_repeats(repeats, k, name):
    errors, u, expanded = repeats
    assert np.all(np.isfinite(errors[:, k])) and np.all(u[:, k] > 0), name
    coverage = np.mean(np.abs(errors[:, k]) <= expanded[:, k])
    assert 0.90 <= coverage <= 0.99, (name, coverage)


def test_errors_scale_with_the_stated_uncertainty(repeats):
    # neither too small nor padded: the rms of error/u is 1 within its sampling spread (200 repeats:
    # ~5 %, plus the spread of the weights' errors, one draw per repeat); no bias beyond 3 se
    errors, u, expanded = repeats
    z = errors / u
    rms = np.sqrt(np.mean(z**2, axis=0))
    assert np.all((rms > 0.85) & (rms < 1.15)), dict(zip(NAMES, rms))
    assert np.all(np.abs(z.mean(axis=0)) < 3.0 / np.sqrt(REPEATS)), dict(zip(NAMES, z.mean(axis=0)))
    # k95 between the rectangular 1.645 and the normal 1.96, + 3 standard errors of the 8192-draw quantile
    # (~1 % each, rig.reduction.coverage; one fixed draw set for every point): mu_v, normal-dominated
    # since its u holds the dynamometer's zero drift, reaches 2.004
    k95 = expanded / u
    assert np.all((k95 > 1.6) & (k95 < 1.96 * 1.03)), (k95.min(axis=0), k95.max(axis=0))
