"""Scenarios made in Python, without ACS.

ViZDoom's scenarios are WADs whose rewards are ACS scripts written in a
Doom editor. Here a scenario is a RON map (written by
:class:`sightline.maps.Map`, or any RON map's text or file) and a reward
specification, a dictionary of what each event pays:

``kill``
    per monster killed;
``pickup``
    per item picked up: a number for every item, or
    ``{"each": 0.0, "kinds": {"medikit": 1.0}}`` by kind (the actor
    table's names);
``damage_taken``
    per point of health lost (negative for a penalty);
``reach``
    ``[{"sector": 3, "reward": 10.0, "end": True}]``: entering a sector,
    paid once an episode; ``end`` ends the episode there;
``secret``
    per secret sector found;
``exit``
    on leaving the level (an exit line), which ends the episode;
``living``
    per tic; ``death`` on dying (negative for a penalty);
``timeout``
    the episode's length in tics (0: none).

Every number is added to the reward when its event happens, so a penalty
is negative (ViZDoom's ``death_penalty`` is subtracted; this one rule is
for every event). The events are read off the simulation each tic (the
player's counts, ViZDoom's tallies, the body's sector), and an event that
pays nothing costs nothing.

:func:`make_scenario` returns a :class:`Scenario`; play it through
``DoomGame``'s API (:meth:`Scenario.doom_game`), Gymnasium
(``SightlineEnv(scenario)``, :meth:`Scenario.env`) or the vector
environment (``SightlineVectorEnv(scenario, n)``). :func:`check` is
``sightline check`` on a map: its findings as :class:`Finding` values.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from typing import Any, Optional, Sequence

from . import _native
from ._enums import Button, GameVariable, ScreenResolution
from .vizdoom import ConfigError, DoomGame, _enum_name

__all__ = ["DEFAULT_BUTTONS", "Finding", "MadeGame", "Scenario", "check", "make_scenario"]

DEFAULT_BUTTONS = (
    Button.MOVE_FORWARD,
    Button.MOVE_BACKWARD,
    Button.MOVE_LEFT,
    Button.MOVE_RIGHT,
    Button.TURN_LEFT,
    Button.TURN_RIGHT,
    Button.ATTACK,
    Button.USE,
)
"""The buttons a made scenario has when :func:`make_scenario` is given none."""


@dataclass(frozen=True)
class Finding:
    """One thing :func:`check` says of a map: ``severity`` is ``"error"``
    (the map does not load, or the rewards name what is not there),
    ``"warning"`` (something cannot be reached or can never pay) or
    ``"note"``."""

    severity: str
    message: str

    def __str__(self) -> str:
        return f"{self.severity}: {self.message}"


def _looks_like_ron(text: str) -> bool:
    head = text.lstrip()
    return "\n" in text or head.startswith(("Map", "GridMap", "(", "//", "/*"))


def _map_arguments(map: Any, art: Optional[str]) -> dict:
    """The native calls' map arguments for a :class:`sightline.maps.Map`,
    RON text, or a path."""
    art = os.fspath(art) if art is not None else None
    if hasattr(map, "to_ron"):
        return {"text": map.to_ron(), "label": f"<map {getattr(map, 'name', '')!r}>", "art": art}
    if isinstance(map, os.PathLike):
        return {"path": os.fspath(map)}
    if isinstance(map, str):
        if _looks_like_ron(map):
            return {"text": map, "label": "<map text>", "art": art}
        return {"path": map}
    raise TypeError(f"a map is a sightline.maps.Map, RON text or a path, not {type(map).__name__}")


def _plain(value: Any) -> Any:
    # numpy's numbers and the like, for json.
    if hasattr(value, "item"):
        return value.item()
    raise TypeError(f"{value!r} is not a number, string, list or dict")


def _check_finite(value: Any, path: str) -> None:
    """NaN and infinities have no JSON: refused here, by element."""
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, f'{path}["{k}"]' if path.endswith("kinds") else f"{path}.{k}")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _check_finite(v, f"{path}[{i}]")
    elif isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{path}: {value} is not a finite number")


def _rewards_text(rewards: Any, timeout: Optional[int]) -> str:
    """The specification as the engine reads it (JSON, or RON as given)."""
    if rewards is None:
        rewards = {}
    if isinstance(rewards, str):
        if timeout is None:
            return rewards
        if not rewards.lstrip().startswith("{"):
            raise ValueError("timeout: give it in the RON rewards (timeout: N) when they are RON text")
        rewards = json.loads(rewards)
    if not isinstance(rewards, dict):
        raise TypeError(f"rewards are a dict or RON/JSON text, not {type(rewards).__name__}")
    if timeout is not None:
        if "timeout" in rewards and rewards["timeout"] != timeout:
            raise ValueError(f"timeout: given twice, {timeout} and rewards' {rewards['timeout']}")
        rewards = {**rewards, "timeout": timeout}
    _check_finite(rewards, "rewards")
    return json.dumps(rewards, default=_plain)


def check(map: Any, rewards: Any = None, skill: int = 3, art: Optional[str] = None) -> list:
    """What ``sightline check`` says of ``map`` (a
    :class:`sightline.maps.Map`, RON text or a path) played at ``skill``:
    a list of :class:`Finding`, errors first. A map that does not load
    gives its errors (each validation problem on its own); one that does,
    what cannot be reached (the exit, keys, secrets, items) and soft
    locks. With ``rewards``, also what in them can never pay (a goal
    sector out of reach, a kill reward and no monster). ``art`` is a
    folder holding ``textures/``, ``flats/``, ``sprites/`` for map text."""
    text = None if rewards is None else _rewards_text(rewards, None)
    pairs = _native.check_map(rewards=text, skill=int(skill), **_map_arguments(map, art))
    return [Finding(s, m) for s, m in pairs]


def _resolution_name(resolution: Any) -> str:
    if isinstance(resolution, (tuple, list)) and len(resolution) == 2:
        name = f"RES_{int(resolution[0])}X{int(resolution[1])}"
        if name not in ScreenResolution.__members__:
            sizes = ", ".join(n[4:].lower() for n in ScreenResolution.__members__)
            raise ConfigError(f"resolution {resolution[0]}x{resolution[1]} is not one of ViZDoom's: {sizes}")
        return name
    return _enum_name(ScreenResolution, resolution)


# The DoomGame setters whose values a made scenario's rewards decide.
_SPEC_SETTERS = {
    "set_living_reward": "living",
    "set_death_penalty": "death",
    "set_death_reward": "death",
    "set_kill_reward": "kill",
    "set_secret_reward": "secret",
    "set_damage_taken_penalty": "damage_taken",
    "set_damage_taken_reward": "damage_taken",
    "set_map_exit_reward": "exit",
    "set_episode_timeout": "timeout",
}


class MadeGame(DoomGame):
    """ViZDoom's ``DoomGame`` on a made scenario: the scenario's settings
    applied, its rewards over ViZDoom's (``get_living_reward`` and the
    rest read them; their setters refuse, naming the reward to set in the
    specification instead). Call :meth:`init` as for any ``DoomGame``."""

    def __init__(self, scenario: "Scenario") -> None:
        super().__init__()
        self._scenario = scenario
        for setter, value in scenario._setup:
            getattr(self, setter)(value)
        scenario._native.configure(self._config)

    def _open(self) -> "_native.Game":
        self._scenario._native.configure(self._config)
        return self._scenario._native.game(self._config)

    def _open_games(self, count: int, threads: int = 0) -> "_native.Games":
        self._scenario._native.configure(self._config)
        return self._scenario._native.games(self._config, count, threads=threads)

    def __getattr__(self, name: str) -> Any:
        if name in _SPEC_SETTERS:
            key = _SPEC_SETTERS[name]

            def refuse(*_: Any) -> None:
                raise ConfigError(f"{name}: a made scenario's rewards are its specification's: give rewards[{key!r}]")

            return refuse
        return super().__getattr__(name)


class Scenario:
    """A scenario made by :func:`make_scenario`: its map opened once, its
    rewards checked against it, its settings. Each :meth:`doom_game` or
    environment plays it afresh."""

    def __init__(self, native: "_native.MadeScenario", setup: list, map_text: Optional[str]):
        self._native = native
        self._setup = setup
        self.map_text = map_text
        """The map's RON text (None for a map read from a file)."""

    @property
    def rewards(self) -> str:
        """The reward specification as the engine read it, in RON."""
        return self._native.rewards()

    @property
    def sectors(self) -> int:
        """How many sectors the map has."""
        return self._native.sectors()

    def doom_game(self) -> MadeGame:
        """A ``DoomGame`` of this scenario, not yet started (call ``init``)."""
        return MadeGame(self)

    def env(self, **kwargs: Any) -> Any:
        """A Gymnasium environment of this scenario (``SightlineEnv``'s
        keyword arguments: ``frame_skip``, ``max_buttons_pressed``,
        ``render_mode``, ``DoomGame`` setters)."""
        from .gym import SightlineEnv

        return SightlineEnv(self, **kwargs)

    def check(self, skill: Optional[int] = None) -> list:
        """:func:`check` on this scenario's map and rewards (at its skill
        unless ``skill`` is given)."""
        if skill is None:
            skill = self.doom_game().get_doom_skill()
        return [Finding(s, m) for s, m in self._native.check(int(skill))]


def make_scenario(
    map: Any,
    rewards: Any = None,
    *,
    buttons: Optional[Sequence[Any]] = None,
    variables: Optional[Sequence[Any]] = None,
    resolution: Any = None,
    timeout: Optional[int] = None,
    skill: Optional[int] = None,
    art: Optional[str] = None,
    **settings: Any,
) -> Scenario:
    """A scenario of ``map`` (a :class:`sightline.maps.Map`, RON text or a
    path) paying ``rewards`` (a dict, or RON/JSON text: see this module's
    docs). ``buttons`` (``Button`` values or names; default
    :data:`DEFAULT_BUTTONS`), ``variables`` (``GameVariable`` values or
    names), ``resolution`` (a ``ScreenResolution``, its name, or
    ``(width, height)``), ``timeout`` (tics; the same as
    ``rewards["timeout"]``), ``skill`` (1 to 5, default 3); other keyword
    arguments call the ``DoomGame`` setter of that name
    (``screen_format="GRAY8"``, ``render_hud=True``).

    A map that does not load, or rewards that name what is not there (a
    sector past the map's, an unknown item kind, a negative timeout), raise
    ``ValueError`` naming the element (``rewards.reach[0].sector: ...``);
    a missing map file ``FileNotFoundError``."""
    arguments = _map_arguments(map, art)
    native = _native.MadeScenario(_rewards_text(rewards, timeout), **arguments)
    setup: list = [
        ("set_available_buttons", [_enum_name(Button, b) for b in (DEFAULT_BUTTONS if buttons is None else buttons)]),
    ]
    if variables is not None:
        setup.append(("set_available_game_variables", [_enum_name(GameVariable, v) for v in variables]))
    if resolution is not None:
        setup.append(("set_screen_resolution", _resolution_name(resolution)))
    if skill is not None:
        setup.append(("set_doom_skill", skill))
    for key, value in settings.items():
        setter = f"set_{key}"
        if setter in _SPEC_SETTERS:
            spec = _SPEC_SETTERS[setter]
            raise ConfigError(f"{key}: a made scenario's rewards are its specification's: give rewards[{spec!r}]")
        setup.append((setter, value))
    scenario = Scenario(native, setup, arguments.get("text"))
    scenario.doom_game()  # every setting checked now, by the setters' own checks
    return scenario
