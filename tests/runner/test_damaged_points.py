"""Old-layout logs are reduced unchanged; a damaged point is NaN with its reason, the others as before.

Data: tests/logbook/data/old_layout_v1.h5, a 4-point stand-A log written by the code before
format version 2 (commit aafa9bc) from old_layout_v1.toml, and its reduced.csv as the current
reduction gives it (regenerate with ``rig reduce`` on a copy of the log when the contact law
changes: FASTSIM's three flexibilities moved its values by <= 2e-5, its spin-moment flexibility L4 by <= 4e-4,
the kinematic model's rim loads and leading-edge cells (discretisation revision 7) mu_v by <= 2e-4 relative;
or the reduction's numerics: the Newton first step of the Jacobian's mu iterations moved u and U95 by <= 2e-8
relative, the values not at all). A columnar log of the same
scene is made by running the scene again; it is simulated with today's contact law, so its
values agree with the old log's to the size of that change, not to the last digit.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import h5py
import numpy as np
import pandas as pd
import pytest

import rig.cli
from rig.runner import reduce_log_file, run_scene
from rig.scenes import load_scene

DATA = Path(__file__).resolve().parents[1] / "logbook" / "data"
OLD_LOG, OLD_CSV, SCENE = DATA / "old_layout_v1.h5", DATA / "old_layout_v1_reduced.csv", DATA / "old_layout_v1.toml"
CHANNEL = "dynamometer_10"


@pytest.fixture(autouse=True)
def _cache(tmp_path_factory, monkeypatch):
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path_factory.getbasetemp() / "cache"))


@pytest.fixture
def old_log(tmp_path) -> Path:
    log = tmp_path / "old" / "log.h5"
    log.parent.mkdir()
    shutil.copyfile(OLD_LOG, log)
    return log


@pytest.fixture(scope="module")
def new_run(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("new")
    run_scene(load_scene(str(SCENE)), folder, progress=False)
    return folder


def test_old_layout_log_is_reduced_unchanged(old_log):
    reduction, _ = reduce_log_file(old_log)
    assert reduction.damaged == ()
    text = (old_log.parent / "reduced.csv").read_text()
    # the same table, plus the off-truth columns a twin's table gets at the end (rig.runner.summary)
    assert text.splitlines()[0].endswith(",z_max,off_truth")
    assert "\n".join(line.rsplit(",", 2)[0] for line in text.splitlines()) + "\n" == OLD_CSV.read_text()


def test_new_layout_gives_the_old_layout_values(new_run):
    new, old = (pd.read_csv(path, index_col="point") for path in (new_run / "reduced.csv", OLD_CSV))
    new = new.drop(columns=["z_max", "off_truth"])  # added since (rig.runner.summary.with_off_truth)
    assert list(new.columns) == list(old.columns) and list(new.index) == list(old.index)
    pd.testing.assert_frame_equal(new, old, check_dtype=False, rtol=1e-3, atol=1e-8)
    with h5py.File(new_run / "log.h5", "r") as f:
        assert f.attrs["format_version"] == 2 and f["points/index"][:].tolist() == [0, 1, 2, 3]


def _reduce_damaged(log: Path, damage, capsys) -> pd.DataFrame:
    with h5py.File(log, "r+") as f:
        damage(f)
    assert rig.cli.main(["reduce", str(log)]) == 3  # some points damaged: documented exit status
    assert "1 damaged point(s) reduced to NaN" in capsys.readouterr().out
    return pd.read_csv(log.parent / "reduced.csv", index_col="point")


def _check_only_point_2_lost(table: pd.DataFrame, *reason_parts: str, good_csv: Path = OLD_CSV) -> None:
    good = pd.read_csv(good_csv, index_col="point")
    table = table.drop(columns=[c for c in ("z_max", "off_truth") if c not in good])  # added since (summary.py)
    assert list(table.index) == [0, 1, 2, 3]
    pd.testing.assert_frame_equal(table.drop(index=2), good.drop(index=2), check_dtype=False)  # reason: empty
    numbers = table.drop(columns="reason").loc[2]
    assert numbers.isna().all(), numbers[numbers.notna()]
    reason = table.loc[2, "reason"]
    assert reason.startswith("damaged point: ") and all(part in reason for part in reason_parts), reason


def _nan_sample_v1(f):
    f[f"points/point_000002/channels/{CHANNEL}"][17] = np.nan


def _nan_sample_v2(f):
    first = f[f"points/channels/{CHANNEL}/first"][2]
    f[f"points/channels/{CHANNEL}/samples"][first + 17] = np.nan


def test_nan_sample_in_one_point_of_an_old_layout_log(old_log, capsys):
    table = _reduce_damaged(old_log, _nan_sample_v1, capsys)
    _check_only_point_2_lost(table, f"/points/point_000002/channels/{CHANNEL}", "samples[17]", "nan")


def test_nan_sample_in_one_point_of_a_columnar_log(new_run, tmp_path, capsys):
    log = tmp_path / "log.h5"
    shutil.copyfile(new_run / "log.h5", log)
    table = _reduce_damaged(log, _nan_sample_v2, capsys)
    _check_only_point_2_lost(table, f"/points/channels/{CHANNEL}/samples", "point 2: sample 17", "nan",
                             good_csv=new_run / "reduced.csv")


def test_point_missing_a_dataset(old_log, new_run, tmp_path, capsys):
    table = _reduce_damaged(old_log, lambda f: f.__delitem__("points/point_000002/readings/T2"), capsys)
    _check_only_point_2_lost(table, "'T2' is missing")
    log = tmp_path / "log.h5"
    shutil.copyfile(new_run / "log.h5", log)

    def drop_t2_of_point_2(f):  # in the columnar layout an absent value is NaN in its row
        f["points/readings/T2"][2] = np.nan
    table = _reduce_damaged(log, drop_t2_of_point_2, capsys)
    _check_only_point_2_lost(table, "'T2' is missing", good_csv=new_run / "reduced.csv")
