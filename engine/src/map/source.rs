//! The RON source form of a sector map, exactly as a person writes it.
//!
//! Types here are deliberately loose (indices as `i64`, light as `i64`) so that
//! a bad value reaches validation and gets an error naming the element, instead
//! of a bare type error from the parser. Struct names match the RON keywords
//! (`Map(...)`, `Sector(...)`), which RON checks. Unknown fields are errors,
//! so a misspelt optional field (`impasable`) is reported, not ignored.

use serde::{Deserialize, Serialize};

use super::special::{Action, Activation, Scroll, SectorSpecial, SkillBand, Who};

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Map", deny_unknown_fields)]
/// `Default` is an empty version-1 map, for generators to fill in.
pub struct MapSource {
    /// The format version: 1 (the default) or 2. In version 2 a thing's
    /// `kind` names a thing type (`"imp"`, `"blue_card"`), checked against
    /// the actor table; in version 1 it names the sprite drawn.
    #[serde(default = "version_1", skip_serializing_if = "is_version_1")]
    pub version: i64,
    pub name: String,
    pub vertices: Vec<(f64, f64)>,
    pub sectors: Vec<SectorSource>,
    pub lines: Vec<LineSource>,
    #[serde(default)]
    pub things: Vec<ThingSource>,
    /// Darken with distance, as Doom's colormaps do (default on).
    #[serde(default = "yes", skip_serializing_if = "is_true")]
    pub diminishing_light: bool,
    /// Fade to a colour with distance (default none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fog: Option<FogSource>,
    /// The texture `"SKY"` ceilings and floors show (default: the built-in SKY).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sky: Option<String>,
    /// A file of animated textures and switch pairs (beside the map) to use
    /// instead of the shipped list (`engine/data/animations.ron`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub animations: Option<String>,
    /// A MIDI file (beside the map) played while the map is played, looping.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub music: Option<String>,
    /// Lines that only set off specials: they draw nothing, block nothing,
    /// have no sides, and may cross anything (Doom's invisible walk-over
    /// lines).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub trigger_lines: Vec<TriggerLineSource>,
}

/// `TriggerLine(from: 4, to: 9, special: LineSpecial(...))`: its front is
/// its right-hand side, as for any line.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "TriggerLine", deny_unknown_fields)]
pub struct TriggerLineSource {
    pub from: i64,
    pub to: i64,
    pub special: LineSpecialSource,
}

/// `special: LineSpecial(on: Walk, tag: 3, action: Lift())`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename = "LineSpecial", deny_unknown_fields)]
pub struct LineSpecialSource {
    pub on: Activation,
    /// Works every time; else only the first (Doom's R and 1 lines).
    #[serde(default, skip_serializing_if = "is_false")]
    pub repeat: bool,
    #[serde(default, skip_serializing_if = "is_players")]
    pub by: Who,
    /// The sectors acted on: those with this tag; 0 (the default) is the
    /// sector behind the line.
    #[serde(default, skip_serializing_if = "is_zero_i64")]
    pub tag: i64,
    pub action: Action,
}

/// `fog: Some(Fog(colour: (r, g, b), distance: D))`: at distance D map units
/// a surface shows only the fog colour; nearer, it fades linearly.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Fog", deny_unknown_fields)]
pub struct FogSource {
    pub colour: (u8, u8, u8),
    pub distance: f64,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(rename = "Sector", deny_unknown_fields)]
pub struct SectorSource {
    pub floor: f64,
    pub ceiling: f64,
    pub light: i64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor_texture: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ceiling_texture: Option<String>,
    /// A number that line specials name to act on this sector (0: none).
    #[serde(default, skip_serializing_if = "is_zero_i64")]
    pub tag: i64,
    /// Light effect, damage, secret, door timer.
    #[serde(default, skip_serializing_if = "SectorSpecial::is_none")]
    pub special: SectorSpecial,
    /// The floor (or ceiling) is lit as this other sector is (Boom's light
    /// transfer lines 213 and 261), following its changes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor_light: Option<i64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ceiling_light: Option<i64>,
    /// Bodies standing on the floor are pushed this much a tick (Boom's
    /// conveyors, line 252).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub carry: Option<Scroll>,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(rename = "Line", deny_unknown_fields)]
pub struct LineSource {
    pub from: i64,
    pub to: i64,
    pub front: SideSource,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub back: Option<SideSource>,
    #[serde(default, skip_serializing_if = "is_false")]
    pub upper_unpegged: bool,
    #[serde(default, skip_serializing_if = "is_false")]
    pub lower_unpegged: bool,
    /// Blocks movement even when two-sided (a fence, a window).
    #[serde(default, skip_serializing_if = "is_false")]
    pub impassable: bool,
    /// Blocks monsters, not the player (Doom's ML_BLOCKMONSTERS).
    #[serde(default, skip_serializing_if = "is_false")]
    pub block_monsters: bool,
    /// Half a wall to sound: a noise crosses one such line, not two
    /// (Doom's ML_SOUNDBLOCK).
    #[serde(default, skip_serializing_if = "is_false")]
    pub block_sound: bool,
    /// A door: using this line opens its back sector: raises its ceiling, or on a
    /// grid map slides its panel (see `play::world::doors`).
    #[serde(default, skip_serializing_if = "is_false")]
    pub door: bool,
    /// Version 1's tagged doors: opens every sector tagged `tag` when the
    /// player uses or walks over the line (the same as a door `special`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trigger: Option<TriggerSource>,
    /// What the line does in play.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub special: Option<LineSpecialSource>,
    /// Its see-through middle textures are drawn half transparent (Boom's 260).
    #[serde(default, skip_serializing_if = "is_false")]
    pub translucent: bool,
}

/// `trigger: Trigger(tag: 3, on: Walk, once: true, stay_open: false)`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Trigger", deny_unknown_fields)]
pub struct TriggerSource {
    pub tag: i64,
    pub on: crate::map::TriggerOn,
    /// Works only the first time (Doom's W1 and S1); else every time (WR, SR).
    #[serde(default, skip_serializing_if = "is_false")]
    pub once: bool,
    /// The doors stay open; else they close again after the wait.
    #[serde(default, skip_serializing_if = "is_false")]
    pub stay_open: bool,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(rename = "Side", deny_unknown_fields)]
pub struct SideSource {
    pub sector: i64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub upper: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub middle: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lower: Option<String>,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub x_offset: f64,
    #[serde(default, skip_serializing_if = "is_zero")]
    pub y_offset: f64,
    /// Scrolls its textures by this much a tick (Doom's 48, Boom's scrollers).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scroll: Option<Scroll>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Thing", deny_unknown_fields)]
pub struct ThingSource {
    pub kind: String,
    pub x: f64,
    pub y: f64,
    #[serde(default)]
    pub angle: f64,
    /// The skill levels it appears on (default: all).
    #[serde(default = "all_skills", skip_serializing_if = "is_all_skills")]
    pub skills: Vec<SkillBand>,
    /// A monster that waits, deaf, until it sees the player (Doom's ambush flag).
    #[serde(default, skip_serializing_if = "is_false")]
    pub ambush: bool,
    /// Appears only in multiplayer games.
    #[serde(default, skip_serializing_if = "is_false")]
    pub multiplayer: bool,
    /// Left out of these multiplayer modes (Boom's flags).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub not_in: Vec<super::GameMode>,
}

impl Default for MapSource {
    fn default() -> MapSource {
        MapSource {
            version: 1,
            name: String::new(),
            vertices: Vec::new(),
            sectors: Vec::new(),
            lines: Vec::new(),
            things: Vec::new(),
            diminishing_light: true,
            fog: None,
            sky: None,
            animations: None,
            music: None,
            trigger_lines: Vec::new(),
        }
    }
}

impl ThingSource {
    /// A thing on every skill level, in every mode.
    pub fn new(kind: &str, x: f64, y: f64, angle: f64) -> ThingSource {
        ThingSource {
            kind: kind.to_string(),
            x,
            y,
            angle,
            skills: all_skills(),
            ambush: false,
            multiplayer: false,
            not_in: Vec::new(),
        }
    }
}

fn version_1() -> i64 {
    1
}

fn is_version_1(v: &i64) -> bool {
    *v == 1
}

fn all_skills() -> Vec<SkillBand> {
    SkillBand::ALL.to_vec()
}

fn is_all_skills(s: &[SkillBand]) -> bool {
    SkillBand::ALL.iter().all(|b| s.contains(b))
}

fn is_players(w: &Who) -> bool {
    *w == Who::Players
}

fn yes() -> bool {
    true
}

fn is_true(b: &bool) -> bool {
    *b
}

fn is_false(b: &bool) -> bool {
    !*b
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

fn is_zero_i64(x: &i64) -> bool {
    *x == 0
}

impl MapSource {
    /// Adds a closed ring of plain lines through `corners`, each with the
    /// sector `front` on its right and `back` (if any) on its left: a room
    /// (clockwise), a solid pillar in it (anticlockwise, no back), or the
    /// edge of a sector inside another.
    pub fn add_ring(&mut self, corners: &[(f64, f64)], front: usize, back: Option<usize>) {
        let first = self.vertices.len();
        self.vertices.extend_from_slice(corners);
        let side = |s: usize| SideSource { sector: s as i64, ..SideSource::default() };
        for k in 0..corners.len() {
            self.lines.push(LineSource {
                from: (first + k) as i64,
                to: (first + (k + 1) % corners.len()) as i64,
                front: side(front),
                back: back.map(side),
                ..LineSource::default()
            });
        }
    }

    /// Pretty RON text that [`crate::map::parse_map`] reads back.
    pub fn to_ron(&self) -> String {
        let config = ron::ser::PrettyConfig::new().struct_names(true).depth_limit(3);
        // Serializing plain data to a String cannot fail.
        ron::ser::to_string_pretty(self, config).unwrap_or_default()
    }
}
