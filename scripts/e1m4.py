"""What the E1M4 comparison scripts (chocolate-compare.py, dsda-compare.py)
share: Sightline's binary, Freedoom's E1M4 and its DEMO1 set out in a
directory, a timed tour, a lump out of a WAD, and a one-tic cut of a demo
(to time a port's start-up and level load alone)."""

import json
import os
import statistics
import struct
import subprocess
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WAD = Path(os.environ.get("SIGHTLINE_DOOM_DIR", "/usr/share/games/doom")) / "freedoom1.wad"


def sightline_binary():
    """Builds the release binary and returns its path."""
    subprocess.run(["cargo", "build", "--release", "--quiet", "-p", "sightline-game"], cwd=ROOT, check=True)
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "sightline"


@contextmanager
def prepared(port, package):
    """Checks that freedoom1.wad and the port's binary `port` are there (else
    exits naming `package` to install), builds Sightline, and sets out E1M4
    (imported) and DEMO1 (which plays it) in a temporary directory. Yields
    Sightline's binary, the directory, the map and the demo."""
    for need in (WAD, Path(port)):
        if not need.exists():
            sys.exit(f"missing {need}: apt-get install {package} freedoom")
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
    lines.append("Load average (1 min) at each round's start: " + ", ".join(f"{x:.2f}" for x in loads) + ".")
    return lines, med


def report(lines, out):
    """Prints the report, and writes it to `out` too when given."""
    text = "\n".join(lines)
    print(text)
    if out:
        out.write_text(text + "\n")
