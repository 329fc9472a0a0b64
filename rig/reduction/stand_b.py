"""Stand B chain: settings + calibrated readings -> l/a, c/a, alpha', mu_v, mu_T, M_C with uncertainties.

Per operating point (seed notes 3.2):
    l from the roller's position on its shaft (screw 19), c = e sin(sigma)     eq. (36)
    v/w0 = R_c (the disc spins under the rolling point); alpha' = 10 mu (b/a) R_c/R_r  eq. (21)
    M_C = T_Mo + R_c F_T (momentometer 8 + dynamometer 5)                 small difference of large terms
    (nu_T, nu_v, nu_0) = coefficients(l/a, c/a, alpha')
    mu_v = F_V/(F_N nu_v) (33), mu_T = F_T/(F_N nu_T) (27), mu_M = |M_C|/(a F_N nu_0) (26)
iterated over mu in alpha' (mu_v first, then mu_T, then mu_M: the first one reportable).
Forces are the calibrated dynamometer outputs [N] in the contact convention of rig.contact
(F_T = F_x, F_V = F_y on the disc, spin w0 > 0); a sensors adapter maps the instruments to it.
Guards: |nu_v| (|nu_T|, nu_0) < nu_min -> that mu is NaN with the reason (hard case 8).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from rig import validate
from rig.errors import ParameterError
from rig.reduction import equations as eq
from rig.reduction.geometry import StandBGeometry
from rig.reduction.iteration import ReductionSettings, solve_mu
from rig.reduction.readings import Measured
from rig.reduction.result import Evaluation, ReducedPoint, reduce_point
from rig.reduction.uncertainty import InputQuantity, InputSet

Coefficients = Callable[[float, float, float], tuple[float, float, float]]

OUTPUTS = (
    "l_m", "c_m", "l_over_a", "c_over_a", "M_C_N_m", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T", "mu_M",
)
GEOMETRY_INPUTS = ("radius_c", "roller_radius", "pivot_distance", "a")
MU_ORDER = ("mu_v", "mu_T", "mu_M")  # which estimate feeds alpha'


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
        InputQuantity("l_setting_m", r.l_setting.value, r.l_setting.u, "m", "roller position scale"),
        InputQuantity("sigma_rad", r.twist.value, r.twist.u, "rad", "twist scale"),
        InputQuantity("F_N_N", r.normal_force.value, r.normal_force.u, "N", "dead weights"),
        InputQuantity("F_T_N", r.peripheral_force.value, r.peripheral_force.u, "N", "dynamometer F_T"),
        InputQuantity("F_V_N", r.lateral_force.value, r.lateral_force.u, "N", "dynamometer F_V"),
        InputQuantity("T_Mo_N_m", r.momentometer_torque.value, r.momentometer_torque.u, "N m", "momentometer"),
    ]
    units = {f.name: f.metadata["unit"] for f in dataclasses.fields(geometry)}
    for name, u in geometry_u.items():
        quantities.append(InputQuantity(f"geom_{name}", getattr(geometry, name), u, units[name], "geometry"))
    return InputSet(tuple(quantities))


def evaluate(
    values: Mapping[str, float],
    mu_start: float,
    *,
    readings: StandBReadings,
    geometry: StandBGeometry,
    coefficients: Coefficients,
    settings: ReductionSettings,
) -> Evaluation:
    """The chain at one set of input values (names as in :func:`input_set`)."""
    g = dataclasses.replace(geometry, **{k[5:]: v for k, v in values.items() if k.startswith("geom_")})
    out = dict.fromkeys(OUTPUTS, math.nan)
    l = values["l_setting_m"]
    c = eq.stand_b_offset(g.pivot_distance, values["sigma_rad"])
    f_n, f_t, f_v = values["F_N_N"], values["F_T_N"], values["F_V_N"]
    moment_c = eq.pivoting_moment_stand_b(values["T_Mo_N_m"], f_t, g.radius_c)
    alpha_per_mu = eq.alpha_prime_line_contact(1.0, readings.b_over_a, g.spin_radius, g.radius_x)
    out.update(l_m=l, c_m=c, l_over_a=l / g.a, c_over_a=c / g.a, M_C_N_m=moment_c)
    guards = (
        ("mu_v", "nu_v", lambda nu: eq.mu_from_force(f_v, f_n, nu)),
        ("mu_T", "nu_T", lambda nu: eq.mu_from_force(f_t, f_n, nu)),
        ("mu_M", "nu_0", lambda nu: eq.mu_from_pivoting_moment(moment_c, f_n, g.a, nu)),
    )

    def estimate(mu: float) -> tuple[float, dict[str, float], str]:
        alpha = alpha_per_mu * mu
        nu_t, nu_v, nu_0 = coefficients(l / g.a, c / g.a, alpha)
        state = dict(alpha_prime=alpha, nu_T=nu_t, nu_v=nu_v, nu_0=nu_0)
        reasons = {}
        for name, nu_name, formula in guards:
            nu = state[nu_name]
            if abs(nu) >= settings.nu_min:
                state[name] = formula(nu)
            else:
                state[name] = math.nan
                reasons[name] = f"|{nu_name}| = {abs(nu):.3g} < nu_min = {settings.nu_min:g} (hard case 8)"
        state["reasons"] = reasons
        for name in MU_ORDER:
            if math.isfinite(state[name]) and state[name] > 0.0:
                return state[name], state, ""
        return math.nan, state, "; ".join(reasons.values()) or "no positive friction estimate"

    fixed = solve_mu(estimate, dataclasses.replace(settings, mu_start=mu_start))
    reasons = dict(fixed.state.pop("reasons")) if fixed.state else {}
    if fixed.reason:
        for name in ("alpha_prime", "nu_T", "nu_v", "nu_0", *MU_ORDER):
            reasons.setdefault(name, fixed.reason)
    else:
        out.update(fixed.state)
    return Evaluation(out, reasons, fixed.mu, fixed.iterations)


def reduce(
    readings: StandBReadings,
    coefficients: Coefficients,
    geometry: StandBGeometry | None = None,
    settings: ReductionSettings | None = None,
    geometry_u: Mapping[str, float] | None = None,
) -> ReducedPoint:
    """Reduce one stand-B operating point (see rig.reduction.stand_a.reduce for the arguments)."""
    if not callable(coefficients):
        raise ParameterError(
            "coefficients", coefficients, "a callable (l_over_a, c_over_a, alpha) -> (nu_T, nu_v, nu_0)"
        )
    geometry = StandBGeometry() if geometry is None else geometry
    settings = ReductionSettings() if settings is None else settings
    inputs = input_set(readings, geometry, geometry_u)

    def chain(values: Mapping[str, float], mu_start: float) -> Evaluation:
        return evaluate(
            values, mu_start, readings=readings, geometry=geometry, coefficients=coefficients, settings=settings
        )

    return reduce_point(chain, inputs, settings.mu_start, settings.relative_step)
