"""Sightline, a Doom engine, in-process for Python.

- :mod:`sightline.vizdoom`: ViZDoom's ``DoomGame`` API on Sightline
  (``import sightline.vizdoom as vzd`` in place of ``import vizdoom as vzd``).
- :mod:`sightline.gym`: Gymnasium environments for every scenario
  (``gymnasium.make("Sightline/Basic-v0")``) and a native vector environment.
- :func:`make_scenario`, :func:`check` and :mod:`sightline.maps`:
  scenarios made in Python from a RON map and a reward specification,
  without ACS (:mod:`sightline.made`).

The engine runs in this process: no executable, no message queue, no
window; games step with the interpreter lock released.
"""

from . import maps
from ._native import Config, Game, Games, __version__
from .made import Finding, Scenario, check, make_scenario
from .scenarios import scenario_path, scenarios_path

__all__ = [
    "Config",
    "Finding",
    "Game",
    "Games",
    "Scenario",
    "__version__",
    "check",
    "make_scenario",
    "maps",
    "scenario_path",
    "scenarios_path",
]

try:  # Register the Gymnasium ids when Gymnasium is installed.
    from . import gym as _gym  # noqa: F401
except ImportError as _e:  # pragma: no cover - only without gymnasium
    if "gymnasium" not in str(_e):
        raise
