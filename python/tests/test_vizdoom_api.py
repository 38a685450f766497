"""sightline.vizdoom against ViZDoom's API: a script written for ViZDoom
runs with only its import changed, and the calls behave as ViZDoom's do."""

import os
import pathlib

import numpy as np
import pytest

import sightline.vizdoom as vzd

# ViZDoom's basic example, in its own style (examples/python/basic.py's
# loop: configure, init, episodes of random actions, the total reward),
# importing vizdoom as such; the test changes only that import.
EXAMPLE = '''
import os
from random import choice
import vizdoom as vzd

game = vzd.DoomGame()
game.load_config(os.path.join(vzd.scenarios_path, "basic.cfg"))
game.set_screen_resolution(vzd.ScreenResolution.RES_320X240)
game.set_screen_format(vzd.ScreenFormat.RGB24)
game.set_render_hud(False)
game.set_render_crosshair(False)
game.set_render_weapon(True)
game.set_available_buttons([vzd.Button.MOVE_LEFT, vzd.Button.MOVE_RIGHT, vzd.Button.ATTACK])
game.set_available_game_variables([vzd.GameVariable.AMMO2])
game.set_episode_timeout(200)
game.set_episode_start_time(10)
game.set_window_visible(False)
game.set_living_reward(-1)
game.set_mode(vzd.Mode.PLAYER)
game.init()
actions = [[True, False, False], [False, True, False], [False, False, True]]
totals = []
for i in range(3):
    game.new_episode()
    while not game.is_episode_finished():
        state = game.get_state()
        n = state.number
        vars = state.game_variables
        screen_buf = state.screen_buffer
        r = game.make_action(choice(actions))
    totals.append(game.get_total_reward())
game.close()
'''


def test_vizdoom_example_runs_with_only_its_import_changed(scenarios):
    source = EXAMPLE.replace("import vizdoom as vzd", "import sightline.vizdoom as vzd")
    scope: dict = {}
    exec(compile(source, "basic_example.py", "exec"), scope)
    totals = scope["totals"]
    assert len(totals) == 3
    # Basic pays -1 a tic, -6 a missed shot, +101 for the kill (less the tic).
    assert all(-300 <= t <= 100 for t in totals), totals
    assert scope["screen_buf"].shape == (240, 320, 3)
    assert scope["vars"].shape == (1,)


def test_state_buffers_and_variables(basic_cfg):
    game = vzd.DoomGame()
    game.load_config(basic_cfg)
    game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
    game.set_automap_buffer_enabled(True)
    game.set_available_game_variables([vzd.GameVariable.AMMO2, vzd.GameVariable.HEALTH, vzd.GameVariable.POSITION_X])
    game.set_seed(7)
    game.init()
    state = game.get_state()
    assert state.screen_buffer.shape == (3, 120, 160)  # basic.cfg's CRCGCB: channels first
    assert state.screen_buffer.dtype == np.uint8
    assert state.automap_buffer.shape == (3, 120, 160)
    assert state.game_variables.tolist()[:2] == [50.0, 100.0]
    ammo = game.get_game_variable(vzd.GameVariable.AMMO2)
    reward = game.make_action([0, 0, 1], 8)  # ATTACK held: the pistol fires once in 8 tics
    assert game.get_game_variable(vzd.GameVariable.AMMO2) == ammo - 1
    # Eight tics' living reward, and the ACS's -5 for a miss or +100 for the kill.
    assert reward in (pytest.approx(-13.0), pytest.approx(92.0))
    assert game.get_available_buttons() == [vzd.Button.MOVE_LEFT, vzd.Button.MOVE_RIGHT, vzd.Button.ATTACK]
    assert game.get_episode_time() >= 1


@pytest.mark.parametrize(
    "fmt, shape",
    [
        (vzd.ScreenFormat.CRCGCB, (3, 120, 160)),
        (vzd.ScreenFormat.RGB24, (120, 160, 3)),
        (vzd.ScreenFormat.RGBA32, (120, 160, 4)),
        (vzd.ScreenFormat.ARGB32, (120, 160, 4)),
        (vzd.ScreenFormat.CBCGCR, (3, 120, 160)),
        (vzd.ScreenFormat.BGR24, (120, 160, 3)),
        (vzd.ScreenFormat.BGRA32, (120, 160, 4)),
        (vzd.ScreenFormat.ABGR32, (120, 160, 4)),
        (vzd.ScreenFormat.GRAY8, (120, 160)),
    ],
)
def test_screen_formats_hold_the_same_picture(basic_cfg, fmt, shape):
    def screen(f):
        game = vzd.DoomGame()
        game.load_config(basic_cfg)
        game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
        game.set_screen_format(f)
        game.set_seed(3)
        game.init()
        return game.get_state().screen_buffer

    rgb = screen(vzd.ScreenFormat.RGB24).astype(np.int32)
    got = screen(fmt)
    assert got.shape == shape
    as_rgb = {
        vzd.ScreenFormat.CRCGCB: lambda s: s.transpose(1, 2, 0),
        vzd.ScreenFormat.RGB24: lambda s: s,
        vzd.ScreenFormat.RGBA32: lambda s: s[:, :, :3],
        vzd.ScreenFormat.ARGB32: lambda s: s[:, :, 1:],
        vzd.ScreenFormat.CBCGCR: lambda s: s.transpose(1, 2, 0)[:, :, ::-1],
        vzd.ScreenFormat.BGR24: lambda s: s[:, :, ::-1],
        vzd.ScreenFormat.BGRA32: lambda s: s[:, :, 2::-1],
        vzd.ScreenFormat.ABGR32: lambda s: s[:, :, :0:-1],
    }
    if fmt == vzd.ScreenFormat.GRAY8:
        luma = (299 * rgb[..., 0] + 587 * rgb[..., 1] + 114 * rgb[..., 2] + 500) // 1000
        assert np.array_equal(got, luma.astype(np.uint8))
    else:
        assert np.array_equal(as_rgb[fmt](got), rgb.astype(np.uint8))
    # A picture, not a blank.
    assert len(np.unique(rgb.reshape(-1, 3), axis=0)) > 20


def test_same_seed_same_actions_same_bytes(basic_cfg):
    def run():
        game = vzd.DoomGame()
        game.load_config(basic_cfg)
        game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
        game.set_seed(11)
        game.init()
        frames = []
        rng = np.random.default_rng(5)
        for _ in range(2):
            game.new_episode()
            while not game.is_episode_finished():
                frames.append(game.get_state().screen_buffer.tobytes())
                game.make_action(rng.integers(0, 2, 3).tolist(), 2)
            frames.append(repr(game.get_total_reward()))
        return frames

    assert run() == run()


def test_seeds_differ(scenarios):
    # defend_the_center's monsters move by the random generator.
    def totals(seed):
        game = vzd.DoomGame()
        game.load_config(os.path.join(scenarios, "defend_the_center.cfg"))
        game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
        game.set_seed(seed)
        game.init()
        for _ in range(60):
            game.make_action([0, 0, 1])
        return game.get_state().screen_buffer.tobytes()

    assert totals(1) != totals(2)


def test_bad_calls_raise_clear_python_errors(basic_cfg, tmp_path: pathlib.Path):
    game = vzd.DoomGame()
    with pytest.raises(vzd.ViZDoomIsNotRunningException, match="init"):
        game.make_action([1, 0, 0])
    with pytest.raises(vzd.FileDoesNotExistException, match="nowhere.cfg"):
        game.load_config(str(tmp_path / "nowhere.cfg"))
    bad = tmp_path / "bad.cfg"
    bad.write_text("doom_skill = 3\navailable_buttons = { MOVE_LEFT JUMP_HIGH }\n")
    with pytest.raises(vzd.ConfigError, match=r"bad.cfg:2: .*JUMP_HIGH"):
        game.load_config(str(bad))
    with pytest.raises(vzd.ConfigError, match="episode_timeout"):
        game.set_config({"episode_timeout": "soon"})
    with pytest.raises(vzd.ConfigError, match="episode_timeout.*soon.*not an unsigned integer"):
        game.set_episode_timeout("soon")
    with pytest.raises(vzd.ConfigError, match="not a number"):
        game.set_living_reward([1])
    with pytest.raises(vzd.ConfigError, match="not a Button"):
        game.set_available_buttons([99])
    game.load_config(basic_cfg)
    game.set_doom_scenario_path(str(tmp_path / "missing.wad"))
    with pytest.raises(vzd.FileDoesNotExistException, match="missing.wad"):
        game.init()
    game.load_config(basic_cfg)
    game.init()
    with pytest.raises(ValueError, match="one value per available button: 2 given for 3"):
        game.make_action([1, 0])
    with pytest.raises(ValueError, match="not a finite number"):
        game.make_action([float("nan"), 0, 0])
    with pytest.raises(ValueError, match="sequence of numbers"):
        game.make_action(["left", 0, 0])
    with pytest.raises(ValueError, match="unknown game variable"):
        game._game.game_variable("MANA")
    with pytest.raises(vzd.NotSupportedError):
        game.set_mode(vzd.Mode.ASYNC_PLAYER)
    corrupt = tmp_path / "corrupt.wad"
    corrupt.write_bytes(b"PWAD\xff\xff\xff\x7f\x10\x00\x00\x00garbage")
    game2 = vzd.DoomGame()
    game2.load_config(basic_cfg)
    game2.set_doom_scenario_path(str(corrupt))
    with pytest.raises(vzd.ViZDoomErrorException, match="corrupt.wad"):
        game2.init()
    # The game that raised goes on.
    game.make_action([0, 0, 1])
    assert game.get_state() is not None or game.is_episode_finished()


def test_depth_and_labels_buffers(scenarios):
    game = vzd.DoomGame()
    game.load_config(os.path.join(scenarios, "defend_the_center.cfg"))
    game.set_screen_resolution(vzd.ScreenResolution.RES_320X240)
    game.set_depth_buffer_enabled(True)
    game.set_labels_buffer_enabled(True)
    game.set_seed(2)
    game.init()
    for _ in range(10):
        game.make_action([0, 0, 0])
    state = game.get_state()
    depth, labels = state.depth_buffer, state.labels_buffer
    assert depth.shape == (240, 320) and depth.dtype == np.float32
    assert labels.shape == (240, 320) and labels.dtype == np.uint8
    finite = depth[np.isfinite(depth)]
    assert finite.size > 0 and (finite > 0).all()
    # The monsters around the player: each label's box holds its pixels.
    assert state.labels, "defend_the_center's monsters are in view"
    for label in state.labels:
        ys, xs = np.nonzero(labels == label.value)
        assert (xs.min(), ys.min()) == (label.x, label.y)
        assert (xs.max() + 1 - label.x, ys.max() + 1 - label.y) == (label.width, label.height)
        assert label.object_name
        # A thing's pixels are nearer than the wall behind it, farther than the eye.
        assert np.isfinite(depth[ys, xs]).all()
    assert set(np.unique(labels)) - {0} == {lab.value for lab in state.labels}
