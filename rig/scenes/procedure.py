"""The procedure of a stand scene: fixed and swept settings, settle timeout, gate time, repeats.

The operating points are the Cartesian product of the swept settings, the first-named sweep
outermost, each point repeated ``repeats`` times in a row; fixed settings are the same at every
point. Every setting a stand declares (``Stand.SETTINGS``) must be given, fixed or swept - no
silent defaults for physical input - and inside its range.
"""

from __future__ import annotations

import enum
import itertools
from collections.abc import Mapping
from dataclasses import dataclass

from rig import validate
from rig.errors import ParameterError
from rig.scenes import tables as T

MAX_POINTS = 10**6 - 1
"""Most operating points one run may have (the log's point index has six digits)."""

WHERE = "procedure"
KEYS = ("settle_timeout_s", "gate_time_s", "repeats", "on_settle_timeout", "fixed", "sweep")


class TimeoutPolicy(enum.Enum):
    """What the operator does when a point does not settle within the timeout.

    SKIP: report the point as failed (no record in the log) and go on with the next point;
    STOP: report it and end the run there (the points before it are kept).
    """

    SKIP = "skip"
    STOP = "stop"


@dataclass(frozen=True)
class PlannedPoint:
    """One operating point of the plan.

    index: position in the plan (the log's point index); settings: {setting name: value in the
    setting's unit}; previous: the settings of point index - 1 (None for the first point: the
    stand starts from rest); repeat: 0 .. repeats - 1.
    """

    index: int
    settings: Mapping[str, float]
    previous: Mapping[str, float] | None
    repeat: int


@dataclass(frozen=True)
class Procedure:
    """What the operator does: fixed settings, swept settings (ordered, outermost first),
    settle timeout [s], gate time [s], repeats per point and the settle-timeout policy."""

    fixed: Mapping[str, float]
    sweep: tuple[tuple[str, tuple[float, ...]], ...]
    settle_timeout_s: float
    gate_time_s: float
    repeats: int
    on_settle_timeout: TimeoutPolicy

    @property
    def n_points(self) -> int:
        """Number of operating points: product of the sweep lengths times repeats."""
        count = self.repeats
        for _, axis in self.sweep:
            count *= len(axis)
        return count

    def points(self) -> list[PlannedPoint]:
        """The operating points in run order (indices 0 .. n_points - 1)."""
        names = [name for name, _ in self.sweep]
        planned: list[PlannedPoint] = []
        previous = None
        for combination in itertools.product(*(axis for _, axis in self.sweep)):
            settings = dict(zip(names, combination)) | dict(self.fixed)
            for repeat in range(self.repeats):
                planned.append(PlannedPoint(len(planned), settings, previous, repeat))
                previous = settings
        return planned


def parse_procedure(table: Mapping[str, object], settings_specs: Mapping[str, object]) -> Procedure:
    """Validate the ``[procedure]`` table against the stand's SETTINGS {name: SettingSpec}."""
    T.check_keys(table, KEYS, WHERE)
    timeout = T.number(T.dotted(WHERE, "settle_timeout_s"),
                       T.required(table, "settle_timeout_s", WHERE, "a number in (0, inf) s"), 0.0, None, "s",
                       lo_open=True)
    gate = T.number(T.dotted(WHERE, "gate_time_s"),
                    T.required(table, "gate_time_s", WHERE, "a number in (0, inf) s"), 0.0, None, "s", lo_open=True)
    repeats = validate.integer(T.dotted(WHERE, "repeats"), table.get("repeats", 1), 1, MAX_POINTS)
    policy = T.member(TimeoutPolicy, table.get("on_settle_timeout", TimeoutPolicy.SKIP.value),
                      T.dotted(WHERE, "on_settle_timeout"))
    fixed_table = T.sub_table(table, "fixed", WHERE, required=False) or {}
    sweep_table = T.sub_table(table, "sweep", WHERE, required=False) or {}
    fixed_where, sweep_where = T.dotted(WHERE, "fixed"), T.dotted(WHERE, "sweep")
    T.check_keys(fixed_table, settings_specs, fixed_where)
    T.check_keys(sweep_table, settings_specs, sweep_where)
    fixed = {}
    for name, value in fixed_table.items():
        spec = settings_specs[name]
        if name in sweep_table:
            raise ParameterError(T.dotted(fixed_where, name), value,
                                 f"either fixed or swept, not both (also in [{sweep_where}])")
        fixed[name] = T.number(T.dotted(fixed_where, name), value, spec.lo, spec.hi, spec.unit)
    sweep = tuple(
        (name, T.values(T.dotted(sweep_where, name), given, settings_specs[name].lo, settings_specs[name].hi,
                        settings_specs[name].unit))
        for name, given in sweep_table.items()
    )
    for name, spec in settings_specs.items():
        if name not in fixed and name not in sweep_table:
            raise ParameterError(T.dotted(fixed_where, name), T.MISSING,
                                 f"a number in [{spec.lo:g}, {spec.hi:g}] {spec.unit} ({spec.description}), fixed "
                                 f"here or swept in [{sweep_where}]; required (no default for physical input)")
    procedure = Procedure(fixed, sweep, timeout, gate, repeats, policy)
    if procedure.n_points > MAX_POINTS:
        raise ParameterError("procedure: number of operating points", procedure.n_points, f"[1, {MAX_POINTS}]")
    return procedure
