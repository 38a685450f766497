//! The RON source form of a grid map, exactly as a person writes it:
//!
//! ```ron
//! GridMap(
//!     name: "Bunker",
//!     cell_size: 64.0,
//!     rows: ["#####", "#P.o#", "#####"],
//!     legend: { '#': Wall(texture: "BRICK"), 'P': PlayerStart(angle: 0.0), ... },
//! )
//! ```
//!
//! Loose types (light as `i64`) let a bad value reach validation and get an
//! error naming the element; unknown fields are errors.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::map::source::FogSource;

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(rename = "GridMap", deny_unknown_fields)]
pub struct GridMapSource {
    pub name: String,
    pub cell_size: f64,
    /// The map seen from above, north edge first; one character per cell.
    pub rows: Vec<String>,
    pub legend: BTreeMap<char, CellSource>,
    /// Floor height (default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor: Option<f64>,
    /// Ceiling height (default the floor plus `cell_size`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ceiling: Option<f64>,
    /// Light level of the whole map, 0..=255 (default 255: Wolfenstein has no light levels).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light: Option<i64>,
    /// Flat textures; without them floor and ceiling are flat colours, as in Wolfenstein.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor_texture: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ceiling_texture: Option<String>,
    /// Darken with distance (default off for grid maps: Wolfenstein is evenly lit).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub diminishing_light: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fog: Option<FogSource>,
}

/// What a legend character stands for.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum CellSource {
    Wall {
        texture: String,
    },
    /// A sliding door between two wall cells on opposite sides.
    Door {
        texture: String,
    },
    /// An empty cell with a thing standing at its centre.
    Thing {
        kind: String,
    },
    /// An empty cell where the player starts, facing `angle` degrees
    /// (counter-clockwise from east).
    PlayerStart {
        angle: f64,
    },
    Empty,
}
