//! Sightline's own cast, modelled in 3D ([`super::models`]) and rendered
//! into Doom-style sprite frames: the roster's monsters (`engine/data/
//! roster.ron`: the sentry, the stalker, the spitter and its bolt), the
//! items and effects the default level uses, under Doom's sprite names (so
//! the shipped table's clip or stimpack shows ours when no WAD is loaded),
//! and the fist, pistol and shotgun on the screen.
//!
//! A name is Doom's: four letters of sprite, a frame letter, and a view
//! (`1` to `8` from Doom's eight directions, `0` alike from all). Each
//! figure is a function from a [`Pose`] to its parts; a frame letter names a
//! pose.

use glam::{Mat3, Vec3};

use super::models::{render, settle, Camera, Part};
use super::paint::{hex, mix, scale, Rgb};
use crate::texture::Texture;

/// How a figure stands in one frame.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pose {
    /// -1 to 1: how far the left leg is forward (the right goes back).
    pub stride: f32,
    /// 0 to 1: the weapon or the arms raised to attack.
    pub aim: f32,
    /// The muzzle or the hand burns (a bright frame).
    pub flash: bool,
    /// 0 to 1: the jaw open, the arm drawn back to throw.
    pub open: f32,
    /// Leaning into a lunge (positive) or flinching back (negative), radians.
    pub lean: f32,
    /// 0 standing to 1 lying on its back.
    pub fall: f32,
    /// Blood pooled under a body.
    pub blood: f32,
}

/// A frame: its letter, its pose, and whether it has eight views (or one, `0`).
struct Frame(u8, Pose, bool);

/// A monster or object in all its frames.
struct Figure {
    sprite: &'static str,
    size: (usize, usize),
    frames: fn() -> Vec<Frame>,
    model: fn(&Pose) -> Vec<Part>,
}

const FIGURES: &[Figure] = &[
    Figure { sprite: "SNTR", size: (44, 66), frames: sentry_frames, model: sentry },
    Figure { sprite: "STLK", size: (70, 64), frames: stalker_frames, model: stalker },
    Figure { sprite: "SPIT", size: (48, 66), frames: spitter_frames, model: spitter },
];

/// Every sprite name this module paints, with the painter of each.
pub fn sprite_names() -> Vec<String> {
    let mut names = Vec::new();
    for f in FIGURES {
        for Frame(letter, _, turns) in (f.frames)() {
            let l = char::from(letter);
            if turns {
                names.extend((1..=8).map(|v| format!("{}{l}{v}", f.sprite)));
            } else {
                names.push(format!("{}{l}0", f.sprite));
            }
        }
    }
    names.extend(ITEMS.iter().map(|(n, _)| n.to_string()));
    names.extend(effect_names());
    names
}

/// The screen pictures this module paints.
pub const SCREENS: &[&str] = &[
    "PUNGA0", "PUNGB0", "PUNGC0", "PUNGD0", "PISGA0", "PISGB0", "PISGC0", "PISFA0", "SHTGA0", "SHTGB0", "SHTGC0",
    "SHTGD0", "SHTFA0", "SHTFB0",
];

/// The sprite `name`, if this module paints it.
pub fn sprite(name: &str) -> Option<Texture> {
    if let Some((_, paint)) = ITEMS.iter().find(|(n, _)| *n == name) {
        return Some(paint());
    }
    if let Some(t) = effect(name) {
        return Some(t);
    }
    let b = name.as_bytes();
    if b.len() != 6 {
        return None;
    }
    let f = FIGURES.iter().find(|f| f.sprite.as_bytes() == &b[..4])?;
    let (letter, view) = (b[4], b[5].wrapping_sub(b'0'));
    let Frame(_, pose, turns) = (f.frames)().into_iter().find(|fr| fr.0 == letter)?;
    if turns != (1..=8).contains(&view) || (!turns && view != 0) {
        return None;
    }
    let mut parts = (f.model)(&pose);
    fall(&mut parts, &pose, 26.0);
    // A body falling across the view needs more room than one standing.
    let size = if turns { f.size } else { (f.size.0.max(80), f.size.1) };
    Some(render(&parts, &Camera::sprite(view.max(1), size)))
}

/// Tips a figure over onto its left side by its pose's `fall` (seen from
/// the front, as death frames are, it falls across the view), settles it on
/// the floor and pools its blood. `slide` is how far it slides back, in
/// map units, when it lies flat (a figure's half-height, about).
pub(super) fn fall(parts: &mut Vec<Part>, pose: &Pose, slide: f32) {
    let lean = Mat3::from_rotation_y(pose.lean);
    let tip = Mat3::from_rotation_x(-pose.fall * std::f32::consts::FRAC_PI_2 * 0.97);
    // Slid back along the fall, so that the body lies across its place.
    let slide = Vec3::new(0.0, -slide * pose.fall * pose.fall, 0.0);
    for p in parts.iter_mut() {
        *p = p.moved(tip * lean, slide);
    }
    settle(parts);
    if pose.blood > 0.0 {
        let r = 6.0 + 12.0 * pose.blood;
        parts.push(Part::ball(Vec3::new(0.0, 4.0 * pose.fall, 0.0), Vec3::new(r * 0.8, r, 1.2), hex(0x6a0a08)));
    }
}

// Walking: Doom's See states go AABBCCDD, so A and C are opposite strides.
fn walk(letter: u8) -> Pose {
    let stride = match letter {
        b'A' => 1.0,
        b'B' => 0.25,
        b'C' => -1.0,
        _ => -0.25,
    };
    Pose { stride, ..Pose::default() }
}

fn dying(k: f32, last: bool) -> Pose {
    Pose { fall: k, blood: if last { 1.0 } else { (k - 0.5).max(0.0) }, ..Pose::default() }
}

fn sentry_frames() -> Vec<Frame> {
    let mut f: Vec<Frame> = (b'A'..=b'D').map(|l| Frame(l, walk(l), true)).collect();
    f.push(Frame(b'E', Pose { aim: 1.0, ..Pose::default() }, true));
    f.push(Frame(b'F', Pose { aim: 1.0, flash: true, ..Pose::default() }, true));
    f.push(Frame(b'G', Pose { lean: -0.25, open: 1.0, ..Pose::default() }, true));
    for (k, l) in (b'H'..=b'L').enumerate() {
        f.push(Frame(l, dying(0.2 + 0.2 * k as f32, l == b'L'), false));
    }
    f
}

fn stalker_frames() -> Vec<Frame> {
    let mut f: Vec<Frame> = (b'A'..=b'D').map(|l| Frame(l, walk(l), true)).collect();
    f.push(Frame(b'E', Pose { open: 0.5, lean: 0.15, ..Pose::default() }, true));
    f.push(Frame(b'F', Pose { open: 1.0, lean: 0.3, ..Pose::default() }, true));
    f.push(Frame(b'G', Pose { open: 0.1, lean: 0.45, aim: 1.0, ..Pose::default() }, true));
    f.push(Frame(b'H', Pose { open: 0.7, lean: -0.3, ..Pose::default() }, true));
    for (k, l) in (b'I'..=b'N').enumerate() {
        f.push(Frame(l, dying(0.15 + 0.17 * k as f32, l == b'N'), false));
    }
    f
}

fn spitter_frames() -> Vec<Frame> {
    let mut f: Vec<Frame> = (b'A'..=b'D').map(|l| Frame(l, walk(l), true)).collect();
    f.push(Frame(b'E', Pose { open: 1.0, flash: true, ..Pose::default() }, true));
    f.push(Frame(b'F', Pose { open: 0.5, aim: 0.5, flash: true, ..Pose::default() }, true));
    f.push(Frame(b'G', Pose { aim: 1.0, lean: 0.2, ..Pose::default() }, true));
    f.push(Frame(b'H', Pose { lean: -0.3, open: 0.3, ..Pose::default() }, true));
    for (k, l) in (b'I'..=b'M').enumerate() {
        f.push(Frame(l, dying(0.2 + 0.2 * k as f32, l == b'M'), false));
    }
    f
}

/// A pair of legs from hips at height `hip`, `apart` between them, feet
/// striding by `pose.stride` times `step`.
pub(super) fn legs(
    parts: &mut Vec<Part>,
    pose: &Pose,
    hip: f32,
    apart: f32,
    step: f32,
    thick: f32,
    colour: Rgb,
    boot: Rgb,
) {
    for side in [1.0f32, -1.0] {
        let swing = pose.stride * side * step;
        let h = Vec3::new(0.0, side * apart, hip);
        let foot = Vec3::new(swing, side * (apart + 1.0), thick * 0.8);
        // The knee bends forward, more on the leg that swings through.
        let knee = (h + foot) * 0.5 + Vec3::new(2.0 + swing.abs() * 0.15, 0.0, 0.0);
        parts.push(Part::limb(h, knee, thick, colour));
        parts.push(Part::limb(knee, foot, thick * 0.85, colour));
        parts.push(Part::block(
            foot + Vec3::new(2.0, 0.0, -thick * 0.3),
            Vec3::new(4.0, thick * 0.8, thick * 0.5),
            boot,
        ));
    }
}

/// A trooper in slate armour with a glowing visor and a rifle: hitscan.
fn sentry(pose: &Pose) -> Vec<Part> {
    let armour = hex(0x4d6784);
    let suit = hex(0x2c3138);
    let steel = hex(0x33373c);
    let mut p = Vec::new();
    legs(&mut p, pose, 27.0, 4.5, 9.0, 3.2, suit, hex(0x1e1c1a));
    // Hips, chest plate and shoulder pads.
    p.push(Part::ball(Vec3::new(0.0, 0.0, 28.0), Vec3::new(5.0, 7.5, 4.0), suit));
    p.push(Part::ball(Vec3::new(0.5, 0.0, 38.0), Vec3::new(6.5, 9.0, 9.5), armour).shiny(0.35));
    for side in [1.0f32, -1.0] {
        p.push(Part::ball(Vec3::new(0.0, side * 9.5, 44.0), Vec3::new(4.5, 4.0, 3.0), armour).shiny(0.35));
    }
    // Helmet and visor.
    p.push(Part::sphere(Vec3::new(0.0, 0.0, 52.0), 5.2, armour).shiny(0.4));
    p.push(Part::block(Vec3::new(4.2, 0.0, 52.5), Vec3::new(1.4, 3.2, 1.3), hex(0xffa43a)).glowing());
    // Arms to the rifle: held across the body, raised to the shoulder to aim.
    let (grip, fore) = if pose.aim > 0.0 {
        (Vec3::new(6.0, -4.0, 41.0), Vec3::new(14.0, -2.0, 42.0))
    } else {
        (Vec3::new(6.0, -4.0, 32.0), Vec3::new(12.0, 2.0, 35.0))
    };
    let flinch = pose.open;
    for (side, hand) in [(-1.0f32, grip), (1.0, fore)] {
        let shoulder = Vec3::new(0.0, side * 9.5, 42.0);
        let hand = hand + Vec3::new(-6.0 * flinch, side * 6.0 * flinch, 4.0 * flinch);
        let elbow = (shoulder + hand) * 0.5 + Vec3::new(-2.0, side * 3.0, -4.0);
        p.push(Part::limb(shoulder, elbow, 2.6, suit));
        p.push(Part::limb(elbow, hand, 2.4, suit));
        p.push(Part::sphere(hand, 2.4, hex(0x2a2622)));
    }
    // The rifle: a stock, a body and a barrel along the line of the hands.
    let dir = (fore - grip).normalize();
    let rifle_at = grip + dir * 4.0 + Vec3::new(-6.0 * flinch, 0.0, 4.0 * flinch);
    let turn = Mat3::from_cols(dir, Vec3::Z.cross(dir).normalize(), dir.cross(Vec3::Z.cross(dir).normalize()));
    p.push(Part::block(rifle_at, Vec3::new(9.0, 1.4, 2.2), steel).turned(turn).shiny(0.6));
    p.push(Part::limb(rifle_at + dir * 8.0, rifle_at + dir * 17.0, 0.9, steel).shiny(0.6));
    if pose.flash {
        p.push(Part::sphere(rifle_at + dir * 19.5, 3.2, hex(0xfff0a0)).glowing());
    }
    p
}

/// A hulking horned brute that charges and bites.
fn stalker(pose: &Pose) -> Vec<Part> {
    let hide = hex(0x9c3b2b);
    let belly = hex(0xc98a62);
    let bone = hex(0xded2b4);
    let mut p = Vec::new();
    legs(&mut p, pose, 22.0, 9.0, 8.0, 5.0, hide, hex(0x40221a));
    // A deep chest leaning forward over the hips, a paler belly.
    p.push(Part::ball(Vec3::new(1.0, 0.0, 32.0), Vec3::new(13.0, 16.0, 14.0), hide));
    p.push(Part::ball(Vec3::new(7.5, 0.0, 28.0), Vec3::new(7.0, 11.0, 9.5), belly));
    // The head thrust forward, horns sweeping back, a jaw that drops open.
    let head = Vec3::new(14.0, 0.0, 40.0);
    p.push(Part::ball(head, Vec3::new(7.0, 7.5, 6.0), hide));
    for side in [1.0f32, -1.0] {
        p.push(Part::limb(
            head + Vec3::new(-1.0, side * 5.0, 3.5),
            head + Vec3::new(-8.0, side * 12.0, 14.0),
            1.6,
            bone,
        ));
        p.push(Part::sphere(head + Vec3::new(5.2, side * 3.0, 2.0), 1.4, hex(0xffe040)).glowing());
    }
    let gape = 0.7 * pose.open;
    let jaw = Part::ball(Vec3::new(6.5, 0.0, -1.5), Vec3::new(6.5, 6.0, 2.4), hide);
    let jaw = jaw.moved(Mat3::from_rotation_y(gape), head + Vec3::new(-2.0, 0.0, -1.0));
    p.push(jaw);
    if pose.open > 0.05 {
        // The mouth's dark inside and a row of teeth.
        p.push(Part::ball(head + Vec3::new(5.0, 0.0, -2.0), Vec3::new(4.0, 4.5, 2.5 * pose.open), hex(0x3a0806)));
        for k in [-3.0f32, -1.0, 1.0, 3.0] {
            p.push(Part::limb(head + Vec3::new(6.6, k, -0.4), head + Vec3::new(6.6, k, -2.2), 0.6, bone));
        }
    }
    // Arms hanging to the knuckles, swung forward to strike.
    for side in [1.0f32, -1.0] {
        let shoulder = Vec3::new(4.0, side * 15.0, 38.0);
        let reach = if pose.aim > 0.0 { 16.0 } else { 6.0 - pose.stride * side * 4.0 };
        let hand = Vec3::new(reach, side * 17.0, if pose.aim > 0.0 { 26.0 } else { 12.0 });
        let elbow = (shoulder + hand) * 0.5 + Vec3::new(-3.0, side * 3.0, 0.0);
        p.push(Part::limb(shoulder, elbow, 4.2, hide));
        p.push(Part::limb(elbow, hand, 3.6, hide));
        for k in [-1.5f32, 0.0, 1.5] {
            p.push(Part::limb(hand, hand + Vec3::new(3.0, k * 1.2, -3.0), 0.9, bone));
        }
    }
    p
}

/// A lean, spined creature that throws glowing bolts.
fn spitter(pose: &Pose) -> Vec<Part> {
    let skin = hex(0x5c6b3c);
    let dark = hex(0x3b4526);
    let bone = hex(0xd8d0a8);
    let glow = hex(0xc8ff50);
    let mut p = Vec::new();
    legs(&mut p, pose, 25.0, 4.0, 8.0, 2.6, skin, dark);
    p.push(Part::ball(Vec3::new(0.0, 0.0, 27.0), Vec3::new(4.0, 6.0, 4.0), dark));
    // A hunched torso, ribbed, with spines down the back.
    p.push(Part::ball(Vec3::new(1.0, 0.0, 37.0), Vec3::new(5.5, 8.0, 10.0), skin));
    for k in 0..4 {
        let z = 34.0 + 4.0 * k as f32;
        p.push(Part::limb(Vec3::new(-4.0, 0.0, z), Vec3::new(-9.0, 0.0, z + 3.0), 1.1, bone));
    }
    for side in [1.0f32, -1.0] {
        p.push(Part::limb(Vec3::new(-1.0, side * 7.0, 45.0), Vec3::new(-4.0, side * 12.0, 51.0), 1.2, bone));
    }
    let head = Vec3::new(3.0, 0.0, 50.5);
    p.push(Part::ball(head, Vec3::new(5.0, 4.5, 4.5), skin));
    for side in [1.0f32, -1.0] {
        p.push(Part::sphere(head + Vec3::new(4.0, side * 2.0, 0.8), 1.2, hex(0xffe640)).glowing());
    }
    // The throwing arm (its right) draws back (`open`) and hurls forward (`aim`).
    for side in [1.0f32, -1.0] {
        let shoulder = Vec3::new(0.0, side * 8.0, 44.0);
        let throwing = side < 0.0;
        let hand = if throwing && pose.open > 0.0 {
            Vec3::new(-8.0 * pose.open + 4.0 * pose.aim, -12.0, 50.0 + 4.0 * pose.open)
        } else if throwing && pose.aim > 0.0 {
            Vec3::new(17.0, -5.0, 40.0)
        } else {
            Vec3::new(6.0 - 3.0 * pose.stride * side, side * 10.0, 28.0)
        };
        let elbow = (shoulder + hand) * 0.5 + Vec3::new(-2.0, side * 3.0, -2.0);
        p.push(Part::limb(shoulder, elbow, 1.9, skin));
        p.push(Part::limb(elbow, hand, 1.7, skin));
        for k in [-1.0f32, 1.0] {
            p.push(Part::limb(hand, hand + Vec3::new(2.5, k, -2.0), 0.6, bone));
        }
        if throwing && pose.flash {
            p.push(Part::sphere(hand + Vec3::new(0.0, 0.0, 3.0), 3.5, glow).glowing());
        }
    }
    p
}

/// An item lying on the floor, seen from the front and a little above.
fn item(parts: &[Part], size: (usize, usize)) -> Texture {
    let mut parts = parts.to_vec();
    settle(&mut parts);
    render(&parts, &Camera { above: 20.0, ..Camera::sprite(1, size) })
}

/// The boss brain: a great brain on a stalk, its folds in darker ridges;
/// in pain (`hurt`) it flushes red.
fn boss_brain(hurt: bool) -> Texture {
    let (flesh, fold) = if hurt { (hex(0xd05050), hex(0x902828)) } else { (hex(0xd88c8c), hex(0x9a5656)) };
    let mut p = vec![
        Part::limb(Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 16.0), 4.0, hex(0x6a3a3a)),
        Part::ball(Vec3::new(0.0, 0.0, 30.0), Vec3::new(12.0, 18.0, 13.0), flesh).shiny(0.3),
    ];
    for k in 0..5 {
        let y = -12.0 + 6.0 * k as f32;
        p.push(Part::limb(Vec3::new(10.0, y, 20.0), Vec3::new(9.0, y * 0.8, 41.0), 1.2, fold));
    }
    p.push(Part::limb(Vec3::new(11.0, -15.0, 31.0), Vec3::new(11.0, 15.0, 31.0), 1.2, fold));
    item(&p, (48, 48))
}

fn cross(parts: &mut Vec<Part>, top: f32, front: f32, s: f32) {
    let red = hex(0xd01818);
    parts.push(Part::block(Vec3::new(front, 0.0, top), Vec3::new(0.4, s, s * 0.3), red));
    parts.push(Part::block(Vec3::new(front, 0.0, top), Vec3::new(0.4, s * 0.3, s), red));
}

const ITEMS: &[(&str, fn() -> Texture)] = &[
    ("CLIPA0", || {
        let body = Part::block(Vec3::new(0.0, 0.0, 5.0), Vec3::new(1.8, 3.0, 5.0), hex(0x2e3034)).shiny(0.5);
        let tip = Part::limb(Vec3::new(0.0, -2.0, 10.5), Vec3::new(0.0, 2.0, 10.5), 0.9, hex(0xd0a040)).shiny(0.8);
        item(&[body.turned(Mat3::from_rotation_x(0.25)), tip], (14, 16))
    }),
    ("SHELA0", || {
        let mut p = Vec::new();
        for k in 0..4 {
            let y = -4.5 + 3.0 * k as f32;
            p.push(Part::limb(Vec3::new(0.0, y, 1.5), Vec3::new(0.0, y, 7.5), 1.3, hex(0xb81c1c)));
            p.push(Part::limb(Vec3::new(0.0, y, 0.8), Vec3::new(0.0, y, 2.2), 1.45, hex(0xd8b048)).shiny(0.8));
        }
        item(&p, (18, 14))
    }),
    ("STIMA0", || {
        let mut p = vec![Part::block(Vec3::new(0.0, 0.0, 3.5), Vec3::new(4.0, 6.0, 3.5), hex(0xe8e8e4))];
        cross(&mut p, 3.8, 4.1, 2.4);
        item(&p, (18, 14))
    }),
    ("MEDIA0", || {
        let mut p = vec![Part::block(Vec3::new(0.0, 0.0, 5.5), Vec3::new(6.0, 11.0, 5.5), hex(0xeeeeea))];
        p.push(Part::limb(Vec3::new(0.0, -3.0, 11.5), Vec3::new(0.0, 3.0, 11.5), 0.9, hex(0x505050)));
        cross(&mut p, 6.0, 6.1, 4.0);
        item(&p, (28, 20))
    }),
    ("LAUNA0", || {
        // The rocket launcher, lying on its side: a long tube, a sight on
        // top, a grip below, the muzzle's rim.
        let (olive, dark) = (hex(0x5a6a48), hex(0x2c3028));
        let p = [
            Part::limb(Vec3::new(0.0, -13.0, 3.5), Vec3::new(0.0, 13.0, 3.5), 3.2, olive).shiny(0.4),
            Part::limb(Vec3::new(0.0, 12.5, 3.5), Vec3::new(0.0, 13.5, 3.5), 3.6, dark),
            Part::block(Vec3::new(0.0, -2.0, 7.5), Vec3::new(1.0, 3.0, 1.2), dark),
            Part::block(Vec3::new(1.5, -5.0, 1.0), Vec3::new(1.2, 1.5, 1.0), dark),
        ];
        item(&p, (32, 14))
    }),
    ("BROKA0", || {
        // A box of rockets: a crate with five warheads showing.
        let mut p = vec![Part::block(Vec3::new(0.0, 0.0, 4.0), Vec3::new(4.5, 9.0, 4.0), hex(0x6a5030))];
        for k in 0..5 {
            let y = -7.2 + 3.6 * k as f32;
            p.push(Part::limb(Vec3::new(0.0, y, 8.0), Vec3::new(0.0, y, 10.5), 1.4, hex(0x707468)).shiny(0.5));
            p.push(Part::limb(Vec3::new(0.0, y, 10.5), Vec3::new(0.0, y, 12.0), 1.0, hex(0xb02020)));
        }
        item(&p, (22, 16))
    }),
    ("BBRNA0", || boss_brain(false)),
    ("BBRNB0", || boss_brain(true)),
    ("SUITA0", || {
        // The radiation suit, hung up empty: boots, legs, body, arms, a
        // hood with a dark visor.
        let (green, dark) = (hex(0x4a9a3a), hex(0x2e6a26));
        let mut p = vec![Part::block(Vec3::new(0.0, 0.0, 30.0), Vec3::new(3.5, 7.0, 9.0), green)];
        for side in [-1.0, 1.0] {
            p.push(Part::limb(Vec3::new(0.0, 3.5 * side, 2.0), Vec3::new(0.0, 3.5 * side, 21.0), 2.6, green));
            p.push(Part::block(Vec3::new(1.0, 3.5 * side, 1.5), Vec3::new(3.5, 2.8, 1.5), hex(0x303030)));
            p.push(Part::limb(Vec3::new(0.0, 8.5 * side, 37.0), Vec3::new(0.5, 9.5 * side, 22.0), 2.0, green));
        }
        p.push(Part::limb(Vec3::new(0.0, 0.0, 42.0), Vec3::new(0.0, 0.0, 44.0), 4.2, dark));
        p.push(Part::block(Vec3::new(3.6, 0.0, 43.0), Vec3::new(0.5, 2.6, 1.6), hex(0x1c2024)).shiny(0.9));
        item(&p, (26, 50))
    }),
    ("BON1A0", || bonus_flask(0.0)),
    ("BON1B0", || bonus_flask(0.33)),
    ("BON1C0", || bonus_flask(0.66)),
    ("BON1D0", || bonus_flask(1.0)),
    ("BON2A0", || bonus_helmet(0.0)),
    ("BON2B0", || bonus_helmet(0.33)),
    ("BON2C0", || bonus_helmet(0.66)),
    ("BON2D0", || bonus_helmet(1.0)),
    ("ARM1A0", || vest(false)),
    ("ARM1B0", || vest(true)),
    ("SHOTA0", || {
        let gun = shotgun_parts(0.0);
        let lying: Vec<Part> =
            gun.iter().map(|p| p.moved(Mat3::from_rotation_z(std::f32::consts::FRAC_PI_2), Vec3::ZERO)).collect();
        item(&lying, (44, 14))
    }),
    ("BKEYB0", || {
        // The card's bright frame: the card with its stripe lit.
        let mut t = super::machinery::card("BKEYA0");
        for p in t.texels.iter_mut().filter(|p| **p >> 24 == 255) {
            let [r, g, b, a] = p.to_le_bytes();
            if b > r + 40 {
                *p = u32::from_le_bytes([r.saturating_add(60), g.saturating_add(90), 255, a]);
            }
        }
        t
    }),
    ("BAR1B0", || super::sprites::barrel(super::paint::seed_of("BARREL") ^ 1)),
];

fn bonus_flask(k: f32) -> Texture {
    let glass = mix(hex(0x2050d0), hex(0x80b0ff), k);
    let p = [
        Part::sphere(Vec3::new(0.0, 0.0, 4.5), 4.5, glass).shiny(0.9),
        Part::limb(Vec3::new(0.0, 0.0, 8.0), Vec3::new(0.0, 0.0, 11.0), 1.5, glass).shiny(0.9),
        Part::limb(Vec3::new(0.0, 0.0, 11.0), Vec3::new(0.0, 0.0, 12.5), 1.8, hex(0xc0c0c0)),
    ];
    item(&p, (14, 16))
}

fn bonus_helmet(k: f32) -> Texture {
    let green = mix(hex(0x2e7a2a), hex(0x70d060), k);
    let p = [
        Part::ball(Vec3::new(0.0, 0.0, 4.0), Vec3::new(6.0, 5.5, 4.5), green).shiny(0.7),
        Part::block(Vec3::new(4.5, 0.0, 3.0), Vec3::new(1.0, 4.0, 1.0), hex(0x202820)),
    ];
    item(&p, (18, 14))
}

fn vest(bright: bool) -> Texture {
    let green = if bright { hex(0x58c048) } else { hex(0x3a8a32) };
    let p = [
        Part::block(Vec3::new(0.0, 0.0, 2.5), Vec3::new(10.0, 13.0, 2.5), green).shiny(0.4),
        Part::block(Vec3::new(0.0, 0.0, 5.5), Vec3::new(4.0, 13.5, 1.0), scale(green, 0.7)),
        Part::ball(Vec3::new(-7.0, 9.0, 4.0), Vec3::new(4.0, 4.0, 2.5), green).shiny(0.4),
        Part::ball(Vec3::new(-7.0, -9.0, 4.0), Vec3::new(4.0, 4.0, 2.5), green).shiny(0.4),
    ];
    item(&p, (34, 16))
}

/// The shotgun's parts along +x, the grip at the origin; `pump` 0 to 1
/// slides the fore-end back.
fn shotgun_parts(pump: f32) -> Vec<Part> {
    let steel = hex(0x3a3d42);
    let wood = hex(0x7a4a24);
    vec![
        Part::block(Vec3::new(-4.0, 0.0, -1.0), Vec3::new(3.0, 2.0, 2.6), wood),
        Part::block(Vec3::new(3.0, 0.0, 0.5), Vec3::new(5.0, 2.2, 2.4), steel).shiny(0.6),
        Part::limb(Vec3::new(7.0, 0.0, 1.6), Vec3::new(30.0, 0.0, 1.6), 1.2, steel).shiny(0.7),
        Part::limb(Vec3::new(7.0, 0.0, -0.8), Vec3::new(27.0, 0.0, -0.8), 1.1, steel).shiny(0.5),
        Part::block(Vec3::new(18.0 - 6.0 * pump, 0.0, -0.8), Vec3::new(4.5, 1.9, 1.9), wood),
    ]
}

/// A first-person picture in perspective: the eye behind and above the
/// weapon's grip (the model's origin), which is drawn at `at` on the
/// 320x200 screen; the weapon points up the middle of the screen.
fn on_screen(parts: &[Part], zoom: f32, at: (f32, f32)) -> Texture {
    let camera = Camera {
        around: 180.0,
        above: 32.0,
        size: (320, 200),
        zoom,
        origin: Vec3::ZERO,
        outline: Some([0.03, 0.03, 0.03]),
        eye: Some(22.0),
    };
    super::models::render_at(parts, &camera, at)
}

/// A gloved hand round a grip at `grip`, its forearm coming from below
/// the screen on side `side` (positive: the left).
fn hand(parts: &mut Vec<Part>, grip: Vec3, side: f32) {
    let glove = hex(0x4a3222);
    let sleeve = hex(0x3c4a2c);
    parts.push(Part::ball(grip, Vec3::new(2.2, 2.6, 2.4), glove));
    parts.push(Part::limb(grip + Vec3::new(-1.5, 0.0, -1.0), grip + Vec3::new(-14.0, side * 5.0, -12.0), 2.6, sleeve));
}

/// The pistol kicked up by `kick` radians; with `flash`, only its flash.
fn pistol_frame(kick: f32, flash: Option<f32>) -> Vec<Part> {
    let steel = hex(0x4a4e55);
    let mut p = match flash {
        Some(r) => muzzle_flash(Vec3::new(14.0, 0.0, 3.2), r),
        None => vec![
            Part::block(Vec3::new(4.5, 0.0, 3.0), Vec3::new(8.0, 1.3, 1.5), steel).shiny(0.7),
            Part::block(Vec3::new(0.0, 0.0, -0.5), Vec3::new(1.8, 1.2, 3.2), hex(0x2a2a2c)),
            Part::block(Vec3::new(11.5, 0.0, 4.8), Vec3::new(0.5, 0.35, 0.5), hex(0x101010)),
        ],
    };
    if flash.is_none() {
        hand(&mut p, Vec3::new(-0.5, 0.0, -1.5), -0.4);
    }
    // Turned a little to the left, so its right side shows.
    let tilt = Mat3::from_rotation_z(0.2) * Mat3::from_rotation_y(-kick);
    p.iter().map(|q| q.moved(tilt, Vec3::new(-6.0 * kick, 0.0, 0.0))).collect()
}

fn muzzle_flash(at: Vec3, r: f32) -> Vec<Part> {
    vec![
        Part::sphere(at + Vec3::new(r * 0.6, 0.0, 0.0), r, hex(0xffa028)).glowing(),
        Part::ball(at + Vec3::new(r * 0.3, 0.0, 0.0), Vec3::new(r * 0.5, r * 1.6, r * 0.5), hex(0xffd060)).glowing(),
        Part::sphere(at, r * 0.55, hex(0xfff8d8)).glowing(),
    ]
}

/// The shotgun with its fore-end pumped back by `pump` and tipped up by
/// `lift` radians; with `flash`, only its flash.
fn shotgun_frame(pump: f32, lift: f32, flash: Option<f32>) -> Vec<Part> {
    let p = match flash {
        Some(r) => muzzle_flash(Vec3::new(31.5, 0.0, 0.5), r),
        None => {
            let mut p = shotgun_parts(pump);
            hand(&mut p, Vec3::new(-4.0, 0.0, -3.0), -0.4);
            hand(&mut p, Vec3::new(18.0 - 6.0 * pump, 0.0, -2.8), 0.5);
            p
        }
    };
    let tilt = Mat3::from_rotation_z(0.15) * Mat3::from_rotation_y(-lift);
    p.iter().map(|q| q.moved(tilt, Vec3::ZERO)).collect()
}

/// The fist drawn back (`k` 0) or punched out (`k` 1).
fn fist_frame(k: f32) -> Vec<Part> {
    let glove = hex(0x6a4630);
    let mut p = vec![Part::ball(Vec3::ZERO, Vec3::new(4.0, 4.5, 3.6), glove)];
    for j in [-3.0f32, -1.0, 1.0, 3.0] {
        p.push(Part::sphere(Vec3::new(3.2, j * 1.1, 1.2), 1.3, scale(glove, 1.1)));
    }
    p.push(Part::limb(Vec3::new(-2.0, 0.0, -1.0), Vec3::new(-22.0, -4.0, -16.0), 3.4, hex(0x3c4a2c)));
    p.iter().map(|q| q.moved(Mat3::IDENTITY, Vec3::new(10.0 * k, 4.0 * k, 3.0 * k))).collect()
}

/// The screen picture `name`, if this module paints it.
pub fn screen(name: &str) -> Option<Texture> {
    const PISTOL: (f32, (f32, f32)) = (6.0, (166.0, 192.0));
    const SHOTGUN: (f32, (f32, f32)) = (5.8, (166.0, 200.0));
    let gun = |parts: Vec<Part>, (zoom, at): (f32, (f32, f32))| on_screen(&parts, zoom, at);
    Some(match name {
        "PUNGA0" => on_screen(&fist_frame(0.0), 8.0, (220.0, 200.0)),
        "PUNGB0" => on_screen(&fist_frame(0.35), 8.0, (208.0, 196.0)),
        "PUNGC0" => on_screen(&fist_frame(0.75), 8.0, (190.0, 190.0)),
        "PUNGD0" => on_screen(&fist_frame(1.0), 8.0, (180.0, 186.0)),
        "PISGA0" => gun(pistol_frame(0.0, None), PISTOL),
        "PISGB0" => gun(pistol_frame(0.3, None), PISTOL),
        "PISGC0" => gun(pistol_frame(0.15, None), PISTOL),
        "PISFA0" => gun(pistol_frame(0.3, Some(3.0)), PISTOL),
        "SHTGA0" => gun(shotgun_frame(0.0, 0.0, None), SHOTGUN),
        "SHTGB0" => gun(shotgun_frame(0.0, 0.25, None), SHOTGUN),
        "SHTGC0" => gun(shotgun_frame(0.6, 0.1, None), SHOTGUN),
        "SHTGD0" => gun(shotgun_frame(1.0, 0.05, None), SHOTGUN),
        "SHTFA0" => gun(shotgun_frame(0.0, 0.25, Some(3.5)), SHOTGUN),
        "SHTFB0" => gun(shotgun_frame(0.0, 0.25, Some(5.0)), SHOTGUN),
        _ => return None,
    })
}

/// Effects: puffs, blood, fogs, the bolt, the barrel's blast. Each a cloud
/// of balls that grows and fades by frame, drawn alike from every side.
struct Effect {
    sprite: &'static str,
    frames: &'static str,
    size: (usize, usize),
    colours: (u32, u32),
    glow: bool,
    /// Balls, their spread and their size at the first frame and the last.
    balls: usize,
    spread: (f32, f32),
    radius: (f32, f32),
    /// Height of the cloud's centre above the origin.
    centre: f32,
}

const EFFECTS: &[Effect] = &[
    Effect {
        sprite: "PUFF",
        frames: "ABCD",
        size: (16, 18),
        colours: (0xfff0c0, 0x8a8a88),
        glow: false,
        balls: 5,
        spread: (1.0, 4.0),
        radius: (2.0, 3.0),
        centre: 8.0,
    },
    Effect {
        sprite: "BLUD",
        frames: "ABC",
        size: (14, 14),
        colours: (0xa01010, 0x6a0606),
        glow: false,
        balls: 4,
        spread: (1.0, 3.5),
        radius: (1.2, 2.2),
        centre: 7.0,
    },
    Effect {
        sprite: "TFOG",
        frames: "ABCDEFGHIJ",
        size: (44, 64),
        colours: (0xd8ffe0, 0x2a8a50),
        glow: true,
        balls: 9,
        spread: (4.0, 16.0),
        radius: (5.0, 1.5),
        centre: 28.0,
    },
    Effect {
        sprite: "IFOG",
        frames: "ABCDE",
        size: (30, 36),
        colours: (0xe0f0ff, 0x3a60b0),
        glow: true,
        balls: 7,
        spread: (3.0, 10.0),
        radius: (4.0, 1.5),
        centre: 14.0,
    },
    Effect {
        sprite: "SBLT",
        frames: "ABCDE",
        size: (30, 30),
        colours: (0xf0ffa0, 0x5a9a10),
        glow: true,
        balls: 6,
        spread: (0.0, 9.0),
        radius: (4.5, 2.0),
        centre: 8.0,
    },
    Effect {
        sprite: "BEXP",
        frames: "ABCDE",
        size: (52, 52),
        colours: (0xfff0a0, 0x902808),
        glow: true,
        balls: 9,
        spread: (2.0, 16.0),
        radius: (6.0, 3.0),
        centre: 22.0,
    },
];

fn effect_names() -> Vec<String> {
    EFFECTS.iter().flat_map(|e| e.frames.chars().map(move |f| format!("{}{f}0", e.sprite))).collect()
}

fn effect(name: &str) -> Option<Texture> {
    let b = name.as_bytes();
    if b.len() != 6 || b[5] != b'0' {
        return None;
    }
    let e = EFFECTS.iter().find(|e| e.sprite.as_bytes() == &b[..4])?;
    let k = e.frames.bytes().position(|f| f == b[4])?;
    // The bolt flies in its first two frames, then bursts.
    let t =
        if e.sprite == "SBLT" { [0.0, 0.05, 0.35, 0.7, 1.0][k] } else { k as f32 / (e.frames.len() - 1).max(1) as f32 };
    let spread = e.spread.0 + (e.spread.1 - e.spread.0) * t;
    let radius = e.radius.0 + (e.radius.1 - e.radius.0) * t;
    let colour = mix(hex(e.colours.0), hex(e.colours.1), t);
    let mut parts = vec![Part::sphere(Vec3::new(0.0, 0.0, e.centre), radius * 1.2, colour)];
    for j in 0..e.balls {
        // Fixed directions round a sphere (a golden-angle spiral).
        let a = j as f32 * 2.399_963 + k as f32 * 0.3;
        let z = 1.0 - 2.0 * (j as f32 + 0.5) / e.balls as f32;
        let r = (1.0 - z * z).sqrt();
        let dir = Vec3::new(r * a.cos(), r * a.sin(), z);
        parts.push(Part::sphere(dir * spread + Vec3::new(0.0, 0.0, e.centre), radius, colour));
    }
    if e.glow {
        parts = parts.into_iter().map(Part::glowing).collect();
        // A white-hot core while it burns.
        if t < 0.6 {
            parts.push(Part::sphere(Vec3::new(2.0, 0.0, e.centre), radius * 0.7, hex(0xffffff)).glowing());
        }
    }
    let outline = if e.glow { None } else { Some([0.05, 0.05, 0.05]) };
    Some(render(&parts, &Camera { outline, ..Camera::sprite(1, e.size) }))
}
