"""Stand B: every parameter, optional effect and per-point setting, with unit, range and source.

The ONE place for stand B's numbers. Geometry shared with the reduction is taken from
rig.reduction.geometry.StandBGeometry (R_c, R_r, e = 70.2 mm, a) so that the simulator and
rig.reduction.stand_b agree by construction; the rest follows Equations §3.2 and 4.2. Sources
start with [text] (stated in [Koziarski]), [computed] (the Equations page's arithmetic) or [assumed]
(plausible, not in the text; the reason is given).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields

from rig import validate
from rig.contact.effects.pressure_friction import friction_at_peak_pressure
from rig.errors import ParameterError
from rig.reduction.geometry import StandBGeometry
from rig.stands.base import EffectSpec, ParameterSpec, SettingSpec
from rig.stands.disc_roller import paper_alpha
from sensors.momentometer import stand_b_momentometer

_GEOMETRY = StandBGeometry()
_GEOMETRY_SOURCE = {f.name: f"[{f.metadata['tag']}] {f.metadata['source']}" for f in fields(StandBGeometry)}
GRAVITY = 9.80665  # standard gravity [m/s^2]

ROLLER_SPEEDS_RPM = (24.0, 48.0, 72.0)
"""The three roller speeds of the continuous drive [rpm] (text, [Koziarski] section 3.2; Equations §3.2)."""

PARAMETERS: Mapping[str, ParameterSpec] = {
    "radius_c_m": ParameterSpec(_GEOMETRY.radius_c, "m", 0.05, 0.3, _GEOMETRY_SOURCE["radius_c"]),
    "roller_radius_m": ParameterSpec(_GEOMETRY.roller_radius, "m", 0.01, 0.2, _GEOMETRY_SOURCE["roller_radius"]),
    "pivot_distance_m": ParameterSpec(_GEOMETRY.pivot_distance, "m", 0.01, 0.3, _GEOMETRY_SOURCE["pivot_distance"]),
    "half_length_m": ParameterSpec(_GEOMETRY.a, "m", 1e-3, 0.02, _GEOMETRY_SOURCE["a"]),
    "contact_modulus_Pa": ParameterSpec(
        22.4e6, "Pa", 1e6, 1e9,
        "[computed] Equations §3.2: apparent E* of the rubber lining from b/a = 0.5/0.75/1/2 at 9/21/36/144 N",
    ),
    "mu": ParameterSpec(0.8, "1", 0.05, 2.0, "[assumed] true friction coefficient rubber/PMMA (Equations §3.2 uses 0.8); "
                        "with the contact effect pressure_exponent k: mu at friction_reference_pressure_Pa"),
    "friction_reference_pressure_Pa": ParameterSpec(
        1e6, "Pa", 1e3, 1e9,
        "[assumed] p_ref of a pressure-dependent mu = mu (p/p_ref)^-k (contact effect pressure_exponent; unused "
        "without it): 1 MPa, within the peak Hertz pressures 0.36-1.43 MPa of the 9-144 N dead weights",
    ),
    "disc_inertia_kg_m2": ParameterSpec(0.07, "kg m^2", 1e-3, 1.0, "[assumed] Equations §4.2: PMMA disc 400 x 20 mm + hub"),
    "roller_inertia_kg_m2": ParameterSpec(3e-3, "kg m^2", 1e-4, 0.1, "[assumed] Equations §4.2: roller hub + lining"),
    "motor_inertia_kg_m2": ParameterSpec(
        1.5e-3, "kg m^2", 1e-4, 0.05, "[assumed] Equations §4.2: 0.37 kW induction motor rotor (at the motor shaft)"
    ),
    "worm_ratio": ParameterSpec(20.0, "1", 5.0, 80.0, "[assumed] Equations §4.2: 1440 rpm / 20 = 72 rpm"),
    "worm_efficiency": ParameterSpec(
        0.45, "1", 0.2, 0.95,
        "[assumed] a self-locking worm (assumed: the seed names only 'the worm gear 22') needs a forward "
        "efficiency below 0.5; Equations §4.2 says 0.6-0.75",
    ),
    "motor_rated_torque_N_m": ParameterSpec(2.45, "N m", 0.1, 50.0, "[computed] 370 W at 1440 rpm (Equations §4.2 motor)"),
    "motor_rated_slip": ParameterSpec(0.04, "1", 0.005, 0.2, "[assumed] 1440 of 1500 rpm synchronous"),
    "spin_regularisation_rad_s": ParameterSpec(
        0.01, "rad/s", 1e-5, 0.5,
        "[assumed] numerical: disc speeds below this count as 'zero' (regularised Coulomb, hard case 7)",
    ),
    "rolling_point_limit": ParameterSpec(
        8.0, "1", 2.0, 50.0,
        "[assumed] numerical: |l|/a beyond this is clipped in transients (forces saturated there, hard case 6)",
    ),
    "recorder_rate_Hz": ParameterSpec(500.0, "Hz", 50.0, 5000.0, "[assumed] MC 201A recorder rate (sensors default)"),
    "u_l_setting_m": ParameterSpec(5e-5, "m", 0.0, 1e-3, "[assumed] reading of the roller position scale (screw 19)"),
    "u_twist_rad": ParameterSpec(1e-3, "rad", 0.0, 0.02, "[assumed] reading of the twist scale (screw 15), 0.06 deg"),
    "u_normal_force_N": ParameterSpec(
        0.098 / math.sqrt(3.0), "N", 0.0, 5.0, "[assumed] dead weights to +-10 gf like stand A's weights, rectangular"
    ),
    "dynamometer_weight_piece_N": ParameterSpec(
        2.0 * GRAVITY, "N", 0.1, 100.0, "[assumed] five 2 kg pieces for dynamometers 5 (98 N against F_T <= 115 N)"
    ),
    "momentometer_weight_piece_N": ParameterSpec(
        0.8 * GRAVITY, "N", 0.1, 100.0, "[assumed] five 0.8 kg pieces for momentometer 8 (19.6 N m at the arm)"
    ),
    "momentometer_arm_m": ParameterSpec(0.5, "m", 0.05, 2.0, "[assumed] calibration arm of momentometer 8"),
    "point_period_s": ParameterSpec(
        60.0, "s", 1.0, 3600.0, "[assumed] run time per operating point: the clock of the slow instrument drift"
    ),
    "settle_tolerance": ParameterSpec(
        1e-3, "1", 1e-6, 0.1, "[assumed] numerical: relative distance to the steady state that counts as settled"
    ),
    "ode_tolerance_factor": ParameterSpec(
        1.0, "1", 1e-3, 1e3, "[assumed] numerical: factor on the drive-train integrator's relative tolerance (1e-7: "
        "rig.stands.disc_roller.integration); rig accuracy studies it"
    ),
}

EFFECTS: Mapping[str, EffectSpec] = {
    "loop_compliance": EffectSpec(
        "torsion of momentometer 8 as the gear-loop state (off: rigid loop, the quasi-static contact)",
        {
            "stiffness_N_m_per_rad": (stand_b_momentometer().torsional_stiffness_N_m_per_rad, "N m/rad"),
            "damping_N_m_s_per_rad": (1.5, "N m s/rad"),
        },
    ),
    "gear_backlash": EffectSpec(
        "backlash of the gear loop 17/13/11 at the disc shaft as a smoothed dead zone (needs loop_compliance)",
        {"backlash_rad": (math.radians(0.2), "rad")},
    ),
    "bearing_friction": EffectSpec(
        "regularised Coulomb friction in the bearings of the disc shaft 3 and the roller shaft 16",
        {"disc_torque_N_m": (0.03, "N m"), "roller_torque_N_m": (0.03, "N m"), "speed_scale_rad_s": (0.02, "rad/s")},
    ),
    "contact_relaxation": EffectSpec(
        "first-order lag of the contact loads dF/dt = (|v|/L_r)(F_ss - F), L_r = length_over_b * b (Equations §4.2)",
        {"length_over_b": (1.0, "1"), "speed_floor_m_s": (1e-3, "m/s")},
    ),
    "swinging_drive": EffectSpec(
        "the earlier oscillating drive: theta_r(t) = amplitude sin(2 pi f t) imposed on shaft 16 (needs "
        "contact_relaxation)",
        {"amplitude_rad": (math.radians(15.0), "rad"), "frequency_Hz": (0.5, "Hz")},
    ),
    "recorder_noise": EffectSpec("white noise of the bridge amplifiers of F_T, F_V and T_Mo (sensors default)"),
    "dynamometer_drift": EffectSpec("random-walk zero drift of dynamometers 5 (sensors default)"),
    "calibration_weight_errors": EffectSpec("true calibration weights differ from nominal within +-0.098 N"),
    "law_mu_range": EffectSpec(
        "numerical: the contact law's alpha' domain laid out for every mu in [mu_low, mu_high] instead of around "
        "the scene's mu, so one surrogate table per load serves every mu of the range (rig lab's hidden mu); the "
        "scene's mu must lie in the range",
        {"mu_low": (0.5, "1"), "mu_high": (1.0, "1")},
    ),
    paper_alpha.EFFECT: EffectSpec(
        "the contact runs at the paper's stated alpha' (ca. 100 ... ca. 1500 for 9 ... 144 N, [Koziarski] section 3.2; a power "
        "law in F_N through both ends) instead of eq. (21)'s Hertz estimate (10.6 ... 42.6 at mu = 0.8): b/a and p0 "
        "stay Hertz's, the creep problem's compliance is m = alpha'_paper/alpha'_Hertz times Kalker's "
        "(rig.stands.disc_roller.paper_alpha)",
        paper_alpha.PARAMETERS,
    ),
}

EFFECT_RANGES: Mapping[str, Mapping[str, tuple[float, float]]] = {
    "loop_compliance": {"stiffness_N_m_per_rad": (100.0, 1e6), "damping_N_m_s_per_rad": (0.0, 1e3)},
    "gear_backlash": {"backlash_rad": (1e-5, math.radians(5.0))},
    "bearing_friction": {"disc_torque_N_m": (0.0, 5.0), "roller_torque_N_m": (0.0, 5.0), "speed_scale_rad_s": (1e-4, 1.0)},
    "contact_relaxation": {"length_over_b": (0.1, 10.0), "speed_floor_m_s": (1e-6, 0.1)},
    "swinging_drive": {"amplitude_rad": (math.radians(0.5), math.radians(90.0)), "frequency_Hz": (0.01, 10.0)},
    "recorder_noise": {},
    "dynamometer_drift": {},
    "calibration_weight_errors": {},
    "law_mu_range": {"mu_low": (PARAMETERS["mu"].lo, PARAMETERS["mu"].hi),
                     "mu_high": (PARAMETERS["mu"].lo, PARAMETERS["mu"].hi)},
    paper_alpha.EFFECT: paper_alpha.RANGES,
}

SETTINGS: Mapping[str, SettingSpec] = {
    "normal_force_N": SettingSpec("N", 1.0, 200.0, "dead-weight load F_N (text: 9, 21, 36, 144 N)"),
    "l_m": SettingSpec("m", -0.025, 0.025, "rolling-point offset l along the contact line, screw 19 (text: 0...+-20 mm)"),
    "sigma_rad": SettingSpec("rad", -0.2, 0.2, "twist of body 14, screw 15: c = e sin(sigma), eq. (36)"),
    "speed_step": SettingSpec("1", 1.0, 3.0, "drive speed 1, 2, 3 = roller 24, 48, 72 rpm (text)", (1.0, 2.0, 3.0)),
    "direction": SettingSpec("1", -1.0, 1.0, "+1 forward, -1 reverse running (text: both directions)", (-1.0, 1.0)),
}


LOG_NAMES = {"normal_force_N": "normal_force", "l_m": "l", "sigma_rad": "sigma", "speed_step": "speed_step",
             "direction": "direction"}
"""Setting name (scene, with unit) -> name in the log (the unit is stored beside it)."""
LOG_UNITS = {LOG_NAMES[name]: spec.unit for name, spec in SETTINGS.items()}


@dataclass(frozen=True)
class StandBParameters:
    """Resolved stand-B parameters, SI; field = PARAMETERS name without its unit suffix (meaning,
    unit and source of each there)."""

    radius_c: float
    roller_radius: float
    pivot_distance: float
    half_length: float
    contact_modulus: float
    mu: float
    friction_reference_pressure: float
    disc_inertia: float
    roller_inertia: float
    motor_inertia: float
    worm_ratio: float
    worm_efficiency: float
    motor_rated_torque: float
    motor_rated_slip: float
    spin_regularisation: float
    rolling_point_limit: float
    recorder_rate: float
    u_l_setting: float
    u_twist: float
    u_normal_force: float
    dynamometer_weight_piece: float
    momentometer_weight_piece: float
    momentometer_arm: float
    point_period: float
    settle_tolerance: float
    ode_tolerance_factor: float

    @property
    def geometry(self) -> StandBGeometry:
        """The reduction's view of the geometry (shared constants, eq. 36, M_C transfer)."""
        return StandBGeometry(
            radius_c=self.radius_c, roller_radius=self.roller_radius,
            pivot_distance=self.pivot_distance, a=self.half_length,
        )

    @property
    def gear_ratio(self) -> float:
        """i_g = omega_roller/omega_disc = R_c/R_r [1] (2.661, Equations §3.2)."""
        return self.radius_c / self.roller_radius

    def roller_speed(self, speed_step: int) -> float:
        """No-load roller speed of drive step 1/2/3 [rad/s] (24/48/72 rpm)."""
        return ROLLER_SPEEDS_RPM[speed_step - 1] * 2.0 * math.pi / 60.0

    def b_over_a(self, normal_force: float) -> float:
        """Hertz line contact of the roller on the flat disc: b = sqrt(4 F_N R_r/(pi 2a E*)) over a [1].

        Equations §3.2: gives 0.500/0.764/1.000/2.000 at 9/21/36/144 N (text: 0.75 at 21 N).
        """
        f = validate.number("normal_force", normal_force, 0.0, lo_open=True)
        b = math.sqrt(4.0 * f * self.roller_radius / (math.pi * 2.0 * self.half_length * self.contact_modulus))
        return b / self.half_length

    def normal_force_for(self, b_over_a: float) -> float:
        """F_N [N] of the Hertz line contact with this b/a (the inverse of :meth:`b_over_a`)."""
        b = validate.number("b_over_a", b_over_a, 0.0, lo_open=True) * self.half_length
        return math.pi * 2.0 * self.half_length * self.contact_modulus * b * b / (4.0 * self.roller_radius)

    def peak_pressure(self, normal_force: float) -> float:
        """p0 = F_N/(pi a b) of the Hertz line contact (length 2a, half width b) [Pa]."""
        return normal_force / (math.pi * self.half_length * self.b_over_a(normal_force) * self.half_length)

    def friction(self, normal_force: float, pressure_exponent: float | None) -> float:
        """The mu the contact runs at [1]: mu, or with a pressure-dependent mu (exponent k, None = off)
        mu(p0) = mu (p0/p_ref)^-k at this load's peak Hertz pressure (rig.contact.effects.pressure_friction)."""
        if pressure_exponent is None:
            return self.mu
        return friction_at_peak_pressure(self.mu, self.peak_pressure(normal_force), self.friction_reference_pressure,
                                         pressure_exponent)

    def alpha_prime(self, normal_force: float, mu: float | None = None) -> float:
        """alpha' = 10 mu (b/a) (v/w0)/R_x with v/w0 = R_c, R_x = R_r (eq. 21, Equations §1.7, 3.2) [1];
        mu: the coefficient the contact runs at (None: the parameter mu; see :meth:`friction`)."""
        mu = self.mu if mu is None else mu
        return 10.0 * mu * self.b_over_a(normal_force) * self.radius_c / self.roller_radius


def field_name(name: str) -> str:
    """Field of StandBParameters for a PARAMETERS name: the name without its unit suffix."""
    for suffix in ("_kg_m2", "_N_m", "_rad_s", "_Pa", "_rad", "_Hz", "_m", "_N", "_s"):
        if name.endswith(suffix):
            return name[: -len(suffix)]
    return name


def resolve_parameters(overrides: Mapping[str, float] | None) -> StandBParameters:
    """Defaults of PARAMETERS with the scene's overrides, each checked against its range."""
    overrides = dict(overrides or {})
    validate.known_keys("stand B parameter", overrides, PARAMETERS)
    values = {}
    for name, spec in PARAMETERS.items():
        values[field_name(name)] = validate.number(name, overrides.get(name, spec.default), spec.lo, spec.hi)
    return StandBParameters(**values)


def resolve_effects(effects: Mapping[str, Mapping[str, float]] | None) -> dict[str, dict[str, float]]:
    """The named effects with their parameters (EffectSpec defaults filled in, ranges checked).

    Dependencies: gear_backlash needs loop_compliance (a dead zone in a rigid loop has no state),
    swinging_drive needs contact_relaxation (the steady law fails through the reversals).
    """
    effects = dict(effects or {})
    validate.known_keys("stand B effect", effects, EFFECTS)
    resolved = {}
    for name, given in effects.items():
        given = dict(given or {})
        spec = EFFECTS[name]
        validate.known_keys(f"{name} parameter", given, spec.parameters)
        params = {}
        for key, (default, _unit) in spec.parameters.items():
            lo, hi = EFFECT_RANGES[name][key]
            params[key] = validate.number(f"{name}.{key}", given.get(key, default), lo, hi)
        resolved[name] = params
    for needs, needed in (("gear_backlash", "loop_compliance"), ("swinging_drive", "contact_relaxation")):
        if needs in resolved and needed not in resolved:
            raise ParameterError("effects", sorted(resolved), f"{needs} together with {needed}")
    if paper_alpha.EFFECT in resolved:
        paper_alpha.check(resolved[paper_alpha.EFFECT])
    if "law_mu_range" in resolved and resolved["law_mu_range"]["mu_high"] < resolved["law_mu_range"]["mu_low"]:
        raise ParameterError("law_mu_range.mu_high", resolved["law_mu_range"]["mu_high"],
                             f">= mu_low = {resolved['law_mu_range']['mu_low']:g}")
    return resolved


@dataclass(frozen=True)
class PointSettings:
    """One operating point: F_N [N], l [m], sigma [rad], drive step 1/2/3, direction +-1."""

    normal_force: float
    l: float
    sigma: float
    speed_step: int
    direction: int

    def offset_c(self, pivot_distance: float) -> float:
        """c = e sin(sigma) [m], eq. (36)."""
        return pivot_distance * math.sin(self.sigma)

    def as_mapping(self) -> dict[str, float]:
        """The settings as logged {name: value} (units in LOG_UNITS)."""
        return dict(normal_force=self.normal_force, l=self.l, sigma=self.sigma,
                    speed_step=float(self.speed_step), direction=float(self.direction))


def point_settings(settings: Mapping[str, float]) -> PointSettings:
    """Check a procedure's settings: every SETTINGS name present, in range; step 1/2/3; direction +-1."""
    validate.known_keys("stand B setting", settings, SETTINGS)
    values = {}
    for name, spec in SETTINGS.items():
        if name not in settings:
            raise ParameterError(name, None, f"a value in [{spec.lo:g}, {spec.hi:g}] {spec.unit} (required per point)")
        values[LOG_NAMES[name]] = spec.check_choice(name, validate.number(name, settings[name], spec.lo, spec.hi))
    return PointSettings(values["normal_force"], values["l"], values["sigma"],
                         int(values["speed_step"]), int(values["direction"]))
