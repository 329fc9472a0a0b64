"""A stand scene: which stand, its parameter overrides, effects, contact, procedure, seed, outputs.

Validated against the named stand's class attributes (rig.stands.base.Stand): PARAMETERS
(ranges and units), EFFECTS (names and their parameters), SETTINGS (what the procedure may
set). Nothing is built here; :meth:`StandScene.build_stand` builds the stand with exactly the
effects the scene names (an effect not named is absent from the mapping: not built).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from rig import validate
from rig.errors import ParameterError
from rig.logbook.content import MAX_SEED
from rig.scenes import tables as T
from rig.scenes.contact import parse_contact
from rig.scenes.procedure import Procedure, parse_procedure
from rig.stands.base import MAX_GATE_SAMPLES, ContactSpec, DriveMode, Stand

# The campaign figures a scene may name in [outputs] paper_figure (rig.campaigns draws them; the
# scene format only knows their names, so scenes never import the campaigns).
PAPER_FIGURE_NAMES = ("fig10", "fig11", "fig14", "fig15")

TOP_KEYS = ("scene", "parameters", "contact", "effects", "procedure", "outputs")
SCENE_KEYS = ("kind", "description", "stand", "seed", "drive")
OUTPUT_KEYS = ("reduce", "figures", "paper_figure")


@dataclass(frozen=True)
class Outputs:
    """Which outputs a run writes besides log.h5 and summary.txt: the reduction (reduced.csv and
    /reduced in the log), the figures (PNG), and a figure laid out like one of the paper's
    (``paper_figure``: one of PAPER_FIGURE_NAMES, drawn by rig.campaigns, or None)."""

    reduce: bool = True
    figures: bool = True
    paper_figure: str | None = None


@dataclass(frozen=True)
class StandScene:
    """A validated stand scene.

    name: the scene's name (file stem); description: one line; source: where it was read;
    text: the scene file's text, verbatim (stored in the log); stand: the scene's stand key;
    stand_class: the Stand subclass; seed: run seed (0 .. 2**63 - 1); drive: DriveMode;
    parameters: {name: value in the parameter's unit} (overrides only); effects: {effect:
    {parameter: value}} for the named effects only, every parameter present (defaults of the
    stand's EffectSpec filled in); contact: ContactSpec; procedure; outputs.
    """

    name: str
    description: str
    source: str
    text: str
    stand: str
    stand_class: type[Stand]
    seed: int
    drive: DriveMode
    parameters: Mapping[str, float]
    effects: Mapping[str, Mapping[str, float]]
    contact: ContactSpec
    procedure: Procedure
    outputs: Outputs

    def build_stand(self) -> Stand:
        """A new stand built from this scene (only the named effects are passed, so only they are built)."""
        return self.stand_class(
            dict(self.parameters), {name: dict(values) for name, values in self.effects.items()}, self.contact,
            self.drive,
        )


def _keep_int(given: object, checked: float) -> float | int:
    """A whole-number TOML value stays an int (counts such as marks per disc), else the checked float."""
    return given if isinstance(given, int) and not isinstance(given, bool) else checked


def parse_parameters(table: Mapping[str, object], specs: Mapping[str, object]) -> dict[str, float]:
    """``[parameters]``: overrides of the stand's PARAMETERS, each inside its [lo, hi] range."""
    T.check_keys(table, specs, "parameters")
    return {
        name: _keep_int(value, T.number(T.dotted("parameters", name), value, specs[name].lo, specs[name].hi,
                                        specs[name].unit))
        for name, value in table.items()
    }


def parse_effects(table: Mapping[str, object], stand_class: type[Stand]) -> dict[str, dict[str, float]]:
    """``[effects.<name>]``: the effects to build, each with its parameters (unnamed ones: defaults),
    checked against the stand's ranges (Stand.resolve_effects) when the scene is read."""
    specs = stand_class.EFFECTS
    effects = {}
    validate.known_keys("effect", table, specs)
    for name, given in table.items():
        where = T.dotted("effects", name)
        if not isinstance(given, Mapping):
            raise ParameterError(where, given, "a table of the effect's parameters (empty: all defaults)")
        spec = specs[name]
        T.check_keys(given, spec.parameters, where)
        effects[name] = {}
        for parameter, (default, unit) in spec.parameters.items():
            value = given.get(parameter, default)
            effects[name][parameter] = _keep_int(value, T.number(T.dotted(where, parameter), value, None, None, unit))
    stand_class.resolve_effects(effects)
    return effects


def parse_outputs(table: Mapping[str, object] | None) -> Outputs:
    """``[outputs]`` (optional): ``reduce`` and ``figures`` flags, both default true, and
    ``paper_figure`` (a campaign figure name, default none)."""
    table = table or {}
    T.check_keys(table, OUTPUT_KEYS, "outputs")
    paper = table.get("paper_figure")
    if paper is not None:
        validate.choice("outputs.paper_figure", paper, PAPER_FIGURE_NAMES)
    return Outputs(reduce=T.flag(table, "reduce", "outputs", True), figures=T.flag(table, "figures", "outputs", True),
                   paper_figure=paper)


def parse_stand_scene(document: Mapping[str, object], *, name: str, source: str, text: str,
                      stand_class_of) -> StandScene:
    """Validate a parsed stand-scene document; ``stand_class_of(key)`` resolves the stand key."""
    T.check_keys(document, TOP_KEYS, "")
    head = T.sub_table(document, "scene", "", required=True)
    T.check_keys(head, SCENE_KEYS, "scene")
    stand = T.required(head, "stand", "scene", "a stand key such as 'yoke'")
    stand_class = stand_class_of(stand)
    seed = validate.integer("scene.seed", T.required(head, "seed", "scene", f"a whole number in [0, {MAX_SEED}]"),
                            0, MAX_SEED)
    drive = T.member(DriveMode, T.required(head, "drive", "scene", "one of " + ", ".join(m.value for m in DriveMode)),
                     "scene.drive")
    parameters = parse_parameters(T.sub_table(document, "parameters", "", required=False) or {},
                                  stand_class.PARAMETERS)
    rate_Hz = stand_class.gate_sample_rate_Hz(parameters)
    procedure = parse_procedure(T.sub_table(document, "procedure", "", required=True), stand_class.SETTINGS,
                                **gate_limit(rate_Hz))
    return StandScene(
        name=name,
        description=T.text(head, "description", "scene"),
        source=source,
        text=text,
        stand=stand,
        stand_class=stand_class,
        seed=seed,
        drive=drive,
        parameters=parameters,
        effects=parse_effects(T.sub_table(document, "effects", "", required=False) or {}, stand_class),
        contact=parse_contact(T.sub_table(document, "contact", "", required=True)),
        procedure=procedure,
        outputs=parse_outputs(T.sub_table(document, "outputs", "", required=False)),
    )


def gate_limit(rate_Hz: float) -> dict[str, object]:
    """The longest gate [s] the recorder holds at ``rate_Hz`` (at most MAX_GATE_SAMPLES samples per
    channel) and why, as parse_procedure's keywords (none at a rate of 0)."""
    if not rate_Hz > 0.0:
        return {}
    return {"max_gate_time_s": MAX_GATE_SAMPLES / rate_Hz,
            "gate_limit": f"at most {MAX_GATE_SAMPLES} samples per channel at {rate_Hz:g} Hz, what the simulated "
                          "recorder holds"}
