"""The TOML sidecar of a digitised figure: what the figure is, its axes, and each dataset's conditions.

Layout (docs/compare.md)::

    figure = "pure spin, circular Hertz contact"     # required: names the figure
    source = "..."                                    # optional
    [conditions]                                      # optional: RESULT column = value, all datasets
    b_over_a = 1.0
    [x]                                               # required
    column = "alpha"      # or quantity = "alpha'" (looked up in rig.compare.quantities)
    units = "1"           # required; "1" = dimensionless
    scale = "log"         # optional: "linear" (default) or "log"
    [datasets.nu_v]                                   # one table per digitised dataset
    quantity = "|F_y| / (mu F_N)"
    units = "1"
    conditions = { c_over_a = 0.4 }                   # optional: added to (and overriding) [conditions]

An axis may also set ``magnitude = true`` (compare |column|); a known quantity written with bars
sets it already. Unknown keys raise UnknownNameError with the closest valid key.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path

from rig import validate
from rig.compare import quantities
from rig.errors import LogFormatError, ParameterError

TOP_KEYS = ("figure", "source", "conditions", "x", "datasets")
AXIS_KEYS = ("quantity", "column", "units", "scale", "magnitude")
DATASET_KEYS = AXIS_KEYS + ("conditions",)

ConditionValue = float | str


class AxisScale(Enum):
    """How an axis of the figure is scaled; interpolation follows it (log: in log of the value)."""

    LINEAR = "linear"
    LOG = "log"


@dataclass(frozen=True)
class Axis:
    """One axis: the RESULT column it shows, its units ("1" = dimensionless), scale and label.

    magnitude: compare the absolute value of the column (figures often plot |F_y|).
    """

    column: str
    units: str
    scale: AxisScale
    quantity: str | None
    magnitude: bool

    @property
    def label(self) -> str:
        """Axis label for plots: the quantity (or column) and its units."""
        name = self.quantity or (f"|{self.column}|" if self.magnitude else self.column)
        return name if self.units == "1" else f"{name} [{self.units}]"


@dataclass(frozen=True)
class DatasetSpec:
    """A digitised dataset: its name in the export, its y axis and the conditions that select it.

    conditions: RESULT column -> value, the global [conditions] merged with the dataset's own
    (the dataset's own win).
    """

    name: str
    y: Axis
    conditions: Mapping[str, ConditionValue] = field(default_factory=dict)


@dataclass(frozen=True)
class Sidecar:
    """The whole sidecar: figure name, optional source, x axis, datasets in file order."""

    figure: str
    source: str | None
    x: Axis
    datasets: tuple[DatasetSpec, ...]

    def dataset(self, name: str) -> DatasetSpec:
        """The dataset called ``name`` (UnknownNameError if the sidecar has none)."""
        names = [d.name for d in self.datasets]
        validate.choice("dataset", name, names)
        return self.datasets[names.index(name)]


def load_sidecar(path: str | Path) -> Sidecar:
    """Read and validate a sidecar TOML file.

    Parameters
    ----------
    path : str or pathlib.Path
        The sidecar file (UTF-8, optional BOM).

    Returns
    -------
    Sidecar
        The figure's axes (columns, units, scales) and datasets.

    Raises
    ------
    LogFormatError
        TOML syntax.
    ParameterError
        Content (unknown keys with a suggestion, bad units or scales).
    """
    path = Path(path)
    if not path.is_file():
        raise ParameterError("sidecar", str(path), "an existing TOML file (default: DIGITISED with suffix .toml)")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise LogFormatError(f"{path}: not a valid TOML sidecar: {error}") from None
    return parse_sidecar(data, source=str(path))


def parse_sidecar(data: Mapping[str, object], source: str = "sidecar") -> Sidecar:
    """Validate a decoded sidecar (a mapping as tomllib returns it).

    Parameters
    ----------
    data : Mapping[str, object]
        The sidecar's tables.
    source : str, optional
        Its name in error messages (default ``"sidecar"``).

    Returns
    -------
    Sidecar
        The figure's axes and datasets.
    """
    validate.known_keys(f"top-level key of {source}", data, TOP_KEYS)
    figure = data.get("figure")
    if not isinstance(figure, str) or not figure.strip():
        raise ParameterError("figure", figure, "a non-empty string naming the figure", hint=f"in {source}")
    source_text = data.get("source")
    if source_text is not None and not isinstance(source_text, str):
        raise ParameterError("source", source_text, "a string", hint=f"in {source}")
    common = _conditions(data.get("conditions", {}), "conditions", source)
    x = _axis(_table(data.get("x"), "x", source), "x", AXIS_KEYS, source)
    datasets_table = _table(data.get("datasets"), "datasets", source)
    if not datasets_table:
        raise ParameterError("datasets", {}, "at least one [datasets.NAME] table", hint=f"in {source}")
    datasets = []
    for name, entry in datasets_table.items():
        where = f"datasets.{name}"
        table = _table(entry, where, source)
        y = _axis(table, where, DATASET_KEYS, source)
        own = _conditions(table.get("conditions", {}), f"{where}.conditions", source)
        datasets.append(DatasetSpec(name=name, y=y, conditions={**common, **own}))
    return Sidecar(figure=figure.strip(), source=source_text, x=x, datasets=tuple(datasets))


def _table(value: object, where: str, source: str) -> dict:
    if not isinstance(value, dict):
        raise ParameterError(where, value, f"a TOML table [{where}]", hint=f"in {source}")
    return value


def _axis(table: Mapping[str, object], where: str, allowed: tuple[str, ...], source: str) -> Axis:
    validate.known_keys(f"key of [{where}] in {source}", table, allowed)
    quantity = _optional_string(table, "quantity", where, source)
    column = _optional_string(table, "column", where, source)
    magnitude = table.get("magnitude")
    if magnitude is not None and not isinstance(magnitude, bool):
        raise ParameterError(f"{where}.magnitude", magnitude, "true or false", hint=f"in {source}")
    if column is None:
        if quantity is None:
            raise ParameterError(
                where, dict(table), "a table with `column` (a RESULT column) or a known `quantity`", hint=f"in {source}"
            )
        known = quantities.lookup(quantity, f"{where}.quantity in {source}")
        column = known.column
        magnitude = known.magnitude if magnitude is None else magnitude
    units = _optional_string(table, "units", where, source)
    if units is None:
        raise ParameterError(f"{where}.units", None, 'a unit string ("1" for dimensionless)', hint=f"in {source}")
    scale_name = table.get("scale", AxisScale.LINEAR.value)
    scale = AxisScale(validate.choice(f"{where}.scale", scale_name, [s.value for s in AxisScale]))
    return Axis(column=column, units=units, scale=scale, quantity=quantity, magnitude=bool(magnitude))


def _optional_string(table: Mapping[str, object], key: str, where: str, source: str) -> str | None:
    value = table.get(key)
    if value is None:
        return None
    if not isinstance(value, str) or not value.strip():
        raise ParameterError(f"{where}.{key}", value, "a non-empty string", hint=f"in {source}")
    return value.strip()


def _conditions(value: object, where: str, source: str) -> dict[str, ConditionValue]:
    if not isinstance(value, dict):
        raise ParameterError(where, value, "a table of RESULT column = value", hint=f"in {source}")
    result: dict[str, ConditionValue] = {}
    for key, item in value.items():
        if isinstance(item, str):
            result[key] = item
        elif isinstance(item, (int, float)) and not isinstance(item, bool):
            result[key] = validate.number(f"{where}.{key}", item)
        else:
            raise ParameterError(f"{where}.{key}", item, "a number or a string", hint=f"in {source}")
    return result
