//! What the outside names of a level's machinery: how a level ended, and
//! which of a converted map's lines carries a special (the game runs them
//! in the simulation, `crate::sim`).

/// How the level ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Exit {
    Normal,
    Secret,
}

/// A line that carries a special: one of the map's walls, or one of its
/// trigger lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SpecialLine {
    Wall(usize),
    Trigger(usize),
}
