"""The lab sheet's judge: a student's values of one point against the reduction of the same readings.

The steps of the method, in order (docs/measurement-method.md), with the values a student
enters for each; stand A (stand B: STAND_B, the chain of rig.reduction.stand_b):

1. the speed ratio i_k = N2 z1/(N1 z2) from the counters of the common gate;
2. the rolling point l/a, c/a from i_k and the stand's geometry, eqs. (29)-(32);
3. the coefficients nu_T, nu_v looked up from the contact law at (l/a, c/a, alpha');
4. mu_v = F_y/(F_N nu_v) and mu_T = [T2 + F_y(Delta h - c)]/(F_N D), eqs. (33), (35).

A value passes when it lies within its tolerance of the reduced value of the same readings. The
tolerance is stated per quantity (:class:`Tolerance`: relative and/or absolute; an exercise may
state its own, DEFAULT_RELATIVE / DEFAULT_ABSOLUTE otherwise), never the reduction's own U95, so
a short gate does not make the sheet lax; it is never less than ROUNDING (relative), so a correct
value rounded to four significant digits passes. The student is sent back to the first step with
a wrong value; i_k, nu_T and nu_v are optional (a step without entries is not judged by itself).
A wrong value is named by the kind of slip it matches (:data:`SLIPS`): its sign, units (x1000),
an inverted ratio.
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
        ("lateral_force", "the lateral force F_y from dynamometer 10: F = (s - s0)/S at its lever, eq. (33)",
         ("F_y_N",)),
        ("alpha_prime", "the track deformability alpha' = 10 mu (b/a)(v/w0)/R_x, eq. (21), at your mu",
         ("alpha_prime",)),
        ("nu_lookup", "the nu lookups nu_T, nu_v, nu_0 at (l/a, c/a, alpha')", ("nu_T", "nu_v", "nu_0")),
        ("friction", "mu_v = F_y/(F_N nu_v), eq. (33), and mu_T from the moment balance, eq. (35)", ("mu_v", "mu_T")),
    ),
    required=("l_over_a", "c_over_a", "mu_v", "mu_T"),
    optional=("i_k", "F_y_N", "alpha_prime", "nu_T", "nu_v", "nu_0"),
)
STAND_B = Sheet(
    steps=(
        ("rolling_point", "the rolling point: l/a from the handwheel (screw 19), c/a from the twist, eq. (36)",
         ("l_over_a", "c_over_a")),
        ("pivoting_moment", "the forces from the recorder, F = (V - s0)/S with each channel's calibration, and "
         "M_C = T_Mo + R_c F_T", ("M_C_N_m",)),
        ("alpha_prime", "the track deformability alpha' = 10 mu (b/a) R_c/R_r, eq. (21), at your mu", ("alpha_prime",)),
        ("nu_lookup", "the nu lookups nu_T, nu_v, nu_0 at (l/a, c/a, alpha')", ("nu_T", "nu_v", "nu_0")),
        ("friction", "mu_v = F_V/(F_N nu_v), eq. (33), mu_T = F_T/(F_N nu_T), eq. (27), mu_M = M_C/(a F_N nu_0), "
         "eq. (26)", ("mu_v", "mu_T", "mu_M")),
    ),
    required=("l_over_a", "c_over_a", "mu_v"),
    optional=("M_C_N_m", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_T", "mu_M"),
)
SHEETS = {"yoke": STAND_A, "disc_roller": STAND_B}
EQUATIONS = {
    "yoke": {
        "speed_ratio": r"i_k = \dfrac{N_2\, z_1}{N_1\, z_2}",
        "rolling_point": r"l = \dfrac{l_1 \sin\alpha_1 + i_k\, l_2}{\sin\alpha_1 + i_k},\quad "
                         r"c = \dfrac{i_k\, \Delta h}{\sin\alpha_1 + i_k}\quad\text{(29)–(32)}",
        "lateral_force": r"F_y = \dfrac{s - s_0}{S}\,\dfrac{l_\mathrm{dyn}}{R_v}\quad\text{(33)}",
        "alpha_prime": r"\alpha' = \dfrac{10\,\mu\,(b/a)\,(v/\omega_0)}{R_x},\quad "
                       r"\dfrac{v}{\omega_0} = \dfrac{r_1}{\sin\alpha_1 + i_k}\quad\text{(21)}",
        "nu_lookup": r"(\nu_T, \nu_v, \nu_0) = \nu(l/a,\ c/a,\ \alpha')\ \text{at the load's } b/a",
        "friction": r"\mu_v = \dfrac{F_y}{F_N\,\nu_v}\ \text{(33)},\quad \mu_T = "
                    r"\dfrac{T_2 + F_y(\Delta h - c)}{F_N\,D},\ D = -(l - l_2)\,\nu_T - a\,\nu_0\ \text{(35)}",
    },
    "disc_roller": {
        "rolling_point": r"c = e \sin\sigma\quad\text{(36)}",
        "pivoting_moment": r"F = \dfrac{V - s_0}{S},\quad M_C = T_{Mo} + R_c\,F_T",
        "alpha_prime": r"\alpha' = 10\,\mu\,(b/a)\,\dfrac{R_c}{R_r}\quad\text{(21)}",
        "nu_lookup": r"(\nu_T, \nu_v, \nu_0) = \nu(l/a,\ c/a,\ \alpha')\ \text{at the load's } b/a",
        "friction": r"\mu_v = \dfrac{F_V}{F_N\nu_v}\ (33),\ \mu_T = \dfrac{F_T}{F_N\nu_T}\ (27),\ "
                    r"\mu_M = \dfrac{M_C}{a F_N \nu_0}\ (26)",
    },
}
"""Each step's equations as TeX ([Koziarski] equation numbers), rendered on the page by KaTeX."""
SYMBOLS = {
    "i_k": (r"i_k", "1"), "l_over_a": (r"l/a", "1"), "c_over_a": (r"c/a", "1"), "F_y_N": (r"F_y", "N"),
    "alpha_prime": (r"\alpha'", "1"), "nu_T": (r"\nu_T", "1"), "nu_v": (r"\nu_v", "1"), "nu_0": (r"\nu_0", "1"),
    "mu_v": (r"\mu_v", "1"), "mu_T": (r"\mu_T", "1"), "mu_M": (r"\mu_M", "1"), "M_C_N_m": (r"M_C", "N m"),
}
"""Each sheet quantity's symbol (TeX) and unit."""
ROUNDING = 5e-4
"""Smallest relative tolerance [1]: half a unit in the fourth significant digit."""
DEFAULT_RELATIVE = 0.01
"""Relative tolerance of a quantity no exercise states another for [1]."""
DEFAULT_ABSOLUTE = {"c_over_a": 0.01, "l_over_a": 0.01, "nu_T": 0.002, "nu_v": 0.002, "nu_0": 0.002}
"""Absolute tolerances where the value may be near zero [1]."""


PLAUSIBLE = 3.0
"""A student's stated U95 counts only within this factor of the reduction's U95 of the same readings [1]."""


@dataclass(frozen=True)
class Tolerance:
    """A quantity's band: the largest of ``relative`` x |reduced value|, ``absolute`` (same unit)
    and ``uncertainty`` x the U95 the student states for the value (0: not used). A stated U95
    counts only when it is plausible - within a factor PLAUSIBLE of the reduction's own U95 - so
    a student cannot widen the band by claiming a large uncertainty."""

    relative: float = DEFAULT_RELATIVE
    absolute: float = 0.0
    uncertainty: float = 0.0

    def band(self, reduced: float, stated: float | None = None) -> float:
        extra = self.uncertainty * stated if self.uncertainty and stated is not None else 0.0
        return max(self.relative * abs(reduced), self.absolute, ROUNDING * abs(reduced), extra)

    def public(self) -> dict:
        return {"relative": self.relative, "absolute": self.absolute, "uncertainty": self.uncertainty}


def plausible(stated: float, u95: float | None) -> bool:
    """Is a student's stated U95 within a factor PLAUSIBLE of the reduction's ``u95``?"""
    return u95 is not None and math.isfinite(u95) and u95 > 0 and stated > 0 and \
        1.0 / PLAUSIBLE <= stated / u95 <= PLAUSIBLE


def default_tolerances(sheet: Sheet) -> dict[str, Tolerance]:
    """The tolerance of each quantity of ``sheet`` when an exercise states none."""
    return {name: Tolerance(DEFAULT_RELATIVE, DEFAULT_ABSOLUTE.get(name, 0.0))
            for name in sheet.required + sheet.optional}


SLIPS = (
    ("sign", "its sign is wrong", lambda v: -v),
    ("units", "a factor 1000 off: units (mm/m, mN/N)?", lambda v: v / 1000.0),
    ("units", "a factor 1000 off: units (mm/m, mN/N)?", lambda v: v * 1000.0),
    ("inverted", "the inverse of the right value: a ratio upside down?", lambda v: 1.0 / v if v else math.inf),
)
"""Kinds of slip a wrong value is tested for: (kind, text, what the right value would be)."""


@dataclass(frozen=True)
class Verdict:
    """One entered value: the reduced value, the tolerance, whether it passes."""

    entered: float
    reduced: float | None
    tolerance: float | None
    ok: bool


def judge(answers: Mapping[str, float], reduced: Mapping[str, float | None], sheet: Sheet = STAND_A,
          tolerances: Mapping[str, Tolerance] | None = None) -> dict:
    """Verdicts of ``answers`` {output: value} against ``reduced`` {output: value or None} within
    ``tolerances`` (default :func:`default_tolerances`), each step's verdict (``steps``: {step:
    True, False, or None when none of its values was entered}) and the first step of ``sheet``
    with a wrong value (``sent_back_to``: {step, text, slips: [{quantity, kind}]} or None; the
    text names the kind of slip a wrong value matches)."""
    tolerances = default_tolerances(sheet) if tolerances is None else tolerances
    verdicts = {}
    for name, value in answers.items():
        if name.startswith("U95_"):  # a stated uncertainty: judged with its value, below
            continue
        target = reduced.get(name)
        if target is None:  # the reduction could not give this output: nothing to hold it against
            verdicts[name] = Verdict(value, None, None, False)
            continue
        tolerance = tolerances.get(name, Tolerance())
        stated = answers.get(f"U95_{name}")
        if tolerance.uncertainty and stated is not None and not plausible(stated, reduced.get(f"U95_{name}")):
            verdicts[name] = Verdict(value, target, tolerance.band(target), False)  # an implausible claim fails
            continue
        band = tolerance.band(target, stated)
        verdicts[name] = Verdict(value, target, band, abs(value - target) <= band)
    steps = {key: (all(verdicts[n].ok for n in names if n in verdicts) if any(n in verdicts for n in names) else None)
             for key, _, names in sheet.steps}
    wrong_step = next(((key, text, names) for key, text, names in sheet.steps if steps[key] is False), None)
    sent_back = None
    if wrong_step is not None:
        slips = [{"quantity": n, "kind": kind, "text": text} for n in wrong_step[2] if n in verdicts
                 for kind, text in [_slip(verdicts[n])] if kind]
        sent_back = {"step": wrong_step[0], "slips": [{"quantity": x["quantity"], "kind": x["kind"]} for x in slips],
                     "text": wrong_step[1] + "".join(f" ({x['quantity']}: {x['text']})" for x in slips)}
    return {
        "values": {name: {"entered": v.entered, "reduced": v.reduced, "tolerance": v.tolerance, "ok": v.ok}
                   for name, v in verdicts.items()},
        "steps": steps,
        "passed": wrong_step is None,
        "sent_back_to": sent_back,
    }


def _slip(verdict: Verdict) -> tuple[str, str] | tuple[None, None]:
    """(kind, text) of the first slip in SLIPS that would make a wrong value pass, else (None, None)."""
    if verdict.ok or verdict.reduced is None or verdict.reduced == 0.0:
        return None, None
    for kind, text, undo in SLIPS:
        if abs(undo(verdict.entered) - verdict.reduced) <= verdict.tolerance:
            return kind, text
    return None, None
