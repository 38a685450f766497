"""The autopilot as an expert for imitation learning: ``DoomGame``'s
``get_expert_action``, the environments' ``expert_action`` and
``info["expert_action"]``, and that following it plays well."""

import gymnasium as gym
import numpy as np
import pytest

import sightline.gym as sgym
import sightline.vizdoom as vzd

SMALL = {"screen_resolution": "RES_160X120"}


@pytest.mark.parametrize("env_id", sgym.ENV_IDS)
def test_the_expert_action_is_in_the_action_space_of_every_id(scenarios, env_id):
    env = gym.make(env_id, **SMALL).unwrapped
    env.reset(seed=4)
    for _ in range(30):
        action = env.expert_action()
        assert env.action_space.contains(action), (env_id, action)
        _, _, terminated, truncated, _ = env.step(action)
        if terminated or truncated:
            break
    env.close()


def test_the_info_field_is_there_only_when_asked_for(scenarios):
    plain = gym.make("Sightline/Basic-v0", **SMALL)
    _, info = plain.reset(seed=1)
    assert "expert_action" not in info
    _, _, _, _, info = plain.step(0)
    assert "expert_action" not in info
    plain.close()
    env = gym.make("Sightline/Basic-v0", expert=True, **SMALL)
    _, info = env.reset(seed=1)
    assert env.action_space.contains(info["expert_action"])
    _, _, _, _, info = env.step(0)
    assert env.action_space.contains(info["expert_action"])
    # The field and the call agree (asked twice on one tic, the same answer).
    assert info["expert_action"] == env.unwrapped.expert_action()
    env.close()


def test_following_the_expert_on_basic_pays(scenarios):
    """Imitation's sanity check: the Discrete action nearest the expert's,
    taken every step, wins Basic (the random policy's mean is about -230)."""
    env = gym.make("Sightline/Basic-v0", expert=True, **SMALL)
    totals = []
    for seed in range(8):
        _, info = env.reset(seed=seed)
        total, done = 0.0, False
        while not done:
            _, reward, terminated, truncated, info = env.step(info["expert_action"])
            total += reward
            done = terminated or truncated
        totals.append(total)
    env.close()
    assert np.mean(totals) > 0, totals


def test_discrete_ids_take_the_nearest_combination(scenarios):
    """One button at a time: ATTACK wins over a strafe pressed with it,
    a turn over MOVE_FORWARD (turning first walks where it should)."""
    env = sgym.SightlineEnv("health_gathering", max_buttons_pressed=1, **SMALL)
    spec = env._spec
    names = [b.name for b in spec.buttons]
    turn_and_walk = [1.0 if n in ("TURN_LEFT", "MOVE_FORWARD") else 0.0 for n in names]
    assert spec.combos[spec.from_buttons(turn_and_walk)] == (names.index("TURN_LEFT"),)
    assert spec.from_buttons([0.0] * len(names)) == 0
    env.close()
    basic = sgym.SightlineEnv("basic", max_buttons_pressed=1, **SMALL)
    spec = basic._spec
    names = [b.name for b in spec.buttons]
    strafe_and_fire = [1.0 if n in ("MOVE_LEFT", "ATTACK") else 0.0 for n in names]
    assert spec.combos[spec.from_buttons(strafe_and_fire)] == (names.index("ATTACK"),)
    basic.close()


def test_delta_buttons_carry_the_expert_turn_in_the_box(scenarios):
    env = sgym.SightlineEnv(
        "defend_the_center",
        available_buttons=[vzd.Button.ATTACK, vzd.Button.TURN_LEFT_RIGHT_DELTA],
        **SMALL,
    )
    env.reset(seed=2)
    turned = False
    for _ in range(60):
        action = env.expert_action()
        assert env.action_space.contains(action)
        turned |= action["continuous"][0] != 0.0
        env.step(action)
    assert turned, "the expert never turned"
    env.close()


def test_doom_game_gives_one_value_per_button_and_nothing_after_the_end(basic_cfg):
    game = vzd.DoomGame()
    game.load_config(basic_cfg)
    game.set_screen_resolution(vzd.ScreenResolution.RES_160X120)
    game.set_seed(3)
    game.init()
    while not game.is_episode_finished():
        action = game.get_expert_action()
        assert len(action) == game.get_available_buttons_size()
        game.make_action(action)
    assert game.get_total_reward() > 0
    assert game.get_expert_action() == [0.0] * game.get_available_buttons_size()
    game.close()


def test_the_vector_env_gives_every_games_expert_action(scenarios):
    envs = sgym.SightlineVectorEnv("basic", num_envs=3, expert=True, **SMALL)
    _, infos = envs.reset(seed=5)
    assert envs.action_space.contains(infos["expert_action"])
    assert infos["_expert_action"].all()
    totals = np.zeros(3)
    for _ in range(120):
        _, rewards, _, _, infos = envs.step(infos["expert_action"])
        totals += rewards
    assert envs.action_space.contains(envs.expert_actions())
    assert (totals > 0).all(), totals
    envs.close()
    plain = sgym.SightlineVectorEnv("basic", num_envs=2, **SMALL)
    _, infos = plain.reset(seed=5)
    assert "expert_action" not in infos
    plain.close()


def test_the_expert_explores_a_scenario_made_in_python_into_its_goal_room():
    """A made scenario (no IWAD needed): a hall and a goal room east of it.
    With nothing to fight or take, the expert goes to the sector it has
    not stood in, and the goal pays and ends the episode."""
    import sightline
    from sightline.maps import Map

    m = Map("Goal")
    m.room(0, 0, 512, 256)
    goal = m.room(512, 64, 640, 192)
    m.player_start(64, 128, angle=90)
    rewards = {"reach": [{"sector": goal, "reward": 10.0, "end": True}], "living": -0.01}
    buttons = ["TURN_LEFT", "TURN_RIGHT", "MOVE_FORWARD"]
    scenario = sightline.make_scenario(m, rewards, buttons=buttons, resolution=(160, 120), timeout=700)
    env = sgym.SightlineEnv(scenario, max_buttons_pressed=1, expert=True)
    _, info = env.reset(seed=0)
    total, done = 0.0, False
    while not done:
        _, reward, terminated, truncated, info = env.step(info["expert_action"])
        total += reward
        done = terminated or truncated
    env.close()
    # The goal pays 10; 700 tics of living cost 7 at most.
    assert terminated and total > 3, total
