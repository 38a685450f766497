//! The sound names actors may use: Doom's sound effects, shipped as
//! `engine/data/sounds.ron` with their priorities and links (Doom's
//! `S_sfx`). A name stands for the WAD lump `DS<NAME>`; the sound issue
//! gives them voices, the actor table only checks that a name exists.

use std::sync::OnceLock;

use serde::Deserialize;

const DOOM_SOUNDS: &str = include_str!("../../data/sounds.ron");

/// One sound effect.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(rename = "Sound", deny_unknown_fields)]
pub struct SoundDef {
    /// The lump name without `DS`, lower case.
    pub name: String,
    /// Doom's priority: a busy channel goes to the higher one.
    pub priority: u8,
    /// Plays another sound at another pitch and volume (Doom's chaingun
    /// is the pistol).
    #[serde(default)]
    pub link: Option<Link>,
}

#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Link {
    pub sound: String,
    pub pitch: i32,
    pub volume: i32,
}

#[derive(Deserialize)]
#[serde(rename = "Sounds")]
struct SoundsSource(Vec<SoundDef>);

/// Doom's sounds, as shipped (checked by the tests: names unique, links
/// resolve).
pub fn doom() -> &'static [SoundDef] {
    static SOUNDS: OnceLock<Vec<SoundDef>> = OnceLock::new();
    let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    SOUNDS.get_or_init(|| match options.from_str::<SoundsSource>(DOOM_SOUNDS) {
        Ok(SoundsSource(list)) => list,
        Err(e) => panic!("engine/data/sounds.ron is broken: {e}"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_sounds_are_unique_and_their_links_resolve() {
        let sounds = doom();
        assert_eq!(sounds.len(), 108);
        let names: std::collections::HashSet<&str> = sounds.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names.len(), sounds.len());
        for s in sounds {
            if let Some(link) = &s.link {
                assert!(names.contains(link.sound.as_str()), "{}: link to {}", s.name, link.sound);
            }
        }
    }
}
