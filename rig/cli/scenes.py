"""``rig scenes``: list the built-in scenes, one line each (name and description)."""

from __future__ import annotations

from rig.scenes.locate import builtin_scenes


def add_parser(subparsers) -> None:
    """Register ``rig scenes``."""
    parser = subparsers.add_parser("scenes", help="list the built-in scenes, one line each",
                                   description="List the built-in scenes (shipped in rig/scenes/builtin/, or $RIG_SCENES_DIR).")
    parser.set_defaults(handler=main)


def main(args) -> int:
    scenes = builtin_scenes()
    width = max((len(s.name) for s in scenes), default=0)
    for scene in scenes:
        print(f"{scene.name:<{width}}  {scene.description}")
    return 0
