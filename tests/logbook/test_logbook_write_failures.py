"""A write that fails (full disk) while an HDF5 file is written: one OSError naming the file, the
target untouched, no temporary file left, and HDF5 still usable (it never saw the failure).

The disk is made "full" by letting os.pwrite of rig.logbook.atomic refuse writes after a budget of
bytes, at many budgets, so that the failure falls on every kind of write HDF5 does (superblock,
object headers, chunks, the flush at close). tests/runner/test_full_disk.py does the same on a
real file system that is full.
"""

from __future__ import annotations

import errno
import os

import h5py
import numpy as np
import pytest

from rig.logbook import atomic


def _write_log(target, tmp_folder=None):
    with atomic.new_hdf5(target, tmp_folder) as handle:
        for k in range(20):
            handle.create_dataset(f"g/d{k}", data=np.arange(2000.0) + k, chunks=(500,), maxshape=(None,),
                                  compression="gzip", fletcher32=True)
        handle.attrs["format"] = "test"


@pytest.mark.parametrize("budget", [0, 100, 2_000, 10_000, 20_000, 40_000])
def test_a_full_disk_at_any_byte_names_the_file_and_leaves_the_target(budget, tmp_path, monkeypatch):
    target = tmp_path / "log.h5"
    target.write_bytes(b"previous log")
    written = {"bytes": 0}
    real_pwrite = os.pwrite

    def pwrite(fd, data, offset):
        if written["bytes"] + len(data) > budget:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        written["bytes"] += len(data)
        return real_pwrite(fd, data, offset)

    monkeypatch.setattr(atomic.os, "pwrite", pwrite)
    with pytest.raises(OSError) as caught:
        _write_log(target)
    monkeypatch.undo()
    assert caught.value.errno == errno.ENOSPC and caught.value.filename == str(target)
    assert str(caught.value) == f"[Errno 28] No space left on device: '{target}'"
    assert target.read_bytes() == b"previous log" and sorted(p.name for p in tmp_path.iterdir()) == ["log.h5"]
    _write_log(target)  # HDF5 is in order: the same write now succeeds
    with h5py.File(target, "r") as f:
        np.testing.assert_array_equal(f["g/d19"][:], np.arange(2000.0) + 19)


def test_an_unnamed_os_error_inside_an_atomic_write_is_named(tmp_path):
    target = tmp_path / "fit.csv"
    with pytest.raises(OSError, match=r"No space left on device: '.*fit\.csv'"):
        with atomic.replace_atomically(target, atomic.temporary_path(tmp_path, target.name)):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    assert not list(tmp_path.iterdir())
