//! The mixer: sounds started at positions, heard from the listener by
//! Doom's rules, mixed into stereo at the output rate. It knows nothing of
//! devices or of the game; [`super::Audio`] feeds it each tick.
//!
//! Doom's rules (S_StartSound, S_AdjustSoundParams, S_getChannel):
//! - distance is Doom's approximation (the larger of |dx| and |dy| plus half
//!   the smaller); beyond [`CLIPPING_DIST`] a sound is not heard (not even
//!   started); within [`CLOSE_DIST`] it is at full volume; between, the volume
//!   falls linearly to nothing at the clipping distance;
//! - stereo separation is `128 - 96 * sin(angle)` (0 to 255), the angle
//!   from the listener's facing to the sound, anticlockwise: a sound to the
//!   left is louder on the left; the listener's own sounds are centred;
//! - one sound per origin: a new one from the same origin cuts off the
//!   old; else the first free channel; else the first channel playing a
//!   sound of a priority number at least as large (Doom's larger numbers
//!   are less important); else the new sound is dropped;
//! - while a sound plays, its volume and separation follow its origin and
//!   the listener each tick, and it stops once out of hearing.

use std::sync::Arc;

use glam::DVec2;

use super::Sample;

/// Beyond this a sound is not heard (Doom's `S_CLIPPING_DIST`).
pub const CLIPPING_DIST: f64 = 1200.0;
/// Within this a sound is at full volume (Doom's `S_CLOSE_DIST`).
pub const CLOSE_DIST: f64 = 200.0;
/// Doom's `S_STEREO_SWING`.
pub const STEREO_SWING: f64 = 96.0;
/// Doom's default number of channels (`snd_channels`).
pub const DEFAULT_CHANNELS: usize = 8;

/// Who made a sound: a new sound from the same origin replaces the old.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    /// The listener (centred, full volume).
    Listener,
    Sector(usize),
    Actor(u32),
    /// A point with no one behind it (a teleport's flash): each its own origin.
    Point(u64),
}

/// Where the listener is and which way it faces (degrees anticlockwise from east).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Listener {
    pub pos: DVec2,
    pub angle: f64,
}

/// Doom's approximate distance (`P_AproxDistance`).
pub fn approx_distance(d: DVec2) -> f64 {
    let (x, y) = (d.x.abs(), d.y.abs());
    x + y - x.min(y) / 2.0
}

/// A sound's volume (0 to 1) and separation (0 to 255, 128 centred) from
/// `at` heard by `listener`; `None` when out of hearing.
pub fn adjust(listener: &Listener, at: Option<DVec2>) -> Option<(f64, f64)> {
    let Some(at) = at else { return Some((1.0, 128.0)) };
    let d = at - listener.pos;
    let dist = approx_distance(d);
    // Written so that a NaN distance (a broken position) is out of hearing too.
    // At the clipping distance the volume is 0, and Doom does not start it.
    if dist.is_nan() || dist >= CLIPPING_DIST {
        return None;
    }
    let volume = if dist < CLOSE_DIST { 1.0 } else { (CLIPPING_DIST - dist) / (CLIPPING_DIST - CLOSE_DIST) };
    let separation = if dist < 1e-9 {
        128.0
    } else {
        let angle = d.y.atan2(d.x) - listener.angle.to_radians();
        128.0 - STEREO_SWING * angle.sin()
    };
    Some((volume, separation))
}

/// Left and right gains of a volume and separation, as Doom's mixer turns
/// them (`(254 - sep) * vol` and `sep * vol`), scaled so that centred is 1.
pub fn gains(volume: f64, separation: f64) -> (f32, f32) {
    let sep = separation.clamp(0.0, 254.0);
    ((volume * (254.0 - sep) / 127.0) as f32, (volume * sep / 127.0) as f32)
}

struct Playing {
    sample: Arc<Sample>,
    /// Where in the sample, in its own samples, and how far per output frame.
    at: f64,
    step: f64,
    key: Key,
    priority: u8,
    /// Where it comes from (`None`: the listener).
    pos: Option<DVec2>,
    gains: (f32, f32),
}

pub struct Mixer {
    rate: u32,
    channels: Vec<Option<Playing>>,
    /// Effects' loudness, 0 to 1.
    pub volume: f32,
}

impl Mixer {
    pub fn new(rate: u32, channels: usize) -> Mixer {
        Mixer { rate, channels: (0..channels.max(1)).map(|_| None).collect(), volume: 1.0 }
    }

    pub fn rate(&self) -> u32 {
        self.rate
    }

    /// Sounds playing now.
    pub fn busy(&self) -> usize {
        self.channels.iter().filter(|c| c.is_some()).count()
    }

    /// The keys of the sounds playing, by channel.
    pub fn playing(&self) -> Vec<Option<Key>> {
        self.channels.iter().map(|c| c.as_ref().map(|p| p.key)).collect()
    }

    /// Starts `sample` from `key` at `pos` (`None`: the listener's own) with
    /// Doom's `priority`. Returns whether it plays.
    pub fn start(
        &mut self,
        sample: Arc<Sample>,
        key: Key,
        pos: Option<DVec2>,
        priority: u8,
        listener: &Listener,
    ) -> bool {
        let pos = if key == Key::Listener { None } else { pos };
        let Some((volume, separation)) = adjust(listener, pos) else { return false };
        // The origin's old sound stops (Doom's S_StopSound(origin)), then
        // the first free channel, else the first with a priority number at
        // least the new one's.
        if !matches!(key, Key::Point(_)) {
            for c in &mut self.channels {
                if c.as_ref().is_some_and(|p| p.key == key) {
                    *c = None;
                }
            }
        }
        let slot = self
            .channels
            .iter()
            .position(Option::is_none)
            .or_else(|| self.channels.iter().position(|c| c.as_ref().is_some_and(|p| p.priority >= priority)));
        let Some(slot) = slot else { return false };
        let step = f64::from(sample.rate) / f64::from(self.rate);
        self.channels[slot] =
            Some(Playing { sample, at: 0.0, step, key, priority, pos, gains: gains(volume, separation) });
        true
    }

    /// The listener moved or the origins did (`moved`: where keys are
    /// now): every sound's volume and separation follow; those out of
    /// hearing stop.
    pub fn update(&mut self, listener: &Listener, moved: &[(Key, DVec2)]) {
        for c in &mut self.channels {
            let Some(p) = c else { continue };
            if let Some(&(_, pos)) = moved.iter().find(|(k, _)| *k == p.key) {
                if p.pos.is_some() {
                    p.pos = Some(pos);
                }
            }
            match adjust(listener, p.pos) {
                Some((volume, separation)) => p.gains = gains(volume, separation),
                None => *c = None,
            }
        }
    }

    /// Stops every sound.
    pub fn stop_all(&mut self) {
        self.channels.iter_mut().for_each(|c| *c = None);
    }

    /// Adds the sounds into `out` (interleaved left, right), advancing them;
    /// those that end free their channels.
    pub fn mix(&mut self, out: &mut [f32]) {
        let master = self.volume;
        for c in &mut self.channels {
            let Some(p) = c else { continue };
            let data = &p.sample.data;
            let (gl, gr) = (p.gains.0 * master, p.gains.1 * master);
            for frame in out.chunks_exact_mut(2) {
                let i = p.at as usize;
                if i >= data.len() {
                    break;
                }
                // Linear interpolation between the two nearest samples.
                let frac = (p.at - i as f64) as f32;
                let next = data.get(i + 1).copied().unwrap_or(0.0);
                let v = data[i] + (next - data[i]) * frac;
                frame[0] += v * gl;
                frame[1] += v * gr;
                p.at += p.step;
            }
            if p.at as usize >= data.len() {
                *c = None;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tone(rate: u32, seconds: f64) -> Arc<Sample> {
        let n = (f64::from(rate) * seconds) as usize;
        Arc::new(Sample { rate, data: (0..n).map(|i| (i as f32 * 0.05).sin()).collect() })
    }

    fn loudness(out: &[f32]) -> (f32, f32) {
        let sum = |k: usize| out.iter().skip(k).step_by(2).map(|v| v * v).sum::<f32>().sqrt();
        (sum(0), sum(1))
    }

    fn heard(pos: Option<DVec2>, key: Key) -> (f32, f32) {
        let listener = Listener { pos: DVec2::ZERO, angle: 90.0 };
        let mut m = Mixer::new(44_100, 8);
        m.start(tone(11_025, 0.5), key, pos, 64, &listener);
        let mut out = vec![0.0; 2 * 4410];
        m.mix(&mut out);
        loudness(&out)
    }

    #[test]
    fn doom_s_positional_rules() {
        // At the listener, or the listener's own: centred (Doom's 126:128 split) and loud.
        let (l, r) = heard(Some(DVec2::ZERO), Key::Actor(1));
        let (ol, or) = heard(None, Key::Listener);
        assert!((l - r).abs() < 0.02 * l && l > 10.0, "{l} {r}");
        assert!((l - ol).abs() < 0.01 * l && (r - or).abs() < 0.01 * r);
        // Facing north, a sound to the west is to the left: louder there.
        let (l, r) = heard(Some(DVec2::new(-100.0, 0.0)), Key::Actor(1));
        assert!(l > 3.0 * r, "{l} {r}");
        // Within the close distance, full volume; farther, quieter; past 1,200, silent.
        let near = heard(Some(DVec2::new(0.0, 150.0)), Key::Actor(1));
        let mid = heard(Some(DVec2::new(0.0, 700.0)), Key::Actor(1));
        assert!((near.0 - ol).abs() < 0.01 * ol);
        assert!((mid.0 / ol - 0.5).abs() < 0.01, "{} of {ol}", mid.0);
        assert_eq!(heard(Some(DVec2::new(0.0, 1300.0)), Key::Actor(1)), (0.0, 0.0));
        assert_eq!(adjust(&Listener::default(), Some(DVec2::new(900.0, 900.0))), None);
        assert!(adjust(&Listener::default(), Some(DVec2::new(1199.0, 0.0))).is_some());
        assert_eq!(adjust(&Listener::default(), Some(DVec2::new(1200.0, 0.0))), None);
    }

    #[test]
    fn one_sound_per_origin_and_the_channel_limit_drops_the_least_important() {
        let listener = Listener::default();
        let mut m = Mixer::new(44_100, 2);
        let s = tone(11_025, 1.0);
        assert!(m.start(s.clone(), Key::Actor(1), Some(DVec2::X), 70, &listener));
        // The same origin again: replaces its sound, no second channel.
        assert!(m.start(s.clone(), Key::Actor(1), Some(DVec2::X), 70, &listener));
        assert_eq!(m.busy(), 1);
        assert!(m.start(s.clone(), Key::Sector(3), Some(DVec2::X), 100, &listener));
        // Full: a more important sound (32) takes the channel of the first
        // with a number at least as large; a less important one (120) is dropped.
        assert!(!m.start(s.clone(), Key::Actor(9), Some(DVec2::X), 120, &listener));
        assert!(m.start(s.clone(), Key::Actor(8), Some(DVec2::X), 32, &listener));
        assert_eq!(m.playing(), [Some(Key::Actor(8)), Some(Key::Sector(3))]);
        assert!(m.start(s.clone(), Key::Actor(7), Some(DVec2::X), 90, &listener));
        assert_eq!(m.playing(), [Some(Key::Actor(8)), Some(Key::Actor(7))]);
        // Points are each their own origin.
        let mut m = Mixer::new(44_100, 4);
        m.start(s.clone(), Key::Point(1), Some(DVec2::X), 32, &listener);
        m.start(s.clone(), Key::Point(1), Some(DVec2::X), 32, &listener);
        assert_eq!(m.busy(), 2);
    }

    #[test]
    fn a_sound_follows_its_origin_stops_out_of_hearing_and_ends() {
        let listener = Listener::default();
        let mut m = Mixer::new(44_100, 8);
        m.start(tone(22_050, 0.1), Key::Actor(1), Some(DVec2::X), 64, &listener);
        m.update(&listener, &[(Key::Actor(1), DVec2::new(5000.0, 0.0))]);
        assert_eq!(m.busy(), 0);
        // Resampled from 22,050 to 44,100: 0.1 s is 4,410 frames, then the channel frees.
        m.start(tone(22_050, 0.1), Key::Actor(1), Some(DVec2::X), 64, &listener);
        let mut out = vec![0.0; 2 * 4400];
        m.mix(&mut out);
        assert_eq!(m.busy(), 1);
        let mut out = vec![0.0; 2 * 20];
        m.mix(&mut out);
        assert_eq!(m.busy(), 0);
        assert!(out[2 * 12..].iter().all(|&v| v == 0.0));
    }
}
