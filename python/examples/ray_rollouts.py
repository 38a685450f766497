#!/usr/bin/env python3
"""Rollouts of many Sightline environments as Ray actors, on one machine or
a cluster: each actor holds a Gymnasium environment and plays episodes of
a seeded random policy, and the driver gathers what they scored.

  ray start --head --port=6379                       # on the first machine
  ray start --address=HEAD_IP:6379                   # on each machine that joins
  python3 python/examples/ray_rollouts.py --address HEAD_IP:6379 --actors 16 --episodes 64

Without --address it starts Ray in this process. Every machine needs the
sightline package installed (pip install ./python) and ViZDoom's scenarios
where it looks (SIGHTLINE_VIZDOOM_DIR, or the vizdoom package). The
results depend only on the seeds: the same seeds give the same rewards
whichever actor, machine or order plays them.
"""

import argparse
import hashlib
import json

import ray


@ray.remote
class Roller:
    """One environment, playing the episodes it is given."""

    def __init__(self, env_id: str, options: dict):
        import gymnasium as gym

        import sightline.gym  # noqa: F401  (registers the ids)

        self.env = gym.make(env_id, **options)

    def rollout(self, seed: int) -> dict:
        import numpy as np

        obs, _ = self.env.reset(seed=seed)
        self.env.action_space.seed(seed)
        digest = hashlib.sha256(obs["screen"].tobytes())
        total, steps, done = 0.0, 0, False
        while not done:
            obs, reward, terminated, truncated, _ = self.env.step(self.env.action_space.sample())
            digest.update(np.ascontiguousarray(obs["screen"]).tobytes())
            total += reward
            steps += 1
            done = terminated or truncated
        return {"seed": seed, "reward": total, "steps": steps, "frames": digest.hexdigest()}


def rollouts(env_id: str, options: dict, actors: int, seeds: list) -> list:
    """Plays one episode per seed on `actors` Ray actors; results in seed order."""
    pool = [Roller.remote(env_id, options) for _ in range(actors)]
    futures = [pool[i % actors].rollout.remote(seed) for i, seed in enumerate(seeds)]
    return ray.get(futures)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--address", help="a running cluster's head (HOST:PORT); default: Ray in this process")
    ap.add_argument("--env", default="Sightline/Basic-v0")
    ap.add_argument("--resolution", default="RES_160X120")
    ap.add_argument("--actors", type=int, default=4)
    ap.add_argument("--episodes", type=int, default=16)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    ray.init(address=args.address, include_dashboard=False, log_to_driver=False)
    seeds = list(range(args.seed, args.seed + args.episodes))
    results = rollouts(args.env, {"screen_resolution": args.resolution}, args.actors, seeds)
    nodes = len([n for n in ray.nodes() if n["Alive"]])
    print(json.dumps({"nodes": nodes, "episodes": results}))


if __name__ == "__main__":
    main()
