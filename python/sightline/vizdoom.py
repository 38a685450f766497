"""ViZDoom's Python API on Sightline's engine, in-process.

Change ``import vizdoom as vzd`` to ``import sightline.vizdoom as vzd`` and a
script written for ViZDoom runs on Sightline: :class:`DoomGame` reads the
same ``.cfg`` files and scenario WADs, takes the same setters, and gives
the same states (screen in every format but ``DOOM_256_COLORS8``, game
variables, the automap), rewards and episode ends.

The game runs in this process, on the engine's simulation with Doom's
arithmetic; there is no engine executable, no message queue, no window.
Calls that ViZDoom has and this does not are listed in
``docs/python.md`` ("ViZDoom compatibility"); they raise
:class:`NotSupportedError` with the reason rather than doing nothing.
"""

from __future__ import annotations

import os
import random
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence

import numpy as np

from . import _native
from ._enums import (  # noqa: F401  (re-exported: ViZDoom's names)
    AutomapMode,
    Button,
    GameVariable,
    Mode,
    SamplingRate,
    ScreenFormat,
    ScreenResolution,
)
from .scenarios import configs, scenarios_path, wads  # noqa: F401

__all__ = [
    "AutomapMode",
    "Button",
    "DoomGame",
    "FileDoesNotExistException",
    "GameState",
    "GameVariable",
    "Label",
    "Line",
    "Object",
    "Sector",
    "Mode",
    "NotSupportedError",
    "SamplingRate",
    "ScreenFormat",
    "ScreenResolution",
    "ViZDoomErrorException",
    "ViZDoomIsNotRunningException",
    "configs",
    "doom_fixed_to_double",
    "doom_tics_to_ms",
    "doom_tics_to_sec",
    "is_binary_button",
    "is_delta_button",
    "ms_to_doom_tics",
    "scenarios_path",
    "sec_to_doom_tics",
    "wads",
]

__version__ = _native.__version__


class FileDoesNotExistException(FileNotFoundError):
    """A file the game needs (a ``.cfg``, the scenario WAD, the IWAD) is missing."""


class ViZDoomErrorException(RuntimeError):
    """The game could not start or go on."""


class ViZDoomIsNotRunningException(RuntimeError):
    """A call that needs a running game came before :meth:`DoomGame.init` or after :meth:`DoomGame.close`."""


class NotSupportedError(NotImplementedError):
    """A ViZDoom call that Sightline does not offer (the message says why)."""


class ConfigError(ValueError):
    """A setting or a ``.cfg`` line is wrong: the message names the file, line and key."""


_DELTA_BUTTONS = {
    Button.LOOK_UP_DOWN_DELTA,
    Button.TURN_LEFT_RIGHT_DELTA,
    Button.MOVE_FORWARD_BACKWARD_DELTA,
    Button.MOVE_LEFT_RIGHT_DELTA,
    Button.MOVE_UP_DOWN_DELTA,
}


def is_delta_button(button: Button) -> bool:
    """Whether ``button`` takes a value (a turn in degrees, a move in units) rather than on/off."""
    return Button(button) in _DELTA_BUTTONS


def is_binary_button(button: Button) -> bool:
    """Whether ``button`` is on or off."""
    return not is_delta_button(button)


def doom_fixed_to_double(doom_fixed: float) -> float:
    """A 16.16 fixed-point number (as ACS keeps rewards) as a float."""
    return float(doom_fixed) / 65536.0


doom_fixed_to_float = doom_fixed_to_double


def doom_tics_to_ms(tics: float, ticrate: int = 35) -> float:
    return float(tics) * 1000.0 / ticrate


def ms_to_doom_tics(ms: float, ticrate: int = 35) -> float:
    return float(ms) * ticrate / 1000.0


def doom_tics_to_sec(tics: float, ticrate: int = 35) -> float:
    return float(tics) / ticrate


def sec_to_doom_tics(sec: float, ticrate: int = 35) -> float:
    return float(sec) * ticrate


@dataclass
class Label:
    """A thing seen in the labels buffer (ViZDoom's ``Label``)."""

    object_id: int
    object_name: str
    value: int
    x: int
    y: int
    width: int
    height: int
    object_position_x: float = 0.0
    object_position_y: float = 0.0
    object_position_z: float = 0.0
    object_angle: float = 0.0
    object_pitch: float = 0.0
    object_roll: float = 0.0
    object_velocity_x: float = 0.0
    object_velocity_y: float = 0.0
    object_velocity_z: float = 0.0
    object_category: str = ""


@dataclass
class Object:
    """A body in the level (ViZDoom's ``Object``): ``id`` is the body's,
    as a :class:`Label`'s ``object_id``; ``name`` ZDoom's class name
    (``DoomPlayer``, ``Cacodemon``); velocities in map units a tic. Pitch
    and roll are 0 and the category is empty (not given)."""

    id: int
    name: str
    position_x: float = 0.0
    position_y: float = 0.0
    position_z: float = 0.0
    angle: float = 0.0
    pitch: float = 0.0
    roll: float = 0.0
    velocity_x: float = 0.0
    velocity_y: float = 0.0
    velocity_z: float = 0.0
    sector_id: int = 0
    category: str = ""


@dataclass
class Line:
    """A line of a sector (ViZDoom's ``Line``): blocking when one-sided or
    flagged to block."""

    x1: float
    y1: float
    x2: float
    y2: float
    is_blocking: bool


@dataclass
class Sector:
    """A sector (ViZDoom's ``Sector``): its heights now and its lines, a
    two-sided line in both its sectors."""

    id: int
    floor_height: float
    ceiling_height: float
    lines: list = field(default_factory=list)


@dataclass
class GameState:
    """What the agent gets after an action (ViZDoom's ``GameState``)."""

    number: int
    tic: int
    game_variables: Optional[np.ndarray]
    screen_buffer: np.ndarray
    depth_buffer: Optional[np.ndarray] = None
    labels_buffer: Optional[np.ndarray] = None
    automap_buffer: Optional[np.ndarray] = None
    audio_buffer: Optional[np.ndarray] = None
    labels: list = field(default_factory=list)
    objects: Optional[list] = None
    sectors: Optional[list] = None
    notifications_buffer: Optional[str] = None


def _flag(value: bool) -> str:
    return "true" if value else "false"


def _enum_name(kind: type, value: Any, call: str = "") -> str:
    """The name of ``value``, one of ``kind``'s members, its number, or its
    name; ``call`` names the setter in the error."""
    where = f"{call}: " if call else ""
    members = ", ".join(kind.__members__)
    if isinstance(value, str):
        if value.upper() in kind.__members__:
            return value.upper()
        raise ConfigError(f"{where}{value!r} is not a {kind.__name__} ({members})")
    try:
        return kind(value).name
    except ValueError:
        raise ConfigError(f"{where}{value!r} is not a {kind.__name__} ({members})") from None


# Settings given by a getter under ViZDoom's name, read from the config.
_GETTERS = {
    "get_vizdoom_path": "vizdoom_path",
    "get_doom_game_path": "doom_game_path",
    "get_doom_scenario_path": "doom_scenario_path",
    "get_doom_config_path": "doom_config_path",
    "get_doom_map": "doom_map",
    "get_doom_skill": "doom_skill",
    "get_game_args": "game_args",
    "get_ticrate": "ticrate",
    "get_episode_timeout": "episode_timeout",
    "get_episode_start_time": "episode_start_time",
    "get_living_reward": "living_reward",
    "get_death_penalty": "death_penalty",
    "get_map_exit_reward": "map_exit_reward",
    "get_kill_reward": "kill_reward",
    "get_item_reward": "item_reward",
    "get_secret_reward": "secret_reward",
    "get_frag_reward": "frag_reward",
    "get_hit_reward": "hit_reward",
    "get_hit_taken_penalty": "hit_taken_penalty",
    "get_damage_made_reward": "damage_made_reward",
    "get_damage_taken_penalty": "damage_taken_penalty",
    "get_health_reward": "health_reward",
    "get_armor_reward": "armor_reward",
    "get_screen_width": "screen_width",
    "get_screen_height": "screen_height",
    "get_audio_sampling_rate": "audio_sampling_rate",  # in hertz, as ViZDoom 1.3.2 gives it
    "get_audio_buffer_size": "audio_buffer_size",
    "get_notifications_buffer_size": "notifications_buffer_size",
    "is_depth_buffer_enabled": "depth_buffer_enabled",
    "is_labels_buffer_enabled": "labels_buffer_enabled",
    "is_automap_buffer_enabled": "automap_buffer_enabled",
    "is_audio_buffer_enabled": "audio_buffer_enabled",
    "is_notifications_buffer_enabled": "notifications_buffer_enabled",
    "is_objects_info_enabled": "objects_info_enabled",
    "is_sectors_info_enabled": "sectors_info_enabled",
}

# Setters that take one value, by the `.cfg` key they set.
_SETTERS = {
    "set_doom_map": "doom_map",
    "set_doom_skill": "doom_skill",
    "set_ticrate": "ticrate",
    "set_episode_timeout": "episode_timeout",
    "set_episode_start_time": "episode_start_time",
    "set_living_reward": "living_reward",
    "set_death_penalty": "death_penalty",
    "set_death_reward": "death_reward",
    "set_map_exit_reward": "map_exit_reward",
    "set_kill_reward": "kill_reward",
    "set_item_reward": "item_reward",
    "set_secret_reward": "secret_reward",
    "set_frag_reward": "frag_reward",
    "set_hit_reward": "hit_reward",
    "set_hit_taken_penalty": "hit_taken_penalty",
    "set_hit_taken_reward": "hit_taken_reward",
    "set_damage_made_reward": "damage_made_reward",
    "set_damage_taken_penalty": "damage_taken_penalty",
    "set_damage_taken_reward": "damage_taken_reward",
    "set_health_reward": "health_reward",
    "set_armor_reward": "armor_reward",
    "set_audio_buffer_size": "audio_buffer_size",
    "set_notifications_buffer_size": "notifications_buffer_size",
}

# Switches, by the `.cfg` key they set.
_SWITCHES = {
    "set_depth_buffer_enabled": "depth_buffer_enabled",
    "set_labels_buffer_enabled": "labels_buffer_enabled",
    "set_automap_buffer_enabled": "automap_buffer_enabled",
    "set_audio_buffer_enabled": "audio_buffer_enabled",
    "set_notifications_buffer_enabled": "notifications_buffer_enabled",
    "set_objects_info_enabled": "objects_info_enabled",
    "set_sectors_info_enabled": "sectors_info_enabled",
    "set_render_hud": "render_hud",
    "set_render_minimal_hud": "render_minimal_hud",
    "set_render_weapon": "render_weapon",
    "set_render_crosshair": "render_crosshair",
    "set_render_decals": "render_decals",
    "set_render_particles": "render_particles",
    "set_render_effects_sprites": "render_effects_sprites",
    "set_render_messages": "render_messages",
    "set_render_corpses": "render_corpses",
    "set_render_screen_flashes": "render_screen_flashes",
    "set_render_all_frames": "render_all_frames",
    "set_window_visible": "window_visible",
    "set_console_enabled": "console_enabled",
    "set_sound_enabled": "sound_enabled",
    "set_automap_rotate": "automap_rotate",
    "set_automap_render_textures": "automap_render_textures",
    "set_automap_render_objects_as_sprites": "automap_render_objects_as_sprites",
}

# The paths' setters: relative paths are taken from the current directory.
_PATH_SETTERS = {
    "set_vizdoom_path": "vizdoom_path",
    "set_doom_game_path": "doom_game_path",
    "set_doom_scenario_path": "doom_scenario_path",
    "set_doom_config_path": "doom_config_path",
}


class DoomGame:
    """One game, as ViZDoom's ``DoomGame``: configure, :meth:`init`, then
    play episodes with :meth:`make_action` and read :meth:`get_state`."""

    def __init__(self) -> None:
        self._config = _native.Config()
        self._game: Optional[_native.Game] = None
        self._seed: Optional[int] = None
        self._next_seed = 0
        self._state_number = 0
        self._action: list = []
        self._outputs: dict = {}

    # ---- configuration -------------------------------------------------

    def _apply(self, line: str, setter: str) -> None:
        try:
            self._config.apply(line, f"<DoomGame.{setter}>")
        except ValueError as e:
            raise ConfigError(str(e)) from None

    def _settings(self) -> dict:
        return self._config.to_dict()

    def load_config(self, config: str) -> bool:
        """Applies the ``.cfg`` file ``config`` onto the settings. A missing
        file raises :class:`FileDoesNotExistException`, a bad line
        :class:`ConfigError` naming the file, line and key (ViZDoom prints a
        warning and goes on; a research run should not)."""
        if not os.path.isfile(config):
            raise FileDoesNotExistException(f"{config}: no such .cfg file")
        try:
            self._config.load(config)
        except ValueError as e:
            raise ConfigError(str(e)) from None
        return True

    def set_config(self, config: Any) -> bool:
        """Applies ``.cfg`` text, or a dictionary of ``.cfg`` keys and values."""
        if isinstance(config, dict):
            lines = []
            for key, value in config.items():
                if isinstance(value, (list, tuple)):
                    names = " ".join(v.name if hasattr(v, "name") else str(v) for v in value)
                    lines.append(f"{key} = {{ {names} }}")
                elif isinstance(value, bool):
                    lines.append(f"{key} = {_flag(value)}")
                else:
                    lines.append(f"{key} = {value.name if hasattr(value, 'name') else value}")
            config = "\n".join(lines)
        self._apply(str(config), "set_config")
        return True

    def __getattr__(self, name: str) -> Any:
        # The many one-value setters and getters, by table.
        if name in _GETTERS:
            key = _GETTERS[name]
            return lambda: self._settings()[key]
        if name in _SETTERS:
            key = _SETTERS[name]

            def setter(value: Any) -> None:
                if isinstance(value, bool) or not isinstance(value, (int, float, str, np.number)):
                    raise ConfigError(f"{name}: {value!r} is not a number")
                self._apply(f"{key} = {value}", name)

            return setter
        if name in _SWITCHES:
            key = _SWITCHES[name]
            return lambda value: self._apply(f"{key} = {_flag(bool(value))}", name)
        if name in _PATH_SETTERS:
            key = _PATH_SETTERS[name]
            return lambda path: self._apply(f"{key} = {os.path.abspath(os.fspath(path))}", name)
        raise AttributeError(f"DoomGame has no attribute {name!r} (see docs/python.md for ViZDoom calls not offered)")

    def set_screen_resolution(self, resolution: ScreenResolution) -> None:
        self._apply(f"screen_resolution = {_enum_name(ScreenResolution, resolution)}", "set_screen_resolution")

    def set_screen_format(self, format: ScreenFormat) -> None:
        self._apply(f"screen_format = {_enum_name(ScreenFormat, format)}", "set_screen_format")

    def get_screen_format(self) -> ScreenFormat:
        return ScreenFormat[self._settings()["screen_format"]]

    def set_mode(self, mode: Mode) -> None:
        name = _enum_name(Mode, mode)
        if Mode[name] is not Mode.PLAYER:
            raise NotSupportedError(
                f"mode {name}: Sightline's games wait for each action (Mode.PLAYER); "
                "spectator and asynchronous modes need a person at a window"
            )
        self._apply(f"mode = {name}", "set_mode")

    def get_mode(self) -> Mode:
        return Mode[self._settings()["mode"]]

    def set_automap_mode(self, mode: AutomapMode) -> None:
        self._apply(f"automap_mode = {_enum_name(AutomapMode, mode)}", "set_automap_mode")

    def set_audio_sampling_rate(self, rate: SamplingRate) -> None:
        name = _enum_name(SamplingRate, rate, "set_audio_sampling_rate")
        self._apply(f"audio_sampling_rate = {name}", "set_audio_sampling_rate")

    def set_available_buttons(self, buttons: Sequence[Button]) -> None:
        names = " ".join(_enum_name(Button, b) for b in buttons)
        self._apply(f"available_buttons = {{ {names} }}", "set_available_buttons")

    def add_available_button(self, button: Button, max_value: float = -1) -> None:
        name = _enum_name(Button, button)
        self._apply(f"available_buttons += {{ {name} }}", "add_available_button")
        if max_value >= 0:
            self.set_button_max_value(button, max_value)

    def clear_available_buttons(self) -> None:
        self._apply("available_buttons = { }", "clear_available_buttons")

    def get_available_buttons(self) -> list:
        return [Button[n] for n in self._settings()["available_buttons"]]

    def get_available_buttons_size(self) -> int:
        return len(self._settings()["available_buttons"])

    def set_button_max_value(self, button: Button, max_value: float) -> None:
        value = int(max_value)
        self._apply(f"button_max_value = {_enum_name(Button, button)} {value}", "set_button_max_value")

    def get_button_max_value(self, button: Button) -> float:
        name = _enum_name(Button, button)
        return float(dict(self._settings()["button_max_values"]).get(name, 0))

    def set_available_game_variables(self, variables: Sequence[GameVariable]) -> None:
        names = " ".join(_enum_name(GameVariable, v) for v in variables)
        self._apply(f"available_game_variables = {{ {names} }}", "set_available_game_variables")

    def add_available_game_variable(self, variable: GameVariable) -> None:
        name = _enum_name(GameVariable, variable)
        self._apply(f"available_game_variables += {{ {name} }}", "add_available_game_variable")

    def clear_available_game_variables(self) -> None:
        self._apply("available_game_variables = { }", "clear_available_game_variables")

    def get_available_game_variables(self) -> list:
        return [GameVariable[n] for n in self._settings()["available_game_variables"]]

    def get_available_game_variables_size(self) -> int:
        return len(self._settings()["available_game_variables"])

    def set_game_args(self, args: str) -> None:
        self._apply(f"game_args = {args}", "set_game_args")

    def add_game_args(self, args: str) -> None:
        self._apply(f"game_args += {args}", "add_game_args")

    def clear_game_args(self) -> None:
        self._apply("game_args = ", "clear_game_args")

    def get_screen_channels(self) -> int:
        fmt = self.get_screen_format()
        if fmt in (ScreenFormat.GRAY8, ScreenFormat.DOOM_256_COLORS8):
            return 1
        if fmt in (ScreenFormat.RGBA32, ScreenFormat.ARGB32, ScreenFormat.BGRA32, ScreenFormat.ABGR32):
            return 4
        return 3

    def get_screen_pitch(self) -> int:
        fmt = self.get_screen_format()
        planar = fmt in (ScreenFormat.CRCGCB, ScreenFormat.CBCGCR)
        return self.get_screen_width() * (1 if planar else self.get_screen_channels())

    def get_screen_size(self) -> int:
        return self.get_screen_width() * self.get_screen_height() * self.get_screen_channels()

    def set_seed(self, seed: int) -> None:
        """Seeds the episodes: the next episode plays with ``seed``, the one
        after with ``seed + 1``, and so on, whatever happened in between."""
        if isinstance(seed, bool) or int(seed) != seed or seed < 0:
            raise ConfigError(f"set_seed: {seed!r} is not a non-negative integer")
        self._seed = int(seed)
        self._next_seed = int(seed)

    def get_seed(self) -> int:
        return self._seed if self._seed is not None else 0

    # ---- the game ------------------------------------------------------

    def init(self) -> bool:
        """Opens the scenario and starts the first episode."""
        settings = self._settings()
        if settings["mode"] != "PLAYER":
            raise NotSupportedError(f"mode {settings['mode']}: only Mode.PLAYER is offered")
        if settings["seed"] is not None and self._seed is None:
            self.set_seed(settings["seed"])
        if self._seed is None:
            self.set_seed(random.SystemRandom().getrandbits(31))
        try:
            self._game = self._open()
        except FileNotFoundError as e:
            raise FileDoesNotExistException(str(e)) from None
        except (RuntimeError, ValueError) as e:
            raise ViZDoomErrorException(str(e)) from None
        # What each state carries is fixed once the game is open: read the
        # settings here, not on every get_state.
        opened = self._settings()
        self._outputs = {
            key: bool(opened[key])
            for key in (
                "available_game_variables",
                "automap_buffer_enabled",
                "depth_buffer_enabled",
                "labels_buffer_enabled",
                "audio_buffer_enabled",
                "notifications_buffer_enabled",
                "objects_info_enabled",
                "sectors_info_enabled",
            )
        }
        self._action = [0.0] * len(opened["available_buttons"])
        self.new_episode()
        return True

    def _open(self) -> "_native.Game":
        """The native game of these settings (a made scenario's game opens its own)."""
        return _native.Game(self._config)

    def _open_games(self, count: int, threads: int = 0) -> "_native.Games":
        """``count`` native games of these settings, for the vector environment."""
        return _native.Games(self._config, count, threads=threads)

    def _running(self) -> "_native.Game":
        if self._game is None:
            raise ViZDoomIsNotRunningException("the game is not running: call init() first")
        return self._game

    def is_running(self) -> bool:
        return self._game is not None

    def close(self) -> None:
        self._game = None

    def new_episode(self, recording_file_path: str = "") -> None:
        if recording_file_path:
            raise NotSupportedError("recording an episode: record with `sightline play --record` instead")
        game = self._running()
        game.new_episode(self._next_seed)
        self._next_seed += 1
        self._state_number = 0

    def _as_action(self, action: Any) -> list:
        # A flat list or tuple of numbers (what most agents pass) is read
        # directly: through numpy it took about 7 us a step, a tenth of a
        # step at 160x120. Anything else (arrays, nested lists) goes through
        # numpy as before.
        if type(action) is list or type(action) is tuple:
            try:
                return [float(v) for v in action]
            except (TypeError, ValueError):
                pass
        try:
            if isinstance(action, np.ndarray):
                return action.astype(np.float64, copy=False).reshape(-1).tolist()
            values = [float(v) for v in np.asarray(action, dtype=np.float64).reshape(-1)]
        except (TypeError, ValueError):
            raise ValueError(f"an action is a sequence of numbers, one per available button, not {action!r}") from None
        return values

    def make_action(self, action: Any, tics: int = 1) -> float:
        """Holds ``action`` for ``tics`` tics; returns the reward they earned."""
        game = self._running()
        if int(tics) < 1:
            raise ValueError(f"make_action: tics must be at least 1, not {tics}")
        self._action = self._as_action(action)
        reward = game.step(self._action, int(tics))
        self._state_number += 1
        return reward

    def set_action(self, action: Any) -> None:
        self._running()
        self._action = self._as_action(action)

    def advance_action(self, tics: int = 1, update_state: bool = True) -> None:
        game = self._running()
        game.step(self._action, int(tics))
        self._state_number += 1

    def get_last_action(self) -> list:
        return list(self._action)

    def get_state(self) -> Optional[GameState]:
        """The state after the last action, or None once the episode is over."""
        game = self._running()
        if game.is_finished():
            return None
        outputs = self._outputs
        variables = game.game_variables() if outputs["available_game_variables"] else None
        automap = game.automap() if outputs["automap_buffer_enabled"] else None
        depth = game.depth() if outputs["depth_buffer_enabled"] else None
        audio = game.audio() if outputs["audio_buffer_enabled"] else None
        notifications = game.notifications() if outputs["notifications_buffer_enabled"] else None
        objects = [Object(**o) for o in game.objects()] if outputs["objects_info_enabled"] else None
        sectors = None
        if outputs["sectors_info_enabled"]:
            sectors = [Sector(**{**s, "lines": [Line(**l) for l in s["lines"]]}) for s in game.sectors()]
        labels_buffer, labels = None, []
        if outputs["labels_buffer_enabled"]:
            labels_buffer, seen = game.labels()
            labels = [Label(**o) for o in seen]
        return GameState(
            number=self._state_number,
            tic=game.episode_time(),
            game_variables=variables,
            screen_buffer=game.screen(),
            depth_buffer=depth,
            labels_buffer=labels_buffer,
            labels=labels,
            automap_buffer=automap,
            audio_buffer=audio,
            notifications_buffer=notifications,
            objects=objects,
            sectors=sectors,
        )

    def is_episode_finished(self) -> bool:
        return self._running().is_finished()

    def is_new_episode(self) -> bool:
        return self._running().actions() == 0

    def is_player_dead(self) -> bool:
        return self._running().is_player_dead()

    def is_episode_timeout_reached(self) -> bool:
        return self._running().is_timeout_reached()

    def get_total_reward(self) -> float:
        return self._running().total_reward()

    def get_last_reward(self) -> float:
        return self._running().last_reward()

    def get_episode_time(self) -> int:
        return self._running().episode_time()

    def get_game_variable(self, variable: GameVariable) -> float:
        return self._running().game_variable(_enum_name(GameVariable, variable))

    def get_button(self, button: Button) -> float:
        buttons = self.get_available_buttons()
        b = Button(button)
        return self._action[buttons.index(b)] if b in buttons and self._action else 0.0

    def get_expert_action(self) -> list:
        """What Sightline's autopilot would press now: an action, one value
        per available button (delta buttons take its exact turn or move),
        to imitate. A Sightline extension: ViZDoom has no such call.

        The autopilot fights what it sees, fetches the health and armour it
        has seen, explores, and leads a moving enemy with a rocket; where
        the buttons cannot say what it wants (basic has no turn buttons) it
        strafes the enemy onto the line of fire and fires only when it is
        there. It is made when first asked in an episode and plays along
        from then on, seeing the game each time it is asked (ask every
        step, whoever acts); it never changes the game, and asked twice on
        one tic it gives the same answer. All zeros once the episode is
        over."""
        return self._running().expert_action()

    def is_multiplayer_game(self) -> bool:
        return False

    def is_recording_episode(self) -> bool:
        return False

    def is_replaying_episode(self) -> bool:
        return False

    def respawn_player(self) -> None:
        """Nothing to do in a one-player game (the episode ends on death)."""

    def get_instance_id(self) -> str:
        return hex(id(self))

    def send_game_command(self, cmd: str) -> None:
        raise NotSupportedError(f"send_game_command({cmd!r}): Sightline has no ZDoom console")

    def replay_episode(self, file_path: str, player: int = 0) -> None:
        raise NotSupportedError("replay_episode: replay with `sightline replay` instead")

    def save(self, file_path: str) -> None:
        raise NotSupportedError("save: a game with ACS scripts cannot be saved yet")

    def load(self, file_path: str) -> None:
        raise NotSupportedError("load: a game with ACS scripts cannot be saved yet")

    def __del__(self) -> None:
        self._game = None
