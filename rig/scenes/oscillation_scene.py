"""An oscillation scene ([Oscillating]): frictional work and slip paths of an oscillating contact
versus the stroke ratio e = x/2b, with the transient grid model (rig.oscillation).

``[oscillation] contact`` names the source: "ball_raceway" ([Oscillating]'s FAG 7208 bearing; keys
ring, force_N) or "disc_roller" (stand B's roller under its swinging drive; key normal_force_N).
"""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass

from rig import validate
from rig.bearing.ball_raceway import Ring
from rig.bearing.fag7208 import FAG_7208
from rig.contact.solve import N_RANGE
from rig.errors import ParameterError
from rig.oscillation import OscillatingContact
from rig.scenes import tables as T

TOP_KEYS = ("scene", "oscillation")
SCENE_KEYS = ("kind", "description")
WHERE = "oscillation"
COMMON_KEYS = ("contact", "mu", "n", "stroke_ratio", "map_stroke_ratio")
MAX_STROKE_RATIO = 10.0


class OscillationSource(enum.Enum):
    """Where the oscillating contact comes from."""

    BALL_RACEWAY = "ball_raceway"
    DISC_ROLLER = "disc_roller"


SOURCE_KEYS = {OscillationSource.BALL_RACEWAY: ("ring", "force_N"), OscillationSource.DISC_ROLLER: ("normal_force_N",)}


@dataclass(frozen=True)
class OscillationScene:
    """A validated oscillation scene: one contact per friction coefficient, the stroke ratios,
    the grid (n cells across 2a) and the stroke ratio of the work-density map."""

    name: str
    description: str
    source: str
    text: str
    contacts: tuple[OscillatingContact, ...]
    stroke_ratios: tuple[float, ...]
    n: int
    map_stroke_ratio: float


def _contact(source: OscillationSource, table: Mapping[str, object], mu: float) -> OscillatingContact:
    if source is OscillationSource.BALL_RACEWAY:
        ring = T.member(Ring, T.required(table, "ring", WHERE, "inner or outer"), "oscillation.ring")
        force = T.number("oscillation.force_N", T.required(table, "force_N", WHERE, "a load [N]"), 0.0, 1e6, "N",
                         lo_open=True)
        return OscillatingContact.ball_raceway(FAG_7208, ring, force, mu)
    load = T.number("oscillation.normal_force_N", T.required(table, "normal_force_N", WHERE, "a load [N]"),
                    0.0, 1e4, "N", lo_open=True)
    return OscillatingContact.disc_roller(load, mu)


def parse_oscillation_scene(document: Mapping[str, object], *, name: str, source: str, text: str) -> OscillationScene:
    """Validate a parsed oscillation-scene document."""
    T.check_keys(document, TOP_KEYS, "")
    head = T.sub_table(document, "scene", "", required=True)
    T.check_keys(head, SCENE_KEYS, "scene")
    table = T.sub_table(document, WHERE, "", required=True)
    kind = T.member(OscillationSource, T.required(table, "contact", WHERE, "ball_raceway or disc_roller"),
                    "oscillation.contact")
    T.check_keys(table, COMMON_KEYS + SOURCE_KEYS[kind], WHERE)
    given = T.required(table, "mu", WHERE, "friction coefficient(s)")
    mus = T.values("oscillation.mu", given if isinstance(given, (list, dict)) else [given], 0.0, 2.0)
    if min(mus) <= 0.0:
        raise ParameterError("oscillation.mu", list(mus), "values in (0, 2]")
    ratios = T.values("oscillation.stroke_ratio", T.required(table, "stroke_ratio", WHERE, "stroke ratios e"),
                      0.0, MAX_STROKE_RATIO)
    return OscillationScene(
        name=name,
        description=T.text(head, "description", "scene"),
        source=source,
        text=text,
        contacts=tuple(_contact(kind, table, mu) for mu in mus),
        stroke_ratios=ratios,
        n=validate.integer("oscillation.n", T.required(table, "n", WHERE, f"a whole number in {list(N_RANGE)}"),
                           *N_RANGE),
        map_stroke_ratio=T.number("oscillation.map_stroke_ratio",
                                  T.required(table, "map_stroke_ratio", WHERE, "the e of the W map"),
                                  0.0, MAX_STROKE_RATIO, lo_open=True),
    )
