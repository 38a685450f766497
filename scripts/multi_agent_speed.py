"""Steps per second of several agents in one game (`sightline.pettingzoo`'s
core, `sightline._native.MultiGame`): deathmatch on freedm's MAP01 with
2, 4, 8 and 16 agents, at 160x120.

A step is one tic for every agent at once: random buttons for each (never
USE, which could press the exit switch), then, in the "screens" column,
every agent's screen drawn from its own eyes and copied into numpy; the
"no screens" column steps alone; the "ParallelEnv" column is PettingZoo's
`step` with its observation dictionaries (screens and game variables).
Each cell is the median of five rounds; a finished episode starts anew
(its start counted).

    python3 scripts/multi_agent_speed.py [--wad /usr/share/games/doom/freedm.wad] [--steps 300]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import sightline._native
from sightline.vizdoom import DoomGame
import sightline.pettingzoo as spz


def _game(wad: str, agents: int):
    game = DoomGame()
    game.set_config(
        {
            "doom_game_path": wad,
            "doom_map": "MAP01",
            "doom_skill": 3,
            "screen_resolution": "RES_160X120",
            "screen_format": "RGB24",
            "available_buttons": spz.DEATHMATCH_BUTTONS,
        }
    )
    return sightline._native.MultiGame(game._config, agents, 1)


def _round(game, agents: int, steps: int, screens: bool, rng: np.random.Generator) -> float:
    use = spz.DEATHMATCH_BUTTONS.index("USE")
    start = time.perf_counter()
    for _ in range(steps):
        if game.is_finished():
            game.new_episode(int(rng.integers(0, 2**31 - 1)))
        actions = (rng.random((agents, len(spz.DEATHMATCH_BUTTONS))) < 0.3).astype(np.float64)
        actions[:, use] = 0.0
        game.step(actions, 1)
        if screens:
            np.array(game.screens(), copy=True)
    return steps / (time.perf_counter() - start)


def _env_round(env, steps: int, rng: np.random.Generator) -> float:
    use = spz.DEATHMATCH_BUTTONS.index("USE")
    start = time.perf_counter()
    for _ in range(steps):
        if not env.agents:
            env.reset(seed=int(rng.integers(0, 2**31 - 1)))
        actions = {a: (rng.random(len(spz.DEATHMATCH_BUTTONS)) < 0.3).astype(np.int64) for a in env.agents}
        for a in actions:
            actions[a][use] = 0
        env.step(actions)
    return steps / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wad", default="/usr/share/games/doom/freedm.wad")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    print("| agents | screens: steps/s | agent-frames/s | no screens: steps/s | ParallelEnv: steps/s |")
    print("|---|---|---|---|---|")
    for agents in [2, 4, 8, 16]:
        game = _game(args.wad, agents)
        game.new_episode(1)
        env = spz.deathmatch_env(wad=args.wad, map="MAP01", num_agents=agents, timeout=100_000)
        env.reset(seed=1)
        cells: dict = {"screens": [], "bare": [], "env": []}
        for _ in range(args.rounds):
            cells["screens"].append(_round(game, agents, args.steps, True, rng))
            cells["bare"].append(_round(game, agents, args.steps, False, rng))
            cells["env"].append(_env_round(env, args.steps, rng))
        med = {k: statistics.median(v) for k, v in cells.items()}
        print(
            f"| {agents} | {med['screens']:,.0f} | {med['screens'] * agents:,.0f} | {med['bare']:,.0f} | {med['env']:,.0f} |"
        )


if __name__ == "__main__":
    main()
