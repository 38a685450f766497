//! What patches change besides the actor table, kept for the game to read
//! later: Doom's strings ([`Strings`]: level names, messages, finale
//! texts), par times ([`Pars`]) and the settings doom.exe hard-codes
//! ([`Settings`]: the player's start and limits, cheats).

use std::collections::BTreeMap;
use std::sync::OnceLock;

use serde::Deserialize;

use super::doom;

const DOOM_STRINGS: &str = include_str!("../../../data/doom_strings.ron");
pub const DOOM_STRINGS_PATH: &str = "engine/data/doom_strings.ron";

#[derive(Deserialize)]
#[serde(rename = "DoomStrings")]
struct StringsSource(Vec<(String, String)>);

/// Doom's strings by BEX name, with doom.exe's English text.
pub fn doom_strings() -> &'static [(String, String)] {
    static STRINGS: OnceLock<Vec<(String, String)>> = OnceLock::new();
    STRINGS.get_or_init(|| match ron::from_str::<StringsSource>(DOOM_STRINGS) {
        Ok(StringsSource(list)) => list,
        Err(e) => panic!("{DOOM_STRINGS_PATH} is broken: {e}"),
    })
}

/// Doom's strings as patches left them. Chocolate Doom keeps one list,
/// old text to new, and looks every string up in it (DEH_String); a BEX
/// name is turned into Doom's text for it first. So does this: a `Text`
/// block and a `[STRINGS]` entry that change the same string are one
/// change, the later winning.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Strings {
    /// Doom's text to its replacement.
    by_text: BTreeMap<String, String>,
    /// BEX names doom.exe has no string for (Boom's STARTUP5, ZDoom's
    /// OB_ and TAG_ names), kept by name (upper case).
    extra: BTreeMap<String, String>,
    /// BEX `[SOUNDS]` and `[MUSIC]`: a lump name's stem to another.
    sounds: BTreeMap<String, String>,
    music: BTreeMap<String, String>,
}

impl Strings {
    /// doom.exe's English text of the BEX name `name` (`HUSTR_E1M1`).
    pub fn original(name: &str) -> Option<&'static str> {
        doom_strings().iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map(|(_, s)| s.as_str())
    }

    /// Doom's string `name` as patches left it; `None` for a name doom.exe
    /// does not have and no patch gave.
    pub fn get(&self, name: &str) -> Option<&str> {
        match Strings::original(name) {
            Some(text) => Some(self.text(text)),
            None => self.extra.get(&name.to_ascii_uppercase()).map(String::as_str),
        }
    }

    /// The text the game shows where doom.exe shows `original`.
    pub fn text<'a>(&'a self, original: &'a str) -> &'a str {
        self.by_text.get(original).map_or(original, String::as_str)
    }

    /// A `Text` block: `from` (doom.exe's text) becomes `to`.
    pub fn replace_text(&mut self, from: &str, to: &str) {
        self.by_text.insert(from.to_string(), to.to_string());
    }

    /// A `[STRINGS]` entry. False when doom.exe has no string of that name
    /// (the text is kept under the name all the same).
    pub fn set(&mut self, name: &str, text: &str) -> bool {
        match Strings::original(name) {
            Some(original) => {
                self.replace_text(original, text);
                true
            }
            None => {
                self.extra.insert(name.to_ascii_uppercase(), text.to_string());
                false
            }
        }
    }

    /// Every replaced string: doom.exe's text and the new one.
    pub fn replaced(&self) -> impl Iterator<Item = (&str, &str)> {
        self.by_text.iter().map(|(a, b)| (a.as_str(), b.as_str()))
    }

    /// The lump stem (`DS` + it) a sound plays from, `[SOUNDS]` applied.
    pub fn sound<'a>(&'a self, name: &'a str) -> &'a str {
        self.sounds.get(&name.to_ascii_lowercase()).map_or(name, String::as_str)
    }

    /// The music lump stem (`D_` + it), `[MUSIC]` applied.
    pub fn music<'a>(&'a self, name: &'a str) -> &'a str {
        self.music.get(&name.to_ascii_lowercase()).map_or(name, String::as_str)
    }

    pub fn rename_sound(&mut self, from: &str, to: &str) {
        self.sounds.insert(from.to_ascii_lowercase(), to.to_ascii_lowercase());
    }

    pub fn rename_music(&mut self, from: &str, to: &str) {
        self.music.insert(from.to_ascii_lowercase(), to.to_ascii_lowercase());
    }
}

/// Par times from BEX `[PARS]`, in seconds. doom.exe's own (pars[][] and
/// cpars[] in g_game.c) are the game's to know; this holds what patches
/// set.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pars {
    episodes: BTreeMap<(u8, u8), u32>,
    maps: BTreeMap<u8, u32>,
}

impl Pars {
    /// ExMy's par, if a patch set it.
    pub fn episode(&self, episode: u8, map: u8) -> Option<u32> {
        self.episodes.get(&(episode, map)).copied()
    }

    /// MAPxx's par, if a patch set it.
    pub fn map(&self, map: u8) -> Option<u32> {
        self.maps.get(&map).copied()
    }

    pub fn set(&mut self, episode: Option<u8>, map: u8, seconds: u32) {
        match episode {
            Some(e) => self.episodes.insert((e, map), seconds),
            None => self.maps.insert(map, seconds),
        };
    }

    pub fn len(&self) -> usize {
        self.episodes.len() + self.maps.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// What doom.exe hard-codes and a patch's `Misc`, `Ammo` and `Cheat`
/// sections change (Chocolate's deh_misc.c names each use). Those the
/// table can hold are applied to it as well: "Max Health" to the health
/// bonus, the armour classes to the armours, the sphere values to the
/// spheres, "BFG Cells/Shot" to the BFG, "Per ammo" to every pickup's
/// ammunition. The rest waits for the game.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    pub initial_health: i32,
    pub initial_bullets: i32,
    pub max_health: i32,
    pub max_armor: i32,
    pub green_armor_class: i32,
    pub blue_armor_class: i32,
    pub max_soulsphere: i32,
    pub soulsphere_health: i32,
    pub megasphere_health: i32,
    pub god_mode_health: i32,
    pub idfa_armor: i32,
    pub idfa_armor_class: i32,
    pub idkfa_armor: i32,
    pub idkfa_armor_class: i32,
    pub bfg_cells_per_shot: i32,
    /// Monsters hurt their own kind with missiles ("Monsters Infight" 221;
    /// 202 is off, Doom's way).
    pub species_infighting: bool,
    /// By [`AmmoKind::index`](crate::actors::AmmoKind::index).
    pub max_ammo: [i32; 4],
    /// What a clip of each kind holds (the backpack gives one of each).
    pub clip_ammo: [i32; 4],
    /// Cheat name (as `Cheat 0` writes it: "God mode") to its keys.
    pub cheats: BTreeMap<String, String>,
}

impl Default for Settings {
    fn default() -> Settings {
        let mut max_ammo = [0; 4];
        let mut clip_ammo = [0; 4];
        for (k, kind) in doom::AMMO.iter().enumerate() {
            max_ammo[kind.index()] = doom::MAX_AMMO[k];
            clip_ammo[kind.index()] = doom::CLIP_AMMO[k];
        }
        Settings {
            initial_health: 100,
            initial_bullets: 50,
            max_health: 200,
            max_armor: 200,
            green_armor_class: 1,
            blue_armor_class: 2,
            max_soulsphere: 200,
            soulsphere_health: 100,
            megasphere_health: 200,
            god_mode_health: 100,
            idfa_armor: 200,
            idfa_armor_class: 2,
            idkfa_armor: 200,
            idkfa_armor_class: 2,
            bfg_cells_per_shot: 40,
            species_infighting: false,
            max_ammo,
            clip_ammo,
            cheats: BTreeMap::new(),
        }
    }
}
