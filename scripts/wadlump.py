"""Small helpers the comparison scripts share: a lump out of a WAD, and a
one-tic cut of a demo (to time a port's start-up and level load alone)."""

import struct
import sys


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
