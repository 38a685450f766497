//! Stand-in figures: a picture for every actor of Doom's roster (and a
//! mod's) that neither a PNG, a WAD nor our own cast ([`super::figures`])
//! draws. One parametrised model, built from the same solids and rendered
//! by the same camera as our roster ([`super::models`]), draws them all:
//! its build (a walker, a floater, a crawler, a pickup, a prop, a hanging
//! body, remains, a missile) and its size come from the actor (its
//! category, flags, radius and height), its colours and features from its
//! sprite's name, and its pose from the state its frame belongs to.
//!
//! The caller (`materials::standin`) reads the actor table; this module
//! knows nothing of it, so a stand-in is a pure function of a [`StandIn`].

use glam::Vec3;

use super::figures::{fall, legs, Pose};
use super::models::{render, Camera, Part};
use super::paint::{hex, mix, scale, seed_of, Rgb};
use crate::texture::Texture;

/// The shape of a stand-in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Build {
    /// On two legs: the zombies, the imp, the barons, the cyberdemon.
    Walker,
    /// A body that flies: the cacodemon, the pain elemental, the lost soul.
    Floater,
    /// Low and wide on many legs: the spiderdemon, the arachnotron.
    Crawler,
    /// Something to pick up, lying on the floor.
    Pickup(Pickup),
    /// A standing prop: a column, a lamp, a tree, a torch.
    Prop,
    /// A body hanging from the ceiling.
    Hanging,
    /// What is left on the floor: a corpse, a pool.
    Remains,
    /// A missile or an effect: a cloud of balls, glowing when it burns.
    Missile,
}

/// What kind of pickup.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Pickup {
    Ammo,
    Medical,
    Gun,
    Armour,
    /// A power-up: a glowing orb.
    Orb,
    Key,
}

/// Everything a stand-in picture depends on.
#[derive(Clone, Copy, Debug)]
pub struct StandIn {
    pub build: Build,
    /// The actor's radius and height in map units.
    pub radius: f32,
    pub height: f32,
    /// The colours and features, from the sprite's name ([`scheme`]).
    pub scheme: Scheme,
    pub pose: Pose,
    /// The frame is drawn at full brightness (a flash, a flame, a light).
    pub bright: bool,
}

/// A stand-in's colours and features.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scheme {
    /// The main colour (skin, hide, paint).
    pub skin: Rgb,
    /// The second colour (armour, belly, legs, trim).
    pub trim: Rgb,
    /// Eyes, flames, glows.
    pub eye: Rgb,
    /// [`GUN`], [`HORNS`], ... or'ed.
    pub features: u8,
}

pub const GUN: u8 = 1;
pub const HORNS: u8 = 2;
pub const SPIKES: u8 = 4;
/// Thin, long limbs (the revenant, the arch-vile).
pub const LEAN: u8 = 8;
/// A heavy body (the mancubus, the cyberdemon).
pub const BULK: u8 = 16;
/// Flames about it (the lost soul, lamps and torches).
pub const FLAME: u8 = 32;
/// Branches (trees).
pub const BRANCHES: u8 = 64;

/// The colours and features of Doom's sprites that a reader would know by
/// sight; any other sprite takes colours from its name's hash, so two
/// actors of a mod still look apart.
const SCHEMES: &[(&str, u32, u32, u32, u8)] = &[
    ("PLAY", 0x3c8a32, 0x5a4a32, 0xd0d0d0, GUN),
    ("POSS", 0x7a7a5a, 0x4a5a3a, 0xff3020, GUN),
    ("SPOS", 0x38383c, 0x8a2a20, 0xff3020, GUN),
    ("CPOS", 0x8a2a1a, 0x38383c, 0xffd040, GUN | BULK),
    ("SSWV", 0x3a4a8a, 0x2c2c30, 0xffffff, GUN),
    ("TROO", 0x7a5634, 0xb08a60, 0xff9020, SPIKES),
    ("SARG", 0xd07a8a, 0x8a4050, 0xffe040, BULK),
    ("HEAD", 0xc02818, 0x3040c0, 0x40ff40, HORNS),
    ("BOSS", 0xc89a80, 0x6a4a2a, 0x40ff40, HORNS),
    ("BOS2", 0x9a8a6a, 0x6a5a3a, 0x40ff40, HORNS),
    ("SKUL", 0xe0d8c0, 0x6a6050, 0xff8020, FLAME),
    ("SPID", 0xd8a0a0, 0x5a5a60, 0xff3020, GUN),
    ("BSPI", 0xd8a0a0, 0x7a7a80, 0x40c0ff, GUN),
    ("CYBR", 0x7a6050, 0x6a6a70, 0xff4020, HORNS | BULK | GUN),
    ("PAIN", 0x8a5a3a, 0xc08060, 0xff8020, HORNS),
    ("VILE", 0xd8c890, 0x8a7a50, 0xff6020, LEAN),
    ("SKEL", 0xe8e4d8, 0x5a4a3a, 0xff4020, LEAN | GUN),
    ("FATT", 0xc0a070, 0x7a5a3a, 0xff6020, BULK | GUN),
    ("KEEN", 0xe0c0a0, 0x30a040, 0xffffff, 0),
    ("BBRN", 0xd88c8c, 0x9a5656, 0xffffff, 0),
    ("BAL1", 0xff6010, 0xffd040, 0xffffff, FLAME),
    ("BAL2", 0xd040ff, 0xffa0ff, 0xffffff, FLAME),
    ("BAL7", 0x40ff40, 0xd0ffd0, 0xffffff, FLAME),
    ("PLSS", 0x4080ff, 0xc0e0ff, 0xffffff, FLAME),
    ("BFS1", 0x40ff40, 0xe0ffe0, 0xffffff, FLAME),
    ("MISL", 0x7a7a6a, 0xff8020, 0xffffff, FLAME),
    ("FATB", 0xff8020, 0xffe060, 0xffffff, FLAME),
    ("MANF", 0xff8020, 0xffe060, 0xffffff, FLAME),
    ("FIRE", 0xff8020, 0xffe060, 0xffffff, FLAME),
    ("APLS", 0x60ff40, 0xe0ffa0, 0xffffff, FLAME),
    ("ELEC", 0x5a5a60, 0x60a0ff, 0x80c0ff, FLAME),
    ("TRE1", 0x5a4028, 0x3a2a18, 0xffffff, BRANCHES),
    ("TRE2", 0x6a4a2a, 0x3a7a2a, 0xffffff, BRANCHES),
    ("SMIT", 0x6a5a4a, 0x4a3a2a, 0xffffff, 0),
    ("CBRA", 0xa08040, 0x6a5020, 0xffe080, FLAME),
    ("CAND", 0xe0d8b0, 0x6a5020, 0xffe080, FLAME),
    ("TBLU", 0x4a4a4a, 0x2a2a2a, 0x4080ff, FLAME),
    ("TGRN", 0x4a4a4a, 0x2a2a2a, 0x40ff60, FLAME),
    ("TRED", 0x4a4a4a, 0x2a2a2a, 0xff4020, FLAME),
    ("SMBT", 0x4a4a4a, 0x2a2a2a, 0x4080ff, FLAME),
    ("SMGT", 0x4a4a4a, 0x2a2a2a, 0x40ff60, FLAME),
    ("SMRT", 0x4a4a4a, 0x2a2a2a, 0xff4020, FLAME),
    ("TLMP", 0x8a8a90, 0x4a4a50, 0xe0f0ff, FLAME),
    ("TLP2", 0x8a8a90, 0x4a4a50, 0xe0f0ff, FLAME),
    ("FCAN", 0x6a6a70, 0x3a3a40, 0xffa020, FLAME),
    ("COL1", 0x3a8a3a, 0x2a5a2a, 0xffffff, 0),
    ("COL2", 0x3a8a3a, 0x2a5a2a, 0xffffff, 0),
    ("COL3", 0xa02a2a, 0x6a1a1a, 0xffffff, 0),
    ("COL4", 0xa02a2a, 0x6a1a1a, 0xffffff, 0),
    ("COL5", 0x3a8a3a, 0xd02020, 0xffffff, 0),
    ("COL6", 0xa02a2a, 0xe0d8c0, 0xffffff, 0),
    ("MEGA", 0xe0e0f0, 0xa0a0c0, 0xffffff, 0),
    ("SOUL", 0x3070ff, 0x80b0ff, 0xffffff, 0),
    ("PINV", 0x40d040, 0xa0ffa0, 0xffffff, 0),
    ("PINS", 0xc04040, 0xffa0a0, 0xffffff, 0),
    ("PVIS", 0xe0e040, 0xffffa0, 0xffffff, 0),
    ("PSTR", 0xe0e0e0, 0xc01818, 0xffffff, 0),
    ("PMAP", 0x40a040, 0xe0e0e0, 0xffffff, 0),
    ("ARM2", 0x3050c0, 0x203080, 0xffffff, 0),
    ("CELL", 0x50a050, 0xc0c0c0, 0x80ff80, 0),
    ("CELP", 0x50a050, 0xc0c0c0, 0x80ff80, 0),
    ("ROCK", 0x707468, 0xb02020, 0xffffff, 0),
    ("AMMO", 0x8a6a30, 0xd0a040, 0xffffff, 0),
    ("SBOX", 0xb01c1c, 0xd8b048, 0xffffff, 0),
    ("BPAK", 0x6a5a3a, 0x4a3a2a, 0xffffff, 0),
];

/// The scheme of sprite `sprite` (its four letters).
pub fn scheme(sprite: &str) -> Scheme {
    if let Some(&(_, skin, trim, eye, features)) = SCHEMES.iter().find(|s| s.0.eq_ignore_ascii_case(sprite)) {
        return Scheme { skin: hex(skin), trim: hex(trim), eye: hex(eye), features };
    }
    // A hue round the wheel from the name, at a middling value, so a
    // mod's actors differ from each other and read against grey walls.
    let h = seed_of(sprite);
    let hue = (h % 360) as f32;
    let skin = hsv(hue, 0.55, 0.7);
    let trim = hsv((hue + 150.0) % 360.0, 0.45, 0.45);
    let eye = hsv((hue + 60.0) % 360.0, 0.8, 1.0);
    Scheme { skin, trim, eye, features: ((h >> 9) as u8) & (HORNS | SPIKES) }
}

fn hsv(h: f32, s: f32, v: f32) -> Rgb {
    let c = v * s;
    let x = c * (1.0 - ((h / 60.0) % 2.0 - 1.0).abs());
    let (r, g, b) = match (h / 60.0) as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    [r + v - c, g + v - c, b + v - c]
}

/// The stand-in seen from Doom's `view` (1 front .. 8; 0 draws the front).
pub fn draw(s: &StandIn, view: u8) -> Texture {
    let mut parts = match s.build {
        Build::Walker => walker(s),
        Build::Floater => floater(s),
        Build::Crawler => crawler(s),
        Build::Pickup(kind) => pickup(s, kind),
        Build::Prop => prop(s),
        Build::Hanging => hanging(s),
        Build::Remains => remains(s),
        Build::Missile => missile(s),
    };
    let lies = matches!(s.build, Build::Walker | Build::Floater | Build::Crawler);
    let mut pose = s.pose;
    if !lies {
        pose.fall = 0.0;
    }
    if s.build == Build::Hanging {
        super::models::settle(&mut parts);
    } else {
        fall(&mut parts, &pose, s.radius.max(8.0));
    }
    let (w, h) = size(s, &pose);
    let camera = match s.build {
        Build::Pickup(_) | Build::Remains => Camera { above: 20.0, ..Camera::sprite(1, (w, h)) },
        Build::Missile => Camera { outline: None, ..Camera::sprite(view.max(1), (w, h)) },
        _ => Camera::sprite(view.max(1), (w, h)),
    };
    render(&parts, &camera)
}

/// The picture's size: room for the figure at its widest from any side,
/// raised arms and horns, and lying across the view when it falls.
fn size(s: &StandIn, pose: &Pose) -> (usize, usize) {
    let (r, h) = (s.radius.clamp(4.0, 160.0), s.height.clamp(4.0, 160.0));
    let (mut w, mut tall) = match s.build {
        Build::Pickup(_) => (2.0 * r + 12.0, (h * 1.2).max(r * 0.8) + 8.0),
        Build::Missile => {
            let burst = 1.0 + 2.0 * pose.fall;
            (2.0 * r * burst + 10.0, 2.0 * r * burst + 10.0)
        }
        Build::Remains => (2.0 * r.max(16.0) + 16.0, r.max(12.0) + 8.0),
        _ => (2.6 * r + 16.0, h * 1.3 + 10.0),
    };
    if pose.fall > 0.0 {
        w = w.max(h * 2.0 + 20.0);
        tall = tall.max(r * 2.0 + 10.0);
    }
    (w.ceil().min(400.0) as usize, tall.ceil().min(240.0) as usize)
}

/// A creature on two legs, its bulk from its radius and height.
fn walker(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, eye, features } = s.scheme;
    let (h, pose) = (s.height, &s.pose);
    // Doom's bodies are boxes wider than the figures in them: a zombieman
    // (radius 20) is about 24 wide at the shoulder.
    let bulk = if features & BULK != 0 {
        0.85
    } else if features & LEAN != 0 {
        0.45
    } else {
        0.6
    };
    let w = (s.radius * bulk).clamp(4.0, 60.0);
    let hip = h * 0.46;
    let thick = if features & LEAN != 0 { h * 0.035 } else { (w * 0.22).max(h * 0.045) };
    let mut p = Vec::new();
    legs(&mut p, pose, hip, w * 0.38, h * 0.16, thick, trim, scale(trim, 0.5));
    p.push(Part::ball(Vec3::new(0.0, 0.0, hip + h * 0.02), Vec3::new(w * 0.5, w * 0.7, h * 0.07), trim));
    let chest = Vec3::new(w * 0.05, 0.0, h * 0.69);
    let belly = if features & BULK != 0 { 1.35 } else { 1.0 };
    p.push(Part::ball(chest, Vec3::new(w * 0.42 * belly, w * 0.82, h * 0.15), skin).shiny(0.15));
    p.push(Part::ball(
        Vec3::new(w * 0.08 * belly, 0.0, h * 0.56),
        Vec3::new(w * 0.36 * belly, w * 0.6, h * 0.1),
        mix(skin, trim, 0.5),
    ));
    if features & LEAN != 0 {
        // Ribs across a narrow chest.
        for k in 0..3 {
            let z = chest.z - h * 0.08 + k as f32 * h * 0.06;
            p.push(Part::limb(Vec3::new(w * 0.45, -w * 0.7, z), Vec3::new(w * 0.45, w * 0.7, z), h * 0.012, trim));
        }
    }
    let head_r = h * 0.08;
    let head = Vec3::new(w * 0.12, 0.0, h * 0.9);
    p.push(Part::limb(chest + Vec3::new(0.0, 0.0, h * 0.1), head, head_r * 0.55, skin));
    p.push(Part::ball(head, Vec3::new(head_r * 1.05, head_r * 0.95, head_r), skin));
    for side in [1.0f32, -1.0] {
        p.push(
            Part::sphere(head + Vec3::new(head_r * 0.85, side * head_r * 0.4, head_r * 0.2), head_r * 0.22, eye)
                .glowing(),
        );
        if features & HORNS != 0 {
            let root = head + Vec3::new(0.0, side * head_r * 0.7, head_r * 0.6);
            p.push(Part::limb(
                root,
                root + Vec3::new(-head_r, side * head_r * 0.9, head_r * 1.6),
                head_r * 0.25,
                hex(0xe0d8c0),
            ));
        }
        if features & SPIKES != 0 {
            let shoulder = Vec3::new(0.0, side * w * 0.9, h * 0.76);
            for k in 0..2 {
                let at = shoulder + Vec3::new(-w * 0.2 * k as f32, 0.0, -h * 0.05 * k as f32);
                p.push(Part::limb(at, at + Vec3::new(-w * 0.2, side * w * 0.25, h * 0.08), h * 0.012, hex(0xe0d8b0)));
            }
        }
    }
    if pose.open > 0.05 {
        p.push(Part::ball(
            head + Vec3::new(head_r * 0.8, 0.0, -head_r * 0.45),
            Vec3::new(head_r * 0.3, head_r * 0.5, head_r * 0.35 * pose.open),
            hex(0x300404),
        ));
    }
    // Arms: hanging and swinging, or raised forward to attack.
    let arm = thick * 0.85;
    let mut hands = Vec::new();
    for side in [1.0f32, -1.0] {
        let shoulder = Vec3::new(0.0, side * w * 0.85, h * 0.77);
        let hand = if pose.aim > 0.0 {
            Vec3::new(w * 0.6 + h * 0.2 * pose.aim, side * w * 0.35, h * (0.58 + 0.1 * pose.aim))
        } else if features & GUN != 0 {
            // The gun held at the hip, pointing ahead.
            Vec3::new(w * 0.7 - pose.stride * h * 0.02, side * w * 0.3, h * 0.52)
        } else {
            Vec3::new(w * 0.3 - pose.stride * side * h * 0.08, side * w * 1.05, h * 0.45)
        };
        let hand = hand + Vec3::new(-h * 0.1 * pose.open.min(0.5) * f32::from(pose.lean < 0.0), 0.0, 0.0);
        let elbow = (shoulder + hand) * 0.5 + Vec3::new(-w * 0.1, side * w * 0.15, -h * 0.04);
        p.push(Part::limb(shoulder, elbow, arm, skin));
        p.push(Part::limb(elbow, hand, arm * 0.9, skin));
        p.push(Part::sphere(hand, arm * 1.05, scale(skin, 0.8)));
        hands.push(hand);
    }
    let front = (hands[0] + hands[1]) * 0.5;
    if features & GUN != 0 {
        let gun = front + Vec3::new(h * 0.08, 0.0, 0.0);
        p.push(Part::block(gun, Vec3::new(h * 0.1, thick * 0.6, thick * 0.8), hex(0x303236)).shiny(0.6));
        p.push(Part::limb(gun, gun + Vec3::new(h * 0.22, 0.0, thick * 0.2), thick * 0.3, hex(0x303236)).shiny(0.6));
        if pose.flash || (s.bright && pose.aim > 0.0) {
            p.push(Part::sphere(gun + Vec3::new(h * 0.27, 0.0, thick * 0.2), h * 0.06, hex(0xfff0a0)).glowing());
        }
    } else if pose.flash || (s.bright && pose.aim > 0.0) {
        p.push(Part::sphere(front + Vec3::new(h * 0.05, 0.0, h * 0.08), h * 0.07, eye).glowing());
    }
    p
}

/// A flying head: one great ball with an eye and a mouth.
fn floater(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, eye, features } = s.scheme;
    let r = (s.height * 0.5).min(s.radius).max(4.0);
    let c = Vec3::new(0.0, 0.0, r + s.height * 0.1);
    let pose = &s.pose;
    let mut p = vec![Part::ball(c, Vec3::new(r * 0.95, r, r * 0.92), skin).shiny(0.25)];
    if features & FLAME != 0 {
        // A skull in flames: jaw and sockets, fire streaming back.
        p[0].colour = skin;
        for side in [1.0f32, -1.0] {
            p.push(Part::sphere(c + Vec3::new(r * 0.7, side * r * 0.35, r * 0.15), r * 0.25, hex(0x100808)));
        }
        for k in 0..5 {
            let a = k as f32 * 1.3;
            let at = c + Vec3::new(-r * 0.8, a.sin() * r * 0.6, r * 0.3 + a.cos() * r * 0.4);
            p.push(Part::sphere(at, r * (0.55 - 0.06 * k as f32), mix(eye, hex(0xffe060), k as f32 / 5.0)).glowing());
        }
    } else {
        p.push(Part::sphere(c + Vec3::new(r * 0.78, 0.0, r * 0.35), r * 0.28, hex(0xf0f0e0)));
        p.push(Part::sphere(c + Vec3::new(r * 0.98, 0.0, r * 0.37), r * 0.14, eye).glowing());
    }
    let gape = 0.25 + 0.5 * pose.open + if pose.aim > 0.0 { 0.3 } else { 0.0 };
    p.push(Part::ball(c + Vec3::new(r * 0.72, 0.0, -r * 0.3), Vec3::new(r * 0.3, r * 0.55, r * 0.3 * gape), trim));
    for k in [-2.0f32, -1.0, 0.0, 1.0, 2.0] {
        let at = c + Vec3::new(r * 0.93, k * r * 0.16, -r * 0.3 + r * 0.22 * gape);
        p.push(Part::limb(at, at - Vec3::new(0.0, 0.0, r * 0.14), r * 0.04, hex(0xf0ead0)));
    }
    if features & HORNS != 0 {
        for side in [1.0f32, -1.0] {
            let root = c + Vec3::new(0.0, side * r * 0.55, r * 0.75);
            p.push(Part::limb(root, root + Vec3::new(-r * 0.2, side * r * 0.2, r * 0.55), r * 0.09, scale(skin, 0.6)));
        }
    }
    if pose.flash || (s.bright && pose.aim > 0.0) {
        p.push(Part::sphere(c + Vec3::new(r * 1.1, 0.0, -r * 0.2), r * 0.3, eye).glowing());
    }
    p
}

/// A body on a low chassis, on six legs.
fn crawler(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, eye, features } = s.scheme;
    let (r, h, pose) = (s.radius.min(140.0), s.height, &s.pose);
    let body = Vec3::new(0.0, 0.0, h * 0.6);
    let mut p = vec![
        Part::ball(body + Vec3::new(-r * 0.1, 0.0, h * 0.12), Vec3::new(r * 0.45, r * 0.5, h * 0.3), skin).shiny(0.35),
        Part::block(body - Vec3::new(0.0, 0.0, h * 0.1), Vec3::new(r * 0.4, r * 0.35, h * 0.1), trim).shiny(0.5),
    ];
    // The brain's folds.
    for k in 0..4 {
        let y = -r * 0.3 + r * 0.2 * k as f32;
        p.push(Part::limb(
            body + Vec3::new(-r * 0.4, y, h * 0.3),
            body + Vec3::new(r * 0.2, y, h * 0.38),
            h * 0.025,
            scale(skin, 0.7),
        ));
    }
    for side in [1.0f32, -1.0] {
        for k in 0..3 {
            let along = (k as f32 - 1.0) * r * 0.35;
            let swing = pose.stride * side * if k == 1 { -1.0 } else { 1.0 } * r * 0.08;
            let hip = body + Vec3::new(along, side * r * 0.3, -h * 0.05);
            let knee = Vec3::new(along * 1.3 + swing, side * r * 0.75, h * 0.85);
            let foot = Vec3::new(along * 1.5 + swing, side * r * 0.95, 0.0);
            p.push(Part::limb(hip, knee, h * 0.04, trim).shiny(0.4));
            p.push(Part::limb(knee, foot, h * 0.035, trim).shiny(0.4));
        }
    }
    let front = body + Vec3::new(r * 0.42, 0.0, -h * 0.08);
    p.push(Part::sphere(front + Vec3::new(0.0, r * 0.08, h * 0.08), h * 0.05, eye).glowing());
    p.push(Part::sphere(front + Vec3::new(0.0, -r * 0.08, h * 0.08), h * 0.05, eye).glowing());
    if features & GUN != 0 {
        p.push(Part::limb(front, front + Vec3::new(r * 0.35, 0.0, -h * 0.05), h * 0.06, hex(0x404248)).shiny(0.7));
        if pose.flash || (s.bright && pose.aim > 0.0) {
            p.push(Part::sphere(front + Vec3::new(r * 0.45, 0.0, -h * 0.05), h * 0.1, hex(0xfff0a0)).glowing());
        }
    }
    p
}

/// A pickup lying on the floor; its frames (`pose.open`, 0 to 1) glint.
fn pickup(s: &StandIn, kind: Pickup) -> Vec<Part> {
    let Scheme { skin, trim, eye, .. } = s.scheme;
    let r = s.radius.clamp(6.0, 24.0);
    let glint = s.pose.open;
    match kind {
        Pickup::Ammo => {
            let mut p = vec![Part::block(Vec3::new(0.0, 0.0, r * 0.3), Vec3::new(r * 0.4, r * 0.6, r * 0.3), skin)];
            for k in 0..3 {
                let y = -r * 0.4 + r * 0.4 * k as f32;
                p.push(Part::limb(Vec3::new(0.0, y, r * 0.6), Vec3::new(0.0, y, r * 0.9), r * 0.12, trim).shiny(0.8));
            }
            p
        }
        Pickup::Medical => {
            let red = hex(0xd01818);
            let white = mix(hex(0xe8e8e4), hex(0xffffff), glint);
            vec![
                Part::block(Vec3::new(0.0, 0.0, r * 0.35), Vec3::new(r * 0.4, r * 0.6, r * 0.35), white),
                Part::block(Vec3::new(r * 0.41, 0.0, r * 0.35), Vec3::new(0.4, r * 0.4, r * 0.12), red),
                Part::block(Vec3::new(r * 0.41, 0.0, r * 0.35), Vec3::new(0.4, r * 0.12, r * 0.28), red),
            ]
        }
        Pickup::Gun => {
            let steel = hex(0x3a3d42);
            vec![
                Part::limb(Vec3::new(0.0, -r * 1.1, r * 0.3), Vec3::new(0.0, r * 1.1, r * 0.3), r * 0.14, steel)
                    .shiny(0.7),
                Part::block(Vec3::new(0.0, -r * 0.2, r * 0.3), Vec3::new(r * 0.18, r * 0.5, r * 0.25), trim).shiny(0.4),
                Part::block(Vec3::new(r * 0.1, -r * 0.75, r * 0.15), Vec3::new(r * 0.12, r * 0.3, r * 0.15), skin),
            ]
        }
        Pickup::Armour => vec![
            Part::block(
                Vec3::new(0.0, 0.0, r * 0.15),
                Vec3::new(r * 0.6, r * 0.8, r * 0.15),
                mix(skin, hex(0xffffff), glint * 0.3),
            )
            .shiny(0.4),
            Part::ball(Vec3::new(-r * 0.4, r * 0.55, r * 0.25), Vec3::new(r * 0.25, r * 0.25, r * 0.15), skin),
            Part::ball(Vec3::new(-r * 0.4, -r * 0.55, r * 0.25), Vec3::new(r * 0.25, r * 0.25, r * 0.15), skin),
        ],
        Pickup::Orb => {
            let c = Vec3::new(0.0, 0.0, r * 0.9);
            vec![
                Part::sphere(c, r * 0.75, mix(skin, trim, glint)).glowing(),
                Part::sphere(c + Vec3::new(r * 0.4, r * 0.2, r * 0.3), r * 0.2, hex(0xffffff)).glowing(),
            ]
        }
        Pickup::Key => vec![
            Part::block(Vec3::new(0.0, 0.0, r * 0.4), Vec3::new(0.5, r * 0.35, r * 0.4), skin),
            Part::block(Vec3::new(0.6, 0.0, r * 0.55), Vec3::new(0.4, r * 0.3, r * 0.08), eye).glowing(),
        ],
    }
}

/// A standing prop: a column or pole of the actor's height, with a light
/// or flame on top when it has one, branches when it is a tree.
fn prop(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, eye, features } = s.scheme;
    let (r, h) = (s.radius.clamp(3.0, 40.0), s.height.clamp(8.0, 140.0));
    let thick = if features & (FLAME | BRANCHES) != 0 { r * 0.3 } else { r * 0.6 };
    let mut p = vec![
        Part::block(Vec3::new(0.0, 0.0, h * 0.04), Vec3::new(r * 0.7, r * 0.7, h * 0.04), trim),
        Part::limb(Vec3::new(0.0, 0.0, h * 0.05), Vec3::new(0.0, 0.0, h * 0.85), thick, skin).shiny(0.3),
        Part::limb(Vec3::new(0.0, 0.0, h * 0.5), Vec3::new(0.0, 0.0, h * 0.52), thick * 1.2, trim),
    ];
    if features & BRANCHES != 0 {
        for k in 0..5 {
            let a = k as f32 * 2.4;
            let from = Vec3::new(0.0, 0.0, h * (0.45 + 0.08 * k as f32));
            let to = from + Vec3::new(a.cos() * r * 1.4, a.sin() * r * 1.4, h * 0.2);
            p.push(Part::limb(from, to, thick * 0.4, skin));
            if trim[1] > trim[0] {
                p.push(Part::sphere(to, r * 0.5, trim));
            }
        }
    } else if features & FLAME != 0 || s.bright {
        let top = Vec3::new(0.0, 0.0, h * 0.9);
        let flicker = 1.0 + 0.15 * (s.pose.open * 6.0).sin();
        p.push(Part::ball(top, Vec3::new(r * 0.45, r * 0.45, h * 0.12 * flicker), eye).glowing());
        p.push(Part::sphere(top - Vec3::new(0.0, 0.0, h * 0.02), r * 0.22, hex(0xffffff)).glowing());
    } else {
        p.push(Part::block(Vec3::new(0.0, 0.0, h * 0.92), Vec3::new(r * 0.7, r * 0.7, h * 0.08), trim));
    }
    p
}

/// A body hanging from a chain, its feet `height` below the ceiling.
fn hanging(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, .. } = s.scheme;
    let h = s.height.clamp(16.0, 120.0);
    let sway = 0.15 * (s.pose.open * 6.0).sin();
    let body = |z: f32| Vec3::new(sway * (h - z), 0.0, z);
    vec![
        Part::limb(body(h * 0.75), Vec3::new(0.0, 0.0, h), 1.0, hex(0x505050)),
        Part::ball(body(h * 0.6), Vec3::new(5.0, 8.0, h * 0.18), skin),
        Part::limb(body(h * 0.45), body(h * 0.05) + Vec3::new(0.0, 3.0, 0.0), 3.0, trim),
        Part::limb(body(h * 0.45), body(h * 0.1) + Vec3::new(0.0, -3.0, 0.0), 3.0, trim),
        Part::limb(body(h * 0.72), body(h * 0.4) + Vec3::new(0.0, 9.0, 0.0), 2.2, skin),
        Part::limb(body(h * 0.72), body(h * 0.4) + Vec3::new(0.0, -9.0, 0.0), 2.2, skin),
        Part::ball(body(h * 0.62) + Vec3::new(2.0, 0.0, 0.0), Vec3::new(2.0, 5.0, 4.0), hex(0x8a1010)),
    ]
}

/// Remains on the floor: a heap in the actor's colours in a pool of blood.
fn remains(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, .. } = s.scheme;
    let r = s.radius.clamp(8.0, 32.0);
    vec![
        Part::ball(Vec3::new(0.0, 0.0, 0.5), Vec3::new(r * 0.9, r * 1.2, 1.0), hex(0x6a0a08)),
        Part::ball(Vec3::new(0.0, -r * 0.3, 3.0), Vec3::new(r * 0.35, r * 0.5, 3.0), skin),
        Part::ball(Vec3::new(r * 0.1, r * 0.35, 2.5), Vec3::new(r * 0.3, r * 0.3, 2.5), trim),
        Part::limb(Vec3::new(0.0, r * 0.1, 2.0), Vec3::new(r * 0.4, -r * 0.6, 1.5), 1.6, skin),
    ]
}

/// A missile or an effect: a ball of its colours, burst by `pose.fall`
/// (its death frames) into a spreading cloud.
fn missile(s: &StandIn) -> Vec<Part> {
    let Scheme { skin, trim, .. } = s.scheme;
    let r = s.radius.clamp(2.0, 40.0);
    let t = s.pose.fall;
    let c = Vec3::new(0.0, 0.0, r * (1.0 + 2.0 * t));
    let colour = mix(trim, skin, t);
    let mut p = vec![Part::sphere(c, r * (0.8 - 0.3 * t), if t < 0.5 { trim } else { skin })];
    let balls = 6;
    for j in 0..balls {
        let a = j as f32 * 2.399_963 + t * 1.7;
        let z = 1.0 - 2.0 * (j as f32 + 0.5) / balls as f32;
        let q = (1.0 - z * z).sqrt();
        let dir = Vec3::new(q * a.cos(), q * a.sin(), z);
        p.push(Part::sphere(c + dir * r * (0.4 + 1.6 * t), r * (0.55 - 0.2 * t), colour));
    }
    if s.bright || s.scheme.features & FLAME != 0 {
        p = p.into_iter().map(Part::glowing).collect();
    }
    p
}

/// A picture for a frame no art has: a box the actor's size in magenta and
/// black checks, with a white question mark, that no one takes for art.
pub fn placeholder(radius: f32, height: f32) -> Texture {
    let w = (2.0 * radius.clamp(4.0, 64.0)).ceil() as usize + 2;
    let h = height.clamp(8.0, 128.0).ceil() as usize;
    let mark = |u: usize, v: usize| {
        // A question mark in a 5x7 grid, scaled to the box's middle.
        const GLYPH: [u8; 7] = [0b01110, 0b10001, 0b00001, 0b00110, 0b00100, 0b00000, 0b00100];
        let cell = (w.min(h) / 9).max(1);
        let (x0, y0) = ((w - 5 * cell) / 2, (h.saturating_sub(7 * cell)) / 2);
        let (x, y) = (u.wrapping_sub(x0) / cell, v.wrapping_sub(y0) / cell);
        u >= x0 && v >= y0 && x < 5 && y < 7 && GLYPH[y] >> (4 - x) & 1 == 1
    };
    Texture::from_fn(w, h, |u, v| {
        if u == 0 || u == w - 1 {
            [0, 0, 0, 0]
        } else if mark(u, v) {
            [255, 255, 255, 255]
        } else if (u / 4 + v / 4) % 2 == 0 {
            [255, 0, 255, 255]
        } else {
            [0, 0, 0, 255]
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stand(build: Build, sprite: &str, radius: f32, height: f32, pose: Pose) -> StandIn {
        StandIn { build, radius, height, scheme: scheme(sprite), pose, bright: false }
    }

    fn shown(t: &Texture) -> usize {
        t.texels.iter().filter(|&&p| p >> 24 == 255).count()
    }

    #[test]
    fn a_walker_is_a_figure_its_height_tall_that_turns() {
        let imp = stand(Build::Walker, "TROO", 20.0, 56.0, Pose::default());
        let front = draw(&imp, 1);
        let side = draw(&imp, 3);
        // Its tallest column is about its height (plus an outline texel).
        let top = (0..front.height).find(|&v| (0..front.width).any(|u| front.texel(u, v) >> 24 == 255)).unwrap();
        let tall = front.height - top;
        assert!((50..=64).contains(&tall), "{tall}");
        assert!(front.texels != side.texels, "the side view is the front view");
        // A figure, not a box: well under the bounding box's area.
        let [u0, u1, v0, v1] = front.shown;
        assert!(shown(&front) * 10 < (u1 - u0) * (v1 - v0) * 8, "{} of {}", shown(&front), (u1 - u0) * (v1 - v0));
    }

    #[test]
    fn schemes_tell_actors_apart_and_poses_change_the_picture() {
        let a = draw(&stand(Build::Walker, "POSS", 20.0, 56.0, Pose::default()), 1);
        let b = draw(&stand(Build::Walker, "SPOS", 20.0, 56.0, Pose::default()), 1);
        assert!(a.texels != b.texels);
        let aiming = draw(&stand(Build::Walker, "POSS", 20.0, 56.0, Pose { aim: 1.0, ..Pose::default() }), 1);
        assert!(a.texels != aiming.texels);
        let dead =
            draw(&stand(Build::Walker, "POSS", 20.0, 56.0, Pose { fall: 1.0, blood: 1.0, ..Pose::default() }), 0);
        assert!(dead.width > dead.height, "{}x{}", dead.width, dead.height);
        assert_ne!(scheme("XYZW"), scheme("XYZV"));
    }

    #[test]
    fn every_build_stands_on_its_bottom_row() {
        let builds = [
            Build::Walker,
            Build::Floater,
            Build::Crawler,
            Build::Pickup(Pickup::Ammo),
            Build::Pickup(Pickup::Medical),
            Build::Pickup(Pickup::Gun),
            Build::Pickup(Pickup::Armour),
            Build::Pickup(Pickup::Orb),
            Build::Pickup(Pickup::Key),
            Build::Prop,
            Build::Hanging,
            Build::Remains,
            Build::Missile,
        ];
        for build in builds {
            let t = draw(&stand(build, "ABCD", 20.0, 40.0, Pose::default()), 1);
            assert!(shown(&t) > 20, "{build:?}");
            assert!(t.texels.iter().all(|&p| matches!(p >> 24, 0 | 255)), "{build:?}");
            if build != Build::Missile && build != Build::Floater {
                let bottom = (0..t.width).filter(|&u| t.texel(u, t.height - 1) >> 24 == 255).count();
                assert!(bottom >= 2, "{build:?} floats");
            }
        }
    }
}
