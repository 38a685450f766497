//! The boss brain (Doom II's MAP30): the level ends when it dies, and it
//! sits behind a wall, seen through a slit no shot from the floor passes.
//! A player kills it the way Doom II's players do: riding a lift up past
//! the slit's height and firing a rocket level through it as the lift goes
//! by, so that the rocket bursts on the wall behind the brain.
//!
//! This module finds where that works: for each standing place on a lift,
//! the heights at which a rocket fired level at the brain bursts near
//! enough to hurt it ([`spots`]), and, as the body rides, whether a rocket
//! fired now would ([`blast`]); and it drives the bot there
//! ([`Autopilot::brain_goal`]) and on the ride.
//!
//! A brain also dies under a crusher (Freedoom's MAP16 crushes its four
//! brains in their closets once a walk line is crossed): [`crushers`] finds
//! the lines that start one over it, for `check`.

use glam::DVec2;

use super::sight::{self, Body};
use super::Observe;
use crate::actors::{ActorTable, Arg, Category};
use crate::geom::Aabb;
use crate::level::Level;
use crate::map::special::{Action, Activation};
use crate::map::Map;
use crate::play::TickInput;
use crate::CompiledMap;

use super::nav::{Cell, Heights, LineId, NavGrid};
use super::plan::{line_of, Goal, Mechanisms, Purpose};
use super::sectors::target_sectors;
use super::{live_heights, turn_to, Active, Autopilot};

/// The reach of a rocket's blast (Doom's `A_Explode`: 128, and 128 damage
/// at its centre).
const BLAST: f64 = 128.0;
/// A missile leaves 32 above the shooter's feet (Doom's `P_SpawnMissile`'s
/// `4*8*FRACUNIT`).
const MISSILE_HEIGHT: f64 = 32.0;
/// A missile's move is taken in pieces of at most this (Doom's
/// `P_XYMovement` halves any move over `MAXMOVE/2`).
const MAX_PIECE: f64 = 15.0;
/// A shot is worth firing when its blast does at least this much.
const WORTH: i32 = 40;
/// Lifts this far from the brain at most, along either axis, are looked at.
const LOOK: f64 = 2048.0;
/// A body's height: a lift's floor goes no nearer its ceiling.
const HEADROOM: f64 = 56.0;
/// Heights tried on a lift, this far apart.
const Z_STEP: f64 = 2.0;
/// The rocket launcher's weapon slot (as the fight's choice of weapon has
/// it).
pub const LAUNCHER_SLOT: u8 = 5;
/// Ticks on a lift firing at the boss brain before the ride is given up
/// (a lift goes down, waits three seconds and comes back up).
const RIDE_TICKS: u32 = 35 * 20;

/// A crusher's ceiling comes down to 8 above its floor (Doom's
/// `EV_DoCeiling`: `bottomheight = floorheight + 8*FRACUNIT`).
const CRUSHER_GAP: f64 = 8.0;

/// A live boss brain.
#[derive(Clone, Copy, Debug)]
pub struct Brain {
    pub actor: u32,
    pub body: Body,
}

/// The body of a boss brain of kind `def` standing at `pos`.
pub fn body(compiled: &CompiledMap, def: &crate::actors::ActorDef, pos: DVec2, index: usize) -> Body {
    let z = compiled.map.sectors[compiled.sector_at(pos)].floor;
    Body { pos, z, height: def.height, radius: def.radius, index }
}

/// The live boss brains of `game`.
pub fn live(game: &dyn Observe) -> Vec<Brain> {
    let table = game.table();
    game.seen()
        .iter()
        .enumerate()
        .filter(|(_, a)| !a.removed && a.health > 0 && table.actors[a.kind].category == Category::BossBrain)
        .map(|(i, a)| {
            let def = &table.actors[a.kind];
            Brain {
                actor: i as u32,
                body: Body { pos: a.pos, z: a.z, height: def.height, radius: def.radius, index: i },
            }
        })
        .collect()
}

/// The rocket a launcher fires: its body and speed (from its actor), how
/// high above the shooter's feet it leaves, and the ticks from the trigger
/// to its leaving (the launcher's `Fire` states before the first that
/// launches an actor: Doom's 8).
#[derive(Clone, Copy, Debug)]
pub struct Rocket {
    pub radius: f64,
    pub height: f64,
    pub speed: f64,
    pub lead: u32,
}

/// The rocket launcher, if `game`'s player has it with a rocket for a
/// shot: the rocket it fires.
pub fn launcher(game: &dyn Observe) -> Option<Rocket> {
    let player = game.player();
    let table = game.table();
    player.weapons.iter().find_map(|&w| {
        let def = table.actors[w].weapon.as_ref().filter(|d| d.slot == LAUNCHER_SLOT)?;
        let ammo = def.ammo.is_none_or(|k| player.ammo[k.index()] >= def.ammo_use.max(1));
        rocket_of(table, w).filter(|_| ammo)
    })
}

/// The rocket of the table's rocket launcher (the weapon in
/// [`LAUNCHER_SLOT`]), whoever holds it.
pub fn table_rocket(table: &ActorTable) -> Option<Rocket> {
    let w = table.actors.iter().position(|a| a.weapon.as_ref().is_some_and(|d| d.slot == LAUNCHER_SLOT))?;
    rocket_of(table, w)
}

/// The rocket weapon `w` fires.
fn rocket_of(table: &ActorTable, w: usize) -> Option<Rocket> {
    let mut state = table.actors[w].label("Fire")?;
    let mut lead = 0u32;
    for _ in 0..16 {
        let s = table.state(state);
        let launched = s.action.as_ref().and_then(|a| {
            a.args.iter().find_map(|g| match g {
                Arg::Actor(k) => Some(*k),
                _ => None,
            })
        });
        if let Some(k) = launched {
            let missile = &table.actors[table.spawned(k)];
            return Some(Rocket { radius: missile.radius, height: missile.height, speed: missile.speed(false), lead });
        }
        lead += s.tics.max(0) as u32;
        state = s.next?;
    }
    None
}

/// One line a rocket's way crosses: how far along, and the sectors either
/// side (none for a wall).
struct Crossing {
    at: f64,
    sides: Option<(usize, usize)>,
}

/// The lines crossed by a level flight from `from` towards `to` and on
/// past it, by the rocket's centre and its two sides, nearest first.
fn crossings(map: &Map, rocket: &Rocket, from: DVec2, to: DVec2) -> Vec<Crossing> {
    let along = (to - from).normalize_or_zero();
    let reach = from.distance(to) + BLAST;
    let side = DVec2::new(-along.y, along.x) * rocket.radius;
    let mut out = Vec::new();
    for l in &map.lines {
        let (a, b) = map.line_points(l);
        let sides = l.back.as_ref().map(|back| (l.front.sector, back.sector));
        for o in [DVec2::ZERO, side, -side] {
            if let Some(t) = crate::geom::crossing(from + o, from + o + along * reach, a, b) {
                out.push(Crossing { at: t * reach, sides });
            }
        }
    }
    out.sort_by(|x, y| x.at.total_cmp(&y.at));
    out
}

/// Where a shot is fired from: the map, and a lift's floor taken at another
/// height than it stands at now (the lift the shooter rides, when working
/// out where it would be worth firing from).
struct Shot<'a> {
    compiled: &'a CompiledMap,
    rocket: &'a Rocket,
    lift: Option<(usize, f64)>,
}

impl Shot<'_> {
    fn floor(&self, s: usize) -> f64 {
        match self.lift {
            Some((lift, floor)) if lift == s => floor,
            _ => self.compiled.map.sectors[s].floor,
        }
    }

    /// Does a rocket with its bottom at `z` pass the line between sectors
    /// `f` and `b`? (A missile whose bottom comes down to a floor bursts.)
    fn passes(&self, (f, b): (usize, usize), z: f64) -> bool {
        let sectors = &self.compiled.map.sectors;
        self.floor(f).max(self.floor(b)) < z && sectors[f].ceiling.min(sectors[b].ceiling) >= z + self.rocket.height
    }

    /// The damage a rocket fired level from `from` along `along` (a unit
    /// vector), its bottom at `z`, does to the brain (0 when it bursts too
    /// far away, out of the brain's sight, or within its blast of the
    /// shooter), given the way's crossings.
    fn damage(
        &self,
        scratch: &mut sight::Scratch,
        from: DVec2,
        along: DVec2,
        z: f64,
        brain: &Body,
        ways: &[Crossing],
    ) -> i32 {
        let stop = ways.iter().find(|c| !c.sides.is_some_and(|s| self.passes(s, z))).map_or(f64::INFINITY, |c| c.at);
        // A direct hit: the rocket meets the brain's box before anything
        // else (its path passes within the two radii of the brain).
        let level_with = z < brain.z + brain.height && z + self.rocket.height > brain.z;
        let to = brain.pos - from;
        let aside = along.perp_dot(to).abs();
        if level_with
            && aside < brain.radius + self.rocket.radius
            && to.dot(along) - brain.radius - self.rocket.radius < stop
        {
            return BLAST as i32;
        }
        if !stop.is_finite() {
            return 0;
        }
        // Doom's blast: by the larger axis distance, less the body's radius.
        let reach = |p: DVec2, q: DVec2, radius: f64| {
            let d = (p - q).abs();
            (d.x.max(d.y) - radius).max(0.0).floor()
        };
        // It bursts where it last stood before the wall: up to one piece of
        // its move (the engine cuts a move into pieces of 15 at most) short
        // of it. The nearer of the two ends counts.
        let piece = self.rocket.speed.min(MAX_PIECE);
        let mut worst = i32::MAX;
        for back in [self.rocket.radius, self.rocket.radius + piece] {
            let burst = from + along * (stop - back);
            let dist = reach(brain.pos, burst, brain.radius);
            if dist >= BLAST || reach(from, burst, crate::play::player::RADIUS) < BLAST {
                return 0;
            }
            let spot =
                Body { pos: burst, z, height: self.rocket.height, radius: self.rocket.radius, index: usize::MAX };
            if !sight::sight(self.compiled, scratch, brain, &spot) {
                return 0;
            }
            worst = worst.min((BLAST - dist) as i32);
        }
        worst
    }
}

/// The damage `rocket`, fired now from `from` with its bottom at `z`, would
/// do to `brain`.
pub fn blast(
    compiled: &CompiledMap,
    scratch: &mut sight::Scratch,
    rocket: &Rocket,
    from: DVec2,
    z: f64,
    brain: &Body,
) -> i32 {
    blast_along(compiled, scratch, rocket, (from, z), brain, (brain.pos - from).normalize_or_zero())
}

/// [`blast`] for a rocket fired along `along` (a unit vector), which need
/// not point at the brain: a 1.9 demo turns in 1/256ths of the circle, and
/// a rocket through the boss brain's slit wants the angle the body can
/// face, not the one it would like to.
pub fn blast_along(
    compiled: &CompiledMap,
    scratch: &mut sight::Scratch,
    rocket: &Rocket,
    (from, z): (DVec2, f64),
    brain: &Body,
    along: DVec2,
) -> i32 {
    let ways = crossings(&compiled.map, rocket, from, from + along * from.distance(brain.pos).max(1.0));
    Shot { compiled, rocket, lift: None }.damage(scratch, from, along, z, brain, &ways)
}

/// The sectors whose floors and ceilings bound `body`: the one under its
/// centre and both sides of every two-sided line its square touches (as
/// Doom's `P_CheckPosition` takes the opening of each line the box
/// touches, so a ceiling moving in any of them can squeeze the body).
fn sectors_under(compiled: &CompiledMap, body: &Body) -> Vec<usize> {
    let map = &compiled.map;
    let square = Aabb { min: body.pos - DVec2::splat(body.radius), max: body.pos + DVec2::splat(body.radius) };
    let (min, max) = (square.min, square.max);
    let corners = [min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)];
    let mut out = vec![compiled.sector_at(body.pos)];
    for l in &map.lines {
        let Some(back) = &l.back else { continue };
        let (a, b) = map.line_points(l);
        let touches = square.contains(a)
            || square.contains(b)
            || (0..4).any(|k| crate::geom::crossing(corners[k], corners[(k + 1) % 4], a, b).is_some());
        if touches {
            out.extend([l.front.sector, back.sector]);
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// The lines a player can set off that start a crusher over `brain`: a
/// body that no longer fits under a ceiling that crushes takes 10 damage
/// every 4 tics (Doom's `PIT_ChangeSector`), and a crusher's ceiling comes
/// down to 8 above the floor and goes on for ever, so a brain taller than
/// that dies under it (250 health: 100 tics of crushing).
///
/// Floors and ceilings that crush once are not counted: vanilla's stop
/// within 8 units of the body's top (`raiseFloorCrush` rises to 8 below
/// the ceiling at full speed, 2 or 3 blows; `lowerAndCrush` comes down to
/// 8 above the floor at an eighth of its speed, 16 blows, 160 damage),
/// short of a brain's 250.
pub fn crushers(level: &Level, brain: &Body) -> Vec<LineId> {
    let map = &level.compiled.map;
    if brain.height <= CRUSHER_GAP {
        return Vec::new();
    }
    let under = sectors_under(&level.compiled, brain);
    (0..(map.lines.len() + map.trigger_lines.len()) as LineId)
        .filter(|&id| {
            let (line, _, _, special) = line_of(map, id);
            special.is_some_and(|special| {
                matches!(special.action, Action::Crusher { .. })
                    && special.by.players()
                    && target_sectors(level, line, special).iter().any(|s| under.contains(s))
            })
        })
        .collect()
}

/// The ways `check` counts to kill `brain`, with the sectors' floors at
/// `floors`: the lines that start a crusher over it ([`crushers`]), and the
/// cells of the lift spots from which `rocket` (the table's launcher's)
/// hurts it ([`spots`]).
pub fn ways(
    nav: &NavGrid,
    level: &Level,
    mech: &Mechanisms,
    rocket: Option<&Rocket>,
    brain: &Body,
    floors: &[f64],
) -> (Vec<LineId>, super::plan::Targets) {
    let mut shot = super::plan::Targets::default();
    for spot in rocket.iter().flat_map(|r| spots(nav, &level.compiled, mech, r, brain, floors)) {
        shot.add(super::plan::cells_near(nav, nav.centre_of(spot.cell), 1.0));
    }
    (crushers(level, brain), shot)
}

/// A brain's death by the crusher that `line` starts, in words.
pub fn crushed_by(map: &Map, line: LineId) -> String {
    let (_, a, b, _) = line_of(map, line);
    let m = (a + b) / 2.0;
    format!("crushed by the crusher that line {line} at ({:.0}, {:.0}) starts", m.x, m.y)
}

/// The highest floor lift `lift` reaches with its floor at `floor`: its
/// top at rest, or, raised above that (something else moves its floor up,
/// as MAP30's switch raises its lift 512), as high as its ceiling lets a
/// body stand.
fn lift_reach(map: &Map, mech: &Mechanisms, lift: usize, floor: f64) -> f64 {
    if floor > mech.lift_top[lift] {
        map.sectors[lift].ceiling - HEADROOM
    } else {
        mech.lift_top[lift]
    }
}

/// A place to fire from: a cell wholly on a lift, and the lowest and
/// highest floor heights of the lift from which a rocket fired level hurts
/// the brain by [`WORTH`] at least.
#[derive(Clone, Copy, Debug)]
pub struct Spot {
    pub cell: Cell,
    pub lift: usize,
    pub low: f64,
    pub high: f64,
}

/// Where to fire `rocket` at `brain` from, with the sectors' floors at
/// `floors` (the level's own, or those a plan assumes): every cell wholly
/// on a lift (not a perpetual one) within reach of it, with the heights the
/// lift passes through (its lowest neighbouring floor to its top) that
/// make a shot worth firing. The widest window first.
pub fn spots(
    nav: &NavGrid,
    compiled: &CompiledMap,
    mech: &Mechanisms,
    rocket: &Rocket,
    brain: &Body,
    floors: &[f64],
) -> Vec<Spot> {
    let map = &compiled.map;
    let mut scratch = sight::Scratch::default();
    let reach = DVec2::splat(LOOK);
    let mut out = Vec::new();
    for cell in nav.cells_in_box(brain.pos - reach, brain.pos + reach) {
        let &[lift] = nav.touched(cell) else { continue };
        let lift = lift as usize;
        if mech.lift_lines[lift].is_empty() || mech.perpetual[lift] || !nav.standable(cell) {
            continue;
        }
        let top = lift_reach(map, mech, lift, floors[lift]);
        let from = nav.centre_of(cell);
        let ways = crossings(map, rocket, from, brain.pos);
        let along = (brain.pos - from).normalize_or_zero();
        let mut window: Option<(f64, f64)> = None;
        let mut best: Option<(f64, f64)> = None;
        let mut floor = mech.lift_low[lift];
        while floor <= top {
            let shot = Shot { compiled, rocket, lift: Some((lift, floor)) };
            if shot.damage(&mut scratch, from, along, floor + MISSILE_HEIGHT, brain, &ways) >= WORTH {
                window = Some(window.map_or((floor, floor), |w| (w.0, floor)));
            } else {
                window = None;
            }
            if let Some(w) = window.filter(|w| best.is_none_or(|b| w.1 - w.0 > b.1 - b.0)) {
                best = Some(w);
            }
            floor += Z_STEP;
        }
        if let Some((low, high)) = best {
            out.push(Spot { cell, lift, low, high });
        }
    }
    out.sort_by(|a, b| (b.high - b.low).total_cmp(&(a.high - a.low)).then(a.cell.cmp(&b.cell)));
    out
}

impl Autopilot {
    /// On the lift, to fire at the boss brain as it rides up.
    pub(super) fn riding(&self) -> bool {
        self.active.as_ref().is_some_and(|a| matches!(a.goal, Goal::Brain(..)) && a.arrived > 0)
    }

    /// The one sector under a body at `p`, if its circle is wholly on one
    /// (a spot's lift: [`spots`] takes only such cells).
    fn lift_at(&self, p: DVec2) -> Option<usize> {
        match self.nav.cell_at(p).map(|c| self.nav.touched(c)) {
            Some(&[s]) => Some(s as usize),
            _ => None,
        }
    }

    /// Is the body wholly on the lift of `goal`, a boss brain goal's spot?
    /// Anywhere on it is arrival (a body that fights on the way may reach
    /// the lift, not the spot, before the lift starts up).
    pub(super) fn on_brain_lift(&self, game: &dyn Observe, goal: &Goal) -> bool {
        let Goal::Brain(spot, _) = goal else { return false };
        let here = self.lift_at(game.player().pos);
        here.is_some() && here == self.lift_at(*spot)
    }

    /// Is the lift under the boss brain goal's spot on its way up?
    pub(super) fn lift_rising(&self, game: &dyn Observe) -> bool {
        let Some(&Goal::Brain(spot, _)) = self.active.as_ref().map(|a| &a.goal) else { return false };
        self.lift_at(spot).is_some_and(|s| game.level().compiled.map.sectors[s].floor > self.last.floor[s])
    }

    /// With no exit line within reach, a live boss brain, and the rocket
    /// launcher with a rocket: the lift to fire from ([`spots`]), the
    /// widest window over every brain. The body goes to its place on it;
    /// at rest above the heights a shot hurts from, the lift is called down
    /// first (the body steps off it to the call), and moving with the place
    /// out of reach, the body waits by the call.
    pub(super) fn brain_goal(&mut self, game: &dyn Observe) -> Option<Active> {
        if let Some(a) = self.crusher_goal(game) {
            return Some(a);
        }
        let rocket = launcher(game)?;
        let level = game.level();
        let map = &level.compiled.map;
        let live_now = live_heights(map);
        let (spot, actor) = live(game)
            .into_iter()
            .filter_map(|b| {
                let spot = *spots(&self.nav, &level.compiled, &self.mech, &rocket, &b.body, &live_now.floor).first()?;
                Some((spot, b.actor))
            })
            .filter(|(s, actor)| !self.failed(&Goal::Brain(self.nav.centre_of(s.cell), *actor)))
            .max_by(|a, b| (a.0.high - a.0.low).total_cmp(&(b.0.high - b.0.low)))?;
        let goal = Goal::Brain(self.nav.centre_of(spot.cell), actor);
        let (lift, now) = (spot.lift, game.ticks());
        if game.is_busy(lift) || live_now.floor[lift] <= spot.high {
            if let Some(route) = self.route_to(game, &goal) {
                return Some(Active::new(goal, Purpose::Exit, route, now));
            }
        }
        // At rest above the heights to fire from: call it. Moving with its
        // place out of reach: wait by its call for it to stop. Every line
        // that lowers it will do (those sorted as calls from below wait
        // for it to come to rest at a new top).
        for (line, on) in self.mech.lift_lines[lift].clone() {
            let call = match on {
                Activation::Use => Goal::Use(line),
                Activation::Walk => Goal::Cross(line),
                _ => continue,
            };
            let up = |h: &mut Heights| (h.low[lift], h.floor[lift]) = (live_now.floor[lift], live_now.floor[lift]);
            if let Some(route) = self.route_with(game, &call, up) {
                self.log.push(format!("tick {now}: calling lift {lift} for a shot at the boss brain"));
                return Some(Active::new(call, Purpose::Lift, route, now));
            }
        }
        None
    }

    /// A live boss brain with a crusher over it ([`crushers`]): the nearest
    /// line that starts one, unless one is running there already (the brain
    /// dies under it: nothing to do but wait) or the line is used up.
    fn crusher_goal(&mut self, game: &dyn Observe) -> Option<Active> {
        let level = game.level();
        let map = &level.compiled.map;
        let spent = self.spent(game);
        let mut best: Option<(super::plan::Route, Goal)> = None;
        // Each line once, however many brains it crushes (MAP16's twelve
        // lines start the crushers over all four).
        let lines: std::collections::BTreeSet<LineId> =
            live(game).iter().flat_map(|b| crushers(level, &b.body)).collect();
        for line in lines {
            let (l, _, _, Some(special)) = line_of(map, line) else { continue };
            if spent.contains(&line) || Self::used_up(game, line) {
                continue;
            }
            if target_sectors(level, l, special).iter().any(|&s| game.is_busy(s)) {
                return None;
            }
            let goal = match special.on {
                Activation::Use => Goal::Use(line),
                Activation::Walk => Goal::Cross(line),
                _ => continue,
            };
            if self.failed(&goal) {
                continue;
            }
            if let Some(route) = self.route_to(game, &goal) {
                if best.as_ref().is_none_or(|(r, _)| route.cost < r.cost) {
                    best = Some((route, goal));
                }
            }
        }
        let (route, goal) = best?;
        self.log.push(format!("tick {}: starting a crusher over the boss brain", game.ticks()));
        Some(Active::new(goal, Purpose::Exit, route, game.ticks()))
    }

    /// On the lift under `spot`: keep the place, face the boss brain with
    /// the launcher up, and hold the trigger while a rocket, leaving
    /// [`Rocket::lead`] ticks from now with the lift that much further up
    /// (or still, at rest), would burst near enough to hurt it (at a lift's
    /// 4 units a tick a window passes in a few ticks: one rocket a ride).
    /// The ride ends when the lift is at rest and a shot from there would
    /// not hurt.
    pub(super) fn fire_at_brain(
        &mut self,
        game: &dyn Observe,
        a: &mut Active,
        spot: DVec2,
        actor: u32,
    ) -> Option<TickInput> {
        let now = game.ticks();
        let level = game.level();
        let map = &level.compiled.map;
        let target = live(game).into_iter().find(|b| b.actor == actor);
        let (Some(target), Some(lift), Some(rocket)) = (target, self.lift_at(spot), launcher(game)) else {
            self.next_replan = now;
            return None;
        };
        let player = game.player();
        let floor = map.sectors[lift].floor;
        let rise = floor - self.last.floor[lift];
        let then = (player.z + rise * f64::from(rocket.lead)).min(lift_reach(map, &self.mech, lift, floor));
        let blast = blast(&level.compiled, &mut self.sight, &rocket, player.pos, then + MISSILE_HEIGHT, &target.body);
        let busy = game.is_busy(lift);
        if (!busy && a.arrived > 1 && blast < WORTH) || a.arrived > RIDE_TICKS {
            self.next_replan = now;
            return None;
        }
        let to = target.body.pos - player.pos;
        let direct = to.y.atan2(to.x).to_degrees();
        let unit = |degrees: f64| DVec2::from_angle(degrees.to_radians());
        let z = then + MISSILE_HEIGHT;
        let mut hurts = |degrees: f64| {
            blast_along(&level.compiled, &mut self.sight, &rocket, (player.pos, z), &target.body, unit(degrees))
                >= WORTH
        };
        // Where the game turns in steps, the angle it can face nearest the
        // brain whose rocket hurts it (the slit is narrow: one step off
        // the direct line may hit its edge).
        let step = game.turn_step();
        let (aim, aim_hurts) = if step > 0.0 {
            let base = (direct / step).round();
            let hurting = [0.0, -1.0, 1.0, -2.0, 2.0].into_iter().map(|k| (base + k) * step).find(|&q| hurts(q));
            (hurting.unwrap_or(base * step), hurting.is_some())
        } else {
            (direct, true)
        };
        let turn = turn_to(player.angle, aim);
        let in_hand = super::slot_of(game, player.pending_weapon.or(player.ready_weapon));
        let ready = player.pending_weapon.is_none() && super::slot_of(game, player.ready_weapon) == Some(LAUNCHER_SLOT);
        // Fired only facing the angle that hurts (the body faces a whole
        // number of steps, so within half a step is on it), and never on
        // the way down: the rocket would leave lower than reckoned.
        let facing = aim_hurts && turn.abs() < if step > 0.0 { step / 2.0 } else { 1.0 };
        let fire = ready && facing && rise >= 0.0 && blast >= WORTH;
        if std::env::var_os("SIGHTLINE_AUTOPILOT_TRACE").is_some() {
            eprintln!(
                "brain tick {now} pos {:?} z {} then {then} blast {blast} ready {ready} turn {turn:.1} arrived {}",
                player.pos, player.z, a.arrived
            );
        }
        if fire && !self.firing {
            self.log.push(format!("tick {now}: rocket at the boss brain from a floor at {:.0}", player.z));
        }
        self.firing = fire;
        // Back to the place, sideways or backwards as need be: the body
        // keeps facing the brain.
        let back = spot - player.pos;
        let keep = if back.length() > 8.0 && player.velocity.length() * 6.0 < back.length() {
            let (forward, strafe) = super::thrust_towards(player.angle, back.y.atan2(back.x).to_degrees());
            TickInput { forward, strafe, ..Default::default() }
        } else {
            self.hold(game)
        };
        Some(TickInput {
            turn: turn as f32,
            fire,
            weapon: if in_hand == Some(LAUNCHER_SLOT) { 0 } else { LAUNCHER_SLOT },
            ..keep
        })
    }
}
