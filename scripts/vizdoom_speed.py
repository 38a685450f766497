"""Steps per second of the vizdoom package and of Sightline's Python
package, measured in one run, alternating (`vizdoom-compare.py --speed`).

A step is what a learner's loop does: the state read and its screen copied
into a numpy array of its own, then one action of random buttons held for
the frame skip; a finished episode starts a new one (its start counted).
The random actions are drawn before a round's clock starts, for every
loop alike: a learner's policy makes them, and they are neither engine's
work (drawing a vector's actions with numpy each call took 7-12 µs, a
tenth of a 4-game call at 160x120).
Each cell is the median of several rounds, the two engines taking turns
round by round, so a noisy neighbour on a shared machine hits both alike.
Sightline's vector environment is measured too: N games stepped together
on all cores, every game's screen copied each step, a finished game
starting anew in the next call on the games' threads (`resets`).
"""

from __future__ import annotations

import os
import random
import statistics
import time

import numpy as np

RESOLUTIONS = ["RES_160X120", "RES_320X240", "RES_640X480"]


def _game(module, cfg: str, resolution: str, seed: int):
    game = module.DoomGame()
    game.load_config(cfg)
    game.set_window_visible(False)
    game.set_screen_format(module.ScreenFormat.RGB24)
    game.set_screen_resolution(getattr(module.ScreenResolution, resolution))
    game.set_mode(module.Mode.PLAYER)
    game.set_seed(seed)
    game.init()
    return game


def _round(game, steps: int, skip: int, rng: random.Random) -> float:
    buttons = game.get_available_buttons_size()
    # The actions are drawn before the clock starts: a learner's policy
    # makes them, and drawing them is neither engine's work.
    actions = [[rng.random() < 0.5 for _ in range(buttons)] for _ in range(steps)]
    start = time.perf_counter()
    for action in actions:
        if game.is_episode_finished():
            game.new_episode()
        state = game.get_state()
        screen = np.array(state.screen_buffer, copy=True)
        del screen
        game.make_action(action, skip)
    return steps / (time.perf_counter() - start)


def _vector_round(games, steps: int, skip: int, rng: np.random.Generator) -> float:
    n = len(games)
    actions = rng.integers(0, 2, size=(steps, n, games.buttons)).astype(np.float64)
    seeds = rng.integers(0, 2**31 - 1, size=(steps, n)).tolist()
    start = time.perf_counter()
    screens = np.array(games.screens(), copy=True)
    resets = None
    for k in range(steps):
        _, done, screens = games.step_screens(actions[k], skip, resets)
        screens = np.array(screens, copy=True)
        # A finished game starts anew in the next call, on the games' threads.
        resets = [seed if end else None for end, seed in zip(done.tolist(), seeds[k])] if done.any() else None
    return n * steps / (time.perf_counter() - start)


class _VectorGames:
    def __init__(self, sightline, cfg: str, resolution: str, count: int):
        config = sightline.Config()
        config.load(cfg)
        config.apply(f"screen_resolution = {resolution}\nscreen_format = RGB24", "<speed>")
        self.games = sightline.Games(config, count, threads=0)
        self.buttons = len(config.to_dict()["available_buttons"])
        for i in range(count):
            self.games.new_episode(i, i)

    def __len__(self):
        return len(self.games)

    def screens(self):
        return self.games.screens()

    def step_screens(self, actions, skip, resets):
        return self.games.step_screens(actions, skip, resets)


def measure(scenarios: str, names: list, steps: int, rounds: int, log) -> list:
    """Rows of (scenario, resolution, skip, vizdoom steps/s, sightline
    steps/s, [(vector games, sightline vector steps/s), ...])."""
    import vizdoom

    import sightline
    import sightline.vizdoom as svzd

    cores = os.cpu_count() or 1
    # Two games a core and four: more games even out the threads' shares
    # (a game starting a new episode takes longer than one stepping) and
    # spread each call's serial part, the caller's Python, over more steps.
    counts = (2 * cores, 4 * cores)
    rows = []
    for name in names:
        cfg = os.path.join(scenarios, f"{name}.cfg")
        for resolution in RESOLUTIONS:
            for skip in (1, 4):
                theirs = _game(vizdoom, cfg, resolution, 1)
                ours = _game(svzd, cfg, resolution, 1)
                vectors = [_VectorGames(sightline, cfg, resolution, count) for count in counts]
                rng_a, rng_b = random.Random(1), random.Random(1)
                rngs_v = [np.random.default_rng(1) for _ in counts]
                a, b, v = [], [], [[] for _ in counts]
                for _ in range(rounds):
                    a.append(_round(theirs, steps, skip, rng_a))
                    b.append(_round(ours, steps, skip, rng_b))
                    for vector, rng_v, out in zip(vectors, rngs_v, v):
                        out.append(_vector_round(vector, max(1, steps // len(vector)), skip, rng_v))
                theirs.close()
                ours.close()
                vector_rates = [(count, statistics.median(rates)) for count, rates in zip(counts, v)]
                row = (name, resolution, skip, statistics.median(a), statistics.median(b), vector_rates)
                vectors_text = ", ".join(f"vector of {n} {r:.0f} ({r / row[4]:.2f}x one)" for n, r in vector_rates)
                log(
                    f"{name} {resolution} skip {skip}: vizdoom {row[3]:.0f}, sightline {row[4]:.0f} "
                    f"({row[4] / row[3]:.2f}x), {vectors_text}"
                )
                rows.append(row)
    return rows


def table(rows: list, steps: int, rounds: int) -> str:
    cores = os.cpu_count() or 1
    out = [
        f"Steps per second, median of {rounds} rounds of {steps} steps each, the engines alternating "
        f"round by round; one process on this {cores}-core machine; RGB24; the state's screen copied "
        "to numpy every step; random buttons. `vector` is Sightline's native vector environment "
        "(`sightline.Games`) stepping its games on all cores, counted in game steps.",
        "",
        "| scenario | resolution | frame skip | vizdoom | sightline | ratio | vector (games) | vector / one |"
        " vector (games) | vector / one |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, res, skip, a, b, vector_rates in rows:
        vectors = " | ".join(f"{r:,.0f} ({n}) | {r / b:.2f}x" for n, r in vector_rates)
        out.append(f"| {name} | {res[4:].lower()} | {skip} | {a:,.0f} | {b:,.0f} | {b / a:.2f}x | {vectors} |")
    return "\n".join(out) + "\n"
