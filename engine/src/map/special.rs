//! Specials: what a line, a sector or a thing does in play, written as typed
//! data a person can read (`Door(kind: Raise)`, `Lift()`, `Exit`), not as
//! Doom's numbers. The same types serve the RON source and the validated
//! [`super::Map`]; `sightline import` translates Doom's numbers into them
//! (`wad::specials`), and `play::world` carries them out.
//!
//! Every numeric parameter has Doom's value as its default, so
//! `Door(kind: Raise)` is Doom's door (2 units a tick, 150 ticks open) and a
//! map says only what differs. Speeds are map units per tick, waits are
//! ticks (35 a second).

use serde::{Deserialize, Serialize};

/// What sets a line special off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Activation {
    /// A body's centre crosses the line, either way (Doom's W lines).
    Walk,
    /// The player uses the line from its front (switches, and Doom's manual D doors).
    Use,
    /// A shot crosses the line (Doom's G lines).
    Shoot,
}

/// Who can set a line special off.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Who {
    /// The player only (most specials).
    #[default]
    Players,
    /// Monsters only (Doom's 125 and 126 teleporters).
    Monsters,
    /// Both: doors monsters open, lifts and teleporters they ride.
    Anyone,
}

impl Who {
    pub fn players(self) -> bool {
        self != Who::Monsters
    }

    pub fn monsters(self) -> bool {
        self != Who::Players
    }
}

/// A key colour. A door locked with a colour opens for the card or the skull
/// of that colour (vanilla Doom's rule).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum KeyColour {
    Blue,
    Yellow,
    Red,
}

impl KeyColour {
    pub const ALL: [KeyColour; 3] = [KeyColour::Blue, KeyColour::Yellow, KeyColour::Red];

    pub fn name(self) -> &'static str {
        match self {
            KeyColour::Blue => "blue",
            KeyColour::Yellow => "yellow",
            KeyColour::Red => "red",
        }
    }
}

/// A door's movement (Doom's `vldoor_e`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum DoorKind {
    /// Open, wait, close (Doom's "raise" doors: DR 1, W1 4, S1 29, ...).
    Raise,
    /// Open and stay open (D1 31, W1 2, S1 103, ...).
    Open,
    /// Close and stay closed (W1 3, S1 50, ...).
    Close,
    /// Close, wait shut, open again (W1 16: closes for 30 s).
    CloseThenOpen,
}

/// Where a floor moves to (Doom's `floor_e` targets, with [`Action::Floor`]'s
/// `offset` added). "Neighbour" means a sector sharing a two-sided line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FloorTarget {
    /// The lowest neighbouring floor, or the sector's own if it is lower.
    LowestNeighbourFloor,
    /// The highest neighbouring floor (the sector's own floor when it has
    /// no neighbour; Doom's -500 sentinel is not kept). As in Doom's turbo
    /// lower, the `offset` is not added when this is the floor's own height.
    HighestNeighbourFloor,
    /// The lowest neighbouring floor above this one (stays put if none).
    NextHigherFloor,
    /// The highest neighbouring floor below this one (stays put if none).
    NextLowerFloor,
    /// The sector's own ceiling.
    Ceiling,
    /// The lowest neighbouring ceiling, at most the sector's own ceiling.
    LowestNeighbourCeiling,
    /// The floor plus the height of the shortest lower texture on its lines
    /// (Doom's "raise to texture").
    ShortestLowerTexture,
    /// The floor where it is: with `offset` a move by that much (Doom's
    /// "raise by 24", "raise by 512").
    Current,
}

/// Where a ceiling moves to (Doom's `ceiling_e` targets, with `offset` added).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CeilingTarget {
    /// The sector's own floor.
    Floor,
    /// The highest neighbouring ceiling (the sector's own when it has none).
    HighestNeighbourCeiling,
    /// The lowest neighbouring ceiling (the sector's own when it has none).
    LowestNeighbourCeiling,
    /// The ceiling where it is: with `offset` a move by that much.
    Current,
}

/// Where a floor move takes its new texture (and maybe special) from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ChangeFrom {
    /// The front sector of the line that set the special off (Doom's
    /// "trigger model").
    Trigger,
    /// The neighbouring sector whose floor is at the destination (Doom's
    /// "numeric model"); nothing changes when there is none.
    Neighbour,
}

/// What happens to the moved sector's special along with its texture.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum SpecialChange {
    #[default]
    Keep,
    /// Take the model's special too (Doom's lower-and-change, raise-24-and-change).
    Copy,
    /// Clear it: no more damage or light effect (Doom's lifts that change texture).
    Clear,
}

/// A floor's change of texture on arrival (or, for a trigger model, at the start).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename = "Change", deny_unknown_fields)]
pub struct Change {
    pub from: ChangeFrom,
    #[serde(default, skip_serializing_if = "is_default")]
    pub special: SpecialChange,
}

/// A change of light level ([`Action::Light`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum LightChange {
    /// To this level, 0..=255 (Doom's 35 and 255 lines).
    Set(u8),
    /// To the brightest neighbouring sector's level (Doom's 12, 80).
    BrightestNeighbour,
    /// To the darkest neighbouring sector's level (Doom's 104).
    DimmestNeighbour,
    /// Start blinking: a slow strobe (Doom's 17).
    Strobe,
}

/// What a line special does. Sector actions act on every sector whose tag
/// is the special's, or, with no tag, on the sector behind the line (Doom's
/// manual doors).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Action {
    /// A door: the sector's ceiling moves between its floor and the lowest
    /// neighbouring ceiling less 4.
    Door {
        kind: DoorKind,
        #[serde(default = "door_speed", skip_serializing_if = "is_door_speed")]
        speed: f64,
        /// Ticks a raise door stays open.
        #[serde(default = "door_wait", skip_serializing_if = "is_door_wait")]
        wait: u32,
        /// Ticks a close-then-open door stays shut (Doom's 30 s).
        #[serde(default = "door_shut", skip_serializing_if = "is_door_shut")]
        shut: u32,
        /// Needs this key (card or skull) to open.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        key: Option<KeyColour>,
    },
    /// A lift: the floor goes down to the lowest neighbouring floor, waits,
    /// and comes back up (Doom's `downWaitUpStay`).
    Lift {
        #[serde(default = "lift_speed", skip_serializing_if = "is_lift_speed")]
        speed: f64,
        #[serde(default = "lift_wait", skip_serializing_if = "is_lift_wait")]
        wait: u32,
    },
    /// A lift that goes between the lowest and highest neighbouring floors
    /// for ever, waiting at each end, until stopped.
    PerpetualLift {
        #[serde(default = "perpetual_speed", skip_serializing_if = "is_perpetual_speed")]
        speed: f64,
        #[serde(default = "lift_wait", skip_serializing_if = "is_lift_wait")]
        wait: u32,
    },
    /// Stops perpetual lifts where they are.
    StopLift,
    /// The floor moves to `to` plus `offset`, up or down, once.
    Floor {
        to: FloorTarget,
        #[serde(default, skip_serializing_if = "is_zero")]
        offset: f64,
        #[serde(default = "floor_speed", skip_serializing_if = "is_floor_speed")]
        speed: f64,
        /// Keeps rising through bodies, hurting them (else it stops while blocked).
        #[serde(default, skip_serializing_if = "is_false")]
        crush: bool,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        change: Option<Change>,
    },
    /// The ceiling moves to `to` plus `offset`, once.
    Ceiling {
        to: CeilingTarget,
        #[serde(default, skip_serializing_if = "is_zero")]
        offset: f64,
        #[serde(default = "floor_speed", skip_serializing_if = "is_floor_speed")]
        speed: f64,
        #[serde(default, skip_serializing_if = "is_false")]
        crush: bool,
    },
    /// A crusher: the ceiling goes down to 8 above the floor and back up,
    /// for ever, hurting what is under it; it slows to an eighth of its speed
    /// while crushing (unless fast).
    Crusher {
        #[serde(default = "floor_speed", skip_serializing_if = "is_floor_speed")]
        speed: f64,
        #[serde(default, skip_serializing_if = "is_false")]
        silent: bool,
    },
    /// Stops crushers where they are (a later crusher special restarts them).
    StopCrusher,
    /// Stairs: the tagged sector rises by `step`, then each next sector in
    /// line (through its front-facing two-sided lines, same floor texture)
    /// by one step more.
    Stairs {
        #[serde(default = "stair_step", skip_serializing_if = "is_stair_step")]
        step: f64,
        #[serde(default = "stair_speed", skip_serializing_if = "is_stair_speed")]
        speed: f64,
        /// Steps keep rising through bodies, hurting them (Doom's turbo stairs).
        #[serde(default, skip_serializing_if = "is_false")]
        crush: bool,
    },
    /// A donut: the tagged sector's floor lowers to the floor of the ring's
    /// outside, and the ring (the sector around it) rises to that height
    /// taking its texture.
    Donut {
        #[serde(default = "donut_speed", skip_serializing_if = "is_donut_speed")]
        speed: f64,
    },
    /// Changes the light level of the tagged sectors at once.
    Light(LightChange),
    /// Teleports the body to the teleport destination in a tagged sector.
    Teleport,
    /// Moves the body to the same place relative to line `to` as it was to
    /// this one, turned by the angle between the lines, keeping its speed
    /// and its height above the floor: no fog, no sound (Boom's 244).
    LineTeleport { to: usize },
    /// Ends the level; the next map follows.
    Exit,
    /// Ends the level; the secret next map follows.
    SecretExit,
}

impl Action {
    /// Does it act on sectors (by tag, or the sector behind the line)?
    pub fn moves_sectors(&self) -> bool {
        !matches!(self, Action::Exit | Action::SecretExit | Action::Teleport | Action::LineTeleport { .. })
    }

    /// A short name for messages ("door", "lift", ...).
    pub fn name(&self) -> &'static str {
        match self {
            Action::Door { .. } => "door",
            Action::Lift { .. } => "lift",
            Action::PerpetualLift { .. } => "perpetual lift",
            Action::StopLift => "lift stop",
            Action::Floor { .. } => "floor",
            Action::Ceiling { .. } => "ceiling",
            Action::Crusher { .. } => "crusher",
            Action::StopCrusher => "crusher stop",
            Action::Stairs { .. } => "stairs",
            Action::Donut { .. } => "donut",
            Action::Light(_) => "light change",
            Action::Teleport | Action::LineTeleport { .. } => "teleporter",
            Action::Exit => "exit",
            Action::SecretExit => "secret exit",
        }
    }
}

/// A line's special: what it does, what sets it off and how often.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineSpecial {
    pub on: Activation,
    /// Works every time (Doom's R lines); else once (1 lines).
    pub repeat: bool,
    pub by: Who,
    /// The sectors it acts on; 0 is the sector behind the line.
    pub tag: u16,
    pub action: Action,
}

/// A sector's lighting effect (Doom's sector types 1, 2, 3, 8, 12, 13, 17).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum LightEffect {
    /// Off for a random time, on for a random time (type 1).
    BlinkRandom,
    /// Dark 15 ticks, bright 5 (type 2), starting at a random point.
    StrobeFast,
    /// Dark 35 ticks, bright 5 (type 3), starting at a random point.
    StrobeSlow,
    /// [`Self::StrobeFast`] in step with every other synchronised strobe (type 13).
    StrobeFastSync,
    /// [`Self::StrobeSlow`] in step (type 12).
    StrobeSlowSync,
    /// Glows down to the dimmest neighbour and back, 8 levels a tick (type 8).
    Glow,
    /// Flickers like fire (type 17).
    Flicker,
}

/// Damage to a player standing on the floor (Doom's nukage and lava).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename = "Damage", deny_unknown_fields)]
pub struct Damage {
    /// Health lost each time.
    pub amount: u32,
    /// Ticks between hurts (Doom: 32).
    #[serde(default = "damage_every", skip_serializing_if = "is_damage_every")]
    pub every: u32,
    /// Ends the level when the player's health falls to this or below
    /// (Doom's type 11, E1M8's exit floor); 0 never does.
    #[serde(default, skip_serializing_if = "is_zero_u32")]
    pub exit_below: u32,
    /// What a radiation suit does against it.
    #[serde(default, skip_serializing_if = "Suit::is_default")]
    pub suit: Suit,
}

/// What a radiation suit does against a damaging floor. Doom's suit shields
/// from its 5 and 10 floors, lets its 20 floors through now and then
/// ([`SUIT_LEAK`] hurts in 256), and does nothing on E1M8's exit floor.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Suit {
    /// No hurt while the suit lasts.
    #[default]
    Shields,
    /// A hurt only when a random byte is below [`SUIT_LEAK`].
    Leaks,
    /// The floor hurts as if there were no suit.
    Useless,
}

/// Doom's chance, in 256, that a 20-damage floor hurts through the suit.
pub const SUIT_LEAK: u8 = 5;

impl Suit {
    fn is_default(&self) -> bool {
        *self == Suit::Shields
    }
}

/// A timed door in a sector (Doom's types 10 and 14).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum DoorTimer {
    /// The open door closes 30 s into the level (type 10).
    CloseIn30s,
    /// The shut door opens 5 minutes into the level (type 14).
    RaiseIn5Min,
}

/// A sector's special: any of a light effect, damage, being a secret, and a
/// door timer (Doom's sector types, and Boom's generalized ones, which
/// combine them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename = "SectorSpecial", deny_unknown_fields)]
pub struct SectorSpecial {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light: Option<LightEffect>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damage: Option<Damage>,
    /// Counted as found when the player enters it.
    #[serde(default, skip_serializing_if = "is_false")]
    pub secret: bool,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub timer: Option<DoorTimer>,
}

impl SectorSpecial {
    pub fn is_none(&self) -> bool {
        *self == SectorSpecial::default()
    }
}

/// Doom's skill levels as its thing flags group them: easy (skills 1 and
/// 2), medium (3), hard (4 and 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum SkillBand {
    Easy,
    Medium,
    Hard,
}

impl SkillBand {
    pub const ALL: [SkillBand; 3] = [SkillBand::Easy, SkillBand::Medium, SkillBand::Hard];

    /// The band of a skill level 1..=5 (out-of-range levels clamp).
    pub fn of_skill(skill: u8) -> SkillBand {
        match skill {
            0..=2 => SkillBand::Easy,
            3 => SkillBand::Medium,
            _ => SkillBand::Hard,
        }
    }
}

/// Scrolling in map units per tick: x along the side (positive moves the
/// texture towards its start, as Doom's 48 "scroll left"), y down.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scroll {
    pub x: f64,
    pub y: f64,
}

pub const DOOR_SPEED: f64 = 2.0;
pub const DOOR_WAIT: u32 = 150;
pub const DOOR_SHUT: u32 = 30 * 35;
pub const LIFT_SPEED: f64 = 4.0;
pub const LIFT_WAIT: u32 = 105;
pub const PERPETUAL_SPEED: f64 = 1.0;
pub const FLOOR_SPEED: f64 = 1.0;
pub const STAIR_STEP: f64 = 8.0;
pub const STAIR_SPEED: f64 = 0.25;
pub const DONUT_SPEED: f64 = 0.5;
pub const DAMAGE_EVERY: u32 = 32;

/// The serde default of a field and its "is the default" test, for each
/// Doom constant above.
macro_rules! defaults {
    ($($value:ident, $is:ident: $ty:ty = $constant:ident;)*) => {
        $(
            fn $value() -> $ty {
                $constant
            }
            fn $is(v: &$ty) -> bool {
                *v == $constant
            }
        )*
    };
}

defaults! {
    door_speed, is_door_speed: f64 = DOOR_SPEED;
    door_wait, is_door_wait: u32 = DOOR_WAIT;
    door_shut, is_door_shut: u32 = DOOR_SHUT;
    lift_speed, is_lift_speed: f64 = LIFT_SPEED;
    lift_wait, is_lift_wait: u32 = LIFT_WAIT;
    perpetual_speed, is_perpetual_speed: f64 = PERPETUAL_SPEED;
    floor_speed, is_floor_speed: f64 = FLOOR_SPEED;
    stair_step, is_stair_step: f64 = STAIR_STEP;
    stair_speed, is_stair_speed: f64 = STAIR_SPEED;
    donut_speed, is_donut_speed: f64 = DONUT_SPEED;
    damage_every, is_damage_every: u32 = DAMAGE_EVERY;
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}
fn is_zero_u32(v: &u32) -> bool {
    *v == 0
}
fn is_false(v: &bool) -> bool {
    !*v
}
fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}
