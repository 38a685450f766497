//! The built-in textures, painted in code so the shipped maps look finished with
//! no art files: walls, flats, a panoramic sky and sprites, each a pure
//! function of its name. [`super::TextureSet::resolve`] falls back to these
//! when no PNG of that name exists.
//!
//! Sizes are deliberately not all powers of two (STONE is 96x128, DIRT 80x80,
//! ODD 37x23), so the renderer's wrapping is exercised by the shipped maps and
//! not only by tests.

mod figures;
mod flats;
mod machinery;
mod models;
mod paint;
mod sky;
mod special;
mod sprites;
pub mod standins;
mod walls;

use std::collections::BTreeMap;

pub use figures::Pose;

use super::{Texture, TextureKind};

/// Wall textures. DEBUG1 (1x1), THIN (1x64) and ODD (37x23) exist for the
/// renderer's hard cases: a texture with one texel, one column, and sides that
/// are prime.
/// SWITCH1 and SWITCH2 (a switch off and on), EXITSW1 and EXITSW2 (an exit
/// switch) are paired in `engine/data/animations.ron`; CHEVRON is made to
/// scroll.
const WALLS: &[&str] = &[
    "BRICK", "STONE", "WOOD", "METAL", "STEP", "DOOR", "GRATE", "FENCE", "SUPPORT", "SKY", "DEBUG1", "THIN", "ODD",
    "SWITCH1", "SWITCH2", "EXITSW1", "EXITSW2", "CHEVRON",
];

/// Floor and ceiling textures. The sky is both a wall and a flat: a sector
/// ceiling named SKY shows the panorama.
/// GOO1 to GOO3 are the frames of an animation (`engine/data/animations.ron`).
const FLATS: &[&str] = &["FLOOR", "TILE", "GRASS", "WATER", "CEIL", "DIRT", "SKY", "GOO1", "GOO2", "GOO3", "TELEPAD"];

/// The keys and the barrel also answer to Doom's sprite names (BKEYA0 is a
/// blue keycard's front view), so a version-2 map's `blue_card` or `barrel`
/// finds a picture with no art files; a WAD's or a PNG's comes first.
const SPRITES: &[&str] = &[
    "BARREL", "LAMP", "COLUMN", "PLANT", "TORCH", "CRATE", "STATUE", "BKEYA0", "YKEYA0", "RKEYA0", "BSKUA0", "YSKUA0",
    "RSKUA0", "BAR1A0", "COLUA0",
];

/// The built-in weapons on the screen: the fist's, pistol's and shotgun's
/// frames and flashes (`figures::screen`).
const SCREENS: &[&str] = figures::SCREENS;

/// The trooper's frames (`sprites::trooper`): the zombieman's sprite
/// names, A-G from eight directions and H-U from all sides alike.
fn trooper_names() -> &'static [&'static str] {
    static NAMES: std::sync::OnceLock<Vec<&'static str>> = std::sync::OnceLock::new();
    NAMES.get_or_init(|| {
        let standing = (b'A'..=b'G').flat_map(|f| (1..=8).map(move |v| format!("POSS{}{v}", char::from(f))));
        let down = (b'H'..=b'U').map(|f| format!("POSS{}0", char::from(f)));
        // Made once for the life of the program, like the other names.
        standing.chain(down).map(|n| &*Box::leak(n.into_boxed_str())).collect()
    })
}

/// The roster's, the items' and the effects' frames, modelled in 3D
/// (`figures`).
pub(super) fn figure_names() -> &'static [&'static str] {
    static NAMES: std::sync::OnceLock<Vec<&'static str>> = std::sync::OnceLock::new();
    NAMES.get_or_init(|| figures::sprite_names().into_iter().map(|n| &*Box::leak(n.into_boxed_str())).collect())
}

/// Names of the built-in textures of each kind, upper case.
pub fn names(kind: TextureKind) -> &'static [&'static str] {
    match kind {
        TextureKind::Wall => WALLS,
        TextureKind::Flat => FLATS,
        TextureKind::Sprite => SPRITES,
        TextureKind::Screen => SCREENS,
    }
}

/// Every built-in name of `kind`: the listed ones, and for sprites the
/// trooper's frames and the modelled figures'.
fn all_names(kind: TextureKind) -> impl Iterator<Item = &'static str> {
    let (trooper, figures) =
        if kind == TextureKind::Sprite { (trooper_names(), figure_names()) } else { (&[][..], &[][..]) };
    names(kind).iter().chain(trooper).chain(figures).copied()
}

/// The listed spelling of built-in `name` (any case) of `kind`, if there is one.
pub fn canonical(name: &str, kind: TextureKind) -> Option<&'static str> {
    all_names(kind).find(|n| n.eq_ignore_ascii_case(name))
}

/// The built-in texture `name` (any case) of `kind`, or `None` when there is
/// none of that kind: a flat name does not resolve as a wall, as in Doom.
pub fn generate(name: &str, kind: TextureKind) -> Option<Texture> {
    let name = canonical(name, kind)?;
    // Made once per process: the figures take a while to draw, and a level
    // opened again (a saved game loaded, a map restarted) asks for the same.
    static MADE: std::sync::Mutex<BTreeMap<(&'static str, TextureKind), Texture>> =
        std::sync::Mutex::new(BTreeMap::new());
    let key = (name, kind);
    if let Some(made) = MADE.lock().ok().and_then(|m| m.get(&key).cloned()) {
        return Some(made);
    }
    let made = draw(name, kind)?;
    if let Ok(mut m) = MADE.lock() {
        m.insert(key, made.clone());
    }
    Some(made)
}

/// Draws the texture `name` (canonical) of `kind`.
fn draw(name: &'static str, kind: TextureKind) -> Option<Texture> {
    match kind {
        TextureKind::Screen => return figures::screen(name),
        TextureKind::Sprite if !names(kind).contains(&name) => {
            return figures::sprite(name).or_else(|| sprites::trooper(name))
        }
        _ => {}
    }
    let seed = paint::seed_of(name);
    Some(match name {
        "BRICK" => walls::brick(seed),
        "STONE" => walls::stone(seed),
        "WOOD" => walls::wood(seed),
        "METAL" => walls::metal(seed),
        "STEP" => walls::step(seed),
        "DOOR" => walls::door(seed),
        "GRATE" => special::grate(seed),
        "FENCE" => special::fence(seed),
        "SUPPORT" => walls::support(seed),
        "DEBUG1" => special::debug1(),
        "THIN" => special::thin(),
        "ODD" => special::odd(),
        "SKY" => sky::sky(seed),
        "FLOOR" => flats::floor(seed),
        "TILE" => flats::tile(seed),
        "GRASS" => flats::grass(seed),
        "WATER" => flats::water(seed),
        "CEIL" => flats::ceil(seed),
        "DIRT" => flats::dirt(seed),
        "BARREL" => sprites::barrel(seed),
        "LAMP" => sprites::lamp(seed),
        "COLUMN" => sprites::column(seed),
        "PLANT" => sprites::plant(seed),
        "TORCH" => sprites::torch(seed),
        "CRATE" => sprites::crate_(seed),
        "STATUE" => sprites::statue(seed),
        "SWITCH1" | "SWITCH2" => machinery::switch(seed, name == "SWITCH2"),
        "EXITSW1" | "EXITSW2" => machinery::exit(seed, name == "EXITSW2"),
        "CHEVRON" => machinery::chevron(seed),
        // One seed for the three frames: the same slime, flowing.
        "GOO1" | "GOO2" | "GOO3" => machinery::goo(paint::seed_of("GOO"), u32::from(name.as_bytes()[3] - b'1')),
        "TELEPAD" => machinery::telepad(seed),
        "BKEYA0" | "YKEYA0" | "RKEYA0" => machinery::card(name),
        "BSKUA0" | "YSKUA0" | "RSKUA0" => machinery::skull(name),
        "BAR1A0" => sprites::barrel(paint::seed_of("BARREL")),
        "COLUA0" => sprites::lamp(paint::seed_of("LAMP")),
        other => unreachable!("{other} is listed but has no painter"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const KINDS: [TextureKind; 3] = [TextureKind::Wall, TextureKind::Flat, TextureKind::Sprite];

    fn alpha(t: &Texture, u: usize, v: usize) -> u8 {
        t.texel(u, v).to_le_bytes()[3]
    }

    #[test]
    fn every_name_generates_with_its_stated_opacity() {
        for kind in KINDS {
            for name in all_names(kind) {
                let t = generate(name, kind).unwrap_or_else(|| panic!("{name} {kind:?}"));
                assert!(t.width >= 1 && t.height >= 1);
                assert_eq!(t.texels.len(), t.width * t.height, "{name}");
                let masked = kind == TextureKind::Sprite || name == "GRATE" || name == "FENCE";
                assert_eq!(t.opaque, !masked, "{name} {kind:?}");
                if masked {
                    let clear = t.texels.iter().filter(|&&p| p >> 24 == 0).count();
                    assert!(clear > 0 && clear < t.texels.len(), "{name}: {clear} clear");
                    // Procedural masks are binary: the renderer may test alpha != 0.
                    assert!(t.texels.iter().all(|&p| matches!(p >> 24, 0 | 255)), "{name}");
                }
            }
        }
    }

    #[test]
    fn sizes_are_as_documented() {
        let size = |name, kind| generate(name, kind).map(|t| (t.width, t.height));
        assert_eq!(size("DEBUG1", TextureKind::Wall), Some((1, 1)));
        assert_eq!(size("THIN", TextureKind::Wall), Some((1, 64)));
        assert_eq!(size("ODD", TextureKind::Wall), Some((37, 23)));
        assert_eq!(size("SKY", TextureKind::Wall), Some((1024, 200)));
        assert_eq!(size("SKY", TextureKind::Flat), size("SKY", TextureKind::Wall));
        let all: Vec<_> = KINDS.iter().flat_map(|&k| names(k).iter().map(move |&n| size(n, k).unwrap())).collect();
        assert!(all.iter().any(|&(w, h)| !w.is_power_of_two() || !h.is_power_of_two()));
    }

    #[test]
    fn odd_texels_identify_their_coordinates() {
        // ODD encodes u in red and v in green, so a renderer test can read back
        // which texel landed on a pixel.
        let t = generate("ODD", TextureKind::Wall).unwrap();
        for u in 0..t.width {
            for v in 0..t.height {
                let [r, g, _, _] = t.texel(u, v).to_le_bytes();
                assert_eq!((r as usize, g as usize), (u * 7, v * 11));
            }
        }
    }

    #[test]
    fn generation_is_deterministic_and_case_blind() {
        for kind in KINDS {
            for name in all_names(kind) {
                let a = generate(name, kind).unwrap();
                let b = generate(&name.to_lowercase(), kind).unwrap();
                assert!(a == b, "{name} differs between runs");
            }
        }
    }

    #[test]
    fn names_are_per_kind() {
        assert!(generate("BRICK", TextureKind::Flat).is_none());
        assert!(generate("FLOOR", TextureKind::Wall).is_none());
        assert!(generate("BARREL", TextureKind::Wall).is_none());
        assert!(generate("NOPE", TextureKind::Sprite).is_none());
        assert!(generate("", TextureKind::Wall).is_none());
        assert!(generate("Sky", TextureKind::Flat).is_some());
    }

    #[test]
    fn sprites_stand_on_their_bottom_row_and_sky_wraps() {
        for &name in names(TextureKind::Sprite) {
            let t = generate(name, TextureKind::Sprite).unwrap();
            let bottom = (0..t.width).filter(|&u| alpha(&t, u, t.height - 1) == 255).count();
            assert!(bottom >= 2, "{name} floats above the ground");
            // A column of air at both edges, so clamped sampling at the
            // sprite's sides never smears the figure.
            for u in [0, t.width - 1] {
                assert!((0..t.height).all(|v| alpha(&t, u, v) == 0), "{name} column {u}");
            }
        }
        // Column 0 continues column width-1: the two differ no more than
        // neighbouring columns inside the panorama do.
        let sky = generate("SKY", TextureKind::Wall).unwrap();
        let step = |a: usize, b: usize| -> u32 {
            sky.column(a)
                .iter()
                .zip(sky.column(b))
                .map(|(&p, &q)| {
                    let (p, q) = (p.to_le_bytes(), q.to_le_bytes());
                    (0..3).map(|i| p[i].abs_diff(q[i]) as u32).sum::<u32>()
                })
                .sum()
        };
        let inside = (1..sky.width).map(|u| step(u - 1, u)).max().unwrap();
        assert!(step(sky.width - 1, 0) <= inside, "seam {} > {inside}", step(sky.width - 1, 0));
        // The bottom of the panorama is land, darker than the sky at the top.
        let luma = |p: u32| p.to_le_bytes()[..3].iter().map(|&c| c as u32).sum::<u32>();
        assert!(luma(sky.texel(0, sky.height - 1)) < luma(sky.texel(0, sky.height / 2)));
    }
}
