//! The thing table: every kind of thing a version-2 map may name, with what
//! the engine needs of it now (what is drawn, what is picked up, what marks
//! a place). Doom's and Doom II's types ship as `engine/data/things.ron`;
//! the table is data, checked when it loads (names and numbers unique,
//! sizes finite), so a mod changes a file, not the code.

use std::collections::HashMap;
use std::sync::OnceLock;

use serde::Deserialize;

use super::special::KeyColour;

/// The shipped table: Doom's and Doom II's thing types.
const DOOM_TABLE: &str = include_str!("../../data/things.ron");

/// What a thing is, in broad strokes (Doom's categories).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum Category {
    /// Player `n`'s start (1 is the single-player start).
    PlayerStart(u8),
    DeathmatchStart,
    /// Where teleporters in its sector put a body.
    TeleportDestination,
    Monster,
    Weapon,
    Ammo,
    Health,
    Armor,
    Powerup,
    Key(KeyColour, KeyForm),
    /// Solid scenery.
    Obstacle,
    /// Scenery that does not block.
    Decoration,
    LightSource,
    Corpse,
    BossBrain,
    BossSpawner,
    BossTarget,
    /// Saved by an editor, never spawned (Doom Builder's camera, 32000).
    EditorOnly,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
pub enum KeyForm {
    Card,
    Skull,
}

/// Doom's mobj flags that a thing type may carry.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum ThingFlag {
    /// Picked up by touch (Doom's MF_SPECIAL).
    Special,
    Solid,
    Shootable,
    NoSector,
    NoBlockmap,
    SpawnCeiling,
    NoGravity,
    Float,
    Shadow,
    NoBlood,
    CountKill,
    CountItem,
    NotDeathmatch,
}

/// One kind of thing.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThingType {
    /// Doom's editor number, which WADs store.
    pub doomednum: u16,
    /// The name maps use.
    pub name: String,
    pub category: Category,
    /// The spawn state's four-letter sprite, "" for a thing never drawn.
    pub sprite: String,
    /// Its frame letters in order.
    pub frames: String,
    /// The first frame's ticks (-1: it stays).
    pub tics: i32,
    /// The first frame is drawn at full brightness.
    pub bright: bool,
    pub radius: f64,
    pub height: f64,
    pub flags: Vec<ThingFlag>,
    /// Frames drawn full-bright, when that differs from frame to frame.
    #[serde(default)]
    pub bright_frames: String,
    /// Per-frame ticks, when they differ.
    #[serde(default)]
    pub frame_tics: Vec<i32>,
    /// The spawn state ends by removing the thing (Doom's dead lost soul).
    #[serde(default)]
    pub then_removed: bool,
}

impl ThingType {
    pub fn has(&self, flag: ThingFlag) -> bool {
        self.flags.contains(&flag)
    }

    /// The sprite lump stem of the first frame (`BKEYA`), if it is drawn.
    /// Markers are not: starts (a player appears there, not a thing),
    /// teleport destinations, boss targets, an editor's camera.
    pub fn first_frame(&self) -> Option<String> {
        let marker = matches!(
            self.category,
            Category::PlayerStart(_)
                | Category::DeathmatchStart
                | Category::TeleportDestination
                | Category::BossTarget
                | Category::EditorOnly
        );
        let frame = self.frames.chars().next()?;
        let drawn = !marker && !self.sprite.is_empty() && !self.has(ThingFlag::NoSector);
        drawn.then(|| format!("{}{frame}", self.sprite))
    }

    /// The key it gives, if it is a key.
    pub fn key(&self) -> Option<KeyColour> {
        match self.category {
            Category::Key(colour, _) => Some(colour),
            _ => None,
        }
    }
}

#[derive(Deserialize)]
#[serde(rename = "ThingTypes")]
struct TableSource(Vec<ThingType>);

/// The thing types, by name and by Doom number.
#[derive(Clone, Debug)]
pub struct ThingTypes {
    pub types: Vec<ThingType>,
    by_name: HashMap<String, usize>,
    by_number: HashMap<u16, usize>,
}

/// Why a thing table could not be loaded.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ThingTableError {
    #[error("{path}:{line}:{col}: {message}")]
    Syntax { path: String, line: usize, col: usize, message: String },
    #[error("{path}: thing type {index} ({name:?}): {message}")]
    Invalid { path: String, index: usize, name: String, message: String },
}

impl ThingTypes {
    /// Doom's and Doom II's types, as shipped (checked by the tests, so
    /// this cannot fail in a release).
    pub fn doom() -> &'static ThingTypes {
        static TABLE: OnceLock<ThingTypes> = OnceLock::new();
        TABLE.get_or_init(|| {
            ThingTypes::parse(DOOM_TABLE, "engine/data/things.ron")
                .unwrap_or_else(|e| panic!("the shipped thing table is broken: {e}"))
        })
    }

    /// Parses and checks a table; `label` names it in errors.
    pub fn parse(text: &str, label: &str) -> Result<ThingTypes, ThingTableError> {
        let TableSource(types) = ron::from_str(text).map_err(|e| ThingTableError::Syntax {
            path: label.to_string(),
            line: e.span.start.line,
            col: e.span.start.col,
            message: e.code.to_string(),
        })?;
        let mut by_name = HashMap::new();
        let mut by_number = HashMap::new();
        for (index, t) in types.iter().enumerate() {
            let invalid = |message: String| ThingTableError::Invalid {
                path: label.to_string(),
                index,
                name: t.name.clone(),
                message,
            };
            let plain = |c: char| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_';
            if t.name.is_empty() || !t.name.chars().all(plain) {
                return Err(invalid("a name is lower-case letters, digits and _".into()));
            }
            if let Some(first) = by_name.insert(t.name.clone(), index) {
                return Err(invalid(format!("the name is also type {first}'s")));
            }
            if let Some(first) = by_number.insert(t.doomednum, index) {
                return Err(invalid(format!("doomednum {} is also type {first}'s", t.doomednum)));
            }
            let size_ok = |v: f64| v.is_finite() && (0.0..=4096.0).contains(&v);
            if !size_ok(t.radius) || !size_ok(t.height) {
                return Err(invalid(format!("radius {} or height {} is not within 0..=4096", t.radius, t.height)));
            }
            let sprite_ok =
                t.sprite.is_empty() || (t.sprite.len() == 4 && t.sprite.chars().all(|c| c.is_ascii_graphic()));
            if !sprite_ok || (!t.sprite.is_empty() && t.frames.is_empty()) {
                return Err(invalid(format!(
                    "sprite {:?} with frames {:?}: a sprite is 4 characters with at least one frame",
                    t.sprite, t.frames
                )));
            }
            if !t.frames.chars().all(|c| c.is_ascii_uppercase() || "[\\]".contains(c)) {
                return Err(invalid(format!("frames {:?} must be letters A to ]", t.frames)));
            }
        }
        Ok(ThingTypes { types, by_name, by_number })
    }

    pub fn get(&self, name: &str) -> Option<&ThingType> {
        self.by_name.get(name).map(|&i| &self.types[i])
    }

    pub fn by_doomednum(&self, number: u16) -> Option<&ThingType> {
        self.by_number.get(&number).map(|&i| &self.types[i])
    }

    /// The known name nearest to `name` (by edit distance), for "did you mean".
    pub fn nearest(&self, name: &str) -> Option<&str> {
        self.types
            .iter()
            .map(|t| (edit_distance(name, &t.name), t.name.as_str()))
            .filter(|&(d, _)| d <= name.len().max(3) / 2)
            .min()
            .map(|(_, n)| n)
    }
}

/// Levenshtein distance over bytes (names are ASCII).
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, &ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != cb)).min(row[j] + 1).min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_table_loads() {
        let t = ThingTypes::doom();
        assert_eq!(t.by_doomednum(5).map(|t| t.name.as_str()), Some("blue_card"));
        assert_eq!(t.get("imp").map(|t| t.doomednum), Some(3001));
        assert_eq!(t.get("player_start").map(|t| t.category), Some(Category::PlayerStart(1)));
        assert_eq!(t.nearest("imps"), Some("imp"));
        assert_eq!(t.get("red_skull").and_then(ThingType::key), Some(KeyColour::Red));
    }

    #[test]
    fn a_broken_table_names_the_type() {
        let dup = r#"ThingTypes([
            ThingType(doomednum: 1, name: "a", category: Monster, sprite: "POSS", frames: "A", tics: -1, bright: false, radius: 1, height: 1, flags: []),
            ThingType(doomednum: 1, name: "b", category: Monster, sprite: "POSS", frames: "A", tics: -1, bright: false, radius: 1, height: 1, flags: []),
        ])"#;
        let e = ThingTypes::parse(dup, "t.ron").unwrap_err().to_string();
        assert_eq!(e, "t.ron: thing type 1 (\"b\"): doomednum 1 is also type 0's");
        let e = ThingTypes::parse("ThingTypes([ThingType(name: 3)])", "t.ron").unwrap_err().to_string();
        assert!(e.starts_with("t.ron:1:"), "{e}");
    }
}
