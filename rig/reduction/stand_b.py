"""Stand B chain: settings + calibrated readings -> l/a, c/a, alpha', mu_v, mu_T, M_C with uncertainties.

Per operating point (Equations §3.2):
    l from the roller's position on its shaft (screw 19), c = e sin(sigma)     eq. (36)
    v/w0 = R_c (the disc spins under the rolling point); alpha' = 10 mu (b/a) R_c/R_r  eq. (21)
    M_C = T_Mo + R_c F_T (momentometer 8 + dynamometer 5)                 small difference of large terms
    (nu_T, nu_v, nu_0) = coefficients(l/a, c/a, alpha')
    mu_v = F_V/(F_N nu_v) (33), mu_T = F_T/(F_N nu_T) (27), mu_M = |M_C|/(a F_N nu_0) (26)
iterated over mu in alpha' with the driver chosen once per point at the nominal readings
(rig.reduction.drivers: mu_v, then mu_T, then mu_M - the first whose reading F_V, F_T, M_C is
significant and which gives a fixed point) and kept while the Jacobian is evaluated: at c = 0
F_V is noise, and a perturbed twist sigma must not let it drive alpha' (hard case 8).
Forces are the calibrated dynamometer outputs [N] in the contact convention of rig.contact
(F_T = F_x, F_V = F_y on the disc, spin w0 > 0); rig.stands.disc_roller.reduction maps the
instruments to it. Guards: |nu| < nu_min, or a nu within ``significance`` u of zero, -> that mu
is NaN with the reason (hard case 8).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass

from rig import validate
from rig.reduction import equations as eq
from rig.reduction.coefficients import Coefficients, call_model, corrected
from rig.reduction.geometry import StandBGeometry, with_inputs
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import Measured, reading_inputs, reading_value
from rig.reduction.result import Evaluation, Guard, ReducedPoint, Start, evaluate_fixed_point, reduce_stand_point
from rig.reduction.uncertainty import InputQuantity, InputSet

OUTPUTS = (
    "l_m", "c_m", "l_over_a", "c_over_a", "M_C_N_m", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T", "mu_M",
)
GEOMETRY_INPUTS = ("radius_c", "roller_radius", "pivot_distance", "a")
MU_ORDER = ("mu_v", "mu_T", "mu_M")  # which estimate feeds alpha', in order of preference
DRIVEN = ("alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T", "mu_M")
GUARDS = (Guard("mu_v", "nu_v"), Guard("mu_T", "nu_T"), Guard("mu_M", "nu_0"))
COEFFICIENT_OF = {"mu_v": "nu_v", "mu_T": "nu_T", "mu_M": "nu_0"}


@dataclass(frozen=True)
class StandBReadings:
    """One operating point of stand B.

    l_setting [m]: rolling-point offset along the contact line set by the screw; twist sigma
    [rad] of body 14 (eq. 36); normal_force F_N [N] (dead weights); peripheral_force F_T [N] and
    lateral_force F_V [N] (dynamometers 5); momentometer_torque T_Mo [N m] (momentometer 8);
    b_over_a [1] at this load (the value bound into the coefficients).
    """

    l_setting: Measured
    twist: Measured
    normal_force: Measured
    peripheral_force: Measured
    lateral_force: Measured
    momentometer_torque: Measured
    b_over_a: float

    def __post_init__(self) -> None:
        validate.number("normal_force", self.normal_force.value, 0.0, lo_open=True)
        validate.number("twist", self.twist.value, -math.pi / 2, math.pi / 2, lo_open=True, hi_open=True)
        validate.number("b_over_a", self.b_over_a, 0.0, lo_open=True)


def input_set(
    readings: StandBReadings, geometry: StandBGeometry, geometry_u: Mapping[str, float] | None = None
) -> InputSet:
    """Inputs with uncertainties and sources; geometry_u as in rig.reduction.stand_a.input_set."""
    geometry_u = dict(geometry_u or {})
    validate.known_keys("geometry constant", geometry_u, GEOMETRY_INPUTS)
    r = readings
    quantities = [
        *reading_inputs("l_setting", "m", "m", r.l_setting, "roller position scale"),
        *reading_inputs("sigma", "rad", "rad", r.twist, "twist scale"),
        *reading_inputs("F_N", "N", "N", r.normal_force, "dead weights"),
        *reading_inputs("F_T", "N", "N", r.peripheral_force, "dynamometer F_T"),
        *reading_inputs("F_V", "N", "N", r.lateral_force, "dynamometer F_V"),
        *reading_inputs("T_Mo", "N_m", "N m", r.momentometer_torque, "momentometer"),
    ]
    units = {f.name: f.metadata["unit"] for f in dataclasses.fields(geometry)}
    for name, u in geometry_u.items():
        quantities.append(InputQuantity(f"geom_{name}", getattr(geometry, name), u, units[name], "geometry"))
    return InputSet(tuple(quantities))


def _pivoting_moment(values: Mapping[str, float], g: StandBGeometry) -> float:
    """M_C = T_Mo + R_c F_T [N m] (Equations §3.2)."""
    return eq.pivoting_moment_stand_b(reading_value(values, "T_Mo", "N_m"), reading_value(values, "F_T", "N"),
                                      g.radius_c)


def evaluate(
    values: Mapping[str, float],
    start: Start,
    *,
    readings: StandBReadings,
    geometry: StandBGeometry,
    coefficients: Coefficients,
    settings: ReductionSettings,
) -> Evaluation:
    """The chain at one set of input values (names as in :func:`input_set`)."""
    g = with_inputs(geometry, values)
    out = dict.fromkeys(OUTPUTS, math.nan)
    l = reading_value(values, "l_setting", "m")
    c = eq.stand_b_offset(g.pivot_distance, reading_value(values, "sigma", "rad"))
    f_n = reading_value(values, "F_N", "N")
    f_t, f_v = reading_value(values, "F_T", "N"), reading_value(values, "F_V", "N")
    moment_c = _pivoting_moment(values, g)
    alpha_per_mu = eq.alpha_prime_line_contact(1.0, readings.b_over_a, g.spin_radius, g.radius_x)
    out.update(l_m=l, c_m=c, l_over_a=l / g.a, c_over_a=c / g.a, M_C_N_m=moment_c)
    formulas = {
        "mu_v": lambda nu: eq.mu_from_force(f_v, f_n, nu),
        "mu_T": lambda nu: eq.mu_from_force(f_t, f_n, nu),
        "mu_M": lambda nu: eq.mu_from_pivoting_moment(moment_c, f_n, g.a, nu),
    }

    def state_at(mu: float) -> tuple[dict[str, float], dict[str, str]]:
        alpha = alpha_per_mu * mu
        state = dict.fromkeys(DRIVEN, math.nan)
        state["alpha_prime"] = alpha
        nu, why = call_model(coefficients, l / g.a, c / g.a, alpha)
        if nu is None:
            return state, dict.fromkeys(DRIVEN[1:], why)
        nu = corrected(nu, values)
        state.update(nu_T=nu[0], nu_v=nu[1], nu_0=nu[2])
        reasons = {}
        for name, formula in formulas.items():
            coefficient = COEFFICIENT_OF[name]
            if abs(state[coefficient]) >= settings.nu_min:
                state[name] = formula(state[coefficient])
            else:
                reasons[name] = (f"|{coefficient}| = {abs(state[coefficient]):.3g} < nu_min = {settings.nu_min:g} "
                                 "(hard case 8)")
        return state, reasons

    return evaluate_fixed_point(state_at, start, settings, out, DRIVEN)


def reduce(
    readings: StandBReadings,
    coefficients: Coefficients,
    geometry: StandBGeometry | None = None,
    settings: ReductionSettings | None = None,
    geometry_u: Mapping[str, float] | None = None,
) -> ReducedPoint:
    """Reduce one stand-B operating point (see rig.reduction.stand_a.reduce for the arguments)."""
    geometry = StandBGeometry() if geometry is None else geometry
    settings = ReductionSettings() if settings is None else settings
    inputs = input_set(readings, geometry, geometry_u)
    numerators = {
        "mu_v": ("F_V", lambda v: reading_value(v, "F_V", "N")),
        "mu_T": ("F_T", lambda v: reading_value(v, "F_T", "N")),
        "mu_M": ("M_C", lambda v: _pivoting_moment(v, with_inputs(geometry, v))),
    }
    return reduce_stand_point(evaluate, inputs, numerators, GUARDS, DRIVEN, settings, readings=readings,
                              geometry=geometry, coefficients=coefficients)
