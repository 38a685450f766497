"""PettingZoo environments: several agents in one game, one process.

ViZDoom runs a multiplayer game as a ZDoom netgame, one engine process per
agent; here every agent's action goes into the same tic of one simulation
(:class:`sightline.MultiGame`), and each agent sees the game from its own
eyes. :class:`SightlineParallelEnv` is PettingZoo's ``ParallelEnv`` on any
scenario with room for several players (``multi_duel``, ``multi``,
``cig``, ``deathmatch``), and :func:`deathmatch_env` plays deathmatch on a
Doom WAD's own map (Debian's ``freedm`` by default).

Agents are ``player_0`` ... ``player_{n-1}``, 1 to 16 of them (ViZDoom's
limit): a game of up to four plays by Doom's rules exactly, and players past
a map's starts spawn at the other starts or beside them (players 5 to 16 have
colours of their own). A dead agent comes back on its next action, as
after ViZDoom's ``respawn_player``; no agent leaves before the episode
ends. The episode is *truncated* at ``max_cycles`` steps (default: the
``.cfg``'s ``episode_timeout``, else 2,100) and *terminated* if the level
is left.
"""

from __future__ import annotations

import os
from typing import Any, Optional

import gymnasium as gym
import numpy as np
from pettingzoo import ParallelEnv

from . import _native
from .gym import _configured_game, _Spec
from .vizdoom import DoomGame, FileDoesNotExistException

__all__ = ["SightlineParallelEnv", "deathmatch_env", "parallel_env"]

DEFAULT_MAX_CYCLES = 2100


class SightlineParallelEnv(ParallelEnv):
    """``num_agents`` agents in one game of ``config_file`` (a ``.cfg`` path
    or the name of one of ViZDoom's). ``deathmatch``: 1 deathmatch, 2
    altdeath, 0 co-operative. Other keyword arguments call the
    ``DoomGame`` setter of that name (``screen_resolution="RES_160X120"``)."""

    metadata = {"render_modes": ["rgb_array"], "name": "sightline_v0", "is_parallelizable": True}

    def __init__(
        self,
        config_file: Optional[str] = "multi_duel",
        num_agents: int = 2,
        deathmatch: int = 1,
        frame_skip: int = 1,
        max_cycles: Optional[int] = None,
        max_buttons_pressed: int = 0,
        render_mode: Optional[str] = None,
        game: Optional[DoomGame] = None,
        **kwargs: Any,
    ):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode {render_mode!r} is not one of {self.metadata['render_modes']}")
        if frame_skip < 1:
            raise ValueError(f"frame_skip must be at least 1, not {frame_skip}")
        self.render_mode = render_mode
        self.frame_skip = frame_skip
        settings = game if game is not None else _configured_game(config_file, kwargs)
        self._spec = _Spec(settings, max_buttons_pressed)
        for extra in ("automap", "depth", "labels"):
            if extra in self._spec.observation_space.spaces:
                raise NotImplementedError(f"the multi-agent environment gives the screen and game variables, not the {extra}")
        timeout = settings.get_episode_timeout()
        self.max_cycles = max_cycles if max_cycles is not None else (timeout or DEFAULT_MAX_CYCLES)
        try:
            self._game = _native.MultiGame(settings._config, num_agents, deathmatch)
        except FileNotFoundError as e:
            raise FileDoesNotExistException(str(e)) from None
        self.possible_agents = [f"player_{i}" for i in range(num_agents)]
        self.agents: list = []
        self._rng = np.random.default_rng()
        self._cycles = 0
        self._last: Optional[dict] = None

    def observation_space(self, agent: str) -> gym.Space:
        return self._spec.observation_space

    def action_space(self, agent: str) -> gym.Space:
        return self._spec.action_space

    def _observe(self) -> dict:
        screens = self._game.screens()
        if screens.ndim == 3:
            screens = screens[..., None]
        variables = None
        if "gamevariables" in self._spec.observation_space.spaces:
            variables = self._game.game_variables().astype(np.float32)
        out = {}
        for i, agent in enumerate(self.possible_agents):
            obs = {"screen": screens[i]}
            if variables is not None:
                obs["gamevariables"] = variables[i]
            out[agent] = obs
        self._last = out
        return out

    def reset(self, seed: Optional[int] = None, options: Optional[dict] = None):
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self._game.new_episode(int(self._rng.integers(0, 2**31 - 1)))
        self.agents = list(self.possible_agents)
        self._cycles = 0
        return self._observe(), {a: {} for a in self.agents}

    def step(self, actions: dict):
        if not self.agents:
            raise RuntimeError("the episode is over: call reset()")
        missing = [a for a in self.agents if a not in actions]
        if missing:
            raise ValueError(f"no action for {', '.join(missing)}: every live agent acts each step")
        rows = np.array([self._spec.to_buttons(actions[a]) for a in self.possible_agents], dtype=np.float64)
        rewards = self._game.step(rows, self.frame_skip)
        self._cycles += 1
        obs = self._observe()
        exited = self._game.end() == "exit"
        truncated = not exited and (self._cycles >= self.max_cycles or self._game.end() == "timeout")
        agents = list(self.agents)
        terminations = {a: exited for a in agents}
        truncations = {a: truncated for a in agents}
        reward = {a: float(rewards[i]) for i, a in enumerate(self.possible_agents)}
        infos = {a: {"dead": self._game.is_player_dead(i)} for i, a in enumerate(self.possible_agents)}
        if exited or truncated:
            self.agents = []
        return obs, reward, terminations, truncations, infos

    def render(self):
        if self.render_mode != "rgb_array" or self._last is None:
            return None
        screens = [self._last[a]["screen"] for a in self.possible_agents]
        screens = [np.repeat(s, 3, axis=2) if s.shape[2] == 1 else s for s in screens]
        return np.concatenate(screens, axis=1)

    def close(self):
        self._game = None

    def state(self) -> np.ndarray:
        screens = self._game.screens()
        return screens


def parallel_env(**kwargs: Any) -> SightlineParallelEnv:
    """PettingZoo's usual constructor name."""
    return SightlineParallelEnv(**kwargs)


DEATHMATCH_BUTTONS = [
    "ATTACK",
    "USE",
    "MOVE_FORWARD",
    "MOVE_BACKWARD",
    "MOVE_LEFT",
    "MOVE_RIGHT",
    "TURN_LEFT",
    "TURN_RIGHT",
    "SPEED",
]


def deathmatch_env(
    wad: str = "freedm.wad",
    map: str = "MAP01",
    num_agents: int = 4,
    screen_resolution: str = "RES_160X120",
    timeout: int = 4200,
    frag_reward: float = 1.0,
    death_penalty: float = 1.0,
    **kwargs: Any,
) -> SightlineParallelEnv:
    """Deathmatch on map ``map`` of ``wad`` (found where Doom ports look:
    ``/usr/share/games/doom`` and the rest; Debian's ``freedm`` package
    installs ``freedm.wad``), ``num_agents`` agents, ``timeout`` tics, a
    frag worth ``frag_reward`` and a death ``-death_penalty``."""
    path = wad if os.path.isfile(wad) else _find_wad(wad)
    game = DoomGame()
    game.set_config(
        {
            "doom_game_path": path,
            "doom_map": map,
            "doom_skill": 3,
            "screen_resolution": screen_resolution,
            "screen_format": "RGB24",
            "episode_timeout": timeout,
            "frag_reward": frag_reward,
            "death_penalty": death_penalty,
            "available_buttons": DEATHMATCH_BUTTONS,
            "available_game_variables": ["HEALTH", "ARMOR", "FRAGCOUNT", "SELECTED_WEAPON_AMMO"],
        }
    )
    return SightlineParallelEnv(None, num_agents=num_agents, game=game, **kwargs)


def _find_wad(name: str) -> str:
    dirs = [os.environ.get("DOOMWADDIR", "")]
    dirs += os.environ.get("DOOMWADPATH", "").split(os.pathsep)
    dirs += ["/usr/local/share/games/doom", "/usr/share/games/doom", "/usr/share/doom"]
    for d in dirs:
        if d and os.path.isfile(os.path.join(d, name)):
            return os.path.join(d, name)
    raise FileDoesNotExistException(
        f"{name}: not found in $DOOMWADDIR, $DOOMWADPATH or /usr/share/games/doom (Debian: apt-get install freedm)"
    )
