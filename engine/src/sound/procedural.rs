//! Our own sounds: a voice for every sound name of the table, synthesized
//! from oscillators, noise and envelopes, so that a RON map with no WAD is
//! heard too (doors grinding, shots, monsters' cries). Deterministic: the
//! same name gives the same samples. Each name belongs to a family (a
//! gunshot, a door, a lift, a switch, a pickup, a cry of sight, pain or
//! death, an explosion ...) and gets that family's shape with a pitch and
//! colour of its own from a hash of its name.

use super::Sample;

/// The rate our sounds are made at (Doom's commonest).
pub const RATE: u32 = 11_025;

/// A small deterministic noise source (xorshift32).
struct Noise(u32);

impl Noise {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        (self.0 as f32 / u32::MAX as f32) * 2.0 - 1.0
    }
}

/// FNV-1a of a name: its sound's own pitch and colour.
fn hash(name: &str) -> u32 {
    name.bytes().fold(0x811c_9dc5u32, |h, b| (h ^ u32::from(b)).wrapping_mul(0x0100_0193))
}

/// A one-pole low-pass filter.
struct LowPass {
    y: f32,
}

impl LowPass {
    fn run(&mut self, x: f32, cutoff: f32) -> f32 {
        let a = 1.0 - (-2.0 * std::f32::consts::PI * cutoff / RATE as f32).exp();
        self.y += a * (x - self.y);
        self.y
    }
}

/// What a family of sounds is made of.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Family {
    Gunshot { body: f32, length: f32 },
    Thump,
    Click { clicks: u32 },
    Door { opening: bool },
    LiftStart,
    LiftStop,
    Grind,
    Switch,
    Pickup { notes: &'static [f32] },
    Teleport,
    Cry { rise: f32, length: f32, rough: f32 },
    Explosion { length: f32 },
    Whoosh,
    Hum,
}

/// The family of a sound name (Doom's names; anything else is a cry).
fn family(name: &str) -> Family {
    match name {
        "pistol" | "chgun" => Family::Gunshot { body: 1.0, length: 0.25 },
        "shotgn" => Family::Gunshot { body: 0.7, length: 0.45 },
        "dshtgn" => Family::Gunshot { body: 0.55, length: 0.6 },
        "punch" | "hoof" | "metal" | "plland" | "slop" | "claw" | "skeswg" | "sawhit" => Family::Thump,
        "sgcock" | "dbload" | "dbopn" | "dbcls" | "tink" | "locked" => Family::Click { clicks: 2 },
        "doropn" | "bdopn" => Family::Door { opening: true },
        "dorcls" | "bdcls" => Family::Door { opening: false },
        "pstart" => Family::LiftStart,
        "pstop" => Family::LiftStop,
        "stnmov" | "sawidl" | "sawful" | "sawup" => Family::Grind,
        "swtchn" | "swtchx" | "mnumov" | "mnuact" | "mnuopn" | "mnucls" | "mnubak" | "mnusli" | "inttic" => {
            Family::Switch
        }
        "itemup" | "keyup" | "inttot" => Family::Pickup { notes: &[880.0, 1320.0] },
        "wpnup" => Family::Pickup { notes: &[440.0, 660.0, 880.0] },
        "getpow" | "secret" | "intnex" | "radio" => Family::Pickup { notes: &[523.0, 659.0, 784.0, 1047.0] },
        "telept" | "itmbk" => Family::Teleport,
        "barexp" | "rxplod" | "firxpl" | "bfg" | "plasma" | "boscub" | "bospit" => Family::Explosion { length: 1.0 },
        "firsht" | "rlaunc" | "flame" | "flamst" | "manatk" | "skeatk" | "vilatk" | "sklatk" => Family::Whoosh,
        "mnuerr" | "noway" | "oof" | "pljump" => Family::Cry { rise: -0.1, length: 0.2, rough: 0.2 },
        n if n.ends_with("sit") || n.starts_with("posit") || n.starts_with("bgsit") => {
            Family::Cry { rise: 0.5, length: 0.7, rough: 0.5 }
        }
        n if n.contains("pain") || n.ends_with("pn") => Family::Cry { rise: 0.3, length: 0.35, rough: 0.3 },
        n if n.contains("dth") || n.contains("deth") || n.contains("die") || n.ends_with("dt") => {
            Family::Cry { rise: -0.6, length: 1.0, rough: 0.6 }
        }
        n if n.ends_with("act") || n.ends_with("wlk") => Family::Hum,
        n if n.ends_with("atk") => Family::Whoosh,
        _ => Family::Cry { rise: 0.0, length: 0.5, rough: 0.4 },
    }
}

/// Our voice for the sound `name`, at [`RATE`].
pub fn voice(name: &str) -> Sample {
    let h = hash(name);
    let mut noise = Noise(h | 1);
    // The name's own shade: a pitch factor 0.8 to 1.25.
    let shade = 0.8 + (h % 1000) as f32 / 1000.0 * 0.45;
    let mut lp = LowPass { y: 0.0 };
    let mut lp2 = LowPass { y: 0.0 };
    let rate = RATE as f32;
    let samples = |seconds: f32| (seconds * rate) as usize;
    let tau = std::f32::consts::TAU;
    let mut phase = 0.0f32;
    let mut data: Vec<f32> = Vec::new();
    match family(name) {
        Family::Gunshot { body, length } => {
            for i in 0..samples(length) {
                let t = i as f32 / rate;
                let crack = noise.next() * (-t * 30.0 / length).exp();
                let thump = (tau * 70.0 * body * shade * t).sin() * (-t * 14.0).exp();
                data.push(lp.run(crack, 3000.0 * body) * 0.9 + thump * 0.6);
            }
        }
        Family::Thump => {
            for i in 0..samples(0.18) {
                let t = i as f32 / rate;
                let v = (tau * 90.0 * shade * t).sin() * (-t * 30.0).exp() + noise.next() * 0.3 * (-t * 60.0).exp();
                data.push(v);
            }
        }
        Family::Click { clicks } => {
            for i in 0..samples(0.12 * clicks as f32 + 0.05) {
                let t = i as f32 / rate;
                let since = t % 0.12;
                data.push(
                    noise.next() * (-since * 120.0).exp() * 0.8
                        + (tau * 1800.0 * shade * t).sin() * (-since * 90.0).exp() * 0.3,
                );
            }
        }
        Family::Door { opening } => {
            let length = 0.9;
            for i in 0..samples(length) {
                let t = i as f32 / rate;
                let f = if opening { 60.0 + 40.0 * t } else { 100.0 - 40.0 * t } * shade;
                phase += tau * f / rate;
                let rumble = (phase.sin() + 0.5 * (2.0 * phase).sin()) * 0.4;
                let grind = lp.run(noise.next(), 500.0) * 1.5;
                let envelope = (t * 20.0).min(1.0) * ((length - t) * 8.0).min(1.0);
                let slam = if !opening && t > length - 0.15 {
                    noise.next() * (-(t - length + 0.15) * 30.0).exp()
                } else {
                    0.0
                };
                data.push((rumble + grind) * envelope + slam);
            }
        }
        Family::LiftStart => {
            for i in 0..samples(0.6) {
                let t = i as f32 / rate;
                phase += tau * (50.0 + 60.0 * t) * shade / rate;
                data.push((phase.sin() * 0.5 + lp.run(noise.next(), 300.0)) * (t * 10.0).min(1.0) * (1.0 - t / 0.6));
            }
        }
        Family::LiftStop => {
            for i in 0..samples(0.3) {
                let t = i as f32 / rate;
                data.push(
                    (tau * 55.0 * shade * t).sin() * (-t * 12.0).exp()
                        + lp.run(noise.next(), 800.0) * (-t * 25.0).exp(),
                );
            }
        }
        Family::Grind => {
            for i in 0..samples(0.35) {
                let t = i as f32 / rate;
                let buzz = ((tau * 40.0 * shade * t).sin() * 6.0).tanh() * 0.3;
                data.push((buzz + lp.run(noise.next(), 1200.0)) * (t * 30.0).min(1.0) * ((0.35 - t) * 30.0).min(1.0));
            }
        }
        Family::Switch => {
            for i in 0..samples(0.2) {
                let t = i as f32 / rate;
                let click = |at: f32| if t >= at { (-(t - at) * 200.0).exp() } else { 0.0 };
                data.push(
                    noise.next() * (click(0.0) + 0.7 * click(0.08))
                        + (tau * 1200.0 * shade * t).sin() * click(0.0) * 0.4,
                );
            }
        }
        Family::Pickup { notes } => {
            let each = 0.07;
            for i in 0..samples(each * notes.len() as f32 + 0.1) {
                let t = i as f32 / rate;
                let k = ((t / each) as usize).min(notes.len() - 1);
                phase += tau * notes[k] * (0.95 + 0.1 * (shade - 0.8)) / rate;
                let since = t - k as f32 * each;
                data.push((phase.sin() + 0.3 * (3.0 * phase).sin()) * 0.5 * (-since * 10.0).exp());
            }
        }
        Family::Teleport => {
            for i in 0..samples(0.8) {
                let t = i as f32 / rate;
                phase += tau * (200.0 + 1400.0 * t) * shade / rate;
                let shimmer = (tau * 23.0 * t).sin() * 0.5 + 0.5;
                data.push((phase.sin() * 0.5 + noise.next() * 0.2) * shimmer * (1.0 - t / 0.8));
            }
        }
        Family::Explosion { length } => {
            for i in 0..samples(length) {
                let t = i as f32 / rate;
                let cutoff = 2500.0 * (-t * 4.0).exp() + 80.0;
                let boom = lp2.run(lp.run(noise.next(), cutoff), cutoff) * 3.0;
                data.push(boom * (-t * 3.0 / length).exp() + (tau * 40.0 * t).sin() * (-t * 6.0).exp() * 0.5);
            }
        }
        Family::Whoosh => {
            for i in 0..samples(0.5) {
                let t = i as f32 / rate;
                let cutoff = 400.0 + 2500.0 * (1.0 - t / 0.5) * shade;
                data.push(lp.run(noise.next(), cutoff) * 2.0 * (t * 20.0).min(1.0) * (1.0 - t / 0.5));
            }
        }
        Family::Hum => {
            for i in 0..samples(0.5) {
                let t = i as f32 / rate;
                phase += tau * (70.0 + 10.0 * (tau * 6.0 * t).sin()) * shade / rate;
                let voice = (phase.sin() * 3.0).tanh() * 0.4;
                data.push((voice + lp.run(noise.next(), 400.0) * 0.4) * (t * 10.0).min(1.0) * (1.0 - t / 0.5));
            }
        }
        Family::Cry { rise, length, rough } => {
            let base = 160.0 * shade;
            for i in 0..samples(length) {
                let t = i as f32 / rate;
                let f = base * (1.0 + rise * t / length) * (1.0 + 0.04 * (tau * 7.0 * t).sin());
                phase += tau * f / rate;
                // A sawtooth through a moving filter, with breath.
                let saw = (phase / tau).fract() * 2.0 - 1.0;
                let formant = 700.0 + 500.0 * (tau * 2.0 * t / length).sin().abs();
                let v = lp.run(saw, formant) * 1.5 + lp2.run(noise.next(), 1500.0) * rough;
                data.push(v * (t * 25.0).min(1.0) * (1.0 - t / length).powf(0.7));
            }
        }
    }
    // Normalised to a common loudness.
    let peak = data.iter().fold(0.0f32, |m, &v| m.max(v.abs())).max(1e-6);
    for v in &mut data {
        *v *= 0.8 / peak;
    }
    Sample { rate: RATE, data }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_sound_of_the_table_has_a_voice_that_is_heard_and_the_same_twice() {
        for def in crate::actors::sounds::doom() {
            let s = voice(&def.name);
            assert_eq!(s.rate, RATE);
            assert!(s.data.len() > RATE as usize / 20, "{}: {} samples", def.name, s.data.len());
            assert!(s.data.len() < 2 * RATE as usize, "{}: {} samples", def.name, s.data.len());
            let rms = (s.data.iter().map(|v| v * v).sum::<f32>() / s.data.len() as f32).sqrt();
            assert!(rms > 0.05 && s.data.iter().all(|v| v.abs() <= 0.81), "{}: rms {rms}", def.name);
            assert_eq!(voice(&def.name), s);
        }
        assert_ne!(voice("posit1").data, voice("posit2").data);
    }
}
