"""The lab sheet's judge: a student's values of one point against the reduction of the same readings.

The steps of the method, in order (docs/measurement-method.md), with the values a student
enters for each:

1. the speed ratio i_k = N2 z1/(N1 z2) from the counters of the common gate;
2. the rolling point l/a, c/a from i_k and the stand's geometry, eqs. (29)-(32);
3. the coefficients nu_T, nu_v looked up from the contact law at (l/a, c/a, alpha');
4. mu_v = F_y/(F_N nu_v) and mu_T = [T2 + F_y(Delta h - c)]/(F_N D), eqs. (33), (35).

A value passes when it lies within its tolerance of the reduced value: the reduction's 95 %
half width U95, but never less than ROUNDING (relative) of the value, so a correct value
rounded to four significant digits passes. The student is sent back to the first step with a
wrong value; i_k, nu_T and nu_v are optional (a step without entries is not judged by itself).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

STEPS: tuple[tuple[str, str, tuple[str, ...]], ...] = (
    ("speed_ratio", "the speed ratio i_k = N2 z1/(N1 z2) from the counters", ("i_k",)),
    ("rolling_point", "the rolling point l/a, c/a from i_k, eqs. (29)-(32)", ("l_over_a", "c_over_a")),
    ("nu_lookup", "the nu lookups nu_T, nu_v at (l/a, c/a, alpha')", ("nu_T", "nu_v")),
    ("friction", "mu_v = F_y/(F_N nu_v), eq. (33), and mu_T from the moment balance, eq. (35)", ("mu_v", "mu_T")),
)
REQUIRED = ("l_over_a", "c_over_a", "mu_v", "mu_T")
OPTIONAL = ("i_k", "nu_T", "nu_v")
ROUNDING = 5e-4
"""Smallest relative tolerance [1]: half a unit in the fourth significant digit."""


@dataclass(frozen=True)
class Verdict:
    """One entered value: the reduced value, the tolerance, whether it passes."""

    entered: float
    reduced: float | None
    tolerance: float | None
    ok: bool


def tolerance(reduced: float, u95: float | None) -> float:
    """The band a value must fall within around ``reduced`` (same unit)."""
    return max(u95 if u95 is not None and math.isfinite(u95) else 0.0, ROUNDING * abs(reduced))


def judge(answers: Mapping[str, float], reduced: Mapping[str, float | None]) -> dict:
    """Verdicts of ``answers`` {output: value} against ``reduced`` {output, U95_output: value or None}
    and the first step with a wrong value (``sent_back_to``: (key, description) or None)."""
    verdicts = {}
    for name, value in answers.items():
        target = reduced.get(name)
        if target is None:  # the reduction could not give this output: nothing to hold it against
            verdicts[name] = Verdict(value, None, None, False)
            continue
        band = tolerance(target, reduced.get(f"U95_{name}"))
        verdicts[name] = Verdict(value, target, band, abs(value - target) <= band)
    wrong_step = next(((key, text) for key, text, names in STEPS
                       if any(n in verdicts and not verdicts[n].ok for n in names)), None)
    return {
        "values": {name: {"entered": v.entered, "reduced": v.reduced, "tolerance": v.tolerance, "ok": v.ok}
                   for name, v in verdicts.items()},
        "passed": wrong_step is None,
        "sent_back_to": None if wrong_step is None else {"step": wrong_step[0], "text": wrong_step[1]},
    }
