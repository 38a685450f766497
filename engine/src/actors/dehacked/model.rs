//! A patch as parsed: what it sets, section by section in file order, each
//! value with the line it came from, numbers already checked against
//! Doom's ranges. `apply.rs` turns it into changes to a table; nothing
//! here knows the table.

use super::Warning;

/// A parsed DeHackEd/BEX patch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Patch {
    /// The file (or `wad:DEHACKED`), for errors and warnings.
    pub path: String,
    pub header: Header,
    pub sections: Vec<Section>,
    /// What the parser could not take (unknown fields, lines it ignored).
    pub warnings: Vec<Warning>,
}

/// The lines before the first section.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Header {
    /// `v3.0` from "Patch File for DeHackEd v3.0"; `None` when the file
    /// does not start with a signature (a bare BEX file).
    pub version: Option<String>,
    /// "Doom version = 19" (1.9; 16 and 17 are 1.666 and 1.7, 20 and 21
    /// Boom's): read, not acted on, as in Chocolate Doom.
    pub doom_version: Option<i64>,
    /// "Patch format = 6", the only text format.
    pub patch_format: Option<i64>,
}

/// One section and the line of its header.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    pub line: usize,
    pub kind: SectionKind,
}

/// One `key = value` of a section.
#[derive(Clone, Debug, PartialEq)]
pub struct Field<K> {
    pub line: usize,
    pub key: K,
    pub value: i64,
}

#[derive(Clone, Debug, PartialEq)]
pub enum SectionKind {
    /// `Thing N (name)`: mobjinfo[N - 1].
    Thing { number: usize, name: Option<String>, fields: Vec<Field<ThingField>> },
    /// `Frame N`: states[N].
    Frame { number: usize, fields: Vec<Field<FrameField>> },
    /// `Pointer K (Frame N)`: "Codep Frame = M" gives frame N the action
    /// frame M had in Doom.
    Pointer { frame: usize, code_frames: Vec<Field<()>> },
    /// `Sound N`: S_sfx[N].
    Sound { number: usize, fields: Vec<Field<SoundField>> },
    /// `Ammo N`: Doom's ammo type N (0 bullets, 1 shells, 2 cells, 3
    /// rockets).
    Ammo { number: usize, fields: Vec<Field<AmmoField>> },
    /// `Weapon N`: weaponinfo[N].
    Weapon { number: usize, fields: Vec<Field<WeaponField>> },
    /// `Cheat 0`: cheat names (as DeHackEd lists them) and their keys.
    Cheat { cheats: Vec<(usize, String, String)> },
    /// `Misc 0`.
    Misc { fields: Vec<Field<MiscField>> },
    /// `Text A B`: the A characters after the header line, replaced by the
    /// B after them.
    Text { from: String, to: String },
    /// BEX `[STRINGS]`: (line, name, text).
    Strings { entries: Vec<(usize, String, String)> },
    /// BEX `[PARS]`.
    Pars { entries: Vec<Par> },
    /// BEX `[CODEPTR]`: (line, frame, action name; `None` for `NULL`).
    CodePointers { entries: Vec<(usize, usize, Option<String>)> },
    /// BEX `[SPRITES]`, `[SOUNDS]`, `[MUSIC]`: (line, old name, new name).
    Renames { kind: RenameKind, entries: Vec<(usize, String, String)> },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenameKind {
    Sprites,
    Sounds,
    Music,
}

/// A par time, in seconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Par {
    pub line: usize,
    /// `None` for a Doom II map (`par MAP SECONDS`).
    pub episode: Option<u8>,
    pub map: u8,
    pub seconds: u32,
}

macro_rules! fields {
    ($(#[$doc:meta])* $name:ident { $($variant:ident = $key:literal),* $(,)? }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name { $($variant),* }

        impl $name {
            /// Every field with its name in a patch.
            pub const ALL: &'static [($name, &'static str)] = &[$(($name::$variant, $key)),*];

            /// The field a patch names (case-insensitive, as in Chocolate).
            pub fn find(key: &str) -> Option<$name> {
                Self::ALL.iter().find(|(_, k)| k.eq_ignore_ascii_case(key)).map(|&(f, _)| f)
            }

            pub fn key(self) -> &'static str {
                Self::ALL.iter().find(|(f, _)| *f == self).map_or("?", |(_, k)| k)
            }
        }
    };
}

fields! {
    /// mobjinfo_t's fields, under DeHackEd's names (Chocolate's deh_thing.c).
    ThingField {
        Doomednum = "ID #",
        SpawnFrame = "Initial frame",
        Health = "Hit points",
        SeeFrame = "First moving frame",
        SeeSound = "Alert sound",
        ReactionTime = "Reaction time",
        AttackSound = "Attack sound",
        PainFrame = "Injury frame",
        PainChance = "Pain chance",
        PainSound = "Pain sound",
        MeleeFrame = "Close attack frame",
        MissileFrame = "Far attack frame",
        DeathFrame = "Death frame",
        XDeathFrame = "Exploding frame",
        DeathSound = "Death sound",
        Speed = "Speed",
        Width = "Width",
        Height = "Height",
        Mass = "Mass",
        Damage = "Missile damage",
        ActiveSound = "Action sound",
        Bits = "Bits",
        RaiseFrame = "Respawn frame",
    }
}

fields! {
    /// state_t's fields (deh_frame.c). "Codep frame" is read so that frame
    /// 966's overflow can be simulated; elsewhere Chocolate ignores it.
    FrameField {
        Sprite = "Sprite number",
        Subnumber = "Sprite subnumber",
        Duration = "Duration",
        Next = "Next frame",
        Unknown1 = "Unknown 1",
        Unknown2 = "Unknown 2",
        Codep = "Codep frame",
    }
}

fields! {
    /// sfxinfo_t's fields (deh_sound.c).
    SoundField {
        Offset = "Offset",
        ZeroOne = "Zero/One",
        Priority = "Value",
        Link = "Zero 1",
        Pitch = "Zero 2",
        Volume = "Zero 3",
        Zero4 = "Zero 4",
        Usefulness = "Neg. One 1",
        Lump = "Neg. One 2",
    }
}

fields! {
    /// deh_ammo.c's two fields.
    AmmoField {
        Max = "Max ammo",
        PerClip = "Per ammo",
    }
}

fields! {
    /// weaponinfo_t's fields (deh_weapon.c). DeHackEd's names are crossed:
    /// "Deselect frame" is the raising state (upstate, our `Select`),
    /// "Select frame" the lowering one (downstate, our `Deselect`).
    WeaponField {
        Ammo = "Ammo type",
        Up = "Deselect frame",
        Down = "Select frame",
        Ready = "Bobbing frame",
        Attack = "Shooting frame",
        Flash = "Firing frame",
    }
}

fields! {
    /// deh_misc.c's settings.
    MiscField {
        InitialHealth = "Initial Health",
        InitialBullets = "Initial Bullets",
        MaxHealth = "Max Health",
        MaxArmor = "Max Armor",
        GreenArmorClass = "Green Armor Class",
        BlueArmorClass = "Blue Armor Class",
        MaxSoulsphere = "Max Soulsphere",
        SoulsphereHealth = "Soulsphere Health",
        MegasphereHealth = "Megasphere Health",
        GodModeHealth = "God Mode Health",
        IdfaArmor = "IDFA Armor",
        IdfaArmorClass = "IDFA Armor Class",
        IdkfaArmor = "IDKFA Armor",
        IdkfaArmorClass = "IDKFA Armor Class",
        BfgCellsPerShot = "BFG Cells/Shot",
        MonstersInfight = "Monsters Infight",
    }
}

/// The cheats a `Cheat 0` section may set (deh_cheat.c's names).
pub const CHEATS: [&str; 17] = [
    "Change music",
    "Chainsaw",
    "God mode",
    "Ammo & Keys",
    "Ammo",
    "No Clipping 1",
    "No Clipping 2",
    "Invincibility",
    "Berserk",
    "Invisibility",
    "Radiation Suit",
    "Auto-map",
    "Lite-Amp Goggles",
    "BEHOLD menu",
    "Level Warp",
    "Player Position",
    "Map cheat",
];
