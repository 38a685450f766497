//! Fighting: which enemy in sight to shoot and with which weapon, and
//! when to hold fire (a barrel near the line of fire, a rocket that would
//! burst on a wall in the bot's face). The route follower decides where
//! the body goes; this module only aims and chooses.

use glam::DVec2;

use super::sight::{self, Body};
use super::{plan, Autopilot, Observe, BARREL_BLAST, BARREL_CLEARANCE, CROWD, FIGHT_RANGE, MELEE_REACH};
use crate::actors::{ActorFlag, Category};
use crate::play::TickInput;

/// The enemy the bot aims at on a tick, for whoever turns its input into
/// other buttons (`scenario::expert`): the point aimed at (the enemy, or
/// where a rocket will meet it) and the enemy's radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aim {
    pub at: DVec2,
    pub radius: f64,
    /// The enemy, by index among the things ([`Observe::seen`]).
    pub thing: usize,
    /// The weapon fires a missile (the rocket launcher, the BFG), not
    /// bullets.
    pub missile: bool,
}

impl Autopilot {
    /// The enemy to shoot, if one is in sight: the angle to it, the
    /// weapon number to hold, how far it is, and how near to let it come
    /// (see [`keep_off`]).
    pub(super) fn fight(&mut self, game: &dyn Observe) -> Option<(f64, u8, f64, f64)> {
        let player = game.player();
        let (seen, table) = (game.seen(), game.table());
        let compiled = &game.level().compiled;
        let looker = Body { pos: player.pos, z: player.z, height: 56.0, radius: 16.0, index: usize::MAX };
        let mut best: Option<(f64, usize)> = None;
        self.in_sight = 0;
        self.unsure = false;
        self.target = None;
        for (i, a) in seen.iter().enumerate() {
            let def = &table.actors[a.kind];
            if a.removed
                || a.health <= 0
                || !(def.has(ActorFlag::CountKill) || def.name == "lost_soul")
                || def.category != Category::Monster && !def.has(ActorFlag::CountKill)
            {
                continue;
            }
            let d = a.pos.distance(player.pos);
            if d > FIGHT_RANGE || (best.is_some_and(|(bd, _)| bd <= d) && self.in_sight >= CROWD) {
                continue;
            }
            let target = Body { pos: a.pos, z: a.z, height: def.height, radius: def.radius, index: i };
            if sight::sight(compiled, &mut self.sight, &looker, &target) {
                self.in_sight += 1;
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, i));
                }
            }
        }
        let Some((d, i)) = best else {
            self.barrel_near = false;
            return None;
        };
        let target = seen[i].pos;
        let to = target - player.pos;
        // Barrels close by in a fight: any shot, the bot's or an enemy's,
        // can set one off, so fall back away from them; one on the line of
        // fire would hurt the bot more than the shot hurts the enemy, so
        // hold fire.
        let mut in_the_way = false;
        self.barrel_near = false;
        for b in seen.iter() {
            if b.removed || b.health <= 0 || table.actors[b.kind].name != "barrel" {
                continue;
            }
            let p = b.pos - player.pos;
            self.barrel_near |= p.length() < BARREL_BLAST;
            in_the_way |= p.length() < BARREL_CLEARANCE
                && p.length() < d
                && p.dot(to) > 0.0
                && plan::nearest_on(b.pos, player.pos, target).distance(b.pos) < 32.0;
        }
        if in_the_way {
            return None;
        }
        // Nothing else that stops a rocket (a monster stepping in, a barrel)
        // near its flight while its blast would still reach the bot.
        let crowded = seen.iter().enumerate().any(|(j, b)| {
            let def = &table.actors[b.kind];
            let p = b.pos - player.pos;
            j != i
                && !b.removed
                && b.health > 0
                && b.shootable
                && p.length() < ROCKET_SAFE + 64.0
                && p.dot(to) > 0.0
                && plan::nearest_on(b.pos, player.pos, target).distance(b.pos) < def.radius + 16.0
        });
        let fire = if d > ROCKET_SAFE && !crowded && rocket_clear(&compiled.map, player.pos, player.z, target) {
            Fire::Any
        } else {
            Fire::NoBlast
        };
        let weapon = weapon_for(game, fire);
        // With only a fist (or chainsaw), an enemy out of its reach is no
        // fight: swinging at it, or falling back from it, only gives it
        // time to shoot; go on (for ammo, say) instead.
        let def = &table.actors[seen[i].kind];
        if weapon == 1 && d > MELEE_REACH + def.radius {
            return None;
        }
        let (radius, keep) = (def.radius, keep_off(def));
        let body = Body { pos: target, z: seen[i].z, height: def.height, radius, index: i };
        let (at, sure) = self.lead(game, body, weapon);
        self.unsure = !sure;
        self.target = Some(Aim { at, radius, thing: i, missile: matches!(weapon, 5 | 7) });
        let to = at - player.pos;
        Some((to.y.atan2(to.x).to_degrees(), weapon, d, keep))
    }

    /// Is a live barrel close in front, near a shot fired facing `angle`
    /// (degrees), before the enemy or beside it: a shot's spread (the
    /// shotgun's, the chaingun's) or a pellet that misses would set it off
    /// in the bot's face, and the barrels beside it with it (E1M1's row of
    /// them by the shotgun guys).
    pub(super) fn barrel_ahead(&self, game: &dyn Observe, angle: f64) -> bool {
        let player = game.player();
        let table = game.table();
        let dir = DVec2::from_angle(angle.to_radians());
        game.seen().iter().any(|b| {
            let p = b.pos - player.pos;
            !b.removed
                && b.health > 0
                && table.actors[b.kind].name == "barrel"
                && p.length() < BARREL_CLEARANCE
                && p.dot(dir) > 0.0
                && (p - dir * p.dot(dir)).length() < 32.0
        })
    }
}

impl Autopilot {
    /// A barrel shot dead goes off some ticks later (its death states end
    /// in `A_Explode`: 128 damage at its centre, less one a unit out to
    /// 128): within reach of it, run straight away, whatever the fight
    /// wanted (E1M3: a barrel beside an imp, set off by the imp's own
    /// fireball, took the bot from 67 health and blue armour in one tick).
    /// True when the body is running.
    pub(super) fn flee_blast(&self, game: &dyn Observe, input: &mut TickInput) -> bool {
        let player = game.player();
        let (seen, table) = (game.seen(), game.table());
        let mut push = DVec2::ZERO;
        for b in seen.iter() {
            if b.removed || b.health > 0 || table.actors[b.kind].name != "barrel" {
                continue;
            }
            let away = player.pos - b.pos;
            if away.length() < BARREL_BLAST {
                push += away.normalize_or(DVec2::X) * (BARREL_BLAST - away.length());
            }
        }
        if push == DVec2::ZERO {
            return false;
        }
        // Of the eight ways the keys move the body, the one most away
        // from the blast where the body keeps its footing; else straight
        // away, off a ledge if need be (a drop is survived, the blast may
        // not be).
        let facing = (player.angle + f64::from(input.turn)).to_radians();
        let (ahead, right) = (DVec2::from_angle(facing), DVec2::new(facing.sin(), -facing.cos()));
        let away = push.normalize();
        let mut ways: Vec<(f64, i8, i8)> = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]
            .into_iter()
            .map(|(f, s): (i8, i8)| ((ahead * f64::from(f) + right * f64::from(s)).normalize().dot(away), f, s))
            .filter(|w| w.0 > 0.3)
            .collect();
        ways.sort_by(|a, b| b.0.total_cmp(&a.0));
        let footed = ways.iter().find(|&&(_, forward, strafe)| {
            let mut try_it = TickInput { forward, strafe, ..*input };
            self.keep_footing(game, &mut try_it);
            (try_it.forward, try_it.strafe) == (forward, strafe)
        });
        let Some(&(_, forward, strafe)) = footed.or(ways.first()) else { return false };
        let run = TickInput { forward, strafe, run: true, ..*input };
        *input = run;
        true
    }
}

/// Would a trigger held this tick be read by the weapon's `A_ReFire`,
/// with a weapon whose shot is accurate only when not fired again with
/// the trigger held (the pistol's and chaingun's, Doom's `refire`)? Then
/// letting go for this one tick keeps every shot true: a held pistol
/// spreads its bullets over 11 degrees (`P_GunShot`'s `<<18`), enough to
/// miss a zombie at 300 units half the time, and tapping costs one tick a
/// shot (the ready state's).
pub(super) fn tap_now(game: &dyn Observe) -> bool {
    let player = game.player();
    let table = game.table();
    let name =
        |s: crate::actors::StateId| table.state(s).action.as_ref().map(|a| crate::actors::actions::spec(a.action).name);
    let Some(weapon) = player.ready_weapon else { return false };
    let def = &table.actors[weapon];
    // The first few states of its fire sequence say which kind it is.
    let mut state = def.label("Fire");
    let mut accurate_first = false;
    for _ in 0..8 {
        let Some(s) = state else { break };
        accurate_first |= matches!(name(s), Some("A_FirePistol" | "A_FireCGun"));
        state = table.state(s).next;
    }
    let psp = &player.psprites[0];
    if !accurate_first || psp.tics != 1 {
        return false;
    }
    // The states entered this tick: the next, and those after it that
    // last no time.
    let mut state = psp.state.and_then(|s| table.state(s).next);
    for _ in 0..4 {
        let Some(s) = state else { break };
        if name(s) == Some("A_ReFire") {
            return true;
        }
        if table.state(s).tics != 0 {
            break;
        }
        state = table.state(s).next;
    }
    false
}

/// How near a body fighting `def` lets it come before backing off: a
/// monster with no missile attack (a demon, a spectre) hurts only in
/// reach of its bite (Doom's `P_CheckMeleeRange`: 44 units plus the
/// body's radius), and walks at 5 units a tick against a back-pedalling
/// body's 16, so keeping well off it wins; others, a little.
fn keep_off(def: &crate::actors::ActorDef) -> f64 {
    if def.label("Missile").is_none() {
        256.0
    } else {
        192.0
    }
}

/// Closer than this a rocket's blast reaches the shooter.
const ROCKET_SAFE: f64 = 300.0;

/// Would a rocket fired from `from` (feet at `z`) at `to` fly clear of
/// walls, ledges and low ceilings until it is past its blast's reach? A
/// rocket that bursts on a corner or a step in front of the face is the
/// bot's own death: the sight line to the target is not enough, the
/// rocket has a body (radius 11) and flies at the height it is fired from.
fn rocket_clear(map: &crate::map::Map, from: DVec2, z: f64, to: DVec2) -> bool {
    const SIDE: f64 = 13.0;
    let along = (to - from).normalize_or_zero();
    let end = from + along * (to.distance(from) - 24.0).min(ROCKET_SAFE + 64.0);
    let side = DVec2::new(-along.y, along.x) * SIDE;
    let (low, high) = (z + 32.0 - 8.0, z + 32.0 + 16.0);
    map.lines.iter().all(|l| {
        if let Some(back) = &l.back {
            let (f, b) = (&map.sectors[l.front.sector], &map.sectors[back.sector]);
            if f.floor.max(b.floor) < low && f.ceiling.min(b.ceiling) > high {
                return true;
            }
        }
        let (a, b) = map.line_points(l);
        [DVec2::ZERO, side, -side].iter().all(|&o| crate::geom::crossing(from + o, end + o, a, b).is_none())
    })
}

/// Which weapons a shot may use.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Fire {
    Any,
    /// No rocket launcher or BFG: a blast would reach the shooter.
    NoBlast,
    /// Hitscan only (a shot line wants bullets).
    Bullets,
}

/// The weapon slot to fight with: the best owned with ammo that `fire`
/// allows.
pub(super) fn weapon_for(game: &dyn Observe, fire: Fire) -> u8 {
    let player = game.player();
    let table = game.table();
    let mut best = (0, 1u8);
    for &w in &player.weapons {
        let Some(def) = table.actors[w].weapon.as_ref() else { continue };
        let has_ammo = def.ammo.is_none_or(|k| player.ammo[k.index()] >= def.ammo_use.max(1));
        if !has_ammo {
            continue;
        }
        let score = match def.slot {
            1 => 1,
            2 => 3,
            3 => 6,
            4 => 5,
            5 if fire == Fire::Any => 7,
            6 if fire != Fire::Bullets => 8,
            7 if fire == Fire::Any => 4,
            _ => 0,
        };
        if score > best.0 {
            best = (score, def.slot);
        }
    }
    best.1
}

impl Autopilot {
    /// With `SIGHTLINE_FIGHT_TRACE` set: each tick the body is hurt, its
    /// health, where it is, and who made a sound (an attack's) this tick.
    pub(super) fn trace_hurt(&self, game: &dyn Observe, before: i32, mode: &str) {
        if std::env::var_os("SIGHTLINE_FIGHT_TRACE").is_none() {
            return;
        }
        let player = game.player();
        if player.health >= before {
            return;
        }
        let (seen, table) = (game.seen(), game.table());
        let mut who = Vec::new();
        for e in game.events() {
            if let crate::play::events::Event::Sound {
                sound,
                origin: crate::play::events::Origin::Actor { index, .. },
            } = e
            {
                if let Some(a) = seen.get(*index as usize) {
                    who.push(format!("{sound}:{}@{:.0}", table.actors[a.kind].name, a.pos.distance(player.pos)));
                }
            }
        }
        eprintln!(
            "hurt tick {} hp {}->{} armor {} at ({:.0},{:.0}) {mode} sight {} [{}]",
            game.ticks(),
            before,
            player.health,
            player.armor,
            player.pos.x,
            player.pos.y,
            self.in_sight,
            who.join(" ")
        );
    }
}
