"""docs/log-format.md: its plain-h5py snippet runs on a real log, and it names every attribute."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import logbook_samples as samples
import pytest

from rig.logbook import layout

DOC = Path(__file__).resolve().parents[2] / "docs" / "log-format.md"


def _snippet() -> str:
    text = DOC.read_text(encoding="utf-8")
    match = re.search(r"<!-- snippet: plain-h5py.*?-->\s*```python\n(.*?)```", text, re.S)
    assert match, "the plain-h5py snippet is missing from docs/log-format.md"
    return match.group(1)


def test_snippet_is_short_and_needs_no_friction_rig() -> None:
    code = _snippet()
    assert len([line for line in code.splitlines() if line.strip()]) <= 12
    assert "rig" not in re.findall(r"^\s*(?:import|from)\s+(\w+)", code, re.M)


def test_snippet_reads_a_log_with_plain_h5py(tmp_path: Path) -> None:
    path = tmp_path / "run.h5"
    samples.write_run(path)
    namespace: dict[str, object] = {"path": str(path)}
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(_snippet(), str(DOC), "exec"), namespace)  # noqa: S102 - our own documentation
    assert namespace["scene"] == samples.SCENE
    lines = out.getvalue().splitlines()
    assert len(lines) == samples.N_POINTS
    first = samples.point(0).channels["F_dyn"]
    name, f_n, unit, channel_unit, t0, x0 = lines[0].split()
    assert (name, float(f_n), unit, channel_unit) == ("0", 96.2, "N", "N")
    assert float(t0) == pytest.approx(2.5) and float(x0) == pytest.approx(first.samples[0])


@pytest.mark.parametrize(
    "name",
    [value for key, value in vars(layout).items() if key.startswith(("ATTR_", "FORMAT_NAME")) and isinstance(value, str)]
    + [layout.SCENE_DATASET, layout.POINTS_GROUP, layout.TRUTH_GROUP, layout.REDUCED_GROUP, layout.COUNT_UNIT],
)
def test_doc_names_every_attribute_and_group(name: str) -> None:
    assert f"`{name}`" in DOC.read_text(encoding="utf-8") or f"{name}/" in DOC.read_text(encoding="utf-8")
