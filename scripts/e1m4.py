"""What the comparison scripts (chocolate-compare.py, dsda-compare.py) share:
Sightline's binary, Freedoom's eight vanilla demos set out in a directory
(each with a one-tic cut of it, to time a program's start-up and level load
alone), Sightline's timedemo of one, a CPU-timed run of any program, a lump
out of a WAD, the round-by-round tables; and for the older E1M4 tour
comparison (--tour) E1M4 and its DEMO1 set out and a timed tour."""

import json
import os
import re
import resource
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOOM_DIR = Path(os.environ.get("SIGHTLINE_DOOM_DIR", "/usr/share/games/doom"))
WAD = DOOM_DIR / "freedoom1.wad"
WADS = (DOOM_DIR / "freedoom1.wad", DOOM_DIR / "freedoom2.wad")
DEMO_LUMPS = ("DEMO1", "DEMO2", "DEMO3", "DEMO4")


def require(paths, package):
    """Exits naming the Debian packages to install when one of `paths` is missing."""
    for need in paths:
        if not Path(need).exists():
            sys.exit(f"missing {need}: apt-get install {package} freedoom")


def sightline_binary():
    """Builds the release binary and returns its path; or, when SIGHTLINE_BIN
    is set, returns that without building (for a tree someone is mid-edit in)."""
    if os.environ.get("SIGHTLINE_BIN"):
        binary = Path(os.environ["SIGHTLINE_BIN"])
        if not binary.is_file():
            sys.exit(f"SIGHTLINE_BIN={binary}: no such file")
        return binary
    build = subprocess.run(["cargo", "build", "--release", "--quiet", "-p", "sightline-game"], cwd=ROOT)
    if build.returncode != 0:
        sys.exit("cargo build --release failed (a source file mid-edit? try again in a minute, "
                 "or set SIGHTLINE_BIN to a built binary)")
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "sightline"


@dataclass
class Demo:
    """One of Freedoom's vanilla demos: its WAD and lump, the map its header
    names, its tics (4 bytes each between the 13-byte header and the 0x80
    end), and where it and its one-tic cut were written."""
    wad: Path
    lump: str
    map: str
    tics: int
    file: Path
    short: Path

    @property
    def name(self):
        return f"{self.wad.stem} {self.lump}"


@contextmanager
def demo_set(programs, package):
    """Checks that the IWADs and `programs` are there (else exits naming
    `package` to install), builds Sightline and copies its binary into a
    temporary directory (so that a rebuild by someone else mid-run changes
    nothing), and writes the eight demos and their one-tic cuts there.
    Yields the binary, the directory and the demos."""
    require(list(WADS) + list(programs), package)
    built = sightline_binary()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        binary = tmp / "sightline"
        shutil.copy2(built, binary)
        demos = []
        for wad in WADS:
            for lump in DEMO_LUMPS:
                file = tmp / f"{wad.stem}-{lump.lower()}.lmp"
                extract_lump(wad, lump, file)
                data = file.read_bytes()
                if len(data) < 14 or data[0] != 109 or data[-1] != 0x80:
                    sys.exit(f"{wad}:{lump}: not a Doom 1.9 demo ending in 0x80")
                # Doom II's header leaves the episode at 1; Doom's map names are ExMy.
                episode, level = data[2], data[3]
                name = f"MAP{level:02}" if wad.stem == "freedoom2" else f"E{episode}M{level}"
                short = tmp / f"{wad.stem}-{lump.lower()}-tic1.lmp"
                one_tic_demo(file, short)
                demos.append(Demo(wad, lump, name, (len(data) - 14) // 4, file, short))
        yield binary, tmp, demos


def timed_run(command, env=None, cwd=None):
    """Runs `command` to its end; returns its output (stdout and stderr) and the
    CPU seconds (user and system) it and its children took."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(command, env=env, cwd=cwd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out.stdout + out.stderr, cpu


SIGHTLINE_TIMED = re.compile(r"timed (\d+) gametics in \d+ realtics \([^)]*\); "
                             r"([\d.]+) ms CPU, ([\d.]+) ms wall per frame")


def sightline_timedemo(binary, demo, size, threads, short=False):
    """`sightline replay WAD:DEMOn --timedemo` (or, if `short`, of the demo's
    one-tic cut, `replay FILE.lmp --iwad WAD`): returns its gametics, its
    printed CPU and wall ms per frame, and the CPU seconds of the whole
    process (start-up and level load included)."""
    what = [str(demo.short), "--iwad", str(demo.wad)] if short else [f"{demo.wad}:{demo.lump}"]
    command = [str(binary), "replay", *what, "--timedemo", "--size", size, "--threads", str(threads)]
    text, cpu = timed_run(command)
    m = SIGHTLINE_TIMED.search(text)
    if not m:
        sys.exit(f"{' '.join(command)} printed no timing:\n{text}")
    return int(m.group(1)), float(m.group(2)), float(m.group(3)), cpu


def load_line(loads):
    return "Load average (1 min) at each round's start: " + ", ".join(f"{x:.2f}" for x in loads) + "."


@contextmanager
def prepared(port, package):
    """Checks that freedoom1.wad and the port's binary `port` are there (else
    exits naming `package` to install), builds Sightline, and sets out E1M4
    (imported) and DEMO1 (which plays it) in a temporary directory. Yields
    Sightline's binary, the directory, the map and the demo."""
    require((WAD, port), package)
    binary = sightline_binary()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        subprocess.run([str(binary), "import", str(WAD), "--map", "E1M4", "-o", str(tmp)],
                       check=True, capture_output=True)
        demo = tmp / "demo1.lmp"
        extract_lump(WAD, "DEMO1", demo)
        yield binary, tmp, tmp / "e1m4.ron", demo


def sightline_tour(binary, ron, size, threads, repeat=None):
    """`sightline bench tour` of `ron`: its JSON object."""
    command = [str(binary), "bench", "tour", str(ron), "--size", size, "--threads", str(threads), "--json"]
    if repeat is not None:
        command += ["--repeat", str(repeat)]
    out = subprocess.run(command, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def extract_lump(wad, name, out):
    """Writes lump `name` of the WAD at path `wad` to the path `out`."""
    data = wad.read_bytes()
    count, offset = struct.unpack_from("<ii", data, 4)
    for i in range(count):
        pos, size, raw = struct.unpack_from("<ii8s", data, offset + 16 * i)
        if raw.rstrip(b"\0").decode("ascii", "replace").upper() == name:
            out.write_bytes(data[pos:pos + size])
            return
    sys.exit(f"{wad}: no {name} lump")


def one_tic_demo(demo, out):
    """Writes the first tic of a one-player Doom 1.9 demo (13-byte header,
    4 bytes a tic, 0x80 at the end) to `out`."""
    data = demo.read_bytes()
    if len(data) < 17 or sum(data[9:13]) != 1:
        sys.exit(f"{demo}: not a one-player Doom 1.9 demo")
    out.write_bytes(data[:13 + 4] + b"\x80")


def rounds_table(keys, labels, rounds, frames, loads):
    """The comparison's table: per row its frames per run, the median of its
    rounds' figures, fps and every round; then the load at each round's
    start. Returns the lines and the medians."""
    med = {k: statistics.median(rounds[k]) for k in keys}
    lines = [
        "| what | frames per run | median ms/frame (of rounds) | fps | all rounds (ms) |",
        "|---|---|---|---|---|",
    ]
    for k in keys:
        lines.append(f"| {labels[k]} | {frames[k]} | {med[k]:.3f} | {1000 / med[k]:.0f} | "
                     + " ".join(f"{x:.3f}" for x in rounds[k]) + " |")
    lines.append("")
    lines.append(load_line(loads))
    return lines, med


def report(lines, out):
    """Prints the report, and writes it to `out` too when given."""
    text = "\n".join(lines)
    print(text)
    if out:
        out.write_text(text + "\n")
