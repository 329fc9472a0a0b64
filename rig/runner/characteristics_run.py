"""A contact-characteristics scene: nu_T, nu_v, nu_0 versus alpha' with rig.characteristics (no stand).

Outputs in the folder: characteristics.csv (one row per case, model and alpha'),
characteristics.png (the models overlaid, one row of panels per case) and summary.txt.
"""

from __future__ import annotations

from pathlib import Path

from tqdm import tqdm

from rig.characteristics import plot, sweep
from rig.runner.stand_run import SUMMARY_NAME, RunReport
from rig.runner.sweep import show_progress
from rig.scenes.characteristics_scene import CharacteristicsScene

CSV_NAME = "characteristics.csv"
FIGURE_NAME = "characteristics.png"


def run_characteristics_scene(scene: CharacteristicsScene, out_dir: Path, *, progress: bool | None = None) -> RunReport:
    """Evaluate every model over the scene's cases and alpha' values; write the outputs into ``out_dir``."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    total = len(scene.cases) * (len(scene.models) + len(scene.variants)) * len(scene.alphas)
    with tqdm(total=total, desc=f"scene {scene.name}", disable=not show_progress(progress)) as bar:
        table = sweep(scene.cases, scene.models, scene.alphas, poisson=scene.poisson, n=scene.n,
                      effects=dict(scene.effects), variants=scene.variants, progress=lambda k, _: bar.update(k - bar.n))
    table.to_csv(out_dir / CSV_NAME, index=False)
    files = [CSV_NAME]
    if scene.outputs.figures:
        plot(table, out_dir / FIGURE_NAME, f"{scene.description} (poisson {scene.poisson:g})")
        files.append(FIGURE_NAME)
    files.append(SUMMARY_NAME)
    text = "\n".join([
        "friction-rig run summary",
        f"scene:       {scene.name} ({scene.source})",
        f"             {scene.description}",
        "kind:        contact characteristics (no stand)",
        f"models:      {', '.join(scene.models)}; n = {scene.n}; poisson {scene.poisson:g}; "
        f"effects: {', '.join(f'{k} = {v:g}' for k, v in scene.effects.items()) or 'none'}",
        *([f"variants:    {', '.join(scene.variants)} (kinematic model)"] if scene.variants else []),
        f"alpha':      {len(scene.alphas)} values {min(scene.alphas):g} .. {max(scene.alphas):g}",
        "cases:       " + "; ".join(case.label for case in scene.cases),
        f"evaluated:   {len(table)} contact solves",
        f"outputs:     {', '.join(files)}",
    ]) + "\n"
    (out_dir / SUMMARY_NAME).write_text(text, encoding="utf-8")
    return RunReport(out_dir, tuple(files), total, len(table), 0, (), False, text)
