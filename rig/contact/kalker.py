"""Kalker's linear-theory creepage coefficients C11, C22, C23 (and C33), eq. (4) of [Koziarski].

Source of C11, C22, C23 for the ellipse: Kalker (1990), Table E.3, as shipped in
``data/kalker_linear_coefficients.csv`` (header there). Kalker's a lies along the rolling
direction, so **Koziarski's b/a is Kalker's a/b** - the only place in friction-rig where the two
namings meet. Interpolation (described by CONTACT, re-implemented): linear in log(b/a) between
table rows, then quadratic Lagrange interpolation of 1/C through nu = 0, 0.25, 0.5.

C33 (ellipse) and all coefficients of the finite line contact are not in Kalker's table; they
come from ``data/derived_linear_coefficients.csv``, computed with this package's own full-stick
solver and extrapolated to zero cell size (``python -m rig.contact.linear_tables`` regenerates
it; docs/contact-model.md describes how and how it was checked).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np

from rig import validate

B_OVER_A_RANGE = (0.1, 10.0)
_NU_NODES = np.array([0.0, 0.25, 0.5])


@dataclass(frozen=True)
class CreepCoefficients:
    """Dimensionless creepage coefficients of linear theory (Kalker's definitions)."""

    C11: float
    C22: float
    C23: float
    C33: float


@lru_cache(maxsize=None)
def _table(name: str) -> dict[tuple[str, float], np.ndarray]:
    """{(shape, b/a): array (3 nu, k coefficients)} from a data CSV (comment lines start with #)."""
    text = resources.files("rig.contact.data").joinpath(name).read_text()
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    header = lines[0].split(",")
    rows = [dict(zip(header, ln.split(","))) for ln in lines[1:]]
    coeffs = [h for h in header if h.startswith("C")]
    out: dict[tuple[str, float], list] = {}
    for row in rows:
        shape = row.get("shape", "ellipse")
        b_over_a = float(row["a_over_b"]) if "a_over_b" in row else float(row["b_over_a"])
        out.setdefault((shape, round(b_over_a, 5)), []).append([float(row["nu"])] + [float(row[c]) for c in coeffs])
    result = {}
    for key, values in out.items():
        arr = np.array(sorted(values))
        if not np.allclose(arr[:, 0], _NU_NODES):
            raise RuntimeError(f"{name}: row {key} does not have nu = 0, 0.25, 0.5")
        result[key] = arr[:, 1:]
    return result


def _interpolate(table: dict, shape: str, b_over_a: float, poisson: float) -> np.ndarray:
    keys = sorted(k[1] for k in table if k[0] == shape)
    g = np.log(np.array(keys))
    x = np.log(b_over_a)
    i = int(np.clip(np.searchsorted(g, x) - 1, 0, len(g) - 2))
    w = (x - g[i]) / (g[i + 1] - g[i])
    inverse = (1 - w) / table[(shape, keys[i])] + w / table[(shape, keys[i + 1])]  # (3 nu, k) of 1/C
    lagrange = np.array(
        [np.prod([(poisson - _NU_NODES[m]) / (_NU_NODES[k] - _NU_NODES[m]) for m in range(3) if m != k]) for k in range(3)]
    )
    return 1.0 / (lagrange @ inverse)


def kalker_coefficients(b_over_a: float, poisson: float) -> CreepCoefficients:
    """Kalker's C11, C22, C23 of a Hertz ellipse (Table E.3); C33 is NaN (not in the table)."""
    b = validate.number("b_over_a", b_over_a, *B_OVER_A_RANGE)
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    c11, c22, c23 = _interpolate(_table("kalker_linear_coefficients.csv"), "ellipse", b, nu)
    return CreepCoefficients(c11, c22, c23, np.nan)


def creep_coefficients(shape: str, b_over_a: float, poisson: float) -> CreepCoefficients:
    """C11, C22, C23, C33 for a Hertz ellipse or finite line contact of the given b/a and nu."""
    b = validate.number("b_over_a", b_over_a, *B_OVER_A_RANGE)
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    derived = _interpolate(_table("derived_linear_coefficients.csv"), shape, b, nu)
    if shape == "ellipse":
        kalker = kalker_coefficients(b, nu)
        return CreepCoefficients(kalker.C11, kalker.C22, kalker.C23, derived[3])
    return CreepCoefficients(*derived)
