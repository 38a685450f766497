//! The autopilot: a bot that plays a level through the player's own inputs.
//!
//! Each tick it looks at what a player can know (the map's geometry and
//! specials as they stand now, the things in view, its own health, ammo and
//! keys) and answers one [`TickInput`], which the caller hands to
//! [`SimGame::tick`](crate::sim::game::SimGame::tick) like a keyboard's. It never changes the game.
//!
//! - [`nav`]: the navigation grid (16-unit cells, walls, heights).
//! - [`plan`]: the level's mechanisms, the heights a plan assumes, the
//!   search, and which goal to go for.
//! - [`leap`]: running jumps across gaps: which runs clear which gaps, and
//!   taking one.
//! - [`brain`]: the boss brain (MAP30): from where on a lift, and at which
//!   heights, a rocket fired level bursts near enough to hurt it.
//! - this module: following a route (steering, doors, lifts, teleports,
//!   getting unstuck), fighting, and the report.
//! - [`check`]: what a map maker asks of a map: can the exit, each key,
//!   secret and item be reached, and where can the player get stuck.
//! - `gather`: for play whose aim is not the exit ([`Options`], off by
//!   default): fetching the health and armour seen, exploring, leading a
//!   moving enemy with a rocket.

mod arrive;
pub mod blockmap;
pub mod brain;
pub mod check;
mod choose;
mod fight;
mod follow;
mod gather;
mod protect;
mod ways;
pub use fight::Aim;
use fight::{weapon_for, Fire};
pub use gather::Options;
pub mod leap;
pub mod nav;
pub mod observe;
pub mod obstacle;
pub mod plan;
pub mod predict;
pub mod press;
pub mod route;
pub mod sectors;
pub mod sight;
mod supplies;

use std::collections::{BTreeMap, BTreeSet};

use glam::DVec2;

/// A point on the map (glam's, re-exported for the command line).
pub type Point = DVec2;

use crate::actors::{ActorDef, ActorFlag, Give, Power};
use crate::map::special::{Action, Activation, KeyColour};
use crate::play::events::Event;
use crate::play::player::{MAX_STEP, RADIUS};
use crate::play::TickInput;
use nav::{Cell, Heights, LineId, NavGrid, Span, CELL, DIRS};
use observe::Observe;
use plan::{line_of, Goal, Mechanisms, Purpose, Route, Search, Targets};

/// Ticks between full replans while a route is followed.
const REPLAN_EVERY: u64 = 350;
/// Ticks without progress along a route before the move is given up.
const STUCK_TICKS: u32 = 70;
/// Periodic re-routes to one goal before it counts as failed.
const MAX_REROUTES: u32 = 3;
/// Times the bot starts over (every switch untried) when it runs out of goals.
const MAX_ROUNDS: u32 = 2;
/// Ticks between two such rounds: one straight after another finds the
/// level as it was (stuck meanwhile, the bot looks again each second).
const ROUND_GAP: u64 = 35 * 10;
/// A goal abandoned this often is not chosen again.
const MAX_FAILURES: u32 = 3;
/// Ticks to wait at a blocked move when nothing there moves and nothing can
/// be done about it.
const STILL_TICKS: u32 = 70;
/// Calls of one lift missed (it came back up before the body got on)
/// after which a route's own unblocking takes over from calling it first.
const MAX_LIFT_MISSES: u32 = 3;
/// Times one repeatable line is taken again with nothing untried left: a
/// door that shuts again would otherwise be opened for ever.
const MAX_RETAKES: u32 = 2;
/// Ticks spent standing to fight what is in sight, then ticks going on
/// along the route while still firing (so an enemy it cannot kill does not
/// hold it for ever).
const STAND_TICKS: u32 = 35 * 6;
const GO_ON_TICKS: u32 = 35 * 2;
/// Missiles further than this are not dodged yet.
const DODGE_RANGE: f64 = 400.0;
/// Ticks without an enemy to fire at that end a fight.
const CALM_TICKS: u32 = 35;
/// A monster further than this is not fought.
const FIGHT_RANGE: f64 = 1400.0;
/// How far a fist or chainsaw reaches beyond the enemy's radius (Doom's
/// melee range is 64 from the body's centre).
const MELEE_REACH: f64 = 64.0;
/// Below this health the bot goes for health it can reach.
const LOW_HEALTH: i32 = 60;
/// A route whose floors would take this much health (or half what is left)
/// fetches a radiation suit first, if one is nearer than the goal.
const SUIT_DOSE: u32 = 30;
/// Ticks of suit left under which floors that hurt are avoided again.
const SUIT_MARGIN: i32 = 35 * 5;
/// Cells within this of where the body fell off a ledge are wary.
const FALL_WARY: f64 = 24.0;
/// A barrel nearer than this on the line of fire stops the bot firing (a
/// barrel's blast reaches 128 units).
const BARREL_CLEARANCE: f64 = 192.0;
/// How far a barrel's blast reaches (128) and a little more.
const BARREL_BLAST: f64 = 160.0;
/// With this many monsters in sight, a fight is fought falling back: they
/// follow one at a time through the way it came.
const CROWD: u32 = 3;
/// Below this health a fight is fought falling back.
const RETREAT_HEALTH: i32 = 40;
/// A drop deeper than this is stepped off at a creep, braking above
/// [`CREEP`] units a tick ...
const LONG_DROP: f64 = 128.0;
/// ... onto a landing narrower than a walking body falling from there
/// would cross at this many units a tick.
const WALK: f64 = 8.0;
const CREEP: f64 = 1.0;
/// The spacing of the trail's points, and how many are kept.
const TRAIL_STEP: f64 = 32.0;
const TRAIL_POINTS: usize = 128;
/// Ticks the body waits before a once-only walk line whose sectors are
/// busy (a lift on its way back takes a few seconds) before crossing it
/// anyway.
const WASTE_PATIENCE: u32 = 35 * 12;
/// Ticks the body waits at a thing whose floor is moving (a pedestal
/// coming down) before giving it up as out of reach.
const MOVING_PATIENCE: u32 = 35 * 60;

/// How a run is going, for the report.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    Playing,
    /// Nothing left to try: no exit, key or untried switch within reach.
    Stuck {
        at: DVec2,
        why: String,
    },
}

/// Figures of the planning, for the benchmark and the report.
#[derive(Clone, Copy, Debug, Default)]
pub struct Figures {
    /// Time building the navigation grid, seconds.
    pub grid_seconds: f64,
    /// Goal choices made; the time of those and of the periodic re-routes
    /// to the same goal, in all; and the worst single choice, seconds.
    pub plans: u32,
    pub plan_seconds: f64,
    pub worst_plan_seconds: f64,
}

/// What a search assumes of the level as it stands: the plan's heights,
/// the cells solid things stand on, the moves given up, the lines used up,
/// the lines a crossing now would waste and the doors shut now.
struct Assumed {
    heights: Heights,
    blocked: BTreeSet<Cell>,
    bad: BTreeSet<u32>,
    spent: BTreeSet<LineId>,
    wasted: BTreeSet<LineId>,
    shut: Vec<bool>,
}

impl Assumed {
    /// The cell the player's body is taken to be in, by these heights,
    /// beside rather than on a cell a solid thing stands on.
    fn start(&self, nav: &NavGrid, game: &dyn Observe) -> Option<Cell> {
        let player = game.player();
        nav.start_cell(player.pos, player.z, &self.heights, |c| self.blocked.contains(&c))
    }

    fn world<'a>(
        &'a self,
        nav: &'a NavGrid,
        mech: &'a Mechanisms,
        (hurts, wary): (&'a [bool], &'a [bool]),
        map: &'a crate::map::Map,
    ) -> plan::World<'a> {
        plan::World {
            wary,
            nav,
            map,
            mech,
            heights: &self.heights,
            blocked: &self.blocked,
            bad: &self.bad,
            spent: &self.spent,
            wasted: &self.wasted,
            hurts,
            shut: &self.shut,
        }
    }
}

/// The route being followed.
struct Active {
    goal: Goal,
    purpose: Purpose,
    route: Route,
    /// Index in the route of the cell the body is at (or last was).
    at: usize,
    /// Ticks since `at` last moved forward.
    idle: u32,
    /// Ticks spent waiting for a door or lift.
    waited: u32,
    /// Ticks spent at a blocked move where nothing moves.
    still: u32,
    /// Times the route was found again on the way.
    reroutes: u32,
    /// Uses pressed at the goal.
    presses: u32,
    /// Ticks spent at the goal.
    arrived: u32,
    /// A press at the goal did nothing because the sectors it moves were
    /// busy (a door switch pressed while its door is open): it waits for
    /// them and presses again.
    busy: bool,
    /// A running jump under way.
    leap: Option<leap::Run>,
    /// The tick the goal was chosen.
    started: u64,
}

impl Active {
    /// A route to `goal` just found at tick `started`, nothing done along
    /// it yet.
    fn new(goal: Goal, purpose: Purpose, route: Route, started: u64) -> Active {
        Active {
            goal,
            purpose,
            route,
            at: 0,
            idle: 0,
            waited: 0,
            still: 0,
            reroutes: 0,
            presses: 0,
            arrived: 0,
            busy: false,
            leap: None,
            started,
        }
    }
}

/// The bot. Make one per game with [`Autopilot::new`], then call
/// [`Autopilot::tick`] before every [`SimGame::tick`](crate::sim::game::SimGame::tick).
pub struct Autopilot {
    nav: NavGrid,
    mech: Mechanisms,
    search: Search,
    active: Option<Active>,
    /// Lines it has set off (walked over, used), and when.
    tried: BTreeMap<LineId, u64>,
    /// Moves that did not work, until a tick.
    bad: BTreeMap<u32, u64>,
    /// Things it could not pick up.
    unreachable: BTreeSet<u32>,
    /// Per thing, the cells it was not picked up from though the body
    /// stood there with its floor still (Doom's touch is a box test: a
    /// key 36 units off along an axis is not touched, however near).
    touch_missed: BTreeMap<u32, BTreeSet<Cell>>,
    /// Goals given up on, and how often: after [`MAX_FAILURES`] they are
    /// not chosen again.
    failures: BTreeMap<(u8, u32), u32>,
    /// Floor and ceiling heights last tick (to see what moves).
    last: Heights,
    /// Repeatable lines taken again with nothing untried left, and how
    /// often (see [`MAX_RETAKES`]).
    retaken: BTreeMap<LineId, u32>,
    /// Repeatable switches whose last press started nothing.
    did_nothing: BTreeSet<LineId>,
    /// Per sector, the last tick its floor moved.
    floor_moved: Vec<u64>,
    /// Lifts a goal search holds where they are now (see `choose`).
    keep_up: Vec<usize>,
    /// Per sector: the last tick the body's centre was in it.
    stood_on: Vec<u64>,
    /// Per lift sector, calls missed (the lift came back up before the
    /// body got on).
    lift_misses: BTreeMap<usize, u32>,
    last_pos: DVec2,
    used_last: bool,
    /// No full replan before this tick (after setting something off, the
    /// world is given time to move).
    settle_until: u64,
    next_replan: u64,
    status: Status,
    keys: usize,
    figures: Figures,
    sight: sight::Scratch,
    /// Goals reached, for the report.
    pub log: Vec<String>,
    /// Hurting sectors, by index.
    hurts: Vec<bool>,
    /// Times everything was tried again after running out of goals.
    rounds: u32,
    /// Sectors dropped into with nothing left to do, and since when
    /// nothing has been (see `ways`).
    dropped: BTreeSet<usize>,
    stuck_since: Option<u64>,
    /// The tick of the last such round.
    last_round: u64,
    /// Ticks into the current stand-and-fight cycle.
    fighting: u32,
    /// Ticks since the last tick with an enemy to fire at.
    calm: u32,
    /// The way a shot just fired at will leave, and until when.
    aim: Option<(f64, u64)>,
    /// Times each walk line was crossed (a live once-only one is crossed
    /// once more at most: it may do nothing for ever).
    crossed: BTreeMap<LineId, u32>,
    /// Something changed that may change the goal (a key picked up).
    rechoose: bool,
    /// A barrel within [`BARREL_BLAST`] while fighting, last tick.
    barrel_near: bool,
    /// Last tick the body headed for a floor far below, stepping off at a
    /// creep (see [`Autopilot::drive_to`]): no fighting or dodging, which
    /// would throw it off at speed. Atomic rather than a `Cell` (it is set
    /// from `&self`) so that a bot can be shared across threads (a Python
    /// game holding one is shared).
    creeping: std::sync::atomic::AtomicBool,
    /// The trigger was held at the boss brain last tick.
    firing: bool,
    /// Live monsters in sight last tick (counted up to [`CROWD`]).
    in_sight: u32,
    /// How badly health and ammunition were needed last tick.
    need: (supplies::Need, supplies::Need),
    /// Cells to keep off where a search can, and to go carefully on: those
    /// within a body and a cell of a teleport line (a body that cuts a bend
    /// past a line's end is sent elsewhere, E2M9; unless the route takes
    /// the teleport), and those around where the body fell off a ledge
    /// (MAP20's walkway over lava, whose way back up is a teleporter).
    wary: Vec<bool>,
    /// Where the body has been, a point every [`TRAIL_STEP`] units, the
    /// newest last: the way back out of a fight going badly.
    trail: Vec<DVec2>,
    /// Health last tick, and what the body did then (for the trace).
    last_health: i32,
    mode: &'static str,
    /// What it plays for besides the exit.
    options: Options,
    /// What it found out looking about (for `options`).
    finds: gather::Finds,
    /// The enemy it aims at this tick.
    target: Option<Aim>,
    /// Where the shot would meet the enemy is not known well enough to
    /// fire (a lead with too short a track: [`Options::lead`]).
    unsure: bool,
}

impl Autopilot {
    pub fn new(game: &dyn Observe) -> Autopilot {
        Autopilot::with_options(game, Options::default())
    }

    /// A bot that also plays for what `options` asks.
    pub fn with_options(game: &dyn Observe, options: Options) -> Autopilot {
        let level = game.level();
        let started = std::time::Instant::now();
        let nav = NavGrid::new(&level.compiled);
        let figures = Figures { grid_seconds: started.elapsed().as_secs_f64(), ..Default::default() };
        let map = &level.compiled.map;
        let mut mech = Mechanisms::of(level);
        mech.locate_doors(&nav, map, Some(&Self::keys_held(game)));
        let hurts = map.sectors.iter().map(|s| s.special.damage.is_some()).collect();
        let mut wary = vec![false; nav.cells()];
        for &l in mech.teleports.keys() {
            for c in cells_near_line(&nav, map, l) {
                wary[c as usize] = true;
            }
        }
        Autopilot {
            nav,
            mech,
            search: Search::default(),
            active: None,
            tried: BTreeMap::new(),
            bad: BTreeMap::new(),
            unreachable: BTreeSet::new(),
            touch_missed: BTreeMap::new(),
            failures: BTreeMap::new(),
            last: Heights::of(map),
            did_nothing: BTreeSet::new(),
            retaken: BTreeMap::new(),
            floor_moved: vec![0; map.sectors.len()],
            keep_up: Vec::new(),
            stood_on: vec![0; map.sectors.len()],
            lift_misses: BTreeMap::new(),
            last_pos: game.player().pos,
            used_last: false,
            settle_until: 0,
            next_replan: 0,
            status: Status::Playing,
            keys: 0,
            figures,
            sight: sight::Scratch::default(),
            log: Vec::new(),
            hurts,
            rounds: 0,
            dropped: BTreeSet::new(),
            stuck_since: None,
            last_round: 0,
            fighting: 0,
            calm: 0,
            aim: None,
            crossed: BTreeMap::new(),
            rechoose: false,
            trail: vec![game.player().pos],
            wary,
            need: (supplies::Need::None, supplies::Need::None),
            in_sight: 0,
            barrel_near: false,
            creeping: std::sync::atomic::AtomicBool::new(false),
            firing: false,
            last_health: game.player().health,
            mode: "",
            options,
            finds: gather::Finds::default(),
            target: None,
            unsure: false,
        }
    }

    /// The enemy aimed at on the last tick, if it fought.
    pub fn aim(&self) -> Option<Aim> {
        self.target
    }

    pub fn status(&self) -> &Status {
        &self.status
    }

    pub fn figures(&self) -> Figures {
        self.figures
    }

    pub fn nav(&self) -> &NavGrid {
        &self.nav
    }

    /// The cells of the route being followed, from where the body is.
    pub fn route(&self) -> Vec<DVec2> {
        self.active
            .as_ref()
            .map_or(Vec::new(), |a| a.route.cells[a.at..].iter().map(|&c| self.nav.centre_of(c)).collect())
    }

    /// This tick's input.
    pub fn tick(&mut self, game: &dyn Observe) -> TickInput {
        let now = game.ticks();
        let player = game.player();
        if player.dead() || game.exit().is_some() {
            return TickInput::default();
        }
        self.trace_hurt(game, self.last_health, self.mode);
        self.last_health = player.health;
        self.note_crossings(game);
        if self.last_pos.distance(player.pos) > 64.0 {
            self.note_teleport(game);
        }
        self.look_about(game);
        // A suit with a few seconds left shields from all but the floors it
        // is no use on (its rare leaks are taken).
        let suited = player.powers[Power::IronFeet as usize] > SUIT_MARGIN;
        // A floor can come to hurt (a line that copies a neighbour's
        // special as it lowers a floor to nukage).
        for (hurts, sector) in self.hurts.iter_mut().zip(&game.level().compiled.map.sectors) {
            *hurts = sector.special.damage.is_some_and(|d| !suited || d.suit == crate::map::special::Suit::Useless);
        }
        self.mech.settle_lifts(game.level(), |s| game.is_busy(s));
        self.bad.retain(|_, until| *until > now);
        if player.keys.len() != self.keys {
            self.keys = player.keys.len();
            self.rechoose = true;
            self.mech.locate_doors(&self.nav, &game.level().compiled.map, Some(&Self::keys_held(game)));
        }
        // Health or ammunition falling short: look for some before going on.
        let need = supplies::need(game);
        if (need.0 > self.need.0 || need.1 > self.need.1)
            && self.active.as_ref().is_none_or(|a| a.purpose != Purpose::Supplies)
        {
            self.rechoose = true;
        }
        self.need = need;
        // Running at a gap, the body must keep its line: no fighting.
        let leaping = self.active.as_ref().and_then(|a| a.leap).is_some_and(|l| l.running());
        let riding = self.riding();
        // On the lift at the bottom, it fights where it stands (turning and
        // firing, not moving); once the lift starts up, it keeps its aim.
        let rising = riding && self.lift_rising(game);
        let creeping = self.creeping.swap(false, std::sync::atomic::Ordering::Relaxed);
        let fight = self.fight(game).filter(|_| !leaping && !rising && !creeping);
        if fight.is_none() {
            self.target = None;
        }
        // With a gun, stand and fight what is in sight (strafing from side
        // to side, backing off what comes close) for a while before going
        // on; with only a fist, go on. Hurt, fall back the way it came,
        // still firing, to fight from behind a corner or go for health.
        // The fight's clock runs on through a second without a shot (an
        // enemy dodging in and out of sight, fire held for a barrel): were
        // it reset, the bot would never get its turn to go on.
        if fight.is_some() {
            self.fighting = (self.fighting + 1) % (STAND_TICKS + GO_ON_TICKS);
            self.calm = 0;
        } else {
            self.calm += 1;
            if self.calm > CALM_TICKS {
                self.fighting = 0;
            }
        }
        // A boss brain spits monsters for as long as it lives: a fight
        // stood or fallen back from never ends, so it is fought on the way.
        let endless = !brain::live(game).is_empty();
        let retreat = !endless
            && fight.is_some()
            && (player.health < RETREAT_HEALTH || self.in_sight >= CROWD || self.barrel_near);
        // Never stand on a floor that hurts.
        let hurting = self.on_hurting_floor(game);
        // A biter close in is backed off from even while going on: the
        // route may lead straight into it.
        let biter_close = fight.is_some_and(|f| f.3 > 192.0 && f.2 < f.3 / 2.0);
        let stand = !retreat
            && !endless
            && !hurting
            && fight.is_some_and(|f| f.1 != 1)
            && (self.fighting < STAND_TICKS || biter_close);
        let back = retreat.then(|| self.fall_back(player.pos)).flatten();
        self.mode = if back.is_some() {
            "retreat"
        } else if stand {
            "stand"
        } else if fight.is_some() {
            "fight-on"
        } else {
            "follow"
        };
        let mut input = if let Some(back) = back {
            self.drive_to(game, back, false)
        } else if stand || (matches!(self.status, Status::Stuck { .. }) && now < self.next_replan) {
            TickInput::default()
        } else {
            self.follow(game)
        };
        // Using a line needs the body to face it: no fighting on that tick.
        let fight = fight.filter(|_| !input.use_line);
        if fight.is_none() {
            self.target = None;
        }
        if let Some((angle, until)) = self.aim.filter(|&(_, until)| now < until && fight.is_none()) {
            // A rocket on its way out: it flies where the body faces.
            input.turn = turn_to(player.angle, angle) as f32;
            self.aim = Some((angle, until));
        }
        if let Some((angle, weapon, _, _)) = fight {
            // Face the enemy and fire, moving the way the route wanted.
            let wanted = player.angle + f64::from(input.turn);
            let move_dir = if input.forward != 0 || input.strafe != 0 {
                Some(wanted - 90.0 * f64::from(input.strafe) + if input.forward < 0 { 180.0 } else { 0.0 })
            } else {
                None
            };
            // A shot the trigger was pulled for leaves some ticks later,
            // where the body faces then: while it is on its way out, keep
            // facing the way it was aimed (turning to another enemy in
            // between would send it there, into a barrel beside the bot,
            // say).
            let held = self.aim.filter(|&(_, until)| now < until);
            let angle = held.map_or(angle, |(aimed, _)| aimed);
            let turn = turn_to(player.angle, angle);
            input.turn = turn as f32;
            // Ask for the weapon only when another is in hand: asking again
            // would step to the next weapon in the slot.
            let in_hand = slot_of(game, player.pending_weapon.or(player.ready_weapon));
            input.weapon = if in_hand == Some(weapon) { 0 } else { weapon };
            // No shot with the weapon being put away (a rocket fired as
            // the enemy closes in bursts in the bot's face).
            input.fire = player.pending_weapon.is_none()
                && slot_of(game, player.ready_weapon) == Some(weapon)
                && !self.barrel_ahead(game, angle)
                && !fight::tap_now(game)
                && !self.unsure;
            if input.fire && held.is_none() {
                // The shot leaves some ticks after the trigger (Doom's
                // rocket launcher: 8; the pistol and shotgun: 3-4): keep
                // facing this way till then.
                self.aim = Some((angle, now + if matches!(weapon, 5 | 7) { 12 } else { 5 }));
            }
            if stand {
                input.strafe = if (now / 24).is_multiple_of(2) { 1 } else { -1 };
                input.forward = if fight.is_some_and(|f| f.2 < f.3) { -1 } else { 0 };
                input.run = true;
                self.keep_footing(game, &mut input);
            } else if let Some(dir) = move_dir {
                (input.forward, input.strafe) = thrust_towards(angle, dir);
                if back.is_some() {
                    self.keep_footing(game, &mut input);
                }
            }
            if riding {
                (input.forward, input.strafe) = (0, 0);
            }
        }
        if !input.use_line && !leaping && !riding && !creeping {
            self.dodge(game, &mut input);
        }
        self.used_last = input.use_line;
        let heights = Heights::of(&game.level().compiled.map);
        if let Some(on) = self.stood_on.get_mut(player.sector) {
            *on = now;
        }
        for (s, moved) in self.floor_moved.iter_mut().enumerate() {
            if heights.floor[s] != self.last.floor[s] {
                *moved = now;
            }
        }
        self.last = heights;
        if self.last_pos.distance(player.pos) > 64.0 {
            // Teleported: the way back is not a walk.
            self.trail.clear();
        }
        self.last_pos = player.pos;
        if back.is_none() && self.trail.last().is_none_or(|t| t.distance(player.pos) >= TRAIL_STEP) {
            if self.trail.len() == TRAIL_POINTS {
                self.trail.remove(0);
            }
            self.trail.push(player.pos);
        }
        input
    }

    /// Moves made up in a fight (strafing, backing off, falling back while
    /// facing the enemy) go only where the body keeps its footing: not off
    /// a ledge it could not climb back (a pit is a soft lock), nor onto a
    /// floor that hurts from one that does not. A strafe that would is
    /// turned the other way, or dropped.
    fn keep_footing(&self, game: &dyn Observe, input: &mut TickInput) {
        let player = game.player();
        let map = &game.level().compiled.map;
        let live = live_heights(map);
        let hurting = self.on_hurting_floor(game);
        let facing = (player.angle + f64::from(input.turn)).to_radians();
        let ahead = DVec2::new(facing.cos(), facing.sin());
        let left = DVec2::new(-ahead.y, ahead.x);
        let safe = |dir: DVec2| {
            [16.0, 32.0, 48.0].iter().all(|&d| {
                let Some(c) = self.nav.cell_at(player.pos + dir * d) else { return true };
                let span = self.nav.span(c, &live);
                let touched = self.nav.touched(c);
                touched.is_empty()
                    || (span.bottom >= player.z - MAX_STEP
                        && (hurting || touched.iter().all(|&s| !self.hurts[s as usize])))
            })
        };
        if input.forward != 0 && !safe(ahead * f64::from(input.forward)) {
            input.forward = 0;
        }
        if input.strafe != 0 {
            // Strafe 1 is to the right.
            let right = -left;
            let dir = right * f64::from(input.strafe);
            if !safe(dir) {
                input.strafe = if safe(-dir) { -input.strafe } else { 0 };
            }
        }
    }

    /// A monster's missile on its way to the body: step aside, across its
    /// flight, to the side the body is already on (where it keeps its
    /// footing; else the other). Imps' and cacodemons' fireballs, barons'
    /// and arachnotrons' plasma fly slowly enough to be stepped out of.
    fn dodge(&self, game: &dyn Observe, input: &mut TickInput) {
        let player = game.player();
        let (seen, table) = (game.seen(), game.table());
        let mut threat: Option<(f64, DVec2)> = None;
        for m in seen.iter() {
            let def = &table.actors[m.kind];
            if m.removed || m.by_player || !m.missile {
                continue;
            }
            let v = m.vel;
            let rel = player.pos - m.pos;
            if v.length_squared() < 1.0 || rel.length() > DODGE_RANGE || v.dot(rel) <= 0.0 {
                continue;
            }
            let t = v.dot(rel) / v.length_squared();
            let miss = (rel - v * t).length();
            if miss < RADIUS + def.radius + 8.0 && t < 40.0 && threat.is_none_or(|(tt, _)| t < tt) {
                // Across the flight, away from its line.
                let across = DVec2::new(-v.y, v.x).normalize_or_zero();
                let away = if across.dot(rel - v * t) >= 0.0 { across } else { -across };
                threat = Some((t, away));
            }
        }
        if self.flee_blast(game, input) {
            return;
        }
        let Some((_, away)) = threat else { return };
        let facing = (player.angle + f64::from(input.turn)).to_radians();
        let right = DVec2::new(facing.sin(), -facing.cos());
        let strafe: i8 = if away.dot(right) >= 0.0 { 1 } else { -1 };
        let mut dodged = TickInput { strafe, forward: input.forward, run: true, ..*input };
        self.keep_footing(game, &mut dodged);
        if dodged.strafe != 0 {
            input.strafe = dodged.strafe;
            input.forward = dodged.forward;
            input.run = true;
        }
    }

    /// The point of the trail to fall back to from `pos`: the newest one
    /// not already reached (those are dropped); `None` at its start.
    fn fall_back(&mut self, pos: DVec2) -> Option<DVec2> {
        while self.trail.len() > 1 && self.trail.last().is_some_and(|t| t.distance(pos) < TRAIL_STEP / 2.0) {
            self.trail.pop();
        }
        self.trail.last().copied().filter(|t| t.distance(pos) >= TRAIL_STEP / 2.0)
    }

    /// Marks the walk lines the body crossed since last tick as tried.
    fn note_crossings(&mut self, game: &dyn Observe) {
        let map = &game.level().compiled.map;
        let (p, q) = (self.last_pos, game.player().pos);
        if p == q {
            return;
        }
        let mut crossed = Vec::new();
        let walk =
            self.mech.triggers.iter().chain(self.mech.exits.iter().map(|e| &e.0)).chain(self.mech.teleports.keys());
        let lifts = self.mech.lifts.iter().flatten();
        for &id in walk.chain(lifts) {
            let (_, a, b, special) = line_of(map, id);
            if special.is_some_and(|s| s.on == Activation::Walk) && crate::geom::crossing(p, q, a, b).is_some() {
                crossed.push(id);
            }
        }
        for id in crossed {
            *self.crossed.entry(id).or_insert(0) += 1;
            self.tried.insert(id, game.ticks());
        }
    }

    /// The body was teleported by a line its route did not take (it
    /// drifted or coasted over it): logged.
    fn note_teleport(&mut self, game: &dyn Observe) {
        let map = &game.level().compiled.map;
        let planned = self.active.as_ref().is_some_and(|a| {
            a.route.teleport[a.at.saturating_sub(2)..(a.at + 6).min(a.route.cells.len())].iter().any(|&t| t)
        });
        let from = self.last_pos;
        let near = self.mech.teleports.keys().copied().min_by(|&l, &m| {
            let d = |l: LineId| {
                let (_, a, b, _) = line_of(map, l);
                plan::nearest_on(from, a, b).distance(from)
            };
            d(l).total_cmp(&d(m))
        });
        let Some(line) = near else { return };
        let (_, a, b, _) = line_of(map, line);
        if planned || plan::nearest_on(from, a, b).distance(from) > RADIUS + 32.0 {
            return;
        }
        self.log.push(format!("tick {}: teleported by {} off the route", game.ticks(), describe(map, line)));
    }

    /// Lines that are used up: set off once and not repeatable.
    fn spent(&self, game: &dyn Observe) -> BTreeSet<LineId> {
        let map = &game.level().compiled.map;
        // A once-only walk line crossed while its sectors were busy did
        // nothing and stays live (the level says which).
        let tried = self.tried.keys().copied().filter(|&id| {
            line_of(map, id).3.is_none_or(|s| !s.repeat && (s.on != Activation::Walk || Self::used_up(game, id)))
        });
        // A switch that has flipped for good shows it.
        let used = self.mech.triggers.iter().chain(self.mech.lifts.iter().flatten()).copied();
        tried.chain(used.filter(|&id| Self::used_up(game, id))).collect()
    }

    /// Has the level used `id`'s special up (a once-only line set off)?
    fn used_up(game: &dyn Observe, id: LineId) -> bool {
        let (line, _, _, special) = line_of(&game.level().compiled.map, id);
        special.is_some() && game.special(line).is_none()
    }

    /// Cells solid things stand on (not monsters: they move; nor the
    /// player's own body, which the simulation lists among its things:
    /// taken for an obstacle, it walled the body's start in where the way
    /// on was narrow, E4M6's pit, E4M7's lift foot, MAP11's door closet).
    fn blocked(&self, game: &dyn Observe) -> BTreeSet<Cell> {
        let (seen, table) = (game.seen(), game.table());
        let me = game.player();
        let mut cells = BTreeSet::new();
        for a in seen.iter() {
            let def = &table.actors[a.kind];
            if a.removed || !a.solid || def.has(ActorFlag::CountKill) || (a.pos == me.pos && a.z == me.z) {
                continue;
            }
            let reach = def.radius + nav::CLEAR;
            let r = (reach / CELL).ceil() as i32;
            let Some(c) = self.nav.cell_at(a.pos) else { continue };
            let (cx, cy) = ((c as usize % self.nav.width) as i32, (c as usize / self.nav.width) as i32);
            for dy in -r..=r {
                for dx in -r..=r {
                    let (x, y) = (cx + dx, cy + dy);
                    if x < 0 || y < 0 || x as usize >= self.nav.width || y as usize >= self.nav.height {
                        continue;
                    }
                    let n = (y as usize * self.nav.width + x as usize) as Cell;
                    let d = (self.nav.centre_of(n) - a.pos).abs();
                    if d.x < reach && d.y < reach {
                        cells.insert(n);
                    }
                }
            }
        }
        cells
    }

    /// Has `goal` been given up on too often?
    fn failed(&self, goal: &Goal) -> bool {
        self.failures.get(&goal.key()).is_some_and(|&n| n >= MAX_FAILURES)
    }

    /// Has `goal` been given up on before (twice: a switch that still does
    /// nothing is taken as used)?
    fn failed_once(&self, goal: &Goal) -> bool {
        self.failures.get(&goal.key()).is_some_and(|&n| n >= 2)
    }

    /// Notes that the route to `goal` was given up.
    fn give_up(&mut self, goal: &Goal) {
        *self.failures.entry(goal.key()).or_insert(0) += 1;
    }

    fn keys_held(game: &dyn Observe) -> Vec<KeyColour> {
        game.player().keys.iter().map(|k| k.colour).collect()
    }

    /// What a search assumes of the level now (see [`Assumed`]).
    fn assume(&self, game: &dyn Observe) -> Assumed {
        let level = game.level();
        let spent = self.spent(game);
        Assumed {
            heights: {
                let mut h = plan::plan_heights(level, &self.mech, &Self::keys_held(game), &spent);
                for &s in &self.keep_up {
                    let floor = level.compiled.map.sectors[s].floor;
                    (h.low[s], h.floor[s]) = (floor, floor);
                }
                h
            },
            blocked: self.blocked(game),
            bad: self.bad.keys().copied().collect(),
            shut: self.mech.shut_doors(&level.compiled.map),
            wasted: self.wasted(game),
            spent,
        }
    }

    /// Live once-only walk lines whose sectors are busy now: Doom spends
    /// such a line when it is crossed, whether or not its special could
    /// start (MAP15's line 163, crossed while a repeatable line's lift
    /// was still moving, left that lift down for good).
    fn wasted(&self, game: &dyn Observe) -> BTreeSet<LineId> {
        let map = &game.level().compiled.map;
        let walk = self.mech.triggers.iter().chain(self.mech.lifts.iter().flatten());
        walk.copied().filter(|&id| Self::would_waste(game, map, id)).collect()
    }

    /// Would crossing `id` now spend it for nothing: a live once-only line
    /// of the kind [`Self::wastable`] says, whose sectors are busy?
    fn would_waste(game: &dyn Observe, map: &crate::map::Map, id: LineId) -> bool {
        let (line, _, _, special) = line_of(map, id);
        special.is_some_and(Self::wastable) && game.special(line).is_some() && Self::targets_busy(game, id)
    }

    /// Is `special` one a crossing spends for nothing while its sectors
    /// are busy: a once-only walk line players set off that moves a floor,
    /// a lift or a ceiling (a door's line crossed while the door is open
    /// loses nothing that matters, and waiting for it changes the fight).
    fn wastable(special: &crate::map::LineSpecial) -> bool {
        special.on == Activation::Walk
            && !special.repeat
            && special.by.players()
            && !matches!(special.action, Action::Door { .. })
    }
}

/// A line for the log: where it is and what it does.
pub fn describe(map: &crate::map::Map, line: LineId) -> String {
    let (_, a, b, special) = line_of(map, line);
    let what = special.map_or("no special".to_string(), |s| format!("{:?} {:?} tag {}", s.on, s.action, s.tag));
    format!("line {line} ({:.0}, {:.0})-({:.0}, {:.0}) {what}", a.x, a.y, b.x, b.y)
}

/// A run stuck this long (nothing left to try) is over.
const GIVE_UP_STUCK: u64 = 35 * 60;

/// How an autopilot run ended.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    /// It left the level, by this exit.
    pub exit: Option<crate::play::Exit>,
    pub died: bool,
    /// Where it gave up, and why.
    pub stuck: Option<(DVec2, String)>,
    /// Every tick's input, from the first (a demo's).
    pub inputs: Vec<TickInput>,
}

/// The autopilot's input between levels (or dead): use pressed every
/// other tick, `tick` counting, so each press is a new one and the
/// intermission goes on as fast as Doom lets it.
pub fn press_on(tick: u64) -> TickInput {
    TickInput { use_line: tick.is_multiple_of(2), ..TickInput::default() }
}

/// Plays `play`'s current level with a new autopilot until it exits, the
/// player dies, the bot has been stuck a minute, `max_ticks` have run, or
/// `each` (called after every tick with the tick number) says stop.
pub fn run(
    play: &mut crate::play::playthrough::Playthrough,
    max_ticks: u64,
    each: impl FnMut(&crate::play::playthrough::Playthrough, u64) -> bool,
) -> Result<(Outcome, Autopilot), crate::play::playthrough::PlaythroughError> {
    run_through(play, max_ticks, |input| input, each)
}

/// [`run`], with each of the bot's inputs passed through `filter` before
/// the game is fed it (a `.lmp` recording rounds turns as the file will).
pub fn run_through(
    play: &mut crate::play::playthrough::Playthrough,
    max_ticks: u64,
    mut filter: impl FnMut(TickInput) -> TickInput,
    mut each: impl FnMut(&crate::play::playthrough::Playthrough, u64) -> bool,
) -> Result<(Outcome, Autopilot), crate::play::playthrough::PlaythroughError> {
    use crate::play::playthrough::Phase;
    let mut bot = Autopilot::new(&play.game);
    let mut outcome = Outcome::default();
    let mut stuck_since: Option<u64> = None;
    for tick in 1..=max_ticks {
        let input = filter(bot.tick(&play.game));
        play.tick(&input)?;
        outcome.inputs.push(input);
        if !each(play, tick) {
            break;
        }
        if play.phase != Phase::Playing {
            // The intermission, or the end of the game (Doom 1's ExM8).
            outcome.exit = play.game.exit();
            break;
        }
        if play.game.player().dead() {
            outcome.died = true;
            break;
        }
        if bot.gave_up(tick, &mut stuck_since, &mut outcome) {
            break;
        }
    }
    Ok((outcome, bot))
}

/// Plays `game`, a level of the simulation with Doom's arithmetic, with a
/// new autopilot until it exits, the player dies, the bot has been stuck a
/// minute, `max_ticks` have run, or `each` (called after every tick with
/// the tick number) says stop. The game keeps the commands it was fed
/// ([`crate::sim::game::SimGame::commands`]): a vanilla demo of the run.
pub fn run_sim(
    game: &mut crate::sim::game::SimGame,
    max_ticks: u64,
    mut each: impl FnMut(&crate::sim::game::SimGame, u64) -> bool,
) -> (Outcome, Autopilot) {
    let mut bot = Autopilot::new(game);
    let mut outcome = Outcome::default();
    let mut stuck_since: Option<u64> = None;
    for tick in 1..=max_ticks {
        let input = bot.tick(game);
        game.tick(&input);
        outcome.inputs.push(input);
        if !each(game, tick) {
            break;
        }
        if let Some(exit) = game.exit() {
            outcome.exit = Some(exit);
            break;
        }
        if Observe::player(game).dead() {
            outcome.died = true;
            break;
        }
        if bot.gave_up(tick, &mut stuck_since, &mut outcome) {
            break;
        }
    }
    (outcome, bot)
}

impl Autopilot {
    /// Whether the bot has been stuck longer than [`GIVE_UP_STUCK`] at
    /// `tick` (then `outcome` says where and why).
    fn gave_up(&self, tick: u64, stuck_since: &mut Option<u64>, outcome: &mut Outcome) -> bool {
        match self.status() {
            Status::Stuck { at, why } => {
                let since = *stuck_since.get_or_insert(tick);
                if tick - since > GIVE_UP_STUCK {
                    outcome.stuck = Some((*at, why.clone()));
                    return true;
                }
            }
            Status::Playing => *stuck_since = None,
        }
        false
    }
}

/// The cells whose centres are within a body and a cell of `line`.
fn cells_near_line(nav: &NavGrid, map: &crate::map::Map, line: LineId) -> Vec<Cell> {
    let (_, a, b, _) = line_of(map, line);
    let margin = DVec2::splat(RADIUS + CELL);
    nav.cells_in_box(a.min(b) - margin, a.max(b) + margin)
        .filter(|&c| {
            let p = nav.centre_of(c);
            plan::nearest_on(p, a, b).distance(p) < RADIUS + CELL
        })
        .collect()
}

/// The live heights, lifts at the height they are.
fn live_heights(map: &crate::map::Map) -> Heights {
    Heights::of(map)
}

/// The turn from `from` to face `to`, degrees in (-180, 180].
fn turn_to(from: f64, to: f64) -> f64 {
    let t = (to - from).rem_euclid(360.0);
    if t > 180.0 {
        t - 360.0
    } else {
        t
    }
}

/// What picking up `def` gives (nothing when it is no pickup).
fn gives(def: &ActorDef) -> impl Iterator<Item = &Give> {
    def.pickup.iter().flat_map(|p| p.give.iter())
}

/// The weapon slot of weapon `w` (an actor), if any.
fn slot_of(game: &dyn Observe, w: Option<usize>) -> Option<u8> {
    w.and_then(|w| game.table().actors[w].weapon.as_ref()).map(|w| w.slot)
}

/// The forward and strafe keys that move a body facing `facing` degrees
/// the `way` (degrees), to the nearest of the eight directions.
fn thrust_towards(facing: f64, way: f64) -> (i8, i8) {
    let (s, c) = (way - facing).to_radians().sin_cos();
    let key = |x: f64| {
        if x > 0.38 {
            1
        } else if x < -0.38 {
            -1
        } else {
            0
        }
    };
    (key(c), -key(s))
}
