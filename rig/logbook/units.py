"""Unit strings of the log and the identifier-safe form used in DataFrame column names.

Units are written in one consistent ASCII form (a choice of this package, documented in
``docs/log-format.md``): ``"1"`` for dimensionless, otherwise symbols made of letters, optionally
with a power ``^2``..``^9``, joined by a space (product) or ``/`` (quotient), optionally starting
with ``1/``: ``"N"``, ``"N m"``, ``"rad/s"``, ``"m/s^2"``, ``"1/rev"``, ``"count"``.

Column names are ``<name>_<safe unit>`` where the safe unit drops ``^``, writes a leading ``1/``
as ``per_`` and both separators as ``_``: ``F_y_N``, ``T2_N_m``, ``omega_rad_s``, ``a_m_s2``,
``mu_1``. The safe form is not one-to-one (``"N m"`` and ``"N/m"`` both give ``N_m``), so every
DataFrame the readers return also carries the exact units in ``DataFrame.attrs["units"]``.
"""

from __future__ import annotations

import functools
import re

from rig.errors import ParameterError
from rig.logbook.layout import NAME_PATTERN

_FACTOR = r"[A-Za-z]+(?:\^[2-9])?"
UNIT_PATTERN = re.compile(rf"1|(?:1/)?{_FACTOR}(?:[ /]{_FACTOR})*")
MAX_UNIT_LENGTH = 32
UNIT_RULE = f"at most {MAX_UNIT_LENGTH} characters, an ASCII unit such as 'N', 'N m', 'rad/s', 'm/s^2', '1/rev' or '1' (dimensionless)"
NAME_RULE = "an identifier of at most 64 ASCII letters, digits and '_', starting with a letter"


def is_unit(unit: object) -> bool:
    """True if ``unit`` is a string in the log's ASCII unit form."""
    return isinstance(unit, str) and _unit_form(unit)


@functools.lru_cache(maxsize=1024)
def _unit_form(unit: str) -> bool:
    """The unit rule for a string, remembered: a study checks the same few units ~10^2 times a point."""
    return len(unit) <= MAX_UNIT_LENGTH and UNIT_PATTERN.fullmatch(unit) is not None


def check_unit(name: str, unit: object) -> str:
    """Return ``unit`` if it is in the ASCII unit form, else raise :class:`ParameterError`."""
    if not is_unit(unit):
        raise ParameterError(name, unit, UNIT_RULE)
    return unit  # type: ignore[return-value]


def is_name(name: object) -> bool:
    """True if ``name`` may name a channel, setting, reading, counter or calibration record."""
    return isinstance(name, str) and _name_form(name)


@functools.lru_cache(maxsize=1024)
def _name_form(name: str) -> bool:
    """The name rule for a string, remembered (as _unit_form)."""
    return NAME_PATTERN.fullmatch(name) is not None


def check_name(kind: str, name: object) -> str:
    """Return ``name`` if it is an identifier (see :data:`NAME_RULE`), else raise."""
    if not is_name(name):
        raise ParameterError(kind, name, NAME_RULE)
    return name  # type: ignore[return-value]


DIMENSIONLESS = "1"


def safe_unit(unit: str) -> str:
    """Identifier-safe form of a unit: ``"N m"`` -> ``"N_m"``, ``"rad/s"`` -> ``"rad_s"``, ``"1/rev"`` -> ``"per_rev"``."""
    check_unit("unit", unit)
    if unit.startswith("1/"):
        unit = "per_" + unit[2:]
    return unit.replace("^", "").replace(" ", "_").replace("/", "_")


def column_name(name: str, unit: str) -> str:
    """DataFrame column name carrying its unit: ``column_name("T2", "N m") == "T2_N_m"``;
    dimensionless quantities (unit "1") keep their bare name: ``column_name("mu_T", "1") == "mu_T"``."""
    check_name("name", name)
    return name if unit == DIMENSIONLESS else f"{name}_{safe_unit(unit)}"
