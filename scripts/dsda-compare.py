#!/usr/bin/env python3
"""Sightline against dsda-doom's software renderer on Freedoom's E1M4, in one run.

dsda-doom: `dsda-doom -iwad freedoom1.wad -timedemo DEMO1 -nosound -nomusic`
with SDL_VIDEODRIVER=dummy, its config's `videomode "Software"` and
`screen_resolution` set to --size, playing freedoom1.wad's DEMO1 lump (E1M4)
extracted to a file. Its fps is game tics (one frame each) over wall-clock
time, so its ms/frame includes its game logic and the copy of each frame to
the SDL surface.

dsda-doom 0.25 sleeps 5 ms after every frame while its window lacks input
focus (d_main.c, "don't thrash cpu ... if the window doesnt have focus"), and
a window of SDL's dummy driver never has it: that run measures the sleep as
much as the renderer. So each round runs it twice: as is, and with a small
LD_PRELOAD library (written and compiled here with `cc`) that reports its
window focused, which is the figure to compare with.

Sightline: `sightline bench tour e1m4.ron --size WxH --threads N --json`, the
median of render_frame over a fixed tour (every thing's position, eight
angles each) of the imported map, in 32-bit colour with textures, sprites,
sky and distance light, and the frame's breakdown by part.

The programs are run alternately, ROUNDS times, and the medians of the rounds
are reported with the load average. Needs: apt-get install dsda-doom freedoom
and a C compiler.

Usage: scripts/dsda-compare.py [--size WxH] [--rounds N] [--out FILE]
"""

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

from e1m4 import WAD, one_tic_demo, prepared, report, rounds_table, sightline_tour

DSDA = "/usr/games/dsda-doom"

# SDL_GetWindowFlags with SDL_WINDOW_SHOWN (0x4) and SDL_WINDOW_INPUT_FOCUS
# (0x200) set: dsda-doom reads its focus from these flags.
FOCUS_SHIM = r"""
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
typedef struct SDL_Window SDL_Window;
uint32_t SDL_GetWindowFlags(SDL_Window *window) {
    static uint32_t (*real)(SDL_Window *);
    if (!real) real = (uint32_t (*)(SDL_Window *))dlsym(RTLD_NEXT, "SDL_GetWindowFlags");
    return real(window) | 0x4u | 0x200u;
}
"""


def dsda_setup(home, size, demo):
    """Writes dsda-doom's config (a first, one-tic run creates it) and the focus shim."""
    env = dict(os.environ, HOME=str(home), SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    short = home / "short.lmp"
    one_tic_demo(demo, short)
    subprocess.run([DSDA, "-iwad", str(WAD), "-timedemo", str(short), "-nosound", "-nomusic"],
                   env=env, capture_output=True, cwd=home, check=False)
    cfg = home / ".dsda-doom" / "dsda-doom.cfg"
    if not cfg.exists():
        sys.exit(f"dsda-doom wrote no config at {cfg}")
    text = cfg.read_text()
    text = re.sub(r'(?m)^screen_resolution\s+.*$', f'screen_resolution "{size}"', text)
    text = re.sub(r'(?m)^videomode\s+.*$', 'videomode "Software"', text)
    cfg.write_text(text)
    shim_c, shim = home / "focus.c", home / "focus.so"
    shim_c.write_text(FOCUS_SHIM)
    subprocess.run(["cc", "-shared", "-fPIC", "-O2", "-o", str(shim), str(shim_c), "-ldl"], check=True)
    return env, shim


def dsda_ms(env, home, demo, shim=None):
    env = dict(env, **({"LD_PRELOAD": str(shim)} if shim else {}))
    out = subprocess.run([DSDA, "-iwad", str(WAD), "-timedemo", str(demo), "-nosound", "-nomusic"],
                         env=env, capture_output=True, text=True, cwd=home)
    text = out.stdout + out.stderr
    m = re.search(r"Timed (\d+) gametics in (\d+) realtics = ([\d.]+) frames per second", text)
    if not m:
        sys.exit(f"dsda-doom printed no timing:\n{text}")
    return 1000.0 / float(m.group(3)), int(m.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="1920x1080")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()
    with prepared(DSDA, "dsda-doom") as (binary, tmp, ron, demo):
        env, shim = dsda_setup(tmp, args.size, demo)
        keys = ["dsda", "dsda focused", "t1", "t2"]
        rounds = {k: [] for k in keys}
        frames, parts, loads = {}, {}, []
        for r in range(args.rounds):
            loads.append(os.getloadavg()[0])
            for key, use_shim in (("dsda", None), ("dsda focused", shim)):
                ms, tics = dsda_ms(env, tmp, demo, use_shim)
                rounds[key].append(ms)
                frames[key] = tics
            for key, threads in (("t1", 1), ("t2", 2)):
                j = sightline_tour(binary, ron, args.size, threads, repeat=1)
                rounds[key].append(j["median_ms"])
                frames[key] = j["frames"]
                parts[key] = j["breakdown"]
            print(f"round {r + 1} (load {loads[-1]:.2f}): "
                  + ", ".join(f"{k} {v[-1]:.3f} ms" for k, v in rounds.items()), file=sys.stderr)
    labels = {
        "dsda": f"dsda-doom timedemo demo1 (E1M4), {args.size}, software, as is (sleeps 5 ms a frame unfocused)",
        "dsda focused": f"dsda-doom timedemo demo1 (E1M4), {args.size}, software, window reported focused",
        "t1": f"Sightline E1M4 tour, {args.size}, 1 thread",
        "t2": f"Sightline E1M4 tour, {args.size}, 2 threads",
    }
    lines, med = rounds_table(keys, labels, rounds, frames, loads)
    lines.append(f"dsda-doom / Sightline one thread: **{med['dsda focused'] / med['t1']:.2f}x** against the focused "
                 f"run, {med['dsda'] / med['t1']:.2f}x against the run as is (goal: at least 2x).")
    lines.append("")
    lines.append("Sightline's last round by part (ms per frame, summed over threads):")
    names = [f"{n}_ms" for n in ("setup", "walk", "walls", "spans", "masked", "copy")]
    lines.append("| threads | " + " | ".join(n.removesuffix("_ms") for n in names) + " |")
    lines.append("|---|" + "---|" * len(names))
    for k in ("t1", "t2"):
        lines.append(f"| {k[1:]} | " + " | ".join(f"{parts[k][n]:.3f}" for n in names) + " |")
    report(lines, args.out)


if __name__ == "__main__":
    main()
