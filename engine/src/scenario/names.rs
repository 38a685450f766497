//! The enumerations a ViZDoom `.cfg` names: buttons, game variables, screen
//! resolutions and formats, modes, automap modes and audio sampling rates.
//!
//! Each type reads the name a `.cfg` spells (already lower-cased by the
//! reader) with `from_cfg` and gives ViZDoom's own spelling back with
//! `name`. The names accepted are exactly those ViZDoom 1.3.2's loader
//! accepts: they were read from the strings of the 1.3.2 wheel's
//! `vizdoom.cpython-311-x86_64-linux-gnu.so`, and the enum order from its
//! `vizdoom.pyi`.

use std::fmt;

/// A button an agent can press (ViZDoom's `Button`, in ViZDoom's order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Button {
    Attack,
    Use,
    Jump,
    Crouch,
    Turn180,
    AltAttack,
    Reload,
    Zoom,
    Speed,
    Strafe,
    MoveRight,
    MoveLeft,
    MoveBackward,
    MoveForward,
    TurnRight,
    TurnLeft,
    LookUp,
    LookDown,
    MoveUp,
    MoveDown,
    Land,
    /// `SELECT_WEAPON1` ... `SELECT_WEAPON9`, then `SELECT_WEAPON0`: slot 0..=9.
    SelectWeapon(u8),
    SelectNextWeapon,
    SelectPrevWeapon,
    DropSelectedWeapon,
    /// Spelt `ACTIVATE_SELECTED_WEAPON` in a `.cfg`: ViZDoom's loader maps
    /// that name to `ACTIVATE_SELECTED_ITEM` and knows no other.
    ActivateSelectedItem,
    SelectNextItem,
    SelectPrevItem,
    DropSelectedItem,
    LookUpDownDelta,
    TurnLeftRightDelta,
    MoveForwardBackwardDelta,
    MoveLeftRightDelta,
    MoveUpDownDelta,
}

const BUTTONS: [(&str, Button); 33] = [
    ("attack", Button::Attack),
    ("use", Button::Use),
    ("jump", Button::Jump),
    ("crouch", Button::Crouch),
    ("turn180", Button::Turn180),
    ("altattack", Button::AltAttack),
    ("reload", Button::Reload),
    ("zoom", Button::Zoom),
    ("speed", Button::Speed),
    ("strafe", Button::Strafe),
    ("move_right", Button::MoveRight),
    ("move_left", Button::MoveLeft),
    ("move_backward", Button::MoveBackward),
    ("move_forward", Button::MoveForward),
    ("turn_right", Button::TurnRight),
    ("turn_left", Button::TurnLeft),
    ("look_up", Button::LookUp),
    ("look_down", Button::LookDown),
    ("move_up", Button::MoveUp),
    ("move_down", Button::MoveDown),
    ("land", Button::Land),
    ("select_next_weapon", Button::SelectNextWeapon),
    ("select_prev_weapon", Button::SelectPrevWeapon),
    ("drop_selected_weapon", Button::DropSelectedWeapon),
    ("activate_selected_weapon", Button::ActivateSelectedItem),
    ("select_next_item", Button::SelectNextItem),
    ("select_prev_item", Button::SelectPrevItem),
    ("drop_selected_item", Button::DropSelectedItem),
    ("look_up_down_delta", Button::LookUpDownDelta),
    ("turn_left_right_delta", Button::TurnLeftRightDelta),
    ("move_forward_backward_delta", Button::MoveForwardBackwardDelta),
    ("move_left_right_delta", Button::MoveLeftRightDelta),
    ("move_up_down_delta", Button::MoveUpDownDelta),
];

impl Button {
    pub fn from_cfg(name: &str) -> Option<Button> {
        if let Some(slot) = numbered(name, "select_weapon", "", 0..=9) {
            return Some(Button::SelectWeapon(slot));
        }
        BUTTONS.iter().find(|(n, _)| *n == name).map(|&(_, b)| b)
    }

    /// ViZDoom's enum name (`MOVE_LEFT`, `SELECT_WEAPON3`, ...).
    pub fn name(self) -> String {
        match self {
            Button::SelectWeapon(slot) => format!("SELECT_WEAPON{slot}"),
            // The enum's name, not the `.cfg` spelling.
            Button::ActivateSelectedItem => "ACTIVATE_SELECTED_ITEM".to_string(),
            b => BUTTONS.iter().find(|(_, x)| *x == b).map_or_else(String::new, |(n, _)| n.to_ascii_uppercase()),
        }
    }

    /// Whether the button takes a value (a turn or move amount) rather than
    /// being pressed or not: ViZDoom's `*_DELTA` buttons.
    pub fn is_delta(self) -> bool {
        matches!(
            self,
            Button::LookUpDownDelta
                | Button::TurnLeftRightDelta
                | Button::MoveForwardBackwardDelta
                | Button::MoveLeftRightDelta
                | Button::MoveUpDownDelta
        )
    }
}

/// A value the agent's state reports (ViZDoom's `GameVariable`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum GameVariable {
    KillCount,
    ItemCount,
    SecretCount,
    FragCount,
    DeathCount,
    HitCount,
    HitsTaken,
    DamageCount,
    DamageTaken,
    Health,
    Armor,
    Dead,
    OnGround,
    AttackReady,
    AltAttackReady,
    SelectedWeapon,
    SelectedWeaponAmmo,
    /// `AMMO0` ... `AMMO9`.
    Ammo(u8),
    /// `WEAPON0` ... `WEAPON9`.
    Weapon(u8),
    PositionX,
    PositionY,
    PositionZ,
    Angle,
    Pitch,
    Roll,
    ViewHeight,
    VelocityX,
    VelocityY,
    VelocityZ,
    CameraPositionX,
    CameraPositionY,
    CameraPositionZ,
    CameraAngle,
    CameraPitch,
    CameraRoll,
    CameraFov,
    PlayerNumber,
    PlayerCount,
    /// `PLAYER1_FRAGCOUNT` ... `PLAYER16_FRAGCOUNT`.
    PlayerFragCount(u8),
    /// `USER1` ... `USER60`: the map scripts' global variables.
    User(u8),
}

const GAME_VARIABLES: [(&str, GameVariable); 36] = [
    ("killcount", GameVariable::KillCount),
    ("itemcount", GameVariable::ItemCount),
    ("secretcount", GameVariable::SecretCount),
    ("fragcount", GameVariable::FragCount),
    ("deathcount", GameVariable::DeathCount),
    ("hitcount", GameVariable::HitCount),
    ("hits_taken", GameVariable::HitsTaken),
    ("damagecount", GameVariable::DamageCount),
    ("damage_taken", GameVariable::DamageTaken),
    ("health", GameVariable::Health),
    ("armor", GameVariable::Armor),
    ("dead", GameVariable::Dead),
    ("on_ground", GameVariable::OnGround),
    ("attack_ready", GameVariable::AttackReady),
    ("altattack_ready", GameVariable::AltAttackReady),
    ("selected_weapon", GameVariable::SelectedWeapon),
    ("selected_weapon_ammo", GameVariable::SelectedWeaponAmmo),
    ("position_x", GameVariable::PositionX),
    ("position_y", GameVariable::PositionY),
    ("position_z", GameVariable::PositionZ),
    ("angle", GameVariable::Angle),
    ("pitch", GameVariable::Pitch),
    ("roll", GameVariable::Roll),
    ("view_height", GameVariable::ViewHeight),
    ("velocity_x", GameVariable::VelocityX),
    ("velocity_y", GameVariable::VelocityY),
    ("velocity_z", GameVariable::VelocityZ),
    ("camera_position_x", GameVariable::CameraPositionX),
    ("camera_position_y", GameVariable::CameraPositionY),
    ("camera_position_z", GameVariable::CameraPositionZ),
    ("camera_angle", GameVariable::CameraAngle),
    ("camera_pitch", GameVariable::CameraPitch),
    ("camera_roll", GameVariable::CameraRoll),
    ("camera_fov", GameVariable::CameraFov),
    ("player_number", GameVariable::PlayerNumber),
    ("player_count", GameVariable::PlayerCount),
];

impl GameVariable {
    pub fn from_cfg(name: &str) -> Option<GameVariable> {
        let numbered_variable = numbered(name, "ammo", "", 0..=9)
            .map(GameVariable::Ammo)
            .or_else(|| numbered(name, "weapon", "", 0..=9).map(GameVariable::Weapon))
            .or_else(|| numbered(name, "user", "", 1..=60).map(GameVariable::User))
            .or_else(|| numbered(name, "player", "_fragcount", 1..=16).map(GameVariable::PlayerFragCount));
        numbered_variable.or_else(|| GAME_VARIABLES.iter().find(|(n, _)| *n == name).map(|&(_, v)| v))
    }

    /// ViZDoom's enum name (`AMMO2`, `HEALTH`, `USER12`, ...).
    pub fn name(self) -> String {
        match self {
            GameVariable::Ammo(n) => format!("AMMO{n}"),
            GameVariable::Weapon(n) => format!("WEAPON{n}"),
            GameVariable::User(n) => format!("USER{n}"),
            GameVariable::PlayerFragCount(n) => format!("PLAYER{n}_FRAGCOUNT"),
            v => GAME_VARIABLES.iter().find(|(_, x)| *x == v).map_or_else(String::new, |(n, _)| n.to_ascii_uppercase()),
        }
    }
}

/// `prefix` + a number in `range` + `suffix`, the number written as ViZDoom
/// writes it (no sign, no leading zero): ViZDoom compares whole strings, so
/// `user07` is not `USER7`.
fn numbered(name: &str, prefix: &str, suffix: &str, range: std::ops::RangeInclusive<u8>) -> Option<u8> {
    let digits = name.strip_prefix(prefix)?.strip_suffix(suffix)?;
    let n: u8 = digits.parse().ok()?;
    (range.contains(&n) && n.to_string() == digits).then_some(n)
}

/// The screen size, one of ViZDoom's `RES_<W>X<H>` (width and height in
/// pixels).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ScreenResolution {
    pub width: u16,
    pub height: u16,
}

/// Every `ScreenResolution` ViZDoom has, in its order.
pub const RESOLUTIONS: [(u16, u16); 36] = [
    (160, 120),
    (200, 125),
    (200, 150),
    (256, 144),
    (256, 160),
    (256, 192),
    (320, 180),
    (320, 200),
    (320, 240),
    (320, 256),
    (400, 225),
    (400, 250),
    (400, 300),
    (512, 288),
    (512, 320),
    (512, 384),
    (640, 360),
    (640, 400),
    (640, 480),
    (800, 450),
    (800, 500),
    (800, 600),
    (1024, 576),
    (1024, 640),
    (1024, 768),
    (1280, 720),
    (1280, 800),
    (1280, 960),
    (1280, 1024),
    (1400, 787),
    (1400, 875),
    (1400, 1050),
    (1600, 900),
    (1600, 1000),
    (1600, 1200),
    (1920, 1080),
];

impl ScreenResolution {
    pub fn from_cfg(name: &str) -> Option<ScreenResolution> {
        let (w, h) = name.strip_prefix("res_")?.split_once('x')?;
        RESOLUTIONS
            .iter()
            .find(|(rw, rh)| rw.to_string() == w && rh.to_string() == h)
            .map(|&(width, height)| ScreenResolution { width, height })
    }
}

impl Default for ScreenResolution {
    fn default() -> Self {
        ScreenResolution { width: 320, height: 240 }
    }
}

impl fmt::Display for ScreenResolution {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "RES_{}X{}", self.width, self.height)
    }
}

/// How the screen buffer's pixels are laid out (ViZDoom's `ScreenFormat`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ScreenFormat {
    /// Three planes: red, green, blue.
    #[default]
    Crcgcb,
    Rgb24,
    Rgba32,
    Argb32,
    /// Three planes: blue, green, red.
    Cbcgcr,
    Bgr24,
    Bgra32,
    Abgr32,
    Gray8,
    /// Doom's palette indices.
    Doom256Colors8,
}

const SCREEN_FORMATS: [(&str, ScreenFormat); 10] = [
    ("crcgcb", ScreenFormat::Crcgcb),
    ("rgb24", ScreenFormat::Rgb24),
    ("rgba32", ScreenFormat::Rgba32),
    ("argb32", ScreenFormat::Argb32),
    ("cbcgcr", ScreenFormat::Cbcgcr),
    ("bgr24", ScreenFormat::Bgr24),
    ("bgra32", ScreenFormat::Bgra32),
    ("abgr32", ScreenFormat::Abgr32),
    ("gray8", ScreenFormat::Gray8),
    ("doom_256_colors8", ScreenFormat::Doom256Colors8),
];

/// Who drives the player, and whether the game waits for it (ViZDoom's
/// `Mode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Mode {
    /// The agent acts; the game waits for each action.
    #[default]
    Player,
    /// A human plays, the agent watches; the game waits.
    Spectator,
    /// The agent acts; the game runs at its ticrate without waiting.
    AsyncPlayer,
    /// A human plays at the ticrate, the agent watches.
    AsyncSpectator,
}

const MODES: [(&str, Mode); 4] = [
    ("player", Mode::Player),
    ("spectator", Mode::Spectator),
    ("async_player", Mode::AsyncPlayer),
    ("async_spectator", Mode::AsyncSpectator),
];

/// What the automap buffer shows (ViZDoom's `AutomapMode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum AutomapMode {
    /// What the player has seen.
    #[default]
    Normal,
    /// The whole map.
    Whole,
    /// The whole map and its things.
    Objects,
    /// The whole map and its things drawn at their size.
    ObjectsWithSize,
}

const AUTOMAP_MODES: [(&str, AutomapMode); 4] = [
    ("normal", AutomapMode::Normal),
    ("whole", AutomapMode::Whole),
    ("objects", AutomapMode::Objects),
    ("objects_with_size", AutomapMode::ObjectsWithSize),
];

/// The audio buffer's sampling rate (ViZDoom's `SamplingRate`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum SamplingRate {
    Sr11025,
    Sr22050,
    /// ViZDoom's default (`DoomController`'s `audioSamplingFreq = 44100`).
    #[default]
    Sr44100,
}

const SAMPLING_RATES: [(&str, SamplingRate); 3] =
    [("sr_11025", SamplingRate::Sr11025), ("sr_22050", SamplingRate::Sr22050), ("sr_44100", SamplingRate::Sr44100)];

impl SamplingRate {
    pub fn hertz(self) -> u32 {
        match self {
            SamplingRate::Sr11025 => 11025,
            SamplingRate::Sr22050 => 22050,
            SamplingRate::Sr44100 => 44100,
        }
    }
}

/// The field-less enums share their lookups: `from_cfg` reads the `.cfg`
/// spelling, `name` gives ViZDoom's enum name.
macro_rules! cfg_names {
    ($($ty:ident => $table:ident),+ $(,)?) => {$(
        impl $ty {
            pub fn from_cfg(name: &str) -> Option<$ty> {
                $table.iter().find(|(n, _)| *n == name).map(|&(_, v)| v)
            }

            pub fn name(self) -> String {
                $table.iter().find(|(_, v)| *v == self).map_or_else(String::new, |(n, _)| n.to_ascii_uppercase())
            }
        }
    )+};
}

cfg_names!(
    ScreenFormat => SCREEN_FORMATS,
    Mode => MODES,
    AutomapMode => AUTOMAP_MODES,
    SamplingRate => SAMPLING_RATES,
);
