"""The ``[contact]`` table of a stand scene -> rig.stands.base.ContactSpec, checked against rig.contact.

Keys: ``model`` (rigid, linear, fastsim, kinematic; required), ``poisson`` (combined Poisson
ratio of the pair [1] in [0, 0.5]; required - physical input), ``n`` (cells across 2a, optional:
the model's default), ``surrogate`` (table or direct calls, default true), ``table_points``
(nodes of the surrogate table per axis l/a, c/a, log alpha'; default (41, 9, 9)),
``error_budget`` (the reduction carries the law's numerical error at each point, default false) and
``effects`` (rig.contact effect keywords, e.g. ``{ psi = 1.2 }``; each must be supported by the
model and in its range - checked by building the effect's parameter object, which costs nothing).
"""

from __future__ import annotations

from collections.abc import Mapping

from rig import validate
from rig.contact.effects import EFFECT_KEYWORDS
from rig.contact.solve import MODEL_EFFECTS, MODELS, N_RANGE
from rig.errors import ParameterError
from rig.scenes import tables as T
from rig.stands.base import ContactSpec

KEYS = ("model", "poisson", "n", "surrogate", "table_points", "error_budget", "effects")
TABLE_AXES = ("l_over_a", "c_over_a", "log_alpha")
MAX_TABLE_POINTS = 1001


def parse_effects(given: object, model: str, where: str) -> dict[str, float]:
    """Contact-effect keywords {name: value}: known, supported by ``model``, values in range."""
    if given is None:
        return {}
    if not isinstance(given, Mapping):
        raise ParameterError(where, given, "a table of contact-effect keywords, e.g. { psi = 1.2 }")
    validate.known_keys("contact effect", given, EFFECT_KEYWORDS)
    effects = {}
    for name, value in given.items():
        path = T.dotted(where, name)
        if name not in MODEL_EFFECTS[model]:
            raise ParameterError(path, value, f"not available for model {model!r}; it supports "
                                 + ", ".join(MODEL_EFFECTS[model]))
        number = T.number(path, value, None, None)
        try:
            EFFECT_KEYWORDS[name](number)  # the effect's own range check
        except ParameterError as error:
            raise ParameterError(path, value, error.valid) from None
        effects[name] = number
    return effects


def parse_contact(table: Mapping[str, object], where: str = "contact") -> ContactSpec:
    """Validate ``[contact]`` and return the ContactSpec the stand is built with."""
    T.check_keys(table, KEYS, where)
    model = validate.choice(T.dotted(where, "model"), T.required(table, "model", where, "one of " + ", ".join(MODELS)),
                            MODELS)
    poisson = T.number(T.dotted(where, "poisson"), T.required(table, "poisson", where, "a number in [0, 0.5]"),
                       0.0, 0.5)
    n = table.get("n")
    if n is not None:
        n = validate.integer(T.dotted(where, "n"), n, *N_RANGE)
    surrogate = T.flag(table, "surrogate", where, True)
    points = table.get("table_points", ContactSpec.table_points)
    if not isinstance(points, (list, tuple)) or len(points) != len(TABLE_AXES):
        raise ParameterError(T.dotted(where, "table_points"), points,
                             "three whole numbers: table nodes along " + ", ".join(TABLE_AXES))
    table_points = tuple(validate.integer(T.dotted(where, f"table_points[{k}]"), p, 2, MAX_TABLE_POINTS)
                         for k, p in enumerate(points))
    effects = parse_effects(table.get("effects"), model, T.dotted(where, "effects"))
    return ContactSpec(model=model, n=n, poisson=poisson, effects=effects, surrogate=surrogate,
                       table_points=table_points, error_budget=T.flag(table, "error_budget", where, False))
