"""The small table of known quantity names a sidecar may give instead of a RESULT column.

A sidecar axis names its RESULT column with ``column = "..."``; when it gives only
``quantity = "..."`` the quantity is looked up here. Spellings are compared after removing
all whitespace and replacing the Greek letters mu, alpha, nu by their Latin names, so
``"|F_y| / (μ F_N)"`` and ``"|F_y|/(mu F_N)"`` are the same quantity. A quantity written
with bars (``|F_y| / ...``) is a magnitude: the absolute value of the column is compared.
The table is documented in docs/compare.md (project choice, not from the seed).
"""

from __future__ import annotations

from dataclasses import dataclass

from rig.errors import UnknownNameError


@dataclass(frozen=True)
class KnownQuantity:
    """A RESULT column [its own units] and whether its magnitude is what a figure shows."""

    column: str
    magnitude: bool


# (spellings, quantity): eq. numbers are those of [Koziarski] (Equations §1.7).
_TABLE: tuple[tuple[tuple[str, ...], KnownQuantity], ...] = (
    (("alpha'", "alpha"), KnownQuantity("alpha", False)),  # eq. (21)
    (("nu_T", "F_x / (mu F_N)"), KnownQuantity("nu_T", False)),  # eq. (27)
    (("|nu_T|", "|F_x| / (mu F_N)"), KnownQuantity("nu_T", True)),
    (("nu_v", "F_y / (mu F_N)"), KnownQuantity("nu_v", False)),  # eq. (28)
    (("|nu_v|", "|F_y| / (mu F_N)"), KnownQuantity("nu_v", True)),
    (("nu_0", "|moment about C| / (mu a F_N)", "|M_C| / (mu a F_N)"), KnownQuantity("nu_0", False)),  # eq. (26)
    (("b/a", "b_over_a"), KnownQuantity("b_over_a", False)),
    (("c/a", "c_over_a"), KnownQuantity("c_over_a", False)),  # eqs. (31)-(32)
    (("l/a", "l_over_a"), KnownQuantity("l_over_a", False)),  # eq. (30)
    (("mu_v",), KnownQuantity("mu_v", False)),  # eq. (33)
    (("mu_T",), KnownQuantity("mu_T", False)),  # eq. (35)
)

_GREEK = {"μ": "mu", "α": "alpha", "ν": "nu"}


def normalise(quantity: str) -> str:
    """The comparison form of a quantity name: no whitespace, Greek mu/alpha/nu spelt out."""
    text = "".join(quantity.split())
    for greek, latin in _GREEK.items():
        text = text.replace(greek, latin)
    return text


def known_spellings() -> list[str]:
    """Every spelling the table accepts (for error messages and the docs)."""
    return [spelling for spellings, _ in _TABLE for spelling in spellings]


_LOOKUP = {normalise(s): quantity for spellings, quantity in _TABLE for s in spellings}


def lookup(quantity: str, where: str) -> KnownQuantity:
    """The RESULT column of ``quantity``; raise UnknownNameError (kind names ``where``) if unknown."""
    found = _LOOKUP.get(normalise(quantity))
    if found is None:
        raise UnknownNameError(f"{where} (no column given; known quantities)", quantity, known_spellings())
    return found
