"""The Gymnasium environments: Gymnasium's own checker on every id, the
spaces, seeding, and the vector environment against single ones, byte
for byte and whatever its thread count."""

import os

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import sightline.gym as sgym


@pytest.mark.parametrize("env_id", sgym.ENV_IDS)
def test_check_env_on_every_registered_id(scenarios, env_id):
    env = gym.make(env_id, screen_resolution="RES_160X120").unwrapped
    check_env(env, skip_render_check=True)
    env.close()


def test_spaces_follow_the_cfg(scenarios):
    env = gym.make("Sightline/Basic-v0")
    assert env.action_space == gym.spaces.Discrete(4)  # none, or one of three buttons
    obs, info = env.reset(seed=1)
    assert obs["screen"].shape == (240, 320, 3)
    assert obs["gamevariables"].shape == (1,)
    env.close()
    multi = gym.make("Sightline/Basic-MultiBinary-v0")
    assert multi.action_space == gym.spaces.MultiBinary(3)
    multi.close()
    with pytest.raises(ValueError, match="no available buttons"):
        sgym.SightlineEnv("basic", available_buttons=[], screen_resolution="RES_160X120")


def test_delta_buttons_make_a_dict_space(scenarios):
    import sightline.vizdoom as vzd

    env = sgym.SightlineEnv(
        "basic",
        screen_resolution=vzd.ScreenResolution.RES_160X120,
        available_buttons=[vzd.Button.ATTACK, vzd.Button.TURN_LEFT_RIGHT_DELTA],
    )
    assert isinstance(env.action_space, gym.spaces.Dict)
    env.reset(seed=0)
    angle0 = env.game.get_game_variable(vzd.GameVariable.ANGLE)
    env.step({"binary": 0, "continuous": np.array([10.0], dtype=np.float32)})
    angle1 = env.game.get_game_variable(vzd.GameVariable.ANGLE)
    assert (angle0 - angle1) % 360 == pytest.approx(10.0, abs=0.1)  # positive turns right
    env.close()


def test_timeout_truncates_and_death_terminates(scenarios):
    env = gym.make("Sightline/Basic-v0", screen_resolution="RES_160X120")
    env.reset(seed=0)
    steps, truncated, terminated = 0, False, False
    while not (truncated or terminated):
        _, _, terminated, truncated, _ = env.step(1)  # move left: never kills
        steps += 1
    assert truncated and not terminated
    assert steps == 300  # basic.cfg's episode_timeout
    env.close()


def test_reset_seed_replays(scenarios):
    env = gym.make("Sightline/DefendTheCenter-v0", screen_resolution="RES_160X120")

    def rollout(seed):
        obs, _ = env.reset(seed=seed)
        frames = [obs["screen"].tobytes()]
        for a in [3, 3, 1, 2, 3] * 10:
            obs, *_ = env.step(a)
            frames.append(obs["screen"].tobytes())
        return frames

    assert rollout(4) == rollout(4)
    assert rollout(4) != rollout(5)
    env.close()


# Tics an episode of the rollouts below may last: short, so that every game
# ends episodes and starts new ones (the autoreset) within the rollout.
EPISODE = 45


def _single_rollouts(n, seed, actions):
    out = []
    for i in range(n):
        env = sgym.SightlineEnv(
            "defend_the_center", max_buttons_pressed=1, screen_resolution="RES_160X120", episode_timeout=EPISODE
        )
        obs, _ = env.reset(seed=seed + i)
        frames = [obs["screen"].tobytes()]
        rewards = []
        done, resets = False, 0
        for a in actions[:, i]:
            if done:  # the vector environment's next-step autoreset
                obs, _ = env.reset()
                r, done, resets = 0.0, False, resets + 1
            else:
                obs, r, term, trunc, _ = env.step(int(a))
                done = term or trunc
            frames.append(obs["screen"].tobytes())
            rewards.append(r)
        assert resets >= 2, f"game {i}: the rollout should start new episodes"
        out.append((frames, rewards))
        env.close()
    return out


def _vector_rollouts(n, seed, actions, threads):
    venv = sgym.SightlineVectorEnv(
        "defend_the_center",
        n,
        max_buttons_pressed=1,
        threads=threads,
        screen_resolution="RES_160X120",
        episode_timeout=EPISODE,
    )
    obs, _ = venv.reset(seed=seed)
    frames = [[obs["screen"][i].tobytes()] for i in range(n)]
    rewards = [[] for _ in range(n)]
    for row in actions:
        obs, r, term, trunc, _ = venv.step(row)
        for i in range(n):
            frames[i].append(obs["screen"][i].tobytes())
            rewards[i].append(float(r[i]))
    venv.close()
    return [(frames[i], rewards[i]) for i in range(n)]


def test_vector_env_matches_single_envs_byte_for_byte(scenarios):
    n = 3
    actions = np.random.default_rng(9).integers(0, 4, size=(120, n))
    single = _single_rollouts(n, 100, actions)
    one_thread = _vector_rollouts(n, 100, actions, threads=1)
    two_threads = _vector_rollouts(n, 100, actions, threads=2)
    assert one_thread == single
    assert two_threads == single


def test_games_resets_and_their_bad_calls(scenarios):
    import sightline

    config = sightline.Config()
    config.load(os.path.join(scenarios, "basic.cfg"))
    config.apply("screen_resolution = RES_160X120", "<test>")
    games = sightline.Games(config, 2, threads=2)
    games.new_episode(0, 1)
    games.new_episode(1, 2)
    act = np.zeros((2, 3))
    _, _, first = games.step_screens(act, 4)
    kept = first.copy()
    # The array a call returned is never drawn into again while Python
    # holds it; one let go of may be.
    _, _, second = games.step_screens(act, 4)
    assert np.array_equal(first, kept)
    assert second is not first
    # A reset seeded as new_episode seeds it gives the same screen.
    rewards, done, screens = games.step_screens(act, 4, [7, None])
    assert rewards[0] == 0.0 and not done[0]
    fresh = sightline.Games(config, 1, threads=1)
    fresh.new_episode(0, 7)
    assert np.array_equal(screens[0], fresh.screens()[0])
    with pytest.raises(ValueError, match="resets has 1 entries for 2 games"):
        games.step(act, 1, [None])
    with pytest.raises(ValueError, match="actions has 3 rows for 2 games"):
        games.step(np.zeros((3, 3)), 1)
    with pytest.raises(TypeError):
        games.step(act, 1, ["soon", None])
