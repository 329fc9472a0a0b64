"""Stand A chain: counts + calibrated readings -> l/a, c/a, alpha', mu_v, mu_T with uncertainties.

Per operating point (Equations §2, "Implementation of the chain"):
    i_k = N2 z1/(N1 z2), w1 = 2 pi N1/(z1 T)                         counters over a common gate
    (c, l) from i_k, eqs. (29)-(31); l/a, c/a                          rig.wheel_kinematics
    v/w0 = r1/(sin alpha1 + i_k); alpha' = 10 mu (b/a)(v/w0)/R_x       eq. (21), line contact
    F_y = [(s - z - s0)/S + e_w] (102 mm/R_v)                          dynamometer 10, eq. (33);
        z: the zero's drift since the calibration (value 0, u = zero_drift_u)
    (nu_T, nu_v, nu_0) = coefficients(l/a, c/a, alpha')               contact model (any)
    D = -(l - l2) nu_T - a nu_0                                        lever of eq. (35)
    mu_v = F_y/(F_N nu_v), mu_T = [T2 + F_y(Delta h - c)]/(F_N D)      eqs. (33), (35)
iterated over mu in alpha' (rig.reduction.iteration) with the driver chosen once per point
(rig.reduction.drivers: mu_v, else mu_T, each only if its reading is significant).
Input uncertainties: counts from the counters' quantisation (sensors.COUNT_QUANTISATION_STD,
triangular), the rest as the readings state them (rig.reduction.readings.Measured, with the
balance's scale-step part). Guards (hard cases 2, 8): fewer than min_counts counts or a
vanishing spin -> all outputs NaN with the reason; |nu_v| < nu_min, |D|/a < denominator_min ->
that mu NaN; a denominator within ``significance`` u of zero -> that mu NaN (rig.reduction.result);
the contact model's own reason when it has no coefficients. Configuration errors (marks, gate
time, b/a, geometry) raise ParameterError instead.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass

from rig import validate
from rig.reduction import equations as eq
from rig.reduction.coefficients import Coefficients, call_model, corrected
from rig.reduction.geometry import StandAGeometry, with_inputs
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import ForceCalibration, Measured, reading_inputs, reading_value
from rig.reduction.result import Evaluation, Guard, ReducedPoint, Start, evaluate_fixed_point, reduce_stand_point
from rig.reduction.uncertainty import Covariance, Distribution, InputQuantity, InputSet
from rig.wheel_kinematics import SpinTooSmallError
from sensors import COUNT_QUANTISATION_STD

OUTPUTS = (
    "i_k", "omega_1_rad_s", "spin_rad_s", "l_m", "c_m", "l_over_a", "c_over_a", "F_y_N",
    "alpha_prime", "nu_T", "nu_v", "nu_0", "D_m", "mu_v", "mu_T",
)
DRIVERS = ("mu_v", "mu_T")  # which estimate feeds alpha', in order of preference (Equations §2)
DRIVEN = ("alpha_prime", "nu_T", "nu_v", "nu_0", "D_m", "mu_v", "mu_T")  # computed from the driving mu
KINEMATIC = tuple(name for name in OUTPUTS if name != "F_y_N")  # the outputs the counts' kinematics feed
GUARDS = (Guard("mu_v", "nu_v"), Guard("mu_T", "D_m"))
COUNT_U = float(COUNT_QUANTISATION_STD)
"""u of a gated count [count]: 1/sqrt(6), the difference of two uniform mark phases at the gate
edges (triangular on (-1, 1); sensors.counters) - the instrument's own model, by import."""
ZERO_DRIFT = "dyn_zero_drift_V"
"""Input: the dynamometer zero's walk since the calibration [V] (value 0, u = zero_drift_u)."""
GEOMETRY_INPUTS = ("l1", "l2", "alpha_1", "delta_h", "a", "r1", "radius_x", "dynamometer_lever", "yoke_lever")


@dataclass(frozen=True)
class StandAReadings:
    """One operating point of stand A.

    counts_k: counter totals [1] of z_k marks (marks_k) in one common gate; gate_time [s];
    normal_force F_N [N]; dynamometer_signal [V] with its calibration; brake_moment T2 [N m]
    from the tangent balance (positive when it resists wheel 2; its u_step is the scale step's
    bias); b_over_a [1] of the contact at this load (the same value the caller binds into the
    coefficients); zero_drift_u [V]: standard uncertainty of the dynamometer's zero at this
    point, the drift since the calibration took it (0: none stated, e.g. a log that does not
    record the drift).
    """

    counts_1: int
    counts_2: int
    marks_1: int
    marks_2: int
    gate_time: Measured
    normal_force: Measured
    dynamometer_signal: Measured
    dynamometer: ForceCalibration
    brake_moment: Measured
    b_over_a: float
    zero_drift_u: float = 0.0

    def __post_init__(self) -> None:
        validate.integer("counts_1", self.counts_1, 0)
        validate.integer("counts_2", self.counts_2, 0)
        validate.integer("marks_1", self.marks_1, 1)
        validate.integer("marks_2", self.marks_2, 1)
        validate.number("gate_time", self.gate_time.value, 0.0, lo_open=True)
        validate.number("normal_force", self.normal_force.value, 0.0, lo_open=True)
        validate.number("b_over_a", self.b_over_a, 0.0, lo_open=True)
        validate.number("zero_drift_u", self.zero_drift_u, 0.0)


def input_set(
    readings: StandAReadings, geometry: StandAGeometry, geometry_u: Mapping[str, float] | None = None
) -> InputSet:
    """The inputs with their uncertainties and sources (instruments) for the budget.

    geometry_u: optional standard uncertainties of geometry constants, keyed by field name
    (one of GEOMETRY_INPUTS) in the field's unit; constants without one are exact.
    """
    geometry_u = dict(geometry_u or {})
    validate.known_keys("geometry constant", geometry_u, GEOMETRY_INPUTS)
    r, cal = readings, readings.dynamometer
    tri = Distribution.TRIANGULAR
    quantities = [
        InputQuantity("N1", float(r.counts_1), COUNT_U, "1", "counter 1 (wheel 1)", tri),
        InputQuantity("N2", float(r.counts_2), COUNT_U, "1", "counter 2 (wheel 2)", tri),
        *reading_inputs("T_gate", "s", "s", r.gate_time, "timer"),
        *reading_inputs("F_N", "N", "N", r.normal_force, "pressing force"),
        *reading_inputs("dyn_signal", "V", "V", r.dynamometer_signal, "dynamometer signal"),
        InputQuantity("dyn_sensitivity_V_per_N", cal.sensitivity, cal.u_sensitivity, "V/N", "dynamometer calibration"),
        InputQuantity("dyn_offset_V", cal.offset, cal.u_offset, "V", "dynamometer calibration"),
        InputQuantity("dyn_weights_N", 0.0, cal.u_weights, "N", "calibration weights"),
        *([InputQuantity(ZERO_DRIFT, 0.0, r.zero_drift_u, "V", "dynamometer zero drift")]
          if r.zero_drift_u > 0 else []),
        *reading_inputs("T2", "N_m", "N m", r.brake_moment, "tangent balance"),
    ]
    units = {f.name: f.metadata["unit"] for f in dataclasses.fields(geometry)}
    for name, u in geometry_u.items():
        quantities.append(InputQuantity(f"geom_{name}", getattr(geometry, name), u, units[name], "geometry"))
    covariances = ()
    if cal.covariance != 0.0:
        covariances = (Covariance("dyn_sensitivity_V_per_N", "dyn_offset_V", cal.covariance),)
    return InputSet(tuple(quantities), covariances)


@functools.lru_cache(maxsize=256)
def _kinematics(n1: float, n2: float, marks_1: int, marks_2: int, alpha_1: float, l1: float, l2: float,
                delta_h: float) -> tuple[float, float, float]:
    """(i_k [1], c [m], l [m]) from the counts, eqs. (29)-(31), remembered: of a point's ~40 evaluations
    (Jacobian, driver check) only those that perturb a count or the geometry ask a new question."""
    i_k = eq.ratio_from_counts(n1, n2, marks_1, marks_2)
    c, l = eq.stand_a_rolling_point(i_k, alpha_1, l1, l2, delta_h)
    return i_k, c, l


def _lateral_force(values: Mapping[str, float], g: StandAGeometry) -> float:
    """F_y [N] from the dynamometer signal and its calibration (eq. 33 lever)."""
    signal = reading_value(values, "dyn_signal", "V") - values.get(ZERO_DRIFT, 0.0)
    force_dyn = eq.force_from_signal(signal, values["dyn_sensitivity_V_per_N"], values["dyn_offset_V"]) + values[
        "dyn_weights_N"]
    return eq.lateral_force_from_dynamometer(force_dyn, g.dynamometer_lever, g.yoke_lever)


def _moment_numerator(values: Mapping[str, float], readings: StandAReadings, g: StandAGeometry) -> float:
    """T2 + F_y (Delta h - c) [N m], the numerator of eq. (35) (NaN without a rolling point)."""
    n1, n2 = values["N1"], values["N2"]
    if min(n1, n2) <= 0.0:
        return math.nan
    try:
        _, c, _ = _kinematics(n1, n2, readings.marks_1, readings.marks_2, g.alpha_1, g.l1, g.l2, g.delta_h)
    except SpinTooSmallError:
        return math.nan
    return reading_value(values, "T2", "N_m") + _lateral_force(values, g) * (g.delta_h - c)


def evaluate(
    values: Mapping[str, float],
    start: Start,
    *,
    readings: StandAReadings,
    geometry: StandAGeometry,
    coefficients: Coefficients,
    settings: ReductionSettings,
) -> Evaluation:
    """The chain at one set of input values (names as in :func:`input_set`)."""
    g = with_inputs(geometry, values)
    out = dict.fromkeys(OUTPUTS, math.nan)
    out["F_y_N"] = f_y = _lateral_force(values, g)
    n1, n2 = values["N1"], values["N2"]
    if min(n1, n2) < settings.min_counts:
        counts = f"counts N1 = {n1:g}, N2 = {n2:g} below min_counts = {settings.min_counts}"
        if n1 < settings.min_counts:  # wheel 1 is driven at its set speed: too few marks passed in the gate
            why = f"{counts}: the gate of {readings.gate_time.value:g} s is too short for wheel 1's marks"
        else:
            why = f"{counts}: wheel 2 stalled (hard case 2)"
        return Evaluation(out, dict.fromkeys(KINEMATIC, why), math.nan, 0)
    omega_1 = eq.angular_speed_from_counts(n1, readings.marks_1, reading_value(values, "T_gate", "s"))
    try:
        i_k, c, l = _kinematics(n1, n2, readings.marks_1, readings.marks_2, g.alpha_1, g.l1, g.l2, g.delta_h)
    except SpinTooSmallError as error:
        return Evaluation(out, dict.fromkeys(KINEMATIC, str(error)), math.nan, 0)
    sin_a1 = math.sin(g.alpha_1)
    f_n, t2 = reading_value(values, "F_N", "N"), reading_value(values, "T2", "N_m")
    alpha_per_mu = eq.alpha_prime_line_contact(1.0, readings.b_over_a, g.r1 / (sin_a1 + i_k), g.radius_x)
    out.update(
        i_k=i_k, omega_1_rad_s=omega_1, spin_rad_s=omega_1 * (sin_a1 + i_k), l_m=l, c_m=c,
        l_over_a=l / g.a, c_over_a=c / g.a,
    )

    def state_at(mu: float) -> tuple[dict[str, float], dict[str, str]]:
        alpha = alpha_per_mu * mu
        state = dict.fromkeys(DRIVEN, math.nan)
        state["alpha_prime"] = alpha
        nu, why = call_model(coefficients, l / g.a, c / g.a, alpha)
        if nu is None:
            return state, dict.fromkeys(DRIVEN[1:], why)
        nu_t, nu_v, nu_0 = corrected(nu, values)
        denominator = eq.mu_t_denominator(nu_t, nu_0, l, g.l2, g.a)
        state.update(nu_T=nu_t, nu_v=nu_v, nu_0=nu_0, D_m=denominator)
        reasons = {}
        if abs(nu_v) >= settings.nu_min:
            state["mu_v"] = eq.mu_v(f_y, f_n, nu_v)
        else:
            reasons["mu_v"] = f"|nu_v| = {abs(nu_v):.3g} < nu_min = {settings.nu_min:g} (c ~ 0, hard case 8)"
        if abs(denominator) >= settings.denominator_min * g.a:
            state["mu_T"] = eq.mu_t(t2, f_n, f_y, nu_t, nu_0, l, c, g.l2, g.delta_h, g.a)
        else:
            reasons["mu_T"] = (
                f"|D|/a = {abs(denominator) / g.a:.3g} < denominator_min = {settings.denominator_min:g} "
                "in eq. (35) (hard case 8)"
            )
        return state, reasons

    return evaluate_fixed_point(state_at, start, settings, out, DRIVEN)


def reduce(
    readings: StandAReadings,
    coefficients: Coefficients,
    geometry: StandAGeometry | None = None,
    settings: ReductionSettings | None = None,
    geometry_u: Mapping[str, float] | None = None,
) -> ReducedPoint:
    """Reduce one stand-A operating point (values, standard uncertainties, U95, budget, reasons).

    coefficients(l/a, c/a, alpha') -> (nu_T, nu_v, nu_0) with b/a, shape and model bound by
    the caller (e.g. functools.partial over rig.contact.solve.solve); it may raise
    rig.reduction.coefficients.OutsideModelDomain. geometry defaults to the Equations page's stand A
    (rig.reduction.geometry); settings to ReductionSettings().
    """
    geometry = StandAGeometry() if geometry is None else geometry
    settings = ReductionSettings() if settings is None else settings
    inputs = input_set(readings, geometry, geometry_u)
    numerators = {
        "mu_v": ("F_y", lambda v: _lateral_force(v, with_inputs(geometry, v))),
        "mu_T": ("T2 + F_y (Delta h - c)", lambda v: _moment_numerator(v, readings, with_inputs(geometry, v))),
    }
    return reduce_stand_point(evaluate, inputs, numerators, GUARDS, DRIVEN, settings, readings=readings,
                              geometry=geometry, coefficients=coefficients)
