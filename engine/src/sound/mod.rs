//! Sound: what the game is heard as. The simulation only emits events
//! (`play::events`: a sound's name and where it comes from); this module
//! turns them into stereo samples, and never touches a device:
//!
//! ```text
//! Playthrough ──Sounds::cues (each tick: the events' voices and positions,
//!    │           the listener, the origins still sounding, music changes)──▶ Cues
//!    │                                                                     │
//!    │                              Audio::apply (start, follow, stop) ◀───┘
//!    ▼                              Audio::render ──▶ stereo f32 at 44,100 Hz
//! bank (the map's voices: a WAD's DMX lumps, WAVs beside a RON map, our own)
//! ```
//!
//! [`Sounds`] lives with the game (it reads the playthrough and owns the
//! map's [`bank::SoundBank`]); [`Audio`] owns the [`mix::Mixer`] and the
//! [`music::Music`] and can live on another thread (the window's audio
//! thread) or run in step with the ticks (`sightline replay --audio`, which
//! renders exactly [`FRAMES_PER_TICK`] frames a tick, so the same demo gives
//! the same bytes). Modules: [`dmx`] and [`mus`] (Doom's lump formats),
//! [`procedural`] (our own voices), [`bank`], [`mix`] (Doom's positional
//! rules and channels), [`music`] (SoundFont synthesis), [`wav`] (offline
//! output).

pub mod bank;
pub mod dmx;
pub mod mix;
pub mod mus;
pub mod music;
pub mod procedural;
pub mod wav;

use std::sync::Arc;

use glam::DVec2;

use crate::autopilot::observe::Observe;
use crate::campaign::MapRef;
use crate::play::events::{Event, Origin};
use crate::play::playthrough::{Phase, Playthrough};
use bank::SoundBank;
use mix::{Key, Listener, Mixer};
use music::Music;

/// The output rate: 44,100 Hz is exactly 1,260 frames a tick.
pub const OUTPUT_RATE: u32 = 44_100;
pub const FRAMES_PER_TICK: usize = (OUTPUT_RATE / crate::play::TICRATE) as usize;
/// How long an actor's sound is followed after it starts (the longest of
/// Doom's sounds is under 3 s).
const FOLLOW_TICKS: u64 = 4 * crate::play::TICRATE as u64;

/// A mono sound: samples in -1..1 at `rate` Hz.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    pub rate: u32,
    pub data: Vec<f32>,
}

/// A sound to start.
#[derive(Clone, Debug)]
pub struct Start {
    pub voice: bank::Voice,
    pub key: Key,
    /// Where it comes from; `None` for the listener's own.
    pub pos: Option<DVec2>,
}

/// What the audio side needs of one tick.
#[derive(Clone, Debug, Default)]
pub struct Cues {
    pub listener: Listener,
    pub starts: Vec<Start>,
    /// Where the origins of sounds still playing are now.
    pub moved: Vec<(Key, DVec2)>,
    /// A new map began: stop every sound.
    pub stop_all: bool,
    /// The music changed: play this MIDI file (`Some(None)`: silence).
    pub music: Option<Option<Arc<Vec<u8>>>>,
}

/// What a tic made heard, apart from the game that made it.
pub struct Heard<'a> {
    /// The tic's events (sounds among them).
    pub events: &'a [Event],
    pub listener: Listener,
    /// The tic's number, for how long a sound follows its thing.
    pub tick: u64,
    /// Where thing `n` is now (None: it is gone).
    pub at: &'a dyn Fn(u32) -> Option<DVec2>,
}

/// The game's side: the map's voices, which origins are sounding, which
/// music plays.
pub struct Sounds {
    bank: SoundBank,
    map: Option<MapRef>,
    /// Actors whose sounds may still be playing, and when they started one.
    sounding: Vec<(u32, u64)>,
    /// The music chosen last (its lump or file name).
    song: Option<String>,
    /// Points get keys of their own.
    points: u64,
    /// Warnings not yet shown (missing or bad sounds and music), one line each.
    pub warnings: Vec<String>,
}

impl Default for Sounds {
    fn default() -> Sounds {
        Sounds::new()
    }
}

impl Sounds {
    pub fn new() -> Sounds {
        Sounds {
            bank: SoundBank::procedural(),
            map: None,
            sounding: Vec::new(),
            song: None,
            points: 0,
            warnings: Vec::new(),
        }
    }

    /// Sounds from `bank` alone, for games that stay on one map
    /// ([`Sounds::effects`]).
    pub fn with_bank(bank: SoundBank) -> Sounds {
        Sounds { bank, ..Sounds::new() }
    }

    /// The voice of sound `name` from the map's bank (the menu's sounds:
    /// a WAD's own, else ours).
    pub fn voice(&mut self, name: &str) -> Option<bank::Voice> {
        let voice = self.bank.get(name).cloned();
        self.warnings.append(&mut self.bank.warnings);
        voice
    }

    /// The cues that play the music lump `lump` of `map`'s WADs (the
    /// title's music), every sound stopped; the next map's cues change it.
    pub fn music(&mut self, map: &MapRef, lump: &str) -> Cues {
        self.enter(map);
        let midi = self.bank.wad_music(lump);
        let music = midi.map(Arc::new).map_err(|e| self.warnings.push(format!("music {lump}: {e}; no music"))).ok();
        self.song = Some(lump.to_string());
        self.sounding.clear();
        Cues { stop_all: true, music: Some(music), ..Cues::default() }
    }

    /// Sounds from `map` on: another WAD or map brings its own voices
    /// (warned about once); whether it is another map.
    fn enter(&mut self, map: &MapRef) -> bool {
        if self.map.as_ref() == Some(map) {
            return false;
        }
        let same_source = match (&self.map, map) {
            (Some(MapRef::Wad { wads: a, .. }), MapRef::Wad { wads: b, .. }) => a == b,
            _ => false,
        };
        if !same_source {
            self.bank = SoundBank::for_map(map);
            self.warnings.append(&mut self.bank.warnings);
        }
        self.map = Some(map.clone());
        true
    }

    /// The cues of the tick `play` just ran.
    pub fn cues(&mut self, play: &Playthrough) -> Cues {
        let mut cues = self.map_cues(play);
        self.effects_into(&play.game, &mut cues);
        cues
    }

    /// The cues of a tic heard elsewhere and shown on `play`'s level (a
    /// Doom demo in the window): `play`'s map and music, `heard`'s sounds.
    pub fn cues_heard(&mut self, play: &Playthrough, heard: &Heard) -> Cues {
        let mut cues = self.map_cues(play);
        self.heard_into(heard, play.game.level(), &mut cues);
        cues
    }

    /// A new map's stop and voices, and a change of music.
    fn map_cues(&mut self, play: &Playthrough) -> Cues {
        let mut cues = Cues::default();
        if self.enter(&play.map) {
            self.sounding.clear();
            cues.stop_all = true;
        }
        let song = match &play.map {
            // A RON map's own music (kept through its intermission).
            MapRef::File(path) => play
                .game
                .level()
                .map
                .music
                .as_ref()
                .map(|m| path.parent().unwrap_or(std::path::Path::new(".")).join(m).display().to_string()),
            MapRef::Wad { .. } => song_for(&play.map, &play.phase),
        };
        if song != self.song {
            let file = matches!(play.map, MapRef::File(_));
            cues.music = Some(song.as_ref().and_then(|name| {
                let midi = if file {
                    std::fs::read(name).map_err(|e| e.to_string()).and_then(|bytes| bank::midi_of(&bytes))
                } else {
                    self.bank.wad_music(name)
                };
                midi.map(Arc::new).map_err(|e| self.warnings.push(format!("music {name}: {e}; no music"))).ok()
            }));
            self.song = song;
        }
        cues
    }

    /// The sound effects of the tic `game` just ran, on a map whose voices
    /// this already holds ([`Sounds::with_bank`]): no map change, no music
    /// (a scenario's audio buffer).
    pub fn effects(&mut self, game: &crate::sim::game::SimGame) -> Cues {
        let mut cues = Cues::default();
        self.effects_into(game, &mut cues);
        cues
    }

    fn effects_into(&mut self, game: &crate::sim::game::SimGame, cues: &mut Cues) {
        let player = game.player();
        let seen = Observe::seen(game);
        let at = |a: u32| seen.get(a as usize).filter(|actor| !actor.removed).map(|actor| actor.pos);
        let heard = Heard {
            events: game.events(),
            listener: Listener { pos: player.pos, angle: player.angle },
            tick: game.ticks(),
            at: &at,
        };
        self.heard_into(&heard, game.level(), cues);
    }

    fn heard_into(&mut self, heard: &Heard, level: &crate::level::Level, cues: &mut Cues) {
        cues.listener = heard.listener;
        let tick = heard.tick;
        for event in heard.events {
            let Event::Sound { sound, origin } = event else { continue };
            let Some(voice) = self.bank.get(sound).cloned() else {
                self.warnings.append(&mut self.bank.warnings);
                continue;
            };
            let (key, pos) = match *origin {
                Origin::Player => (Key::Listener, None),
                Origin::Sector(s) => (Key::Sector(s), level.sector_boxes.get(s).map(|b| (b.min + b.max) / 2.0)),
                Origin::Actor { index, pos } => {
                    self.sounding.retain(|&(a, _)| a != index);
                    self.sounding.push((index, tick));
                    (Key::Actor(index), Some(pos))
                }
                Origin::At(pos) => {
                    self.points += 1;
                    (Key::Point(self.points), Some(pos))
                }
            };
            cues.starts.push(Start { voice, key, pos });
        }
        self.sounding.retain(|&(_, since)| tick.saturating_sub(since) <= FOLLOW_TICKS && since <= tick);
        for &(a, _) in &self.sounding {
            if let Some(pos) = (heard.at)(a) {
                cues.moved.push((Key::Actor(a), pos));
            }
        }
    }
}

/// The music lump of a WAD map, or of its intermission: Doom's `D_E1M1`
/// for episode maps, Doom II's table for `MAPxx`, `D_INTER` and `D_DM2INT`
/// between levels. Nothing for a RON map.
pub fn song_for(map: &MapRef, phase: &Phase) -> Option<String> {
    const DOOM2: [&str; 32] = [
        "RUNNIN", "STALKS", "COUNTD", "BETWEE", "DOOM", "THE_DA", "SHAWN", "DDTBLU", "IN_CIT", "DEAD", "STLKS2",
        "THEDA2", "DOOM2", "DDTBL2", "RUNNI2", "DEAD2", "STLKS3", "ROMERO", "SHAWN2", "MESSAG", "COUNT2", "DDTBL3",
        "AMPIE", "THEDA3", "ADRIAN", "MESSG2", "ROMER2", "TENSE", "SHAWN3", "OPENIN", "EVIL", "ULTIMA",
    ];
    let MapRef::Wad { map: Some(name), .. } = map else { return None };
    let name = name.to_ascii_uppercase();
    let doom2 = name.starts_with("MAP");
    if *phase != Phase::Playing {
        return Some(if doom2 { "D_DM2INT" } else { "D_INTER" }.into());
    }
    if doom2 {
        let n: usize = name[3..].parse().ok()?;
        return DOOM2.get(n.checked_sub(1)?).map(|s| format!("D_{s}"));
    }
    Some(format!("D_{name}"))
}

/// The audio side: the mixer and the music.
pub struct Audio {
    pub mixer: Mixer,
    pub music: Option<Music>,
    listener: Listener,
}

impl Audio {
    /// Effects on `channels` channels, and music when `music` is given.
    pub fn new(channels: usize, music: Option<Music>) -> Audio {
        Audio { mixer: Mixer::new(OUTPUT_RATE, channels), music, listener: Listener::default() }
    }

    /// Effects alone on `channels` channels at `rate` Hz (a whole number
    /// of frames a tick: 11,025, 22,050 and 44,100 are 315, 630 and 1,260).
    pub fn effects_at(rate: u32, channels: usize) -> Audio {
        Audio { mixer: Mixer::new(rate, channels), music: None, listener: Listener::default() }
    }

    /// Frames a tick at the mixer's rate ([`FRAMES_PER_TICK`] at the
    /// output rate).
    pub fn frames_per_tick(&self) -> usize {
        (self.mixer.rate() / crate::play::TICRATE) as usize
    }

    /// Acts on a tick's cues: music changes, stops, the sounds' new
    /// positions, the new sounds. A song that does not parse is `Err` (and
    /// silence); everything else applies regardless.
    pub fn apply(&mut self, cues: &Cues) -> Result<(), String> {
        let mut result = Ok(());
        if cues.stop_all {
            self.mixer.stop_all();
        }
        if let (Some(change), Some(music)) = (&cues.music, &mut self.music) {
            match change {
                Some(midi) => result = music.play(midi),
                None => music.stop(),
            }
        }
        self.listener = cues.listener;
        self.mixer.update(&self.listener, &cues.moved);
        for s in &cues.starts {
            self.mixer.start(s.voice.sample.clone(), s.key, s.pos, s.voice.priority, &self.listener);
        }
        result
    }

    /// One tick offline, in step with the game: `cues` applied, then exactly
    /// [`Audio::frames_per_tick`] frames appended to `out` (what makes the
    /// same demo sound the same). `Err` as [`Audio::apply`]'s.
    pub fn render_tick(&mut self, cues: &Cues, out: &mut Vec<f32>) -> Result<(), String> {
        let result = self.apply(cues);
        let at = out.len();
        out.resize(at + 2 * self.frames_per_tick(), 0.0);
        self.render(&mut out[at..]);
        result
    }

    /// The next `out.len() / 2` frames (interleaved stereo), clipped to -1..1.
    pub fn render(&mut self, out: &mut [f32]) {
        out.fill(0.0);
        if let Some(music) = &mut self.music {
            music.mix(out);
        }
        self.mixer.mix(out);
        for v in out {
            *v = v.clamp(-1.0, 1.0);
        }
    }
}
