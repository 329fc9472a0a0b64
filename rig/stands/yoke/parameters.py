"""Every parameter of stand A (the yoke/spring stand, [Koziarski] Figs. 8-9) in ONE place.

Each entry says where its default comes from: [text] stated in [Koziarski], [computed] arithmetic on
the text (Equations §3.1), [assumed] a plausible value of ours with the reason (Equations §4.1
gives most of the drive-train values). Geometry defaults are not repeated here: they are read
from :class:`rig.reduction.geometry.StandAGeometry` (the reduction's view of the same stand), so
the simulator and the reduction cannot drift apart. Units are SI and part of every name.

* ``PARAMETERS``: what a scene may override (``[parameters]``), ParameterSpec each.
* ``EFFECTS``: optional effects (``[effects.<name>]``); absent = not built.
* ``SETTINGS``: what a procedure sets per operating point.
* :class:`YokeParameters`: the resolved values of one stand, built by :func:`resolve`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields, replace
from types import MappingProxyType

from rig import validate
from rig.errors import ParameterError
from rig.reduction.geometry import StandAGeometry
from rig.stands.base import EffectSpec, ParameterSpec, SettingSpec
from rig.stands.yoke.laws import MU_MAX, MU_MIN

_GEOMETRY = StandAGeometry()
_GEOMETRY_META = {f.name: f.metadata for f in fields(StandAGeometry)}

# parameter name -> StandAGeometry field it overrides
GEOMETRY_FIELDS = {
    "l1_m": "l1", "l2_m": "l2", "alpha_1_rad": "alpha_1", "a_m": "a", "r1_m": "r1", "radius_x_m": "radius_x",
    "dynamometer_lever_m": "dynamometer_lever", "yoke_lever_m": "yoke_lever", "balance_arm_m": "balance_arm",
}
_GEOMETRY_RANGES = {
    "l1_m": (0.01, 0.1), "l2_m": (-0.1, -0.01), "alpha_1_rad": (0.1, math.pi / 2), "a_m": (0.3e-3, 5e-3),
    "r1_m": (0.01, 0.1), "radius_x_m": (0.02, 1.0), "dynamometer_lever_m": (0.02, 0.5),
    "yoke_lever_m": (0.01, 0.2), "balance_arm_m": (0.05, 2.0),
}


def _from_geometry(name: str) -> ParameterSpec:
    meta = _GEOMETRY_META[GEOMETRY_FIELDS[name]]
    lo, hi = _GEOMETRY_RANGES[name]
    value = getattr(_GEOMETRY, GEOMETRY_FIELDS[name])
    return ParameterSpec(value, meta["unit"], lo, hi, f"[{meta['tag']}] {meta['source']} (StandAGeometry)")


PARAMETERS: Mapping[str, ParameterSpec] = MappingProxyType({
    **{name: _from_geometry(name) for name in GEOMETRY_FIELDS},
    "mu": ParameterSpec(0.4, "1", MU_MIN, MU_MAX, "[assumed] true friction coefficient of the pair (Equations §3.1: "
                        "textolite on steel ~0.4, Niemann); one value for every slip direction, as the paper "
                        "assumes; range = the contact-law tables' a-priori range (rig.stands.yoke.laws)"),
    "E_lam_Pa": ParameterSpec(4.5e9, "Pa", 1e8, 1e11, "[assumed] laminate modulus (Equations §3.1: 4.5 GPa makes "
                              "a Hertz line contact of a = 1.215 mm give b/a = 1 at 96.2 N); enters p0 only"),
    "poisson_lam": ParameterSpec(0.3, "1", 0.0, 0.5, "[assumed] laminate Poisson ratio (Equations §3.1)"),
    "J_1_kg_m2": ParameterSpec(1.0e-3, "kg m^2", 1e-5, 1.0, "[assumed] wheel 1 + shaft + strobe disc 13 "
                               "(Equations §4.1: steel wheel 82 x 20 mm ~ 7e-4)"),
    "J_2_kg_m2": ParameterSpec(4.0e-3, "kg m^2", 1e-5, 1.0, "[assumed] lined disc + drum 11 + strobe disc 14 "
                               "(Equations §4.1)"),
    "marks_1": ParameterSpec(60, "1", 1, 10_000, "[assumed] marks on strobe disc 13 (not given; 60 gives "
                             "~4800 counts in a 20 s gate, Equations §2)"),
    "marks_2": ParameterSpec(60, "1", 1, 10_000, "[assumed] marks on strobe disc 14"),
    "timer_u_s": ParameterSpec(1e-4, "s", 0.0, 1.0, "[assumed] standard uncertainty of the gate time of timer 22 "
                               "(cancels in i_k and alpha')"),
    "normal_force_u_N": ParameterSpec(0.5, "N", 0.0, 50.0, "[assumed] standard uncertainty of the spring "
                                      "setting F_N (scale of spring 5/screw 6)"),
    "dynamometer_rate_Hz": ParameterSpec(50.0, "Hz", 1.0, 5000.0, "[assumed] sampling of the dynamometer "
                                         "amplifier output over the gate"),
    "ode_tolerance_factor": ParameterSpec(1.0, "1", 1e-3, 1e3, "[assumed] numerical: factor on the drive-train integrator's "
                                          "relative tolerances (1e-5 settling, 1e-4 over the gate: "
                                          "rig.stands.yoke.integration); rig accuracy studies it"),
    "balance_rate_Hz": ParameterSpec(1.0, "Hz", 0.05, 100.0, "[assumed] readings of the tangent balance per "
                                     "second (the operator reads the pointer)"),
    "balance_step_N": ParameterSpec(0.098, "N", 1e-3, 1.0, "[assumed] scale step of the tangent balance at its "
                                    "arm; 0.098 N reads the paper's 'accuracy 0.049 N' as a +-limit (u(T2) = "
                                    "0.0113 N m, conservative default), 0.049 N as the step itself (0.0057 N m); "
                                    "the log records it for the reduction (sensors.balance)"),
    "point_period_s": ParameterSpec(60.0, "s", 1.0, 3600.0, "[assumed] run time per operating point, places "
                                    "point k's gate at a fixed run time for the slow dynamometer drift"),
    "speed_ramp_s": ParameterSpec(1.0, "s", 0.01, 60.0, "[assumed] ramp time of the motor speed set-point "
                                  "(start from rest and speed steps)"),
    "slip_speed_eps_m_s": ParameterSpec(1e-3, "m/s", 1e-6, 0.1, "[assumed] regularisation of Coulomb contact "
                                        "friction at standstill: forces x tanh(s/eps), s = slip speed scale "
                                        "(hard case 7)"),
    "brake_speed_eps_rad_s": ParameterSpec(0.01, "rad/s", 1e-5, 1.0, "[assumed] regularisation of the brake "
                                           "and bearing Coulomb moments at zero speed: x tanh(w/eps)"),
})

EFFECTS: Mapping[str, EffectSpec] = MappingProxyType({
    "drive_compliance": EffectSpec(
        "motor 9 with rotor inertia and a speed controller (PI) driving wheel 1 through the elastic coupling 8; "
        "off: wheel 1 follows the speed set-point exactly (ideal speed source)",
        {"J_m_kg_m2": (2.5e-3, "kg m^2"), "coupling_stiffness_N_m_per_rad": (300.0, "N m/rad"),
         "coupling_damping_ratio": (0.07, "1"), "motor_bandwidth_Hz": (8.0, "Hz")},
    ),
    "brake_dynamics": EffectSpec(
        "shoe brake 12 with mechanical feedback as a loop of three lags (lever, shoe linkage, lining) with a "
        "finite loop gain; off: the brake moment equals the set-point",
        {"loop_gain": (10.0, "1"), "tau_lever_s": (0.1, "s"), "tau_shoe_s": (0.02, "s"), "tau_lining_s": (0.005, "s")},
    ),
    "bearing_friction": EffectSpec(
        "Coulomb friction moments in bearings 7 (wheel 1) and of wheel 2 (regularised at zero speed)",
        {"moment_1_N_m": (0.03, "N m"), "moment_2_N_m": (0.02, "N m")},
    ),
    "brake_friction_fluctuation": EffectSpec(
        "seeded random variation of the brake lining friction (sum of sines, unit rms shape); the feedback "
        "loop must reject it; needs brake_dynamics",
        {"relative_rms": (0.05, "1"), "f_min_Hz": (0.05, "Hz"), "f_max_Hz": (0.5, "Hz")},
    ),
    "dynamometer_noise": EffectSpec("white noise at the input of the dynamometer 10 amplifier",
                                    {"std_V": (1.0e-6, "V")}),
    "dynamometer_drift": EffectSpec("random-walk zero drift of the dynamometer 10 amplifier (over the run)",
                                    {"diffusion_V_per_sqrt_s": (1.0e-7, "V/s^0.5")}),
    "balance_noise": EffectSpec("reading scatter of the tangent balance at its arm", {"std_N": (0.01, "N")}),
    "counter_pulse_noise": EffectSpec("photocell pulse-amplitude scatter (a pulse below the threshold is missed)",
                                      {"std_V": (0.00625, "V")}),
    "calibration_weight_error": EffectSpec("true weights of the calibration pieces differ from nominal "
                                           "(uniform within +-0.098 N, [Koziarski])"),
    "load_device": EffectSpec("an idealised load device on wheel 2 that can also drive it: negative brake "
                              "set-points (rolling point at l < 0), same loop and regularisation as the brake; "
                              "not in the paper; off: shoe brake 12 only brakes, T_set >= 0"),
})

# Valid ranges of the effect parameters (the scene checks names, the stand checks values).
EFFECT_RANGES: Mapping[str, tuple[float, float]] = MappingProxyType({
    "J_m_kg_m2": (1e-5, 1.0), "coupling_stiffness_N_m_per_rad": (1.0, 1e6), "coupling_damping_ratio": (0.0, 2.0),
    "motor_bandwidth_Hz": (0.1, 100.0), "loop_gain": (1e-6, 1e4), "tau_lever_s": (1e-4, 10.0),
    "tau_shoe_s": (1e-4, 10.0), "tau_lining_s": (1e-4, 10.0), "moment_1_N_m": (0.0, 1.0),
    "moment_2_N_m": (0.0, 1.0), "relative_rms": (1e-6, 0.2), "f_min_Hz": (1e-3, 50.0), "f_max_Hz": (1e-3, 50.0),
    "std_V": (1e-12, 1.0), "diffusion_V_per_sqrt_s": (1e-15, 1e-3), "std_N": (1e-9, 10.0),
})

SETTINGS: Mapping[str, SettingSpec] = MappingProxyType({
    "brake_setpoint_N_m": SettingSpec("N m", -8.0, 8.0, "set-point T_set of the load moment on wheel 2 (brake 12); "
                                      "negative only with effects.load_device, which then drives wheel 2 "
                                      "(docs/stand-a.md section 4)"),
    "normal_force_N": SettingSpec("N", 10.0, 500.0, "pressing force F_N of spring 5 (text: 96.2 N and 385 N)"),
    "delta_h_m": SettingSpec("m", 0.0, 1.5e-3, "yoke shift Delta h along axle 4 (text: 0 and 1.06 mm)"),
    "omega_1_set_rad_s": SettingSpec("rad/s", 1.0, 60.0, "speed set-point of wheel 1 (text: 240 rpm = 25.13 rad/s)"),
})
# Setting name -> (log name, unit): the log stores the bare name with the unit attached.
LOG_SETTINGS = MappingProxyType({
    "brake_setpoint_N_m": ("brake_setpoint", "N m"), "normal_force_N": ("normal_force", "N"),
    "delta_h_m": ("delta_h", "m"), "omega_1_set_rad_s": ("omega_1_set", "rad/s"),
})


@dataclass(frozen=True)
class YokeParameters:
    """Resolved parameters of one stand A (SI units; names as in PARAMETERS, the geometry ones in ``geometry``)."""

    geometry: StandAGeometry
    mu: float
    E_lam_Pa: float
    poisson_lam: float
    J_1_kg_m2: float
    J_2_kg_m2: float
    marks_1: int
    marks_2: int
    timer_u_s: float
    normal_force_u_N: float
    dynamometer_rate_Hz: float
    ode_tolerance_factor: float
    balance_rate_Hz: float
    balance_step_N: float
    point_period_s: float
    speed_ramp_s: float
    slip_speed_eps_m_s: float
    brake_speed_eps_rad_s: float

    def geometry_at(self, delta_h_m: float) -> StandAGeometry:
        """The geometry with the yoke shift Delta h [m] of an operating point."""
        return replace(self.geometry, delta_h=delta_h_m)

    @property
    def contact_modulus_Pa(self) -> float:
        """E* of the pair [Pa]: steel rigid against the laminate, E*= E_lam/(1 - nu^2) (eq. 23)."""
        return self.E_lam_Pa / (1.0 - self.poisson_lam**2)


def resolve(overrides: Mapping[str, object]) -> YokeParameters:
    """Defaults of PARAMETERS with ``overrides`` {name: value} applied and range-checked."""
    validate.known_keys("stand A parameter", overrides, PARAMETERS)
    values = {}
    for name, spec in PARAMETERS.items():
        given = overrides.get(name, spec.default)
        values[name] = validate.number(name, given, spec.lo, spec.hi)
    for name in ("marks_1", "marks_2"):
        if values[name] != int(values[name]):
            raise ParameterError(name, overrides[name], f"a whole number in [{PARAMETERS[name].lo:g}, "
                                 f"{PARAMETERS[name].hi:g}]")
        values[name] = int(values[name])
    geometry = replace(_GEOMETRY, **{GEOMETRY_FIELDS[n]: values.pop(n) for n in GEOMETRY_FIELDS})
    return YokeParameters(geometry=geometry, **values)


def effect_values(name: str, given: Mapping[str, object]) -> dict[str, float]:
    """The parameters of effect ``name`` (defaults filled in), each checked against EFFECT_RANGES."""
    spec = EFFECTS[name]
    validate.known_keys(f"parameter of effect {name!r}", given, spec.parameters)
    out = {}
    for parameter, (default, _unit) in spec.parameters.items():
        lo, hi = EFFECT_RANGES[parameter]
        out[parameter] = validate.number(f"effects.{name}.{parameter}", given.get(parameter, default), lo, hi)
    return out
