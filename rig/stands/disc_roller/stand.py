"""DiscRollerStand: stand B built from a scene (contract: rig.stands.base).

Only the named effects are built (rig.stands.disc_roller.parameters.EFFECTS); the contact law
per load (b/a) comes from rig.stands.contact_law.make_contact_law (direct or surrogate table,
ContactSpec) over the domain the stand needs (l/a within +-rolling_point_limit, c/a of the
twist range, alpha' from a quarter to four times the point's value - or of every mu in the range of
the effect law_mu_range), built on first use.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import ClassVar

from rig import validate
from rig.contact.surrogate import TableDomain
from rig.errors import ParameterError
from rig.logbook import LogSchema
from rig.reduction.iteration import ReductionSettings
from rig.stands.base import ContactSpec, DriveMode, PointSimulation, Stand
from rig.stands.contact_law import make_contact_law
from rig.stands.disc_roller import paper_alpha
from rig.stands.disc_roller import parameters as P
from rig.stands.disc_roller.components import BearingFriction, ContactRelaxation, LoopCompliance, WormDrive
from rig.stands.disc_roller.contact import ContactPoint, Law
from rig.stands.disc_roller.drive_train import DriveTrain
from rig.stands.disc_roller.instruments import CHANNELS, InstrumentEffects, calibrate
from rig.stands.disc_roller.swinging_drive import SwingingDrive

ALPHA_BAND = 4.0  # the law's alpha' domain: [alpha/4, 4 alpha] around the point's value [1] ...
START_MARGIN = 1.25  # ... widened to reach this factor past the reduction's start alpha'(mu_start) [1]
REDUCTION_START = ReductionSettings()  # the reduction's default settings (its mu_start)
LawFactory = Callable[[float], Law]
"""b/a [1] -> canonical contact law (vectorised)."""


class DiscRollerStand(Stand):
    """Stand B (Figs. 12-13). See the package docstring and docs/stand-b.md.

    parameters: overrides of PARAMETERS; effects: {name: {parameter: value}} of EFFECTS (absent
    = off, not built); contact: the ContactSpec (shape is "line": roller on a flat disc);
    drive: DYNAMIC (drive-train ODE) or QUASI_STATIC (steady state solved directly).
    law_factory: optional b/a -> law replacing make_contact_law (tests, tools).
    """

    name: ClassVar[str] = "disc_roller"
    PARAMETERS = P.PARAMETERS
    EFFECTS = P.EFFECTS
    SETTINGS = P.SETTINGS
    LOG_SCHEMA: ClassVar[LogSchema] = LogSchema(
        channels={name: "V" for name in CHANNELS},
        settings=dict(P.LOG_UNITS),
    )
    SHAPE: ClassVar[str] = "line"

    @classmethod
    def resolve_effects(cls, effects: Mapping[str, Mapping[str, float]] | None) -> dict[str, dict[str, float]]:
        return P.resolve_effects(effects)

    def __init__(
        self, parameters: Mapping[str, float] | None, effects: Mapping[str, Mapping[str, float]] | None,
        contact: ContactSpec, drive: DriveMode, *, law_factory: LawFactory | None = None,
    ) -> None:
        self.params = P.resolve_parameters(parameters)
        self.effects = self.resolve_effects(effects)
        if not isinstance(contact, ContactSpec):
            raise ParameterError("contact", contact, "a rig.stands.base.ContactSpec")
        if not isinstance(drive, DriveMode):
            raise ParameterError("drive", drive, "a rig.stands.base.DriveMode")
        if drive is DriveMode.QUASI_STATIC and "swinging_drive" in self.effects:
            raise ParameterError("drive", drive.value, "dynamic with the swinging drive (it has no steady state)")
        if "law_mu_range" in self.effects:
            span = self.effects["law_mu_range"]
            if not span["mu_low"] <= self.params.mu <= span["mu_high"]:
                raise ParameterError("mu", self.params.mu, f"[{span['mu_low']:g}, {span['mu_high']:g}], the range "
                                     "of effects.law_mu_range")
        self.contact = contact
        self.pressure_exponent = contact.effects.get("pressure_exponent")  # k of mu(p), None = off
        self.drive = drive
        self.instrument_effects = InstrumentEffects(
            noise="recorder_noise" in self.effects, drift="dynamometer_drift" in self.effects,
            weight_errors="calibration_weight_errors" in self.effects,
        )
        self._law_factory = law_factory
        self._laws: dict[float, Law] = {}
        self._calibrations: dict[int, dict] = {}

    @classmethod
    def gate_sample_rate_Hz(cls, parameters: Mapping[str, float]) -> float:
        """The recorder's rate [Hz] (every channel and the true signals are sampled at it)."""
        return P.resolve_parameters(parameters).recorder_rate

    # ---- components -------------------------------------------------------------------------
    def friction(self, normal_force: float) -> float:
        """The mu the contact runs at at this load [1]: the parameter mu, or mu(p0) with a
        pressure-dependent mu (contact effect pressure_exponent; StandBParameters.friction)."""
        return self.params.friction(normal_force, self.pressure_exponent)

    def law_domain(self, b_over_a: float) -> TableDomain:
        """Canonical (l/a, c/a, alpha') domain the stand evaluates the law in at this b/a (alpha' of eq. 21)."""
        p = self.params
        limit = p.rolling_point_limit
        c_max = p.pivot_distance * math.sin(P.SETTINGS["sigma_rad"].hi) / p.half_length
        mu = p.mu if self.pressure_exponent is None else self.friction(p.normal_force_for(b_over_a))
        alpha = 10.0 * mu * b_over_a * p.radius_c / p.roller_radius
        start = alpha * REDUCTION_START.mu_start / mu  # alpha' ~ mu: where the reduction's iteration starts
        low = high = alpha
        if "law_mu_range" in self.effects:  # laid out for a range of mu, not around the scene's (eq. 21)
            span = self.effects["law_mu_range"]
            low, high = (10.0 * span[k] * b_over_a * p.radius_c / p.roller_radius for k in ("mu_low", "mu_high"))
        return TableDomain((-limit, limit), (-c_max, c_max), (min(low / ALPHA_BAND, start / START_MARGIN),
                                                               max(high * ALPHA_BAND, start * START_MARGIN)))

    def alpha_factor(self, b_over_a: float) -> float:
        """alpha' the contact runs at over eq. (21)'s [1]: 1, or alpha'_paper/alpha'_Hertz with the
        effect paper_alpha_range (rig.stands.disc_roller.paper_alpha)."""
        values = self.effects.get(paper_alpha.EFFECT)
        if values is None:
            return 1.0
        force = self.params.normal_force_for(b_over_a)
        return paper_alpha.paper_alpha_prime(values, force) / self.params.alpha_prime(force)

    def law(self, b_over_a: float) -> Law:
        """The canonical contact law at b/a in eq. (21)'s alpha' (built once per load; cached)."""
        key = float(b_over_a)
        if key not in self._laws:
            factor = self.alpha_factor(key)
            if self._law_factory is not None:
                law = self._law_factory(key)
            else:
                domain = self.law_domain(key)
                law = make_contact_law(self.contact, self.SHAPE, key, TableDomain(
                    domain.l_over_a, domain.c_over_a, tuple(factor * x for x in domain.alpha)))
            self._laws[key] = law if factor == 1.0 else paper_alpha.AlphaScaledLaw(law, factor)
        return self._laws[key]

    def contact_point(self, settings: P.PointSettings) -> ContactPoint:
        """The contact of an operating point (Hertz line contact, alpha' of eq. 21)."""
        p = self.params
        b_over_a = p.b_over_a(settings.normal_force)
        domain = self.law_domain(b_over_a)
        mu = self.friction(settings.normal_force)
        return ContactPoint(
            law=self.law(b_over_a), normal_force=settings.normal_force, mu=mu, a=p.half_length,
            b=b_over_a * p.half_length, alpha=p.alpha_prime(settings.normal_force, mu), alpha_max=domain.alpha[1],
            l_set=settings.l, c=settings.offset_c(p.pivot_distance), radius_c=p.radius_c,
            spin_eps=p.spin_regularisation, l_limit=p.rolling_point_limit,
        )

    def drive_train(self, settings: P.PointSettings) -> DriveTrain:
        """The drive train of an operating point with the named effects."""
        p, e = self.params, self.effects
        contact = self.contact_point(settings)
        loop = relaxation = bearings = worm = swinging = None
        if "loop_compliance" in e:
            backlash = e["gear_backlash"]["backlash_rad"] if "gear_backlash" in e else None
            loop = LoopCompliance(e["loop_compliance"]["stiffness_N_m_per_rad"],
                                  e["loop_compliance"]["damping_N_m_s_per_rad"], backlash)
        if "bearing_friction" in e:
            f = e["bearing_friction"]
            bearings = BearingFriction(f["disc_torque_N_m"], f["roller_torque_N_m"], f["speed_scale_rad_s"])
        if "contact_relaxation" in e:
            relaxation = ContactRelaxation(e["contact_relaxation"]["length_over_b"] * contact.b,
                                           e["contact_relaxation"]["speed_floor_m_s"])
        if "swinging_drive" in e:
            swinging = SwingingDrive(e["swinging_drive"]["amplitude_rad"], e["swinging_drive"]["frequency_Hz"])
        else:
            worm = WormDrive.from_rating(p.roller_inertia, p.motor_inertia, p.worm_ratio, p.worm_efficiency,
                                         p.motor_rated_torque, p.motor_rated_slip)
        return DriveTrain(
            contact=contact, radius_c=p.radius_c, roller_radius=p.roller_radius, disc_inertia=p.disc_inertia,
            worm=worm, set_speed=settings.direction * p.roller_speed(settings.speed_step), swinging=swinging,
            loop=loop, bearings=bearings, relaxation=relaxation,
        )

    # ---- contract ---------------------------------------------------------------------------
    def calibrate(self, seed: int) -> Mapping[str, object]:
        """Calibrations of dynamometers 5 (F_T, F_V) and momentometer 8, once per run (cached by seed)."""
        seed = validate.integer("seed", seed, 0)
        if seed not in self._calibrations:
            self._calibrations[seed] = calibrate(self.params, seed, self.instrument_effects)
        return dict(self._calibrations[seed])

    def start_point(
        self, index: int, settings: Mapping[str, float], previous: Mapping[str, float] | None, seed: int
    ) -> PointSimulation:
        """Point ``index``: from the steady state of ``previous`` (rest if None) to ``settings``."""
        from rig.stands.disc_roller.simulation import DiscRollerPoint

        index = validate.integer("index", index, 0, 10**6 - 1)
        target = P.point_settings(settings)
        before = None if previous is None else P.point_settings(previous)
        return DiscRollerPoint(self, index, target, before, validate.integer("seed", seed, 0))

    def reduce_log(self, log_path, contact_law=None):
        """Reduce a stand-B log (rig.stands.disc_roller.reduction.reduce_log): a DataFrame per point.

        contact_law: the scene's ContactSpec (None: this stand's) or a b/a -> law factory.
        """
        from rig.stands.disc_roller.reduction import reduce_log

        if "swinging_drive" in self.effects:
            raise ParameterError("effects", "swinging_drive", "the continuous drive: the reduction (eqs. 26-28, 33, "
                                 "M_C = T_Mo + R_c F_T) needs a steady operating point")
        if contact_law is None or contact_law == self.contact:
            factory = self.law
        elif isinstance(contact_law, ContactSpec):
            factory = DiscRollerStand(self._overrides(), {}, contact_law, DriveMode.QUASI_STATIC).law
        elif callable(contact_law):
            factory = contact_law
        else:
            raise ParameterError("contact_law", contact_law, "a ContactSpec, a b/a -> law callable, or None")
        return reduce_log(log_path, self.params, factory, self.law_domain)

    def _overrides(self) -> dict[str, float]:
        return {name: getattr(self.params, P.field_name(name)) for name in P.PARAMETERS}
