"""A twin run says when a reduced point is off its truth by more than its stated u (summary, reduced.csv, exit)."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.stats import norm

from rig.cli import run as run_cli
from rig.runner import off_truth as S
from rig.runner.stand_run import RunReport


def table(mu_v, u, true=0.6) -> pd.DataFrame:
    mu_v = np.asarray(mu_v, dtype=float)
    frame = pd.DataFrame({"mu_v": mu_v, "u_mu_v": np.full(mu_v.size, u), "true_mu_v": np.full(mu_v.size, true)})
    frame.index.name = "point"
    frame.attrs["units"] = {c: "1" for c in frame.columns}
    return frame


def test_threshold_is_3_for_few_comparisons_and_bonferroni_for_many():
    assert S.off_truth_threshold(1) == 3.0  # Phi^-1(1 - 0.005) = 2.58 < 3
    assert S.off_truth_threshold(100) == pytest.approx(norm.isf(0.01 / 200), rel=1e-12)
    assert 3.8 < S.off_truth_threshold(100) < 4.0  # 3.89 (tables of the normal distribution)


def test_a_wrong_root_is_flagged_with_a_column_and_a_first_warning():
    # three points reduced to the other root 0.28 +- 0.02 for a truth of 0.6 (z = 16), the rest right
    values = [0.6, 0.61, 0.28, 0.28, 0.59, 0.28, math.nan]
    flagged = S.with_off_truth(table(values, 0.02))
    assert flagged["off_truth"].tolist()[:6] == [0.0, 0.0, 1.0, 1.0, 0.0, 1.0]
    assert math.isnan(flagged["off_truth"].iloc[6])  # NaN: not comparable, not flagged
    assert flagged["z_max"].iloc[2] == pytest.approx(16.0)
    assert S.off_truth_points(flagged) == (2, 3, 5)
    lines = S.off_truth_lines(flagged)
    assert lines[0].startswith("WARNING: 3 reduced point(s) off their truth") and "z = 16.0" in lines[1]
    assert flagged.attrs["units"]["off_truth"] == "1"


def test_a_run_within_its_u_is_not_flagged():
    rng = np.random.default_rng(3)
    flagged = S.with_off_truth(table(0.6 + 0.02 * rng.standard_normal(200), 0.02))
    assert S.off_truth_points(flagged) == () and S.off_truth_lines(flagged) == []


def test_a_table_without_truth_is_unchanged():
    frame = pd.DataFrame({"mu_v": [0.5], "u_mu_v": [0.01]})
    assert S.with_off_truth(frame) is frame


@pytest.mark.parametrize("failures, damaged, off, status", [
    ((), (), (), 0), ((), (), (4,), 4), ((), (2,), (4,), 3), (("x",), (2,), (4,), 1)])
def test_rig_run_exit_status(monkeypatch, tmp_path, failures, damaged, off, status):
    report = RunReport(Path(tmp_path), ("summary.txt",), 5, 5, 0, failures, False, "summary\n", damaged, off)
    monkeypatch.setattr(run_cli, "load_scene", lambda name: argparse.Namespace(name="s"))
    monkeypatch.setattr(run_cli, "run_scene", lambda *a, **k: report)
    args = argparse.Namespace(scene="s", output=tmp_path, jobs=1, scheduler=None)
    assert run_cli.main(args) == status
