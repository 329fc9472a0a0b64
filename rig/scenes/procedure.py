"""The procedure of a stand scene: fixed and swept settings, settle timeout, gate time, repeats.

The operating points are the Cartesian product of the swept settings, the first-named sweep
outermost, each point repeated ``repeats`` times in a row; fixed settings are the same at every
point. A procedure may instead hold several series (``[[procedure.series]]``), each with its own
fixed and swept settings, run one after the other - e.g. a brake sweep whose range depends on
the load; ``[procedure.fixed]`` then holds what all series share, and every series sweeps the
same settings. Every setting a stand declares (``Stand.SETTINGS``) must be given, fixed or swept
- no silent defaults for physical input - and inside its range.
"""

from __future__ import annotations

import enum
import itertools
import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

from rig import validate
from rig.errors import ParameterError
from rig.scenes import tables as T

MAX_POINTS = 10**6 - 1
"""Most operating points one run may have (the log's point index has six digits)."""

WHERE = "procedure"
KEYS = ("settle_timeout_s", "gate_time_s", "repeats", "on_settle_timeout", "fixed", "sweep", "series")
SERIES_KEYS = ("fixed", "sweep")


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
class Series:
    """Fixed settings and swept settings (ordered, outermost first) of one series of points."""

    fixed: Mapping[str, float]
    sweep: tuple[tuple[str, tuple[float, ...]], ...]

    @property
    def n_combinations(self) -> int:
        return math.prod(len(axis) for _, axis in self.sweep)

    def combinations(self) -> list[dict[str, float]]:
        names = [name for name, _ in self.sweep]
        return [dict(zip(names, values)) | dict(self.fixed)
                for values in itertools.product(*(axis for _, axis in self.sweep))]

    def thinned(self, max_values: int) -> Series:
        """At most ``max_values`` values of each swept setting, spread over its range."""
        return Series(self.fixed, tuple((name, _spread(axis, max_values)) for name, axis in self.sweep))


def _spread(values: tuple[float, ...], count: int) -> tuple[float, ...]:
    if len(values) <= count:
        return values
    picks = sorted({round(k * (len(values) - 1) / max(count - 1, 1)) for k in range(count)})
    return tuple(values[k] for k in picks)


@dataclass(frozen=True)
class Procedure:
    """What the operator does: one or more series of points, settle timeout [s], gate time [s],
    repeats per point and the settle-timeout policy."""

    series: tuple[Series, ...]
    settle_timeout_s: float
    gate_time_s: float
    repeats: int
    on_settle_timeout: TimeoutPolicy

    @property
    def sweep(self) -> tuple[tuple[str, tuple[float, ...]], ...]:
        """The swept settings (the same names in every series), each with all its values."""
        names = [name for name, _ in self.series[0].sweep]
        return tuple((name, tuple(dict.fromkeys(v for s in self.series for v in dict(s.sweep)[name])))
                     for name in names)

    @property
    def fixed(self) -> dict[str, float]:
        """The settings fixed at the same value in every series."""
        first = self.series[0].fixed
        return {k: v for k, v in first.items() if all(s.fixed.get(k) == v for s in self.series)}

    @property
    def series_settings(self) -> list[str]:
        """Settings fixed within each series but different between series (they label the series)."""
        return [k for k in self.series[0].fixed if k not in self.fixed]

    @property
    def n_points(self) -> int:
        """Number of operating points: the series' combinations times repeats."""
        return self.repeats * sum(s.n_combinations for s in self.series)

    def points(self) -> list[PlannedPoint]:
        """The operating points in run order (indices 0 .. n_points - 1)."""
        planned: list[PlannedPoint] = []
        previous = None
        for series in self.series:
            for settings in series.combinations():
                for repeat in range(self.repeats):
                    planned.append(PlannedPoint(len(planned), settings, previous, repeat))
                    previous = settings
        return planned

    def thinned(self, max_values: int) -> Procedure:
        """A shorter procedure: at most ``max_values`` values per swept setting and series, one repeat."""
        return replace(self, series=tuple(s.thinned(max_values) for s in self.series), repeats=1)


def _fixed(table: Mapping[str, object], specs: Mapping[str, object], where: str) -> dict[str, float]:
    T.check_keys(table, specs, where)
    return {name: _setting(T.dotted(where, name), value, specs[name]) for name, value in table.items()}


def _setting(where: str, value: object, spec) -> float:
    """One value of a setting: inside the spec's range and one of its choices, if it has any."""
    return spec.check_choice(where, T.number(where, value, spec.lo, spec.hi, spec.unit))


def _sweep(table: Mapping[str, object], specs: Mapping[str, object], where: str):
    T.check_keys(table, specs, where)
    sweep = []
    for name, given in table.items():
        values = T.values(T.dotted(where, name), given, specs[name].lo, specs[name].hi, specs[name].unit)
        sweep.append((name, tuple(specs[name].check_choice(f"{T.dotted(where, name)}[{k}]", value)
                                  for k, value in enumerate(values))))
    return tuple(sweep)


def _series(common: dict[str, float], fixed: dict[str, float], sweep, specs, where: str) -> Series:
    """One series: common + own fixed settings and the sweep; every setting given exactly once."""
    for name in fixed:
        if name in common:
            raise ParameterError(T.dotted(where, f"fixed.{name}"), fixed[name],
                                 f"given once: it is also in [{WHERE}.fixed]")
    fixed = common | fixed
    for name, _ in sweep:
        if name in fixed:
            raise ParameterError(T.dotted(where, f"sweep.{name}"), dict(sweep)[name],
                                 "either fixed or swept, not both")
    swept = dict(sweep)
    for name, spec in specs.items():
        if name not in fixed and name not in swept:
            raise ParameterError(T.dotted(where, f"fixed.{name}"), T.MISSING,
                                 f"a number in [{spec.lo:g}, {spec.hi:g}] {spec.unit} ({spec.description}), fixed "
                                 f"or swept; required (no default for physical input)")
    return Series(fixed, sweep)


def parse_procedure(table: Mapping[str, object], settings_specs: Mapping[str, object], *,
                    max_gate_time_s: float | None = None, gate_limit: str = "") -> Procedure:
    """Validate the ``[procedure]`` table against the stand's SETTINGS {name: SettingSpec};
    ``max_gate_time_s`` [s]: the longest gate the stand can record (``gate_limit`` says why), so
    that the range an error states is the range enforced."""
    T.check_keys(table, KEYS, WHERE)
    timeout = T.number(T.dotted(WHERE, "settle_timeout_s"),
                       T.required(table, "settle_timeout_s", WHERE, "a number in (0, inf) s"), 0.0, None, "s",
                       lo_open=True)
    gate_range = f"(0, {'inf)' if max_gate_time_s is None else f'{max_gate_time_s:g}]'} s"
    given_gate = T.required(table, "gate_time_s", WHERE, f"a number in {gate_range}")
    try:
        gate = T.number(T.dotted(WHERE, "gate_time_s"), given_gate, 0.0, max_gate_time_s, "s", lo_open=True)
    except ParameterError as error:
        valid = f"{gate_range}: {gate_limit}" if gate_limit else gate_range
        raise ParameterError(error.name, error.value, valid) from None
    repeats = validate.integer(T.dotted(WHERE, "repeats"), table.get("repeats", 1), 1, MAX_POINTS)
    policy = T.member(TimeoutPolicy, table.get("on_settle_timeout", TimeoutPolicy.SKIP.value),
                      T.dotted(WHERE, "on_settle_timeout"))
    common = _fixed(T.sub_table(table, "fixed", WHERE, required=False) or {}, settings_specs, T.dotted(WHERE, "fixed"))
    given = table.get("series")
    if given is None:
        sweep = _sweep(T.sub_table(table, "sweep", WHERE, required=False) or {}, settings_specs,
                       T.dotted(WHERE, "sweep"))
        series = (_series({}, common, sweep, settings_specs, WHERE),)
    else:
        if "sweep" in table:
            raise ParameterError(T.dotted(WHERE, "sweep"), table["sweep"],
                                 f"absent when [[{WHERE}.series]] is given (each series has its own sweep)")
        if not isinstance(given, list) or not given:
            raise ParameterError(T.dotted(WHERE, "series"), given, "a non-empty array of tables [[procedure.series]]")
        series = []
        for k, entry in enumerate(given):
            where = f"{WHERE}.series[{k}]"
            if not isinstance(entry, Mapping):
                raise ParameterError(where, entry, "a table with 'fixed' and 'sweep'")
            T.check_keys(entry, SERIES_KEYS, where)
            own = _fixed(T.sub_table(entry, "fixed", where, required=False) or {}, settings_specs,
                         T.dotted(where, "fixed"))
            sweep = _sweep(T.sub_table(entry, "sweep", where, required=False) or {}, settings_specs,
                           T.dotted(where, "sweep"))
            series.append(_series(common, own, sweep, settings_specs, where))
        names = [name for name, _ in series[0].sweep]
        for k, entry in enumerate(series[1:], start=1):
            if [name for name, _ in entry.sweep] != names:
                raise ParameterError(f"{WHERE}.series[{k}].sweep", [n for n, _ in entry.sweep],
                                     f"the settings series[0] sweeps, in the same order: {names}")
        series = tuple(series)
    procedure = Procedure(series, timeout, gate, repeats, policy)
    if procedure.n_points > MAX_POINTS:
        raise ParameterError("procedure: number of operating points", procedure.n_points, f"[1, {MAX_POINTS}]")
    return procedure
