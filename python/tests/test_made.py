"""Scenarios made in Python: a map built with sightline.maps, checked,
played through DoomGame's API, the Gymnasium environment and the vector
environment, paying what its reward specification says; bad maps and
specifications refused with the element named. The maps use only
built-in art (the zombieman and the items), so no IWAD is needed."""

import math

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import sightline
import sightline.vizdoom as vzd
from sightline.gym import SightlineEnv, SightlineVectorEnv
from sightline.maps import Map


def goal_map(monster=False):
    """A hall 512 by 256 and a goal room east of it; the player starts at
    the west end facing east, a clip on the way."""
    m = Map("Goal")
    hall = m.room(0, 0, 512, 256)
    goal = m.room(512, 64, 640, 192, light=255, floor_texture="TILE")
    m.player_start(64, 128, angle=0)
    m.thing("clip", 256, 128)
    m.thing("medikit", 128, 224)
    if monster:
        m.thing("zombieman", 448, 224, angle=180)
    return m, hall, goal


GOAL_REWARDS = lambda goal: {  # noqa: E731
    "reach": [{"sector": goal, "reward": 10.0, "end": True}],
    "pickup": {"kinds": {"clip": 1.0}},
    "living": -0.01,
}


def test_a_map_built_in_python_checks_clean_as_text_and_as_a_file(tmp_path):
    m, _, goal = goal_map(monster=True)
    findings = sightline.check(m, rewards=GOAL_REWARDS(goal))
    assert findings, "check says at least how much can be reached"
    assert all(f.severity == "note" for f in findings), [str(f) for f in findings]
    assert any("2 of 2 items" in f.message for f in findings), [str(f) for f in findings]
    path = tmp_path / "goal.ron"
    m.save(str(path))
    assert sightline.check(str(path), rewards=GOAL_REWARDS(goal)) == findings
    assert sightline.check(path.read_text(), rewards=GOAL_REWARDS(goal)) == findings


def test_check_finds_errors_and_what_cannot_be_reached():
    m = Map("No start")
    m.room(0, 0, 256, 256)
    findings = sightline.check(m)
    assert [f.severity for f in findings] == ["error"]
    assert 'no thing of kind "player_start"' in findings[0].message
    # A goal room on its own, with no way in.
    m = Map("Apart")
    m.room(0, 0, 256, 256)
    apart = m.room(512, 0, 768, 256)
    m.player_start(64, 64)
    findings = sightline.check(m, rewards={"reach": [{"sector": apart, "reward": 1.0}], "kill": 1.0})
    warnings = [f.message for f in findings if f.severity == "warning"]
    assert f"rewards.reach[0]: sector {apart} cannot be reached" in warnings, warnings
    assert any(w.startswith("rewards.kill: the map has no monster") for w in warnings), warnings


def test_overlapping_rooms_are_refused_by_the_map_model():
    m = Map("Overlap")
    m.room(0, 0, 256, 256)
    m.room(0, 0, 256, 256)
    with pytest.raises(ValueError, match="overlap"):
        m.to_ron()


def scenario(**settings):
    m, _, goal = goal_map()
    return sightline.make_scenario(m, GOAL_REWARDS(goal), buttons=["MOVE_FORWARD"], resolution=(160, 120), **settings)


def test_an_episode_in_the_gymnasium_env_pays_as_specified():
    env = SightlineEnv(scenario(timeout=700), max_buttons_pressed=1)
    assert env.action_space == gym.spaces.Discrete(2)  # none, or forward
    obs, _ = env.reset(seed=3)
    assert obs["screen"].shape == (120, 160, 3)
    rewards, terminated, truncated = [], False, False
    while not (terminated or truncated):
        _, reward, terminated, truncated, _ = env.step(1)
        rewards.append(reward)
    assert terminated and not truncated, "the goal ends the episode as the exit does"
    assert sum(rewards) == pytest.approx(1.0 + 10.0 - 0.01 * len(rewards))
    paid = [r for r in rewards if not math.isclose(r, -0.01)]
    assert paid == pytest.approx([1.0 - 0.01, 10.0 - 0.01]), "the clip, then the goal, once each"
    env.close()


def test_gymnasiums_checker_passes_on_a_made_scenario():
    env = SightlineEnv(scenario(timeout=100))
    check_env(env, skip_render_check=True)
    env.close()


def test_the_doom_game_api_plays_a_made_scenario():
    game = scenario(timeout=700, variables=["POSITION_X", "KILLCOUNT"]).doom_game()
    assert game.get_living_reward() == pytest.approx(-0.01)
    assert game.get_episode_timeout() == 700
    with pytest.raises(vzd.ConfigError, match=r"rewards\['living'\]"):
        game.set_living_reward(1.0)
    game.set_seed(11)
    game.init()
    state = game.get_state()
    assert state.game_variables.shape == (2,) and state.screen_buffer.shape == (3, 120, 160)
    while not game.is_episode_finished():
        game.make_action([1])
    assert game.get_total_reward() == pytest.approx(11.0 - 0.01 * game.get_episode_time() + 0.01)
    assert not game.is_player_dead() and not game.is_episode_timeout_reached()


def test_the_timeout_truncates_and_a_kill_pays():
    m = Map("Zombie")
    m.room(0, 0, 512, 128)
    m.player_start(64, 64, angle=0)
    m.thing("zombieman", 320, 64, angle=180)
    sc = sightline.make_scenario(m, {"kill": 1.5}, buttons=[vzd.Button.ATTACK], timeout=350, variables=["KILLCOUNT"])
    env = sc.env(max_buttons_pressed=1)
    env.reset(seed=0)
    total, steps, terminated, truncated = 0.0, 0, False, False
    while not (terminated or truncated):
        obs, reward, terminated, truncated, _ = env.step(1)
        total, steps = total + reward, steps + 1
    assert truncated and not terminated and steps == 350
    assert env.game.get_game_variable(vzd.GameVariable.KILLCOUNT) == 1
    assert total == 1.5
    env.close()


def test_the_vector_environment_plays_a_made_scenario_as_single_ones_do():
    sc = scenario(timeout=700)
    vec = SightlineVectorEnv(sc, 2, max_buttons_pressed=1, threads=2)
    vec.reset(seed=5)
    totals, done = np.zeros(2), np.zeros(2, dtype=bool)
    while not done.all():
        _, rewards, terminated, truncated, _ = vec.step(np.ones(2, dtype=np.int64))
        totals += np.where(done, 0.0, rewards)
        done |= terminated | truncated
    for i in range(2):
        env = SightlineEnv(sc, max_buttons_pressed=1)
        env.reset(seed=5 + i)
        total, finished = 0.0, False
        while not finished:
            _, r, terminated, truncated, _ = env.step(1)
            total, finished = total + r, terminated or truncated
        assert totals[i] == pytest.approx(total)
        env.close()


def test_a_seeded_episode_replays_exactly():
    m, _, goal = goal_map(monster=True)
    sc = sightline.make_scenario(m, GOAL_REWARDS(goal), buttons=["MOVE_FORWARD", "ATTACK"], resolution=(160, 120))
    runs = []
    for _ in range(2):
        env = SightlineEnv(sc, max_buttons_pressed=0)
        obs, _ = env.reset(seed=9)
        frames, rewards = [obs["screen"]], []
        for t in range(120):
            obs, r, terminated, truncated, _ = env.step(np.array([1, t % 2]))
            frames.append(obs["screen"])
            rewards.append(r)
            if terminated or truncated:
                break
        runs.append((frames, rewards))
        env.close()
    assert runs[0][1] == runs[1][1]
    assert all(np.array_equal(a, b) for a, b in zip(runs[0][0], runs[1][0]))


@pytest.mark.parametrize(
    "rewards, message",
    [
        (
            {"reach": [{"sector": 9, "reward": 1.0}]},
            r"rewards\.reach\[0\]\.sector: sector 9 is not in the map \(its sectors are 0\.\.2\)",
        ),
        ({"reach": [{"sector": 1}, {"sector": 1}]}, r"rewards\.reach\[1\]\.sector: sector 1 is already reach\[0\]"),
        ({"timeout": -1}, r"rewards\.timeout: -1 tics is negative"),
        ({"kil": 1.0}, r"rewards: unknown field `kil`"),
        (
            {"pickup": {"kinds": {"medkit": 1.0}}},
            r'rewards\.pickup\.kinds\["medkit"\]: "medkit" names no item; did you mean "medikit"\?',
        ),
        ({"living": float("nan")}, r"rewards\.living: nan is not a finite number"),
        ({"reach": [{"sector": 1, "reward": float("inf")}]}, r"rewards\.reach\[0\]\.reward: inf is not a finite"),
        ("Rewards(kill: 1.0", r"rewards: 1:15: Expected comma"),
        ("Rewards(death: -1.0, reach: [(sector: 5)])", r"rewards\.reach\[0\]\.sector: sector 5"),
    ],
)
def test_bad_specifications_raise_value_error_naming_the_element(rewards, message):
    m, _, _ = goal_map()
    with pytest.raises(ValueError, match=message):
        sightline.make_scenario(m, rewards)


def test_bad_maps_and_settings_raise_naming_what_is_wrong(tmp_path):
    with pytest.raises(ValueError, match=r"<map text>:3:14: Expected opening `\[`"):
        sightline.make_scenario("Map(\n  name: \"x\",\n    vertices: 3,\n)")
    with pytest.raises(FileNotFoundError, match="no such map file"):
        sightline.make_scenario(str(tmp_path / "missing.ron"))
    m, _, goal = goal_map()
    with pytest.raises(ValueError, match="timeout: given twice"):
        sightline.make_scenario(m, {"timeout": 10}, timeout=20)
    with pytest.raises(ValueError, match="FORWARD"):
        sightline.make_scenario(m, buttons=["FORWARD"])
    with pytest.raises(ValueError, match="resolution 100x100"):
        sightline.make_scenario(m, resolution=(100, 100))
    with pytest.raises(ValueError, match=r"rewards\['kill'\]"):
        sightline.make_scenario(m, kill_reward=1.0)
    with pytest.raises(ValueError, match=r"rewards\['timeout'\]"):
        SightlineEnv(scenario(), episode_timeout=5)
