"""An oscillation scene: amplitude sweep of frictional work and slip paths ([Oscillating]), no stand.

Outputs: oscillation_sweep.csv (one row per friction coefficient and stroke ratio, units in the
column names), oscillation_sweep.png (max W and slip path versus e and the drive amplitude, e = 1
and 1.5 marked), work_map.png (W on the material over one cycle at map_stroke_ratio) and
summary.txt (plateau onset per mu, and the ratio of W and slip path between the mu values).
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd
from tqdm import tqdm

from rig.logbook.atomic import naming
from rig.oscillation import amplitude_sweep, cycle_work, plateau_onset, plot_sweep, plot_work_map
from rig.runner.outputs import OSCILLATION_CSV as CSV_NAME
from rig.runner.outputs import OSCILLATION_FIGURE as SWEEP_FIGURE
from rig.runner.folder_lock import folder_lock
from rig.runner.outputs import OSCILLATION_KIND, SUMMARY_NAME, claim_folder, output_folder, staged_outputs
from rig.runner.outputs import WORK_MAP_FIGURE as MAP_FIGURE
from rig.runner.stand_run import RunReport
from rig.runner.sweep import show_progress
from rig.scenes.oscillation_scene import OscillationScene

FILES = (CSV_NAME, SWEEP_FIGURE, MAP_FIGURE, SUMMARY_NAME)


def run_oscillation_scene(scene: OscillationScene, out_dir: Path, *, progress: bool | None = None) -> RunReport:
    """Run the sweep and write the outputs into ``out_dir`` (holding its lock, rig.runner.folder_lock;
    a folder of another kind of run is refused)."""
    out_dir = output_folder(out_dir)
    with folder_lock(out_dir, f"rig run {scene.name}"):
        claim_folder(out_dir, OSCILLATION_KIND)
        return _run_locked(scene, out_dir, progress)


def _run_locked(scene: OscillationScene, out_dir: Path, progress: bool | None) -> RunReport:
    total = len(scene.contacts) * len(scene.stroke_ratios)
    tables = []
    with tqdm(total=total, desc=f"scene {scene.name}", disable=not show_progress(progress)) as bar:
        for contact in scene.contacts:
            table = amplitude_sweep(contact, scene.stroke_ratios, scene.n, progress=lambda *_: bar.update(1))
            table.insert(0, "mu", contact.mu)
            table.insert(1, "alpha", contact.alpha)
            tables.append(table)
    first = scene.contacts[0]
    work = cycle_work(first, scene.map_stroke_ratio, scene.n)
    with staged_outputs(out_dir, replace_previous=True) as staging:
        pd.concat(tables, ignore_index=True).to_csv(staging / CSV_NAME, index=False)
        with naming(out_dir / SWEEP_FIGURE):
            plot_sweep(tables[0], staging / SWEEP_FIGURE, f"{scene.description}\n{first.label}, n = {scene.n}")
        with naming(out_dir / MAP_FIGURE):
            plot_work_map(work, staging / MAP_FIGURE, f"{first.label}, e = {scene.map_stroke_ratio:g}")
        text = _summary(scene, tables)
        (staging / SUMMARY_NAME).write_text(text, encoding="utf-8")
    return RunReport(out_dir, FILES, total, total, 0, (), False, text)


def _summary(scene: OscillationScene, tables: list[pd.DataFrame]) -> str:
    first = scene.contacts[0]
    lines = [
        "friction-rig run summary",
        f"scene:       {scene.name} ({scene.source})",
        f"             {scene.description}",
        "kind:        oscillation (transient grid model, [Oscillating] eqs. 15-20)",
        f"grid:        n = {scene.n} cells across 2a; stroke ratios {', '.join(f'{e:g}' for e in scene.stroke_ratios)}",
    ]
    for contact, table in zip(scene.contacts, tables):
        lines.append(f"mu = {contact.mu:g}:   alpha' = {contact.alpha:.3g}, b/a = {contact.b_over_a:.3g}, "
                     f"e = 1 at double amplitude {contact.amplitude_deg(1.0):.3g} deg; plateau onset "
                     f"(ramp-and-plateau knee) at e = {plateau_onset(table):.2f}")
    if len(tables) > 1:
        a, b = (t.set_index("stroke_ratio") for t in tables[:2])
        ratio_w = (b["max_work_J_m2"] / a["max_work_J_m2"]).median()
        ratio_u = (b["max_slip_path_m"] / a["max_slip_path_m"]).median()
        lines.append(f"mu {scene.contacts[1].mu:g} vs {first.mu:g}: max W x {ratio_w:.2f}, max slip path x "
                     f"{ratio_u:.2f} (medians over e)")
    lines.append(f"outputs:     {', '.join(FILES)}")
    return "\n".join(lines) + "\n"
