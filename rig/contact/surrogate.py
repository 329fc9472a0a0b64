"""Surrogate table of a contact model over (l/a, c/a, log alpha'), built once, evaluated fast.

A stand's ODE calls the contact law thousands of times per simulated second; a grid solve costs
10-100 ms. The table samples ``solve`` (nu_T, nu_v, nu_0; eqs. 26-28) for one fixed model, shape,
b/a, Poisson ratio, grid n and effects on a uniform grid of nodes in l/a, c/a and log(alpha')
(alpha' of eq. 21) over a domain the caller chooses, and interpolates it with a tensor-product
not-a-knot cubic spline (rig.contact.tensor_spline): C2, fourth order, exact at the nodes, with
analytic first derivatives for the Jacobian of an implicit integrator.

Why a cubic spline and not a monotone cubic (PCHIP): nu_v has a maximum in alpha' (Equations
§1.10(c)), and PCHIP flattens every extremum of the data to a zero slope, which costs accuracy
exactly there; PCHIP is also only C1 and third order. The laws are smooth and saturating
(|nu| < 1), and on the tables we use the spline's overshoot stays below the measured
interpolation error (docs/stands-contact.md, "Surrogate tables").

Domain (decided, not clamped): the rolling point may lie far outside the contact (hard case 6),
so the caller chooses l/a and c/a ranges and an alpha' range [alpha_lo, alpha_hi] with
alpha_lo > 0. Evaluating outside raises ParameterError naming the coordinate, its value and the
table's range: a clamp would return the force of a different rolling point without telling.
Below alpha_lo, models with a finite rigid-sliding limit (rigid, fastsim, kinematic: alpha' -> 0
is hard case 3) continue to alpha' = 0 through a *bridge*: the table also stores the model's own
alpha' = 0 values (rigid sliding on the model's cells), and for 0 <= alpha' < alpha_lo the law is
the quadratic in alpha' through that value that meets the spline with equal value and slope at
alpha_lo (C1; [R] our construction). The linear model has no sliding limit: below alpha_lo it
raises. The rigid model does not depend on alpha' at all (only the slip direction counts), so
its table is one (l, c) slice repeated.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

import numpy as np

import rig
from rig import validate
from rig.contact.effects import EFFECT_KEYWORDS
from rig.contact.grid import SHAPES, make_grid
from rig.contact.kalker import B_OVER_A_RANGE
from rig.contact.models import rigid
from rig.contact.solve import DEFAULT_N, DISCRETISATION_REVISION, MODEL_EFFECTS, MODELS, N_RANGE, solve
from rig.contact.tensor_spline import MIN_NODES, TensorSpline
from rig.errors import ConvergenceError, ParameterError

TABLE_FORMAT = 1  # bump when the stored arrays or their meaning change (part of the cache key)
SLIDING_MODELS = ("rigid", "fastsim", "kinematic")  # finite alpha' -> 0 limit: bridge to alpha' = 0
OUTPUTS = ("nu_T", "nu_v", "nu_0")
_JACOBIAN_COLUMNS = [4, 2, 1]  # spline derivative index (bits l, c, log alpha') of d/dl, d/dc, d/dlog(alpha')
_CHUNK_ELEMENTS = 2_000_000  # nodes x quadrature points per vectorised rigid-sliding chunk


@dataclass(frozen=True)
class TableDomain:
    """Where a table is valid: l/a, c/a ranges [units of a] and alpha' range (0 < lo < hi < inf).

    l_over_a, c_over_a: rolling point in the model's canonical frame (material flows in +x,
    spin w0 > 0; rig.stands.contact_law maps a signed state onto it). alpha: (lo, hi) of eq. (21).
    """

    l_over_a: tuple[float, float]
    c_over_a: tuple[float, float]
    alpha: tuple[float, float]

    def __post_init__(self) -> None:
        for name in ("l_over_a", "c_over_a", "alpha"):
            pair = getattr(self, name)
            if not isinstance(pair, (tuple, list)) or len(pair) != 2:
                raise ParameterError(name, pair, "a pair (lo, hi) of finite numbers with lo < hi")
            lo_min = 0.0 if name == "alpha" else None
            lo = validate.number(f"{name}[0]", pair[0], lo_min, lo_open=name == "alpha")
            hi = validate.number(f"{name}[1]", pair[1])
            if not hi > lo:
                raise ParameterError(f"{name}[1]", hi, f"> {name}[0] = {lo:g}")
            object.__setattr__(self, name, (lo, hi))


@dataclass(frozen=True)
class TableInputs:
    """Everything a table depends on (and its cache key hashes): use :func:`table_inputs`.

    points: nodes along (l/a, c/a, log alpha'); effects: sorted (keyword, value) pairs.
    """

    model: str
    shape: str
    b_over_a: float
    poisson: float
    n: int
    effects: tuple[tuple[str, float], ...]
    domain: TableDomain
    points: tuple[int, int, int]

    def axes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Node vectors: l/a, c/a [a] and log(alpha') (uniform)."""
        d = self.domain
        return (
            np.linspace(*d.l_over_a, self.points[0]),
            np.linspace(*d.c_over_a, self.points[1]),
            np.linspace(math.log(d.alpha[0]), math.log(d.alpha[1]), self.points[2]),
        )

    def alpha_nodes(self) -> np.ndarray:
        """alpha' at the nodes (exp of the log axis, with the end points exactly as given)."""
        alpha = np.exp(self.axes()[2])
        alpha[0], alpha[-1] = self.domain.alpha
        return alpha

    def description(self) -> dict:
        """JSON-ready description of every input, with the package, table format and grid-model
        (discretisation) revisions: a table built by another solver is never reused."""
        d = self.domain
        return dict(
            table_format=TABLE_FORMAT, package_version=rig.__version__, model=self.model,
            discretisation=DISCRETISATION_REVISION, shape=self.shape,
            b_over_a=self.b_over_a, poisson=self.poisson, n=self.n, effects=[list(e) for e in self.effects],
            l_over_a=list(d.l_over_a), c_over_a=list(d.c_over_a), alpha=list(d.alpha), points=list(self.points),
        )

    def key(self) -> str:
        """SHA-256 (hex) of :meth:`description` (floats written exactly, by repr)."""
        import hashlib

        text = json.dumps(self.description(), sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()


def check_model_inputs(model, shape, b_over_a, poisson, n, effects) -> tuple:
    """The fixed arguments of ``solve``, checked as solve checks them (named errors, suggestions).

    Returns (model, shape, b_over_a, poisson, n, effects) with n resolved (None -> solve's
    default) and effects as sorted (keyword, value) pairs, each supported by the model and in range.
    """
    model = validate.choice("model", model, MODELS)
    shape = validate.choice("shape", shape, SHAPES)
    beta = validate.number("b_over_a", b_over_a, *B_OVER_A_RANGE)
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    n = DEFAULT_N if n is None else validate.integer("n", n, *N_RANGE)
    effects = dict(effects or {})
    validate.known_keys("effect", effects, EFFECT_KEYWORDS)
    pairs = []
    for name, value in sorted(effects.items()):
        if name not in MODEL_EFFECTS[model]:
            raise ParameterError(name, value, f"not available for model {model!r}; it supports {MODEL_EFFECTS[model]}")
        EFFECT_KEYWORDS[name](value)  # the effect's own range check
        pairs.append((name, float(value)))
    return model, shape, beta, nu, n, tuple(pairs)


def table_inputs(
    model: str,
    *,
    shape: str,
    b_over_a: float,
    poisson: float,
    n: int | None,
    effects: dict[str, float] | None,
    domain: TableDomain,
    points: tuple[int, int, int],
) -> TableInputs:
    """Checked :class:`TableInputs`: the arguments of ``solve`` that stay fixed over the table.

    b_over_a [1] in B_OVER_A_RANGE; poisson [1] in [0, 0.5]; n: cells across 2a (None: solve's
    default); effects: solve()'s keywords; points: nodes per axis, each >= 2 (cubic from 4 on).
    """
    fixed = check_model_inputs(model, shape, b_over_a, poisson, n, effects)
    if not isinstance(domain, TableDomain):
        raise ParameterError("domain", domain, "a rig.contact.surrogate.TableDomain")
    if not isinstance(points, (tuple, list)) or len(points) != 3:
        raise ParameterError("points", points, f"three node counts (l/a, c/a, log alpha'), each >= {MIN_NODES}")
    counts = tuple(validate.integer(f"points[{i}]", p, MIN_NODES, 4096) for i, p in enumerate(points))
    return TableInputs(*fixed, domain, counts)  # type: ignore[arg-type]


@dataclass(frozen=True, eq=False)
class SurrogateTable:
    """A built table: node values and its splines.

    values: (n_l, n_c, n_alpha, 3) nu_T, nu_v, nu_0 at the nodes; sliding: (n_l, n_c, 3) the
    alpha' = 0 values for SLIDING_MODELS, else None. Evaluation returns values (3, N) and the
    Jacobian (3, 3, N), d(nu_T, nu_v, nu_0)/d(l/a, c/a, alpha').
    """

    inputs: TableInputs
    values: np.ndarray
    sliding: np.ndarray | None
    _spline: TensorSpline = field(init=False, repr=False)
    _sliding_spline: TensorSpline | None = field(init=False, repr=False)

    def __post_init__(self) -> None:
        axes = self.inputs.axes()
        object.__setattr__(self, "_spline", TensorSpline.fit(list(axes), self.values))
        slide = None if self.sliding is None else TensorSpline.fit(list(axes[:2]), self.sliding)
        object.__setattr__(self, "_sliding_spline", slide)

    def check_domain(self, l_over_a: np.ndarray, c_over_a: np.ndarray, alpha: np.ndarray) -> None:
        """Raise ParameterError for the first coordinate outside the table's domain (or NaN)."""
        d = self.inputs.domain
        alpha_lo = 0.0 if self.sliding is not None else d.alpha[0]
        for name, x, (lo, hi) in (("l_over_a", l_over_a, d.l_over_a), ("c_over_a", c_over_a, d.c_over_a),
                                  ("alpha", alpha, (alpha_lo, d.alpha[1]))):
            bad = ~((x >= lo) & (x <= hi))  # NaN is bad too
            if np.any(bad):
                value = float(np.asarray(x)[bad].flat[0])
                raise ParameterError(
                    name, value, f"[{lo:g}, {hi:g}]",
                    hint="outside the surrogate table's domain (canonical frame v > 0, w0 > 0); widen the TableDomain",
                )

    def evaluate(self, l_over_a, c_over_a, alpha) -> tuple[np.ndarray, np.ndarray]:
        """Values (3, N) and Jacobian (3, 3, N) at arrays (broadcast, flattened) of states."""
        l, c, a = (np.ravel(v).astype(float) for v in np.broadcast_arrays(l_over_a, c_over_a, alpha))
        self.check_domain(l, c, a)
        alpha_lo = self.inputs.domain.alpha[0]
        log_lo = self._spline.starts[2]
        s = np.log(np.maximum(a, alpha_lo))
        s = np.where(a <= alpha_lo, log_lo, s)  # exactly on the first node in and below it
        r = self._spline.evaluate(np.stack([l, c, s]))  # (N, 3, 8): bits (l, c, s)
        values = r[:, :, 0].T.copy()
        jac = np.stack([r[:, :, 4].T, r[:, :, 2].T, r[:, :, 1].T / np.maximum(a, alpha_lo)], axis=1)
        low = a < alpha_lo
        if np.any(low):
            v_low, j_low = self._bridge(r[low], l[low], c[low], a[low])
            values[:, low] = v_low
            jac[:, :, low] = j_low
        return values, jac

    def evaluate_one(self, l_over_a: float, c_over_a: float, alpha: float) -> tuple[np.ndarray, np.ndarray]:
        """As :meth:`evaluate` for one state given as floats; returns (3,) and (3, 3)."""
        d = self.inputs.domain
        alpha_lo = d.alpha[0]
        if not (d.l_over_a[0] <= l_over_a <= d.l_over_a[1] and d.c_over_a[0] <= c_over_a <= d.c_over_a[1]
                and alpha_lo < alpha <= d.alpha[1]):
            values, jac = self.evaluate(l_over_a, c_over_a, alpha)  # the bridge, or a named error
            return values[:, 0], jac[:, :, 0]
        r = self._spline.evaluate_one((l_over_a, c_over_a, math.log(alpha)))
        jac = r[:, _JACOBIAN_COLUMNS]
        jac[:, 2] /= alpha  # d/d(alpha') = d/d(log alpha')/alpha'
        return r[:, 0], jac

    def value_one(self, l_over_a: float, c_over_a: float, alpha: float) -> np.ndarray:
        """Values (3,) at one state given as floats (no Jacobian); alpha' on the domain's lower end (where
        a stand clamps it) is the first node, as in :meth:`evaluate`."""
        d = self.inputs.domain
        if not (d.l_over_a[0] <= l_over_a <= d.l_over_a[1] and d.c_over_a[0] <= c_over_a <= d.c_over_a[1]
                and d.alpha[0] <= alpha <= d.alpha[1]):
            return self.evaluate(l_over_a, c_over_a, alpha)[0][:, 0]
        log_alpha = self._spline.starts[2] if alpha == d.alpha[0] else math.log(alpha)
        return self._spline.value_one((l_over_a, c_over_a, float(log_alpha)))

    def _bridge(self, r: np.ndarray, l: np.ndarray, c: np.ndarray, a: np.ndarray):
        """Quadratic in alpha' on [0, alpha_lo): value f0 at 0, value and slope of the spline at alpha_lo.

        q = f0 (1 - x)^2 + g x (2 - x) + g_s x (x - 1), x = alpha'/alpha_lo, g_s = dg/d(log alpha').
        """
        alpha_lo = self.inputs.domain.alpha[0]
        f0r = self._sliding_spline.evaluate(np.stack([l, c]))  # (M, 3, 4): bits (l, c)
        f0, f0_l, f0_c = f0r[:, :, 0].T, f0r[:, :, 2].T, f0r[:, :, 1].T
        g, g_l, g_c = r[:, :, 0].T, r[:, :, 4].T, r[:, :, 2].T
        g_s, g_ls, g_cs = r[:, :, 1].T, r[:, :, 5].T, r[:, :, 3].T
        x = a / alpha_lo
        w0, w1, w2 = (1.0 - x) ** 2, x * (2.0 - x), x * (x - 1.0)
        values = f0 * w0 + g * w1 + g_s * w2
        d_l = f0_l * w0 + g_l * w1 + g_ls * w2
        d_c = f0_c * w0 + g_c * w1 + g_cs * w2
        d_a = (2.0 * (g - f0) * (1.0 - x) + g_s * (2.0 * x - 1.0)) / alpha_lo
        return values, np.stack([d_l, d_c, d_a], axis=1)


def build_table(
    inputs: TableInputs, *, progress: Callable[[int, int], None] | None = None, workers: int = 1
) -> SurrogateTable:
    """Solve the model at every node of ``inputs`` and return the table.

    progress(done, total) is called as node values arrive (per node, or per alpha' slice with
    workers > 1); workers > 1 solves alpha' slices in that many processes (same numbers).
    The rigid model and the alpha' = 0 slice are vectorised over the nodes (no solve calls).
    """
    workers = validate.integer("workers", workers, 1, 256)
    l_nodes, c_nodes, _ = inputs.axes()
    alpha_nodes = inputs.alpha_nodes()
    ll, cc = np.meshgrid(l_nodes, c_nodes, indexing="ij")
    total = ll.size * alpha_nodes.size
    sliding = None
    if inputs.model in SLIDING_MODELS:
        sliding = rigid_sliding(inputs, cc.ravel(), ll.ravel()).reshape(ll.shape + (3,))
    if inputs.model == "rigid":  # independent of alpha' (module docstring)
        values = np.repeat(sliding[:, :, None, :], alpha_nodes.size, axis=2)
        if progress is not None:
            progress(total, total)
        return SurrogateTable(inputs, values, sliding)
    values = np.empty(ll.shape + (alpha_nodes.size, 3))
    tasks = [(inputs, float(a)) for a in alpha_nodes]
    if workers == 1:
        done = 0
        for k, alpha in enumerate(alpha_nodes):
            for i in range(l_nodes.size):
                for j in range(c_nodes.size):
                    values[i, j, k] = _solve_node(inputs, float(alpha), float(c_nodes[j]), float(l_nodes[i]))
                    done += 1
                    if progress is not None:
                        progress(done, total)
    else:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            for k, block in enumerate(pool.map(_solve_slice, tasks)):
                values[:, :, k] = block
                if progress is not None:
                    progress((k + 1) * ll.size, total)
    return SurrogateTable(inputs, values, sliding)


def _solve_node(inputs: TableInputs, alpha: float, c: float, l: float) -> tuple[float, float, float]:
    try:
        r = solve(inputs.model, shape=inputs.shape, b_over_a=inputs.b_over_a, alpha=alpha, c_over_a=c,
                  l_over_a=l, poisson=inputs.poisson, n=inputs.n, **dict(inputs.effects))
    except ConvergenceError as error:
        raise ConvergenceError(f"surrogate node l/a = {l:g}, c/a = {c:g}, alpha' = {alpha:g}: {error}") from error
    out = (r.nu_T, r.nu_v, r.nu_0)
    if not all(math.isfinite(v) for v in out):
        raise ConvergenceError(f"surrogate node l/a = {l:g}, c/a = {c:g}, alpha' = {alpha:g}: non-finite result {out}")
    return out


def _solve_slice(task: tuple[TableInputs, float]) -> np.ndarray:
    """One alpha' slice (n_l, n_c, 3): the unit of work of a parallel build."""
    inputs, alpha = task
    l_nodes, c_nodes, _ = inputs.axes()
    return np.array([[_solve_node(inputs, alpha, float(c), float(l)) for c in c_nodes] for l in l_nodes])


def rigid_sliding(inputs: TableInputs, c_over_a: np.ndarray, l_over_a: np.ndarray) -> np.ndarray:
    """nu_T, nu_v, nu_0 (K, 3) of rigid full sliding (alpha' = 0) for K rolling points, vectorised.

    The same quadrature as solve(): the rigid model's fine sample points, or the grid model's own
    cells (its alpha' -> 0 limit); q = -p s_g/|s_g| (rig.contact.models.rigid), coefficients as in
    rig.contact.integrate (M_C = M_O - c F_y + l F_x, nu_0 = -nu_MC for w0 > 0). The
    rolling-length effect moves c to c + f/a first (eq. 3), as solve() does.
    """
    if inputs.model == "rigid":
        x, y, p = rigid.sample_points(inputs.shape, inputs.b_over_a, inputs.n)
    else:
        grid = make_grid(inputs.shape, inputs.b_over_a, inputs.n)
        x, y = grid.centres()
        p = grid.gather(grid.p)
    c_eff = np.asarray(c_over_a, dtype=float) + dict(inputs.effects).get("rolling_length", 0.0)
    l_eff = np.asarray(l_over_a, dtype=float)
    load = float(np.sum(p))
    out = np.empty((c_eff.size, 3))
    step = max(1, _CHUNK_ELEMENTS // x.size)
    for start in range(0, c_eff.size, step):
        c = c_eff[start:start + step, None]
        l = l_eff[start:start + step, None]
        sx, sy = -(y - l), x - c
        norm = np.hypot(sx, sy)
        scale = -p / np.where(norm > 0.0, norm, np.inf)
        qx, qy = scale * sx, scale * sy
        nu_T = np.sum(qx, axis=1) / load
        nu_v = np.sum(qy, axis=1) / load
        nu_mo = np.sum(x * qy - y * qx, axis=1) / load
        out[start:start + step] = np.stack([nu_T, nu_v, -(nu_mo - c[:, 0] * nu_v + l[:, 0] * nu_T)], axis=1)
    return out
