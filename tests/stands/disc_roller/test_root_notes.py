"""The stand-B summary's lines on root notes (rig.stands.disc_roller.reduction.root_notes): each kind of
note (rig.reduction.stand_b) counted once, resolved and NaN points told apart."""

from __future__ import annotations

import math

import pandas as pd

from rig.stands.disc_roller.reduction import root_notes

TWO_RESOLVED = "two roots: mu_v = 0.55 and 1.45; mu_T (one root, 1.45) drives alpha' instead"
TWO_NAN = "three roots: mu_v = 0.555, 1.453 and 1.455"
ONE_RESOLVED = ("one root: mu_v = 0.52, but mu_M = 1.63 differs by z = 11.9: a root the reading cannot show (a "
                "turning point of F_V/F_N at mu = 1.45, 2.9 u from the reading) may hold the truth; mu_M (one root, "
                "1.40) drives alpha' instead")
ONE_NAN = ("one root: mu_v = 0.52, but mu_M = 1.63 differs by z = 11.9: a root the reading cannot show (a turning "
           "point of F_V/F_N at mu = 1.45, 2.9 u from the reading) may hold the truth")


def test_each_kind_of_root_note_is_counted_once():
    frame = pd.DataFrame({"note": ["", TWO_RESOLVED, TWO_NAN, ONE_RESOLVED, ONE_NAN, ""],
                          "mu_v": [0.3, 1.45, math.nan, 1.40, math.nan, 0.4]})
    two, one = root_notes(frame)
    assert two.startswith("2 point(s) where the driving estimate's equation has more than one root")
    assert two.endswith("1 resolved by another reading, 1 reduced to NaN (points 2)")
    assert one.startswith("2 point(s) whose only root in mu another estimate contradicts")
    assert one.endswith("1 resolved by another reading, 1 reduced to NaN (points 4)")


def test_no_root_note_no_line():
    assert root_notes(pd.DataFrame({"note": ["", ""], "mu_v": [0.3, 0.4]})) == []
