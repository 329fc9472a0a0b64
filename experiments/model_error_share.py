"""How much of a run's stated uncertainty is the contact model's numerical error (stand A or B).

    python experiments/model_error_share.py RUN_DIR [--scene fig10] [--every 6]

RUN_DIR holds a ``log.h5`` of the scene (e.g. from ``rig run fig10 -o RUN_DIR``). Every ``every``-th
point is reduced again with its budget (rig.reduction.stand_a or stand_b, the scene's own laws with
their error budget, docs/reduction.md section 4); printed per point and friction estimate (mu_v, mu_T;
stand B also mu_M): the value, its u, the part of u from "contact model (grid and table)" and that
part's share of the variance.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rig.logbook import read_points
from rig.reduction import stand_a, stand_b
from rig.reduction.coefficients import MODEL_SOURCE
from rig.scenes.load import load_scene
from rig.stands.contact_law import LawCoefficients
from rig.stands.disc_roller.reduction import point_readings as stand_b_readings
from rig.stands.yoke.reduction import point_readings as stand_a_readings


def reduced_again(stand, record, where: str):
    """(b/a, the ReducedPoint with its budget) of one logged point of either stand."""
    if hasattr(stand.params, "geometry_at"):  # stand A: the geometry depends on the yoke's shift
        geometry = stand.params.geometry_at(float(record.settings["delta_h"].value))
        readings = stand_a_readings(record, stand.params, geometry, where)
        law, domain = stand.law(readings.b_over_a, geometry)
        return readings.b_over_a, stand_a.reduce(readings, LawCoefficients(law, domain), geometry)
    readings = stand_b_readings(record, stand.params, where)
    law = LawCoefficients(stand.law(readings.b_over_a), stand.law_domain(readings.b_over_a))
    return readings.b_over_a, stand_b.reduce(readings, law, stand.params.geometry)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir", type=Path)
    parser.add_argument("--scene", default="fig10")
    parser.add_argument("--every", type=int, default=6)
    args = parser.parse_args()
    stand = load_scene(args.scene).build_stand()
    print("point  b/a    l/a     alpha'   output  value    u        model part  share")
    for index, record in read_points(args.run_dir / "log.h5"):
        if index % args.every:
            continue
        b_over_a, point = reduced_again(stand, record, f"point {index}")
        by_source = point.budget.by_source()
        v = point.values
        for name in ("mu_v", "mu_T", "mu_M"):
            u = point.uncertainties.get(name)
            if u is None or not u > 0.0:
                continue
            part = max(by_source.loc[MODEL_SOURCE, name], 0.0) ** 0.5 if MODEL_SOURCE in by_source.index else 0.0
            print(f"{index:5d}  {b_over_a:5.2f}  {v['l_over_a']:6.3f}  {v['alpha_prime']:7.3f}  {name:6s}  "
                  f"{v[name]:.4f}  {u:.4f}   {part:.4f}      {part ** 2 / u ** 2:.2f}")


if __name__ == "__main__":
    main()
