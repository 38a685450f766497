#!/usr/bin/env python3
"""Sightline against Chocolate Doom on Freedoom's E1M4, in one run.

Chocolate Doom: `chocolate-doom -iwad freedoom1.wad -timedemo demo1 -noblit
-nosound -nomusic` with SDL_VIDEODRIVER=dummy (demo1 plays E1M4; -noblit
skips copying the frame to the screen). Its fps is frames (game tics, one
frame each) over wall-clock time, so its ms/frame includes the game logic.

Sightline: `sightline bench tour e1m4.ron --size WxH --threads N --json`, the
median of render_frame over a fixed tour (every thing's position, eight
angles each) of the imported map, in 32-bit colour with textures, sprites,
sky and distance light.

The two are run alternately, ROUNDS times, and the medians of the rounds are
reported. Needs: apt-get install chocolate-doom freedoom.

Usage: scripts/chocolate-compare.py [--rounds N] [--out FILE]
"""

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WAD = Path(os.environ.get("SIGHTLINE_DOOM_DIR", "/usr/share/games/doom")) / "freedoom1.wad"
CHOCOLATE = "/usr/games/chocolate-doom"


def sightline_binary():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "sightline"


def chocolate_ms():
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    with tempfile.TemporaryDirectory() as home:
        env["HOME"] = home  # keep its config files out of the user's
        out = subprocess.run(
            [CHOCOLATE, "-iwad", str(WAD), "-timedemo", "demo1", "-noblit", "-nosound", "-nomusic"],
            env=env, capture_output=True, text=True, cwd=home,
        )
    text = out.stdout + out.stderr
    m = re.search(r"timed (\d+) gametics in (\d+) realtics \(([\d.]+) fps\)", text)
    if not m:
        sys.exit(f"chocolate-doom printed no timing:\n{text}")
    return 1000.0 / float(m.group(3)), int(m.group(1))


def sightline_tour(binary, ron, size, threads):
    out = subprocess.run(
        [str(binary), "bench", "tour", str(ron), "--size", size, "--threads", str(threads), "--json"],
        capture_output=True, text=True, check=True,
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()
    for need in (WAD, Path(CHOCOLATE)):
        if not need.exists():
            sys.exit(f"missing {need}: apt-get install chocolate-doom freedoom")
    binary = sightline_binary()
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([str(binary), "import", str(WAD), "--map", "E1M4", "-o", tmp],
                       check=True, capture_output=True)
        ron = Path(tmp) / "e1m4.ron"
        rounds = {"chocolate": [], "320x200 t1": [], "1920x1080 t1": [], "1920x1080 t2": []}
        frames = {}
        for r in range(args.rounds):
            ms, tics = chocolate_ms()
            rounds["chocolate"].append(ms)
            frames["chocolate"] = tics
            for key, size, threads in (("320x200 t1", "320x200", 1), ("1920x1080 t1", "1920x1080", 1),
                                       ("1920x1080 t2", "1920x1080", 2)):
                j = sightline_tour(binary, ron, size, threads)
                rounds[key].append(j["median_ms"])
                frames[key] = j["frames"]
            print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]:.3f} ms" for k, v in rounds.items()), file=sys.stderr)
    med = {k: statistics.median(v) for k, v in rounds.items()}
    lines = [
        "| what | frames per run | median ms/frame (of rounds) | fps | all rounds (ms) |",
        "|---|---|---|---|---|",
    ]
    labels = {
        "chocolate": "Chocolate Doom timedemo demo1 (E1M4), 320x200, 8-bit, -noblit",
        "320x200 t1": "Sightline E1M4 tour, 320x200, 1 thread",
        "1920x1080 t1": "Sightline E1M4 tour, 1920x1080, 1 thread",
        "1920x1080 t2": "Sightline E1M4 tour, 1920x1080, 2 threads",
    }
    for k, v in rounds.items():
        lines.append(f"| {labels[k]} | {frames[k]} | {med[k]:.3f} | {1000 / med[k]:.0f} | "
                     + " ".join(f"{x:.3f}" for x in v) + " |")
    lines.append("")
    lines.append(f"Chocolate Doom / Sightline at 320x200, one thread: **{med['chocolate'] / med['320x200 t1']:.2f}x** "
                 f"(goal: at least 3x).")
    lines.append(f"Sightline 1920x1080: 1 thread {1000 / med['1920x1080 t1']:.0f} fps, 2 threads "
                 f"{1000 / med['1920x1080 t2']:.0f} fps (goal: at least 150), speed-up "
                 f"{med['1920x1080 t1'] / med['1920x1080 t2']:.2f}x.")
    report = "\n".join(lines)
    print(report)
    if args.out:
        args.out.write_text(report + "\n")


if __name__ == "__main__":
    main()
