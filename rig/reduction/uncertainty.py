"""Propagation of standard uncertainties through a reduction: first order and Monte Carlo.

Uncertainty model (docs/reduction.md): every input is a number with a standard uncertainty
(GUM), optionally correlated in pairs (e.g. a calibration's sensitivity and offset). The output
covariance is V_y = J V_x J^T (GUM eq. 13) with the Jacobian J taken *numerically*, by central
differences with the step h_i = relative_step * u(x_i) (Kragten's choice of a step of one
standard uncertainty by default). The numerical Jacobian is a choice: the reduction contains an
implicit mu <-> alpha' iteration and an arbitrary contact model, whose derivatives are not
available in closed form; differencing the whole converged chain captures both.

The Monte-Carlo propagator (GUM Supplement 1) draws the inputs from their distributions and
evaluates the model per draw; it is used in tests to check the first-order result.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from rig import validate
from rig.errors import ParameterError

Model = Callable[[Mapping[str, float]], Mapping[str, float]]
MIN_RELATIVE_STEP = 1e-9  # smallest Jacobian step relative to the input's value [1]


class Distribution(Enum):
    """Distribution of an input for the Monte-Carlo propagation (first order needs only u)."""

    NORMAL = "normal"
    RECTANGULAR = "rectangular"  # half width sqrt(3) u, e.g. a scale step's bias
    TRIANGULAR = "triangular"  # half width sqrt(6) u, e.g. a gated count (difference of two uniform phases)


HALF_WIDTH_PER_U = {Distribution.RECTANGULAR: math.sqrt(3.0), Distribution.TRIANGULAR: math.sqrt(6.0)}
"""Half width of a bounded distribution per standard uncertainty [1]."""


def rectangular_u(half_width: float) -> float:
    """Standard uncertainty of a rectangular distribution of the given half width: a/sqrt(3)."""
    return validate.number("half_width", half_width, 0.0) / math.sqrt(3.0)


@dataclass(frozen=True)
class InputQuantity:
    """One input: value and standard uncertainty u in `unit`; `source` names the instrument."""

    name: str
    value: float
    u: float
    unit: str
    source: str
    distribution: Distribution = Distribution.NORMAL

    def __post_init__(self) -> None:
        validate.number(self.name, self.value)
        validate.number(f"u({self.name})", self.u, 0.0)


@dataclass(frozen=True)
class Covariance:
    """Covariance of two inputs, in the product of their units."""

    first: str
    second: str
    value: float


@dataclass(frozen=True)
class InputSet:
    """The inputs of one operating point and the covariances between them."""

    quantities: tuple[InputQuantity, ...]
    covariances: tuple[Covariance, ...] = ()

    def __post_init__(self) -> None:
        names = self.names
        if len(set(names)) != len(names):
            raise ParameterError("quantities", names, "unique names")
        u = {q.name: q for q in self.quantities}
        for cov in self.covariances:
            for name in (cov.first, cov.second):
                validate.choice("input", name, names)
                if u[name].distribution is not Distribution.NORMAL:
                    kind = u[name].distribution.value
                    raise ParameterError(f"distribution of {name}", kind, "normal when correlated")
            bound = u[cov.first].u * u[cov.second].u
            validate.number(f"cov({cov.first}, {cov.second})", cov.value, -bound, bound)

    @functools.cached_property
    def names(self) -> tuple[str, ...]:
        return tuple(q.name for q in self.quantities)

    @property
    def values(self) -> np.ndarray:
        return np.array([q.value for q in self.quantities])

    @property
    def uncertainties(self) -> np.ndarray:
        return np.array([q.u for q in self.quantities])

    def covariance_matrix(self) -> np.ndarray:
        """Input covariance V_x (n, n) in the inputs' units."""
        v = np.diag(self.uncertainties**2)
        index = {name: i for i, name in enumerate(self.names)}
        for cov in self.covariances:
            i, j = index[cov.first], index[cov.second]
            v[i, j] = v[j, i] = cov.value
        return v

    def mapping(self, values: Sequence[float]) -> dict[str, float]:
        return dict(zip(self.names, np.asarray(values, dtype=float).tolist()))


@dataclass(frozen=True)
class Propagation:
    """First-order result: outputs y, Jacobian J = dy/dx (n_out, n_in), V_y = J V_x J^T."""

    inputs: InputSet
    output_names: tuple[str, ...]
    values: np.ndarray
    jacobian: np.ndarray
    covariance: np.ndarray

    @property
    def uncertainties(self) -> np.ndarray:
        """Standard uncertainties of the outputs (NaN where undefined)."""
        return np.sqrt(np.diag(self.covariance))

    def value(self, name: str) -> float:
        return float(self.values[self.output_names.index(name)])

    def u(self, name: str) -> float:
        return float(self.uncertainties[self.output_names.index(name)])


def _evaluate(model: Model, inputs: InputSet, x: np.ndarray, output_names: tuple[str, ...]) -> np.ndarray:
    out = model(inputs.mapping(x))
    return np.array([out[name] for name in output_names], dtype=float)


def first_order(
    model: Model, inputs: InputSet, output_names: Sequence[str], relative_step: float = 1.0,
    y0: np.ndarray | None = None,
) -> Propagation:
    """Propagate with a central-difference Jacobian, step h_i = relative_step u(x_i).

    Inputs with u = 0 get a zero column (not evaluated); the step is at least MIN_RELATIVE_STEP
    |x_i|, so that a tiny u cannot make x_i +- h round to x_i. Where a perturbed evaluation is NaN
    (the chain hit a guard) the derivative, and the uncertainty of that output, is NaN. ``y0``: the
    outputs at the inputs' values, when the caller has them (else the model is evaluated there).
    """
    validate.number("relative_step", relative_step, 0.0, lo_open=True)
    names = tuple(output_names)
    x0 = inputs.values
    y0 = _evaluate(model, inputs, x0, names) if y0 is None else np.asarray(y0, dtype=float)
    jac = np.zeros((len(names), x0.size))
    for i, u in enumerate(inputs.uncertainties):
        if u == 0.0:
            continue
        h = max(relative_step * u, MIN_RELATIVE_STEP * abs(x0[i]))  # x +- h must differ from x
        step = np.zeros_like(x0)
        step[i] = h
        jac[:, i] = (_evaluate(model, inputs, x0 + step, names) - _evaluate(model, inputs, x0 - step, names)) / (2 * h)
    v_x = inputs.covariance_matrix()
    with np.errstate(invalid="ignore"):
        v_y = _sandwich(jac, v_x)
    return Propagation(inputs, names, y0, jac, v_y)


def _sandwich(jac: np.ndarray, v_x: np.ndarray) -> np.ndarray:
    """J V J^T where a NaN derivative only poisons the outputs it belongs to."""
    finite = np.where(np.isfinite(jac), jac, 0.0)
    v_y = finite @ v_x @ finite.T
    bad = ~np.all(np.isfinite(jac[:, v_x.diagonal() > 0]), axis=1)
    v_y[bad, :] = np.nan
    v_y[:, bad] = np.nan
    return v_y


@dataclass(frozen=True)
class MonteCarlo:
    """Monte-Carlo result: per output mean and standard deviation over the finite draws."""

    output_names: tuple[str, ...]
    samples: np.ndarray  # (n_samples, n_out)

    @property
    def mean(self) -> np.ndarray:
        return np.nanmean(self.samples, axis=0)

    @property
    def std(self) -> np.ndarray:
        return np.nanstd(self.samples, axis=0, ddof=1)

    def u(self, name: str) -> float:
        return float(self.std[self.output_names.index(name)])


def draw_inputs(inputs: InputSet, n_samples: int, rng: np.random.Generator) -> np.ndarray:
    """n_samples draws (n_samples, n_in): correlated normal block, independent rectangular and
    triangular ones (symmetric about the value, half width HALF_WIDTH_PER_U u)."""
    validate.integer("n_samples", n_samples, 2)
    x0, u = inputs.values, inputs.uncertainties
    kinds = [q.distribution for q in inputs.quantities]
    draws = np.tile(x0, (n_samples, 1))
    normal = np.array([k is Distribution.NORMAL for k in kinds]) & (u > 0)
    if normal.any():
        v = inputs.covariance_matrix()[np.ix_(normal, normal)]
        draws[:, normal] += rng.multivariate_normal(np.zeros(normal.sum()), v, size=n_samples, method="eigh")
    for kind, unit_draw in UNIT_DRAWS.items():
        cols = np.array([k is kind for k in kinds])
        if cols.any():
            draws[:, cols] += unit_draw(rng, (n_samples, int(cols.sum()))) * HALF_WIDTH_PER_U[kind] * u[cols]
    return draws


UNIT_DRAWS = {  # draws on [-1, 1] of the bounded distributions: draw(rng, size)
    Distribution.RECTANGULAR: lambda rng, size: rng.uniform(-1.0, 1.0, size=size),
    Distribution.TRIANGULAR: lambda rng, size: rng.random(size) - rng.random(size),  # U - U': triangular
}


def monte_carlo(
    model: Model, inputs: InputSet, output_names: Sequence[str], n_samples: int, rng: np.random.Generator
) -> MonteCarlo:
    """Propagate by evaluating the model at n_samples random draws of the inputs (seeded rng)."""
    names = tuple(output_names)
    draws = draw_inputs(inputs, n_samples, rng)
    samples = np.array([_evaluate(model, inputs, x, names) for x in draws])
    return MonteCarlo(names, samples)
