//! The RON shape of an actor table, as a modder writes it. Every property
//! may be left out: a new actor then takes Doom's defaults, and an actor
//! `based_on` another takes its parent's value.
//!
//! ```ron
//! Actors(
//!     sprites: ["POSS"],          // sprite names this file adds
//!     actors: [
//!         Actor(
//!             name: "zombieman",
//!             doomednum: 3004,
//!             category: Monster,
//!             health: 20, pain_chance: 200, speed: 8, height: 56,
//!             sounds: (see: "posit1", attack: "pistol", pain: "popain", death: "podth1", active: "posact"),
//!             flags: [Solid, Shootable, CountKill],
//!             drop: "clip",
//!             states: r#"
//!                 Spawn:
//!                     POSS AB 10 A_Look
//!                     loop
//!                 ...
//!             "#,
//!         ),
//!     ],
//! )
//! ```

use serde::Deserialize;

use super::{ActorFlag, Category, Pickup, WeaponDef};

#[derive(Debug, Deserialize)]
#[serde(rename = "Actors", deny_unknown_fields)]
pub struct TableSource {
    /// Sprite names (four characters) the file's states may use, besides
    /// the ones the files before it listed.
    #[serde(default)]
    pub sprites: Vec<String>,
    pub actors: Vec<ActorSource>,
}

/// Sound names by role; each is a name from the sound list.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SoundsSource {
    pub see: Option<String>,
    pub attack: Option<String>,
    pub pain: Option<String>,
    pub death: Option<String>,
    pub active: Option<String>,
}

/// One actor as written.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(rename = "Actor", deny_unknown_fields)]
pub struct ActorSource {
    pub name: String,
    /// Start from this actor's resolved definition (its properties, flags
    /// and labels), then apply the fields given here.
    pub based_on: Option<String>,
    /// Spawn this actor wherever the named one would spawn (map things,
    /// drops, actions that spawn it).
    pub replaces: Option<String>,
    pub doomednum: Option<u16>,
    pub category: Option<Category>,
    pub health: Option<i32>,
    pub reaction_time: Option<i32>,
    pub pain_chance: Option<i32>,
    pub speed: Option<f64>,
    pub fast_speed: Option<f64>,
    pub radius: Option<f64>,
    pub height: Option<f64>,
    pub mass: Option<i32>,
    pub damage: Option<i32>,
    pub sounds: Option<SoundsSource>,
    /// Replaces the parent's flags.
    pub flags: Option<Vec<ActorFlag>>,
    /// Added to the parent's flags.
    #[serde(default)]
    pub add_flags: Vec<ActorFlag>,
    /// Taken from the parent's flags.
    #[serde(default)]
    pub remove_flags: Vec<ActorFlag>,
    pub species: Option<String>,
    pub drop: Option<String>,
    pub pickup: Option<Pickup>,
    pub weapon: Option<WeaponDef>,
    /// The state text (see `states.rs`); labels it defines replace the
    /// parent's of the same name, the others are kept.
    pub states: Option<String>,
}
