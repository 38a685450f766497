#!/usr/bin/env python3
"""A short PPO learner (CleanRL's recipe, in numpy) for the learning proof.

The same script trains on ViZDoom and on Sightline: the only difference is
the import (``import vizdoom`` or ``import sightline.vizdoom as vizdoom``),
so both engines get the same settings, the same network, the same seeds and
the same number of steps. It writes one JSON file of episode returns against
steps and wall-clock seconds; ``scripts/ppo-plot.py`` draws them.

    scripts/ppo.py --engine sightline --scenario basic --steps 100000 --seed 1 -o out.json

The policy is a two-layer perceptron (tanh hidden layer shared by the policy
and value heads) on the 160x120 grey screen averaged down to 80x60 and standardised, with the
actions the scenario's buttons one at a time (three for Basic and Defend the
Center), four tics per action. numpy has no automatic gradients, so the
backward pass is written out below; nothing else (torch, stable-baselines3)
is needed, and the whole learner is this file.
"""

import argparse
import importlib
import json
import os
import sys
import time

import numpy as np

POOL = 2  # 160x120 averaged in 2x2 blocks: 80x60 inputs


def make_games(vizdoom, scenario: str, n: int, seed: int) -> list:
    games = []
    for i in range(n):
        game = vizdoom.DoomGame()
        game.load_config(os.path.join(vizdoom.scenarios_path, f"{scenario}.cfg"))
        game.set_screen_resolution(vizdoom.ScreenResolution.RES_160X120)
        game.set_screen_format(vizdoom.ScreenFormat.GRAY8)
        game.set_window_visible(False)
        game.set_seed(seed * 1000 + i)
        game.init()
        games.append(game)
    return games


class Normalise:
    """Each input standardised by the running mean and variance of all the
    screens seen so far (Gymnasium's NormalizeObservation): the room's still
    background goes to about zero, and what moves (the monsters) stands out."""

    def __init__(self, size: int):
        self.mean = np.zeros(size, np.float64)
        self.var = np.ones(size, np.float64)
        self.count = 1e-4

    def __call__(self, batch: np.ndarray) -> np.ndarray:
        mean, var, n = batch.mean(axis=0), batch.var(axis=0), len(batch)
        total = self.count + n
        delta = mean - self.mean
        self.mean += delta * n / total
        self.var = (self.var * self.count + var * n + delta**2 * self.count * n / total) / total
        self.count = total
        return np.clip((batch - self.mean) / np.sqrt(self.var + 1e-8), -5, 5).astype(np.float32)


def observe(game) -> np.ndarray:
    screen = game.get_state().screen_buffer  # (120, 160) uint8
    h, w = screen.shape
    pooled = screen.reshape(h // POOL, POOL, w // POOL, POOL).mean(axis=(1, 3))
    return (pooled.ravel() / 255.0).astype(np.float32)


class Net:
    """x -> tanh(x W1 + b1) -> (logits, value), with Adam."""

    def __init__(self, inputs: int, hidden: int, actions: int, rng: np.random.Generator):
        def layer(n_in, n_out, scale):
            return (rng.standard_normal((n_in, n_out)) * scale / np.sqrt(n_in)).astype(np.float32)

        self.params = {
            "w1": layer(inputs, hidden, 1.0),
            "b1": np.zeros(hidden, np.float32),
            "wp": layer(hidden, actions, 0.01),
            "bp": np.zeros(actions, np.float32),
            "wv": layer(hidden, 1, 1.0),
            "bv": np.zeros(1, np.float32),
        }
        self.m = {k: np.zeros_like(v) for k, v in self.params.items()}
        self.v = {k: np.zeros_like(v) for k, v in self.params.items()}
        self.t = 0

    def forward(self, x: np.ndarray):
        p = self.params
        h = np.tanh(x @ p["w1"] + p["b1"])
        logits = h @ p["wp"] + p["bp"]
        value = (h @ p["wv"] + p["bv"])[:, 0]
        return h, logits, value

    def adam(self, grads: dict, lr: float, max_norm: float = 0.5):
        norm = np.sqrt(sum(float((g * g).sum()) for g in grads.values()))
        scale = min(1.0, max_norm / (norm + 1e-8))
        self.t += 1
        b1, b2, eps = 0.9, 0.999, 1e-5
        for k, g in grads.items():
            g = g * scale
            self.m[k] = b1 * self.m[k] + (1 - b1) * g
            self.v[k] = b2 * self.v[k] + (1 - b2) * g * g
            mhat = self.m[k] / (1 - b1**self.t)
            vhat = self.v[k] / (1 - b2**self.t)
            self.params[k] -= lr * mhat / (np.sqrt(vhat) + eps)


def log_softmax(logits: np.ndarray) -> np.ndarray:
    z = logits - logits.max(axis=1, keepdims=True)
    return z - np.log(np.exp(z).sum(axis=1, keepdims=True))


def ppo_grads(net: Net, x, actions, old_logp, adv, returns, clip, vf_coef, ent_coef):
    """The gradients of CleanRL's PPO loss (clipped surrogate, value error,
    entropy bonus) for one minibatch, written out by hand."""
    p = net.params
    n = len(x)
    h, logits, value = net.forward(x)
    logp_all = log_softmax(logits)
    probs = np.exp(logp_all)
    rows = np.arange(n)
    logp = logp_all[rows, actions]
    ratio = np.exp(logp - old_logp)
    unclipped = ratio * adv
    clipped = np.clip(ratio, 1 - clip, 1 + clip) * adv
    # d(-mean(min(unclipped, clipped)))/d logp: only where the unclipped term is the minimum.
    dlogp = np.where(unclipped <= clipped, -adv * ratio, 0.0) / n
    dlogits = -probs * dlogp[:, None]
    dlogits[rows, actions] += dlogp
    entropy = -(probs * logp_all).sum(axis=1)
    dlogits += ent_coef / n * probs * (logp_all + entropy[:, None])
    dvalue = vf_coef * (value - returns) / n
    dh = dlogits @ p["wp"].T + dvalue[:, None] @ p["wv"].T
    dz = dh * (1 - h * h)
    grads = {
        "w1": x.T @ dz,
        "b1": dz.sum(axis=0),
        "wp": h.T @ dlogits,
        "bp": dlogits.sum(axis=0),
        "wv": h.T @ dvalue[:, None],
        "bv": np.array([dvalue.sum()], np.float32),
    }
    return {k: g.astype(np.float32) for k, g in grads.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--engine", choices=["vizdoom", "sightline"], required=True)
    ap.add_argument("--scenario", default="basic")
    ap.add_argument("--steps", type=int, default=100_000, help="actions in all (each is --skip tics)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--envs", type=int, default=8)
    ap.add_argument("--rollout", type=int, default=128, help="actions per game per update")
    ap.add_argument("--skip", type=int, default=4, help="tics per action")
    ap.add_argument("--hidden", type=int, default=128)
    ap.add_argument("--lr", type=float, default=5e-4)
    ap.add_argument("--reward-scale", type=float, default=1.0)
    ap.add_argument("-o", "--out", required=True)
    args = ap.parse_args(argv)

    vizdoom = importlib.import_module("vizdoom" if args.engine == "vizdoom" else "sightline.vizdoom")
    rng = np.random.default_rng(args.seed)
    games = make_games(vizdoom, args.scenario, args.envs, args.seed)
    buttons = games[0].get_available_buttons_size()
    choices = [[1.0 if b == a else 0.0 for b in range(buttons)] for a in range(buttons)]
    inputs = (120 // POOL) * (160 // POOL)
    net = Net(inputs, args.hidden, len(choices), rng)

    gamma, lam, clip, epochs, minibatches = 0.99, 0.95, 0.1, 4, 4
    vf_coef, ent_coef = 0.5, 0.01
    n, t_len = args.envs, args.rollout
    normalise = Normalise(inputs)
    raw = np.stack([observe(g) for g in games])
    obs = normalise(raw)
    xs = np.zeros((t_len, n, inputs), np.float32)
    acts = np.zeros((t_len, n), np.int64)
    logps = np.zeros((t_len, n), np.float32)
    rewards = np.zeros((t_len, n), np.float32)
    dones = np.zeros((t_len, n), np.float32)
    values = np.zeros((t_len, n), np.float32)
    episodes = []  # (steps, seconds, return)
    steps = 0
    start = time.perf_counter()
    game_seconds = 0.0
    updates = args.steps // (n * t_len)
    for update in range(updates):
        lr = args.lr * (1 - update / updates)
        for t in range(t_len):
            _, logits, value = net.forward(obs)
            logp_all = log_softmax(logits)
            probs = np.exp(logp_all)
            a = np.array([rng.choice(len(choices), p=row / row.sum()) for row in probs])
            xs[t], acts[t], values[t] = obs, a, value
            logps[t] = logp_all[np.arange(n), a]
            g0 = time.perf_counter()
            for i, game in enumerate(games):
                rewards[t, i] = game.make_action(choices[a[i]], args.skip) * args.reward_scale
                done = game.is_episode_finished()
                dones[t, i] = done
                if done:
                    elapsed = round(time.perf_counter() - start, 2)
                    episodes.append((steps + i + 1, elapsed, round(game.get_total_reward(), 2)))
                    game.new_episode()
                raw[i] = observe(game)
            game_seconds += time.perf_counter() - g0
            obs = normalise(raw)
            steps += n
        # Generalised advantage estimates, bootstrapped from the last value.
        _, _, next_value = net.forward(obs)
        adv = np.zeros((t_len, n), np.float32)
        last = np.zeros(n, np.float32)
        for t in reversed(range(t_len)):
            nxt = next_value if t == t_len - 1 else values[t + 1]
            live = 1.0 - dones[t]
            delta = rewards[t] + gamma * nxt * live - values[t]
            last = delta + gamma * lam * live * last
            adv[t] = last
        returns = adv + values
        b_x, b_a = xs.reshape(-1, inputs), acts.ravel()
        b_logp, b_adv, b_ret = logps.ravel(), adv.ravel(), returns.ravel()
        size = len(b_x)
        for _ in range(epochs):
            order = rng.permutation(size)
            for mb in np.array_split(order, minibatches):
                mb_adv = (b_adv[mb] - b_adv[mb].mean()) / (b_adv[mb].std() + 1e-8)
                grads = ppo_grads(net, b_x[mb], b_a[mb], b_logp[mb], mb_adv, b_ret[mb], clip, vf_coef, ent_coef)
                net.adam(grads, lr)
        recent = [r for _, _, r in episodes[-20:]]
        if recent and update % 10 == 0:
            print(
                f"{args.engine} {args.scenario} update {update + 1}/{updates}: {steps} steps, "
                f"{time.perf_counter() - start:.0f} s, {len(episodes)} episodes, mean return of the last 20 "
                f"{np.mean(recent):.1f}, actions taken {np.bincount(b_a, minlength=len(choices)) / size}",
                file=sys.stderr,
            )
    for game in games:
        game.close()
    result = {
        "engine": args.engine,
        "scenario": args.scenario,
        "seed": args.seed,
        "settings": {k: v for k, v in vars(args).items() if k not in ("engine", "scenario", "seed", "out")},
        "seconds": time.perf_counter() - start,
        "game_seconds": game_seconds,
        "steps": steps,
        "episodes": episodes,
    }
    tmp = args.out + ".part"
    with open(tmp, "w") as f:
        json.dump(result, f, separators=(",", ":"))
    os.replace(tmp, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
