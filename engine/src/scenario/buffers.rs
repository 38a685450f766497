//! What ViZDoom's state carries from the tics between two states, beside
//! the screen: the audio buffer (the sound effects of the last tics, mixed
//! as the player hears them) and the notifications buffer (the messages the
//! player was shown in the last tics). [`TicBuffers`] is fed every tic the
//! episode plays (`run::Episode`) and read whenever a state is asked for.
//!
//! ```text
//! SimGame::events (each tic) ──Sounds::effects──▶ Cues ──Audio (mixer at the buffer's rate)──▶ int16 ring
//!                            └─Event::Message, scripts' Print/Log──▶ (tic, line) ring
//! ```
//!
//! An episode whose `.cfg` asks for neither has no `TicBuffers` and pays
//! one branch a tic. Both are deterministic: they read only the game's
//! events, and the mixer's state is the episode's own.

use std::collections::VecDeque;
use std::sync::Arc;

use super::ScenarioConfig;
use crate::campaign::Opened;
use crate::play::events::Event;
use crate::sim::game::SimGame;
use crate::sound::bank::SoundBank;
use crate::sound::mix::DEFAULT_CHANNELS;
use crate::sound::{Audio, Sounds};

/// The longest audio buffer, in tics (a minute of sound: at 44,100 Hz,
/// 2,646,000 frames, 10.6 MB of int16 stereo). ViZDoom sets no limit; past
/// this a state's copy of the buffer would cost more than the tic.
pub const MAX_AUDIO_TICS: u32 = 2100;

/// The buffers a scenario's `.cfg` turned on, for one episode.
pub struct TicBuffers {
    audio: Option<AudioBuffer>,
    notifications: Option<Notifications>,
}

impl TicBuffers {
    /// The buffers `config` asks for on `opened`'s map, for an episode of
    /// `game` from now on, or `None` when it asks for neither.
    pub fn new(config: &ScenarioConfig, opened: &Opened, game: &SimGame) -> Option<TicBuffers> {
        let o = &config.outputs;
        if !o.audio_buffer && !o.notifications_buffer {
            return None;
        }
        let audio = o.audio_buffer.then(|| {
            let bank = match &opened.wad {
                Some(art) => SoundBank::of_art(Arc::clone(art)),
                None => SoundBank::for_map(&opened.map),
            };
            AudioBuffer::new(bank, o.audio_sampling_rate.hertz(), o.audio_buffer_size)
        });
        let notifications = o.notifications_buffer.then(|| Notifications::new(o.notifications_buffer_size, game));
        Some(TicBuffers { audio, notifications })
    }

    /// The tic `game` just ran.
    pub fn tic(&mut self, game: &SimGame) {
        if let Some(a) = &mut self.audio {
            a.tic(game);
        }
        if let Some(n) = &mut self.notifications {
            n.tic(game);
        }
    }

    pub fn audio(&self) -> Option<&AudioBuffer> {
        self.audio.as_ref()
    }

    pub fn notifications(&self) -> Option<&Notifications> {
        self.notifications.as_ref()
    }
}

/// The sound of the last tics, interleaved stereo int16 at one rate.
pub struct AudioBuffer {
    sounds: Sounds,
    audio: Audio,
    /// The last `tics` tics' frames, oldest first (silence before the
    /// episode's first tics, so the buffer always has its full length).
    samples: VecDeque<i16>,
    /// One tic's mix, reused.
    scratch: Vec<f32>,
}

impl AudioBuffer {
    /// `tics` tics at `rate` Hz (one of ViZDoom's three: a whole number of
    /// frames a tic), voices from `bank`, Doom's eight channels.
    pub fn new(bank: SoundBank, rate: u32, tics: u32) -> AudioBuffer {
        let mut audio = Audio::effects_at(rate, DEFAULT_CHANNELS);
        // Doom's default effects volume, 8 of 15 (Chocolate Doom's
        // `sfx_volume`), about half: at full volume Freedoom's pistol alone
        // reaches full scale, and two sounds at once would clip.
        audio.mixer.volume = 0.5;
        let len = 2 * audio.frames_per_tick() * tics.min(MAX_AUDIO_TICS) as usize;
        AudioBuffer {
            sounds: Sounds::with_bank(bank),
            audio,
            samples: std::iter::repeat_n(0, len).collect(),
            scratch: Vec::new(),
        }
    }

    fn tic(&mut self, game: &SimGame) {
        let cues = self.sounds.effects(game);
        let len = self.samples.len();
        if cues.starts.is_empty() && self.audio.mixer.busy() == 0 {
            // Nothing sounds and nothing starts: the mix would be zeros
            // (and the listener, all `apply` would change, is set again
            // before the next sound starts). Most tics are silent.
            self.samples.extend(std::iter::repeat_n(0, 2 * self.audio.frames_per_tick()));
        } else {
            self.scratch.clear();
            // No music is applied, so nothing can fail.
            let _ = self.audio.render_tick(&cues, &mut self.scratch);
            // Mixed in -1..1 (clipped there), as Doom's mixer fills its 16-bit buffer.
            self.samples.extend(self.scratch.iter().map(|&v| (v * 32767.0).round() as i16));
        }
        let extra = self.samples.len() - len;
        self.samples.drain(..extra);
    }

    /// Frames a tic.
    pub fn frames_per_tick(&self) -> usize {
        self.audio.frames_per_tick()
    }

    /// The buffer's frames (tics times frames a tic).
    pub fn frames(&self) -> usize {
        self.samples.len() / 2
    }

    /// The samples, interleaved left, right, oldest first.
    pub fn samples(&self) -> Vec<i16> {
        self.samples.iter().copied().collect()
    }

    /// Warnings from loading the voices (a missing or corrupt lump), one
    /// line each, taken.
    pub fn take_warnings(&mut self) -> Vec<String> {
        std::mem::take(&mut self.sounds.warnings)
    }
}

/// The messages of the last tics, as the player saw them: pickups, keys,
/// locked doors, secrets (`Event::Message`), and what the map's scripts
/// printed or logged (ViZDoom's buffer holds ZDoom's console notifications,
/// `Log` included).
pub struct Notifications {
    tics: u32,
    /// Tics fed so far.
    fed: u64,
    /// How many lines scripts had printed after the last tic (what they
    /// printed before the episode, in the game it was copied from, is not
    /// its own).
    printed: usize,
    /// (tic fed, line), oldest first, the last `tics` tics' only.
    lines: VecDeque<(u64, String)>,
}

impl Notifications {
    /// The last `tics` tics of `game` from now on.
    pub fn new(tics: u32, game: &SimGame) -> Notifications {
        Notifications { tics, fed: 0, printed: printed(game).len(), lines: VecDeque::new() }
    }

    fn tic(&mut self, game: &SimGame) {
        self.fed += 1;
        let printed = printed(game);
        let new = printed.get(self.printed..).unwrap_or(&[]);
        let messages = game.events().iter().filter_map(|e| match e {
            Event::Message(m) => Some(m.as_str()),
            _ => None,
        });
        for line in messages.chain(new.iter().map(String::as_str)) {
            self.lines.push_back((self.fed, line.to_string()));
        }
        self.printed = printed.len();
        let oldest = self.fed.saturating_sub(u64::from(self.tics));
        while self.lines.front().is_some_and(|&(t, _)| t <= oldest) {
            self.lines.pop_front();
        }
    }

    /// The lines of the last tics, oldest first.
    pub fn lines(&self) -> impl Iterator<Item = &str> {
        self.lines.iter().map(|(_, l)| l.as_str())
    }

    /// The buffer as ViZDoom gives it: every line followed by a newline
    /// (`""` when there are none).
    pub fn text(&self) -> String {
        self.lines().flat_map(|l| [l, "\n"]).collect()
    }
}

/// What `game`'s scripts have printed or logged, oldest first.
fn printed(game: &SimGame) -> &[String] {
    game.scripts().map_or(&[], |s| &s.printed)
}

#[cfg(test)]
mod tests {
    use super::super::{Scenario, ScenarioConfig};

    /// basic.cfg with `extra` lines applied.
    fn basic(extra: &str) -> Option<Scenario> {
        let dir = super::super::shipped_dir()?;
        let mut config = ScenarioConfig::load(dir.join("basic.cfg")).unwrap();
        config.apply(extra, "test").unwrap();
        Some(Scenario::open(&config, None).unwrap())
    }

    /// The loudest sample of each tic in a buffer of whole tics.
    fn peaks(samples: &[i16], frames_per_tick: usize) -> Vec<i32> {
        samples.chunks(2 * frames_per_tick).map(|t| t.iter().map(|&v| i32::from(v).abs()).max().unwrap_or(0)).collect()
    }

    /// basic's buttons are MOVE_LEFT, MOVE_RIGHT, ATTACK: 20 idle tics,
    /// one shot, 40 idle tics; each state's one-tic buffer kept. (With
    /// seed 3 the shot misses: the episode goes on.)
    fn shot(scenario: &Scenario, seed: u64) -> Vec<Vec<i16>> {
        let mut e = scenario.episode(seed).unwrap();
        let mut states = Vec::new();
        for t in 0..61 {
            e.step(&[0.0, 0.0, if t == 20 { 1.0 } else { 0.0 }]);
            states.push(e.buffers().and_then(|b| b.audio()).map(|a| a.samples()).unwrap_or_default());
        }
        assert_eq!(e.end(), None, "the shot missed");
        states
    }

    #[test]
    fn the_pistol_is_heard_after_the_shot_and_not_before() {
        let Some(scenario) = basic("audio_buffer_enabled = true\naudio_sampling_rate = SR_22050") else { return };
        let states = shot(&scenario, 3);
        // One tic at 22,050 Hz: 630 frames of two samples.
        assert!(states.iter().all(|s| s.len() == 2 * 630));
        let peak: Vec<i32> = states.iter().map(|s| peaks(s, 630)[0]).collect();
        // Doom's pistol fires (A_FirePistol, and its sound) on the fifth
        // tic after ATTACK: S_PISTOL1 lasts 4 tics.
        assert!(peak[..24].iter().all(|&p| p == 0), "before the shot: {:?}", &peak[..24]);
        // The pistol (DSPISTOL, about a third of a second) is loud from
        // then, centred, and ends.
        assert!(peak[24] > 8000, "the shot's tic: {}", peak[24]);
        assert!(peak[24..35].iter().all(|&p| p > 1000), "after the shot: {:?}", &peak[24..]);
        assert_eq!(peak[60], 0, "long after: {:?}", &peak[24..]);
        let s = &states[24];
        let (l, r): (i64, i64) =
            s.chunks(2).fold((0, 0), |(l, r), f| (l + i64::from(f[0].abs()), r + i64::from(f[1].abs())));
        assert!((l - r).abs() * 50 < l.max(r), "the player's own sound is centred: {l} {r}");
        // Same seed and actions: the same bytes; the buffer off: none kept.
        assert_eq!(states, shot(&scenario, 3));
        let Some(quiet) = basic("") else { return };
        assert!(quiet.episode(3).unwrap().buffers().is_none());
    }

    #[test]
    fn a_buffer_of_several_tics_holds_them_oldest_first() {
        let Some(scenario) =
            basic("audio_buffer_enabled = true\naudio_buffer_size = 4\naudio_sampling_rate = SR_11025")
        else {
            return;
        };
        let mut e = scenario.episode(3).unwrap();
        for t in 0..26 {
            e.step(&[0.0, 0.0, if t == 20 { 1.0 } else { 0.0 }]);
        }
        assert_eq!(e.end(), None, "the shot missed");
        let audio = e.buffers().and_then(|b| b.audio()).unwrap();
        assert_eq!((audio.frames_per_tick(), audio.frames()), (315, 4 * 315));
        // Tics 23 to 26: two silent, then the shot's (the fifth after
        // ATTACK) and the one after.
        let p = peaks(&audio.samples(), 315);
        assert!(p[0] == 0 && p[1] == 0 && p[2] > 8000 && p[3] > 1000, "{p:?}");
    }

    #[test]
    fn pickups_are_notified_for_the_buffer_s_tics() {
        let Some(dir) = super::super::shipped_dir() else { return };
        let mut config = ScenarioConfig::load(dir.join("health_gathering.cfg")).unwrap();
        config.apply("notifications_buffer_enabled = true\nnotifications_buffer_size = 3", "test").unwrap();
        let scenario = Scenario::open(&config, None).unwrap();
        // The autopilot fetches medikits.
        let mut e = scenario.episode(1).unwrap();
        let mut expert = super::super::Expert::new(&e);
        let mut texts = Vec::new();
        for _ in 0..2000 {
            let action = expert.action(&e);
            e.step(&action);
            let Some(n) = e.buffers().and_then(|b| b.notifications()) else { panic!("the buffer is on") };
            texts.push(n.text());
            if e.end().is_some() {
                break;
            }
        }
        let first = texts.iter().position(|t| !t.is_empty()).expect("a medikit taken");
        let line = &texts[first];
        assert!(line == "Picked up a medikit.\n" || line == "Picked up a medikit that you REALLY need!\n", "{line:?}");
        // Shown for three states, then gone (unless another is taken).
        assert_eq!(texts[first + 1], texts[first]);
        assert_eq!(texts[first + 2], texts[first]);
        assert!(texts[first + 3].is_empty() || texts[first + 3].matches('\n').count() == 1);
    }
}
