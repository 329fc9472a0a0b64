"""Oscillating rolling contacts ([Oscillating]): frictional work density W = mu u p (eq. 16) and the
stroke ratio e = x/2b (eq. 15), computed with the transient grid model (rig.contact.transient).

An ``OscillatingContact`` couples the dimensionless contact (shape, b/a, alpha', rolling point)
with its physical scale (mu, p0, a, Kalker's combined G), so that work densities come out in J/m^2
and slip paths in m. Two sources are provided: the ball-raceway contact of [Oscillating]'s FAG 7208
bearing (Tables 1-2) and stand B's roller under its earlier swinging drive.

``amplitude_sweep`` runs two cycles per stroke ratio and keeps the second (the first starts
from an unloaded contact), recording the largest work density and slip path on the material.
Model limits: the spin follows the rolling (rolling point fixed on the contact); the
differential (Heathcote) slip of conforming ball contacts is not modelled (docs/oscillation.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from rig import validate
from rig.bearing.amplitude import KinematicAssumption, amplitude_for_stroke_ratio
from rig.bearing.ball_raceway import BearingGeometry, Ring, raceway_contact
from rig.bearing.kinematics import cage_speed, contact_spin, raceway_speed
from rig.contact.grid import make_grid
from rig.contact.kinematics import Creepage
from rig.contact.hertz import LineGeometry, line_contact
from rig.contact.materials import (
    PMMA,
    RUBBER_LINING,
    combined_poisson,
    combined_shear_modulus,
    contact_modulus,
    substitute_modulus,
)
from rig.reduction.geometry import StandBGeometry

if TYPE_CHECKING:
    from rig.contact.transient import WorkMap

SWEEP_COLUMNS = ["stroke_ratio", "max_work_J_m2", "max_slip_path_m", "max_slip_lengthwise_m", "max_slip_crosswise_m"]


@dataclass(frozen=True)
class OscillatingContact:
    """A contact whose spin follows its rolling, with the scale that turns results into SI.

    shape, b_over_a, alpha (eq. 21), c_over_a, l_over_a, poisson: the dimensionless contact;
    mu [1], p0 [Pa], a [m] (half length across the rolling direction), shear_modulus [Pa]
    (Kalker's combined G); stroke_per_radian [m/rad]: rolled distance per radian of the drive's
    double amplitude (None when the amplitude is not an angle); label: for plots.
    """

    shape: str
    b_over_a: float
    alpha: float
    c_over_a: float
    l_over_a: float
    poisson: float
    mu: float
    p0: float
    a: float
    shear_modulus: float
    stroke_per_radian: float | None
    label: str

    @property
    def slip_scale_m(self) -> float:
        """Displacement unit of the model, mu p0 a/G [m]."""
        return self.mu * self.p0 * self.a / self.shear_modulus

    @property
    def work_scale_J_m2(self) -> float:
        """Work-density unit of the model, (mu p0)^2 a/G [J/m^2]."""
        return self.mu * self.p0 * self.slip_scale_m

    def creepage(self) -> Creepage:
        """Rigid slip per unit rolled distance (elastic units): spin about (c, l), alpha' fixed."""
        return Creepage.from_rolling_point(self.alpha, self.c_over_a, self.l_over_a, self.poisson)

    def amplitude_deg(self, stroke_ratio: float) -> float:
        """Double amplitude [deg] of the drive at which e = x/2b reaches ``stroke_ratio``."""
        if self.stroke_per_radian is None:
            return math.nan
        return math.degrees(2.0 * self.b_over_a * self.a * stroke_ratio / self.stroke_per_radian)

    @classmethod
    def ball_raceway(
        cls, bearing: BearingGeometry, ring: Ring, force_N: float, mu: float,
        assumption: KinematicAssumption = KinematicAssumption.K3,
    ) -> OscillatingContact:
        """A ball on a raceway of an oscillating bearing ([Oscillating]), the other ring held still.

        alpha' from eq. (21) with v/w0 = (rolling speed)/(spin) at the contact (S4-S11), the
        rolling point at the contact centre; stroke per radian from the kinematic assumption.
        """
        mu = validate.number("mu", mu, 0.0, lo_open=True)
        hertz = raceway_contact(bearing, ring, force_N)
        omega = (1.0, 0.0) if ring is Ring.INNER else (0.0, 1.0)
        spin = abs(contact_spin(bearing, ring, *omega))
        speed = abs(raceway_speed(bearing, ring, omega[0] if ring is Ring.INNER else omega[1])
                    - cage_speed(bearing, *omega) * bearing.contact_radius(ring))
        material = bearing.material
        alpha = 40.0 * mu * hertz.p0 * (speed / spin) / (hertz.a * substitute_modulus(material, material))
        e1_amplitude = amplitude_for_stroke_ratio(bearing, 1.0, hertz.b, assumption)
        return cls(
            shape="ellipse", b_over_a=hertz.b_over_a, alpha=alpha, c_over_a=0.0, l_over_a=0.0,
            poisson=combined_poisson(material, material), mu=mu, p0=hertz.p0, a=hertz.a,
            shear_modulus=combined_shear_modulus(material, material),
            stroke_per_radian=2.0 * hertz.b / e1_amplitude,
            label=f"{ring.name.lower()} raceway, F = {force_N / 1e3:g} kN, mu = {mu:g}",
        )


    @classmethod
    def disc_roller(cls, normal_force_N: float, mu: float) -> OscillatingContact:
        """Stand B's roller under its earlier swinging drive ([Koziarski] section 3.2.2, Equations §4.2).

        Line contact of the rubber-lined roller (d = 125 mm, 2a = 8 mm) on the PMMA disc; the
        disc is geared to the roller, so the spin follows the rolling with v/w0 = R_c and the
        rolling point stays where the screws set it (here the contact centre). The roller's
        double amplitude 2 theta_A rolls x = R_r 2 theta_A, so e = R_r theta_A/b.
        """
        mu = validate.number("mu", mu, 0.0, lo_open=True)
        stand = StandBGeometry()
        pair = (RUBBER_LINING, PMMA)
        hertz = line_contact(normal_force_N, LineGeometry(2.0 * stand.a, stand.roller_radius), contact_modulus(*pair))
        alpha = 40.0 * mu * hertz.p0 * stand.radius_c / (hertz.a * substitute_modulus(*pair))
        return cls(
            shape="line", b_over_a=hertz.b_over_a, alpha=alpha, c_over_a=0.0, l_over_a=0.0,
            poisson=combined_poisson(*pair), mu=mu, p0=hertz.p0, a=hertz.a,
            shear_modulus=combined_shear_modulus(*pair), stroke_per_radian=stand.roller_radius,
            label=f"stand B swinging drive, F_N = {normal_force_N:g} N, mu = {mu:g}",
        )


def cycle_work(contact: OscillatingContact, stroke_ratio: float, n: int) -> WorkMap:
    """Work density [J/m^2] and slip paths [m] on the material over the second of two cycles."""
    # imported on first use: the transient solver's compiled loops (numba) cost ~0.2 s to import,
    # which every `rig` command would pay (this module is imported to validate oscillation scenes)
    from rig.contact.transient import RollingPath, WorkMap, solve_transient

    e = validate.number("stroke_ratio", stroke_ratio, 0.0, 20.0)
    grid = make_grid(contact.shape, contact.b_over_a, n)
    stroke = 2.0 * contact.b_over_a * e  # x = 2 b e, in units of a
    path = RollingPath.oscillation(contact.creepage(), stroke=stroke, cycles=2, step=grid.hx)
    result = solve_transient(
        shape=contact.shape, b_over_a=contact.b_over_a, poisson=contact.poisson, n=n, path=path,
        frictional_work=True, work_from_step=path.distance.size // 2,
    )
    w, u = result.work, contact.slip_scale_m
    return WorkMap(w.x * contact.a, w.y * contact.a, w.work * contact.work_scale_J_m2,
                   w.path_lengthwise * u, w.path_crosswise * u, w.path * u)


def amplitude_sweep(contact: OscillatingContact, stroke_ratios, n: int, progress=None) -> pd.DataFrame:
    """Largest work density and slip paths per cycle versus the stroke ratio (and the amplitude)."""
    rows = []
    for k, e in enumerate(stroke_ratios):
        w = cycle_work(contact, float(e), n)
        rows.append([float(e), w.work.max(), w.path.max(), w.path_lengthwise.max(), w.path_crosswise.max()])
        if progress is not None:
            progress(k + 1, len(stroke_ratios))
    table = pd.DataFrame(rows, columns=SWEEP_COLUMNS)
    table["double_amplitude_deg"] = [contact.amplitude_deg(e) for e in table["stroke_ratio"]]
    return table


def plateau_onset(table: pd.DataFrame, column: str = "max_work_J_m2") -> float:
    """Stroke ratio of the knee of a ramp-and-plateau fit: ``column`` = P + s min(e - e_k, 0),
    least squares over all points, e_k scanned over the swept range (0.001 resolution).

    A two-point secant would hang on the noise of single points; the fit uses them all
    (tests/test_oscillation.py: 0.94-1.06 for [Oscillating]'s contact over grids n = 16-32).
    """
    e = table["stroke_ratio"].to_numpy(dtype=float)
    w = table[column].to_numpy(dtype=float)
    best_residual, best_knee = np.inf, math.nan
    for knee in np.arange(e.min(), e.max() + 1e-9, 1e-3):
        design = np.stack([np.ones_like(e), np.minimum(e - knee, 0.0)], axis=1)
        coef = np.linalg.lstsq(design, w, rcond=None)[0]
        residual = float(np.sum((design @ coef - w) ** 2))
        if residual < best_residual:
            best_residual, best_knee = residual, float(knee)
    return best_knee


def plot_sweep(table: pd.DataFrame, path: Path, title: str) -> Path:
    """max W and max slip path versus e (bottom axis) and the drive amplitude (top), e = 1, 1.5 marked."""
    from rig.plotting import new_figure

    fig = new_figure(figsize=(7, 6.5))
    ax_w, ax_u = fig.subplots(2, 1, sharex=True)
    ax_w.plot(table["stroke_ratio"], table["max_work_J_m2"], "o-")
    ax_w.set_ylabel("max W per cycle [J/m$^2$]")
    ax_u.plot(table["stroke_ratio"], table["max_slip_path_m"] * 1e6, "s-", label="total")
    ax_u.plot(table["stroke_ratio"], table["max_slip_lengthwise_m"] * 1e6, "--", label="lengthwise")
    ax_u.plot(table["stroke_ratio"], table["max_slip_crosswise_m"] * 1e6, ":", label="crosswise")
    ax_u.set_ylabel(r"max slip path per cycle [$\mu$m]")
    ax_u.set_xlabel("stroke ratio e = x/2b ([Oscillating], eq. 15)")
    ax_u.legend(fontsize=8)
    for ax in (ax_w, ax_u):
        for e, style in ((1.0, "-"), (1.5, "--")):
            ax.axvline(e, color="grey", linestyle=style, linewidth=0.8)
        ax.grid(True, alpha=0.3)
    amplitude = table["double_amplitude_deg"]
    if amplitude.notna().all() and len(table) > 1:
        slope = float(np.polyfit(table["stroke_ratio"], amplitude, 1)[0])
        top = ax_w.secondary_xaxis("top", functions=(lambda e: e * slope, lambda t: t / slope))
        top.set_xlabel("double amplitude [deg]")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path


def plot_work_map(work: WorkMap, path: Path, title: str) -> Path:
    """Map of the frictional work density W [J/m^2] on the material over one cycle."""
    from rig.plotting import new_figure

    fig = new_figure(figsize=(7, 3.6))
    ax = fig.subplots()
    extent = [work.x[0] * 1e3, work.x[-1] * 1e3, work.y[0] * 1e3, work.y[-1] * 1e3]
    image = ax.imshow(work.work.T, origin="lower", extent=extent, aspect="auto", cmap="inferno")
    fig.colorbar(image, ax=ax, label="W per cycle [J/m$^2$]")
    ax.set_xlabel("material coordinate along rolling x [mm]")
    ax.set_ylabel("across rolling y [mm]")
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path
