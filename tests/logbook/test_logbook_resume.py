"""Resuming equals an uninterrupted run; a write that fails half-way leaves the previous state."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import h5py
import logbook_samples as samples
import pandas as pd
import pytest

import rig.logbook.journal as journal_module
import rig.logbook.reduced as reduced
import rig.logbook.writer as writer_module
from rig.errors import LogFormatError, ParameterError, RigError
from rig.logbook import LogWriter, RunMetadata, read_metadata, read_reduced, staging_dir, write_reduced


@pytest.fixture(scope="module")
def reference(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An uninterrupted run."""
    path = tmp_path_factory.mktemp("reference") / "run.h5"
    samples.write_run(path)
    return path


def test_resumed_run_equals_uninterrupted_run(reference: Path, tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    first = samples.write_run(path, [0, 2, 3], finalize=False)  # interrupted after points 0, 2, 3
    assert not path.exists() and first.done == {0, 2, 3}
    resumed = LogWriter(path, samples.metadata())
    assert resumed.done == {0, 2, 3}
    for k in range(samples.N_POINTS):
        if k not in resumed.done:
            resumed.write_point(samples.point(k), samples.truth(k))
    assert resumed.finalize() == path
    assert samples.dump(path) == samples.dump(reference)
    assert path.read_bytes() == reference.read_bytes()
    assert not staging_dir(path).exists()


def test_resume_keeps_first_start_time_and_refuses_another_run(tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    samples.write_run(path, [0], finalize=False)
    later = RunMetadata(samples.SCENE, 7, "stand_A", "2030-01-01T00:00:00Z")
    assert LogWriter(path, later).metadata.created_utc == "2024-05-01T12:00:00Z"
    with pytest.raises(ParameterError, match=r"metadata.seed = 8 .*valid: 7, as in the interrupted run.*delete"):
        LogWriter(path, samples.metadata(seed=8))
    other_scene = RunMetadata("x = 2\n", 7, "stand_A", "2024-05-01T12:00:00Z")
    with pytest.raises(ParameterError, match="metadata.scene_toml"):
        LogWriter(path, other_scene)


def test_writer_refuses_duplicates_and_use_after_finalize(tmp_path: Path) -> None:
    writer = samples.write_run(tmp_path / "run.h5", [0], finalize=False)
    with pytest.raises(ParameterError, match=r"point.index = 0 .*not yet written"):
        writer.write_point(samples.point(0), samples.truth(0))
    with pytest.raises(ParameterError, match=r"truth\['mu'\]"):
        writer.write_point(samples.point(1), {"mu": 0.4})
    with pytest.raises(ParameterError, match="path"):
        LogWriter(tmp_path / "no" / "such" / "run.h5", samples.metadata())
    writer.finalize()
    with pytest.raises(RigError, match="finalized"):
        writer.write_point(samples.point(1), samples.truth(1))


def test_new_run_replaces_previous_log_only_at_finalize(reference: Path, tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    path.write_bytes(reference.read_bytes())
    writer = samples.write_run(path, [0], seed=99, finalize=False)
    assert path.read_bytes() == reference.read_bytes()
    writer.finalize()
    assert read_metadata(path).seed == 99


def test_stale_staging_without_run_part_is_cleared(tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    samples.write_run(path, [0, 1], finalize=False)
    (staging_dir(path) / "run.h5").unlink()  # as left by a kill during finalize's clean-up
    writer = LogWriter(path, samples.metadata(seed=1))
    assert writer.done == frozenset()
    assert sorted(p.name for p in staging_dir(path).iterdir()) == ["run.h5"]


def test_damaged_journal_frame_drops_it_and_what_follows(tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    samples.write_run(path, [0, 1, 2], finalize=False)
    journal = staging_dir(path) / "points.journal"
    data = bytearray(journal.read_bytes())
    data[len(data) // 2] ^= 0xFF  # a flipped byte inside point 1's frame: its checksum fails
    journal.write_bytes(bytes(data))
    writer = LogWriter(path, samples.metadata())
    assert writer.done == {0}  # points 1 and 2 are simulated again, never read wrong
    for k in range(1, samples.N_POINTS):
        writer.write_point(samples.point(k), samples.truth(k))
    writer.finalize()
    assert samples.dump(path) == samples.dump(samples.write_run(tmp_path / "ref.h5").path)


def _fail_half_way(*_args: object) -> None:
    raise RuntimeError("disk full (simulated)")


def test_point_write_failing_half_way_leaves_previous_parts(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    writer = samples.write_run(path, [0, 1], finalize=False)
    before = {p.name: p.read_bytes() for p in staging_dir(path).iterdir()}
    monkeypatch.setattr(journal_module, "encode", _fail_half_way)
    with pytest.raises(RuntimeError, match="disk full"):
        writer.write_point(samples.point(2), samples.truth(2))
    assert {p.name: p.read_bytes() for p in staging_dir(path).iterdir()} == before
    assert writer.done == {0, 1} and LogWriter(path, samples.metadata()).done == {0, 1}
    monkeypatch.undo()
    journal = staging_dir(path) / "points.journal"
    with journal.open("ab") as handle:  # a frame torn by a write that failed half-way (disk full)
        handle.write(b"RIGP torn")
    for k in range(2, samples.N_POINTS):  # the same writer goes on: the torn bytes are cut off
        writer.write_point(samples.point(k), samples.truth(k))
    writer.finalize()
    assert samples.dump(path) == samples.dump(samples.write_run(tmp_path / "ref.h5").path)


def test_finalize_failing_half_way_leaves_previous_log(
    monkeypatch: pytest.MonkeyPatch, reference: Path, tmp_path: Path
) -> None:
    path = tmp_path / "run.h5"
    path.write_bytes(b"previous log")
    writer = samples.write_run(path, finalize=False)

    def lay_out_then_fail(root, entries):
        root.create_group("points")
        _fail_half_way()

    monkeypatch.setattr(writer_module, "write_columnar", lay_out_then_fail)
    with pytest.raises(OSError, match=r"writing failed \(disk full \(simulated\)\): '.*run\.h5'"):
        writer.finalize()
    assert path.read_bytes() == b"previous log"
    assert not list(staging_dir(path).glob("*.tmp"))
    monkeypatch.undo()
    writer.finalize()
    assert path.read_bytes() == reference.read_bytes()


def test_write_reduced_failing_half_way_leaves_log(
    monkeypatch: pytest.MonkeyPatch, reference: Path, tmp_path: Path
) -> None:
    path = tmp_path / "run.h5"
    path.write_bytes(reference.read_bytes())

    def write_then_fail(group, table, units):
        group.create_dataset("mu", data=[0.4])
        _fail_half_way()

    monkeypatch.setattr(reduced, "_write_table", write_then_fail)
    with pytest.raises(OSError, match=r"writing failed \(disk full \(simulated\)\): '.*run\.h5'"):
        write_reduced(path, pd.DataFrame({"mu": [0.4]}), {"mu": "1"})
    assert path.read_bytes() == reference.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.h5"]
    with pytest.raises(LogFormatError, match="no 'reduced' group"):
        read_reduced(path)
    with h5py.File(path, "r") as f:
        assert "reduced" not in f


def test_writing_a_point_never_rewrites_earlier_ones(tmp_path: Path) -> None:
    """Each point appends one frame to the journal (the writer is O(total size), not O(points^2))."""
    path = tmp_path / "run.h5"
    writer = samples.write_run(path, [0, 1, 2], finalize=False)
    journal = staging_dir(path) / "points.journal"
    before, names = journal.read_bytes(), sorted(p.name for p in staging_dir(path).iterdir())
    writer.write_point(samples.point(3), samples.truth(3))
    after = journal.read_bytes()
    assert after[: len(before)] == before and len(after) > len(before)
    assert sorted(p.name for p in staging_dir(path).iterdir()) == names
    assert samples.journal_frames(path) == [0, 1, 2, 3]


def test_a_finished_log_of_the_same_run_is_not_written_again(reference: Path, tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    path.write_bytes(reference.read_bytes())
    stamp = path.stat().st_mtime_ns
    writer = LogWriter(path, samples.metadata())
    assert writer.done == set(range(samples.N_POINTS))  # nothing to simulate
    writer.finalize()
    assert path.stat().st_mtime_ns == stamp and not staging_dir(path).exists()
    partial = tmp_path / "partial.h5"
    samples.write_run(partial, [0, 2, 4])  # a finished log, some points missing (e.g. not settled)
    writer = LogWriter(partial, samples.metadata())
    assert writer.done == {0, 2, 4}
    for k in (1, 3, 5):
        writer.write_point(samples.point(k), samples.truth(k))
    writer.finalize()
    assert partial.read_bytes() == reference.read_bytes()
    other = samples.write_run(tmp_path / "other.h5", [0], seed=99).path
    assert LogWriter(other, samples.metadata()).done == frozenset()  # another run's log is no base


def test_log_gets_ordinary_file_permissions(tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    samples.write_run(path, [0])
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask
    path.chmod(0o640)
    write_reduced(path, pd.DataFrame({"mu": [0.4]}), {"mu": "1"})
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
