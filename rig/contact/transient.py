"""Transient rolling contact: the kinematic law of friction step by step along a rolling path.

The steady law (rig.contact.models.kinematic) assumes constant rolling; it does not hold when the
rolling speed reverses (oscillating drives, start-up; hard case 7). Here the surface
displacement field is carried with the actual motion of the material: in a step the material
rolls the signed distance d (units of a) through the contact, so the point now at x was at
x - d, and the slip *displacement* of the step is

    sigma = Delta s_g + U^k (x) - U^(k-1) (x - d) + (Psi - 1) v_el |d| q^k

with the same Coulomb law as the steady model (q opposes sigma where it slips, |q| <= r); the last
term is the plastic self slip of eq. (25) over the distance rolled (rig.contact.effects.plastic_slip).
Coulomb friction is rate independent, so only distances enter: standstill is d = 0, reversal is
d < 0 (the material then arrives from the x > b side). The step carries the displacement by linear
interpolation, a first-order transport: at constant rolling the transient solution converges to
the steady model's as the grid is refined (tests/contact/test_transient.py). Each step is a static
frictional problem with the influence operator K itself (no upwind difference), solved with the
same semi-smooth Newton-Krylov solver.

Effects: plastic slip (psi) and static friction (static_ratio, with the stick state carried by
the material) as in the steady model; surface inertia needs a time scale and is not available.
Frictional work ([Oscillating], eq. 16: W = mu u p) is an optional output accumulated on the material
(``frictional_work=True``; off: not computed).

Dimensionless units as the steady model: lengths in a, traction in mu p0, displacements and slip
displacements in mu p0 a/G, frictional work density in (mu p0)^2 a/G.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.contact.effects import ContactEffects
from rig.contact.grid import SHAPES, make_grid
from rig.contact.influence import influence_operator
from rig.contact.kalker import B_OVER_A_RANGE
from rig.contact.kinematics import Creepage
from rig.contact import newton
from rig.contact.elastic_law import ElasticLaw
from rig.contact.newton import STICK_MARGIN
from rig.contact.solve import DEFAULT_N, N_RANGE
from rig.errors import ParameterError

TRANSIENT_EFFECTS = ("psi", "static_ratio")


@dataclass(frozen=True)
class RollingPath:
    """A sequence of rolling steps.

    distance: (K,) signed rolled distance of each step [a] (positive: material moves in +x);
    slip: (K, 3) rigid-slip displacement of each step in elastic units (mu p0 a/G):
    (d_xi, d_eta, d_psi) with Delta s_g(X, Y) = (d_xi - d_psi Y, d_eta + d_psi X).
    """

    distance: np.ndarray
    slip: np.ndarray

    @classmethod
    def rolling(cls, creepage: Creepage, distances: np.ndarray) -> RollingPath:
        """Rolling with rigid slip proportional to the rolled distance: the spin and the centre
        slip follow the rolling speed (a rolling point fixed on the contact, as on stand B).

        creepage: rigid slip per unit rolled distance (Creepage, elastic units);
        distances: (K,) signed rolled distances of the steps [a].
        """
        d = np.asarray(distances, dtype=float)
        return cls(d, d[:, None] * np.array([creepage.xi, creepage.eta, creepage.phi])[None, :])

    @classmethod
    def oscillation(cls, creepage: Creepage, stroke: float, cycles: float, step: float) -> RollingPath:
        """Oscillation of the rolled position between -stroke/2 and +stroke/2, starting at 0.

        stroke: peak-to-peak rolled distance x [a] ([Oscillating]: e = x/2b); cycles: number of
        periods; step: largest rolled distance of one step [a]. Coulomb friction is rate
        independent, so only the sequence of positions matters, not how fast they are passed:
        the positions are stepped uniformly (a triangle wave), whatever the drive's time law.
        """
        stroke = validate.number("stroke", stroke, 0.0)
        cycles = validate.number("cycles", cycles, 0.0, lo_open=True)
        step = validate.number("step", step, 0.0, lo_open=True)
        count = max(int(np.ceil(2.0 * stroke * cycles / step)), 8)
        phase = np.linspace(0.0, cycles, count + 1)
        position = stroke * (np.abs(((phase + 0.25) % 1.0) - 0.5) - 0.25) * 2.0
        return cls.rolling(creepage, np.diff(position))

    def positions(self) -> np.ndarray:
        """Cumulative rolled distance after each step [a]."""
        return np.cumsum(self.distance)


@dataclass(frozen=True)
class WorkMap:
    """Frictional work and slip paths accumulated on the material, per material cell.

    x: material coordinate [a] of each column (material at x when the path starts), y [a];
    work: sum over steps of |q . sigma| [(mu p0)^2 a/G] (eq. 16, W = mu u p);
    path_lengthwise, path_crosswise: sums of |sigma_x|, |sigma_y| [mu p0 a/G] ([Oscillating] eqs. 17-18);
    path: sum of |sigma| (eq. 20).
    """

    x: np.ndarray
    y: np.ndarray
    work: np.ndarray
    path_lengthwise: np.ndarray
    path_crosswise: np.ndarray
    path: np.ndarray


@dataclass(frozen=True)
class TransientResult:
    """Per-step force coefficients and the final state of a transient solve.

    nu_T, nu_v, nu_Mo, stick_fraction: (K,) after each step (definitions as ContactResult);
    traction: final (2, N) [mu p0]; work: WorkMap if frictional work was requested, else None.
    """

    nu_T: np.ndarray
    nu_v: np.ndarray
    nu_Mo: np.ndarray
    stick_fraction: np.ndarray
    traction: np.ndarray
    work: WorkMap | None
    newton_iterations: int


def solve_transient(
    *,
    shape: str,
    b_over_a: float,
    poisson: float,
    path: RollingPath,
    n: int | None = None,
    frictional_work: bool = False,
    work_from_step: int = 0,
    **effects: float,
) -> TransientResult:
    """Follow ``path`` step by step from an unloaded contact (no traction, no displacement).

    frictional_work: accumulate the WorkMap (off: not computed), over the steps from
    ``work_from_step`` on (e.g. skip the first cycle of an oscillation).
    """
    shape = validate.choice("shape", shape, SHAPES)
    beta = validate.number("b_over_a", b_over_a, *B_OVER_A_RANGE)
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    n = DEFAULT_N if n is None else validate.integer("n", n, *N_RANGE)
    validate.known_keys("effect", effects, TRANSIENT_EFFECTS)
    grid = make_grid(shape, beta, n)
    distance = np.asarray(path.distance, dtype=float)
    slip = np.asarray(path.slip, dtype=float)
    if distance.ndim != 1 or slip.shape != (distance.size, 3) or not np.all(np.isfinite(slip)):
        raise ParameterError("path", f"{distance.shape} steps, slip {slip.shape}", "K steps with (K, 3) finite slip")
    too_long = np.flatnonzero(~(np.abs(distance) <= grid.hx * (1 + 1e-12)))
    if too_long.size:
        k = int(too_long[0])
        raise ParameterError(f"path.distance[{k}]", float(distance[k]), f"|d| <= cell length {grid.hx:g} a (finer steps)")
    work_from_step = validate.integer("work_from_step", work_from_step, 0, max(distance.size - 1, 0))
    built = ContactEffects.from_keywords(**effects)
    return _Stepper(grid, nu, built, frictional_work).run(distance, slip, work_from_step)


class _Stepper:
    """State carried from step to step: displacement field, traction, stick state, work maps."""

    def __init__(self, grid, poisson, effects: ContactEffects, frictional_work: bool) -> None:
        self.grid = grid
        op = influence_operator(grid, poisson)
        # a step carries no transport: the slip displacement takes the displacement at the cell itself
        self.law = ElasticLaw(grid, op, np.ones((1, grid.index.size)))
        self.plastic_rate = effects.plastic_rate(poisson)
        self.static = effects.static_friction
        self.rho = 1.0 / op.self_term[0]
        self.x, self.y = grid.centres()
        self.p = grid.gather(grid.p)
        self.index = grid.index
        self.columns, self.rows = np.divmod(self.index, grid.ny)
        self.frictional_work = frictional_work

    def carried(self, t: np.ndarray) -> np.ndarray:
        """The elastic displacement U on the full rectangle (2, cells) for tractions t at the cells."""
        return self.law.displacement(t).reshape(2, -1)

    def shifted(self, full: np.ndarray, d: float) -> np.ndarray:
        """full (..., cells) sampled at x - d for each active cell (linear interpolation, |d| <= hx)."""
        f = d / self.grid.hx
        neighbour = self.index - self.grid.ny * int(np.sign(f))
        return (1.0 - abs(f)) * full[..., self.index] + abs(f) * full[..., neighbour]

    def run(self, distance: np.ndarray, slip: np.ndarray, work_from_step: int) -> TransientResult:
        grid, n_cells = self.grid, self.index.size
        t = np.zeros((2, n_cells))
        carried = np.zeros((2, grid.p.size))
        stuck = np.ones(grid.p.size)  # material outside the contact arrives sticking
        steps = distance.size
        out = {k: np.zeros(steps) for k in ("nu_T", "nu_v", "nu_Mo", "stick_fraction")}
        work = _WorkAccumulator(grid, distance) if self.frictional_work else None
        newton_total = 0
        load = self.p.sum()
        for k in range(steps):
            d = float(distance[k])
            d_xi, d_eta, d_psi = slip[k]
            s0 = np.stack(np.broadcast_arrays(d_xi - d_psi * self.y, d_eta + d_psi * self.x)) - self.shifted(carried, d)
            if self.static is None:
                r = self.p
            else:
                r = self.static.bound(self.p, self.shifted(stuck, d) >= 0.5)

            plastic = self.plastic_rate * abs(d)  # eq. (25): plastic slip per distance rolled
            step_law = dataclasses.replace(self.law, plastic_rate=plastic)
            t, its, _ = newton.solve(step_law, s0, r, self.rho, t)
            newton_total += its
            now = self.carried(t)
            sigma = s0 + now[:, self.index] + plastic * t
            stick = np.hypot(t[0], t[1]) < r * (1.0 - STICK_MARGIN)
            carried = now
            stuck = np.ones(grid.p.size)
            stuck[self.index] = stick
            out["nu_T"][k] = t[0].sum() / load
            out["nu_v"][k] = t[1].sum() / load
            out["nu_Mo"][k] = np.sum(self.x * t[1] - self.y * t[0]) / load
            out["stick_fraction"][k] = stick.mean()
            if work is not None and k >= work_from_step:
                work.add(k, self.columns, self.rows, t, np.where(stick, 0.0, sigma))
        return TransientResult(**out, traction=t, work=None if work is None else work.result(),
                               newton_iterations=newton_total)


class _WorkAccumulator:
    """Adds per-step frictional work and slip paths to the material columns the contact cells
    cover, splitting each increment linearly between the two nearest columns (the contact moves
    by fractions of a cell, so nearest-column binning would alias)."""

    def __init__(self, grid, distance: np.ndarray) -> None:
        self.grid = grid
        self.shift = np.cumsum(distance) / grid.hx  # material column offset after each step [cells]
        lo = int(np.floor(min(self.shift.min(), 0.0))) - 1
        hi = int(np.ceil(max(self.shift.max(), 0.0))) + 1
        self.offset = -lo
        self.maps = np.zeros((4, grid.full_shape[0] + hi - lo, grid.ny))
        self.x0 = grid.x[0] + lo * grid.hx

    def add(self, k: int, columns: np.ndarray, rows: np.ndarray, q: np.ndarray, sigma: np.ndarray) -> None:
        position = columns - self.shift[k] + self.offset
        left = np.floor(position).astype(int)
        weight = position - left
        increments = np.stack([np.abs(np.sum(q * sigma, axis=0)), np.abs(sigma[0]), np.abs(sigma[1]),
                               np.hypot(sigma[0], sigma[1])])
        for m in range(4):
            np.add.at(self.maps[m], (left, rows), (1.0 - weight) * increments[m])
            np.add.at(self.maps[m], (left + 1, rows), weight * increments[m])

    def result(self) -> WorkMap:
        x = self.x0 + self.grid.hx * np.arange(self.maps.shape[1])
        return WorkMap(x, self.grid.y.copy(), *self.maps)
