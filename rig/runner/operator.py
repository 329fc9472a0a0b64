"""The operator: a simpy process that plays the experimenter at the stand.

For each operating point: set the point (``stand.start_point``) -> wait until it settles (the
stand detects the steady state; past the scene's timeout it raises SettleTimeoutError, which is
reported, never waited on forever) -> open the common gate for the gate time -> read the
instruments -> next point. The simpy clock is the operator's simulated time [s]: settling takes
the stand's reported settle time, a point that does not settle costs the whole timeout, the gate
costs the gate time. The physics is in the stand (rig.stands.base); every point is simulated
from its own arguments, so a point gives the same result in any process and in any order.

Policy on non-convergence (``procedure.on_settle_timeout``): SKIP reports the point and goes
on, STOP reports it and ends the run. Any other error propagates (after the points already
delivered, so an interrupted run resumes).
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Generator, Iterable
from dataclasses import dataclass

import simpy

from rig.errors import RigError
from rig.scenes.procedure import PlannedPoint, Procedure, TimeoutPolicy
from rig.stands.base import PointOutcome, SettleReport, SettleTimeoutError, Stand


class Step(enum.Enum):
    """What the operator did at a moment of its clock."""

    SET = "set point"
    SETTLED = "settled"
    TIMED_OUT = "settle timeout"
    GATE_OPEN = "gate open"
    GATE_CLOSED = "gate closed"
    READ = "read instruments"


@dataclass(frozen=True)
class PointResult:
    """One operating point as the operator finished it.

    outcome: the stand's PointOutcome (None if the point did not settle); settle: the report
    of ``settle`` as the operator received it (None if it did not settle); failure: the
    SettleTimeoutError message (None if it settled); timeline: (step, operator time [s]).
    """

    point: PlannedPoint
    outcome: PointOutcome | None
    settle: SettleReport | None
    failure: str | None
    timeline: tuple[tuple[Step, float], ...]


def _one_point(env: simpy.Environment, stand: Stand, point: PlannedPoint, procedure: Procedure,
               seed: int) -> Generator[simpy.Event, None, PointResult]:
    timeline = [(Step.SET, env.now)]
    timeout = procedure.settle_timeout_s
    simulation = stand.start_point(point.index, dict(point.settings),
                                   None if point.previous is None else dict(point.previous), seed)
    try:
        report = simulation.settle(timeout)
        if not report.duration_s <= timeout:  # a stand past its timeout (or NaN) did not settle
            raise SettleTimeoutError(point.settings, timeout, report.residual, report.criterion)
    except SettleTimeoutError as error:
        yield env.timeout(timeout)
        timeline.append((Step.TIMED_OUT, env.now))
        return PointResult(point, None, None, str(error), tuple(timeline))
    yield env.timeout(report.duration_s)
    timeline.append((Step.SETTLED, env.now))
    gate = simulation.gate(procedure.gate_time_s)
    timeline.append((Step.GATE_OPEN, env.now))
    yield env.timeout(procedure.gate_time_s)
    timeline.append((Step.GATE_CLOSED, env.now))
    outcome = simulation.read(gate)
    timeline.append((Step.READ, env.now))
    if outcome.record.index != point.index:
        raise RigError(f"stand {stand.name!r} returned a record with index {outcome.record.index} for point "
                       f"{point.index}")
    return PointResult(point, outcome, report, None, tuple(timeline))


def operate(env: simpy.Environment, stand: Stand, points: Iterable[PlannedPoint], procedure: Procedure, seed: int,
            deliver: Callable[[PointResult], None], raised: list[Exception]) -> Generator[simpy.Event, None, None]:
    """The operator process: ``deliver`` receives each finished point in order.

    An error of a point (or of ``deliver``) is appended to ``raised`` and ends the process,
    instead of propagating through simpy (which rebuilds an exception as
    ``type(error)(*error.args)`` - a TypeError for errors whose constructor takes other arguments).
    """
    try:
        for point in points:
            result = yield from _one_point(env, stand, point, procedure, seed)
            deliver(result)
            if result.failure is not None and procedure.on_settle_timeout is TimeoutPolicy.STOP:
                return
    except Exception as error:  # noqa: BLE001 - handed to run_operator, raised there unchanged
        raised.append(error)


def run_operator(stand: Stand, points: Iterable[PlannedPoint], procedure: Procedure, seed: int,
                 deliver: Callable[[PointResult], None]) -> float:
    """Run the operator over ``points`` on a fresh simpy clock; returns the operator time spent [s].

    An error inside a point propagates as it was raised (type, message and attributes)."""
    env = simpy.Environment()
    raised: list[Exception] = []
    env.process(operate(env, stand, points, procedure, seed, deliver, raised))
    env.run()
    if raised:
        raise raised[0]
    return float(env.now)
