"""``solve``: one entry point for the contact-model ladder rigid -> linear -> fastsim -> kinematic.

    from rig.contact import solve
    r = solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=10.0, c_over_a=0.0, l_over_a=0.0,
              poisson=0.28, n=32)
    r.nu_T, r.nu_v, r.nu_0, r.stick_fraction

alpha is alpha' of eq. (21) (0 = rigid sliding, inf = no slip); (c/a, l/a) is the rolling point;
poisson is the (combined) Poisson ratio of the pair; n = cells across 2a for the grid models (more
rows for a narrow contact, b/a < 0.15, and a wide one, b/a > 6.67: rig.contact.grid.rows_across).
``solve_creepage`` states the same problem in creepages, which also covers zero spin (hard case 1).
Effects are keyword arguments (see rig.contact.effects); an effect not named is not built.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from rig import validate
from rig.contact.effects import EFFECT_KEYWORDS, ContactEffects
from rig.contact.grid import SHAPES, make_grid
from rig.contact.integrate import coefficients
from rig.contact.kalker import B_OVER_A_RANGE, creep_coefficients
from rig.contact.kinematics import Creepage
from rig.contact.models import fastsim, linear, rigid
from rig.contact.result import ContactMaps, ContactResult
from rig.errors import ParameterError

MODELS = ("rigid", "linear", "fastsim", "kinematic")
# A rigid slip this many elastic slip units (mu p0 v/G) wide is full sliding to 1e-12: the elastic
# slip, O(1), turns its direction only within 1e-12 a of the rolling point (hard cases 2 and 3).
RIGID_SLIDING_CREEPAGE = 1e12
DEFAULT_N = 32
# Revision of the grid models' discretisation; part of every surrogate table's cache key.
# 2: plastic slip of eq. (25) as a grid-independent slip velocity (docs/contact-model.md).
# 3: FASTSIM's spin-moment flexibility L4 (fitted to C33).
# 4: kinematic transport of second order with the edge-corrected row entry (rig.contact.models.kinematic).
# 5: the kinematic solver's third pass (rig.contact.newton, elastic_law): Newton tolerance 1e-6, values move <= 1e-7.
# 6: a grid cell's pressure is the load of the contact nearest its centre (the rim's cut cells no longer drop theirs).
# 7: each row's first cell carries its traction with the leading edge's sqrt profile, the second its own step (rig.contact.entry).
# 8: every cell the contact reaches shares out its load (a sliver thinner than a sub-cell no longer lost it), sub-cells exact across x.
# 9: a narrow contact (b/a < 0.15) gets more rows than n, up to 2n (rig.contact.grid.rows_across).
# 10: a wide contact (b/a > 6.67) gets more rows, up to 1.5n, and cells at most 2.5 times as long as high
#     (rig.contact.grid.rows_across, cells_along_rolling).
DISCRETISATION_REVISION = 10
N_RANGE = (4, 512)
# Effects each model can represent; the others would be silently meaningless, so they are errors.
# The pressure-dependent mu changes only the traction bound, so every model with one has it; linear
# theory has none (no sliding): there it would be silently meaningless.
MODEL_EFFECTS = {
    "rigid": ("rolling_length", "pressure_exponent"),
    "linear": ("rolling_length",),
    "fastsim": ("rolling_length", "pressure_exponent"),
    "kinematic": tuple(EFFECT_KEYWORDS),
}


def solve(
    model: str,
    *,
    shape: str,
    b_over_a: float,
    alpha: float,
    c_over_a: float,
    l_over_a: float,
    poisson: float,
    n: int | None = None,
    **effects: float,
) -> ContactResult:
    """Force coefficients of a steady rolling contact with spin about the rolling point (c, l).

    Parameters
    ----------
    model : str
        ``"rigid"``, ``"linear"``, ``"fastsim"`` or ``"kinematic"`` (the paper's law, [Koziarski] section 2).
    shape : str
        ``"ellipse"`` or ``"line"``.
    b_over_a : float
        Semi-axis ratio b/a of the contact [1].
    alpha : float
        Track deformability alpha' of [Koziarski] eq. (21) [1], >= 0 (inf allowed).
    c_over_a, l_over_a : float
        The rolling point C [units of a].
    poisson : float
        Poisson ratio of the pair [1], in [0, 0.5].
    n : int, optional
        Cells across 2a (default 32; more rows when b/a < 0.15, rig.contact.grid.rows_across).
    **effects : float
        psi, static_ratio, inertia_number, rolling_length, pressure_exponent (kinematic model;
        MODEL_EFFECTS lists what the others support). With pressure_exponent the friction
        coefficient of the units (nu = F/(mu F_N), alpha') is mu(p0), at the peak pressure.

    Returns
    -------
    ContactResult
        nu_T, nu_v, nu_0 of [Koziarski] eqs. (26)-(28) [1], nu_Mo, the stick fraction and diagnostics.
    """
    alpha = validate.number("alpha", alpha, 0.0, allow_inf=True)
    c = validate.number("c_over_a", c_over_a)
    l = validate.number("l_over_a", l_over_a)
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    creepage = None if alpha == 0.0 else Creepage.from_rolling_point(alpha, c, l, nu)
    if creepage is not None and not np.all(np.isfinite([creepage.xi, creepage.eta, creepage.phi])):
        creepage = None  # alpha' so small (or C so far out) that a creepage overflows: rigid sliding
    info = dict(alpha=alpha, c_over_a=c, l_over_a=l)
    result = _solve(model, shape, b_over_a, creepage, (c, l), nu, n, effects, info)
    if np.isinf(alpha):  # no slip anywhere: every coefficient is 0, nu_0 too (its alpha' -> inf limit)
        result = dataclasses.replace(result, nu_0=0.0, info=dict(result.info, nu_MC=0.0))
    return result


def solve_creepage(
    model: str,
    *,
    shape: str,
    b_over_a: float,
    xi: float,
    eta: float,
    phi: float,
    poisson: float,
    n: int | None = None,
    **effects: float,
) -> ContactResult:
    """As :func:`solve`, with the rigid slip given as creepages in elastic units (Creepage).

    Parameters
    ----------
    model, shape, b_over_a, poisson, n, **effects
        As for :func:`solve`.
    xi, eta : float
        Centre slip [mu p0 v/G].
    phi : float
        Spin a G (w0/v)/(mu p0) [1]; phi = 0 (no spin) is allowed: the rolling point is then at
        infinity and nu_0 is NaN (use nu_Mo).

    Returns
    -------
    ContactResult
        The force coefficients [1], as for :func:`solve`.
    """
    creepage = Creepage(
        xi=validate.number("xi", xi), eta=validate.number("eta", eta), phi=validate.number("phi", phi)
    )
    nu = validate.number("poisson", poisson, 0.0, 0.5)
    return _solve(model, shape, b_over_a, creepage, None, nu, n, effects, dict(xi=xi, eta=eta, phi=phi))


def _solve(model, shape, b_over_a, creepage, rolling_point, nu, n, effects, info) -> ContactResult:
    model = validate.choice("model", model, MODELS)
    shape = validate.choice("shape", shape, SHAPES)
    beta = validate.number("b_over_a", b_over_a, *B_OVER_A_RANGE)
    n = DEFAULT_N if n is None else validate.integer("n", n, *N_RANGE)
    validate.known_keys("effect", effects, EFFECT_KEYWORDS)
    for name, value in effects.items():
        if name not in MODEL_EFFECTS[model]:
            raise ParameterError(name, value, f"not available for model {model!r}; it supports {MODEL_EFFECTS[model]}")
    built = ContactEffects.from_keywords(**effects)
    if built.rolling_resistance is not None:
        creepage, rolling_point = built.rolling_resistance.shift(creepage, rolling_point)
    size = 0.0 if creepage is None else max(abs(creepage.xi), abs(creepage.eta), abs(creepage.phi))
    if creepage is None:  # alpha' = 0 (or a creepage overflowed): unit spin about C fixes the slip directions
        creepage = Creepage(xi=rolling_point[1], eta=-rolling_point[0], phi=1.0)
        rigid_sliding = True
    elif size > RIGID_SLIDING_CREEPAGE:  # the elastic slip cannot turn the rigid slip: rigid sliding
        creepage = Creepage(xi=creepage.xi / size, eta=creepage.eta / size, phi=creepage.phi / size)
        rigid_sliding = True
    else:
        rigid_sliding = False
    info = dict(info, poisson=nu, n=n, effects=built.names())

    if model == "rigid" or (rigid_sliding and model in ("fastsim", "kinematic")):
        return _rigid(model, shape, beta, n, creepage, built, info, on_grid=model != "rigid")
    if model == "linear":
        if rigid_sliding:
            raise ParameterError(
                "alpha" if "alpha" in info else "creepage", info.get("alpha", size),
                f"alpha' > 0 and creepages <= {RIGID_SLIDING_CREEPAGE:g} elastic slip units for the linear model "
                "(it has no sliding; this state is full sliding)",
            )
        return _linear(shape, beta, nu, creepage, info)
    grid = make_grid(shape, beta, n)
    xc, yc = grid.centres()
    p = grid.gather(grid.p)
    s_g = creepage.field(xc, yc)
    if model == "fastsim":
        flex = fastsim.flexibility(shape, beta, creep_coefficients(shape, beta, nu), creepage)
        bound = built.traction_bound(grid.p)
        q = grid.gather(fastsim.march(grid, fastsim.slip_increments(grid, creepage), bound, flex))
        stick = np.hypot(q[0], q[1]) < grid.gather(bound) * (1.0 - 1e-12)
        slip = np.where(stick, 0.0, s_g)  # FASTSIM's slip direction follows the rigid slip
        info["flexibility"] = flex
    else:
        # imported on first use: its compiled loops (numba) cost ~0.2 s to import, which a run on cached
        # surrogate tables never needs
        from rig.contact.models import kinematic

        solution = kinematic.solve_grid(grid, nu, creepage, built)
        q, stick, slip = solution.q, solution.stick, solution.s
        info.update(
            newton_iterations=solution.newton_iterations,
            krylov_iterations=solution.krylov_iterations,
            memory_passes=solution.memory_passes,
        )
    maps = ContactMaps(xc, yc, np.full(p.size, grid.cell_area), p, q, slip, stick)
    return _result(model, shape, beta, xc, yc, q, p, creepage, float(np.mean(stick)), maps, info)


def _rigid(model, shape, beta, n, creepage, effects, info, *, on_grid: bool) -> ContactResult:
    if on_grid:  # the grid model's own alpha' = 0 limit, on its cells
        grid = make_grid(shape, beta, n)
        x, y = grid.centres()
        p = grid.gather(grid.p)
    else:
        x, y, p = rigid.sample_points(shape, beta, n)
    q = rigid.tractions(x, y, effects.traction_bound(p), creepage)
    return _result(model, shape, beta, x, y, q, p, creepage, 0.0, None, info)


def _linear(shape, beta, nu, creepage, info) -> ContactResult:
    values = linear.force_coefficients(shape, beta, creep_coefficients(shape, beta, nu), creepage)
    c, l = creepage.rolling_point()
    if creepage.phi == 0.0:
        nu_mc = nu_0 = np.nan
    else:
        nu_mc = values["nu_Mo"] - c * values["nu_v"] + l * values["nu_T"]
        nu_0 = -np.sign(creepage.phi) * nu_mc
    return ContactResult(
        "linear", shape, beta, values["nu_T"], values["nu_v"], float(nu_0), values["nu_Mo"], 1.0,
        None, dict(info, nu_MC=float(nu_mc)),
    )


def _result(model, shape, beta, x, y, q, p, creepage, stick_fraction, maps, info) -> ContactResult:
    values = coefficients(x, y, q, p, creepage)
    return ContactResult(
        model, shape, beta, values["nu_T"], values["nu_v"], float(values["nu_0"]), values["nu_Mo"],
        stick_fraction, maps, dict(info, nu_MC=float(values["nu_MC"])),
    )
