"""The contact laws of stand A: one per b/a (load) over a domain chosen for the stand, shared by
the simulation and the reduction (so both evaluate exactly the same function).

Domain [our choice, docs/stand-a.md]:
* l/a in [-L_MAX, L_MAX], L_MAX = 2.5: the brake sweep covers about -1 .. +1, with margin; the
  start-up transient (C at A1, l/a ~ 35) is continued outside (rig.stands.yoke.contact_forces);
* c/a in [0, max(C_MIN, Delta h/a)]: c = Delta h (l1 - l)/(l1 - l2) lies in [0, Delta h) for
  forward running (eq. 32); C_MIN = 0.9 lets Delta h = 0 and 1.06 mm (a = 1.215 mm) share a table;
* alpha' (eq. 21, line contact) over mu in [MU_MIN, MU_MAX] and the l range, widened by
  ALPHA_MARGIN at both ends: the reduction's mu <-> alpha' iteration and its perturbed
  evaluations must stay inside it; the simulation's mu must lie in [MU_MIN, MU_MAX].
"""

from __future__ import annotations

from collections.abc import Callable

from rig.errors import ParameterError
from rig.reduction.equations import alpha_prime_line_contact
from rig.reduction.geometry import StandAGeometry
from rig.stands.base import ContactSpec
from rig.contact.surrogate import TableDomain
from rig.stands.yoke.contact_forces import Law

L_MAX = 2.5  # [1]
C_MIN = 0.9  # [1]
MU_MIN, MU_MAX = 0.1, 1.2  # a-priori range of friction coefficients of the pair [1] (assumed)
ALPHA_MARGIN = 1.5  # the alpha' domain reaches this factor past the range's ends: a reduction at mu = MU_MIN
# or MU_MAX perturbs its inputs (first-order uncertainties) and moves alpha' by ~15 % (issue 14) [1]
SHAPE = "line"  # stand A: line contact ([Koziarski] section 3.1: "Linear contact was applied")

LawFactory = Callable[[ContactSpec, str, float, TableDomain], Law]


def domain(geometry: StandAGeometry, b_over_a: float, mu: float) -> TableDomain:
    """The law's domain for a geometry [m, rad] (its Delta h), b/a [1] and the simulated mu [1]."""
    if not MU_MIN <= mu <= MU_MAX:
        raise ParameterError("mu", mu, f"[{MU_MIN:g}, {MU_MAX:g}] (the a-priori range of the contact-law tables)")
    g = geometry
    span = g.l1 - g.l2

    def v_over_spin(l: float) -> float:  # v/w0 = l1 (l - l2)/(l1 - l2) [m] (eqs. 29, 30)
        return g.l1 * (l - g.l2) / span

    l_lo = max(-L_MAX * g.a, g.l2 + 0.1 * span)  # forward running has l2 < l < l1
    l_hi = min(L_MAX * g.a, g.l1)
    lo = alpha_prime_line_contact(MU_MIN, b_over_a, v_over_spin(l_lo), g.radius_x) / ALPHA_MARGIN
    hi = alpha_prime_line_contact(MU_MAX, b_over_a, v_over_spin(l_hi), g.radius_x) * ALPHA_MARGIN
    return TableDomain((-L_MAX, L_MAX), (0.0, max(C_MIN, g.delta_h / g.a)), (lo, hi))


def default_factory() -> LawFactory:
    """rig.stands.contact_law.make_contact_law (imported when a stand first needs a law)."""
    from rig.stands.contact_law import make_contact_law

    return make_contact_law


class LawCache:
    """The laws of one ContactSpec, built on first use per (b/a, domain) and kept.

    spec: the scene's ContactSpec; mu: the simulated friction coefficient [1] (checked against
    the tables' range); factory: make_contact_law's signature (None = the real one).
    """

    def __init__(self, spec: ContactSpec, mu: float, factory: LawFactory | None = None) -> None:
        if not isinstance(spec, ContactSpec):
            raise ParameterError("contact", spec, "a rig.stands.base.ContactSpec")
        self.spec = spec
        self.mu = mu
        self.factory = factory
        self._laws: dict[tuple[float, TableDomain], Law] = {}

    def __call__(self, b_over_a: float, geometry: StandAGeometry) -> tuple[Law, TableDomain]:
        """The law for b/a [1] and a geometry [m, rad] (its Delta h), with its domain."""
        where = domain(geometry, b_over_a, self.mu)
        key = (b_over_a, where)
        if key not in self._laws:
            factory = self.factory or default_factory()
            self._laws[key] = factory(self.spec, SHAPE, b_over_a, where)
        return self._laws[key], where
