#!/usr/bin/env python3
"""Generate maps/music/outpost.mid: the default level's music, composed by
rule rather than played, so that it is ours like the rest of the level's
art.

    python3 maps/generators/outpost_music.py

A loop of 32 bars at 132 beats a minute (about 58 s) in A minor over the
progression Am F G Em: a synth bass in driving eighths, a string pad holding
each chord, drums (kick, snare, closed and open hats), and in the second half
a lead (a square wave) playing a motif that climbs and falls over the
chords. Standard MIDI File format 0, 96 ticks a quarter note, General MIDI
instruments; the game plays it through the SoundFont it finds."""

import os
import struct

TPQ = 96  # ticks per quarter note
BAR = 4 * TPQ
TEMPO_BPM = 132

# Chords of the progression, as MIDI notes (root, third, fifth), one a bar.
CHORDS = [(57, 60, 64), (53, 57, 60), (55, 59, 62), (52, 55, 59)]  # Am F G Em
# The lead's motif over each chord: (beat offset in eighths, semitones above the chord's root + 12, eighths long).
MOTIF = [
    [(0, 0, 2), (2, 3, 2), (4, 7, 3), (7, 5, 1)],
    [(0, 7, 2), (2, 4, 2), (4, 2, 2), (6, 0, 2)],
    [(0, 2, 3), (3, 4, 1), (4, 7, 2), (6, 9, 2)],
    [(0, 7, 4), (4, 5, 2), (6, 3, 2)],
]

BASS, PAD, LEAD, DRUMS = 0, 1, 2, 9
PROGRAMS = {BASS: 38, PAD: 48, LEAD: 80}  # Synth Bass 1, String Ensemble 1, Square Lead
KICK, SNARE, HAT, OPEN_HAT, CRASH = 36, 38, 42, 46, 49


def compose():
    """Every note as (start tick, channel, note, velocity, length in ticks)."""
    notes = []
    eighth = TPQ // 2
    for bar in range(32):
        t0 = bar * BAR
        root, third, fifth = CHORDS[bar % 4]
        second_half = bar >= 16
        # Bass: eighths on the root an octave down, the last two of the bar up an octave.
        for k in range(8):
            note = root - 24 + (12 if k in (6, 7) and bar % 2 else 0)
            notes.append((t0 + k * eighth, BASS, note, 100 if k % 2 == 0 else 80, eighth - 8))
        # Pad: the chord held for the bar.
        for n in (root - 12, third - 12, fifth - 12, root):
            notes.append((t0, PAD, n, 55, BAR - 4))
        # Drums: kick on 1 and 3 (and the and of 3 in the second half), snare on 2 and 4, hats on eighths.
        for beat in (0, 2):
            notes.append((t0 + beat * TPQ, DRUMS, KICK, 110, eighth))
        if second_half:
            notes.append((t0 + 2 * TPQ + eighth, DRUMS, KICK, 90, eighth))
        for beat in (1, 3):
            notes.append((t0 + beat * TPQ, DRUMS, SNARE, 100, eighth))
        for k in range(8):
            hat = OPEN_HAT if k == 7 and bar % 4 == 3 else HAT
            notes.append((t0 + k * eighth, DRUMS, hat, 70 if k % 2 else 85, eighth // 2))
        if bar % 8 == 0:
            notes.append((t0, DRUMS, CRASH, 100, TPQ))
        # Lead: the motif over the chord, from the second half on.
        if second_half:
            for at, step, length in MOTIF[bar % 4]:
                notes.append((t0 + at * eighth, LEAD, root + 12 + step, 90, length * eighth - 10))
    return notes


def vlq(n):
    out = [n & 0x7F]
    n >>= 7
    while n:
        out.append((n & 0x7F) | 0x80)
        n >>= 7
    return bytes(reversed(out))


def midi(notes):
    events = []  # (tick, order, bytes): note-offs before note-ons at the same tick
    events.append((0, 0, b"\xff\x51\x03" + struct.pack(">I", 60_000_000 // TEMPO_BPM)[1:]))
    events.append((0, 0, b"\xff\x58\x04\x04\x02\x18\x08"))
    for ch, program in PROGRAMS.items():
        events.append((0, 1, bytes([0xC0 | ch, program])))
        events.append((0, 1, bytes([0xB0 | ch, 7, 100])))
    for start, ch, note, velocity, length in notes:
        events.append((start, 3, bytes([0x90 | ch, note, velocity])))
        events.append((start + length, 2, bytes([0x80 | ch, note, 0])))
    events.sort(key=lambda e: (e[0], e[1]))
    track = bytearray()
    now = 0
    for tick, _, data in events:
        track += vlq(tick - now) + data
        now = tick
    # The loop is 32 bars long: end exactly there.
    track += vlq(32 * BAR - now) + b"\xff\x2f\x00"
    header = b"MThd" + struct.pack(">IHHH", 6, 0, 1, TPQ)
    return header + b"MTrk" + struct.pack(">I", len(track)) + bytes(track)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "music", "outpost.mid")
    with open(out, "wb") as f:
        f.write(midi(compose()))
    print(f"wrote {os.path.normpath(out)}")
