#!/usr/bin/env python3
"""The audio buffer, as ViZDoom's examples/python/audio_buffer.py uses it:
an episode of basic played with random actions, every state's audio
buffer joined into one WAV file, and the tics where the pistol was heard
listed with their levels.

    python audio_buffer.py [OUT.wav] [--vizdoom]

With ``--vizdoom`` the same script runs on the ``vizdoom`` package (the
buffer is silent there without a sound device).
"""

import os
import sys
import wave
from random import Random

import numpy as np

if "--vizdoom" in sys.argv:
    import vizdoom as vzd
else:
    import sightline.vizdoom as vzd

FRAME_SKIP = 4

if __name__ == "__main__":
    out = next((a for a in sys.argv[1:] if not a.startswith("--")), "basic_episode.wav")
    game = vzd.DoomGame()
    game.load_config(os.path.join(vzd.scenarios_path, "basic.cfg"))
    game.set_window_visible(False)
    game.set_audio_buffer_enabled(True)
    game.set_audio_sampling_rate(vzd.SamplingRate.SR_22050)
    # A state after make_action(a, FRAME_SKIP) holds the sound of those tics.
    game.set_audio_buffer_size(FRAME_SKIP)
    game.set_seed(7)
    game.init()
    rate = game.get_audio_sampling_rate()

    rng = Random(7)
    actions = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    chunks = []
    shots = []
    first_tic = None
    while not game.is_episode_finished():
        state = game.get_state()
        if first_tic is None:
            # The first state's buffer holds the FRAME_SKIP tics up to its own.
            first_tic = state.tic - FRAME_SKIP + 1
        chunks.append(state.audio_buffer)
        action = rng.choice(actions)
        if action[2]:
            shots.append(state.tic + 1)
        game.make_action(action, FRAME_SKIP)
    sound = np.concatenate(chunks)
    with wave.open(out, "wb") as wav:
        wav.setnchannels(2)
        wav.setsampwidth(2)
        wav.setframerate(rate)
        wav.writeframes(sound.astype("<i2").tobytes())
    print(f"{out}: {len(sound)} frames at {rate} Hz ({len(sound) / rate:.2f} s), total reward {game.get_total_reward():.0f}")
    print(f"ATTACK held from tics {shots} (for {FRAME_SKIP} tics each)")
    # Levels by game tic.
    per_tic = rate // 35
    peaks = np.abs(sound.astype(np.int32)).reshape(-1, per_tic, 2).max(axis=(1, 2))
    loud = [i for i, p in enumerate(peaks) if p > 0]
    print(f"tics heard: {len(loud)} of {len(peaks)}; peak {peaks.max()} (full scale 32767)")
    runs = []
    for i in loud:
        if runs and i == runs[-1][1] + 1:
            runs[-1][1] = i
        else:
            runs.append([i, i])
    for a, b in runs:
        print(f"  tics {first_tic + a}-{first_tic + b}: peak {peaks[a:b + 1].max()}")
