"""docs/stand-a.md names every parameter, effect and setting of the stand (the page is the reference)."""

from __future__ import annotations

from pathlib import Path

from rig.stands.yoke import parameters as P

DOC = (Path(__file__).resolve().parents[3] / "docs" / "stand-a.md").read_text()


def test_every_parameter_effect_and_setting_is_documented():
    names = list(P.PARAMETERS) + list(P.EFFECTS) + list(P.SETTINGS)
    names += [p for spec in P.EFFECTS.values() for p in spec.parameters]
    missing = [name for name in names if f"`{name}`" not in DOC and name not in ("marks_1", "marks_2")]
    assert not missing
    assert "`marks_1`, `marks_2`" in DOC
