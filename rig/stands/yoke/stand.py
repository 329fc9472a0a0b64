"""Stand A of [Koziarski] (Figs. 8-9, 3.1): the yoke/spring stand as a digital twin.

    YokeStand(parameters, effects, contact, drive)   # rig.stands.base.Stand
    stand.calibrate(seed); point = stand.start_point(k, settings, previous, seed)
    point.settle(timeout_s); gate = point.gate(gate_time_s); outcome = point.read(gate)
    stand.reduce_log(log_path, contact_law=None)  -> reduced DataFrame

Steel wheel 1 (driven by motor 9 through coupling 8) presses, through spring 5, on the laminate
disc 2 in yoke 3 (axle 4, dynamometer 10 at 102 mm against R_v = 42.5 mm); shoe brake 12 on drum
11 with mechanical feedback loads wheel 2; strobe discs 13/14, photocells 15/16 and counters
18/19 gated by timer 22 measure the speed ratio. Parameters: rig.stands.yoke.parameters; the
physics in contact_forces, drive_train, brake, steady_state; docs/stand-a.md.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Mapping
from typing import ClassVar

from rig import validate
from rig.errors import ParameterError
from rig.logbook import LogSchema
from rig.stands.base import ContactSpec, DriveMode, Stand
from rig.stands.yoke import instruments, laws
from rig.stands.yoke import parameters as spec
from rig.stands.yoke.brake import critical_gain
from rig.stands.yoke.contact_forces import StandAContact
from rig.stands.yoke.drive_train import BearingFriction
from rig.stands.yoke.integration import GATE_SAMPLE_RATE_HZ
from rig.stands.yoke.point import YokePoint
from rig.stands.yoke.reduction import reduce_log
from rig.stands.yoke.steady_state import OperatingPoint, steady_state

KEPT = 2
"""Steady operating points and contacts a stand remembers (this point's and the previous one's)."""

DYNAMIC_ONLY = ("drive_compliance", "brake_dynamics", "brake_friction_fluctuation")


def _kept(cache: OrderedDict, key, make: Callable[[], object]):
    """cache[key], made by make() on first use; the oldest entries beyond KEPT are dropped."""
    found = cache.get(key)
    if found is None:
        found = cache[key] = make()
        while len(cache) > KEPT:
            cache.popitem(last=False)
    return found


class YokeStand(Stand):
    """Stand A. ``law_factory(spec, shape, b_over_a, domain) -> law`` defaults to
    rig.stands.contact_law.make_contact_law (a stand-in can be given, e.g. in tests)."""

    name: ClassVar[str] = "yoke"
    PARAMETERS = spec.PARAMETERS
    EFFECTS = spec.EFFECTS
    SETTINGS = spec.SETTINGS
    LOG_SCHEMA = LogSchema(
        channels={instruments.DYNAMOMETER: "V", instruments.BALANCE: "N m"},
        settings=dict(spec.LOG_SETTINGS.values()),
        readings={"T2": "N m", "dynamometer_signal": "V"},
        counters=instruments.CHANNELS,
    )

    @classmethod
    def resolve_effects(cls, effects: Mapping[str, Mapping[str, float]]) -> dict[str, dict[str, float]]:
        validate.known_keys("stand A effect", effects, spec.EFFECTS)
        return {name: spec.effect_values(name, given) for name, given in effects.items()}

    @classmethod
    def gate_sample_rate_Hz(cls, parameters: Mapping[str, float]) -> float:
        """The true signals' rate, the dynamometer's or the balance's, whichever is highest [Hz]."""
        p = spec.resolve(parameters)
        return max(GATE_SAMPLE_RATE_HZ, p.dynamometer_rate_Hz, p.balance_rate_Hz)

    def __init__(self, parameters: Mapping[str, float], effects: Mapping[str, Mapping[str, float]],
                 contact: ContactSpec, drive: DriveMode, *, law_factory: laws.LawFactory | None = None) -> None:
        self.params = spec.resolve(parameters)
        if "pressure_exponent" in contact.effects:  # its mu(p0) per load is done for stand B only
            raise ParameterError("contact.effects.pressure_exponent", contact.effects["pressure_exponent"],
                                 "not on stand A (yoke): the pressure-dependent mu is available on stand B "
                                 "(disc_roller) and in the contact model (docs/contact-model.md)")
        self.law = laws.LawCache(contact, self.params.mu, law_factory)  # law(b_over_a, geometry) -> (law, domain)
        if not isinstance(drive, DriveMode):
            raise ParameterError("drive", drive, "one of " + ", ".join(repr(m.value) for m in DriveMode))
        self.effects = self.resolve_effects(effects)
        self._check_effects(drive)
        self.contact_spec = contact
        self.drive = drive
        self._law_factory = law_factory
        self._calibrations: dict[int, object] = {}
        self._steady: OrderedDict[tuple, OperatingPoint] = OrderedDict()
        self._contacts: OrderedDict[tuple[float, float], StandAContact] = OrderedDict()

    def _check_effects(self, drive: DriveMode) -> None:
        if drive is DriveMode.QUASI_STATIC:
            for name in DYNAMIC_ONLY:
                if name in self.effects:
                    raise ParameterError(f"effects.{name}", "named", "only with scene.drive = 'dynamic' (the "
                                         "quasi-static drive has no dynamics)")
        if "brake_friction_fluctuation" in self.effects and "brake_dynamics" not in self.effects:
            raise ParameterError("effects.brake_friction_fluctuation", "named without brake_dynamics",
                                 "together with effects.brake_dynamics (the disturbance acts through the loop)")
        if "brake_dynamics" in self.effects:
            e = self.effects["brake_dynamics"]
            g_max = critical_gain((e["tau_lever_s"], e["tau_shoe_s"], e["tau_lining_s"]))
            if e["loop_gain"] >= g_max:
                raise ParameterError("effects.brake_dynamics.loop_gain", e["loop_gain"],
                                     f"(0, {g_max:.4g}): Routh-Hurwitz limit of the three-lag brake loop")
        f = self.effects.get("brake_friction_fluctuation")
        if f is not None and f["f_max_Hz"] < f["f_min_Hz"]:
            raise ParameterError("effects.brake_friction_fluctuation.f_max_Hz", f["f_max_Hz"],
                                 f">= f_min_Hz = {f['f_min_Hz']:g} Hz")

    # ------------------------------------------------------------------------------ pieces

    def check_settings(self, settings: Mapping[str, float]) -> dict[str, float]:
        """Every SETTING present and inside its range (named errors); returns floats."""
        validate.known_keys("stand A setting", settings, self.SETTINGS)
        out = {}
        for name, setting in self.SETTINGS.items():
            if name not in settings:
                raise ParameterError(name, "missing", f"a number in [{setting.lo:g}, {setting.hi:g}] {setting.unit}")
            out[name] = validate.number(name, settings[name], setting.lo, setting.hi)
        if out["brake_setpoint_N_m"] < 0.0 and "load_device" not in self.effects:
            raise ParameterError("brake_setpoint_N_m", out["brake_setpoint_N_m"],
                                 f"[0, {self.SETTINGS['brake_setpoint_N_m'].hi:g}] N m: shoe brake 12 only brakes",
                                 hint="name [effects.load_device] for an idealised device that drives wheel 2")
        return out

    def contact_for(self, settings: Mapping[str, float]) -> StandAContact:
        """The contact of an operating point's settings (F_N, Delta h), kept for the last KEPT pairs (a
        sweep at one load and yoke shift builds it once)."""
        def make() -> StandAContact:
            p = self.params
            geometry = p.geometry_at(settings["delta_h_m"])
            f_n = settings["normal_force_N"]
            b_over_a = geometry.b_over_a(f_n)
            law, domain = self.law(b_over_a, geometry)
            return StandAContact(geometry, f_n, b_over_a, p.mu, law, domain, p.slip_speed_eps_m_s)

        return _kept(self._contacts, (settings["normal_force_N"], settings["delta_h_m"]), make)

    def steady_state(self, settings: Mapping[str, float], bearing: BearingFriction | None) -> OperatingPoint:
        """The steady operating point of checked ``settings`` (rig.stands.yoke.steady_state), kept for
        the last KEPT settings: a point's start is the previous point's steady state, which that point
        has just computed (a pure function of the settings, so reusing it changes nothing). Raises
        ParameterError where there is none (never kept)."""
        key = (tuple(sorted(settings.items())), None if bearing is None else (bearing.moment_1, bearing.moment_2))
        return _kept(self._steady, key, lambda: steady_state(
            self.contact_for(settings), settings["omega_1_set_rad_s"], settings["brake_setpoint_N_m"],
            brake_speed_eps=self.params.brake_speed_eps_rad_s, bearing=bearing))

    def calibration(self, seed: int):
        """The calibration record of dynamometer 10 for the run ``seed`` (made once, then kept)."""
        seed = validate.integer("seed", seed, 0)
        if seed not in self._calibrations:
            self._calibrations[seed] = instruments.calibrate(self.params, self.effects, seed)
        return self._calibrations[seed]

    # ------------------------------------------------------------------------------ contract

    def calibrate(self, seed: int) -> Mapping[str, object]:
        """Calibrate dynamometer 10 with weights (once per run); {"dynamometer_10": CalibrationRecord}."""
        return {instruments.DYNAMOMETER: self.calibration(seed)}

    def start_point(self, index: int, settings: Mapping[str, float], previous: Mapping[str, float] | None,
                    seed: int) -> YokePoint:
        """Point ``index``: from the steady state of ``previous`` (rest if None), step to ``settings``."""
        return YokePoint(self, index, settings, previous, seed)

    def reduce_log(self, log_path, contact_law=None):
        """Reduce a log of this stand (eqs. 29-35): DataFrame, one row per point.

        contact_law: None = the stand's own laws (the scene's ContactSpec, as simulated); a
        ContactSpec = laws of that spec; or a callable law_for(b_over_a, geometry) -> (law, domain).
        """
        if contact_law is None:
            law_for = self.law
        elif isinstance(contact_law, ContactSpec):
            law_for = self.law if contact_law == self.contact_spec else laws.LawCache(
                contact_law, self.params.mu, self._law_factory)
        elif callable(contact_law):
            law_for = contact_law
        else:
            raise ParameterError("contact_law", contact_law, "None, a ContactSpec or law_for(b_over_a, geometry)")
        return reduce_log(log_path, self.params, law_for)
