"""The design of an accuracy study: which settings of a stand scene are run, and against what.

Four axes, each varied on its own with everything else at the scene's setting (docs/accuracy.md):

* CONTACT - contact model (rigid, fastsim, kinematic, and the scene's own) x grid n (cells
  across 2a). Reference: the last model of MODEL_LADDER present, extrapolated to zero cell size
  from its grids N/4, N/2, N (N its largest n; the two coarser are added when missing:
  rig.accuracy.table, Richardson with the observed order); where N/4 would be below the smallest
  grid (4), that model at N itself.
* TABLE - surrogate-table resolution: the scene's node counts scaled along every axis (the
  factor 1 is the scene's own). Reference: the largest factor. Only for a scene with a table.
* DRIVE - quasi-static drive (without the effects the stand refuses without dynamics, e.g.
  stand A's brake loop; left out if the stand refuses the drive), and the dynamic drive with the
  stand's integrator tolerances multiplied by a factor (the stand parameter
  ode_tolerance_factor). Reference:
  dynamic at the smallest factor.
* GATE - gate time (the scene's times a factor); the "error" is the stated uncertainty and the
  cost the lab time, so no reference run is needed.

The procedure is shortened for the study (``shorten``): at most ``max_values`` values of each
swept setting (evenly spaced, ends kept) and one repeat per point. The study is about relative
cost, so every setting runs the same shortened procedure [our choice].
"""

from __future__ import annotations

import dataclasses
import enum
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.contact.solve import DEFAULT_N, MODEL_EFFECTS, MODELS, N_RANGE
from rig.errors import ParameterError
from rig.scenes.procedure import MAX_POINTS, Procedure
from rig.scenes.stand_scene import StandScene
from rig.stands.base import ContactSpec, DriveMode

MODEL_LADDER = ("rigid", "linear", "fastsim", "kinematic")
"""Contact models from the simplest to the most complete (docs/contact-model.md): the reference
of the CONTACT axis is the most complete one studied, at the finest grid [our choice]."""


class Axis(enum.Enum):
    """What one part of the study varies."""

    CONTACT = "contact model x grid"
    TABLE = "surrogate table"
    DRIVE = "drive / ODE tolerance"
    GATE = "gate time"


@dataclass(frozen=True)
class Setting:
    """How one study run simulates the scene.

    contact: the ContactSpec; drive: DriveMode; tolerance_factor: multiplier of the stand's
    integrator tolerances [1] (1.0 = the stand's own; always 1.0 with the quasi-static drive);
    gate_time_s: common gate [s]; dropped_effects: scene effects not built (those the stand
    refuses with the quasi-static drive, e.g. stand A's brake dynamics).
    """

    contact: ContactSpec
    drive: DriveMode
    tolerance_factor: float
    gate_time_s: float
    dropped_effects: tuple[str, ...] = ()

    def key(self) -> tuple:
        """A hashable identity (ContactSpec holds a dict of effects)."""
        return (self.contact_key(), self.drive, self.tolerance_factor, self.gate_time_s, self.dropped_effects)

    def contact_key(self) -> tuple:
        """Identity of the contact law, so of the surrogate tables the setting builds or loads."""
        c = self.contact
        return (c.model, c.n, c.poisson, tuple(sorted(c.effects.items())), c.surrogate, tuple(c.table_points))


@dataclass(frozen=True)
class Entry:
    """One row of an axis: a label for humans and the setting it runs."""

    label: str
    setting: Setting


@dataclass(frozen=True)
class AxisPlan:
    """The entries of one axis, which one is the reference (None: GATE) and which the scene's own.

    extrapolated: indices of three entries on grids N/4, N/2, N whose reduced outputs are
    extrapolated to zero cell size to give the axis's reference (CONTACT axis; None elsewhere, or
    when the finest model has no such grids); ``reference`` is then the finest of them, kept as a
    setting like any other.
    """

    axis: Axis
    entries: tuple[Entry, ...]
    reference: int | None
    scene_choice: int
    extrapolated: tuple[int, int, int] | None = None


@dataclass(frozen=True)
class StudyOptions:
    """What the study varies and how it runs.

    models: contact models of the CONTACT axis (the scene's own is added); grids: n values
    (the scene's own is added); table_factors: multipliers of the scene's table node counts;
    tolerance_factors: multipliers of the stand's integrator tolerances (dynamic drive);
    gate_factors: multipliers of the scene's gate time; max_values: values kept per swept
    setting; repeats: timed runs per setting (median CPU time).
    """

    models: tuple[str, ...] = ("rigid", "fastsim", "kinematic")
    grids: tuple[int, ...] = (8, 12, 16, 24)
    table_factors: tuple[float, ...] = (0.5, 0.75, 1.0, 1.25)
    tolerance_factors: tuple[float, ...] = (100.0, 10.0, 1.0, 0.1)
    gate_factors: tuple[float, ...] = (0.25, 0.5, 1.0, 2.0)
    max_values: int = 4
    repeats: int = 3

    def __post_init__(self) -> None:
        for model in self.models:
            validate.choice("contact model", model, MODELS)
        for n in self.grids:
            validate.integer("grid n", n, *N_RANGE)
        for name in ("table_factors", "tolerance_factors", "gate_factors"):
            values = getattr(self, name)
            if not values:
                raise ParameterError(name, values, "at least one factor > 0")
            for value in values:
                validate.number(name, value, 0.0, 1e6, lo_open=True)
        if not self.models or not self.grids:
            raise ParameterError("models and grids", (self.models, self.grids), "at least one model and one n")
        validate.integer("max_values", self.max_values, 2, MAX_POINTS)
        validate.integer("repeats", self.repeats, 1, 100)


def scaled_nodes(points: Sequence[int], factor: float) -> tuple[int, int, int]:
    """Table node counts scaled by ``factor`` [1]: k -> floor((k - 1) factor + 1/2) + 1 (halves
    round up), at least 2."""
    return tuple(max(2, math.floor((k - 1) * factor + 0.5) + 1) for k in points)


def shorten(procedure: Procedure, max_values: int) -> Procedure:
    """The study's procedure: at most ``max_values`` values per swept setting (and series), spread
    over the range with both ends kept, one repeat per point (Procedure.thinned)."""
    return procedure.thinned(validate.integer("max_values", max_values, 2, MAX_POINTS))


def _grid(contact: ContactSpec) -> int:
    return DEFAULT_N if contact.n is None else contact.n


def _contact_variant(scene: ContactSpec, model: str, n: int) -> ContactSpec:
    """The scene's contact with another model and grid; effects the model lacks are dropped."""
    effects = {k: v for k, v in scene.effects.items() if k in MODEL_EFFECTS[model]}
    same = model == scene.model and n == _grid(scene)
    return scene if same else dataclasses.replace(scene, model=model, n=n, effects=effects)


def reference_grids(finest: int) -> tuple[int, int, int] | None:
    """(N/4, N/2, N) for the finest grid N, or None when N is not a multiple of 4 or N/4 is below
    the smallest grid N_RANGE[0]."""
    if finest % 4 or finest // 4 < N_RANGE[0]:
        return None
    return finest // 4, finest // 2, finest


def _contact_axis(scene: Setting, options: StudyOptions) -> AxisPlan:
    own = scene.contact
    models = sorted(set(options.models) | {own.model}, key=MODEL_LADDER.index)
    grids = sorted(set(options.grids) | {_grid(own)})
    triple = reference_grids(grids[-1]) if models[-1] != "linear" else None
    entries = []
    for model in models:
        for n in sorted(set(grids) | (set(triple) if triple and model == models[-1] else set())):
            contact = _contact_variant(own, model, n)
            dropped = sorted(set(own.effects) - set(contact.effects))
            label = f"{model} n={n}" + (f" (without {', '.join(dropped)})" if dropped else "")
            entries.append(Entry(label, dataclasses.replace(scene, contact=contact)))
    choice = next(i for i, e in enumerate(entries) if e.setting.contact is own)
    extrapolated = None
    if triple:
        finest = [i for i, e in enumerate(entries) if e.setting.contact.model == models[-1]]
        by_n = {_grid(entries[i].setting.contact): i for i in finest}
        extrapolated = tuple(by_n[n] for n in triple)
    return AxisPlan(Axis.CONTACT, tuple(entries), len(entries) - 1, choice, extrapolated)


def _table_axis(scene: Setting, options: StudyOptions) -> AxisPlan | None:
    own = scene.contact
    if not own.surrogate:
        return None
    factors = sorted(set(options.table_factors) | {1.0})
    entries, seen = [], set()
    for factor in factors:
        points = own.table_points if factor == 1.0 else scaled_nodes(own.table_points, factor)
        if points in seen:
            continue
        seen.add(points)
        contact = own if points == tuple(own.table_points) else dataclasses.replace(own, table_points=points)
        label = "table " + "x".join(str(p) for p in points) + f" ({int(np.prod(points))} nodes)"
        entries.append(Entry(label, dataclasses.replace(scene, contact=contact)))
    choice = next(i for i, e in enumerate(entries) if e.setting.contact is own)
    return AxisPlan(Axis.TABLE, tuple(entries), len(entries) - 1, choice)


def build_stand(scene: StandScene, setting: Setting):
    """The stand of ``scene`` as ``setting`` simulates it (cheap: no table is built until a point needs it);
    raises the stand's named error for a setting it refuses."""
    effects = {k: dict(v) for k, v in scene.effects.items() if k not in setting.dropped_effects}
    return scene.stand_class(dict(scene.parameters), effects, setting.contact, setting.drive)


def _quasi_static(scene: StandScene, own: Setting) -> Entry | None:
    """The quasi-static entry: the scene's effects minus those the stand refuses without dynamics
    (dropped one by one as the stand names them); None if the stand refuses the drive itself."""
    dropped: list[str] = []
    while True:
        setting = dataclasses.replace(own, drive=DriveMode.QUASI_STATIC, tolerance_factor=1.0,
                                      dropped_effects=tuple(dropped))
        try:
            build_stand(scene, setting)
        except ParameterError as error:
            name = str(getattr(error, "name", "")).removeprefix("effects.")
            if name in scene.effects and name not in dropped:
                dropped.append(name)
                continue
            return None
        return Entry("quasi-static" + (f" (without {', '.join(dropped)})" if dropped else ""), setting)


def _drive_axis(scene: StandScene, own: Setting, options: StudyOptions) -> AxisPlan:
    quasi = _quasi_static(scene, own)
    entries = [] if quasi is None else [quasi]
    for factor in sorted(set(options.tolerance_factors) | {1.0}, reverse=True):
        label = "dynamic, stand's tolerances" if factor == 1.0 else f"dynamic, tolerances x{factor:g}"
        entries.append(Entry(label, dataclasses.replace(own, drive=DriveMode.DYNAMIC, tolerance_factor=factor)))
    choice = next(i for i, e in enumerate(entries) if e.setting.key() == own.key())
    return AxisPlan(Axis.DRIVE, tuple(entries), len(entries) - 1, choice)


def _gate_axis(scene: Setting, options: StudyOptions) -> AxisPlan:
    factors = sorted(set(options.gate_factors) | {1.0})
    entries = [Entry(f"gate {scene.gate_time_s * f:g} s",
                     scene if f == 1.0 else dataclasses.replace(scene, gate_time_s=scene.gate_time_s * f))
               for f in factors]
    return AxisPlan(Axis.GATE, tuple(entries), None, factors.index(1.0))


@dataclass(frozen=True)
class StudyDesign:
    """The scene's own setting, the shortened procedure every run uses, and the axes."""

    scene_setting: Setting
    procedure: Procedure
    axes: tuple[AxisPlan, ...]

    def settings(self) -> list[Setting]:
        """Every distinct setting of the study (the scene's own first), each once."""
        unique: dict[tuple, Setting] = {self.scene_setting.key(): self.scene_setting}
        for plan in self.axes:
            for entry in plan.entries:
                unique.setdefault(entry.setting.key(), entry.setting)
        return list(unique.values())


def study_design(scene: StandScene, options: StudyOptions) -> StudyDesign:
    """The settings the study runs for a stand scene (ParameterError for another kind of scene)."""
    if not isinstance(scene, StandScene):
        raise ParameterError("scene", getattr(scene, "name", scene),
                             "a stand scene ([scene] kind = \"stand\"): the study varies a stand's settings")
    own = Setting(scene.contact, scene.drive, 1.0, scene.procedure.gate_time_s)
    build_stand(scene, own)  # the scene itself must build (named error otherwise)
    axes = [_contact_axis(own, options), _table_axis(own, options), _drive_axis(scene, own, options),
            _gate_axis(own, options)]
    design = StudyDesign(own, shorten(scene.procedure, options.max_values), tuple(a for a in axes if a is not None))
    for setting in design.settings():  # fail before any run, with the stand's named error
        build_stand(scene, setting)
    return design
