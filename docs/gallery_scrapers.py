"""Sphinx-gallery helpers for docs/conf.py: which scripts are examples, their command line, their figures.

The tutorial steps and the virtual experiments in experiments/ are ordinary command-line scripts that write
their figure as a PNG into an output folder (``-o DIR``). In the gallery each runs with its output folder in a
temporary directory, and the PNGs it wrote are shown under the code block that wrote them. Scripts that draw
with pyplot are shown by sphinx-gallery's own matplotlib scraper.
"""

from __future__ import annotations

import shutil
from pathlib import Path

# The scripts of experiments/ that are gallery examples (file stems; regular expressions). Everything else in
# experiments/ (development studies) is left out of the gallery.
GALLERY_SCRIPTS = (r"first_virtual_experiment", r"compare_and_fit", r"gate_time", r"step\d\d_[a-z0-9_]+")


class TutorialOutputs:
    """Command line and image scraper for the gallery's scripts (picklable, so Sphinx can cache the config)."""

    def __init__(self, out_dir: Path) -> None:
        self.out_dir = Path(out_dir)
        self._seen: set[Path] = set()

    def __repr__(self) -> str:  # Sphinx compares configurations by repr
        return "TutorialOutputs()"

    @property
    def ignore_pattern(self) -> str:
        return r"^(?!(" + "|".join(GALLERY_SCRIPTS) + r")\.py$)"

    def folder(self, src_file: str | Path) -> Path:
        return self.out_dir / Path(src_file).stem

    def argv(self, gallery_conf: dict, script_vars: dict) -> list[str]:
        """``sys.argv[1:]`` for an example: its output folder in the temporary directory."""
        src_file = Path(script_vars["src_file"])
        folder = self.folder(src_file)
        folder.mkdir(parents=True, exist_ok=True)
        if src_file.stem == "gate_time":
            return ["--out", str(folder)]
        if src_file.stem.startswith("step"):
            return ["-o", str(folder)]
        return []

    def __call__(self, block, block_vars: dict, gallery_conf: dict) -> str:
        """Show the PNGs the block wrote into the example's output folder (each once)."""
        from sphinx_gallery.scrapers import figure_rst

        folder = self.folder(block_vars["src_file"])
        if not folder.is_dir():
            return ""
        new = sorted(p for p in folder.rglob("*.png") if p not in self._seen)
        images = []
        for png, target in zip(new, block_vars["image_path_iterator"]):
            shutil.copyfile(png, target)
            self._seen.add(png)
            images.append(target)
        return figure_rst(images, gallery_conf["src_dir"]) if images else ""
