"""The simpy operator: order set -> settle -> gate -> read per point, its clock, and timeouts.

Independent numbers: the fake stand settles as a first-order lag, so a load step of D newtons
takes tau ln(1 + D / 1 N) seconds (tests/runner/fake_stand.py); the operator's clock must add
exactly these settle times and the gate times, and a point that does not settle costs the whole
timeout.
"""

from __future__ import annotations

import math
from unittest import mock

import pytest

from rig.runner.operator import Step, run_operator
from rig.scenes import TimeoutPolicy, parse_scene
from rig.stands.base import SettleReport
from tests.runner.fake_stand import FakePoint, register, scene_text


@pytest.fixture(autouse=True)
def _fake_stand(monkeypatch):
    register(monkeypatch)


def scene_with(replace):
    return parse_scene(scene_text(replace), name="fake")


def run(scene, stand=None):
    stand = stand or scene.build_stand()
    stand.calibrate(scene.seed)
    results = []
    clock = run_operator(stand, scene.procedure.points(), scene.procedure, scene.seed, results.append)
    return results, clock


def test_each_point_is_set_settled_gated_and_read_in_order():
    scene = scene_with({"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 10.0, 30.0]"})
    calls = []
    for method in ("settle", "gate", "read"):
        original = getattr(FakePoint, method)

        def spy(self, *args, _name=method, _original=original):
            calls.append((_name, self.index))
            return _original(self, *args)

        mock.patch.object(FakePoint, method, spy).start()
    try:
        results, clock = run(scene)
    finally:
        mock.patch.stopall()
    assert calls == [(step, k) for k in range(3) for step in ("settle", "gate", "read")]
    tau, gate = 0.2, 1.0
    settle = [tau * math.log(6.0), tau * math.log(6.0), tau * math.log(21.0)]  # steps 5, 5, 20 N
    start = 0.0
    for result, expected in zip(results, settle):
        times = dict(result.timeline)
        assert [step for step, _ in result.timeline] == [Step.SET, Step.SETTLED, Step.GATE_OPEN, Step.GATE_CLOSED,
                                                         Step.READ]
        assert times[Step.SET] == pytest.approx(start)
        assert times[Step.SETTLED] - times[Step.SET] == pytest.approx(expected)
        assert times[Step.GATE_CLOSED] - times[Step.GATE_OPEN] == pytest.approx(gate)
        assert result.settle.duration_s == pytest.approx(expected)
        start = times[Step.READ]
    assert clock == pytest.approx(sum(settle) + 3 * gate)


@pytest.mark.parametrize("policy, delivered", [("skip", [0, 1, 2, 3]), ("stop", [0, 1, 2])])
def test_a_point_that_does_not_settle_is_reported_and_costs_the_timeout(policy, delivered):
    # tau = 1 s, timeout 3 s: the step 10 -> 50 N needs ln(41) = 3.71 s > 3 s; 5 N steps need 1.79 s
    scene = scene_with({"mu = 0.3": "mu = 0.3\nsettle_tau_s = 1.0", "load_N = [5.0, 10.0, 20.0, 25.0]":
                        "load_N = [5.0, 10.0, 50.0, 55.0]",
                        "settle_timeout_s = 3.0": f'settle_timeout_s = 3.0\non_settle_timeout = "{policy}"'})
    assert scene.procedure.on_settle_timeout is TimeoutPolicy(policy)
    results, clock = run(scene)
    assert [r.point.index for r in results] == delivered
    failed = results[2]
    assert failed.outcome is None and failed.settle is None
    assert "did not settle within 3 s" in failed.failure and "'load_N': 50.0" in failed.failure
    assert [step for step, _ in failed.timeline] == [Step.SET, Step.TIMED_OUT]
    assert failed.timeline[1][1] - failed.timeline[0][1] == pytest.approx(3.0)
    settled = [math.log(6.0), math.log(6.0)] + ([math.log(6.0)] if policy == "skip" else [])
    assert clock == pytest.approx(sum(settled) + 3.0 + len(settled) * 1.0)


@pytest.mark.parametrize("duration", [float("nan"), 4.0, float("inf")])
def test_a_settle_report_past_the_timeout_counts_as_not_settled(duration):
    """A stand that reports a settle time beyond (or not comparable with) the timeout never makes
    the operator wait for it: the point is reported like a SettleTimeoutError."""
    scene = scene_with({"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0]"})
    report = SettleReport(duration, "|x| < 1", 0.5, "rest")
    with mock.patch.object(FakePoint, "settle", return_value=report), \
            mock.patch.object(FakePoint, "gate") as gate:
        results, clock = run(scene)
    assert results[0].outcome is None and "did not settle within 3 s" in results[0].failure
    assert clock == pytest.approx(3.0)
    gate.assert_not_called()


def test_calibration_is_done_once_and_used_in_every_record():
    scene = scene_with(None)
    stand = scene.build_stand()
    results, _ = run(scene, stand)
    assert stand.calibrations == 1
    records = [r.outcome.record.calibration["dynamometer"]["gain"] for r in results]
    assert len(records) == 4 and all(r == records[0] for r in records)


def test_points_are_pure_in_their_arguments():
    """The same point simulated alone equals the point inside the sweep (the contract's rule that
    makes resuming and parallel runs identical)."""
    scene = scene_with(None)
    all_results, _ = run(scene)
    third = scene.procedure.points()[2]
    stand = scene.build_stand()
    stand.calibrate(scene.seed)
    single = []
    run_operator(stand, [third], scene.procedure, scene.seed, single.append)
    assert single[0].outcome.record == all_results[2].outcome.record
    assert single[0].outcome.truth == all_results[2].outcome.truth
