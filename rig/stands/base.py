"""The contract between a test stand, the operator that runs a procedure, and the reduction.

A stand (rig.stands.yoke, rig.stands.disc_roller) composes a contact law, a drive train, a
brake or load, and the instruments of ``sensors``. A scene (rig.scenes) names the stand, its
parameter overrides, the effects to build and the procedure; the operator (rig.runner) plays
the experimenter: set the point -> wait to settle -> open the common gate -> read -> next.

**Every operating point is simulated independently of every other.** A point starts from the
steady state of the previous point's settings (computed directly, quasi-statically; rest for
the first point of a procedure) and steps to its own settings; its random streams derive from
(run seed, point index, instrument, effect). So an interrupted run resumes at point k with the
same results, and points may run in any order or in parallel (local pool, Dask) with results
identical to a serial run.

Units: SI throughout; every setting, parameter and logged quantity carries its unit in its
name or in a ``unit`` field.
"""

from __future__ import annotations

import enum
from abc import ABC, abstractmethod
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import ClassVar

from rig.errors import ConvergenceError, ParameterError
from rig.logbook import LogSchema, PointRecord, Quantity


class DriveMode(enum.Enum):
    """DYNAMIC: drive-train ODE (solve_ivp, implicit); QUASI_STATIC: steady state solved directly."""

    DYNAMIC = "dynamic"
    QUASI_STATIC = "quasi_static"


@dataclass(frozen=True)
class ParameterSpec:
    """A stand parameter a scene may override: default, unit, valid range, provenance.

    source: where the default comes from, starting with [text], [computed] or [assumed]
    (the Equations page tags), e.g. "[text] [Koziarski] section 3.1: F_N = 96.2 N and 385 N".
    """

    default: float
    unit: str
    lo: float
    hi: float
    source: str


@dataclass(frozen=True)
class ContactSpec:
    """How a stand evaluates the contact: model and grid, its effects, surrogate table or not.

    model: "rigid" | "linear" | "fastsim" | "kinematic"; n: cells across 2a (None: default);
    poisson: combined Poisson ratio of the pair [1]; effects: rig.contact effect keywords;
    surrogate: evaluate through a table over (l/a, c/a, log alpha') built once and cached on
    disk (True) or call the model directly (False); table_points: table nodes per axis;
    error_budget: the reduction estimates the law's numerical error at every reduced point (two
    direct solves, on n and 2n cells; rig.contact.numerical_error) and carries it in its budget.
    """

    model: str
    n: int | None
    poisson: float
    effects: Mapping[str, float] = field(default_factory=dict)
    surrogate: bool = True
    table_points: tuple[int, int, int] = (41, 9, 9)
    error_budget: bool = False


@dataclass(frozen=True)
class EffectSpec:
    """An optional effect a scene may name for a stand (drive compliance, brake dynamics,
    instrument noise, ...): its parameters with defaults and units, and what it models."""

    description: str
    parameters: Mapping[str, tuple[float, str]] = field(default_factory=dict)  # name -> (default, unit)


@dataclass(frozen=True)
class SettingSpec:
    """A quantity a procedure may set per operating point (e.g. the brake set-point).

    unit: SI unit string; lo, hi: valid range (inclusive) in that unit; description: one line;
    choices: the only values allowed, for a setting that takes a few (a speed step, a running
    direction); empty: any value in [lo, hi]. A scene is checked against them when it is read.
    """

    unit: str
    lo: float
    hi: float
    description: str
    choices: tuple[float, ...] = ()

    def check_choice(self, name: str, value: float) -> float:
        """``value`` if it is one of ``choices`` (or there are none), else a ParameterError naming ``name``."""
        if self.choices and value not in self.choices:
            raise ParameterError(name, value, "one of " + ", ".join(f"{c:g}" for c in self.choices)
                                 + f" ({self.description})")
        return value


@dataclass(frozen=True)
class SettleReport:
    """How an operating point reached its steady state.

    duration_s: simulated time from the step to the detected steady state [s];
    criterion: what was checked (e.g. "|d omega_2/dt| < 1e-4 rad/s^2 and |T_B - T_set| < 0.2 %
    over 0.5 s"); residual: the checked quantity's final value (dimensionless, relative);
    start: the state the point started from, in words ("rest", "steady state of the previous
    point", "disc following the swinging roller", ...).
    """

    duration_s: float
    criterion: str
    residual: float
    start: str


@dataclass(frozen=True)
class GateData:
    """What happened while the common gate was open: sampled true signals.

    t_s: sample times [s] covering [gate_open_s, gate_open_s + gate_time_s]; signals: name ->
    samples in the unit given by ``units[name]`` (wheel angles [rad], forces [N], moments
    [N m], ...). Stands decide which signals they need for their instruments and truth.
    """

    gate_open_s: float
    gate_time_s: float
    t_s: object  # numpy array
    signals: Mapping[str, object]
    units: Mapping[str, str]


@dataclass(frozen=True)
class PointOutcome:
    """One finished operating point: the log record, the truth, how it settled."""

    record: PointRecord
    truth: Mapping[str, Quantity]
    settle: SettleReport


class SettleTimeoutError(ConvergenceError):
    """The drive train did not reach a steady state within the timeout (reported, not hung)."""

    def __init__(self, settings: Mapping[str, float], timeout_s: float, residual: float, criterion: str) -> None:
        self.settings = dict(settings)
        self.timeout_s = timeout_s
        self.residual = residual
        super().__init__(
            f"operating point {self.settings} did not settle within {timeout_s:g} s of simulated time: "
            f"{criterion} still {residual:.3g}"
        )


class PointSimulation(ABC):
    """One operating point being simulated; the operator calls settle, gate, read in order."""

    @abstractmethod
    def settle(self, timeout_s: float) -> SettleReport:
        """Integrate from the step until steady (detected); SettleTimeoutError past timeout_s [s]."""

    @abstractmethod
    def gate(self, gate_time_s: float) -> GateData:
        """Integrate over the common gate of gate_time_s [s] and return the true signals."""

    @abstractmethod
    def read(self, gate: GateData) -> PointOutcome:
        """Feed the instruments with the gate's true signals: the log record and the truth."""


MAX_GATE_SAMPLES = 250_000
"""Most samples per channel one gate may hold: the simulated recorders' capacity (a stand-B gate
costs ~2 kB of working memory per sample, so ~0.5 GB at this limit) [1]."""


class Stand(ABC):
    """A test stand built from a scene; one instance per run.

    Class attributes: ``name`` (the scene's ``stand`` key), ``PARAMETERS`` (what a scene may
    override), ``EFFECTS`` (optional effects a scene may name; an effect not named is not built),
    ``SETTINGS`` (what a procedure may set per point), ``LOG_SCHEMA`` (channels, readings and
    counters every point's record has, with units - checked when a log is reduced).

    Constructor: ``Stand(parameters, effects, contact, drive)`` with parameter overrides
    {name: value}, effects {name: {parameter: value}} (absent = off), a ContactSpec and a
    DriveMode; it validates them (named errors, "did you mean") and builds only what is named.
    """

    name: ClassVar[str]
    PARAMETERS: ClassVar[Mapping[str, ParameterSpec]]
    EFFECTS: ClassVar[Mapping[str, EffectSpec]]
    SETTINGS: ClassVar[Mapping[str, SettingSpec]]
    LOG_SCHEMA: ClassVar[LogSchema]

    @classmethod
    @abstractmethod
    def resolve_effects(cls, effects: Mapping[str, Mapping[str, float]]) -> dict[str, dict[str, float]]:
        """The named effects with every parameter filled in (EffectSpec defaults) and range-checked
        (named errors). The scene loader calls it, so a bad value fails when the scene is read."""

    @classmethod
    def gate_sample_rate_Hz(cls, parameters: Mapping[str, float]) -> float:
        """The highest rate [Hz] at which a gate is sampled with these parameter overrides (its
        recorders and true signals); the longest gate is MAX_GATE_SAMPLES at this rate. Default:
        0 (no limit), for a stand that stores no samples."""
        return 0.0

    @abstractmethod
    def calibrate(self, seed: int) -> Mapping[str, object]:
        """Run the instruments' calibration procedures once per run (weights, levers) and keep
        the records; returns them by instrument name (they go into every point's record)."""

    @abstractmethod
    def start_point(
        self, index: int, settings: Mapping[str, float], previous: Mapping[str, float] | None, seed: int
    ) -> PointSimulation:
        """Set up operating point ``index``: the steady state of ``previous`` (rest if None),
        then a step to ``settings``; random streams from (seed, index). Pure in its arguments."""

    @abstractmethod
    def reduce_log(self, log_path, contact_law) -> object:
        """Reduce a log of this stand with eqs. (29)-(36): a DataFrame, one row per point."""
