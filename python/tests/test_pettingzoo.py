"""The PettingZoo environment: PettingZoo's own API and seed tests, and
several agents in the same tic of one game."""

import os

import numpy as np
import pytest
from pettingzoo.test import parallel_api_test, parallel_seed_test

import sightline.pettingzoo as spz


def _duel(**kwargs):
    return spz.SightlineParallelEnv("multi_duel", num_agents=2, screen_resolution="RES_160X120", max_cycles=200, **kwargs)


def test_parallel_api(scenarios):
    parallel_api_test(_duel(), num_cycles=300)


def test_parallel_seed(scenarios):
    parallel_seed_test(_duel)


@pytest.mark.parametrize(
    "name, agents", [("multi_duel", 2), ("multi", 3), ("cig", 4), ("deathmatch", 2), ("multi_duel", 8), ("cig", 16)]
)
def test_agents_act_in_one_tic_and_see_their_own_views(scenarios, name, agents):
    env = spz.SightlineParallelEnv(name, num_agents=agents, screen_resolution="RES_160X120", max_cycles=400)
    obs, _ = env.reset(seed=1)
    assert set(obs) == {f"player_{i}" for i in range(agents)}
    total = {a: 0.0 for a in env.possible_agents}
    while env.agents:
        actions = {a: env.action_space(a).sample() for a in env.agents}
        obs, rewards, term, trunc, infos = env.step(actions)
        for a, r in rewards.items():
            total[a] += r
    screens = [obs[a]["screen"].tobytes() for a in env.possible_agents]
    assert len(set(screens)) == agents, "each agent sees from its own body"
    assert all(np.isfinite(v) for v in total.values())
    env.close()


def test_bad_multi_agent_calls(scenarios):
    with pytest.raises(ValueError, match="17 agents: a game holds 1 to 16 players"):
        spz.SightlineParallelEnv("multi_duel", num_agents=17)
    with pytest.raises(ValueError, match="a game holds 1 to 16 players"):
        spz.SightlineParallelEnv("multi_duel", num_agents=0)
    env = _duel()
    env.reset(seed=0)
    with pytest.raises(ValueError, match="no action for player_1"):
        env.step({"player_0": env.action_space("player_0").sample()})


FREEDM = "/usr/share/games/doom/freedm.wad"


@pytest.fixture(scope="session")
def freedm() -> str:
    if not os.path.isfile(FREEDM):
        if os.environ.get("SIGHTLINE_REQUIRE_FREEDM", "") not in ("", "0"):
            pytest.fail("SIGHTLINE_REQUIRE_FREEDM is set but freedm.wad is not installed (apt-get install freedm)")
        pytest.skip("freedm.wad is not installed (apt-get install freedm)")
    return FREEDM


def _freedm_env(wad, agents, **kwargs):
    return spz.deathmatch_env(wad=wad, map="MAP01", num_agents=agents, timeout=200, **kwargs)


@pytest.mark.parametrize("agents", [8, 16])
def test_parallel_api_with_many_agents(freedm, agents):
    parallel_api_test(_freedm_env(freedm, agents), num_cycles=150)


@pytest.mark.parametrize("agents", [8, 16])
def test_parallel_seed_with_many_agents(freedm, agents):
    parallel_seed_test(lambda: _freedm_env(freedm, agents))


def test_sixteen_agents_each_see_their_own_view_and_score_their_own_frags(freedm):
    env = spz.deathmatch_env(wad=freedm, map="MAP03", num_agents=16, timeout=3000, frame_skip=4)
    obs, _ = env.reset(seed=5)
    assert sorted(obs) == sorted(f"player_{i}" for i in range(16))
    screens = [obs[a]["screen"].tobytes() for a in env.possible_agents]
    assert len(set(screens)) == 16, "each agent sees from its own body"
    rng = np.random.default_rng(7)
    total = {a: 0.0 for a in env.possible_agents}
    frags = None
    while env.agents:
        # Fire, run and turn at random, never USE (an exit switch would end it).
        actions = {a: (rng.random(len(spz.DEATHMATCH_BUTTONS)) < 0.3).astype(np.int64) for a in env.agents}
        for a in actions:
            actions[a][spz.DEATHMATCH_BUTTONS.index("USE")] = 0
        obs, rewards, term, trunc, infos = env.step(actions)
        for a, r in rewards.items():
            total[a] += r
        frags = [obs[a]["gamevariables"][2] for a in env.possible_agents]
    assert all(trunc.values()) and not any(term.values())
    assert any(f != 0 for f in frags[4:]), f"players 5 to 16 fragged no one: {frags}"
    assert any(total[a] != 0 for a in env.possible_agents[4:]), "players 5 to 16 were paid nothing"
    env.close()


def test_deathmatch_on_freedm(freedm):
    env = spz.deathmatch_env(wad=freedm, map="MAP01", num_agents=4, timeout=700)
    obs, _ = env.reset(seed=3)
    assert obs["player_0"]["screen"].shape == (120, 160, 3)
    assert obs["player_0"]["gamevariables"].shape == (4,)
    steps = 0
    while env.agents:
        obs, rewards, term, trunc, infos = env.step({a: env.action_space(a).sample() for a in env.agents})
        steps += 1
    assert steps == 700 and all(trunc.values())
    env.close()
