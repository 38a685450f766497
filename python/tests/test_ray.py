"""Rollouts as Ray actors on a local cluster (`ray start --head`, then the
example joins it by address), equal to the same seeds played here."""

import json
import os
import socket
import subprocess
import sys
import tempfile

import pytest

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "examples", "ray_rollouts.py")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_rollouts_on_a_local_cluster_match_local_play(scenarios):
    ray = pytest.importorskip("ray", reason="ray is not installed (pip install ./python[test])")
    bin_dir = os.path.dirname(sys.executable)
    ray_cli = os.path.join(bin_dir, "ray")
    port = _free_port()
    env = dict(os.environ, SIGHTLINE_VIZDOOM_DIR=scenarios, RAY_USAGE_STATS_ENABLED="0")
    # Ray's sockets live under its temp dir, and a Unix socket's path is at
    # most 107 bytes: a short one of our own.
    temp = tempfile.mkdtemp(prefix="ray", dir="/tmp")
    head = [ray_cli, "start", "--head", f"--port={port}", "--node-ip-address=127.0.0.1", "--num-cpus=2",
            "--include-dashboard=false", f"--temp-dir={temp}", "--disable-usage-stats"]
    started = subprocess.run(head, env=env, capture_output=True, text=True, timeout=180)
    assert started.returncode == 0, started.stdout + started.stderr
    try:
        out = subprocess.run(
            [sys.executable, EXAMPLE, "--address", f"127.0.0.1:{port}", "--actors", "3", "--episodes", "6"],
            check=True, env=env, capture_output=True, text=True, timeout=600,
        )
    except subprocess.CalledProcessError as e:
        pytest.fail(f"the example failed: {e.stdout}{e.stderr}")
    finally:
        subprocess.run([ray_cli, "stop", "--force"], env=env, capture_output=True, timeout=120)
    report = json.loads(out.stdout.strip().splitlines()[-1])
    assert report["nodes"] >= 1
    episodes = report["episodes"]
    assert [e["seed"] for e in episodes] == list(range(6))
    # The same seeds played in this process, without Ray: the same episodes.
    import gymnasium as gym
    import hashlib
    import numpy as np

    import sightline.gym  # noqa: F401

    local = gym.make("Sightline/Basic-v0", screen_resolution="RES_160X120")
    for e in episodes:
        obs, _ = local.reset(seed=e["seed"])
        local.action_space.seed(e["seed"])
        digest = hashlib.sha256(obs["screen"].tobytes())
        total, steps, done = 0.0, 0, False
        while not done:
            obs, r, term, trunc, _ = local.step(local.action_space.sample())
            digest.update(np.ascontiguousarray(obs["screen"]).tobytes())
            total, steps, done = total + r, steps + 1, term or trunc
        assert (total, steps, digest.hexdigest()) == (e["reward"], e["steps"], e["frames"]), e["seed"]
    del ray
