//! Which textures animate and which are switches: data, not code. Doom's
//! lists ship as `engine/data/animations.ron`, checked when they load
//! (every animation has at least two frames and a positive frame time,
//! names are plain). [`crate::materials`] resolves the frames and partners
//! of the textures a map uses; `play::world` advances and flips them.

use std::sync::OnceLock;

use serde::Deserialize;

const DOOM_LIST: &str = include_str!("../../data/animations.ron");

/// Frames shown in turn, `tics` ticks each.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Animation", deny_unknown_fields)]
pub struct AnimDef {
    pub frames: Vec<String>,
    pub tics: u32,
}

/// A switch's two textures, and the first game whose switch list has it.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Switch", deny_unknown_fields)]
pub struct SwitchDef {
    pub off: String,
    pub on: String,
    #[serde(default)]
    pub game: SwitchGame,
}

/// The first game a switch is one in (Doom's `alphSwitchList` grows with
/// the game: a Doom II switch texture in an Ultimate Doom map is not a
/// switch there, and a demo depends on it). Sightline's own switches are
/// switches in RON maps only; a mod's switch is one everywhere.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
pub enum SwitchGame {
    #[default]
    Shareware,
    Registered,
    Doom2,
    Sightline,
}

#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Animations", deny_unknown_fields)]
pub struct AnimDefs {
    pub flats: Vec<AnimDef>,
    pub textures: Vec<AnimDef>,
    pub switches: Vec<SwitchDef>,
}

#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AnimDefsError {
    #[error("{path}:{line}:{col}: {message}")]
    Syntax { path: String, line: usize, col: usize, message: String },
    #[error("{path}: {what}: {message}")]
    Invalid { path: String, what: String, message: String },
}

impl AnimDefs {
    /// Doom's lists, as shipped (checked by the tests).
    pub fn doom() -> &'static AnimDefs {
        static LIST: OnceLock<AnimDefs> = OnceLock::new();
        LIST.get_or_init(|| {
            AnimDefs::parse(DOOM_LIST, "engine/data/animations.ron")
                .unwrap_or_else(|e| panic!("the shipped animation list is broken: {e}"))
        })
    }

    pub fn parse(text: &str, label: &str) -> Result<AnimDefs, AnimDefsError> {
        let defs: AnimDefs = ron::from_str(text).map_err(|e| AnimDefsError::Syntax {
            path: label.to_string(),
            line: e.span.start.line,
            col: e.span.start.col,
            message: e.code.to_string(),
        })?;
        let invalid = |what: String, message: &str| AnimDefsError::Invalid {
            path: label.to_string(),
            what,
            message: message.to_string(),
        };
        let plain = |n: &str| !n.is_empty() && n.chars().all(|c| c.is_ascii_graphic() && !"/\\.:".contains(c));
        for (kind, list) in [("flat", &defs.flats), ("texture", &defs.textures)] {
            for (i, a) in list.iter().enumerate() {
                let what = format!("{kind} animation {i}");
                if a.frames.len() < 2 {
                    return Err(invalid(what, "an animation needs at least two frames"));
                }
                if a.tics == 0 {
                    return Err(invalid(what, "tics must be at least 1"));
                }
                if let Some(bad) = a.frames.iter().find(|f| !plain(f)) {
                    return Err(invalid(what, &format!("frame {bad:?} is not a plain texture name")));
                }
            }
        }
        for (i, s) in defs.switches.iter().enumerate() {
            if !plain(&s.off) || !plain(&s.on) || s.off == s.on {
                return Err(invalid(format!("switch {i}"), "needs two different plain texture names"));
            }
        }
        Ok(defs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doom_lists_load_and_bad_ones_are_named() {
        let d = AnimDefs::doom();
        assert_eq!(d.flats[0].frames, ["NUKAGE1", "NUKAGE2", "NUKAGE3"]);
        assert_eq!(d.switches.len(), 42);
        let bad = "Animations(flats: [Animation(frames: [\"A\"], tics: 8)], textures: [], switches: [])";
        assert_eq!(
            AnimDefs::parse(bad, "a.ron").unwrap_err().to_string(),
            "a.ron: flat animation 0: an animation needs at least two frames"
        );
    }
}
