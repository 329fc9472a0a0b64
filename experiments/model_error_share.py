"""How much of a stand-A run's stated uncertainty is the contact model's numerical error.

    python experiments/model_error_share.py RUN_DIR [--scene fig10] [--every 6]

RUN_DIR holds a ``log.h5`` of a stand-A scene (e.g. from ``rig run fig10 -o RUN_DIR``). Every
``every``-th point is reduced again with its budget (rig.reduction.stand_a, the scene's own laws with
their error budget, docs/reduction.md section 4); printed per point: b/a, l/a, alpha', nu_v, mu_v,
u(mu_v), the part of u(mu_v) from "contact model (grid and table)" and its share of the variance.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rig.logbook import read_points
from rig.reduction import stand_a
from rig.reduction.coefficients import MODEL_SOURCE
from rig.scenes.load import load_scene
from rig.stands.contact_law import LawCoefficients
from rig.stands.yoke.reduction import point_readings


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir", type=Path)
    parser.add_argument("--scene", default="fig10")
    parser.add_argument("--every", type=int, default=6)
    args = parser.parse_args()
    stand = load_scene(args.scene).build_stand()
    print("point  b/a   l/a    alpha'  nu_v    mu_v    u(mu_v)  model part  share")
    for index, record in read_points(args.run_dir / "log.h5"):
        if index % args.every:
            continue
        geometry = stand.params.geometry_at(float(record.settings["delta_h"].value))
        readings = point_readings(record, stand.params, geometry, f"point {index}")
        law, domain = stand.law(readings.b_over_a, geometry)
        point = stand_a.reduce(readings, LawCoefficients(law, domain), geometry)
        by_source = point.budget.by_source()
        part = by_source.loc[MODEL_SOURCE, "mu_v"] ** 0.5 if MODEL_SOURCE in by_source.index else 0.0
        v, u = point.values, point.uncertainties["mu_v"]
        print(f"{index:5d}  {readings.b_over_a:4.2f}  {v['l_over_a']:5.3f}  {v['alpha_prime']:6.3f}  {v['nu_v']:.4f}  "
              f"{v['mu_v']:.4f}  {u:.4f}   {part:.4f}      {part ** 2 / u ** 2:.2f}")


if __name__ == "__main__":
    main()
