"""The contact law inside the stands: the model called directly or through a surrogate table,
and the signed physical wrapper that maps a wheel pair's state onto the model's canonical case.

    law = make_contact_law(spec, "line", b_over_a=1.0, domain=TableDomain((-1.5, 1.5), (0, 0.9), (0.3, 3)))
    nu_T, nu_v, nu_0 = law(l_over_a, c_over_a, alpha)            # canonical: material in +x, w0 > 0
    values, jacobian = law.derivatives(l_over_a, c_over_a, alpha)  # d/d(l/a, c/a, alpha')
    f = contact_forces(law, patch, speed=v, spin=w0, c=c, l=l, jacobian=True)

The scene chooses (ContactSpec.surrogate): a :class:`TableLaw` (rig.contact.surrogate, cached on
disk) or a :class:`DirectLaw` (one ``solve`` per state; derivatives by central differences).

**Signed states and mirror symmetries** (derived here; tests/stands/test_contact_law.py checks
them against the rigid model and solve_creepage). The model solves one canonical case: material
flows through the contact in +x (v > 0) and the rigid slip is a rotation w0 > 0 about C = (c, l),
s_g = w0 (-(y - l), x - c) (Equations §1.1). The Hertz pressure is symmetric in x and in y.
* Mirror y (y -> -y) maps rotation w0 about (c, l) to rotation -w0 about (c, -l); the flow
  direction is kept. So w0 < 0 with v > 0 is the canonical problem at (c, -l) with F_y and every
  moment negated (as rig.contact.physical.mirror_y).
* Mirror x (x -> -x) reverses the flow, **and** - a reflection - the sense of rotation: v < 0
  with spin w0 about (c, l) is the flow-(+x) problem with spin -w0 about (-c, l), with F_x and
  the moments negated.
Hence, with s_v = sign(v) (+1 at v = 0) and s_y = sign(s_v w0): canonical rolling point
(s_v c, s_y l), and F_x = s_v F_x', F_y = s_y F_y', M = s_v s_y M'. For v < 0 < w0 both
mirrors apply: the half-turn about z (F -> -F, M kept). A rule that flipped w0 only for w0 < 0
and c only for v < 0, independently, would get the case v < 0, w0 < 0 wrong (test).

Hard cases (decided): v -> 0 is alpha' -> 0, rigid sliding, finite (the table's bridge to
alpha' = 0, or solve at alpha' = 0); w0 = 0 puts the rolling point at infinity and makes alpha'
infinite: ParameterError naming ``spin`` (state the slip in creepages, rig.contact.solve.solve_creepage);
a small w0 with a table law ends in the domain error for alpha'. NaN input raises; no NaN is
returned.
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rig import validate
from rig.contact.numerical_error import converged_error
from rig.contact.solve import solve
from rig.contact.surrogate import SurrogateTable, TableDomain, check_model_inputs, table_inputs
from rig.contact.surrogate_cache import CacheOutcome, load_or_build
from rig.errors import ConvergenceError, ParameterError
from rig.reduction.coefficients import OutsideModelDomain
from rig.stands.base import ContactSpec

FD_STEP = 1e-4  # central-difference step of DirectLaw: in l/a, c/a [a] and in log(alpha')
# Below this alpha' the DirectLaw solves alpha' = 0 (rigid sliding; the coefficients differ by
# O(alpha')), because solve's spin creepage 20 (1 - nu)/alpha' overflows to inf near 1e-308.
ALPHA_SLIDING = 1e-12


class ContactLaw(ABC):
    """(nu_T, nu_v, nu_0) of the canonical case (v > 0, w0 > 0) at (l/a, c/a, alpha').

    model, shape, b_over_a, poisson, n, effects: the fixed inputs of ``solve`` (checked);
    rolling_length: f/a of the rolling-resistance effect (0 when off); error_budget: the
    reduction carries the law's numerical error (ContactSpec.error_budget; set by make_contact_law).
    """

    def __init__(self, model: str, shape: str, b_over_a: float, poisson: float, n: int, effects: tuple) -> None:
        self.model, self.shape, self.b_over_a, self.poisson, self.n = model, shape, b_over_a, poisson, n
        self.effects = dict(effects)
        self.rolling_length = float(self.effects.get("rolling_length", 0.0))
        self.error_budget = False

    def __call__(self, l_over_a, c_over_a, alpha):
        """(nu_T, nu_v, nu_0) [1], floats for scalar input, else arrays of the broadcast shape."""
        if (type(l_over_a) is float and type(c_over_a) is float and type(alpha) is float) or (
                np.ndim(l_over_a) == 0 and np.ndim(c_over_a) == 0 and np.ndim(alpha) == 0):
            values = self.value_one(float(l_over_a), float(c_over_a), float(alpha))
            return float(values[0]), float(values[1]), float(values[2])
        shape = np.broadcast(l_over_a, c_over_a, alpha).shape
        values = self._values(*_flat(l_over_a, c_over_a, alpha))
        return tuple(values[i].reshape(shape) for i in range(3))

    def derivatives(self, l_over_a, c_over_a, alpha) -> tuple[np.ndarray, np.ndarray]:
        """Values (3, *shape) and Jacobian (3, 3, *shape): d(nu_T, nu_v, nu_0)/d(l/a, c/a, alpha')."""
        shape = np.broadcast(l_over_a, c_over_a, alpha).shape
        values, jac = self._with_derivatives(*_flat(l_over_a, c_over_a, alpha))
        return values.reshape((3,) + shape), jac.reshape((3, 3) + shape)

    def evaluate_one(self, l_over_a: float, c_over_a: float, alpha: float) -> tuple[np.ndarray, np.ndarray]:
        """Values (3,) and Jacobian (3, 3) at one state (the wrapper's scalar path)."""
        values, jac = self._with_derivatives(*_flat(l_over_a, c_over_a, alpha))
        return values[:, 0], jac[:, :, 0]

    def value_one(self, l_over_a: float, c_over_a: float, alpha: float) -> np.ndarray:
        """Values (3,) at one state."""
        return self._values(*_flat(l_over_a, c_over_a, alpha))[:, 0]

    def numerical_error(self, l_over_a: float, c_over_a: float, alpha: float) -> np.ndarray:
        """|nu - converged model| (3,) of nu_T, nu_v, nu_0 [1] at one state: the grid's and the
        table's error together (rig.contact.numerical_error; two direct solves)."""
        fixed = dict(shape=self.shape, b_over_a=self.b_over_a, poisson=self.poisson, **self.effects)
        return converged_error(self.value_one(l_over_a, c_over_a, alpha), self.model, fixed, self.n,
                               (l_over_a, c_over_a, alpha))

    @abstractmethod
    def _values(self, l: np.ndarray, c: np.ndarray, a: np.ndarray) -> np.ndarray:
        """(3, N) at flat arrays."""

    @abstractmethod
    def _with_derivatives(self, l: np.ndarray, c: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(3, N) and (3, 3, N) at flat arrays."""


def _flat(l_over_a, c_over_a, alpha) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (l_over_a, c_over_a, alpha)))
    return tuple(np.ravel(a) for a in arrays)  # type: ignore[return-value]


class DirectLaw(ContactLaw):
    """One ``solve`` per state (no domain limit; alpha' in [0, inf), below ALPHA_SLIDING solved as
    0). Derivatives: central differences with FD_STEP in l/a, c/a and log(alpha') (forward in
    alpha' from alpha' = 0 below ALPHA_SLIDING), 6 extra solves per state; the grid model's
    stick/slip changes make them noisy at O(1/n)."""

    def _solve(self, l: float, c: float, a: float) -> np.ndarray:
        validate.number("l_over_a", l)
        validate.number("c_over_a", c)
        validate.number("alpha", a, 0.0)
        if a < ALPHA_SLIDING:
            a = 0.0
        r = solve(self.model, shape=self.shape, b_over_a=self.b_over_a, alpha=a, c_over_a=c, l_over_a=l,
                  poisson=self.poisson, n=self.n, **self.effects)
        out = np.array([r.nu_T, r.nu_v, r.nu_0])
        if not np.all(np.isfinite(out)):
            raise ConvergenceError(f"{self.model} model returned {out} at l/a = {l:g}, c/a = {c:g}, alpha' = {a:g}")
        return out

    def _values(self, l, c, a):
        """One solve per distinct state, in order (a quasi-static gate asks for its one steady state
        at every sample, e.g. 251 times; the solve is deterministic, so each copy is the same)."""
        solved: dict[tuple[str, str, str], np.ndarray] = {}
        out = np.empty((l.size, 3))
        for k, state in enumerate(zip(l.tolist(), c.tolist(), a.tolist())):
            key = tuple(map(float.hex, state))  # bit-exact (0.0 and -0.0 differ)
            found = solved.get(key)
            if found is None:
                found = solved[key] = self._solve(*state)
            out[k] = found
        return out.T

    def _with_derivatives(self, l, c, a):
        values = self._values(l, c, a)
        jac = np.empty((3, 3, l.size))
        h = FD_STEP
        for k, (li, ci, ai) in enumerate(zip(l, c, a)):
            jac[:, 0, k] = (self._solve(li + h, ci, ai) - self._solve(li - h, ci, ai)) / (2 * h)
            jac[:, 1, k] = (self._solve(li, ci + h, ai) - self._solve(li, ci - h, ai)) / (2 * h)
            if ai > ALPHA_SLIDING:
                up, down = ai * math.exp(h), ai * math.exp(-h)
                jac[:, 2, k] = (self._solve(li, ci, up) - self._solve(li, ci, down)) / (up - down)
            else:
                jac[:, 2, k] = (self._solve(li, ci, h) - values[:, k]) / h
        return values, jac


class TableLaw(ContactLaw):
    """Evaluated through a SurrogateTable (its domain applies); cache: how the table was obtained."""

    def __init__(self, table: SurrogateTable, cache: CacheOutcome | None = None) -> None:
        i = table.inputs
        super().__init__(i.model, i.shape, i.b_over_a, i.poisson, i.n, i.effects)
        self.table = table
        self.cache = cache

    def _values(self, l, c, a):
        return self.table.evaluate(l, c, a)[0]

    def _with_derivatives(self, l, c, a):
        return self.table.evaluate(l, c, a)

    def evaluate_one(self, l_over_a, c_over_a, alpha):
        return self.table.evaluate_one(l_over_a, c_over_a, alpha)

    def value_one(self, l_over_a, c_over_a, alpha):
        return self.table.value_one(l_over_a, c_over_a, alpha)


def make_contact_law(
    spec: ContactSpec,
    shape: str,
    b_over_a: float,
    domain: TableDomain | None,
    *,
    cache_directory: Path | None = None,
    progress: Callable[[int, int], None] | None = None,
    workers: int = 1,
) -> ContactLaw:
    """The scene's contact law: a TableLaw (spec.surrogate; built once, cached in cache_directory
    or rig.contact.surrogate_cache.cache_dir()) or a DirectLaw.

    domain: the table's (l/a, c/a, alpha') ranges in the canonical frame (required for a table;
    any object with l_over_a, c_over_a, alpha pairs is accepted; ignored by DirectLaw).
    progress(done, total) and workers go to the table build.
    """
    if not isinstance(spec, ContactSpec):
        raise ParameterError("spec", spec, "a rig.stands.base.ContactSpec")
    law = _law(spec, shape, b_over_a, domain, cache_directory, progress, workers)
    law.error_budget = spec.error_budget
    return law


def _law(spec, shape, b_over_a, domain, cache_directory, progress, workers) -> ContactLaw:
    """make_contact_law's law, before its error budget is set."""
    if not spec.surrogate:
        return DirectLaw(*check_model_inputs(spec.model, shape, b_over_a, spec.poisson, spec.n, spec.effects))
    if domain is None:
        raise ParameterError("domain", None, "a TableDomain (l/a, c/a, alpha' ranges) for a surrogate table")
    if not isinstance(domain, TableDomain):
        domain = TableDomain(tuple(domain.l_over_a), tuple(domain.c_over_a), tuple(domain.alpha))
    inputs = table_inputs(spec.model, shape=shape, b_over_a=b_over_a, poisson=spec.poisson, n=spec.n,
                          effects=dict(spec.effects), domain=domain, points=tuple(spec.table_points))
    table, outcome = load_or_build(inputs, directory=cache_directory, progress=progress, workers=workers)
    return TableLaw(table, outcome)


class LawCoefficients:
    """A stand's law as the reduction asks it: coefficients(l/a, c/a, alpha') -> (nu_T, nu_v, nu_0)
    as floats, OutsideModelDomain (naming the coordinate and the domain) outside ``domain``.

    numerical_error(l/a, c/a, alpha') -> (3,) [1], the law's error against the converged model
    there, is offered when the law carries an error budget (the scene's [contact] error_budget);
    it is None otherwise, and the reduction adds no component.
    """

    def __init__(self, law, domain: TableDomain) -> None:
        self.law = law
        self.domain = domain
        self.numerical_error = law.numerical_error if getattr(law, "error_budget", False) else None

    def __call__(self, l_over_a: float, c_over_a: float, alpha: float) -> tuple[float, float, float]:
        d = self.domain
        if not (d.l_over_a[0] <= l_over_a <= d.l_over_a[1] and d.c_over_a[0] <= c_over_a <= d.c_over_a[1]
                and d.alpha[0] <= alpha <= d.alpha[1]):
            for name, x, (lo, hi) in (("l/a", l_over_a, d.l_over_a), ("c/a", c_over_a, d.c_over_a),
                                      ("alpha'", alpha, d.alpha)):
                if not lo <= x <= hi:
                    raise OutsideModelDomain(name, x, f"[{lo:.6g}, {hi:.6g}], the domain of the stand's contact law",
                                             hint="the rolling point or alpha' left the table (hard case 6)")
        nu = self.law(float(l_over_a), float(c_over_a), float(alpha))
        if isinstance(self.law, ContactLaw):  # its scalar path gives three floats
            return nu
        return tuple(float(x) for x in np.asarray(nu, dtype=float).reshape(3))


@dataclass(frozen=True)
class ContactPatch:
    """Hertz contact and friction of a wheel pair (constant over an operating point).

    mu: friction coefficient [1]; normal_force_N: F_N [N]; a_m: half length a along the contact
    line [m]; p0_Pa: maximum Hertz pressure [Pa]; modulus_Pa: substitute modulus E of eq. (22) [Pa].
    """

    mu: float
    normal_force_N: float
    a_m: float
    p0_Pa: float
    modulus_Pa: float

    def __post_init__(self) -> None:
        for name in ("mu", "normal_force_N", "a_m", "p0_Pa", "modulus_Pa"):
            object.__setattr__(self, name, validate.number(name, getattr(self, name), 0.0, lo_open=True))

    @property
    def alpha_per_length(self) -> float:
        """K = 40 mu p0/(a E) [1/m], so that alpha' = K |v/w0| (eq. 21)."""
        return 40.0 * self.mu * self.p0_Pa / (self.a_m * self.modulus_Pa)


@dataclass(frozen=True)
class ContactForces:
    """Contact forces on body 1 for a signed state, in the stand's (unmirrored) frame.

    force_x_N, force_y_N: F_x, F_y [N] (eqs. 27-28); moment_C_N_m: moment about the rolling
    point C = (c + sign(v) f, l) [N m] (f: rolling length, 0 when off); moment_O_N_m: about the
    contact centre [N m]; friction_power_W: P_t = mu a F_N |w0| nu_0 >= 0 [W] (eq. 26);
    nu_T, nu_v: F_x, F_y/(mu F_N) [1]; nu_0: |M_C|/(mu a F_N) [1]; alpha_prime: eq. (21) [1];
    jacobian: None, or (4, 4) d(F_x [N], F_y [N], M_C [N m], M_O [N m])/d(v [m/s], w0 [rad/s],
    c [m], l [m]) (at v = 0 the right-hand derivative in v: alpha' has a kink |v| there).
    """

    force_x_N: float
    force_y_N: float
    moment_C_N_m: float
    moment_O_N_m: float
    friction_power_W: float
    nu_T: float
    nu_v: float
    nu_0: float
    alpha_prime: float
    jacobian: np.ndarray | None = None


def _finite(name: str, value: float) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        x = math.nan
    if not math.isfinite(x) or isinstance(value, bool):
        raise ParameterError(name, value, "a finite number")
    return x


def contact_forces(
    law: ContactLaw, patch: ContactPatch, *, speed: float, spin: float, c: float, l: float, jacobian: bool = False
) -> ContactForces:
    """Forces and moments on body 1 from a signed wheel-pair state (module docstring: mirrors).

    speed: rolling speed v [m/s], signed (+ = material moves through the contact in +x);
    spin: w0 [rad/s], signed, non-zero; c, l: rolling point [m] across / along the contact line.
    """
    v = _finite("speed", speed)
    w0 = _finite("spin", spin)
    c = _finite("c", c)
    l = _finite("l", l)
    if w0 == 0.0:
        raise ParameterError("spin", spin, "non-zero [rad/s]",
                             hint="zero spin puts the rolling point at infinity; use creepages (solve_creepage)")
    s_v = -1.0 if v < 0.0 else 1.0
    s_y = 1.0 if s_v * w0 > 0.0 else -1.0
    a = patch.a_m
    k_alpha = patch.alpha_per_length
    alpha = k_alpha * abs(v) / abs(w0)
    try:
        if jacobian:
            nu, jac = law.evaluate_one(s_y * l / a, s_v * c / a, alpha)
        else:
            nu = law.value_one(s_y * l / a, s_v * c / a, alpha)
    except ParameterError as error:
        raise ParameterError(error.name, error.value, error.valid, hint=(
            f"outside the law's domain: state v = {v:g} m/s, w0 = {w0:g} rad/s, c = {c:g} m, l = {l:g} m "
            f"maps to the canonical l/a = {s_y * l / a:g}, c/a = {s_v * c / a:g}, alpha' = {alpha:g}")) from error
    nu_t, nu_v, nu_0 = nu.tolist()
    mu_f = patch.mu * patch.normal_force_N
    f = law.rolling_length * a
    fx, fy, mc = mu_f * nu_t, mu_f * nu_v, -mu_f * a * nu_0  # canonical frame, eqs. (26)-(28)
    c_can, l_can = s_v * c, s_y * l
    mo = mc + (c_can + f) * fy - l_can * fx  # M_C = M_O - c F_y + l F_x (Equations §1.1)
    flip = s_v * s_y
    matrix = None
    if jacobian:
        dz = np.array([[0.0, 0.0, 0.0, s_y / a], [0.0, 0.0, s_v / a, 0.0],
                       [k_alpha * s_v / abs(w0), -alpha / w0, 0.0, 0.0]])  # d(l'/a, c'/a, alpha')/d(v, w0, c, l)
        dnu = jac @ dz
        dfx, dfy, dmc = mu_f * dnu[0], mu_f * dnu[1], -mu_f * a * dnu[2]
        dmo = dmc + (c_can + f) * dfy - l_can * dfx + np.array([0.0, 0.0, s_v * fy, -s_y * fx])
        matrix = np.stack([s_v * dfx, s_y * dfy, flip * dmc, flip * dmo])
    return ContactForces(
        force_x_N=s_v * fx, force_y_N=s_y * fy, moment_C_N_m=flip * mc, moment_O_N_m=flip * mo,
        friction_power_W=mu_f * a * abs(w0) * nu_0, nu_T=s_v * nu_t, nu_v=s_y * nu_v, nu_0=nu_0,
        alpha_prime=alpha, jacobian=matrix,
    )
