//! Setting up a scene on the simulation for a test, as a level editor or
//! Doom's cheats would (the player put somewhere, made hard to kill), and
//! reading its bodies by their actor names. Each change goes through the
//! simulation's own functions (`P_TeleportMove`), so the game goes on from
//! a state Doom could reach.

use glam::DVec2;
use sightline::autopilot::observe::Observe;
use sightline::fixed::{Angle, Fixed};
use sightline::play::TickInput;
use sightline::sim::game::SimGame;
use sightline::sim::mobj::mf;
use sightline::sim::{collision, MobjId};

use crate::{load, root};

/// A game on `tests/maps/{name}.ron` with the default options.
pub fn game(name: &str) -> SimGame {
    game_with(name, sightline::play::GameOptions::default())
}

pub fn game_with(name: &str, options: sightline::play::GameOptions) -> SimGame {
    let p = root().join("tests").join("maps").join(format!("{name}.ron"));
    assert!(p.exists(), "missing fixture {}", p.display());
    SimGame::on_level(load(&p), &format!("{name}.ron"), options).unwrap_or_else(|e| panic!("{e}"))
}

/// The player's body.
pub fn player_mo(g: &SimGame) -> MobjId {
    g.sim.player(g.sim.console).expect("a player in the game").mo
}

/// Puts the player at `pos` on the floor there, facing `angle` degrees, at
/// rest, as a teleporter does without its fog and freeze (Doom's
/// `P_TeleportMove`, which telefrags what stands there). Panics if the spot
/// is outside the map.
pub fn teleport(g: &mut SimGame, pos: DVec2, angle: f64) {
    let mo = player_mo(g);
    let (x, y) = (Fixed::from_f64(pos.x), Fixed::from_f64(pos.y));
    assert!(collision::teleport_move(&mut g.sim, mo, x, y), "could not teleport the player to {pos}");
    let m = g.sim.mo_mut(mo);
    m.z = m.floorz;
    m.angle = Angle::from_degrees(angle);
    (m.momx, m.momy, m.momz) = (Fixed::ZERO, Fixed::ZERO, Fixed::ZERO);
    let z = m.z;
    let console = g.sim.console;
    let p = g.sim.players[console].as_mut().expect("a player in the game");
    p.viewz = z + p.viewheight;
}

/// [`teleport`] only where the player could stand: in the map, clear of
/// walls and solid things (`P_CheckPosition`, asked of a copy of the game
/// since it picks up what it touches), with room for its height. Whether
/// it went.
pub fn try_teleport(g: &mut SimGame, pos: DVec2, angle: f64) -> bool {
    if Observe::level(g).compiled.locate(pos).is_none() {
        return false;
    }
    let mo = player_mo(g);
    let (x, y) = (Fixed::from_f64(pos.x), Fixed::from_f64(pos.y));
    let mut probe = g.sim.clone();
    if !collision::check_position(&mut probe, mo, x, y) || probe.tm.ceilingz - probe.tm.floorz < probe.mo(mo).height {
        return false;
    }
    teleport(g, pos, angle);
    true
}

/// Whether `looker` sees `target` by Doom's `P_CheckSight`, leaving the
/// game as it was (the check marks lines with `validcount` and sets the
/// shared slopes: both are put back).
pub fn sees(g: &mut SimGame, looker: MobjId, target: MobjId) -> bool {
    let sim = &mut g.sim;
    let kept = (sim.validcount, sim.line_valid.clone(), sim.tm.clone());
    let seen = sightline::sim::sight::check_sight(sim, looker, target);
    (sim.validcount, sim.line_valid, sim.tm) = kept;
    seen
}

/// Wakes a monster on the player as `A_Look` does when it sees it: the
/// player its target, its see state.
pub fn wake(g: &mut SimGame, id: MobjId) {
    let me = player_mo(g);
    g.sim.mo_mut(id).target = Some(me);
    let see = g.sim.info.things[g.sim.mo(id).kind].seestate;
    g.sim.set_mobj_state(id, see);
}

/// Wakes every live monster (counted as a kill, not dead).
pub fn wake_all(g: &mut SimGame) {
    let asleep: Vec<MobjId> = g
        .sim
        .live_mobjs()
        .filter(|&id| {
            let m = g.sim.mo(id);
            m.has(mf::COUNTKILL) && m.health > 0 && m.target.is_none()
        })
        .collect();
    for id in asleep {
        wake(g, id);
    }
}

/// Turns the player to `angle` degrees where it stands.
pub fn turn(g: &mut SimGame, angle: f64) {
    let mo = player_mo(g);
    g.sim.mo_mut(mo).angle = Angle::from_degrees(angle);
}

/// The bodies (removed ones too) of the actor `name`, in spawn order.
pub fn named(g: &SimGame, name: &str) -> Vec<MobjId> {
    let table = &g.sim.info.table;
    (0..g.sim.mobjs.len() as u32).map(MobjId).filter(|&id| table.actors[g.sim.mo(id).kind].name == name).collect()
}

/// The first body of the actor `name`.
pub fn first(g: &SimGame, name: &str) -> MobjId {
    *named(g, name).first().unwrap_or_else(|| panic!("no {name} in play"))
}

/// A body's place in map units.
pub fn pos(g: &SimGame, id: MobjId) -> DVec2 {
    let m = g.sim.mo(id);
    DVec2::new(m.x.to_f64(), m.y.to_f64())
}

/// Whether a body is still in play (not removed, its state not Doom's
/// NULL state).
pub fn present(g: &SimGame, id: MobjId) -> bool {
    let m = g.sim.mo(id);
    !m.removed && m.state.is_some()
}

pub fn idle(g: &mut SimGame, ticks: usize) {
    for _ in 0..ticks {
        g.tick(&TickInput::default());
    }
}

/// What the renderers draw is every body still in play but the player's
/// own and those Doom keeps out of the sectors' lists (`MF_NOSECTOR`: a
/// teleport destination, which `R_AddSprites` never sees), where it stands
/// (`sim::draw::Scene::draw` writes them each tic).
pub fn assert_drawn_as_they_stand(g: &SimGame) {
    let level = Observe::level(g);
    let mut drawn: Vec<_> = level.things.iter().map(|t| (t.key, t.pos.to_array(), t.z.to_bits())).collect();
    let me = player_mo(g);
    let mut want: Vec<_> = g
        .sim
        .live_mobjs()
        .filter(|&id| id != me && present(g, id) && !g.sim.mo(id).has(mf::NOSECTOR))
        .map(|id| (id.0 as usize, pos(g, id).to_array(), g.sim.mo(id).z.to_f64().to_bits()))
        .collect();
    drawn.sort_by(|a, b| a.0.cmp(&b.0));
    want.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(drawn, want);
}

/// Puts the player at `at` facing `angle` degrees, still, feet on the
/// floor, use released (the start of a scenario): Doom's `P_TeleportMove`,
/// then the floor and ceiling `P_CheckPosition` finds there
/// (P_TeleportMove takes the sector's alone, so a body overhanging a ledge
/// would stand in the air until it moved), without the fog or the 18-tic
/// hold. Use is released as a tic without it leaves it (G_PlayerReborn
/// holds use down at a level's start so that nothing is used on tic 0).
pub fn stand(g: &mut SimGame, at: DVec2, angle: f64) {
    let mo = player_mo(g);
    let (x, y) = (Fixed::from_f64(at.x), Fixed::from_f64(at.y));
    assert!(collision::teleport_move(&mut g.sim, mo, x, y), "could not stand the player at {at}");
    collision::check_position(&mut g.sim, mo, x, y);
    let (floorz, ceilingz) = (g.sim.tm.floorz, g.sim.tm.ceilingz);
    let m = g.sim.mo_mut(mo);
    (m.floorz, m.ceilingz) = (floorz, ceilingz);
    m.z = m.floorz;
    (m.momx, m.momy, m.momz) = (Fixed::ZERO, Fixed::ZERO, Fixed::ZERO);
    m.angle = Angle::from_degrees(angle);
    m.reactiontime = 0;
    let console = g.sim.console;
    g.sim.players[console].as_mut().expect("a player in the game").usedown = false;
}

/// The thinker a sector's `specialdata` names, unless removed (a RON
/// map's sector `s` is the simulation's sector `s`).
pub fn mover(g: &SimGame, s: usize) -> Option<&sightline::sim::ThinkerKind> {
    let id = g.sim.level.sectors[s].specialdata?;
    let t = g.sim.thinker(id);
    (t.status != sightline::sim::think::Status::Removed).then_some(&t.kind)
}

/// What a door thinker (`vldoor_t`) is doing, by its `direction`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DoorState {
    /// 1: going up.
    Opening,
    /// 0: at the top, counting down `topcountdown`.
    Open,
    /// -1: going down.
    Closing,
    /// 2: a raise-in-5-minutes door's first wait.
    Waiting,
}

/// What the door on sector `s` is doing; `None` when no door is at work
/// there (it is shut, or open for good), as Doom finds it.
pub fn door(g: &SimGame, s: usize) -> Option<DoorState> {
    match mover(g, s)? {
        sightline::sim::ThinkerKind::Door(d) => Some(match d.direction {
            1 => DoorState::Opening,
            0 => DoorState::Open,
            -1 => DoorState::Closing,
            _ => DoorState::Waiting,
        }),
        _ => None,
    }
}
