"""Where ViZDoom's scenarios are: the ``.cfg`` files and WADs that the
``vizdoom`` package ships. Sightline does not ship them (they are
ViZDoom's); it finds them in ``SIGHTLINE_VIZDOOM_DIR``, else in an
installed ``vizdoom`` package, else in a Sightline checkout's
``target/vizdoom/scenarios`` (``scripts/vizdoom-scenarios.sh`` unpacks
them there from the ``vizdoom`` wheel)."""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path


def _candidates() -> list:
    found = []
    given = os.environ.get("SIGHTLINE_VIZDOOM_DIR")
    if given:
        found.append(Path(given))
    spec = importlib.util.find_spec("vizdoom")
    if spec is not None and spec.submodule_search_locations:
        for root in spec.submodule_search_locations:
            found.append(Path(root) / "scenarios")
    here = Path(__file__).resolve()
    for parent in here.parents:
        found.append(parent / "target" / "vizdoom" / "scenarios")
    return found


def _find() -> str:
    for path in _candidates():
        if (path / "basic.cfg").is_file():
            return str(path)
    return ""


scenarios_path = _find()
"""The folder holding ViZDoom's scenarios, or "" if none was found."""

wads = sorted(f for f in os.listdir(scenarios_path) if f.endswith(".wad")) if scenarios_path else []
configs = sorted(f for f in os.listdir(scenarios_path) if f.endswith(".cfg")) if scenarios_path else []


def scenario_path(name: str) -> str:
    """The path of ViZDoom's scenario ``name`` (``basic``, ``basic.cfg``),
    or a ``FileNotFoundError`` saying where it was looked for."""
    file = name if name.endswith(".cfg") else f"{name}.cfg"
    if scenarios_path and os.path.isfile(os.path.join(scenarios_path, file)):
        return os.path.join(scenarios_path, file)
    looked = ", ".join(str(p) for p in _candidates())
    raise FileNotFoundError(
        f"ViZDoom's scenario {file} is not here (looked in {looked}); "
        "install the vizdoom package, or set SIGHTLINE_VIZDOOM_DIR to a folder holding its scenarios"
    )
