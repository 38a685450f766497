//! Sets off every line special of a level through the player's inputs, as
//! a player who could stand anywhere would: each use special used from in
//! front of its line, each walk special walked across, each shoot special
//! shot, every key held. Putting the player in front of each line
//! (`SimGame::place_player`) is the only help (tests/freedoom.rs does the
//! same for use lines).
//!
//! Whether a special went off is read from what the simulation shows the
//! outside: a used line's `Event::Special` (`P_UseSpecialLine` acted); a
//! walk line's when the player's centre went from one side of it to the
//! other (`P_TryMove` calls `P_CrossSpecialLine` then), a teleport froze
//! the player, a mover started or the line lost its special (W1); a shot
//! line's when the shot changed a switch texture
//! (each of Doom's three gun specials does) or started a mover.
//!
//! Left out: exits (the level would end and ticks would do nothing), the
//! specials only monsters set off, the specials that stop perpetual lifts
//! and crushers, and a special whose sectors all have a mover at work
//! already, such as the second side of a door: using a moving door
//! reverses it, as in Doom, and would undo what the first side set going.

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::fixed::Fixed;
use sightline::geom::{exact_side, Side};
use sightline::map::special::{Action, Activation};
use sightline::map::{LineSpecial, Map};
use sightline::play::events::Event;
use sightline::play::world::SpecialLine;
use sightline::play::TickInput;
use sightline::sim::game::SimGame;
use sightline::sim::{ThinkerKind, NUMCARDS};

/// What setting the specials off did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SetOff {
    /// Specials tried (exits and stops excluded), by how they go off: use, walk, shoot.
    pub tried: [usize; 3],
    /// ... and of those, the ones that went off (their line's special ran).
    pub fired: [usize; 3],
    /// Specials not tried because every sector they move was already moving.
    pub busy: usize,
    /// The specials tried that did not go off, on either pass.
    pub failed: Vec<Failure>,
    /// Ticks it took.
    pub ticks: u64,
}

/// A special that did not go off: its line, what it does, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    pub line: SpecialLine,
    pub action: &'static str,
    pub on: Activation,
    pub why: Outcome,
}

/// What one try did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    WentOff,
    /// No place inside the map on the side it goes off from (the sector in
    /// front is too thin, a point there is in another sector, or Doom's
    /// 32-unit body does not fit there: `P_CheckPosition` finds a wall, a
    /// thing or too low a ceiling, as for the face of a shut door).
    NoRoom,
    /// The player stood there and pressed, fired or walked, and the special
    /// did not go off: the way across is blocked (a closed door, a step or
    /// a solid thing such as a tree just beyond the line), or a wall came
    /// first.
    Blocked,
}

impl SetOff {
    pub fn tried_total(&self) -> usize {
        self.tried.iter().sum()
    }

    pub fn fired_total(&self) -> usize {
        self.fired.iter().sum()
    }
}

fn slot(on: Activation) -> usize {
    match on {
        Activation::Use => 0,
        Activation::Walk => 1,
        Activation::Shoot => 2,
    }
}

/// How long what a special starts usually keeps running: set off the
/// long-lived ones first and doors last, so that as many as possible still
/// run when the setup ends (one special a tick; a Doom door is done about
/// 214 ticks after it opens, and some maps have hundreds of specials).
fn lifetime_rank(action: &Action) -> u8 {
    match action {
        Action::Crusher { .. } | Action::PerpetualLift { .. } | Action::Light(_) => 0,
        Action::Stairs { .. } | Action::Donut { .. } | Action::Floor { .. } | Action::Ceiling { .. } => 1,
        Action::Lift { .. } => 2,
        Action::Door { .. } => 3,
        _ => 4,
    }
}

/// The specials worth setting off, long-lived first, then in line order.
fn specials(map: &Map) -> Vec<(SpecialLine, LineSpecial)> {
    let walls = map.lines.iter().enumerate().filter_map(|(i, l)| Some((SpecialLine::Wall(i), l.special.clone()?)));
    let triggers = map.trigger_lines.iter().enumerate().map(|(i, t)| (SpecialLine::Trigger(i), t.special.clone()));
    let mut all: Vec<(SpecialLine, LineSpecial)> = walls
        .chain(triggers)
        .filter(|(_, s)| s.by.players())
        .filter(|(_, s)| {
            !matches!(s.action, Action::Exit | Action::SecretExit | Action::StopLift | Action::StopCrusher)
        })
        .collect();
    all.sort_by_key(|(_, s)| lifetime_rank(&s.action));
    all
}

/// Gives the player every key (Doom's six cards and skulls), so that
/// locked doors open.
fn give_all_keys(game: &mut SimGame) {
    let console = game.sim.console;
    if let Some(p) = game.sim.players[console].as_mut() {
        p.cards = [true; NUMCARDS];
    }
}

/// Sets off every special of the game's map it can (see the module doc)
/// and returns what it did. Those that do not go off are tried once more
/// after the rest, when the doors and floors in their way may have moved.
/// The player ends wherever the last one left it.
pub fn set_off_everything(game: &mut SimGame) -> SetOff {
    let map = game.level().compiled.map.clone();
    give_all_keys(game);
    let start = game.ticks();
    let mut out = SetOff::default();
    let mut retry = Vec::new();
    for (line, special) in specials(&map) {
        if moves_only_busy_sectors(game, &map, line, &special) {
            out.busy += 1;
            continue;
        }
        out.tried[slot(special.on)] += 1;
        match try_one(game, &map, line, &special) {
            Outcome::WentOff => out.fired[slot(special.on)] += 1,
            _ => retry.push((line, special)),
        }
    }
    for (line, special) in retry {
        if moves_only_busy_sectors(game, &map, line, &special) {
            // Something else has set its sectors moving since.
            out.tried[slot(special.on)] -= 1;
            out.busy += 1;
            continue;
        }
        match try_one(game, &map, line, &special) {
            Outcome::WentOff => out.fired[slot(special.on)] += 1,
            why => out.failed.push(Failure { line, action: special.action.name(), on: special.on, why }),
        }
    }
    out.ticks = game.ticks() - start;
    out
}

fn try_one(game: &mut SimGame, map: &Map, line: SpecialLine, special: &LineSpecial) -> Outcome {
    match special.on {
        Activation::Use => press(game, map, line, TickInput { use_line: true, ..Default::default() }),
        Activation::Shoot => press(game, map, line, TickInput { fire: true, ..Default::default() }),
        Activation::Walk => walk_across(game, map, line),
    }
}

/// Does `special` move sectors (with a mover: lights and teleports do not)
/// and is every one of them moving already?
fn moves_only_busy_sectors(game: &SimGame, map: &Map, line: SpecialLine, special: &LineSpecial) -> bool {
    if !special.action.moves_sectors() || matches!(special.action, Action::Light(_)) {
        return false;
    }
    let targets: Vec<usize> = match (special.tag, line) {
        (0, SpecialLine::Wall(i)) => map.lines[i].back.iter().map(|b| b.sector).collect(),
        (0, SpecialLine::Trigger(_)) => Vec::new(),
        (tag, _) => map.sectors_tagged(tag).collect(),
    };
    !targets.is_empty() && targets.iter().all(|&s| game.is_busy(s))
}

/// The line's two ends, the unit normal pointing to its front (right-hand)
/// side, and the sector on each side (none for a trigger line).
fn geometry(map: &Map, line: SpecialLine) -> (DVec2, DVec2, DVec2, [Option<usize>; 2]) {
    let ((a, b), sectors) = match line {
        SpecialLine::Wall(i) => {
            let l = &map.lines[i];
            (map.line_points(l), [Some(l.front.sector), l.back.as_ref().map(|s| s.sector)])
        }
        SpecialLine::Trigger(i) => {
            let t = &map.trigger_lines[i];
            ((map.vertices[t.from], map.vertices[t.to]), [None, None])
        }
    };
    let d = (b - a).normalize();
    (a, b, DVec2::new(d.y, -d.x), sectors)
}

/// Puts the player `distance` in front of (`side` 1) or behind (-1) the
/// middle of `line`, facing it, alive and free to act. `false` when no
/// such place is inside the map on that side.
fn stand_by(game: &mut SimGame, map: &Map, line: SpecialLine, side: f64, distances: &[f64]) -> bool {
    let (a, b, normal, sectors) = geometry(map, line);
    let want = if side > 0.0 { Side::Front } else { Side::Back };
    let sector = if side > 0.0 { sectors[0] } else { sectors[1] };
    let middle = (a + b) / 2.0;
    let Some(pos) = distances
        .iter()
        .map(|&k| middle + normal * (k * side))
        .find(|&p| exact_side(a, b, p) == want && sector.is_none_or(|s| map.sector_strictly_containing(p) == Some(s)))
    else {
        return false;
    };
    let facing = -normal * side;
    if !game.place_player(pos, facing.y.atan2(facing.x).to_degrees()) {
        return false;
    }
    game.set_health(100);
    let console = game.sim.console;
    let Some(p) = game.sim.players[console].as_mut() else { return false };
    // Free to act: use and fire let go (a press needs them up first, as
    // Doom's `usedown` and `attackdown` say), no teleport freeze left.
    (p.usedown, p.attackdown) = (false, false);
    let mo = p.mo;
    game.sim.mo_mut(mo).reactiontime = 0;
    true
}

/// What a shot or walk line's going off changes: the switch textures
/// flipped so far and the movers started so far.
fn marks(game: &SimGame) -> (u32, usize) {
    let movers = game.sim.thinkers.iter().filter(|t| !matches!(t.kind, ThinkerKind::Mobj(_))).count();
    (game.sim.textures_changed, movers)
}

/// Did the used `line`'s special go off on the last tick?
fn used(game: &SimGame, line: SpecialLine) -> bool {
    game.events().iter().any(|e| matches!(e, Event::Special { line: l, .. } if *l == line))
}

/// Uses or shoots `line` from its front: one tick.
fn press(game: &mut SimGame, map: &Map, line: SpecialLine, input: TickInput) -> Outcome {
    if !stand_by(game, map, line, 1.0, &[20.0, 8.0, 2.0]) {
        return Outcome::NoRoom;
    }
    let before = marks(game);
    game.tick(&input);
    let went_off = if input.use_line { used(game, line) } else { marks(game) != before };
    if went_off {
        Outcome::WentOff
    } else {
        Outcome::Blocked
    }
}

/// Runs across `line` from 12 units in front of it (or, if that fails,
/// from behind: walk specials go off either way), a few ticks at most.
fn walk_across(game: &mut SimGame, map: &Map, line: SpecialLine) -> Outcome {
    let (a, b, normal, _) = geometry(map, line);
    let mut outcome = Outcome::NoRoom;
    for side in [1.0, -1.0] {
        if !stand_by(game, map, line, side, &[12.0, 6.0, 2.0]) {
            continue;
        }
        outcome = Outcome::Blocked;
        let start = if side > 0.0 { Side::Front } else { Side::Back };
        let velocity = -normal * side * 16.0;
        let mo = game.sim.player(game.sim.console).map(|p| p.mo).expect("a player in the game");
        let m = game.sim.mo_mut(mo);
        (m.momx, m.momy) = (Fixed::from_f64(velocity.x), Fixed::from_f64(velocity.y));
        for _ in 0..3 {
            let before = marks(game);
            game.tick(&TickInput { forward: 1, run: true, ..Default::default() });
            let crossed = exact_side(a, b, game.player().pos) != start;
            // A teleport freezes the player (`P_Teleport` sets its
            // reactiontime to 18), wherever the destination is; a W1 line
            // loses its special once it has acted.
            let teleported = game.player().freeze > 0;
            if crossed || teleported || marks(game) != before || game.special(line).is_none() {
                return Outcome::WentOff;
            }
        }
    }
    outcome
}
