//! Doom's special numbers translated into Sightline's typed specials: every
//! vanilla line special, the Boom ones Freedoom uses (scrollers, light
//! transfers, translucency, conveyors, the silent line teleporter) and
//! Boom's generalized line types; Doom's sector types and Boom's
//! generalized sector bits. Facts from Doom's p_spec.c, p_switch.c,
//! p_doors.c, p_plats.c, p_floor.c and p_ceilng.c, and Boom's p_genlin.c
//! (speeds in map units per tick, waits in ticks).

use crate::map::source::LineSpecialSource;
use crate::map::special::{
    Action, Activation, CeilingTarget, Change, ChangeFrom, Damage, DoorKind, DoorTimer, FloorTarget, KeyColour,
    LightChange, LightEffect, Scroll, SectorSpecial, SpecialChange, Suit, Who, DOOR_SHUT, DOOR_SPEED, DOOR_WAIT,
    FLOOR_SPEED, LIFT_SPEED, LIFT_WAIT, PERPETUAL_SPEED, STAIR_SPEED, STAIR_STEP,
};

/// What a line special number comes to.
#[derive(Clone, Debug, PartialEq)]
pub enum Effect {
    /// A special the line carries (its `tag` already set).
    Special(LineSpecialSource),
    /// The line's front side scrolls (48, 85).
    Scroll(Scroll),
    /// The tagged sectors' floor (or ceiling) is lit as the line's front
    /// sector (213, 261).
    LightTransfer { floor: bool },
    /// Middle textures of the tagged lines (or this one, with tag 0) are
    /// drawn translucent (260).
    Translucent,
    /// The tagged sectors carry bodies along the line's direction (252).
    Carry,
    /// Boom's silent line teleport (244): to the other line with the tag.
    LineTeleport,
    /// A number Doom and Boom do nothing with; the reason says what it is elsewhere.
    Ignored(&'static str),
}

/// The trigger of a special: how it goes off and how often.
#[derive(Clone, Copy)]
struct Trigger {
    on: Activation,
    repeat: bool,
    /// A manual (D) special: acts on the sector behind the line, no tag.
    manual: bool,
}

const W1: Trigger = Trigger { on: Activation::Walk, repeat: false, manual: false };
const WR: Trigger = Trigger { on: Activation::Walk, repeat: true, manual: false };
const S1: Trigger = Trigger { on: Activation::Use, repeat: false, manual: false };
const SR: Trigger = Trigger { on: Activation::Use, repeat: true, manual: false };
const G1: Trigger = Trigger { on: Activation::Shoot, repeat: false, manual: false };
const GR: Trigger = Trigger { on: Activation::Shoot, repeat: true, manual: false };
const D1: Trigger = Trigger { on: Activation::Use, repeat: false, manual: true };
const DR: Trigger = Trigger { on: Activation::Use, repeat: true, manual: true };

/// Blazing doors and lifts move at 8 (Doom's 4 x VDOORSPEED, 8 x PLATSPEED).
const BLAZE: f64 = 8.0;

fn special(t: Trigger, by: Who, tag: u16, action: Action) -> Effect {
    let tag = if t.manual { 0 } else { i64::from(tag) };
    Effect::Special(LineSpecialSource { on: t.on, repeat: t.repeat, by, tag, action })
}

fn door(kind: DoorKind, speed: f64, key: Option<KeyColour>) -> Action {
    Action::Door { kind, speed, wait: DOOR_WAIT, shut: DOOR_SHUT, key }
}

fn floor(to: FloorTarget, offset: f64, speed: f64, crush: bool, change: Option<Change>) -> Action {
    Action::Floor { to, offset, speed, crush, change }
}

/// Doom's "raise and change" lifts: the floor rises at half speed, taking
/// the trigger line's front sector's floor texture at once.
fn raise_and_change(to: FloorTarget, offset: f64, special: SpecialChange) -> Action {
    floor(to, offset, 0.5, false, Some(Change { from: ChangeFrom::Trigger, special }))
}

/// Translates line special `number` (not 0) with the line's `tag`. `Err`
/// names what it is when it cannot be translated.
pub fn translate(number: u16, tag: u16) -> Result<Effect, String> {
    use Action as A;
    use DoorKind::{Close, CloseThenOpen, Open, Raise};
    use FloorTarget as F;
    use KeyColour::{Blue, Red, Yellow};
    use Who::{Anyone, Monsters, Players as P};
    let s = |t, by, action| Ok(special(t, by, tag, action));
    let d = DOOR_SPEED;
    match number {
        // Doors (p_doors.c, p_switch.c, p_spec.c).
        1 => s(DR, Anyone, door(Raise, d, None)),
        2 => s(W1, P, door(Open, d, None)),
        3 => s(W1, P, door(Close, d, None)),
        4 => s(W1, Anyone, door(Raise, d, None)),
        16 => s(W1, P, door(CloseThenOpen, d, None)),
        26 => s(DR, P, door(Raise, d, Some(Blue))),
        27 => s(DR, P, door(Raise, d, Some(Yellow))),
        28 => s(DR, P, door(Raise, d, Some(Red))),
        29 => s(S1, P, door(Raise, d, None)),
        31 => s(D1, P, door(Open, d, None)),
        32 => s(D1, P, door(Open, d, Some(Blue))),
        33 => s(D1, P, door(Open, d, Some(Red))),
        34 => s(D1, P, door(Open, d, Some(Yellow))),
        42 => s(SR, P, door(Close, d, None)),
        46 => s(GR, Anyone, door(Open, d, None)),
        50 => s(S1, P, door(Close, d, None)),
        61 => s(SR, P, door(Open, d, None)),
        63 => s(SR, P, door(Raise, d, None)),
        75 => s(WR, P, door(Close, d, None)),
        76 => s(WR, P, door(CloseThenOpen, d, None)),
        86 => s(WR, P, door(Open, d, None)),
        90 => s(WR, P, door(Raise, d, None)),
        99 => s(SR, P, door(Open, BLAZE, Some(Blue))),
        103 => s(S1, P, door(Open, d, None)),
        105 => s(WR, P, door(Raise, BLAZE, None)),
        106 => s(WR, P, door(Open, BLAZE, None)),
        107 => s(WR, P, door(Close, BLAZE, None)),
        108 => s(W1, P, door(Raise, BLAZE, None)),
        109 => s(W1, P, door(Open, BLAZE, None)),
        110 => s(W1, P, door(Close, BLAZE, None)),
        111 => s(S1, P, door(Raise, BLAZE, None)),
        112 => s(S1, P, door(Open, BLAZE, None)),
        113 => s(S1, P, door(Close, BLAZE, None)),
        114 => s(SR, P, door(Raise, BLAZE, None)),
        115 => s(SR, P, door(Open, BLAZE, None)),
        116 => s(SR, P, door(Close, BLAZE, None)),
        117 => s(DR, P, door(Raise, BLAZE, None)),
        118 => s(D1, P, door(Open, BLAZE, None)),
        133 => s(S1, P, door(Open, BLAZE, Some(Blue))),
        134 => s(SR, P, door(Open, BLAZE, Some(Red))),
        135 => s(S1, P, door(Open, BLAZE, Some(Red))),
        136 => s(SR, P, door(Open, BLAZE, Some(Yellow))),
        137 => s(S1, P, door(Open, BLAZE, Some(Yellow))),
        // Floors (p_floor.c EV_DoFloor).
        5 => s(W1, P, floor(F::LowestNeighbourCeiling, 0.0, 1.0, false, None)),
        24 => s(G1, P, floor(F::LowestNeighbourCeiling, 0.0, 1.0, false, None)),
        64 => s(SR, P, floor(F::LowestNeighbourCeiling, 0.0, 1.0, false, None)),
        91 => s(WR, P, floor(F::LowestNeighbourCeiling, 0.0, 1.0, false, None)),
        101 => s(S1, P, floor(F::LowestNeighbourCeiling, 0.0, 1.0, false, None)),
        55 => s(S1, P, floor(F::LowestNeighbourCeiling, -8.0, 1.0, true, None)),
        56 => s(W1, P, floor(F::LowestNeighbourCeiling, -8.0, 1.0, true, None)),
        65 => s(SR, P, floor(F::LowestNeighbourCeiling, -8.0, 1.0, true, None)),
        94 => s(WR, P, floor(F::LowestNeighbourCeiling, -8.0, 1.0, true, None)),
        18 => s(S1, P, floor(F::NextHigherFloor, 0.0, 1.0, false, None)),
        69 => s(SR, P, floor(F::NextHigherFloor, 0.0, 1.0, false, None)),
        119 => s(W1, P, floor(F::NextHigherFloor, 0.0, 1.0, false, None)),
        128 => s(WR, P, floor(F::NextHigherFloor, 0.0, 1.0, false, None)),
        129 => s(WR, P, floor(F::NextHigherFloor, 0.0, 4.0, false, None)),
        130 => s(W1, P, floor(F::NextHigherFloor, 0.0, 4.0, false, None)),
        131 => s(S1, P, floor(F::NextHigherFloor, 0.0, 4.0, false, None)),
        132 => s(SR, P, floor(F::NextHigherFloor, 0.0, 4.0, false, None)),
        19 => s(W1, P, floor(F::HighestNeighbourFloor, 0.0, 1.0, false, None)),
        45 => s(SR, P, floor(F::HighestNeighbourFloor, 0.0, 1.0, false, None)),
        83 => s(WR, P, floor(F::HighestNeighbourFloor, 0.0, 1.0, false, None)),
        102 => s(S1, P, floor(F::HighestNeighbourFloor, 0.0, 1.0, false, None)),
        36 => s(W1, P, floor(F::HighestNeighbourFloor, 8.0, 4.0, false, None)),
        70 => s(SR, P, floor(F::HighestNeighbourFloor, 8.0, 4.0, false, None)),
        71 => s(S1, P, floor(F::HighestNeighbourFloor, 8.0, 4.0, false, None)),
        98 => s(WR, P, floor(F::HighestNeighbourFloor, 8.0, 4.0, false, None)),
        23 => s(S1, P, floor(F::LowestNeighbourFloor, 0.0, 1.0, false, None)),
        38 => s(W1, P, floor(F::LowestNeighbourFloor, 0.0, 1.0, false, None)),
        60 => s(SR, P, floor(F::LowestNeighbourFloor, 0.0, 1.0, false, None)),
        82 => s(WR, P, floor(F::LowestNeighbourFloor, 0.0, 1.0, false, None)),
        37 | 84 => {
            let change = Some(Change { from: ChangeFrom::Neighbour, special: SpecialChange::Copy });
            s(if number == 37 { W1 } else { WR }, P, floor(F::LowestNeighbourFloor, 0.0, 1.0, false, change))
        }
        58 => s(W1, P, floor(F::Current, 24.0, 1.0, false, None)),
        92 => s(WR, P, floor(F::Current, 24.0, 1.0, false, None)),
        59 | 93 => {
            let change = Some(Change { from: ChangeFrom::Trigger, special: SpecialChange::Copy });
            s(if number == 59 { W1 } else { WR }, P, floor(F::Current, 24.0, 1.0, false, change))
        }
        30 => s(W1, P, floor(F::ShortestLowerTexture, 0.0, 1.0, false, None)),
        96 => s(WR, P, floor(F::ShortestLowerTexture, 0.0, 1.0, false, None)),
        140 => s(S1, P, floor(F::Current, 512.0, 1.0, false, None)),
        // Raise-and-change lifts (p_plats.c raiseAndChange, raiseToNearestAndChange).
        14 => s(S1, P, raise_and_change(F::Current, 32.0, SpecialChange::Keep)),
        15 => s(S1, P, raise_and_change(F::Current, 24.0, SpecialChange::Keep)),
        66 => s(SR, P, raise_and_change(F::Current, 24.0, SpecialChange::Keep)),
        67 => s(SR, P, raise_and_change(F::Current, 32.0, SpecialChange::Keep)),
        20 => s(S1, P, raise_and_change(F::NextHigherFloor, 0.0, SpecialChange::Clear)),
        22 => s(W1, P, raise_and_change(F::NextHigherFloor, 0.0, SpecialChange::Clear)),
        47 => s(G1, P, raise_and_change(F::NextHigherFloor, 0.0, SpecialChange::Clear)),
        68 => s(SR, P, raise_and_change(F::NextHigherFloor, 0.0, SpecialChange::Clear)),
        95 => s(WR, P, raise_and_change(F::NextHigherFloor, 0.0, SpecialChange::Clear)),
        // Lifts (p_plats.c).
        10 => s(W1, Anyone, A::Lift { speed: LIFT_SPEED, wait: LIFT_WAIT }),
        21 => s(S1, P, A::Lift { speed: LIFT_SPEED, wait: LIFT_WAIT }),
        62 => s(SR, P, A::Lift { speed: LIFT_SPEED, wait: LIFT_WAIT }),
        88 => s(WR, Anyone, A::Lift { speed: LIFT_SPEED, wait: LIFT_WAIT }),
        120 => s(WR, P, A::Lift { speed: BLAZE, wait: LIFT_WAIT }),
        121 => s(W1, P, A::Lift { speed: BLAZE, wait: LIFT_WAIT }),
        122 => s(S1, P, A::Lift { speed: BLAZE, wait: LIFT_WAIT }),
        123 => s(SR, P, A::Lift { speed: BLAZE, wait: LIFT_WAIT }),
        53 => s(W1, P, A::PerpetualLift { speed: PERPETUAL_SPEED, wait: LIFT_WAIT }),
        87 => s(WR, P, A::PerpetualLift { speed: PERPETUAL_SPEED, wait: LIFT_WAIT }),
        54 => s(W1, P, A::StopLift),
        89 => s(WR, P, A::StopLift),
        // Ceilings and crushers (p_ceilng.c). Special 40 also names a floor
        // lower, which never runs in Doom (the ceiling takes the sector).
        40 => {
            s(W1, P, A::Ceiling { to: CeilingTarget::HighestNeighbourCeiling, offset: 0.0, speed: 1.0, crush: false })
        }
        41 => s(S1, P, A::Ceiling { to: CeilingTarget::Floor, offset: 0.0, speed: 1.0, crush: false }),
        43 => s(SR, P, A::Ceiling { to: CeilingTarget::Floor, offset: 0.0, speed: 1.0, crush: false }),
        44 => s(W1, P, A::Ceiling { to: CeilingTarget::Floor, offset: 8.0, speed: 1.0, crush: false }),
        72 => s(WR, P, A::Ceiling { to: CeilingTarget::Floor, offset: 8.0, speed: 1.0, crush: false }),
        6 => s(W1, P, A::Crusher { speed: 2.0, silent: false }),
        77 => s(WR, P, A::Crusher { speed: 2.0, silent: false }),
        25 => s(W1, P, A::Crusher { speed: 1.0, silent: false }),
        49 => s(S1, P, A::Crusher { speed: 1.0, silent: false }),
        73 => s(WR, P, A::Crusher { speed: 1.0, silent: false }),
        141 => s(W1, P, A::Crusher { speed: 1.0, silent: true }),
        57 => s(W1, P, A::StopCrusher),
        74 => s(WR, P, A::StopCrusher),
        // Stairs and donut (p_floor.c EV_BuildStairs, p_spec.c EV_DoDonut).
        7 => s(S1, P, A::Stairs { step: STAIR_STEP, speed: STAIR_SPEED, crush: false }),
        8 => s(W1, P, A::Stairs { step: STAIR_STEP, speed: STAIR_SPEED, crush: false }),
        100 => s(W1, P, A::Stairs { step: 16.0, speed: 4.0, crush: true }),
        127 => s(S1, P, A::Stairs { step: 16.0, speed: 4.0, crush: true }),
        9 => s(S1, P, A::Donut { speed: 0.5 }),
        // Lights (p_lights.c).
        12 => s(W1, P, A::Light(LightChange::BrightestNeighbour)),
        80 => s(WR, P, A::Light(LightChange::BrightestNeighbour)),
        13 => s(W1, P, A::Light(LightChange::Set(255))),
        81 => s(WR, P, A::Light(LightChange::Set(255))),
        138 => s(SR, P, A::Light(LightChange::Set(255))),
        35 => s(W1, P, A::Light(LightChange::Set(35))),
        79 => s(WR, P, A::Light(LightChange::Set(35))),
        139 => s(SR, P, A::Light(LightChange::Set(35))),
        104 => s(W1, P, A::Light(LightChange::DimmestNeighbour)),
        17 => s(W1, P, A::Light(LightChange::Strobe)),
        // Teleporters (p_telept.c).
        39 => s(W1, Anyone, A::Teleport),
        97 => s(WR, Anyone, A::Teleport),
        125 => s(W1, Monsters, A::Teleport),
        126 => s(WR, Monsters, A::Teleport),
        // Exits (p_switch.c, p_spec.c); the level ends, so once is enough.
        11 => s(S1, P, A::Exit),
        51 => s(S1, P, A::SecretExit),
        52 => s(W1, P, A::Exit),
        124 => s(W1, P, A::SecretExit),
        // Effects that are not set off (p_spec.c P_SpawnSpecials, Boom's scrollers).
        48 => Ok(Effect::Scroll(Scroll { x: 1.0, y: 0.0 })),
        85 => Ok(Effect::Scroll(Scroll { x: -1.0, y: 0.0 })),
        213 => Ok(Effect::LightTransfer { floor: true }),
        261 => Ok(Effect::LightTransfer { floor: false }),
        260 => Ok(Effect::Translucent),
        252 => Ok(Effect::Carry),
        244 => Ok(Effect::LineTeleport),
        // Numbers of other ports' specials; Doom and Boom do nothing with
        // them (Boom refuses its own 160 and 181 with tag 0).
        160 if tag == 0 => Ok(Effect::Ignored("ZDoom's 3D floor, or Boom's 160 with no tag; Doom and Boom do nothing")),
        181 if tag == 0 => Ok(Effect::Ignored("ZDoom's slope, or Boom's 181 with no tag; Doom and Boom do nothing")),
        340 => Ok(Effect::Ignored("Eternity's and ZDoom's floor slope; Doom and Boom do nothing")),
        0x2F80..=0x7FFF => generalized(number, tag),
        _ => Err(format!("line special {number} (not a Doom or Boom special Sightline knows)")),
    }
}

/// Boom's generalized line types (p_genlin.c): bit fields for the
/// trigger, speed, and what moves where.
fn generalized(number: u16, tag: u16) -> Result<Effect, String> {
    let unsupported = |what: &str| Err(format!("generalized line type {number:#06x} ({what})"));
    let (base, kind) = match number {
        0x6000..=0x7FFF => (0x6000, "floor"),
        0x4000..=0x5FFF => (0x4000, "ceiling"),
        0x3C00..=0x3FFF => (0x3C00, "door"),
        0x3800..=0x3BFF => (0x3800, "locked door"),
        0x3400..=0x37FF => (0x3400, "lift"),
        0x3000..=0x33FF => (0x3000, "stairs"),
        _ => (0x2F80, "crusher"),
    };
    let v = number - base;
    let trigger = [W1, WR, S1, SR, G1, GR, D1, DR][usize::from(v & 7)];
    let speed = usize::from((v >> 3) & 3);
    let monsters = |bit: u16| if v >> bit & 1 == 1 { Who::Anyone } else { Who::Players };
    let s = |by, action| Ok(special(trigger, by, tag, action));
    match kind {
        "floor" => {
            let change = (v >> 10) & 3;
            let model = if (v >> 5) & 1 == 1 { ChangeFrom::Neighbour } else { ChangeFrom::Trigger };
            let up = (v >> 6) & 1 == 1;
            let sign = if up { 1.0 } else { -1.0 };
            let (to, offset) = match (v >> 7) & 7 {
                0 => (FloorTarget::HighestNeighbourFloor, 0.0),
                1 => (FloorTarget::LowestNeighbourFloor, 0.0),
                2 if up => (FloorTarget::NextHigherFloor, 0.0),
                2 => (FloorTarget::NextLowerFloor, 0.0),
                3 => (FloorTarget::LowestNeighbourCeiling, 0.0),
                4 => (FloorTarget::Ceiling, 0.0),
                5 if up => (FloorTarget::ShortestLowerTexture, 0.0),
                5 => return unsupported("floor down by the shortest lower texture"),
                6 => (FloorTarget::Current, 24.0 * sign),
                _ => (FloorTarget::Current, 32.0 * sign),
            };
            let special = match change {
                0 => None,
                1 => Some(SpecialChange::Clear),
                2 => Some(SpecialChange::Keep),
                _ => Some(SpecialChange::Copy),
            };
            let change = special.map(|special| Change { from: model, special });
            let by = if change.is_none() { monsters(5) } else { Who::Players };
            let speed = [1.0, 2.0, 4.0, 8.0][speed] * FLOOR_SPEED;
            s(by, floor(to, offset, speed, (v >> 12) & 1 == 1, change))
        }
        "ceiling" => {
            if (v >> 10) & 3 != 0 {
                return unsupported("ceiling texture change");
            }
            let up = (v >> 6) & 1 == 1;
            let sign = if up { 1.0 } else { -1.0 };
            let (to, offset) = match (v >> 7) & 7 {
                0 => (CeilingTarget::HighestNeighbourCeiling, 0.0),
                1 => (CeilingTarget::LowestNeighbourCeiling, 0.0),
                4 => (CeilingTarget::Floor, 0.0),
                6 => (CeilingTarget::Current, 24.0 * sign),
                7 => (CeilingTarget::Current, 32.0 * sign),
                _ => return unsupported("ceiling to the next ceiling, a floor, or by a texture"),
            };
            let speed = [1.0, 2.0, 4.0, 8.0][speed];
            s(monsters(5), Action::Ceiling { to, offset, speed, crush: (v >> 12) & 1 == 1 })
        }
        "door" => {
            let kind =
                [DoorKind::Raise, DoorKind::Open, DoorKind::CloseThenOpen, DoorKind::Close][usize::from((v >> 5) & 3)];
            let wait = [35, 150, 300, 1050][usize::from((v >> 8) & 3)];
            let speed = [2.0, 4.0, 8.0, 16.0][speed];
            // One delay field: how long the door stays open, or shut.
            s(monsters(7), Action::Door { kind, speed, wait, shut: wait, key: None })
        }
        "locked door" => {
            let kind = if (v >> 5) & 1 == 0 { DoorKind::Raise } else { DoorKind::Open };
            let either = (v >> 9) & 1 == 1;
            let key = match ((v >> 6) & 7, either) {
                (1, true) | (4, true) => KeyColour::Red,
                (2, true) | (5, true) => KeyColour::Blue,
                (3, true) | (6, true) => KeyColour::Yellow,
                (1..=6, false) => return unsupported("a lock that wants a card or a skull, not either"),
                _ => return unsupported("a lock that wants any key or all keys"),
            };
            let speed = [2.0, 4.0, 8.0, 16.0][speed];
            s(Who::Players, Action::Door { kind, speed, wait: DOOR_WAIT, shut: DOOR_SHUT, key: Some(key) })
        }
        "lift" => {
            let wait = [35, 105, 175, 350][usize::from((v >> 6) & 3)];
            let speed = [2.0, 4.0, 8.0, 16.0][speed];
            match (v >> 8) & 3 {
                0 => s(monsters(5), Action::Lift { speed, wait }),
                3 => s(monsters(5), Action::PerpetualLift { speed, wait }),
                _ => unsupported("a lift to the next lower floor or to the ceiling"),
            }
        }
        "stairs" => {
            if (v >> 9) & 1 == 1 {
                return unsupported("stairs that ignore the floor texture");
            }
            let step = [4.0, 8.0, 16.0, 24.0][usize::from((v >> 6) & 3)];
            let step = if (v >> 8) & 1 == 1 { step } else { -step };
            let speed = [0.25, 0.5, 2.0, 4.0][speed];
            s(monsters(5), Action::Stairs { step, speed, crush: false })
        }
        _ => {
            let speed = [1.0, 2.0, 4.0, 8.0][speed];
            s(monsters(5), Action::Crusher { speed, silent: (v >> 6) & 1 == 1 })
        }
    }
}

/// Translates sector type `number`: Doom's types 1 to 17 and Boom's
/// generalized bits (light 0-4, damage 5-6, secret 7). `Err` names what
/// cannot be translated.
pub fn sector_special(number: i16) -> Result<SectorSpecial, String> {
    let n = number as u16;
    let mut s = SectorSpecial::default();
    // Doom's suit shields from 5 and 10 and lets 20 through now and then.
    let damage = |amount| {
        let suit = if amount >= 20 { Suit::Leaks } else { Suit::Shields };
        Some(Damage { amount, every: 32, exit_below: 0, suit })
    };
    s.light = match n & 31 {
        1 => Some(LightEffect::BlinkRandom),
        2 | 4 => Some(LightEffect::StrobeFast),
        3 => Some(LightEffect::StrobeSlow),
        8 => Some(LightEffect::Glow),
        12 => Some(LightEffect::StrobeSlowSync),
        13 => Some(LightEffect::StrobeFastSync),
        17 => Some(LightEffect::Flicker),
        _ => None,
    };
    match n & 31 {
        0 | 1 | 2 | 3 | 8 | 12 | 13 | 17 => {}
        4 | 16 => s.damage = damage(20),
        5 => s.damage = damage(10),
        7 => s.damage = damage(5),
        9 => s.secret = true,
        10 => s.timer = Some(DoorTimer::CloseIn30s),
        11 => s.damage = Some(Damage { amount: 20, every: 32, exit_below: 10, suit: Suit::Useless }),
        14 => s.timer = Some(DoorTimer::RaiseIn5Min),
        // Name the number the WAD holds: for a Boom generalized type (32 and
        // up) the bad part is only its low five bits.
        other if n < 32 => return Err(format!("sector type {other} (not a Doom sector type)")),
        other => return Err(format!("sector type {number} (its low five bits, {other}, are not a Doom sector type)")),
    }
    if n < 32 {
        return Ok(s);
    }
    match (n >> 5) & 3 {
        0 => {}
        1 => s.damage = damage(5),
        2 => s.damage = damage(10),
        _ => s.damage = damage(20),
    }
    s.secret |= (n >> 7) & 1 == 1;
    if n >> 8 != 0 {
        return Err(format!("sector type {n} (Boom's friction, wind or current bits)"));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn freedoom_generalized_types_decode() {
        // E3M7's walk-repeatable fast door, MAP26's switch lift (see the research notes).
        let Ok(Effect::Special(door)) = translate(15889, 9) else { panic!() };
        assert_eq!((door.on, door.repeat, door.by, door.tag), (Activation::Walk, true, Who::Players, 9));
        assert_eq!(door.action, Action::Door { kind: DoorKind::Raise, speed: 8.0, wait: 300, shut: 300, key: None });
        let Ok(Effect::Special(lift)) = translate(13331, 11) else { panic!() };
        assert_eq!((lift.on, lift.repeat), (Activation::Use, true));
        assert_eq!(lift.action, Action::Lift { speed: 8.0, wait: 35 });
    }

    #[test]
    fn sector_types_decode() {
        let s = sector_special(72).unwrap();
        assert_eq!((s.light, s.damage.map(|d| d.amount)), (Some(LightEffect::Glow), Some(10)));
        let s = sector_special(77).unwrap();
        assert_eq!((s.light, s.damage.map(|d| d.amount)), (Some(LightEffect::StrobeFastSync), Some(10)));
        assert_eq!(sector_special(4).unwrap().damage.map(|d| d.amount), Some(20));
        assert!(sector_special(9).unwrap().secret);
        assert!(sector_special(6).is_err());
        assert!(sector_special(0x300).is_err());
    }

    #[test]
    fn manual_doors_have_no_tag_and_keys() {
        let Ok(Effect::Special(d)) = translate(26, 7) else { panic!() };
        assert_eq!((d.tag, d.on), (0, Activation::Use));
        assert!(matches!(d.action, Action::Door { key: Some(KeyColour::Blue), .. }));
        assert!(translate(9999, 0).is_err());
    }
}
