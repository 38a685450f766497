//! The RON source form of a sector map, exactly as a person writes it.
//!
//! Types here are deliberately loose (indices as `i64`, light as `i64`) so that
//! a bad value reaches validation and gets an error naming the element, instead
//! of a bare type error from the parser. Struct names match the RON keywords
//! (`Map(...)`, `Sector(...)`), which RON checks. Unknown fields are errors,
//! so a misspelt optional field (`impasable`) is reported, not ignored.

use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Map", deny_unknown_fields)]
pub struct MapSource {
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
}

/// `fog: Some(Fog(colour: (r, g, b), distance: D))`: at distance D map units
/// a surface shows only the fog colour; nearer, it fades linearly.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Fog", deny_unknown_fields)]
pub struct FogSource {
    pub colour: (u8, u8, u8),
    pub distance: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Sector", deny_unknown_fields)]
pub struct SectorSource {
    pub floor: f64,
    pub ceiling: f64,
    pub light: i64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor_texture: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ceiling_texture: Option<String>,
    /// A number that line triggers name to act on this sector (0: none).
    #[serde(default, skip_serializing_if = "is_zero_i64")]
    pub tag: i64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
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
    /// A door: using this line opens its back sector: raises its ceiling, or on a
    /// grid map slides its panel (see `play::doors`).
    #[serde(default, skip_serializing_if = "is_false")]
    pub door: bool,
    /// Opens every sector tagged `tag` when the player uses or walks over it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trigger: Option<TriggerSource>,
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
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "Thing", deny_unknown_fields)]
pub struct ThingSource {
    pub kind: String,
    pub x: f64,
    pub y: f64,
    #[serde(default)]
    pub angle: f64,
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
    /// Pretty RON text that [`crate::map::parse_map`] reads back.
    pub fn to_ron(&self) -> String {
        let config = ron::ser::PrettyConfig::new().struct_names(true).depth_limit(3);
        // Serializing plain data to a String cannot fail.
        ron::ser::to_string_pretty(self, config).unwrap_or_default()
    }
}
