#!/usr/bin/env python3
"""Draws the learning curves of scripts/ppo.py runs side by side and prints
their table (markdown) for docs/learning.md.

    scripts/ppo-plot.py RUN.json... -o docs/learning/ppo.png

One column per scenario; the top row plots the mean return of the last 50
episodes against actions taken, the bottom row against wall-clock seconds,
one line per engine and seed. Needs matplotlib.
"""

import argparse
import json
import sys

import numpy as np

COLOURS = {"vizdoom": "tab:blue", "sightline": "tab:red"}
NAMES = {"vizdoom": "ViZDoom 1.3.2", "sightline": "Sightline"}
WINDOW = 50


def name(run: dict) -> str:
    """The engine's name, and the run's variant where it has one (a run
    of a later build, say, beside the first)."""
    variant = run.get("variant")
    return f"{NAMES[run['engine']]} ({variant})" if variant else NAMES[run["engine"]]


def colour(run: dict) -> str:
    return "tab:orange" if run.get("variant") else COLOURS[run["engine"]]


def smooth(values: list) -> np.ndarray:
    out = np.empty(len(values))
    for i in range(len(values)):
        out[i] = np.mean(values[max(0, i + 1 - WINDOW) : i + 1])
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("-o", "--out", required=True)
    args = ap.parse_args(argv)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = []
    for path in args.runs:
        with open(path) as f:
            runs.append(json.load(f))
    scenarios = sorted({r["scenario"] for r in runs}, key=lambda s: (s != "basic", s))
    fig, axes = plt.subplots(2, len(scenarios), figsize=(6 * len(scenarios), 8), squeeze=False)
    for col, scenario in enumerate(scenarios):
        for run in sorted((r for r in runs if r["scenario"] == scenario), key=lambda r: (r["engine"], r["seed"], r.get("variant", ""))):
            steps, seconds, returns = zip(*run["episodes"])
            label = f"{name(run)}, seed {run['seed']}"
            curve = smooth(returns)
            axes[0][col].plot(steps, curve, color=colour(run), alpha=0.8, label=label)
            axes[1][col].plot(seconds, curve, color=colour(run), alpha=0.8, label=label)
        axes[0][col].set_title(f"{scenario}: PPO, mean return of the last {WINDOW} episodes")
        axes[0][col].set_xlabel("actions (4 tics each)")
        axes[1][col].set_xlabel("wall-clock seconds (learner and game, one thread each)")
        for row in (0, 1):
            axes[row][col].set_ylabel("episode return")
            axes[row][col].grid(alpha=0.3)
            axes[row][col].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=90)

    print("| scenario | engine | seed | actions | wall-clock s | of which game s | return, first 100 episodes | return, last 100 episodes |")
    print("|---|---|---|---|---|---|---|---|")
    for scenario in scenarios:
        for run in sorted((r for r in runs if r["scenario"] == scenario), key=lambda r: (r["engine"], r["seed"], r.get("variant", ""))):
            returns = [e[2] for e in run["episodes"]]
            print(
                f"| {scenario} | {name(run)} | {run['seed']} | {run['steps']:,} | {run['seconds']:.0f} | "
                f"{run['game_seconds']:.0f} | {np.mean(returns[:100]):.1f} | {np.mean(returns[-100:]):.1f} |"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
