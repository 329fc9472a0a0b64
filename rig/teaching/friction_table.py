"""[Zhao]'s friction coefficients as data, with their source and the flagged contradiction.

Source: [Zhao] (R.-y. Zhao, "Mutual actions in machinery elements", lecture notes 2014),
slide 19 "Approximate coefficients of friction" (static friction; columns "Dry and clean" and
"Lubricated"; some entries marked "wet") and slide 18 (ranges of mu_s and mu_k for two pairs);
Equations §6. The OCR lists the table cell by cell; our reading follows the Equations page:
"0.30 (wet)", printed after the last row, belongs to concrete-rubber [reconstructed].

The two slides disagree on steel-PTFE: slide 18 gives mu_s = 0.3-0.6 and mu_k = 0.1-0.2, the
table 0.04 (dry and lubricated). `contradictions()` finds this from the data (a quoted range
that misses the table, or a kinetic value above the static one); we do not decide which slide
is right (handbooks list PTFE on steel near 0.04-0.1, i.e. the table's side).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from rig import validate
from rig.errors import ParameterError, UnknownNameError

SOURCE_TABLE = "[Zhao] slide 19 'Approximate coefficients of friction' (static friction)"
SOURCE_RANGES = "[Zhao] slide 18 'coefficient of static friction and kinetic friction'"


class Condition(Enum):
    """Surface condition of a table entry."""

    DRY = "dry and clean"
    LUBRICATED = "lubricated"
    WET = "wet"


@dataclass(frozen=True)
class CoefficientRange:
    """A friction coefficient [1] given as a value (low = high) or a range low-high."""

    low: float
    high: float

    def __post_init__(self) -> None:
        validate.number("low", self.low, 0.0)
        validate.number("high", self.high, self.low)

    def overlaps(self, other: CoefficientRange) -> bool:
        """True when the two ranges share at least one value."""
        return self.low <= other.high and other.low <= self.high

    def __str__(self) -> str:
        return f"{self.low:g}" if self.low == self.high else f"{self.low:g}-{self.high:g}"


def _r(low: float, high: float | None = None) -> CoefficientRange:
    return CoefficientRange(low, low if high is None else high)


@dataclass(frozen=True)
class TableRow:
    """One row of slide 19: the pair and its static coefficients [1] per condition (None: blank)."""

    material_1: str
    material_2: str
    dry: CoefficientRange
    lubricated: CoefficientRange | None = None
    wet: CoefficientRange | None = None

    def coefficient(self, condition: Condition) -> CoefficientRange | None:
        """The static coefficient for ``condition`` (None where the table is blank)."""
        return {Condition.DRY: self.dry, Condition.LUBRICATED: self.lubricated, Condition.WET: self.wet}[condition]


STATIC_TABLE: tuple[TableRow, ...] = (
    TableRow("aluminium", "steel", _r(0.61)),
    TableRow("copper", "steel", _r(0.53)),
    TableRow("brass", "steel", _r(0.51)),
    TableRow("cast iron", "copper", _r(1.05)),
    TableRow("cast iron", "zinc", _r(0.85)),
    TableRow("concrete", "rubber", _r(1.0), wet=_r(0.30)),
    TableRow("concrete", "wood", _r(0.62)),
    TableRow("copper", "glass", _r(0.68)),
    TableRow("glass", "glass", _r(0.94)),
    TableRow("metal", "wood", _r(0.2, 0.6), wet=_r(0.2)),
    TableRow("polyethene", "steel", _r(0.2), lubricated=_r(0.2)),
    TableRow("steel", "steel", _r(0.80), lubricated=_r(0.16)),
    TableRow("steel", "PTFE", _r(0.04), lubricated=_r(0.04)),
    TableRow("PTFE", "PTFE", _r(0.04), lubricated=_r(0.04)),
    TableRow("wood", "wood", _r(0.25, 0.5), wet=_r(0.2)),
)


@dataclass(frozen=True)
class QuotedRange:
    """Slide 18: ranges of mu_s and mu_k [1] quoted for a pair (dry)."""

    material_1: str
    material_2: str
    static: CoefficientRange
    kinetic: CoefficientRange


QUOTED_RANGES: tuple[QuotedRange, ...] = (
    QuotedRange("steel", "steel", _r(0.3, 0.8), _r(0.15, 0.6)),
    QuotedRange("steel", "PTFE", _r(0.3, 0.6), _r(0.1, 0.2)),
)

ALIASES = {"teflon": "PTFE", "ptfe": "PTFE", "polyethylene": "polyethene", "aluminum": "aluminium"}
MATERIALS = tuple(sorted({m for row in STATIC_TABLE for m in (row.material_1, row.material_2)}))


def material(name: object) -> str:
    """The table's spelling of a material name (case-insensitive, with aliases such as "Teflon")."""
    if isinstance(name, str):
        key = name.strip().lower()
        key = ALIASES.get(key, key)
        for known in MATERIALS:
            if known.lower() == key.lower():
                return known
    raise UnknownNameError("material", name, MATERIALS)


def _same_pair(a1: str, a2: str, b1: str, b2: str) -> bool:
    return sorted((a1, a2)) == sorted((b1, b2))


def table_row(material_1: str, material_2: str) -> TableRow:
    """The slide-19 row of a pair, in either order; unknown names raise UnknownNameError."""
    m1, m2 = material(material_1), material(material_2)
    for row in STATIC_TABLE:
        if _same_pair(row.material_1, row.material_2, m1, m2):
            return row
    pairs = ", ".join(f"{r.material_1}-{r.material_2}" for r in STATIC_TABLE)
    raise ParameterError("material pair", f"{m1}-{m2}", f"a pair of the table: {pairs}")


def static_coefficient(material_1: str, material_2: str, condition: Condition = Condition.DRY) -> CoefficientRange:
    """Static friction coefficient mu_s [1] of a pair under ``condition`` (slide 19)."""
    if not isinstance(condition, Condition):
        raise UnknownNameError("condition", condition, [c.name for c in Condition])
    row = table_row(material_1, material_2)
    value = row.coefficient(condition)
    if value is None:
        given = [c.value for c in Condition if row.coefficient(c) is not None]
        raise ParameterError("condition", condition.value, f"one of those the table gives for {row.material_1}-"
                             f"{row.material_2}: {', '.join(given)}")
    return value


@dataclass(frozen=True)
class Contradiction:
    """Two statements of [Zhao] about one pair that cannot both hold."""

    material_1: str
    material_2: str
    quoted: str
    table: str
    reason: str


def contradictions() -> tuple[Contradiction, ...]:
    """Check slide 18's ranges against slide 19's table and against mu_k <= mu_s (slide 10).

    Flags a pair when the quoted mu_s range does not overlap the table's dry value, and when the
    quoted mu_k lies wholly above the table's dry mu_s. [Zhao] gives one such pair: steel-PTFE.
    """
    found = []
    for quoted in QUOTED_RANGES:
        row = table_row(quoted.material_1, quoted.material_2)
        text = f"{SOURCE_RANGES}: mu_s = {quoted.static}, mu_k = {quoted.kinetic}"
        table = f"{SOURCE_TABLE}: mu_s = {row.dry} (dry)"
        if not quoted.static.overlaps(row.dry):
            found.append(Contradiction(row.material_1, row.material_2, text, table,
                                       "the quoted static range does not contain the table's value"))
        if quoted.kinetic.low > row.dry.high:
            found.append(Contradiction(row.material_1, row.material_2, text, table,
                                       "the quoted kinetic coefficient exceeds the table's static one (mu_k > mu_s)"))
    return tuple(found)
