"""The lab sheet's judge: a student's values of one point against the reduction of the same readings.

The steps of the method, in order (docs/measurement-method.md), with the values a student
enters for each; stand A (stand B: STAND_B, the chain of rig.reduction.stand_b):

1. the speed ratio i_k = N2 z1/(N1 z2) from the counters of the common gate;
2. the rolling point l/a, c/a from i_k and the stand's geometry, eqs. (29)-(32);
3. the coefficients nu_T, nu_v looked up from the contact law at (l/a, c/a, alpha');
4. mu_v = F_y/(F_N nu_v) and mu_T = [T2 + F_y(Delta h - c)]/(F_N D), eqs. (33), (35).

A value passes when it lies within its tolerance of the reduced value: the reduction's 95 %
half width U95, but never less than ROUNDING (relative) of the value, so a correct value
rounded to four significant digits passes. The student is sent back to the first step with a
wrong value; i_k, nu_T and nu_v are optional (a step without entries is not judged by itself).
A wrong value that is right but for its sign is named as such (reverse running on stand B).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

Step = tuple[str, str, tuple[str, ...]]
"""(key, what the student is sent back to, the values of that step)."""


@dataclass(frozen=True)
class Sheet:
    """A stand's lab sheet: its steps in order, the values a student must enter and those they may."""

    steps: tuple[Step, ...]
    required: tuple[str, ...]
    optional: tuple[str, ...]


STAND_A = Sheet(
    steps=(
        ("speed_ratio", "the speed ratio i_k = N2 z1/(N1 z2) from the counters", ("i_k",)),
        ("rolling_point", "the rolling point l/a, c/a from i_k, eqs. (29)-(32)", ("l_over_a", "c_over_a")),
        ("nu_lookup", "the nu lookups nu_T, nu_v at (l/a, c/a, alpha')", ("nu_T", "nu_v")),
        ("friction", "mu_v = F_y/(F_N nu_v), eq. (33), and mu_T from the moment balance, eq. (35)", ("mu_v", "mu_T")),
    ),
    required=("l_over_a", "c_over_a", "mu_v", "mu_T"),
    optional=("i_k", "nu_T", "nu_v"),
)
STAND_B = Sheet(
    steps=(
        ("rolling_point", "the rolling point: l/a from the handwheel (screw 19), c/a = e sin(sigma)/a, eq. (36); "
         "in reverse running the chain's frame is mirrored (x -> -x): c/a = -e sin(sigma)/a", ("l_over_a", "c_over_a")),
        ("pivoting_moment", "the forces from the recorder, F = (V - s0)/S with each channel's calibration, and "
         "M_C = T_Mo + R_c F_T (reverse running: F_T and T_Mo change sign)", ("M_C_N_m",)),
        ("nu_lookup", "the nu lookups nu_T, nu_v, nu_0 at (l/a, c/a, alpha' = 10 mu (b/a) R_c/R_r, eq. 21)",
         ("nu_T", "nu_v", "nu_0")),
        ("friction", "mu_v = F_V/(F_N nu_v), eq. (33), mu_T = F_T/(F_N nu_T), eq. (27), mu_M = M_C/(a F_N nu_0), "
         "eq. (26)", ("mu_v", "mu_T", "mu_M")),
    ),
    required=("l_over_a", "c_over_a", "mu_v"),
    optional=("M_C_N_m", "nu_T", "nu_v", "nu_0", "mu_T", "mu_M"),
)
SHEETS = {"yoke": STAND_A, "disc_roller": STAND_B}
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


def judge(answers: Mapping[str, float], reduced: Mapping[str, float | None], sheet: Sheet = STAND_A) -> dict:
    """Verdicts of ``answers`` {output: value} against ``reduced`` {output, U95_output: value or None}
    and the first step of ``sheet`` with a wrong value (``sent_back_to``: {step, text} or None; the
    text names a wrong value whose sign alone is wrong)."""
    verdicts = {}
    for name, value in answers.items():
        target = reduced.get(name)
        if target is None:  # the reduction could not give this output: nothing to hold it against
            verdicts[name] = Verdict(value, None, None, False)
            continue
        band = tolerance(target, reduced.get(f"U95_{name}"))
        verdicts[name] = Verdict(value, target, band, abs(value - target) <= band)
    wrong_step = next(((key, text, names) for key, text, names in sheet.steps
                       if any(n in verdicts and not verdicts[n].ok for n in names)), None)
    if wrong_step is not None:
        flipped = [n for n in wrong_step[2] if n in verdicts and _sign_only(verdicts[n])]
        text = wrong_step[1] + "".join(f" (the sign of {n} is wrong)" for n in flipped)
        wrong_step = (wrong_step[0], text)
    return {
        "values": {name: {"entered": v.entered, "reduced": v.reduced, "tolerance": v.tolerance, "ok": v.ok}
                   for name, v in verdicts.items()},
        "passed": wrong_step is None,
        "sent_back_to": None if wrong_step is None else {"step": wrong_step[0], "text": wrong_step[1]},
    }


def _sign_only(verdict: Verdict) -> bool:
    """A wrong value that would pass with the other sign."""
    return (not verdict.ok and verdict.reduced is not None and verdict.reduced != 0.0
            and abs(verdict.entered + verdict.reduced) <= verdict.tolerance)
