"""Gymnasium environments on Sightline's scenarios.

``gymnasium.make("Sightline/Basic-v0")`` plays ViZDoom's Basic scenario:
each ``.cfg`` of ViZDoom's gets an id by its name in CamelCase, in two
action forms as ViZDoom's own wrapper registers them:

- ``Sightline/<Name>-v0``: one button pressed at a time (``Discrete``,
  the choice "none" included);
- ``Sightline/<Name>-MultiBinary-v0``: any buttons together
  (``MultiBinary``).

Delta buttons (turns and moves by a value) are a ``Box`` beside them, in a
``Dict`` action space with keys ``binary`` and ``continuous``.

The autopilot is an expert to imitate: ``env.expert_action()`` is what it
would do now, in the environment's action space, and an environment made
with ``expert=True`` also puts it in ``info["expert_action"]`` at every
reset and step (``SightlineVectorEnv.expert_actions()`` for many games).

Observations are a ``Dict``: ``screen`` (height, width, channels; RGB24
unless the ``.cfg`` asks for GRAY8, which has one channel), ``depth``
(float32 map units), ``labels`` and ``automap`` when the ``.cfg`` turns
them on, ``audio`` (int16, frames by 2: the sound of the step's tics) and
``notifications`` (text: the messages of the step's tics) when it turns
those buffers on, and ``gamevariables`` (float32) when it lists any. As in
ViZDoom's wrapper, the audio and notifications buffers hold ``frame_skip``
tics unless a keyword argument sets their size. An episode that reaches the ``.cfg``'s ``episode_timeout`` is
*truncated*; death and the exit *terminate* it.

:class:`SightlineVectorEnv` steps many games of one scenario at once on
the engine's threads, with Gymnasium's vector API and autoreset.
"""

from __future__ import annotations

import itertools
import os
from typing import Any, Optional

import gymnasium as gym
import numpy as np
from gymnasium.envs.registration import register

from . import _native, scenarios
from ._enums import Button, ScreenFormat
from .vizdoom import DoomGame, is_delta_button

__all__ = ["SightlineEnv", "SightlineVectorEnv", "ENV_IDS"]


def _camel(name: str) -> str:
    return "".join(part.capitalize() for part in name.split("_"))


def _config_file(config_file: str) -> str:
    if os.path.isfile(config_file):
        return config_file
    return scenarios.scenario_path(config_file)


class _Spec:
    """What the action and observation spaces are made of, from a game's settings."""

    def __init__(self, game: DoomGame, max_buttons_pressed: int):
        if max_buttons_pressed < 0:
            raise ValueError(f"max_buttons_pressed must be 0 or more, not {max_buttons_pressed}")
        buttons = game.get_available_buttons()
        self.buttons = buttons
        self.binary = [i for i, b in enumerate(buttons) if not is_delta_button(b)]
        self.delta = [i for i, b in enumerate(buttons) if is_delta_button(b)]
        self.max_pressed = max_buttons_pressed
        # Discrete: every set of at most `max_pressed` binary buttons, the
        # empty set first.
        self.combos: list = []
        if max_buttons_pressed > 0:
            for k in range(0, min(max_buttons_pressed, len(self.binary)) + 1):
                self.combos.extend(itertools.combinations(self.binary, k))
        binary_space: Optional[gym.Space] = None
        if self.binary:
            binary_space = gym.spaces.Discrete(len(self.combos)) if self.combos else gym.spaces.MultiBinary(len(self.binary))
        continuous_space: Optional[gym.Space] = None
        if self.delta:
            limit = np.finfo(np.float32).max
            continuous_space = gym.spaces.Box(-limit, limit, (len(self.delta),), np.float32)
        if binary_space is not None and continuous_space is not None:
            self.action_space: gym.Space = gym.spaces.Dict({"binary": binary_space, "continuous": continuous_space})
        elif binary_space is not None or continuous_space is not None:
            self.action_space = binary_space if binary_space is not None else continuous_space
        else:
            raise ValueError("the scenario has no available buttons: there is no action to take")
        height, width = game.get_screen_height(), game.get_screen_width()
        channels = game.get_screen_channels()
        spaces = {"screen": gym.spaces.Box(0, 255, (height, width, channels), np.uint8)}
        if game.is_depth_buffer_enabled():
            spaces["depth"] = gym.spaces.Box(0, np.inf, (height, width, 1), np.float32)
        if game.is_labels_buffer_enabled():
            spaces["labels"] = gym.spaces.Box(0, 255, (height, width, 1), np.uint8)
        if game.is_automap_buffer_enabled():
            spaces["automap"] = gym.spaces.Box(0, 255, (height, width, channels), np.uint8)
        if game.is_audio_buffer_enabled():
            frames = game.get_audio_sampling_rate() * game.get_audio_buffer_size() // 35
            spaces["audio"] = gym.spaces.Box(-32768, 32767, (frames, 2), np.int16)
        if game.is_notifications_buffer_enabled():
            spaces["notifications"] = gym.spaces.Text(min_length=0, max_length=32768, charset=_ASCII)
        n_vars = game.get_available_game_variables_size()
        if n_vars:
            limit = np.finfo(np.float32).max
            spaces["gamevariables"] = gym.spaces.Box(-limit, limit, (n_vars,), np.float32)
        self.observation_space = gym.spaces.Dict(spaces)
        self.channels = channels

    def to_buttons(self, action: Any) -> list:
        """The game's action (one value per button) for an agent's action."""
        values = [0.0] * len(self.buttons)
        binary, continuous = action, None
        if isinstance(self.action_space, gym.spaces.Dict):
            binary, continuous = action["binary"], action["continuous"]
        elif self.delta and not self.binary:
            binary, continuous = None, action
        if binary is not None:
            if self.combos:
                index = int(np.asarray(binary).reshape(()))
                if not 0 <= index < len(self.combos):
                    raise ValueError(f"action {index} is not in Discrete({len(self.combos)})")
                for i in self.combos[index]:
                    values[i] = 1.0
            else:
                pressed = np.asarray(binary).reshape(-1)
                if pressed.shape[0] != len(self.binary):
                    raise ValueError(f"a MultiBinary action has {len(self.binary)} values, not {pressed.shape[0]}")
                for i, p in zip(self.binary, pressed):
                    values[i] = 1.0 if p else 0.0
        if continuous is not None:
            deltas = np.asarray(continuous, dtype=np.float64).reshape(-1)
            if deltas.shape[0] != len(self.delta):
                raise ValueError(f"the continuous action has {len(self.delta)} values, not {deltas.shape[0]}")
            for i, v in zip(self.delta, deltas):
                values[i] = float(v)
        return values

    def from_buttons(self, values: Any) -> Any:
        """The agent's action nearest the game's action ``values`` (one per
        button): for ``Discrete``, the combination of buttons that misses
        the fewest of those pressed, a missed ATTACK weighing most, then
        USE, then turns (one button at a time can press only one of
        TURN_LEFT and MOVE_FORWARD: turning first walks where it should);
        for ``MultiBinary`` the buttons themselves; delta values as they
        are, in the ``Box``."""
        values = [float(v) for v in values]
        binary: Any = None
        if self.binary:
            pressed = [values[i] != 0.0 for i in self.binary]
            if self.combos:
                weight = {i: _MISS_WEIGHT.get(self.buttons[i], 1) for i in self.binary}
                wanted = {i for i, p in zip(self.binary, pressed) if p}

                def miss(combo: tuple) -> int:
                    return sum(weight[i] for i in wanted.symmetric_difference(combo))

                binary = min(range(len(self.combos)), key=lambda k: miss(self.combos[k]))
            else:
                binary = np.array(pressed, dtype=np.int8)
        continuous = np.array([values[i] for i in self.delta], dtype=np.float32) if self.delta else None
        if isinstance(self.action_space, gym.spaces.Dict):
            return {"binary": binary, "continuous": continuous}
        return binary if binary is not None else continuous

    def screen(self, raw: np.ndarray) -> np.ndarray:
        return raw[:, :, None] if raw.ndim == 2 else raw


# How much a button the expert pressed weighs when a Discrete combination
# leaves it out (1 for the rest).
_MISS_WEIGHT = {Button.ATTACK: 8, Button.USE: 4, Button.TURN_LEFT: 2, Button.TURN_RIGHT: 2}


# The notifications' characters (ViZDoom's wrapper: codes 0 to 126).
_ASCII = [chr(i) for i in range(127)]


def _configured_game(config_file: Optional[str], kwargs: dict, frame_skip: int = 1) -> DoomGame:
    made = getattr(config_file, "doom_game", None)  # a scenario made in Python (sightline.made)
    game = made() if made is not None else DoomGame()
    if config_file is not None and made is None:
        game.load_config(_config_file(config_file))
    # A step's buffers hold its tics, unless the caller says otherwise.
    game.set_audio_buffer_size(min(frame_skip, 2100))  # the audio buffer's limit: a minute
    game.set_notifications_buffer_size(frame_skip)
    for key, value in kwargs.items():
        getattr(game, f"set_{key}")(value)
    if game.get_screen_format() != ScreenFormat.GRAY8:
        game.set_screen_format(ScreenFormat.RGB24)
    return game


def _empty(space: gym.Space) -> Any:
    """The observation of ``space`` once the episode is over: zeros, or no text."""
    if isinstance(space, gym.spaces.Text):
        return ""
    return np.zeros(space.shape, space.dtype)


class SightlineEnv(gym.Env):
    """One scenario game as a Gymnasium environment.

    ``config_file`` is a ``.cfg`` path or the name of one of ViZDoom's
    (``"basic"``); ``frame_skip`` tics pass per step holding the action;
    ``expert=True`` puts the autopilot's action in every reset's and step's
    ``info["expert_action"]`` (see :meth:`expert_action`); other keyword
    arguments call the ``DoomGame`` setter of that name (``doom_skill=5``
    calls ``set_doom_skill(5)``)."""

    metadata = {"render_modes": ["human", "rgb_array"], "render_fps": 35}

    def __init__(
        self,
        config_file: Optional[str] = None,
        frame_skip: int = 1,
        max_buttons_pressed: int = 0,
        render_mode: Optional[str] = None,
        expert: bool = False,
        **kwargs: Any,
    ):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode {render_mode!r} is not one of {self.metadata['render_modes']}")
        if frame_skip < 1:
            raise ValueError(f"frame_skip must be at least 1, not {frame_skip}")
        self.frame_skip = frame_skip
        self.render_mode = render_mode
        self.expert = expert
        self.game = _configured_game(config_file, kwargs, frame_skip)
        self.game.set_seed(0)
        self.game.init()
        self._spec = _Spec(self.game, max_buttons_pressed)
        self.action_space = self._spec.action_space
        self.observation_space = self._spec.observation_space
        self._last_screen: Optional[np.ndarray] = None
        self._window = None

    def _observe(self) -> dict:
        state = self.game.get_state()
        if state is None:
            # The episode is over: ViZDoom gives no state, but the game's
            # last frame is there to see (the death or the exit), as the
            # vector environment gives it; the rest is empty.
            self._last_screen = self._spec.screen(self.game._running().screen())
            return {k: _empty(s) for k, s in self.observation_space.spaces.items()} | {"screen": self._last_screen}
        obs = {"screen": self._spec.screen(state.screen_buffer)}
        if "depth" in self.observation_space.spaces:
            obs["depth"] = state.depth_buffer[:, :, None]
        if "labels" in self.observation_space.spaces:
            obs["labels"] = state.labels_buffer[:, :, None]
        if "automap" in self.observation_space.spaces:
            obs["automap"] = self._spec.screen(state.automap_buffer)
        if "audio" in self.observation_space.spaces:
            obs["audio"] = state.audio_buffer
        if "notifications" in self.observation_space.spaces:
            obs["notifications"] = state.notifications_buffer
        if "gamevariables" in self.observation_space.spaces:
            obs["gamevariables"] = state.game_variables.astype(np.float32)
        self._last_screen = obs["screen"]
        return obs

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        super().reset(seed=seed)
        # The game's seed comes from the environment's generator, so a
        # seeded reset replays exactly and later resets differ.
        self.game.set_seed(int(self.np_random.integers(0, 2**31 - 1)))
        self.game.new_episode()
        self._last_screen = None
        obs = self._observe()
        if self.render_mode == "human":
            self.render()
        return obs, self._info()

    def step(self, action: Any):
        reward = self.game.make_action(self._spec.to_buttons(action), self.frame_skip)
        obs = self._observe()
        finished = self.game.is_episode_finished()
        truncated = finished and self.game.is_episode_timeout_reached()
        terminated = finished and not truncated
        if self.render_mode == "human":
            self.render()
        return obs, float(reward), terminated, truncated, self._info()

    def expert_action(self) -> Any:
        """What the autopilot would do now, in this environment's action
        space (:meth:`_Spec.from_buttons`: for a ``Discrete`` space the
        nearest combination). Ask at every step, whatever the agent does:
        the autopilot plays along, seeing the game when asked
        (``DoomGame.get_expert_action``). Once the episode is over, the
        action that presses nothing."""
        return self._spec.from_buttons(self.game.get_expert_action())

    def _info(self) -> dict:
        return {"expert_action": self.expert_action()} if self.expert else {}

    def render(self):
        frame = self._last_screen
        if frame is None:
            return None
        rgb = np.repeat(frame, 3, axis=2) if frame.shape[2] == 1 else frame
        if self.render_mode == "rgb_array":
            return rgb
        if self.render_mode == "human":
            self._show(rgb)
        return None

    def _show(self, rgb: np.ndarray) -> None:
        try:
            import pygame
        except ImportError as e:
            raise gym.error.DependencyNotInstalled("render_mode='human' needs pygame (pip install pygame)") from e
        if self._window is None:
            pygame.init()
            self._window = pygame.display.set_mode((rgb.shape[1], rgb.shape[0]))
            pygame.display.set_caption("Sightline")
        surface = pygame.surfarray.make_surface(rgb.swapaxes(0, 1))
        self._window.blit(surface, (0, 0))
        pygame.event.pump()
        pygame.display.flip()

    def close(self):
        self.game.close()
        if self._window is not None:
            import pygame

            pygame.display.quit()
            self._window = None


class SightlineVectorEnv(gym.vector.VectorEnv):
    """``num_envs`` games of one scenario stepped together on the engine's
    threads (``threads``: 0 is one per core), with Gymnasium's vector API;
    a game whose episode ended starts a new one on the next step
    (``autoreset_mode`` NEXT_STEP, Gymnasium's default). Observations are
    the screen and game variables; every game is seeded apart, so N games
    give byte for byte what N :class:`SightlineEnv` would. ``expert=True``
    puts every game's expert action in ``infos["expert_action"]``
    (:meth:`expert_actions`)."""

    metadata = {"autoreset_mode": gym.vector.AutoresetMode.NEXT_STEP}

    def __init__(
        self,
        config_file: str,
        num_envs: int,
        frame_skip: int = 1,
        max_buttons_pressed: int = 0,
        threads: int = 0,
        expert: bool = False,
        **kwargs: Any,
    ):
        game = _configured_game(config_file, kwargs, frame_skip)
        self.expert = expert
        self._spec = _Spec(game, max_buttons_pressed)
        self.num_envs = num_envs
        self.frame_skip = frame_skip
        self.single_action_space = self._spec.action_space
        self.single_observation_space = self._spec.observation_space
        for extra in ("automap", "depth", "labels", "audio", "notifications"):
            if extra in self.single_observation_space.spaces:
                raise NotImplementedError(f"the vector environment gives the screen and game variables, not the {extra}")
        self.action_space = gym.vector.utils.batch_space(self.single_action_space, num_envs)
        self.observation_space = gym.vector.utils.batch_space(self.single_observation_space, num_envs)
        self._games = game._open_games(num_envs, threads)
        self._needs_reset = np.zeros(num_envs, dtype=bool)
        self._rngs = [gym.utils.seeding.np_random()[0] for _ in range(num_envs)]

    def _observe(self, screens: Optional[np.ndarray] = None) -> dict:
        if screens is None:
            screens = self._games.screens()
        obs = {"screen": screens[..., None] if screens.ndim == 3 else screens}
        if "gamevariables" in self.single_observation_space.spaces:
            obs["gamevariables"] = self._games.game_variables().astype(np.float32)
        return obs

    def _next_seed(self, i: int) -> int:
        # As SightlineEnv.reset draws its game's seed.
        return int(self._rngs[i].integers(0, 2**31 - 1))

    def _new_episode(self, i: int) -> None:
        self._games.new_episode(i, self._next_seed(i))

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """Starts every game anew; ``seed`` seeds game ``i`` as
        ``SightlineEnv.reset(seed=seed + i)`` would."""
        if seed is not None:
            self._rngs = [gym.utils.seeding.np_random(seed + i)[0] for i in range(self.num_envs)]
        for i in range(self.num_envs):
            self._new_episode(i)
        self._needs_reset[:] = False
        return self._observe(), self._infos()

    def step(self, actions: Any):
        rows = np.zeros((self.num_envs, len(self._spec.buttons)), dtype=np.float64)
        for i in range(self.num_envs):
            if isinstance(self.single_action_space, gym.spaces.Dict):
                one = {k: v[i] for k, v in actions.items()}
            else:
                one = actions[i]
            rows[i] = self._spec.to_buttons(one)
        # A game whose episode ended last step takes no action: it starts
        # anew (its seed drawn as SightlineEnv.reset draws it) on the
        # games' threads, in the same pass that steps the others and draws
        # every screen.
        resetting = self._needs_reset.copy()
        resets = [self._next_seed(i) if resetting[i] else None for i in range(self.num_envs)] if resetting.any() else None
        rewards, _, screens = self._games.step_screens(rows, self.frame_skip, resets)
        obs = self._observe(screens)
        rewards = np.where(resetting, 0.0, rewards)
        ends = self._games.ends()
        truncated = np.array([e == "timeout" for e in ends]) & ~resetting
        terminated = np.array([e in ("exit", "death") for e in ends]) & ~resetting
        self._needs_reset = terminated | truncated
        return obs, rewards, terminated, truncated, self._infos()

    def expert_actions(self) -> Any:
        """Every game's expert action (:meth:`SightlineEnv.expert_action`),
        batched as the action space is, answered on the engine's threads.
        A game whose episode ended (it starts anew on the next step) gives
        the action that presses nothing."""
        rows = self._games.expert_actions()
        actions = [self._spec.from_buttons(row) for row in rows]
        return gym.vector.utils.concatenate(
            self.single_action_space, actions, gym.vector.utils.create_empty_array(self.single_action_space, self.num_envs)
        )

    def _infos(self) -> dict:
        if not self.expert:
            return {}
        return {"expert_action": self.expert_actions(), "_expert_action": np.ones(self.num_envs, dtype=bool)}

    def close_extras(self, **kwargs: Any) -> None:
        self._games = None


# ViZDoom's scenarios that Sightline registers: every one whose buffers it
# gives (the audio and notification variants need buffers it does not).
_REGISTERED = [
    "basic",
    "simpler_basic",
    "rocket_basic",
    "deadly_corridor",
    "defend_the_center",
    "defend_the_line",
    "health_gathering",
    "health_gathering_supreme",
    "my_way_home",
    "predict_position",
    "take_cover",
    "deathmatch",
]

ENV_IDS: list = []
for _name in _REGISTERED:
    for _suffix, _pressed in (("", 1), ("-MultiBinary", 0)):
        _id = f"Sightline/{_camel(_name)}{_suffix}-v0"
        register(
            id=_id,
            entry_point="sightline.gym:SightlineEnv",
            kwargs={"config_file": f"{_name}.cfg", "max_buttons_pressed": _pressed},
        )
        ENV_IDS.append(_id)
