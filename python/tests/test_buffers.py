"""The audio and notifications buffers, as ViZDoom's state carries them:
the shape and type ViZDoom 1.3.2 gives, the pistol heard on the tics after
the shot and silence before, the same bytes for the same seed and actions,
pickup messages, and errors that name the call."""

import os

import gymnasium as gym
import numpy as np
import pytest

import sightline
import sightline.gym  # noqa: F401  (registers the environments)
import sightline.vizdoom as vzd
from vizdoom_games import open_game




def _peaks(audio: np.ndarray, frames_per_tic: int) -> list:
    """The loudest sample of each tic of a buffer."""
    return [int(np.abs(t.astype(np.int32)).max()) for t in np.split(audio, len(audio) // frames_per_tic)]


def _shot(cfg: str, tics: int = 61, **settings) -> list:
    """basic: 20 idle tics, ATTACK, then idle; every state's audio buffer.
    Seed 3's shot misses, so the episode goes on."""
    game = open_game(cfg, audio_buffer_enabled=True, **settings)
    buffers = []
    for t in range(tics):
        game.make_action([0, 0, 1] if t == 20 else [0, 0, 0])
        buffers.append(game.get_state().audio_buffer)
    return buffers


@pytest.mark.parametrize(
    "rate, hertz", [(vzd.SamplingRate.SR_11025, 11025), (vzd.SamplingRate.SR_22050, 22050), (vzd.SamplingRate.SR_44100, 44100)]
)
@pytest.mark.parametrize("tics", [1, 4])
def test_the_audio_buffer_has_vizdoom_s_shape_and_type(basic_cfg, rate, hertz, tics):
    game = open_game(basic_cfg, audio_buffer_enabled=True, audio_sampling_rate=rate, audio_buffer_size=tics)
    assert game.is_audio_buffer_enabled()
    assert game.get_audio_sampling_rate() == hertz  # ViZDoom 1.3.2's getter gives hertz
    assert game.get_audio_buffer_size() == tics
    audio = game.get_state().audio_buffer
    assert audio.dtype == np.int16
    assert audio.shape == (tics * hertz // 35, 2)
    game.make_action([0, 0, 0])
    assert game.get_state().audio_buffer.shape == (tics * hertz // 35, 2)


def test_defaults_are_vizdoom_s_and_off_means_none(basic_cfg):
    game = vzd.DoomGame()
    assert not game.is_audio_buffer_enabled() and not game.is_notifications_buffer_enabled()
    assert (game.get_audio_buffer_size(), game.get_audio_sampling_rate(), game.get_notifications_buffer_size()) == (1, 44100, 1)
    game = open_game(basic_cfg)
    state = game.get_state()
    assert state.audio_buffer is None and state.notifications_buffer is None
    native = game._running()
    with pytest.raises(RuntimeError, match="set_audio_buffer_enabled"):
        native.audio()
    with pytest.raises(RuntimeError, match="set_notifications_buffer_enabled"):
        native.notifications()


def test_the_pistol_is_heard_after_the_shot_and_not_before(basic_cfg):
    buffers = _shot(basic_cfg, audio_sampling_rate=vzd.SamplingRate.SR_22050)
    peaks = [_peaks(b, 630)[0] for b in buffers]
    rms = [float(np.sqrt(np.mean(b.astype(np.float64) ** 2))) for b in buffers]
    # Doom's pistol fires on the fifth tic after ATTACK (its first frame
    # lasts 4 tics): silence until then, not just quiet.
    assert peaks[:24] == [0] * 24
    assert peaks[24] > 8000 and rms[24] > 1000, (peaks[24], rms[24])
    assert all(p > 1000 for p in peaks[24:35]), peaks[24:]
    assert peaks[60] == 0, peaks[24:]
    # The player's own sound is centred.
    left, right = np.abs(buffers[24].astype(np.int64)).sum(axis=0)
    assert abs(left - right) * 50 < max(left, right)


def test_a_longer_buffer_holds_the_last_tics_oldest_first(basic_cfg):
    buffers = _shot(basic_cfg, tics=26, audio_buffer_size=4, audio_sampling_rate=vzd.SamplingRate.SR_11025)
    # After tic 26 the buffer holds tics 23 to 26: two silent, the shot's, one more.
    p = _peaks(buffers[-1], 315)
    assert p[0] == 0 and p[1] == 0 and p[2] > 8000 and p[3] > 1000, p
    # Each tic's sound is the one-tic buffer's of the same tic.
    one = _shot(basic_cfg, tics=26, audio_sampling_rate=vzd.SamplingRate.SR_11025)
    assert np.array_equal(buffers[-1], np.concatenate(one[-4:]))


def test_the_same_seed_and_actions_give_the_same_bytes(basic_cfg):
    a = _shot(basic_cfg, tics=40)
    b = _shot(basic_cfg, tics=40)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))
    assert any(x.any() for x in a)


def test_a_pickup_is_notified_for_the_buffer_s_tics(scenarios):
    game = open_game(os.path.join(scenarios, "health_gathering.cfg"), seed=1, notifications_buffer_enabled=True, notifications_buffer_size=3)
    texts = []
    while not game.is_episode_finished() and len(texts) < 2000:
        game.make_action(game.get_expert_action())  # the autopilot fetches medikits
        state = game.get_state()
        if state is not None:
            texts.append(state.notifications_buffer)
    first = next(i for i, t in enumerate(texts) if t)
    assert texts[first] in ("Picked up a medikit.\n", "Picked up a medikit that you REALLY need!\n")
    assert texts[first + 1] == texts[first + 2] == texts[first]
    assert isinstance(texts[0], str)


def test_script_logs_are_notified_as_vizdoom_gives_them(scenarios):
    # ViZDoom 1.3.2 gives these states (basic_notifications.cfg, buffer of
    # 4 tics, seed 1, these actions) "Shoot: Cacodemon\n", the map's Log,
    # on the states of tics 16 to 19 and nothing else in the first 40.
    game = open_game(os.path.join(scenarios, "basic_notifications.cfg"), seed=1, notifications_buffer_size=4)
    seen = []
    for i in range(40):
        game.make_action([0, 0, 1] if i % 10 == 0 else [0, 1, 0])
        state = game.get_state()
        if state is None:
            break
        if state.notifications_buffer:
            seen.append((state.tic, state.notifications_buffer))
    assert seen == [(tic, "Shoot: Cacodemon\n") for tic in (16, 17, 18, 19)]


@pytest.mark.parametrize(
    "call, value, words",
    [
        ("set_audio_sampling_rate", 5, "is not a SamplingRate"),
        ("set_audio_sampling_rate", "SR_48000", "is not a SamplingRate"),
        ("set_audio_buffer_size", -1, "is not a number of tics"),
        ("set_audio_buffer_size", 100000, "is not a number of tics from 0 to 2100"),
        ("set_notifications_buffer_size", -3, "is not an unsigned integer"),
        ("set_audio_buffer_size", "four", "is not a number of tics"),
    ],
)
def test_bad_values_are_errors_naming_the_call(call, value, words):
    game = vzd.DoomGame()
    with pytest.raises(vzd.ConfigError, match=call) as error:
        getattr(game, call)(value)
    assert words in str(error.value)


def test_the_cfg_keys_in_both_spellings(basic_cfg):
    game = vzd.DoomGame()
    game.load_config(basic_cfg)
    game.set_config("audioBufferEnabled = true\naudioSamplingRate = SR_11025\naudioBufferSize = 2\nnotificationsBufferEnabled = 1\nnotifications_buffer_size = 5")
    assert game.is_audio_buffer_enabled() and game.is_notifications_buffer_enabled()
    assert (game.get_audio_sampling_rate(), game.get_audio_buffer_size(), game.get_notifications_buffer_size()) == (11025, 2, 5)


def test_gym_observes_the_step_s_audio_and_notifications():
    env = gym.make(
        "Sightline/Basic-v0", frame_skip=4, audio_buffer_enabled=True, notifications_buffer_enabled=True,
        audio_sampling_rate="SR_22050",
    )
    space = env.observation_space
    # As ViZDoom's wrapper: the buffers hold frame_skip tics.
    assert space["audio"].shape == (4 * 630, 2) and space["audio"].dtype == np.int16
    assert isinstance(space["notifications"], gym.spaces.Text)
    obs, _ = env.reset(seed=0)
    assert obs["audio"].shape == (2520, 2) and obs["notifications"] == ""
    heard = 0
    for _ in range(4):
        obs, *_ = env.step(3)  # ATTACK alone (0 is no button)
        assert space.contains(obs)
        heard = max(heard, int(np.abs(obs["audio"].astype(np.int32)).max()))
    assert heard > 8000
    env.close()

