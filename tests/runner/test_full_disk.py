"""A run onto a full file system: one named line, exit 2, nothing committed lost, the rerun completes.

A small tmpfs (mounted here; the test is skipped, with the reason, where mounting is not
allowed) is filled so that a few kB to some tens of kB stay free, which makes the run fail while
writing the staging part run.h5, the log, or the outputs. Each time ``rig run`` must print one
line naming the file and the cause and exit 2 (HDF5 left to itself crashed the process with a
segmentation fault or printed tracebacks); after the space is freed the same command must give
the log and reduced.csv of an undisturbed run.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.runner import fake_stand
from tests.runner.logs import assert_same_log

ROOT = Path(__file__).resolve().parents[2]
TMPFS_KB = 1024
FREE_KB = (8, 32, 72)
"""Free space left [kB]: the run fails at run.h5 (8), at the log (32), at the outputs (72)."""


@pytest.fixture
def small_disk(tmp_path: Path):
    mount = tmp_path / "disk"
    mount.mkdir()
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={TMPFS_KB}k", "tmpfs", str(mount)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here ({done.stderr.strip() or done.returncode}); needs root")
    try:
        yield mount
    finally:
        subprocess.run(["umount", "-l", str(mount)], check=False)


def test_run_onto_a_full_disk_names_the_file_and_the_rerun_completes(small_disk, tmp_path, monkeypatch):
    scene = tmp_path / "fake.toml"
    scene.write_text(fake_stand.scene_text())
    results = tmp_path / "results"
    child = subprocess.run([sys.executable, "-m", "tests.runner.full_disk_child", str(scene), str(small_disk),
                            str(results), *map(str, FREE_KB)], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert child.returncode == 0, child.stderr[-2000:]
    levels = [json.loads(line) for line in child.stdout.splitlines()]
    assert [level["free_kb"] for level in levels] == list(FREE_KB)

    fake_stand.register(monkeypatch)
    import rig.cli

    reference = tmp_path / "reference"
    assert rig.cli.main(["run", str(scene), "-o", str(reference)]) == 0
    failed_at = set()
    for level in levels:
        lines = level["stderr"].splitlines()
        assert level["status"] == 2 and len(lines) == 1, level
        prefix = f"rig run: error: No space left on device: {small_disk}/run/"
        match = re.fullmatch(rf"{re.escape(prefix)}(\S+)", lines[0])
        assert match, lines[0]
        failed_at.add(match.group(1))
        assert level["rerun_status"] == 0 and level["rerun_stderr"] == "", level
        kept = results / str(level["free_kb"])
        assert (kept / "reduced.csv").read_text() == (reference / "reduced.csv").read_text()
        assert_same_log(kept / "log.h5", reference / "log.h5")
    assert len(failed_at) == len(FREE_KB), failed_at  # three different write paths were hit
