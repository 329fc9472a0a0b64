"""An interrupted run resumes to the same log; a process pool gives the same log as one process.

The reference is always an uninterrupted single-process run of the same scene in another folder;
logs are compared by content (records, truth, metadata but the start time) and reduced.csv by text.
"""

from __future__ import annotations

import subprocess
import sys
from unittest import mock

import pytest

from rig.errors import ParameterError
from rig.logbook import staging_dir
from rig.runner import run_scene
from rig.scenes import parse_scene
from tests.runner.fake_stand import NO_FIGURES, FakeStand, register, scene_text
from tests.runner.logs import assert_same_log

SWEEP = NO_FIGURES | {"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 10.0, 50.0, 55.0, 60.0, 8.0]",
         "mu = 0.3": "mu = 0.3\nsettle_tau_s = 1.0"}  # point 2 (10 -> 50 N) does not settle; 5 (60 -> 8) neither


@pytest.fixture(autouse=True)
def _fake_stand(monkeypatch):
    register(monkeypatch)


@pytest.fixture
def scene():
    return parse_scene(scene_text(SWEEP), name="fake")


@pytest.fixture
def reference(scene, tmp_path):
    folder = tmp_path / "reference"
    report = run_scene(scene, folder, progress=False)
    assert [f.index for f in report.failures] == [2, 5]
    return folder, report


def test_interrupted_run_resumes_to_the_same_log(scene, reference, tmp_path):
    folder = tmp_path / "interrupted"
    original = FakeStand.start_point

    def start_point(self, index, *args):
        if index == 3:
            raise KeyboardInterrupt  # the operator is stopped after points 0 and 1 were written
        return original(self, index, *args)

    with mock.patch.object(FakeStand, "start_point", start_point), pytest.raises(KeyboardInterrupt):
        run_scene(scene, folder, progress=False)
    assert not (folder / "log.h5").exists() and staging_dir(folder / "log.h5").is_dir()

    report = run_scene(scene, folder, progress=False)
    assert report.resumed == 2 and report.in_log == 4 and [f.index for f in report.failures] == [2, 5]
    assert "(2 resumed from an interrupted run, 2 simulated now), failed 2" in report.summary
    assert_same_log(reference[0] / "log.h5", folder / "log.h5")
    assert (folder / "reduced.csv").read_text() == (reference[0] / "reduced.csv").read_text()
    assert not staging_dir(folder / "log.h5").exists()


def test_resuming_with_another_scene_text_is_refused(scene, tmp_path):
    folder = tmp_path / "run"
    with mock.patch.object(FakeStand, "start_point", side_effect=KeyboardInterrupt), pytest.raises(KeyboardInterrupt):
        run_scene(scene, folder, progress=False)
    other = parse_scene(scene_text(SWEEP | {"seed = 7": "seed = 8"}), name="fake")
    with pytest.raises(ValueError, match="delete .* to start the run over"):
        run_scene(other, folder, progress=False)


def test_two_jobs_give_the_same_log_as_one(scene, reference, tmp_path):
    folder = tmp_path / "pool"
    report = run_scene(scene, folder, jobs=2, progress=False)
    assert [f.index for f in report.failures] == [2, 5] and report.in_log == 4
    assert_same_log(reference[0] / "log.h5", folder / "log.h5")
    assert (folder / "reduced.csv").read_text() == (reference[0] / "reduced.csv").read_text()
    assert report.summary.replace("jobs 2", "jobs 1").splitlines()[:12] == reference[1].summary.splitlines()[:12]


def test_two_jobs_stop_where_one_job_stops(tmp_path):
    stop = SWEEP | {"gate_time_s = 1.0": 'gate_time_s = 1.0\non_settle_timeout = "stop"'}
    scene = parse_scene(scene_text(stop), name="fake")
    one = run_scene(scene, tmp_path / "one", progress=False)
    two = run_scene(scene, tmp_path / "two", jobs=2, progress=False)
    assert one.stopped and two.stopped and one.in_log == two.in_log == 2
    assert_same_log(tmp_path / "one" / "log.h5", tmp_path / "two" / "log.h5")


@pytest.mark.parametrize("jobs", [1, 2])
def test_a_named_error_inside_a_point_arrives_whole_and_removes_the_staging_folder(tmp_path, jobs):
    # simpy rebuilt a point's error as type(error)(*error.args) - a TypeError for ParameterError
    # (issue 14 item 1); a worker sent it back as text. Now it is the error the stand raised.
    scene = parse_scene(scene_text(NO_FIGURES | {"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 950.0]"}),
                        name="fake")
    with pytest.raises(ParameterError) as raised:
        run_scene(scene, tmp_path, jobs=jobs, progress=False)
    assert raised.value.name == "load_N" and raised.value.value == 950.0
    assert str(raised.value) == "load_N = 950.0 is not valid; valid: at most 900 N (the fake stand's stall)"
    assert not staging_dir(tmp_path / "log.h5").exists() and not (tmp_path / "log.h5").exists()


def test_a_script_without_a_main_guard_gets_a_worker_error_that_names_the_guard(tmp_path):
    """Each worker of the pool starts by importing the calling script (spawn): a script that runs its
    study on import makes every worker fail. The run stops with a WorkerError that says what to do,
    instead of hanging or blaming the stand."""
    script = tmp_path / "study.py"
    script.write_text('import rig\nrig.run("default", "out", jobs=2)\n')
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=240)
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("rig.runner.pool.WorkerError") and 'if __name__ == "__main__":' in last, done.stderr[-2000:]
