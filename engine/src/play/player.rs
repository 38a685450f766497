//! The player as the outside reads it (the window, the status bar, the
//! sound, the autopilot, tests): where the body is, what it holds, in map
//! units and degrees, written each tic from the simulation by
//! [`crate::sim::game::SimGame`]; and Doom's player measures the autopilot
//! plans with (p_user.c, p_mobj.c, g_game.c, converted from 16.16 fixed
//! point to map units per tick).

use glam::DVec2;

use crate::actors::KeyForm;
use crate::map::special::KeyColour;
use crate::render::view::EYE_HEIGHT;

/// The body is a circle of this radius (Doom's player radius, 16).
pub const RADIUS: f64 = 16.0;
/// The body is this tall: a passage needs this much headroom (Doom: 56).
pub const HEIGHT: f64 = 56.0;
/// The highest step the body climbs without jumping (Doom: 24).
pub const MAX_STEP: f64 = 24.0;

/// Thrust per tick while running forward, in units per tick per tick:
/// Doom's `forwardmove` 50 times `2048 / 65536`. With [`FRICTION`] the top
/// speed is `thrust / (1 - friction)` = 16.7 units per tick.
pub const RUN_THRUST: f64 = 50.0 / 32.0;
/// Velocity kept per tick on the ground (Doom's `FRICTION` 0xe800 / 0x10000).
/// The top speed is reached to 90% in about 23 ticks (two thirds of a second),
/// and a running player stops within about 8 units of coasting per tick.
pub const FRICTION: f64 = 0.90625;
/// Health at the start (Doom's 100).
pub const START_HEALTH: i32 = 100;

/// A key the player holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize)]
pub struct Key {
    pub colour: KeyColour,
    pub form: KeyForm,
}

/// Bullets a player starts with (Doom's `initial_bullets`).
pub const START_BULLETS: i32 = 50;
/// Doom's ammunition limits (`maxammo`): bullets, shells, rockets, cells.
pub const MAX_AMMO: [i32; 4] = [200, 50, 50, 300];

/// The player: where the body is and how it moves.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Player {
    /// Centre of the body's circle.
    pub pos: DVec2,
    /// Height of the feet.
    pub z: f64,
    /// View direction in degrees, counter-clockwise from +x, in `[0, 360)`.
    pub angle: f64,
    /// Map units per tick.
    pub velocity: DVec2,
    /// Vertical speed, units per tick (negative while falling).
    pub vz: f64,
    /// The sector under the centre.
    pub sector: usize,
    /// Highest floor and lowest ceiling under the whole circle: what the body
    /// stands on and must fit under.
    pub floor: f64,
    pub ceiling: f64,
    /// Eye above the feet: [`EYE_HEIGHT`] at rest, lower for a few ticks
    /// after a step up or a hard landing (Doom's `viewheight`).
    pub view_height: f64,
    /// How fast `view_height` recovers (Doom's `deltaviewheight`).
    pub view_delta: f64,
    /// At 0 or below the player is dead.
    pub health: i32,
    /// Keys picked up, in the order found.
    pub keys: Vec<Key>,
    /// Armour points and class: 1 (green) absorbs a third of each hurt, 2
    /// (blue) a half; 0 is none.
    pub armor: i32,
    pub armor_class: u8,
    /// Ammunition by kind ([`crate::actors::AmmoKind::ALL`] order), and its limits (doubled
    /// by a backpack).
    pub ammo: [i32; 4],
    pub max_ammo: [i32; 4],
    pub backpack: bool,
    /// Weapons owned, by actor index (the fist and pistol from the start).
    pub weapons: Vec<usize>,
    /// Power-ups: ticks left (the computer map and berserk last the level:
    /// 1 while owned).
    pub powers: [i32; 6],
    /// Ticks left during which input is ignored (after a teleport: Doom's
    /// `reactiontime`).
    pub freeze: u32,
    /// Use and fire were held on the last tick: each acts once per press,
    /// as Doom's `usedown` makes use.
    pub use_held: bool,
    pub fire_held: bool,
    /// The weapon in hand and the one being changed to (actor indices).
    pub ready_weapon: Option<usize>,
    pub pending_weapon: Option<usize>,
    /// The weapon's sprite and its flash, on screen (Doom's psprites).
    pub psprites: [PSprite; 2],
    /// Shots fired with the trigger held (the pistol and chaingun are
    /// accurate only on the first).
    pub refire: i32,
    /// Fire was held when the weapon last looked (rockets and the BFG need
    /// a fresh press).
    pub attack_down: bool,
    /// The weapon's light on the room (0 to 2: Doom's `extralight`).
    pub extra_light: i32,
    /// Recent hurt and pickups, for the screen's red and gold tints.
    pub damage_count: i32,
    pub bonus_count: i32,
}

/// A sprite drawn on the screen rather than in the world: the weapon or
/// its flash (Doom's `pspdef_t`). `sx`, `sy` place its origin on Doom's
/// 320x200 screen.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PSprite {
    /// `None`: not shown.
    pub state: Option<crate::actors::StateId>,
    pub tics: i32,
    pub sx: f64,
    pub sy: f64,
}

impl Player {
    /// A player standing at `pos` on `floor`, under `ceiling`.
    pub fn new(pos: DVec2, angle: f64, sector: usize, floor: f64, ceiling: f64) -> Player {
        Player {
            pos,
            z: floor,
            angle: angle.rem_euclid(360.0),
            velocity: DVec2::ZERO,
            vz: 0.0,
            sector,
            floor,
            ceiling,
            view_height: EYE_HEIGHT,
            view_delta: 0.0,
            health: START_HEALTH,
            keys: Vec::new(),
            armor: 0,
            armor_class: 0,
            ammo: [START_BULLETS, 0, 0, 0],
            max_ammo: MAX_AMMO,
            backpack: false,
            weapons: Vec::new(),
            powers: [0; 6],
            freeze: 0,
            use_held: false,
            fire_held: false,
            ready_weapon: None,
            pending_weapon: None,
            psprites: [PSprite::default(); 2],
            refire: 0,
            attack_down: false,
            extra_light: 0,
            damage_count: 0,
            bonus_count: 0,
        }
    }

    pub fn dead(&self) -> bool {
        self.health <= 0
    }

    /// Standing on the floor (not falling): only then do thrust and friction act.
    pub fn on_ground(&self) -> bool {
        self.z <= self.floor
    }

    /// The eye's height: feet plus view height, kept 4 units under the
    /// ceiling as Doom does, so the eye never pokes through a low ceiling.
    pub fn eye_z(&self) -> f64 {
        (self.z + self.view_height).min(self.ceiling - 4.0).max(self.z + 1.0)
    }
}
