"""Shards merged into one log hold what the log written point by point holds, dataset by dataset.

The reference is rig.logbook.columnar.write_columnar over all the points (the serial writer's
layout). The points are hostile to a merge: a setting, a reading, a calibration record, the
counters and a channel that only some points have, a channel of zero samples, and shards whose
points interleave (any partition of the points, drawn by hypothesis).
"""

from __future__ import annotations

import h5py
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.logbook import Channel, Counter, CounterReadings, PointRecord, Quantity, RunMetadata
from rig.logbook.atomic import LIBVER
from rig.logbook.columnar import write_columnar
from rig.logbook.h5format import write_metadata
from rig.logbook.journal import entry_of
from rig.logbook.shards import find_shards, merge_logs, shard_name, store_shard, write_shard
from tests.runner.logs import log_objects

META = RunMetadata("[scene]\n", 3, "fake", "2026-01-01T00:00:00Z")
POINTS = 9


def _entry(index: int):
    """Point ``index``: what it holds depends on the index (some quantities only on some points)."""
    rng = np.random.default_rng(index)
    settings = {"load": Quantity(5.0 + index, "N")} | ({"speed": Quantity(2.0, "rad/s")} if index % 2 else {})
    readings = {"F_mean": Quantity(float(rng.normal()), "N")} | ({"extra": Quantity(1.5, "1")} if index % 3 == 0 else {})
    channels = {"force": Channel(rng.normal(size=3 + index), "N", 100.0, 0.5)}
    if index % 4 == 1:
        channels["torque"] = Channel(rng.normal(size=index), "N m", 50.0, 0.0)  # 0 samples at point 0 never: 1, 5
    counters = CounterReadings(1.0, {"N1": Counter(10 * index, 60)}) if index != 4 else None
    calibration = {"gain": {"k": Quantity(1.01, "N/V")}} | ({"empty": {}} if index % 2 == 0 else {})
    record = PointRecord(index, settings, channels, counters, readings, calibration)
    return entry_of(record, {"mu": Quantity(0.3, "1"), "F": Quantity(1.0 + index, "N")})


ENTRIES = [_entry(i) for i in range(POINTS)]


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    path = tmp_path_factory.mktemp("reference") / "log.h5"
    with h5py.File(path, "w", libver=LIBVER) as handle:
        write_metadata(handle, META)
        write_columnar(handle, lambda: ENTRIES)
    return log_objects(path)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(shard_of=st.lists(st.integers(0, 3), min_size=POINTS, max_size=POINTS))
def test_any_partition_of_the_points_merges_to_the_serial_log(reference, tmp_path_factory, shard_of):
    folder = tmp_path_factory.mktemp("shards")
    sources = []
    for shard in sorted(set(shard_of)):
        entries = [e for e, s in zip(ENTRIES, shard_of) if s == shard]
        path = folder / f"part_{shard}.h5"
        write_shard(path, META, entries)
        sources.append(path)
    merged = merge_logs(folder / "log.h5", META, sources[::-1])  # any order of the sources
    assert log_objects(merged) == reference


def test_a_point_in_two_shards_is_refused(tmp_path):
    write_shard(tmp_path / "a.h5", META, ENTRIES[:3])
    write_shard(tmp_path / "b.h5", META, ENTRIES[2:5])
    with pytest.raises(ParameterError, match="a point is in two"):
        merge_logs(tmp_path / "log.h5", META, [tmp_path / "a.h5", tmp_path / "b.h5"])
    assert not (tmp_path / "log.h5").exists()


def test_a_quantity_in_two_units_is_refused(tmp_path):
    other = entry_of(PointRecord(20, {"load": Quantity(5.0, "kN")}), {})
    write_shard(tmp_path / "a.h5", META, ENTRIES[:2])
    write_shard(tmp_path / "b.h5", META, [other])
    with pytest.raises(ParameterError, match="points/settings/load.units = 'kN'"):
        merge_logs(tmp_path / "log.h5", META, [tmp_path / "a.h5", tmp_path / "b.h5"])


def test_only_complete_shards_of_the_same_run_are_found(tmp_path):
    write_shard(tmp_path / "one.h5", META, ENTRIES[:3])
    store_shard(tmp_path, 0, 2, (tmp_path / "one.h5").read_bytes())
    write_shard(tmp_path / "other.h5", RunMetadata("[scene]\n", 4, "fake", META.created_utc), ENTRIES[3:5])
    store_shard(tmp_path, 3, 4, (tmp_path / "other.h5").read_bytes())  # another seed: another run
    (tmp_path / shard_name(5, 6)).write_bytes(b"torn")  # not HDF5
    (tmp_path / ".points_0000007_0000008.h5.1-ab.h5.tmp").write_bytes(b"")  # a killed store's temporary file
    found = find_shards(tmp_path, META)
    assert [shard.indices for shard in found] == [(0, 1, 2)]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["one.h5", "other.h5", shard_name(0, 2)]
