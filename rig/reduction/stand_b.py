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
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass

from rig import validate
from rig.reduction import equations as eq
from rig.reduction.coefficients import Coefficients, call_model, corrected, with_model_error
from rig.reduction.drivers import significant_drivers
from rig.reduction.geometry import StandBGeometry, with_inputs
from rig.reduction.iteration import ReductionSettings
from rig.reduction.readings import Measured, reading_inputs, reading_value
from rig.reduction.result import Evaluation, Guard, ReducedPoint, Start, evaluate_fixed_point, reduce_stand_point
from rig.reduction.roots import scan
from rig.reduction.uncertainty import InputQuantity, InputSet, first_order

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


def chain_at(
    values: Mapping[str, float],
    *,
    readings: StandBReadings,
    geometry: StandBGeometry,
    coefficients: Coefficients,
    settings: ReductionSettings,
) -> tuple[dict[str, float], float, Callable[[float], tuple[dict[str, float], dict[str, str]]]]:
    """The chain at one set of input values, before the mu <-> alpha' fixed point: the outputs that
    do not depend on mu, alpha'/mu [1] (eq. 21), and state_at(mu) -> (the driven outputs at
    alpha'(mu), reasons for their NaNs)."""
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

    return out, alpha_per_mu, state_at


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
    out, _, state_at = chain_at(values, readings=readings, geometry=geometry, coefficients=coefficients,
                                settings=settings)
    return evaluate_fixed_point(state_at, start, settings, out, DRIVEN)


def reduce(
    readings: StandBReadings,
    coefficients: Coefficients,
    geometry: StandBGeometry | None = None,
    settings: ReductionSettings | None = None,
    geometry_u: Mapping[str, float] | None = None,
) -> ReducedPoint:
    """Reduce one stand-B operating point (see rig.reduction.stand_a.reduce for the arguments).

    The driving estimate's equation is checked for more than one root in the bracket
    (:func:`mu_bracket`, rig.reduction.roots), counting a turning point of its ratio within
    ``settings.significance`` standard uncertainties of the reading as a root (:func:`driver_roots`:
    the reading cannot exclude mu there). With two or more, the next significant estimate whose own
    equation has exactly one root and no such turning point drives alpha' instead (mu_T from F_T,
    mu_M from M_C); failing that, :func:`choose_root` keeps the root the other estimates agree with,
    or reports the driven outputs as NaN naming the roots.

    One root is checked too, where a root could hide from the reading: when the driver's ratio has a
    turning point in the bracket (a peak below the reading, a trough above it, z_t standard
    uncertainties away, :func:`driver_roots`), the other significant estimates are compared with the
    driver at the reduced point (:func:`_difference_z`, covariance-aware). If one differs by z >
    DISCRIMINATION_Z and some turning point has z_t < z (the reading being z_t u off is likelier than
    that disagreement by chance; a turning point of unknown u counts), the root is contradicted: the
    note says so ("one root: mu_v = 0.52, but mu_M = 1.63 differs by z = 11.9: a root the reading
    cannot show (a turning point of F_V/F_N at mu = 1.45, 2.9 u from the reading) may hold the
    truth"), and as with two roots the next significant estimate whose equation has exactly one root
    and no near turning point drives alpha' instead; failing that, the driven outputs are NaN with
    that reason (the contradicted root is not reported). With no turning point in the bracket the
    ratio is monotone, no other root can hide, and a disagreement is the readings' or the model's,
    not the root's: no check. The returned point's ``note`` says which (empty when the root is
    unique and uncontradicted): a non-unique mu is never resolved silently.
    """
    geometry = StandBGeometry() if geometry is None else geometry
    settings = ReductionSettings() if settings is None else settings
    inputs = input_set(readings, geometry, geometry_u)
    numerators = {
        "mu_v": ("F_V", lambda v: reading_value(v, "F_V", "N")),
        "mu_T": ("F_T", lambda v: reading_value(v, "F_T", "N")),
        "mu_M": ("M_C", lambda v: _pivoting_moment(v, with_inputs(geometry, v))),
    }
    chain = dict(readings=readings, geometry=geometry, coefficients=coefficients)
    point = reduce_stand_point(evaluate, inputs, numerators, GUARDS, DRIVEN, settings, **chain)
    drivers = significant_drivers(inputs, numerators, settings.significance)[0]
    driver = point.driver or next(iter(drivers), "")
    if not driver:
        return dataclasses.replace(point, note="")

    def roots_of(name: str) -> DriverRoots:
        return driver_roots(inputs, name, readings=readings, geometry=geometry, coefficients=coefficients,
                            settings=settings)

    found = roots_of(driver)
    roots = found.candidates

    def another_drives(head: str) -> tuple[ReducedPoint | None, list[str]]:
        """(the point driven by the first other significant estimate whose equation has exactly one
        root and no turning point within ``significance`` u of its reading, noted, or None; why the
        others tried could not drive)."""
        why = []
        for other in (name for name in drivers if name != driver):
            other_roots = roots_of(other)
            unique = other_roots.exact
            if len(unique) != 1 or other_roots.near:
                why.append(roots_text(other, other_roots.candidates, other_roots.near) if other_roots.candidates
                           else f"{other}: no root")
                continue
            alternative = reduce_stand_point(evaluate, inputs, numerators, GUARDS, DRIVEN,
                                             dataclasses.replace(settings, mu_start=unique[0]), driver=other,
                                             **chain)
            if alternative.driver == other and math.isfinite(alternative.values[other]):
                return dataclasses.replace(alternative, note=f"{head}; {other} (one root, {unique[0]:.2f}) "
                                           "drives alpha' instead"), why
            why.append(f"{other}: {alternative.reasons.get(other) or 'does not reduce'}")
        return None, why

    if len(found.exact) == 1 and len(roots) == 1 and found.turning and point.driver == driver:
        against = contradictions(point, driver, (name for name in drivers if name != driver))
        # a root hides behind a turning point only if the reading is z_t u off: likelier than a z u
        # disagreement by chance when z_t < z (a turning point of unknown u counts)
        hiding = {mu: z for mu, z in found.turning.items() if against and not z >= max(against.values())}
        if not hiding:
            return dataclasses.replace(point, note="")
        head = one_root_text(driver, roots[0], point, against, hiding)
        alternative, why = another_drives(head)
        return alternative or without_driven(point, head, f"{head}; no other estimate can drive alpha' instead "
                                             f"({'; '.join(why) or 'none is significant'})")
    if len(roots) < 2:
        return dataclasses.replace(point, note="")
    head = roots_text(driver, roots, found.near)
    alternative, _ = another_drives(head)
    if alternative is not None:
        return alternative
    at_roots = [reduce_stand_point(evaluate, inputs, numerators, GUARDS, DRIVEN,
                                   dataclasses.replace(settings, mu_start=root), driver=driver, **chain)
                for root in roots]
    return choose_root(driver, roots, at_roots, found.near)


RATIO_OF = {"mu_v": "F_V/F_N", "mu_T": "F_T/F_N", "mu_M": "M_C/(a F_N)"}  # the ratio each estimate inverts


def contradictions(point: ReducedPoint, driver: str, others: Iterable[str]) -> dict[str, float]:
    """{other: z} [1] of the estimates that differ from the driver's at the reduced point by
    z > DISCRIMINATION_Z standard uncertainties of the difference (:func:`_difference_z`)."""
    zs = {other: _difference_z(point, driver, other) for other in others}
    return {other: z for other, z in zs.items() if math.isfinite(z) and z > DISCRIMINATION_Z}


def one_root_text(driver: str, root: float, point: ReducedPoint, against: Mapping[str, float],
                  turning: Mapping[float, float]) -> str:
    """"one root: mu_v = 0.52, but mu_M = 1.62 differs by z = 11.9: a root the reading cannot show (a
    turning point of F_V/F_N at mu = 1.45, 7.8 u from the reading) may hold the truth" [1]: the
    driver's only root, the estimates that contradict it ({name: z}) and the turning points of its
    ratio ({mu: z_t}, z_t NaN when its u is not known)."""
    told = " and ".join(f"{name} = {point.values[name]:.2f} differs by z = {z:.1f}" for name, z in against.items())
    where = ", ".join(f"{mu:.2f}" + (f", {z:.1f} u from the reading" if math.isfinite(z) else " (its u not known)")
                      for mu, z in sorted(turning.items()))
    points = "a turning point" if len(turning) == 1 else "turning points"
    return (f"one root: {driver} = {root:.2f}, but {told}: a root the reading cannot show ({points} of "
            f"{RATIO_OF[driver]} at mu = {where}) may hold the truth")


def without_driven(point: ReducedPoint, note: str, why: str) -> ReducedPoint:
    """The point with alpha', the nu's and every mu NaN for the reason ``why``, noted."""
    values, u, expanded, reasons = (dict(point.values), dict(point.uncertainties), dict(point.expanded),
                                    dict(point.reasons))
    for name in DRIVEN:
        values[name] = u[name] = expanded[name] = math.nan
        reasons[name] = why
    return dataclasses.replace(point, values=values, uncertainties=u, expanded=expanded, reasons=reasons,
                               note=note)


def roots_text(driver: str, roots: tuple[float, ...], near: Mapping[float, float] | None = None) -> str:
    """"two roots: mu_v = 0.28 and 0.60" [1]: two decimals, more (up to six) where two roots would
    read alike ("three roots: mu_v = 0.555, 1.453 and 1.455"); ``near`` {mu: z}: the roots that are
    turning points of the ratio z standard uncertainties from the reading (:func:`driver_roots`),
    named after the list: "two roots: mu_v = 0.55 and 1.45 (turning points of the ratio within u of
    the reading: 1.45 at 1.3 u)"."""
    digits = next((d for d in range(2, 7) if len({f"{r:.{d}f}" for r in roots}) == len(roots)), 6)
    names = ", ".join(f"{r:.{digits}f}" for r in roots[:-1]) + f" and {roots[-1]:.{digits}f}"
    count = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}.get(len(roots), str(len(roots)))
    turning = ", ".join(f"{mu:.{digits}f} at {z:.1f} u" for mu, z in sorted((near or {}).items()))
    return f"{count} roots: {driver} = {names}" + (f" (turning points of the ratio within u of the reading: "
                                                    f"{turning})" if turning else "")


MU_BRACKET = (0.05, 2.0)  # the range of mu searched for roots: stand B's parameter range of mu [1]
DISCRIMINATION_Z = 3.0  # an estimate this many u of the difference away from the root rejects it [1]


def mu_bracket(readings: StandBReadings, geometry: StandBGeometry, coefficients: Coefficients) -> tuple[float, float]:
    """[lo, hi] of mu [1] scanned for roots: MU_BRACKET, cut to the law's alpha' domain when the
    coefficients state one (``coefficients.domain.alpha``, rig.stands.contact_law.LawCoefficients)."""
    lo, hi = MU_BRACKET
    domain = getattr(coefficients, "domain", None)
    if domain is not None:
        per_mu = eq.alpha_prime_line_contact(1.0, readings.b_over_a, geometry.spin_radius, geometry.radius_x)
        lo, hi = max(lo, domain.alpha[0] / per_mu), min(hi, domain.alpha[1] / per_mu)
    return lo, hi


@dataclass(frozen=True)
class DriverRoots:
    """The roots of a driver's equation in the bracket: ``exact`` [1], the fixed points at the
    nominal readings, and ``turning`` {mu [1]: z [1]}, every turning point of its ratio with the
    number of its standard uncertainties by which the reading misses it (NaN: u not known), where a
    root could hide behind a reading that far off; those missed by z <= ``significance`` [1] are
    ``near`` (the readings cannot exclude mu there)."""

    exact: tuple[float, ...]
    turning: dict[float, float] = dataclasses.field(default_factory=dict)
    significance: float = 0.0

    @property
    def near(self) -> dict[float, float]:
        """{mu [1]: z [1]} of the turning points the reading misses by z <= significance (NaN never)."""
        return {mu: z for mu, z in self.turning.items() if z <= self.significance}

    @property
    def candidates(self) -> tuple[float, ...]:
        """Every mu [1] the reading allows, ascending."""
        return tuple(sorted((*self.exact, *self.near)))


def driver_roots(inputs: InputSet, driver: str, *, readings: StandBReadings, geometry: StandBGeometry,
                 coefficients: Coefficients, settings: ReductionSettings) -> DriverRoots:
    """Every mu [1] in :func:`mu_bracket` with mu = the driver's estimate at alpha'(mu) (eq. 21 with
    eq. 33 for mu_v, 27 for mu_T, 26 for mu_M), at the nominal input values (rig.reduction.roots),
    and every turning point of the driver's ratio (a peak, a trough) that the reading misses by at
    most ``settings.significance`` standard uncertainties: z = |ln(g/mu)| / u(ln g) at that mu, u
    from a first-order propagation of the inputs at fixed alpha' (with the contact model's
    numerical error there when the coefficients state one, rig.reduction.coefficients). Near a trough of F_V/F_N a
    reading a fraction of its u lower has only the root far off: without this that root would be
    reported as unique. Every turning point with its z is returned as well (``turning``)."""
    nominal = inputs.mapping(inputs.values)
    chain = dict(readings=readings, geometry=geometry, coefficients=coefficients, settings=settings)
    out, alpha_per_mu, state_at = chain_at(nominal, **chain)
    lo, hi = mu_bracket(readings, geometry, coefficients)
    if not lo < hi:
        return DriverRoots(())
    found = scan(lambda mu: state_at(mu)[0][driver], lo, hi)
    error_at = getattr(coefficients, "numerical_error", None)
    every = {}
    for turning in found.turning_points:
        def log_estimate(values: Mapping[str, float], mu: float = turning.mu) -> dict[str, float]:
            g = chain_at(values, **chain)[2](mu)[0][driver]
            return {"ln_g": math.log(g) if math.isfinite(g) and g > 0.0 else math.nan}

        at = inputs  # plus the contact model's numerical error there, as in the reduction's budget
        if error_at is not None:
            at = with_model_error(inputs, error_at(out["l_over_a"], out["c_over_a"], alpha_per_mu * turning.mu))
        u = float(first_order(log_estimate, at, ("ln_g",)).uncertainties[0])
        z = abs(turning.residual) / u if u > 0.0 else math.inf
        every[turning.mu] = z  # NaN (no u) is never near: the scan's roots stand alone
    return DriverRoots(found.roots, every, settings.significance)


def _difference_z(point: ReducedPoint, driver: str, other: str) -> float:
    """|mu_other - mu_driver| over the standard uncertainty of the difference [1] (their covariance
    from the point's first-order propagation); NaN when either is not reported."""
    prop = point.propagation
    names = prop.output_names
    i, j = names.index(driver), names.index(other)
    a, b = point.values[driver], point.values[other]
    var = prop.covariance[i, i] + prop.covariance[j, j] - 2.0 * prop.covariance[i, j]
    if not (math.isfinite(a) and math.isfinite(b) and math.isfinite(var) and var > 0.0):
        return math.nan
    return abs(b - a) / math.sqrt(var)


def choose_root(driver: str, roots: tuple[float, ...], points: list[ReducedPoint],
                near: Mapping[float, float] | None = None) -> ReducedPoint:
    """The reduced point at the one root the other friction estimates agree with, or NaN naming the roots.

    At a root mu_r of the driver's equation, the other estimates (mu_T from F_T, mu_M from M_C)
    computed with the coefficients at alpha'(mu_r) equal mu_r only if mu_r is the contact's mu
    (each reading is mu nu(alpha'(mu)) with its own coefficient). A root is rejected when some
    other estimate differs from it by more than DISCRIMINATION_Z standard uncertainties of the
    difference; exactly one root not rejected, with every other one rejected, is chosen. A turning
    point in ``near`` ({mu: z}, :func:`driver_roots`) is no fixed point: it is never chosen and
    rejects nothing. Otherwise the driven outputs are NaN with the reason "two roots: mu_v =
    0.28 and 0.60 ...".
    """
    head = roots_text(driver, roots, near)
    verdicts, words = [], []
    for root, point in zip(roots, points):
        if root in (near or {}):
            verdicts.append(None)  # no fixed point: the iteration started there ends elsewhere
            words.append(f"at {root:.2f} a turning point, not a fixed point")
            continue
        zs = {other: _difference_z(point, driver, other) for other in MU_ORDER if other != driver}
        zs = {k: z for k, z in zs.items() if math.isfinite(z)}
        if not math.isfinite(point.values[driver]):
            verdicts.append(None)
            words.append(f"at {root:.2f} the point does not reduce ({point.reasons.get(driver, 'no value')})")
            continue
        verdicts.append(bool(zs) and max(zs.values()) > DISCRIMINATION_Z)
        told = ", ".join(f"{k} z = {z:.1f}" for k, z in zs.items()) or "no other estimate"
        words.append(f"at {root:.2f}: {told}")
    evidence = "; ".join(words)
    kept = [k for k, v in enumerate(verdicts) if v is False]
    if len(kept) == 1 and all(v is True or v is None for k, v in enumerate(verdicts) if k != kept[0]) and \
            any(v is True for v in verdicts):
        chosen = points[kept[0]]
        return dataclasses.replace(chosen, note=f"{head}; chose {roots[kept[0]]:.2f}, the root the other "
                                   f"estimates agree with (reject at z > {DISCRIMINATION_Z:g}: {evidence})")
    why = (f"{head} (the ratio is not monotone in mu, eqs. 33-35 with alpha'(mu), eq. 21); the other estimates "
           f"do not tell them apart ({evidence})")
    return without_driven(points[0], head, why)
