"""A contact-characteristics scene: nu_T, nu_v, nu_0 versus alpha' with rig.characteristics (no stand).

Outputs in the folder: characteristics.csv (one row per case, model and alpha'),
characteristics.png (the models overlaid, one row of panels per case) and summary.txt. One
writer per folder (its lock), and never into the folder of another kind of run.
"""

from __future__ import annotations

from pathlib import Path

from tqdm import tqdm

from rig.characteristics import plot, sweep
from rig.logbook.atomic import naming
from rig.runner.outputs import CHARACTERISTICS_CSV as CSV_NAME
from rig.runner.outputs import CHARACTERISTICS_FIGURE as FIGURE_NAME
from rig.runner.folder_lock import folder_lock
from rig.runner.outputs import CHARACTERISTICS_KIND, SUMMARY_NAME, claim_folder, output_folder, staged_outputs
from rig.runner.stand_run import RunReport
from rig.runner.sweep import show_progress
from rig.scenes.characteristics_scene import CharacteristicsScene


def run_characteristics_scene(scene: CharacteristicsScene, out_dir: Path, *, progress: bool | None = None) -> RunReport:
    """Evaluate every model over the scene's cases and alpha' values; write the outputs into ``out_dir``
    (holding its lock, rig.runner.folder_lock; a folder of another kind of run is refused)."""
    out_dir = output_folder(out_dir)
    with folder_lock(out_dir, f"rig run {scene.name}"):
        claim_folder(out_dir, CHARACTERISTICS_KIND)
        return _run_locked(scene, out_dir, progress)


def _run_locked(scene: CharacteristicsScene, out_dir: Path, progress: bool | None) -> RunReport:
    total = len(scene.cases) * (len(scene.models) + len(scene.variants)) * len(scene.alphas)
    with tqdm(total=total, desc=f"scene {scene.name}", disable=not show_progress(progress)) as bar:
        table = sweep(scene.cases, scene.models, scene.alphas, poisson=scene.poisson, n=scene.n,
                      effects=dict(scene.effects), variants=scene.variants, progress=lambda k, _: bar.update(k - bar.n))
    with staged_outputs(out_dir, replace_previous=True) as staging:
        text = _write_outputs(scene, table, total, staging)
    return RunReport(out_dir, tuple(_files(scene)), total, len(table), 0, (), False, text)


def _files(scene: CharacteristicsScene) -> list[str]:
    return [CSV_NAME, *([FIGURE_NAME] if scene.outputs.figures else []), SUMMARY_NAME]


def _write_outputs(scene: CharacteristicsScene, table, total: int, staging: Path) -> str:
    """Write the CSV, the figure and summary.txt into ``staging``; returns the summary text."""
    table.to_csv(staging / CSV_NAME, index=False)
    if scene.outputs.figures:
        with naming(staging.parent / FIGURE_NAME):
            plot(table, staging / FIGURE_NAME, f"{scene.description} (poisson {scene.poisson:g})")
    files = _files(scene)
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
    (staging / SUMMARY_NAME).write_text(text, encoding="utf-8")
    return text
