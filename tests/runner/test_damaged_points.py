"""Old-layout logs are reduced unchanged; a damaged point is NaN with its reason, the others as before.

Data: tests/logbook/data/old_layout_v1.h5, a 4-point stand-A log written by the code before
format version 2 from old_layout_v1.toml, and its reduced.csv as the current
reduction gives it (regenerate with ``rig reduce`` on a copy of the log when the contact law
changes: FASTSIM's three flexibilities moved its values by <= 2e-5, its spin-moment flexibility L4 by <= 4e-4,
the kinematic model's rim loads and leading-edge cells (discretisation revision 7) mu_v by <= 2e-4 relative;
or the reduction's numerics: the Newton first step of the Jacobian's mu iterations moved u and U95 by <= 2e-8
relative, the values not at all). A columnar log of the same
scene is made by running the scene again; it is simulated with today's contact law, so its
values agree with the old log's to the size of that change, not to the last digit.
"""

from __future__ import annotations

import re
import shutil
import warnings
from pathlib import Path

import h5py
import numpy as np
import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

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
    # the same table, plus the off-truth columns a twin's table gets at the end (rig.runner.off_truth)
    assert text.splitlines()[0].endswith(",z_max,off_truth")
    assert "\n".join(line.rsplit(",", 2)[0] for line in text.splitlines()) + "\n" == OLD_CSV.read_text()


def test_new_layout_gives_the_old_layout_values(new_run):
    new, old = (pd.read_csv(path, index_col="point") for path in (new_run / "reduced.csv", OLD_CSV))
    new = new.drop(columns=["z_max", "off_truth"])  # added since (rig.runner.off_truth.with_off_truth)
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


def _row_of_point_2(f, path: str, value) -> None:
    f[path][2] = value


def _sample_of_point_2(value):
    def damage(f):
        first = f[f"points/channels/{CHANNEL}/first"][2]
        f[f"points/channels/{CHANNEL}/samples"][first + 17] = value
    return damage


DAMAGE_KINDS = {
    # kind: (damage, parts of the reason: the dataset, the point, the value)
    "inf reading": (lambda f: _row_of_point_2(f, "points/readings/T2", np.inf),
                    ("/points/readings/T2", "point 2", "inf is not finite")),
    "sample 1e300": (_sample_of_point_2(1e300), (f"/points/channels/{CHANNEL}/samples[17]", "point 2", "1e+300")),
    "normal force <= 0": (lambda f: _row_of_point_2(f, "points/settings/normal_force", -5.0),
                          ("/points/settings/normal_force", "point 2", "-5.0")),
    "sensitivity 0": (lambda f: _row_of_point_2(f, f"points/calibration/{CHANNEL}/sensitivity", 0.0),
                      (f"/points/calibration/{CHANNEL}/sensitivity", "point 2", "sensitivity = 0.0")),
    "negative u": (lambda f: _row_of_point_2(f, f"points/calibration/{CHANNEL}/u_sensitivity", -1e-3),
                   (f"/points/calibration/{CHANNEL}/u_sensitivity", "point 2", "-0.001")),
    "length out of range": (lambda f: _row_of_point_2(f, f"points/channels/{CHANNEL}/length", 10**9),
                            (f"/points/channels/{CHANNEL}", "point 2", "length = 1000000000", "outside")),
    "first out of range": (lambda f: _row_of_point_2(f, f"points/channels/{CHANNEL}/first", -3),
                           (f"/points/channels/{CHANNEL}", "point 2", "first = -3", "outside")),
}


@pytest.mark.parametrize("kind", sorted(DAMAGE_KINDS))
def test_a_damaged_value_costs_its_point_only(kind, new_run, tmp_path, capsys):
    """Each kind of damage of one point's value: that point NaN with a reason naming the file, the
    dataset, the point and the value; the others as from the undamaged log; exit 3; no warning."""
    damage, parts = DAMAGE_KINDS[kind]
    log = tmp_path / "log.h5"
    shutil.copyfile(new_run / "log.h5", log)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # e.g. numpy's overflow RuntimeWarning on 1e300
        table = _reduce_damaged(log, damage, capsys)
    _check_only_point_2_lost(table, str(log), *parts, good_csv=new_run / "reduced.csv")


def test_a_rerun_into_a_folder_with_a_damaged_finished_log_rewrites_it(new_run, tmp_path, capsys):
    folder = tmp_path / "run"
    shutil.copytree(new_run, folder)
    with h5py.File(folder / "log.h5", "r+") as f:
        first = f[f"points/channels/{CHANNEL}/first"][2]
        f[f"points/channels/{CHANNEL}/samples"][first + 17] = np.nan
    data = bytearray((folder / "log.h5").read_bytes())
    assert rig.cli.main(["run", str(SCENE), "-o", str(folder)]) == 0, capsys.readouterr().err
    assert "1 simulated now" in capsys.readouterr().out  # the damaged point only
    assert (folder / "reduced.csv").read_text() == (new_run / "reduced.csv").read_text()
    assert (folder / "log.h5").read_bytes() != bytes(data)


def _sample_byte_ranges(log: Path) -> list[tuple[int, int]]:
    """(start, end) byte offsets of every chunk of every channel's samples in the file."""
    ranges = []
    with h5py.File(log, "r") as f:
        for name in f["points/channels"]:
            ds = f[f"points/channels/{name}/samples"]
            for k in range(ds.id.get_num_chunks()):
                info = ds.id.get_chunk_info(k)
                ranges.append((info.byte_offset, info.byte_offset + info.size))
    return ranges


def _reduce_flipped(good: Path, flips, folder: Path) -> tuple[int, list[str], pd.DataFrame | None]:
    """Reduce a copy of ``good`` with bytes XORed at the given offsets: exit status, stderr lines and
    the reduced table (None when not reduced). An exception other than rig's named errors (which
    rig.cli.main prints as one line) escapes and fails the test with its traceback."""
    import contextlib
    import io

    log = folder / "log.h5"
    data = bytearray(good.read_bytes())
    for offset, mask in flips:
        data[offset % len(data)] ^= mask
    log.write_bytes(bytes(data))
    (folder / "reduced.csv").unlink(missing_ok=True)
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        status = rig.cli.main(["reduce", str(log)])
    table = pd.read_csv(folder / "reduced.csv", index_col="point") if status in (0, 3) else None
    return status, err.getvalue().splitlines(), table


@pytest.fixture(scope="module")
def flip_setup(new_run, tmp_path_factory):
    """The good log, its reduced table (by rig reduce itself) and a scratch folder; no figure drawn."""
    import rig.runner.reduce_file as reduce_file

    folder = tmp_path_factory.mktemp("flips")
    original = reduce_file.reduced_vs_truth_figure
    reduce_file.reduced_vs_truth_figure = lambda *args, **kwargs: None  # matplotlib: most of a reduce's time
    status, err, good = _reduce_flipped(new_run / "log.h5", [], folder)
    assert status == 0 and not err
    yield new_run / "log.h5", good, folder
    reduce_file.reduced_vs_truth_figure = original


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(flips=st.lists(st.tuples(st.integers(0, 10**6), st.integers(1, 255)), min_size=1, max_size=3))
def test_random_byte_flips_never_give_a_traceback(flip_setup, flips):
    """Any bytes of a finished log flipped: rig reduce exits 0, 2 or 3 with at most one line on
    stderr (a named error), never a traceback (an unnamed exception fails this test)."""
    good_log, _, folder = flip_setup
    status, err, _ = _reduce_flipped(good_log, flips, folder)
    assert status in (0, 2, 3) and len(err) <= (1 if status == 2 else 0), (status, err)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(where=st.floats(0.0, 1.0, exclude_max=True), mask=st.integers(1, 255))
def test_a_flipped_raw_sample_byte_is_detected_or_changes_nothing(flip_setup, where, mask):
    """One byte of a channel's raw samples flipped: the points of that chunk are named damaged
    (its Fletcher-32 checksum fails; exit 3), or the result equals the undamaged log's - never a
    silently different number."""
    good_log, good, folder = flip_setup
    ranges = _sample_byte_ranges(good_log)
    sizes = [end - start for start, end in ranges]
    k = int(where * sum(sizes))
    for (start, _), size in zip(ranges, sizes):
        if k < size:
            offset = start + k
            break
        k -= size
    status, err, table = _reduce_flipped(good_log, [(offset, mask)], folder)
    assert status in (0, 3) and not err, (status, err)
    if status == 0:
        pd.testing.assert_frame_equal(table, good)
    else:
        damaged = table["reason"].astype(str).str.startswith("damaged point: ")
        assert damaged.any() and table.loc[damaged, "reason"].str.contains("/samples").all()
        if not damaged.all():  # (a table of damaged points only has no value columns)
            pd.testing.assert_frame_equal(table.loc[~damaged], good.loc[~damaged])


@pytest.mark.parametrize("damage, message", [
    (lambda f: f["points/readings/T2"].attrs.__setitem__("units", "N"),
     r"/points/readings/T2: attribute 'units' = 'N', expected 'N m'"),
    (lambda f: f[f"points/channels/{CHANNEL}/samples"].attrs.__setitem__("units", "mV"),
     rf"/points/channels/{CHANNEL}/samples: attribute 'units' = 'mV', expected 'V'"),
    (lambda f: f.attrs.__setitem__("stand", "disc_roller"),
     r"root attribute 'stand' = 'disc_roller', but the scene stored in the log runs stand 'yoke'"),
])
def test_units_and_stand_other_than_the_reader_expects_are_named(damage, message, new_run, tmp_path, capsys):
    log = tmp_path / "log.h5"
    shutil.copyfile(new_run / "log.h5", log)
    with h5py.File(log, "r+") as f:
        damage(f)
    assert rig.cli.main(["reduce", str(log)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and re.search(f"{re.escape(str(log))}: .*{message}", err[0]), err


def test_a_folder_named_log_h5_is_named_at_once(tmp_path, capsys):
    (tmp_path / "log.h5").mkdir()
    assert rig.cli.main(["reduce", str(tmp_path / "log.h5")]) == 2
    assert capsys.readouterr().err == f"rig reduce: error: {tmp_path / 'log.h5'}: is a folder, not a log file\n"
    assert rig.cli.main(["run", str(SCENE), "-o", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "log.h5" in err and "a folder (or another non-file) of that name is in the way" in err
    assert not (tmp_path / "log.h5.parts").exists()  # refused before anything was simulated


def test_a_flipped_byte_in_the_truth_is_named_not_dropped(flip_setup, tmp_path):
    """The truth columns never vanish silently: a truth chunk failing its checksum is a named error."""
    good_log, _, folder = flip_setup
    with h5py.File(good_log, "r") as f:
        info = f["truth/mu"].id.get_chunk_info(0)
    status, err, _ = _reduce_flipped(good_log, [(info.byte_offset + info.size // 2, 0x5A)], folder)
    assert status == 2 and len(err) == 1 and "/truth/mu: unreadable" in err[0], err


def test_a_flipped_byte_in_the_scene_text_is_named(flip_setup):
    """The scene text (HDF5's global heap, no checksum of its own) is checked against scene_sha256."""
    good_log, _, folder = flip_setup
    offset = good_log.read_bytes().index(b"mu = 0.4") + len("mu = 0.")
    status, err, _ = _reduce_flipped(good_log, [(offset, ord("4") ^ ord("5"))], folder)  # mu = 0.5
    assert status == 2 and len(err) == 1 and "does not match its checksum" in err[0], err
