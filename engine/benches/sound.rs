//! What sound costs: one second of audio (44,100 stereo frames, rendered a
//! tick's 1,260 frames at a time, as the window's audio thread and `replay
//! --audio` do) with 16 channels busy, with music playing (freedoom2's
//! D_RUNNIN through the SoundFont), and with both. The 16 sounds are
//! Freedoom2's commonest (shots, doors, monsters) at positions around the
//! listener, restarted as they end so all 16 channels stay busy; the
//! listener turns a little every tick so every channel's gains are worked
//! out again. Medians over [`ROUNDS`] rounds, each timed on its own, and the
//! share of one core they take (target: under 2% with 16 channels and music).
//! A custom loop, as the world bench's: it prints one table.
//!
//! Run: `cargo bench -p sightline-engine --bench sound`. Needs Freedoom's
//! WADs and a General MIDI SoundFont (Debian: freedoom, timgm6mb-soundfont).

mod common;

use std::sync::Arc;
use std::time::Instant;

use common::{doom_dir, median, Wanted};
use glam::DVec2;
use sightline::sound::bank::{midi_of, SoundBank};
use sightline::sound::mix::{Key, Listener, Mixer};
use sightline::sound::music::{find_soundfont, load_soundfont, Music};
use sightline::sound::{FRAMES_PER_TICK, OUTPUT_RATE};
use sightline::wad::Wad;

const ROUNDS: usize = 21;
const SOUNDS: [&str; 16] = [
    "pistol", "shotgn", "doropn", "dorcls", "pstart", "posit1", "bgsit1", "sgtsit", "popain", "podth1", "bgdth1",
    "firsht", "firxpl", "barexp", "itemup", "telept",
];

fn main() {
    let wanted = Wanted::from_args();
    let rounds = if wanted.quick { 3 } else { ROUNDS };
    let wad = Arc::new(Wad::open(&doom_dir().join("freedoom2.wad")).unwrap_or_else(|e| panic!("{e}")));
    let mut bank = SoundBank::of_wad(wad.clone());
    let voices: Vec<_> = SOUNDS.iter().map(|s| bank.get(s).cloned().unwrap_or_else(|| panic!("no {s}"))).collect();
    let font = find_soundfont(None).expect("a General MIDI SoundFont (apt-get install timgm6mb-soundfont)");
    let font = load_soundfont(&font).unwrap_or_else(|e| panic!("{e}"));
    let song = midi_of(wad.bytes(wad.find("D_RUNNIN").expect("D_RUNNIN"))).unwrap_or_else(|e| panic!("{e}"));

    println!("| one second of audio | median ms | share of one core |");
    println!("|---|---|---|");
    for (label, effects, music) in
        [("16 channels busy", true, false), ("music", false, true), ("16 channels busy and music", true, true)]
    {
        let mut times = Vec::new();
        for _ in 0..rounds {
            let mut mixer = Mixer::new(OUTPUT_RATE, 16);
            let mut player = music.then(|| {
                let mut m = Music::new(&font, OUTPUT_RATE).unwrap();
                m.play(&song).unwrap();
                m
            });
            let mut out = vec![0.0f32; 2 * FRAMES_PER_TICK];
            let ticks = OUTPUT_RATE as usize / FRAMES_PER_TICK;
            let start = Instant::now();
            for tick in 0..ticks {
                let listener = Listener { pos: DVec2::ZERO, angle: tick as f64 * 3.0 };
                if effects {
                    // Keep every channel busy: restart what has ended.
                    let playing = mixer.playing();
                    for (k, voice) in voices.iter().enumerate() {
                        if !playing.contains(&Some(Key::Actor(k as u32))) {
                            let angle = k as f64 * 22.5_f64.to_radians();
                            let pos = DVec2::new(angle.cos(), angle.sin()) * (100.0 + 50.0 * k as f64);
                            mixer.start(voice.sample.clone(), Key::Actor(k as u32), Some(pos), 0, &listener);
                        }
                    }
                    mixer.update(&listener, &[]);
                    assert_eq!(mixer.busy(), 16, "not every channel is busy");
                }
                out.fill(0.0);
                if let Some(m) = &mut player {
                    m.mix(&mut out);
                }
                mixer.mix(&mut out);
                for v in &mut out {
                    *v = v.clamp(-1.0, 1.0);
                }
                std::hint::black_box(&out);
            }
            times.push(start.elapsed().as_secs_f64() * 1e3);
        }
        let ms = median(&mut times);
        println!("| {label} | {ms:.2} | {:.2}% |", ms / 10.0);
    }
}
