"""Sphinx configuration of the friction-rig documentation site.

Build (from the repository root; offline, warnings are errors, every gallery example is executed):

    .venv/bin/pip install -e ".[docs]" && .venv/bin/python -m sphinx -W --keep-going -b html docs docs/_build/html
"""

from __future__ import annotations

import atexit
import os
import re
import shutil
import sys
import tempfile
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS))  # gallery_scrapers.py
os.environ.setdefault("MPLBACKEND", "Agg")

from gallery_scrapers import TutorialOutputs  # noqa: E402

project = "friction-rig"
author = "the friction-rig developers"
copyright = "the friction-rig developers, MIT licence"
release = version = "0.1.0"

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store", "sg_execution_times.rst", "accuracy-contact-sweep.md", "gallery/**/*.ipynb", "gallery/**/*.py",
                    "gallery/**/*.md5", "gallery/**/*.zip", "gallery/**/*.json"]
templates_path = ["_templates"]

# Markdown: the existing docs/*.md stay Markdown.
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 3
# Heading levels are the authors' choice in the Markdown pages (some skip a level for small headings).
suppress_warnings = ["myst.header"]

# API reference: autosummary over each package's __all__, numpydoc docstrings.
autosummary_generate = True
autosummary_ignore_module_all = False
autosummary_imported_members = False
autodoc_default_options: dict[str, object] = {}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()

# Offline: no intersphinx, no CDN. No page uses maths, so MathJax is never loaded; if one ever does, the
# path below (a local file) makes the build fail visibly instead of loading a script from another host.
mathjax_path = "mathjax-not-vendored.js"

html_theme = "furo"
html_title = "friction-rig"
html_static_path: list[str] = []
html_show_sourcelink = False
html_theme_options = {"navigation_with_keys": True}

# The gallery: the tutorial steps and the virtual experiments in experiments/, executed at build time.
_GALLERY_OUT = Path(tempfile.mkdtemp(prefix="friction-rig-gallery-"))  # the examples' output folders
atexit.register(shutil.rmtree, _GALLERY_OUT, True)
_tutorial_outputs = TutorialOutputs(_GALLERY_OUT)

sphinx_gallery_conf = {
    "examples_dirs": [str(ROOT / "experiments")],
    "gallery_dirs": ["gallery"],
    # Only the gallery's scripts (the user-facing experiments and the tutorial); development studies are not.
    "filename_pattern": r".*\.py$",
    "ignore_pattern": _tutorial_outputs.ignore_pattern,
    "within_subsection_order": "FileNameSortKey",
    "reset_argv": _tutorial_outputs.argv,
    "image_scrapers": ("matplotlib", _tutorial_outputs),
    "abort_on_example_error": False,
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "remove_config_comments": True,
    "show_memory": False,
    "plot_gallery": "True",
    "matplotlib_animations": False,
    "line_numbers": False,
    "capture_repr": (),
    "promote_jupyter_magic": False,
    "first_notebook_cell": None,
    "copyfile_regex": "",
    "write_computation_times": False,  # its pages load scripts from a CDN
}


# Docstrings are written as plain text with mathematical bars (|F|, |strain|): escape them so that
# reStructuredText does not read them as substitutions. Table rows (lines starting with "|" or "+") stay.
_BAR = re.compile(r"(?<!\\)\|")


def _escape_bars(app, what, name, obj, options, lines):
    for i, line in enumerate(lines):
        if not line.lstrip().startswith(("|", "+")):
            lines[i] = _BAR.sub(r"\\|", line)


def setup(app):
    app.connect("autodoc-process-docstring", _escape_bars)
