"""The house rules of the layout, as tests (README "Layout", developers' guide).

- ``rig.contact`` knows nothing of stands, instruments, logs or runs: importing it loads no
  ``sensors`` module, and no contact module imports ``rig.stands``, ``rig.logbook``,
  ``rig.runner``, ``rig.scenes``, ``rig.campaigns``, ``rig.reduction`` or ``sensors``;
- ``sensors`` knows nothing of ``rig``; ``paramcheck`` (the shared errors and argument checks)
  knows neither;
- nothing installed imports ``experiments`` or ``studies`` (scripts that use rig, never imported by it);
- rig's sub-packages import each other without cycles.

The import graph is read from the source (every import statement, function-level ones included),
so a lazy import inside a function cannot hide a broken rule.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("rig", "sensors", "paramcheck")
OURS = PACKAGES + ("experiments", "studies")


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(path): path for package in PACKAGES for path in sorted((ROOT / package).rglob("*.py"))}


def _imported(name: str, path: Path) -> set[str]:
    """Modules of ours that ``path`` imports (``from p import m`` counts as p.m when m is a module)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            found.add(base)
            found |= {f"{base}.{alias.name}" for alias in node.names if f"{base}.{alias.name}" in MODULES}
    return {module for module in found if module.split(".")[0] in OURS}


GRAPH = {name: _imported(name, path) for name, path in MODULES.items()}


def _within(module: str, prefix: str) -> bool:
    return module == prefix or module.startswith(prefix + ".")


def _violations(source: str, forbidden: tuple[str, ...]) -> list[str]:
    return sorted(f"{name} imports {target}" for name, targets in GRAPH.items() if _within(name, source)
                  for target in targets if any(_within(target, f) for f in forbidden))


def test_the_graph_sees_the_packages():
    assert {"rig.contact.solve", "sensors.counters", "paramcheck.errors"} <= set(GRAPH)
    assert "rig.contact.kalker" in GRAPH["rig.contact.solve"]  # the reader works (a rule on an empty graph passes)


@pytest.mark.parametrize("source, forbidden", [
    ("rig.contact", ("rig.stands", "rig.logbook", "rig.runner", "rig.scenes", "rig.campaigns", "rig.reduction",
                     "rig.cli", "sensors")),
    ("sensors", ("rig",)),
    ("paramcheck", ("rig", "sensors")),
    ("rig", ("experiments", "studies")),
    ("sensors", ("experiments", "studies")),
])
def test_layers_import_only_downwards(source, forbidden):
    assert _violations(source, forbidden) == []


def _subpackage(module: str) -> str:
    return ".".join(module.split(".")[:2])


def test_rig_subpackages_have_no_import_cycle():
    edges: dict[str, set[str]] = {}
    for name, targets in GRAPH.items():
        if _within(name, "rig"):
            for target in targets:
                a, b = _subpackage(name), _subpackage(target)
                if a != b and _within(b, "rig") and b != "rig":
                    edges.setdefault(a, set()).add(b)
    cycles = []

    def visit(node, trail):
        for nxt in sorted(edges.get(node, ())):
            if nxt in trail:
                cycles.append(trail[trail.index(nxt):] + [nxt])
            elif len(trail) < len(edges) + 1:
                visit(nxt, trail + [nxt])

    for start in sorted(edges):
        visit(start, [start])
    assert cycles == [], cycles[:3]


def test_importing_the_contact_model_loads_no_instrument_and_no_stand():
    code = ("import sys, rig.contact; from rig.contact import solve; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'sensors' or m.startswith(('rig.stands', "
            "'rig.logbook', 'rig.runner', 'rig.scenes'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.strip() == "[]"


def test_from_rig_contact_import_solve_gives_the_function():
    from rig.contact import solve
    from rig.contact.solve import solve as same

    assert callable(solve) and solve is same
    assert solve("rigid", shape="ellipse", b_over_a=1.0, alpha=0.0, c_over_a=0.0, l_over_a=0.0,
                 poisson=0.3, n=64).nu_0 == pytest.approx(0.58905, abs=2e-3)  # 3 pi/16, Equations §1.10(a)


def test_the_scene_format_and_the_campaigns_name_the_same_figures():
    from rig.campaigns import PAPER_FIGURES
    from rig.scenes.stand_scene import PAPER_FIGURE_NAMES

    assert tuple(PAPER_FIGURES) == PAPER_FIGURE_NAMES
