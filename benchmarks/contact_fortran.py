"""Reference numbers for pure spin on a circular Hertz contact from Kalker's exact theory (program CONTACT).

Writes CONTACT (E.A.H. Vollebregt, github.com/eve70a/CONTACT) input files for steady rolling with pure spin,
runs a CONTACT stand-alone executable on them one case at a time, and reduces the traction output to our
dimensionless coefficients, appended to a CSV (default tests/contact/data/contact_fortran_pure_spin.csv):

    alpha_prime [1], elements_across [1], nu_v [1], nu_0 [1], cpu_s [s]

* nu_v = |F_y| / (mu F_N): lateral force, y perpendicular to rolling (Equations, eq. (28)).
* nu_0 = |M_z| / (mu a F_N): moment about the contact centre (Equations, eq. (26), rolling point at the centre).
* cpu_s: user + system CPU time of the CONTACT process for one case (influence coefficients, normal and
  tangential solves and output).

Not run in CI. It needs a CONTACT executable, which is not part of this repository: build CONTACT's
stand-alone program as its own README and makefile describe (upstream targets Intel Fortran with MKL) and pass
its path with --contact. The sidecar .toml of the CSV records the build that made the committed table.

The problem (CONTACT module 3, Hertzian option IPOTCN = -3, circular, semi-axes a): identical elastic bodies
(shear modulus G, Poisson ratio nu), normal force F_N prescribed, full elastic normal problem (not a fixed
ellipse), Coulomb friction mu, steady rolling in +x, zero longitudinal and lateral creepage, spin creepage

    phi = phi* mu p0 / (G a) [rad/mm],  phi* = 20 (1 - nu) / alpha'  (rig.contact.kinematics, Creepage),

which is alpha' = 40 mu p0 v / (a E' w0) of seed eq. (21) with E' = E/(1 - nu^2) = 2 G/(1 - nu) (eqs. 22-23)
and phi = w0/v. p0 = 3 F_N / (2 pi a^2) is the peak Hertz pressure. CONTACT works in mm, N and N/mm^2.
"elements_across" counts square elements across the contact diameter 2a; the potential contact is the
square of side SCALE * 2a, SCALE = 1.1, with the same element size.

Usage:
    python benchmarks/contact_fortran.py --contact /path/to/contact_linux64 \
        --alpha 20.5 10.2313 --elements 10 20 40 80 [--out FILE] [--workdir DIR]

Rows already in the output CSV are skipped (the sweep resumes); the CSV is rewritten through a temporary file.
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import resource
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

COLUMNS = ("alpha_prime", "elements_across", "nu_v", "nu_0", "cpu_s")
DEFAULT_OUT = Path(__file__).resolve().parents[1] / "tests/contact/data/contact_fortran_pure_spin.csv"


@dataclass(frozen=True)
class SpinCase:
    """One CONTACT case. Units: mm, N, N/mm^2 (CONTACT's), creepage phi in rad/mm."""

    alpha_prime: float
    elements_across: int
    radius_mm: float = 5.0
    normal_force_n: float = 10_000.0
    shear_modulus_n_per_mm2: float = 82_000.0
    poisson: float = 0.28
    friction: float = 0.3
    scale: float = 1.1

    @property
    def peak_pressure(self) -> float:
        """Hertz p0 = 3 F_N / (2 pi a^2) [N/mm^2]."""
        return 3.0 * self.normal_force_n / (2.0 * math.pi * self.radius_mm**2)

    @property
    def spin_creepage(self) -> float:
        """phi = 20 (1 - nu) mu p0 / (alpha' G a) [rad/mm]."""
        phi_star = 20.0 * (1.0 - self.poisson) / self.alpha_prime
        return phi_star * self.friction * self.peak_pressure / (self.shear_modulus_n_per_mm2 * self.radius_mm)

    @property
    def cells(self) -> int:
        """Elements per side of the square potential contact (SCALE * elements_across, rounded)."""
        return round(self.scale * self.elements_across)

    @property
    def element_size(self) -> float:
        """Element side [mm]; also CONTACT's rolling step DQ."""
        return 2.0 * self.radius_mm / self.elements_across

    def input_text(self) -> str:
        """CONTACT module-3 input: Coulomb friction, elastic half-spaces, steady rolling, F_N given."""
        g, nu, mu, a = self.shear_modulus_n_per_mm2, self.poisson, self.friction, self.radius_mm
        lines = [
            " 3 MODULE",
            "  203100   P-B-T-N-F-S  PVTIME BOUND TANG NORM FORCE STRESS",
            "  022020   L-D-C-M-Z-E  FRCLAW DISCNS INFLCF MATER RZNORM EXRHS",
            " 0001341   H-G-I-A-O-W-R  HEAT GAUSEI IESTIM MATFIL OUTPUT FLOW RETURN",
            "  100 500 20 1 1e-8   MAXGS MAXIN MAXNR MAXOUT EPS",
            f"  {self.normal_force_n:.6f} 0.0 0.0 {self.spin_creepage:.12e}   FN CKSI CETA CPHI",
            f"  {mu} {mu}   FSTAT FKIN",
            f"  0.0 {self.element_size:.12f} 10000.0   CHI DQ VELOC",
            f"  {nu} {nu} {g} {g}   POISS1 POISS2 GG1 GG2",
            "  -3   IPOTCN",
            f"  {self.cells} {self.cells} {a} {a} {self.cells * self.element_size / (2.0 * a):.12f}"
            "   MX MY AA BB SCALE",
            " 0 MODULE",
        ]
        return "\n".join(lines) + "\n"


def coefficients_from_mat(mat_file: Path, case: SpinCase) -> tuple[float, float]:
    """nu_v [1] and nu_0 [1] from the tractions in CONTACT's .mat output (pn, px, py in N/mm^2).

    Element centres are x = XL + (ix - 1/2) DX, y = YL + (iy - 1/2) DY [mm]; forces are the midpoint sums.
    """
    rows = [line.split() for line in mat_file.read_text().splitlines()]
    header = next(i for i, r in enumerate(rows) if r[:3] == ["%", "MX", "MY"])
    mx, my = int(rows[header + 1][0]), int(rows[header + 1][1])
    xl, yl, dx, dy = (float(v) for v in rows[header + 1][2:6])
    start = next(i for i, r in enumerate(rows) if r[:3] == ["%", "I", "IGS"]) + 1
    data = np.array([[float(v) for v in r[:7]] for r in rows[start:] if r and not r[0].startswith("%")])
    index = data[:, 0].astype(int) - 1
    if index.max() >= mx * my:
        raise ValueError(f"element index {index.max() + 1} outside the {mx} x {my} grid in {mat_file}")
    x = xl + (index % mx + 0.5) * dx
    y = yl + (index // mx + 0.5) * dy
    pn, px, py = data[:, 4], data[:, 5], data[:, 6]
    area = dx * dy
    normal_force = pn.sum() * area
    lateral_force = py.sum() * area
    moment = ((x * py - y * px).sum()) * area
    mu = case.friction
    return abs(lateral_force) / (mu * normal_force), abs(moment) / (mu * case.radius_mm * normal_force)


def run_case(contact: Path, case: SpinCase, workdir: Path) -> dict[str, float]:
    """Run one case in workdir and return a CSV row; cpu_s is the child's user + system CPU time [s]."""
    name = f"spin_a{case.alpha_prime:g}_n{case.elements_across}".replace(".", "p")
    (workdir / f"{name}.inp").write_text(case.input_text())
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([str(contact), "2", name], cwd=workdir, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    mat_file = workdir / f"{name}.0001.mat"
    if done.returncode != 0 or not mat_file.exists():
        raise RuntimeError(f"CONTACT failed on {name} (exit {done.returncode}): {done.stdout[-2000:]}")
    nu_v, nu_0 = coefficients_from_mat(mat_file, case)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"alpha_prime": case.alpha_prime, "elements_across": case.elements_across,
            "nu_v": nu_v, "nu_0": nu_0, "cpu_s": cpu}


def read_rows(path: Path) -> list[dict[str, float]]:
    """Rows of an existing output CSV (comment lines start with '#'); empty if it does not exist."""
    if not path.exists():
        return []
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(lines)]


def write_rows(path: Path, rows: list[dict[str, float]]) -> None:
    """Write rows sorted by (alpha', elements) through a temporary file renamed into place."""
    rows = sorted(rows, key=lambda r: (r["alpha_prime"], r["elements_across"]))
    with tempfile.NamedTemporaryFile("w", dir=path.parent, delete=False, suffix=".tmp", newline="") as tmp:
        writer = csv.DictWriter(tmp, fieldnames=COLUMNS)
        writer.writeheader()
        for r in rows:
            writer.writerow({"alpha_prime": f"{r['alpha_prime']:g}",
                             "elements_across": int(r["elements_across"]),
                             "nu_v": f"{r['nu_v']:.6f}", "nu_0": f"{r['nu_0']:.6f}",
                             "cpu_s": f"{r['cpu_s']:.3f}"})
    os.replace(tmp.name, path)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--contact", type=Path, required=True, help="CONTACT stand-alone executable")
    parser.add_argument("--alpha", type=float, nargs="+", required=True, help="alpha' values [1]")
    parser.add_argument("--elements", type=int, nargs="+", required=True, help="elements across 2a [1]")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="CSV to extend")
    parser.add_argument("--workdir", type=Path, default=None, help="folder for CONTACT's files")
    args = parser.parse_args()
    workdir = args.workdir or Path(tempfile.mkdtemp(prefix="contact_spin_"))
    workdir.mkdir(parents=True, exist_ok=True)
    rows = read_rows(args.out)
    for alpha in args.alpha:
        for n in args.elements:
            if any(r["alpha_prime"] == float(f"{alpha:g}") and r["elements_across"] == n for r in rows):
                continue
            row = run_case(args.contact.resolve(), SpinCase(alpha, n), workdir)
            print(f"alpha'={alpha:g} n={n}: nu_v={row['nu_v']:.6f} nu_0={row['nu_0']:.6f}"
                  f" cpu={row['cpu_s']:.2f} s", flush=True)
            rows.append(row)
            write_rows(args.out, rows)


if __name__ == "__main__":
    main()
