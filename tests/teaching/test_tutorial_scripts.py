"""Smoke test of the tutorial scripts (experiments/tutorial/): each runs, writes its PNG and CSV into
the folder given by -o, and its CSV holds numbers that can be checked independently.

Each script runs as a reader runs it, ``python experiments/tutorial/<step>.py -o DIR ...`` in a
subprocess (experiments/ is not a package: nothing imports it); the contact steps run on a coarse
grid and step 10 on the quick stand-A scene.
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from rig.teaching.coulomb import STANDARD_GRAVITY

TUTORIAL = Path(__file__).resolve().parents[2] / "experiments" / "tutorial"
QUICK_SCENE = TUTORIAL / "stand_a_quick.toml"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run_step(name: str, out: Path, *extra: str) -> tuple[Path, pd.DataFrame]:
    """Run ``python experiments/tutorial/<name>.py -o out ...``; return its PNG and its CSV table."""
    done = subprocess.run([sys.executable, str(TUTORIAL / f"{name}.py"), "-o", str(out), *extra],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    png, csv = out / f"{name}.png", out / f"{name}.csv"
    assert png.read_bytes()[:8] == PNG_SIGNATURE and png.stat().st_size > 10_000
    return png, pd.read_csv(csv)


def test_every_step_is_tested_here():
    steps = sorted(p.stem for p in TUTORIAL.glob("step*.py"))
    assert steps == sorted(STEPS_TESTED), "a tutorial step without a smoke test"


def test_step01_pull_test(tmp_path):
    _, table = run_step("step01_pull_test", tmp_path)
    n = 2.0 * STANDARD_GRAVITY
    assert table.friction_N.max() == pytest.approx(0.8 * n, rel=2e-3)  # mu_s N, steel-steel dry
    assert table.friction_N.iloc[-1] == pytest.approx(0.6 * n)  # mu_k N


def test_step02_inclined_plane(tmp_path):
    _, table = run_step("step02_inclined_plane", tmp_path)
    rest = table[table["at_rest_mu_s_0.8"]]
    assert rest.alpha_deg.max() == pytest.approx(math.degrees(math.atan(0.8)), abs=0.5)  # 38.66 deg, 0.5-deg grid
    row = table[table.alpha_deg == 30.0].iloc[0]
    assert row["a_mu_k_0_m_s2"] == pytest.approx(STANDARD_GRAVITY / 2)


def test_step03_friction_table(tmp_path):
    _, table = run_step("step03_friction_table", tmp_path)
    assert len(table) == 15 and table.contradiction.sum() == 1
    flagged = table[table.contradiction].iloc[0]
    assert (flagged.material_1, flagged.material_2, flagged.mu_s_dry_high) == ("steel", "PTFE", 0.04)


def test_step04_rolling_wheel(tmp_path):
    _, table = run_step("step04_rolling_wheel", tmp_path)
    n, f_v = 10.0 * STANDARD_GRAVITY, 0.015
    f_max = 3.0 * n - 2.0 * f_v * n  # solid disc: F_max = 3 mu_s N - 2 f_v N, mu_s = 1 (concrete-rubber)
    assert table[table.rolls].pull_N.max() == pytest.approx(f_max, rel=1e-9)  # the grid ends rolling at F_max
    assert table[~table.rolls].pull_N.min() > f_max


def test_step05_rolling_resistance(tmp_path):
    _, table = run_step("step05_rolling_resistance", tmp_path)
    assert table.pull_N.mean() / 3000.0 == pytest.approx(0.015, abs=3 * table.pull_N.std() / np.sqrt(len(table)) / 3000)


def test_step06_hysteresis(tmp_path):
    _, table = run_step("step06_hysteresis", tmp_path)
    np.testing.assert_allclose(table.loop_area_J_m3, table.dissipation_J_m3, rtol=1e-3, atol=1e-6)
    assert table.f_v.iloc[0] == 0.0 and np.all(np.diff(table.f_v.iloc[:20]) > 0)


def test_step07_spin(tmp_path):
    _, table = run_step("step07_spin", tmp_path, "--n", "8")
    rigid = table[table.alpha_prime == 0.0].iloc[0]
    assert rigid.nu_0 == pytest.approx(3 * math.pi / 16, abs=2e-3)  # Equations §1.10(a), Hertz circle
    kinematic = table[table.alpha_prime > 0.0]
    assert kinematic.nu_0.iloc[0] == pytest.approx(3 * math.pi / 16, abs=0.02)  # alpha' = 0.1: nearly sliding
    assert np.all(np.diff(kinematic.nu_0) < 1e-3)  # nu_0 falls with alpha' (Equations §1.10(c))
    assert np.abs(kinematic.nu_T).max() < 1e-6  # pure spin: no peripheral force


def test_step08_rolling_point(tmp_path):
    _, table = run_step("step08_rolling_point", tmp_path, "--n", "8")
    rigid = table[table.alpha_prime == 0.0]

    def at(c, l):
        row = rigid[np.isclose(rigid.c_over_a, c) & np.isclose(rigid.l_over_a, l)].iloc[0]
        return row.nu_T, row.nu_v, row.nu_0

    # Equations §1.10(a), line contact b/a = 1, full sliding
    np.testing.assert_allclose(at(0.0, 0.5), (-0.44604, 0.0, 0.82383), atol=2e-3)
    np.testing.assert_allclose(at(0.0, 1.0), (-0.81814, 0.0, 1.14653), atol=2e-3)
    np.testing.assert_allclose(at(0.4, 0.0), (0.0, 0.40027, 0.79276), atol=2e-3)
    np.testing.assert_allclose(at(1.0, 0.0), (0.0, 0.81847, 1.17536), atol=2e-3)
    stand_a = table[(table.alpha_prime > 0.0) & (table.alpha_prime < 1.0)]
    assert stand_a.alpha_prime.iloc[0] == pytest.approx(0.64, abs=0.01)  # Equations §3.1


def test_step09_stand_a_kinematics(tmp_path):
    _, table = run_step("step09_stand_a_kinematics", tmp_path)
    centre = table.iloc[(table.l_over_a.abs()).argmin()]
    assert centre.i_k == pytest.approx(0.8115, abs=2e-4)  # Equations §3.1: i_k = r1/r2 at l = 0
    assert centre.c_over_a_delta_h_1_06mm == pytest.approx(0.40, abs=0.005)  # c/a = 0.4 at l = 0 (a = 1.215 mm)
    assert centre.spin_rad_s == pytest.approx(44.5, abs=0.1) and centre.alpha_prime == pytest.approx(0.64, abs=0.01)


def test_step10_measurement_recovers_mu(tmp_path, monkeypatch):
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "cache"))
    _, table = run_step("step10_measurement", tmp_path, "--scene", str(QUICK_SCENE))
    assert len(table) == 5 and (tmp_path / "step10_run_stand_a_quick" / "log.h5").is_file()
    assert np.all(np.diff(table.l_over_a) > 0)  # a larger brake moment moves C towards wheel 1 (l > 0)
    for name in ("mu_v", "mu_T", "l_over_a"):
        valid = table[table[name].notna()]
        z = np.abs(valid[name] - valid[f"true_{name}"]) / valid[f"u_{name}"]
        assert len(valid) >= 4 and np.all(z < 3.0), (name, z.tolist())


STEPS_TESTED = [
    "step01_pull_test", "step02_inclined_plane", "step03_friction_table", "step04_rolling_wheel",
    "step05_rolling_resistance", "step06_hysteresis", "step07_spin", "step08_rolling_point",
    "step09_stand_a_kinematics", "step10_measurement",
]
