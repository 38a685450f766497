//! The map model: the source form read from RON ([`source`]), the checks that
//! turn it into a [`Map`] ([`validate`]), and the loader with its errors ([`load`]).
//!
//! A [`Map`] is the validated level: indices are in range, geometry is finite and
//! closed, and every sector is enclosed. The BSP compiler takes it from here.

pub mod load;
pub mod semantics;
pub mod source;
pub mod special;
pub mod validate;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::geom::{self, exact_side, on_segment};

pub use load::{load_map, parse_map, MapError, Problem, SpecialAt};
pub use special::{Action, Activation, LineSpecial, SectorSpecial, SkillBand, Who};

/// A validated sector map. Built only by [`validate::validate`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Map {
    /// The source's format version (1 or 2; see [`source::MapSource::version`]).
    pub version: u8,
    pub name: String,
    pub vertices: Vec<DVec2>,
    pub sectors: Vec<Sector>,
    pub lines: Vec<Line>,
    pub things: Vec<Thing>,
    /// Index into `things` of the (first) player start.
    pub player_start: usize,
    pub diminishing_light: bool,
    pub fog: Option<Fog>,
    /// The texture sky surfaces show; `None` is the built-in [`SKY`].
    pub sky: Option<String>,
    /// The map's own animations file, if it names one (see [`source::MapSource::animations`]).
    pub animations: Option<String>,
    /// The MIDI file the map's music is, if it names one (a path beside the map).
    pub music: Option<String>,
    /// Lines that only set off specials (no sides, not in the BSP).
    pub trigger_lines: Vec<TriggerLine>,
}

/// A line that only sets off its special: it draws and blocks nothing.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TriggerLine {
    pub from: usize,
    pub to: usize,
    pub special: LineSpecial,
}

/// Distance fog: full `colour` at `distance` map units, fading in linearly.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Fog {
    pub colour: [u8; 3],
    pub distance: f64,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sector {
    pub floor: f64,
    pub ceiling: f64,
    pub light: u8,
    pub floor_texture: Option<String>,
    pub ceiling_texture: Option<String>,
    /// What line specials name to act on this sector; 0 is none.
    pub tag: u16,
    pub special: SectorSpecial,
    /// Light its floor and ceiling from these sectors instead (Boom's light
    /// transfers); `None` is its own.
    pub floor_light: Option<usize>,
    pub ceiling_light: Option<usize>,
    /// Pushes bodies standing on the floor, units per tick per tick.
    pub carry: Option<special::Scroll>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Line {
    pub from: usize,
    pub to: usize,
    /// The right-hand side walking `from -> to`.
    pub front: Side,
    /// `None` for a solid one-sided wall.
    pub back: Option<Side>,
    pub flags: LineFlags,
    pub special: Option<LineSpecial>,
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct LineFlags {
    pub upper_unpegged: bool,
    pub lower_unpegged: bool,
    pub impassable: bool,
    pub block_monsters: bool,
    pub block_sound: bool,
    /// See-through middles drawn half transparent.
    pub translucent: bool,
}

/// What sets a version-1 `trigger` off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum TriggerOn {
    /// The player uses the line, from its front (a switch).
    Use,
    /// The player's centre crosses the line, either way.
    Walk,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Side {
    pub sector: usize,
    pub upper: Option<String>,
    pub middle: Option<String>,
    pub lower: Option<String>,
    pub x_offset: f64,
    pub y_offset: f64,
    /// Texture scrolling per tick (zero: none).
    pub scroll: special::Scroll,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Thing {
    pub kind: String,
    pub pos: DVec2,
    /// Degrees, counter-clockwise from +x.
    pub angle: f64,
    /// Appears on these skill bands: `[easy, medium, hard]`.
    pub skills: [bool; 3],
    pub ambush: bool,
    /// Only in multiplayer games.
    pub multiplayer: bool,
    pub not_in: Vec<GameMode>,
}

/// A multiplayer mode, for things left out of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum GameMode {
    Deathmatch,
    Coop,
}

impl Thing {
    /// A thing on every skill, in every mode.
    pub fn new(kind: &str, pos: DVec2, angle: f64) -> Thing {
        Thing {
            kind: kind.to_string(),
            pos,
            angle,
            skills: [true; 3],
            ambush: false,
            multiplayer: false,
            not_in: Vec::new(),
        }
    }

    /// Is it in a single-player game at `skill` (1..=5)?
    pub fn in_single_player(&self, skill: u8) -> bool {
        !self.multiplayer && self.skills[special::SkillBand::of_skill(skill) as usize]
    }
}

/// Thing kind that marks where the player begins.
pub const PLAYER_START: &str = "player_start";

/// Texture name that makes a ceiling or floor show the sky.
pub const SKY: &str = "SKY";

impl Sector {
    pub fn ceiling_is_sky(&self) -> bool {
        self.ceiling_texture.as_deref().is_some_and(|t| t.eq_ignore_ascii_case(SKY))
    }

    pub fn floor_is_sky(&self) -> bool {
        self.floor_texture.as_deref().is_some_and(|t| t.eq_ignore_ascii_case(SKY))
    }
}

impl Line {
    /// The front side, or the back side when `back` (the front again on a
    /// one-sided line, which has no other).
    pub fn side(&self, back: bool) -> &Side {
        match (&self.back, back) {
            (Some(b), true) => b,
            _ => &self.front,
        }
    }
}

impl Map {
    pub fn line_points(&self, line: &Line) -> (DVec2, DVec2) {
        (self.vertices[line.from], self.vertices[line.to])
    }

    pub fn player_start(&self) -> &Thing {
        &self.things[self.player_start]
    }

    /// Is `p` in the map: in the interior of the closure of the union of the
    /// sectors? That is a point strictly inside a sector, or a point on
    /// two-sided lines only (a point of a line between two sectors, or a
    /// vertex where only such lines meet). Not in: a point on any one-sided
    /// line (the map's outer boundary, a pillar's edge), in a hole, or in
    /// the void.
    ///
    /// Why a point on two-sided lines only is surrounded by sectors: lines
    /// neither cross nor touch, so near `p` the only lines are the ones
    /// through it; each wedge between them runs along a two-sided line,
    /// which has a sector on both sides all along its length (validation
    /// checked each side at its middle, and no line meets it on the way).
    ///
    /// Exact (orient2d) and independent of the BSP, so the validator asks it
    /// of the player start before anything is compiled. Which sector such a
    /// point belongs to is the BSP's answer: [`crate::bsp::CompiledMap::locate`].
    pub fn contains(&self, p: DVec2) -> bool {
        let mut on_two_sided = false;
        for line in &self.lines {
            let (a, b) = self.line_points(line);
            if on_segment(a, b, p) {
                if line.back.is_none() {
                    return false;
                }
                on_two_sided = true;
            }
        }
        on_two_sided || self.sector_strictly_containing(p).is_some()
    }

    /// The sector `p` lies strictly inside, by the crossing-number test over
    /// each sector's lines; `None` outside every sector or exactly on a line.
    ///
    /// Deliberately independent of the BSP: the reference renderer and the
    /// tests use it as the oracle. It answers nothing for a point on a line,
    /// so nothing a user gives (a pose, a start) is checked with it alone:
    /// that is [`Map::contains`] and [`crate::bsp::CompiledMap::locate`].
    pub fn sector_strictly_containing(&self, p: DVec2) -> Option<usize> {
        let mut crossings = vec![0u32; self.sectors.len()];
        for line in &self.lines {
            let (a, b) = self.line_points(line);
            let side = exact_side(a, b, p);
            if side == geom::Side::On && on_segment(a, b, p) {
                return None;
            }
            // Half-open rule on y so a ray through a vertex counts once. The
            // ray from `p` towards +x crosses the line right of `p` when `p`
            // is left of the line walked upwards: behind an upward line, in
            // front of a downward one (exact, not an interpolated x).
            let upward = b.y > a.y;
            if (a.y > p.y) != (b.y > p.y) && side == if upward { geom::Side::Back } else { geom::Side::Front } {
                crossings[line.front.sector] += 1;
                if let Some(back) = &line.back {
                    crossings[back.sector] += 1;
                }
            }
        }
        crossings.iter().position(|c| c % 2 == 1)
    }

    /// The sectors at `p`: the one containing it, or the sectors of every
    /// line it lies on (a point on a line touches both sides).
    pub fn sectors_near(&self, p: DVec2) -> Vec<usize> {
        if let Some(s) = self.sector_strictly_containing(p) {
            return vec![s];
        }
        let mut out: Vec<usize> = self
            .lines
            .iter()
            .filter(|l| {
                let (a, b) = self.line_points(l);
                on_segment(a, b, p)
            })
            .flat_map(|l| std::iter::once(l.front.sector).chain(l.back.as_ref().map(|b| b.sector)))
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// Distance from `p` to the nearest line.
    pub fn distance_to_nearest_line(&self, p: DVec2) -> f64 {
        self.lines
            .iter()
            .map(|line| {
                let (a, b) = self.line_points(line);
                let d = b - a;
                let t = ((p - a).dot(d) / d.length_squared()).clamp(0.0, 1.0);
                (a + d * t).distance(p)
            })
            .fold(f64::INFINITY, f64::min)
    }
}

impl Map {
    /// The RON source form of this map (what the compiled file stores).
    /// Version 1's `door` and `trigger` come back as the `special`s they
    /// were read as.
    pub fn to_source(&self) -> source::MapSource {
        use source::{
            FogSource, LineSource, LineSpecialSource, MapSource, SectorSource, SideSource, ThingSource,
            TriggerLineSource,
        };
        let side = |s: &Side| SideSource {
            sector: s.sector as i64,
            upper: s.upper.clone(),
            middle: s.middle.clone(),
            lower: s.lower.clone(),
            x_offset: s.x_offset,
            y_offset: s.y_offset,
            scroll: (s.scroll != special::Scroll::default()).then_some(s.scroll),
        };
        let special = |s: &LineSpecial| LineSpecialSource {
            on: s.on,
            repeat: s.repeat,
            by: s.by,
            tag: i64::from(s.tag),
            action: s.action.clone(),
        };
        MapSource {
            version: i64::from(self.version),
            name: self.name.clone(),
            vertices: self.vertices.iter().map(|v| (v.x, v.y)).collect(),
            sectors: self
                .sectors
                .iter()
                .map(|s| SectorSource {
                    floor: s.floor,
                    ceiling: s.ceiling,
                    light: i64::from(s.light),
                    floor_texture: s.floor_texture.clone(),
                    ceiling_texture: s.ceiling_texture.clone(),
                    tag: i64::from(s.tag),
                    special: s.special,
                    floor_light: s.floor_light.map(|k| k as i64),
                    ceiling_light: s.ceiling_light.map(|k| k as i64),
                    carry: s.carry,
                })
                .collect(),
            lines: self
                .lines
                .iter()
                .map(|l| LineSource {
                    from: l.from as i64,
                    to: l.to as i64,
                    front: side(&l.front),
                    back: l.back.as_ref().map(side),
                    upper_unpegged: l.flags.upper_unpegged,
                    lower_unpegged: l.flags.lower_unpegged,
                    impassable: l.flags.impassable,
                    block_monsters: l.flags.block_monsters,
                    block_sound: l.flags.block_sound,
                    door: false,
                    trigger: None,
                    special: l.special.as_ref().map(special),
                    translucent: l.flags.translucent,
                })
                .collect(),
            things: self
                .things
                .iter()
                .map(|t| ThingSource {
                    kind: t.kind.clone(),
                    x: t.pos.x,
                    y: t.pos.y,
                    angle: t.angle,
                    skills: special::SkillBand::ALL.into_iter().filter(|&b| t.skills[b as usize]).collect(),
                    ambush: t.ambush,
                    multiplayer: t.multiplayer,
                    not_in: t.not_in.clone(),
                })
                .collect(),
            diminishing_light: self.diminishing_light,
            fog: self.fog.map(|f| FogSource { colour: (f.colour[0], f.colour[1], f.colour[2]), distance: f.distance }),
            sky: self.sky.clone(),
            animations: self.animations.clone(),
            music: self.music.clone(),
            trigger_lines: self
                .trigger_lines
                .iter()
                .map(|t| TriggerLineSource { from: t.from as i64, to: t.to as i64, special: special(&t.special) })
                .collect(),
        }
    }

    /// The sectors whose tag is `tag` (none for tag 0), in index order.
    pub fn sectors_tagged(&self, tag: u16) -> impl Iterator<Item = usize> + '_ {
        self.sectors.iter().enumerate().filter(move |(_, s)| tag != 0 && s.tag == tag).map(|(i, _)| i)
    }
}
