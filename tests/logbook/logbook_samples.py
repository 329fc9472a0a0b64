"""Sample runs for the logbook tests, and a child-process entry point for the kill tests.

Numbers are stand A's of the Equations page (section 3.1): F_N = 96.2 N, Delta h = 1.06 mm,
omega_1 = 25.13 rad/s (240 rpm), i_k = 0.8115, 60 marks per disc [A] over a 17 s gate.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import h5py
import numpy as np

from rig.logbook import (
    Channel,
    Counter,
    CounterReadings,
    LogWriter,
    PointRecord,
    Quantity,
    RunMetadata,
)

SCENE = 'stand = "A"\n[load]\nF_N = 96.2  # N\n[drive]\nrpm = 240\n'
N_POINTS = 6
GATE_S = 17.0
MARKS = 60
OMEGA_1 = 25.13  # rad/s
I_K = 0.8115


def metadata(seed: int = 7) -> RunMetadata:
    return RunMetadata(scene_toml=SCENE, seed=seed, stand="stand_A", created_utc="2024-05-01T12:00:00Z")


def counts(k: int) -> tuple[int, int]:
    """Counter totals of point k: N = omega z T / (2 pi) (Equations §2)."""
    omega_2 = OMEGA_1 * (I_K + 0.01 * k)
    return (round(OMEGA_1 * MARKS * GATE_S / (2 * math.pi)), round(omega_2 * MARKS * GATE_S / (2 * math.pi)))


def point(k: int, n_samples: int = 200) -> PointRecord:
    rng = np.random.default_rng(np.random.SeedSequence([7, k]))
    n1, n2 = counts(k)
    return PointRecord(
        index=k,
        settings={"F_N": Quantity(96.2, "N"), "delta_h": Quantity(1.06e-3, "m"), "omega": Quantity(OMEGA_1, "rad/s")},
        channels={
            "F_dyn": Channel(1.7 + 0.01 * k + 0.05 * rng.standard_normal(n_samples), "N", 1000.0, 2.5),
            "U_bridge": Channel(rng.standard_normal(n_samples // 2), "V", 500.0, 0.0),
        },
        counters=CounterReadings(GATE_S, {"N1": Counter(n1, MARKS), "N2": Counter(n2, MARKS)}),
        readings={"T2": Quantity(0.35 + 0.01 * k, "N m"), "F_y": Quantity(4.08, "N")},
        calibration={"dynamometer": {"gain": Quantity(2.5, "N/V"), "lever_ratio": Quantity(102 / 42.5, "1")}},
    )


def truth(k: int) -> dict[str, Quantity]:
    return {"l": Quantity(1e-4 * k, "m"), "c": Quantity(4.86e-4, "m"), "mu": Quantity(0.4, "1"),
            "F_x": Quantity(30.0 + k, "N")}


def write_run(path: Path, indices=range(N_POINTS), *, seed: int = 7, finalize: bool = True) -> LogWriter:
    writer = LogWriter(path, metadata(seed))
    for k in indices:
        if k not in writer.done:
            writer.write_point(point(k), truth(k))
    if finalize:
        writer.finalize()
    return writer


def _v1_quantities(group: h5py.Group, values) -> None:
    for name, q in values.items():
        group.create_dataset(name, data=np.float64(q.value)).attrs["units"] = q.unit


def _v1_point(points: h5py.Group, p: PointRecord) -> None:
    """One point in the layout of format version 1 (docs/log-format.md), as earlier versions wrote it."""
    group = points.create_group(f"point_{p.index:06d}")
    group.attrs["index"] = np.int64(p.index)
    _v1_quantities(group.create_group("settings"), p.settings)
    _v1_quantities(group.create_group("readings"), p.readings)
    channels = group.create_group("channels")
    for name, channel in p.channels.items():
        ds = channels.create_dataset(name, data=channel.samples)
        ds.attrs.update(units=channel.unit, sample_rate_Hz=np.float64(channel.sample_rate_Hz),
                        start_time_s=np.float64(channel.start_time_s))
    if p.counters is not None:
        counters = group.create_group("counters")
        counters.attrs["gate_time_s"] = np.float64(p.counters.gate_time_s)
        for name, counter in p.counters.counters.items():
            ds = counters.create_dataset(name, data=np.int64(counter.count))
            ds.attrs.update(units="count", marks_per_rev=np.int64(counter.marks_per_rev))
    calibration = group.create_group("calibration")
    for name, record in p.calibration.items():
        _v1_quantities(calibration.create_group(name), record)


def write_v1_run(path: Path) -> None:
    """The same run in the layout of format version 1 (one group per point), as earlier versions
    wrote it: the readers of version-1 logs are tested on it."""
    import rig.logbook.h5format as h5format

    with h5py.File(path, "w") as f:
        h5format.write_metadata(f, metadata())
        f.attrs["format_version"] = np.int64(1)
        points, truths = f.create_group("points"), f.create_group("truth")
        for k in range(N_POINTS):
            _v1_point(points, point(k))
            group = truths.create_group(f"point_{k:06d}")
            group.attrs["index"] = np.int64(k)
            _v1_quantities(group, truth(k))


def journal_frames(path: Path) -> list[int]:
    """Indices of the complete frames in the staging journal of the log ``path`` (none yet: [])."""
    from rig.logbook import journal, staging_dir

    file = staging_dir(path) / "points.journal"
    return [frame.index for frame in journal.scan(file)[0]] if file.is_file() else []


def dump(path: Path) -> dict:
    """Every object of an HDF5 file: {path: (kind, attrs, data)} (for content comparison)."""
    out = {}
    with h5py.File(path, "r") as handle:
        def visit(name, obj):
            attrs = {k: np.asarray(v).tolist() for k, v in sorted(obj.attrs.items())}
            data = np.asarray(obj[()]).tolist() if isinstance(obj, h5py.Dataset) else None
            out[name] = (type(obj).__name__, attrs, data)
        visit("/", handle)
        handle.visititems(visit)
    return out


def _hang(marker: Path, handle: h5py.File) -> None:
    """Flush what is written so far, tell the parent, and wait to be killed."""
    handle.flush()
    marker.touch()
    while True:
        time.sleep(1.0)


def main(mode: str, path: str, marker: str) -> None:
    """Child process: write a run and hang mid-write (the parent kills it with SIGKILL)."""
    import rig.logbook.reduced as reduced
    import rig.logbook.writer as writer

    log, signal = Path(path), Path(marker)
    if mode == "point":  # hang in the middle of writing point 3's frame (half of it on disk)
        import rig.logbook.journal as journal
        original = journal.encode

        def encode(entry):
            frame = original(entry)
            if entry.index == 3:
                with open(writer.staging_dir(log) / writer.JOURNAL, "ab") as handle:
                    handle.write(frame[: len(frame) // 2])
                signal.touch()
                while True:
                    time.sleep(1.0)
            return frame
        journal.encode = encode
        write_run(log)
    elif mode == "finalize":  # hang after laying out part of the new log
        def write_columnar(root, entries):
            root.create_group("points").create_dataset("index", data=np.arange(2))
            _hang(signal, root.file)
        writer.write_columnar = write_columnar
        write_run(log)
    elif mode == "reduced":  # hang in the middle of writing /reduced
        def write_table(group, table, units):
            group.create_dataset("partial", data=np.zeros(3))
            _hang(signal, group.file)
        reduced._write_table = write_table
        import pandas as pd
        reduced.write_reduced(log, pd.DataFrame({"mu": [0.4]}), {"mu": "1"})
    elif mode == "free":  # no hook: the parent kills at a moment of its choice
        signal.touch()
        writer_ = LogWriter(log, metadata())
        for k in range(200):
            writer_.write_point(point(k, n_samples=20_000), truth(k))
        while True:  # never end before the parent's kill (that would be a different test)
            time.sleep(1.0)
    else:
        raise SystemExit(f"unknown mode {mode!r}")


if __name__ == "__main__":
    main(*sys.argv[1:])
