"""A contact-characteristics scene: nu_T, nu_v, nu_0 versus alpha' ([Koziarski] Figs. 3-7), no stand.

Runs rig.characteristics.sweep over the listed contact models, rolling points (cases) and a
log-spaced alpha' range. All quantities are dimensionless (alpha' of eq. 21; nu of eqs. 26-28).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from rig import validate
from rig.characteristics import Case
from rig.contact.grid import SHAPES
from rig.contact.kalker import B_OVER_A_RANGE
from rig.contact.solve import MODELS, N_RANGE
from rig.errors import ParameterError
from rig.scenes import tables as T
from rig.scenes.contact import parse_effects
from rig.scenes.stand_scene import Outputs

TOP_KEYS = ("scene", "characteristics")
SCENE_KEYS = ("kind", "description")
WHERE = "characteristics"
KEYS = ("models", "poisson", "n", "alpha", "effects", "variants", "cases")
CASE_KEYS = ("shape", "b_over_a", "c_over_a", "l_over_a")
MAX_ROLLING_POINT = 1e3  # |c/a|, |l/a| [1]: far outside any contact (hard case 6), still finite


@dataclass(frozen=True)
class CharacteristicsScene:
    """A validated characteristics scene: models, cases, alpha' values [1], poisson [1], n (cells
    across 2a), contact effects (kinematic model only), plus name/description/source/text."""

    name: str
    description: str
    source: str
    text: str
    models: tuple[str, ...]
    cases: tuple[Case, ...]
    alphas: tuple[float, ...]
    poisson: float
    n: int
    effects: Mapping[str, float]
    variants: Mapping[str, Mapping[str, float]] = field(default_factory=dict)
    outputs: Outputs = Outputs(reduce=False, figures=True)


def parse_case(given: object, where: str) -> Case:
    """One ``[[characteristics.cases]]`` entry: shape, b/a, c/a, l/a (all required)."""
    if not isinstance(given, Mapping):
        raise ParameterError(where, given, "a table {shape, b_over_a, c_over_a, l_over_a}")
    T.check_keys(given, CASE_KEYS, where)
    shape = validate.choice(T.dotted(where, "shape"), T.required(given, "shape", where, "one of " + ", ".join(SHAPES)),
                            SHAPES)
    b = T.number(T.dotted(where, "b_over_a"), T.required(given, "b_over_a", where, "a number"), *B_OVER_A_RANGE)
    c = T.number(T.dotted(where, "c_over_a"), T.required(given, "c_over_a", where, "a number"),
                 -MAX_ROLLING_POINT, MAX_ROLLING_POINT)
    l = T.number(T.dotted(where, "l_over_a"), T.required(given, "l_over_a", where, "a number"),
                 -MAX_ROLLING_POINT, MAX_ROLLING_POINT)
    return Case(shape, b, c, l)


def parse_characteristics_scene(document: Mapping[str, object], *, name: str, source: str,
                                text: str) -> CharacteristicsScene:
    """Validate a parsed characteristics-scene document."""
    T.check_keys(document, TOP_KEYS, "")
    head = T.sub_table(document, "scene", "", required=True)
    T.check_keys(head, SCENE_KEYS, "scene")
    table = T.sub_table(document, WHERE, "", required=True)
    T.check_keys(table, KEYS, WHERE)
    models = T.required(table, "models", WHERE, "a list of contact models")
    if not isinstance(models, list) or not models:
        raise ParameterError(T.dotted(WHERE, "models"), models, "a non-empty list of " + ", ".join(MODELS))
    models = tuple(validate.choice(f"{WHERE}.models[{k}]", m, MODELS) for k, m in enumerate(models))
    cases = T.required(table, "cases", WHERE, "an array of tables [[characteristics.cases]]")
    if not isinstance(cases, list) or not cases:
        raise ParameterError(T.dotted(WHERE, "cases"), cases, "a non-empty array of tables [[characteristics.cases]]")
    alpha_where = T.dotted(WHERE, "alpha")
    return CharacteristicsScene(
        name=name,
        description=T.text(head, "description", "scene"),
        source=source,
        text=text,
        models=models,
        cases=tuple(parse_case(c, f"{WHERE}.cases[{k}]") for k, c in enumerate(cases)),
        alphas=T.values(alpha_where, T.required(table, "alpha", WHERE, "alpha' values"), 0.0, None),
        poisson=T.number(T.dotted(WHERE, "poisson"), T.required(table, "poisson", WHERE, "a number in [0, 0.5]"),
                         0.0, 0.5),
        n=validate.integer(T.dotted(WHERE, "n"), T.required(table, "n", WHERE, f"a whole number in {list(N_RANGE)}"),
                           *N_RANGE),
        effects=parse_effects(table.get("effects"), "kinematic", T.dotted(WHERE, "effects")),
        variants=parse_variants(table.get("variants")),
    )


def parse_variants(given: object) -> dict[str, dict[str, float]]:
    """``[characteristics.variants]`` (optional): {label: {effect: value}} - kinematic-model runs
    with other effects, e.g. ``"psi = 2" = { psi = 2.0 }``."""
    if given is None:
        return {}
    where = T.dotted(WHERE, "variants")
    if not isinstance(given, Mapping) or not given:
        raise ParameterError(where, given, "a table {label = {effect = value, ...}, ...}")
    return {str(label): parse_effects(effects, "kinematic", T.dotted(where, str(label)))
            for label, effects in given.items()}
