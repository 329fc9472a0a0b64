"""[Zhao]'s friction table as data (slides 18-19, Equations §6) and the flagged steel-PTFE contradiction."""

from __future__ import annotations

import pytest

from rig.errors import ParameterError, UnknownNameError
from rig.teaching.friction_table import (
    QUOTED_RANGES,
    STATIC_TABLE,
    Condition,
    contradictions,
    static_coefficient,
    table_row,
)

# Equations §6, "Values to preload (dry / lubricated, static)", transcribed independently.
SEED_NOTES = {
    ("aluminium", "steel"): ((0.61, 0.61), None, None),
    ("copper", "steel"): ((0.53, 0.53), None, None),
    ("brass", "steel"): ((0.51, 0.51), None, None),
    ("cast iron", "copper"): ((1.05, 1.05), None, None),
    ("cast iron", "zinc"): ((0.85, 0.85), None, None),
    ("concrete", "rubber"): ((1.0, 1.0), None, (0.30, 0.30)),
    ("concrete", "wood"): ((0.62, 0.62), None, None),
    ("copper", "glass"): ((0.68, 0.68), None, None),
    ("glass", "glass"): ((0.94, 0.94), None, None),
    ("metal", "wood"): ((0.2, 0.6), None, (0.2, 0.2)),
    ("polyethene", "steel"): ((0.2, 0.2), (0.2, 0.2), None),
    ("steel", "steel"): ((0.80, 0.80), (0.16, 0.16), None),
    ("steel", "PTFE"): ((0.04, 0.04), (0.04, 0.04), None),
    ("PTFE", "PTFE"): ((0.04, 0.04), (0.04, 0.04), None),
    ("wood", "wood"): ((0.25, 0.5), None, (0.2, 0.2)),
}


def _pair(value):
    return None if value is None else (value.low, value.high)


def test_every_row_of_the_table_matches_the_equations_page():
    table = {(r.material_1, r.material_2): (_pair(r.dry), _pair(r.lubricated), _pair(r.wet)) for r in STATIC_TABLE}
    assert table == SEED_NOTES


def test_lookup_in_either_order_with_aliases_and_conditions():
    assert static_coefficient("Teflon", "steel").high == 0.04
    assert static_coefficient("steel", "steel", Condition.LUBRICATED).high == 0.16
    assert static_coefficient("rubber", "concrete", Condition.WET).low == 0.30
    assert table_row("Wood", "metal").dry.low == 0.2


def test_slide_18_ranges_respect_kinetic_below_static_for_steel_steel():
    steel = next(q for q in QUOTED_RANGES if q.material_2 == "steel")
    assert (steel.static.low, steel.static.high, steel.kinetic.low, steel.kinetic.high) == (0.3, 0.8, 0.15, 0.6)
    assert steel.kinetic.high <= steel.static.high and steel.static.overlaps(table_row("steel", "steel").dry)


def test_only_steel_ptfe_is_flagged_with_both_reasons():
    found = contradictions()
    assert {(c.material_1, c.material_2) for c in found} == {("steel", "PTFE")}
    reasons = " | ".join(c.reason for c in found)
    assert "does not contain" in reasons and "mu_k > mu_s" in reasons
    assert all("0.3-0.6" in c.quoted and "0.04" in c.table for c in found)


def test_unknown_names_and_blank_cells_are_clear_errors():
    with pytest.raises(UnknownNameError, match="did you mean 'steel'"):
        static_coefficient("steal", "steel")
    with pytest.raises(ParameterError, match="material pair"):
        static_coefficient("glass", "steel")
    with pytest.raises(ParameterError, match="dry and clean, lubricated"):
        static_coefficient("steel", "steel", Condition.WET)
    with pytest.raises(UnknownNameError):
        static_coefficient("steel", "steel", "wet")
