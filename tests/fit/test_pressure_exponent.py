"""`rig fit` frees the pressure exponent k of mu(p) (contact effect pressure_exponent) on a contact curve.

Data: the kinematic model's own nu_v(alpha') at k = 0.4 (rolling point (0.3, 0.5) a, circle, n = 8),
u = 0.002 without noise added, so the fit must return k = 0.4 inside a narrow interval and rank
the effect first; the same curve at k = 0 must not need it.
"""

from __future__ import annotations

import numpy as np
import pytest

from rig.contact.solve import solve
from rig.fit import fit_data

ALPHAS = np.geomspace(0.3, 30.0, 9)
CONDITIONS = dict(shape="ellipse", b_over_a=1.0, c_over_a=0.3, l_over_a=0.5, poisson=0.3)


def _curve(folder, k):
    y = [solve("kinematic", alpha=float(a), n=8, **CONDITIONS, **({"pressure_exponent": k} if k else {})).nu_v
         for a in ALPHAS]
    data = folder / f"curve_{k}.csv"
    data.write_text("nu_v,\nX,Y\n" + "".join(f"{float(a)!r},{float(v)!r}\n" for a, v in zip(ALPHAS, y)))
    data.with_suffix(".toml").write_text(
        'figure = "kinematic model, k = %g"\n[conditions]\n' % k
        + "".join(f"{key} = {value!r}\n".replace("'", '"') for key, value in CONDITIONS.items())
        + '[x]\nquantity = "alpha\'"\nunits = "1"\n[datasets.nu_v]\nquantity = "F_y/(mu F_N)"\nunits = "1"\n')
    return data


@pytest.mark.parametrize("k", [0.4, 0.0])
def test_fit_recovers_the_exponent_and_the_model_choice_asks_for_it_only_when_present(tmp_path, k):
    report = fit_data(_curve(tmp_path, k), ["pressure_exponent"], sigma=0.002, n=8)
    estimate = report.full.estimate("pressure_exponent")
    assert estimate.lo95 <= k <= estimate.hi95
    assert estimate.hi95 - estimate.lo95 < 0.1
    assert report.best.label.startswith("(all fixed") == (k == 0.0)
