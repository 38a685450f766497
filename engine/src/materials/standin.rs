//! What an actor's frame looks like when no art has it: the stand-in
//! ([`crate::texture::procedural::standins`]) made from the actor table
//! (its build from the actor's category and flags, its size from its
//! radius and height, its pose from the state label its frame is in), or
//! a placeholder. The materials ask here when a sprite frame resolves to
//! nothing.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::actors::{ActorDef, ActorFlag, ActorTable, Category, KeyForm, StateId};
use crate::texture::procedural::standins::{self, Build, Pickup, StandIn};
use crate::texture::procedural::Pose;
use crate::texture::Texture;

/// What a sprite frame that no art has is drawn as.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MissingArt {
    /// A stand-in figure drawn for the actor (no WAD: our own look).
    #[default]
    StandIn,
    /// A placeholder, with a warning naming the actor and the frame (a
    /// WAD was given, and its look has a hole).
    Placeholder,
    /// Nothing is drawn, nor looked up: a command that draws nothing.
    Skip,
}

/// The stand-in of `actor`'s frame `frame` of sprite `sprite`, from each
/// of Doom's eight directions (all alike for a frame seen the same from
/// every side), drawn once per process.
pub fn views(table: &ActorTable, actor: &ActorDef, sprite: u16, frame: u8) -> Vec<Arc<Texture>> {
    let build = build_of(actor);
    let (pose, bright) = pose_of(table, actor, sprite, frame, build);
    let turns = matches!(build, Build::Walker | Build::Floater | Build::Crawler) && pose.fall == 0.0;
    let name = &table.sprites[usize::from(sprite)];
    let spec = StandIn {
        build,
        radius: actor.radius as f32,
        height: actor.height as f32,
        scheme: standins::scheme(name),
        pose,
        bright,
    };
    let count = if turns { 8 } else { 1 };
    (1..=count).map(|view| memo(format!("{name}{frame}/{view}/{spec:?}"), || standins::draw(&spec, view))).collect()
}

/// A placeholder for `actor`: its size, unmistakably not art.
pub fn placeholder(actor: Option<&ActorDef>) -> Arc<Texture> {
    let (r, h) = actor.map_or((16.0, 32.0), |a| (a.radius as f32, a.height as f32));
    memo(format!("placeholder/{r}/{h}"), || standins::placeholder(r, h))
}

/// Drawing a figure takes milliseconds; a level opened again (a restart,
/// a test's second map) asks for the same ones.
fn memo(key: String, draw: impl FnOnce() -> Texture) -> Arc<Texture> {
    static MADE: OnceLock<Mutex<HashMap<String, Arc<Texture>>>> = OnceLock::new();
    let made = MADE.get_or_init(Default::default);
    if let Some(t) = made.lock().ok().and_then(|m| m.get(&key).cloned()) {
        return t;
    }
    let t = Arc::new(draw());
    if let Ok(mut m) = made.lock() {
        m.insert(key, t.clone());
    }
    t
}

/// The build an actor is drawn with, from its category and flags.
fn build_of(actor: &ActorDef) -> Build {
    match actor.category {
        Category::Player | Category::Monster => {
            if actor.has(ActorFlag::Float) {
                Build::Floater
            } else if actor.radius >= actor.height * 0.9 {
                Build::Crawler
            } else {
                Build::Walker
            }
        }
        Category::Weapon => Build::Pickup(Pickup::Gun),
        Category::Ammo => Build::Pickup(Pickup::Ammo),
        Category::Health => Build::Pickup(Pickup::Medical),
        Category::Armor => Build::Pickup(Pickup::Armour),
        Category::Powerup => Build::Pickup(Pickup::Orb),
        Category::Key(_, KeyForm::Card) | Category::Key(_, KeyForm::Skull) => Build::Pickup(Pickup::Key),
        Category::Projectile | Category::Effect => Build::Missile,
        Category::Corpse => Build::Remains,
        _ if actor.has(ActorFlag::SpawnCeiling) => Build::Hanging,
        _ if !actor.has(ActorFlag::Solid) && actor.height <= 16.0 => Build::Remains,
        _ => Build::Prop,
    }
}

/// The labels a frame takes its pose from, first match first: a frame in
/// both Spawn and See (Doom's monsters stand in their first walking
/// frames) walks.
const ORDER: [&str; 8] = ["See", "Missile", "Melee", "Pain", "Death", "XDeath", "Raise", "Spawn"];

/// The pose of sprite `sprite`'s frame `frame` in `actor`'s states, and
/// whether it is bright: walking strides by its place in the walk, an
/// attack aims (and flashes when bright), pain flinches, a death falls
/// by its place in the death.
fn pose_of(table: &ActorTable, actor: &ActorDef, sprite: u16, frame: u8, build: Build) -> (Pose, bool) {
    let labels = ORDER.iter().filter_map(|l| actor.label(l).map(|s| (*l, s)));
    let others = actor.labels.iter().map(|(l, s)| (l.as_str(), *s));
    for (label, start) in labels.chain(others) {
        let run = sequence(table, actor, start);
        let Some(k) = run.iter().position(|&id| {
            let s = table.state(id);
            s.sprite == sprite && s.frame == frame
        }) else {
            continue;
        };
        let state = table.state(run[k]);
        // Frames of the run by letter, so AABBCCDD strides as ABCD.
        let mut letters: Vec<u8> = Vec::new();
        for &id in &run {
            let f = table.state(id).frame;
            if table.state(id).sprite == sprite && !letters.contains(&f) {
                letters.push(f);
            }
        }
        let at = letters.iter().position(|&f| f == frame).unwrap_or(0);
        let share = (at + 1) as f32 / letters.len().max(1) as f32;
        let pose = match label {
            "See" => Pose { stride: [1.0, 0.25, -1.0, -0.25][at % 4], ..Pose::default() },
            "Missile" | "Melee" => Pose {
                aim: if at == 0 && letters.len() > 1 { 0.5 } else { 1.0 },
                open: share,
                flash: state.bright,
                ..Pose::default()
            },
            "Pain" => Pose { lean: -0.25, open: 1.0, ..Pose::default() },
            "Death" | "XDeath" if matches!(build, Build::Missile) => Pose { fall: share, ..Pose::default() },
            "Death" | "XDeath" => {
                Pose { fall: share, blood: if at + 1 == letters.len() { 1.0 } else { 0.0 }, ..Pose::default() }
            }
            "Raise" => Pose { fall: 1.0 - share, ..Pose::default() },
            // Items and props glint and flicker through their frames.
            _ => Pose { open: at as f32 / letters.len().max(1) as f32, ..Pose::default() },
        };
        return (pose, state.bright);
    }
    (Pose::default(), false)
}

/// The states from `start` until the sequence loops back, stops or runs
/// into another label's states.
fn sequence(table: &ActorTable, actor: &ActorDef, start: StateId) -> Vec<StateId> {
    let starts: Vec<StateId> = actor.labels.iter().map(|&(_, s)| s).filter(|&s| s != start).collect();
    let mut run = vec![start];
    let mut at = table.state(start).next;
    while let Some(id) = at {
        if run.contains(&id) || starts.contains(&id) || run.len() >= 64 {
            break;
        }
        run.push(id);
        at = table.state(id).next;
    }
    run
}

#[cfg(test)]
mod tests {
    use super::*;

    fn actor(name: &str) -> &'static ActorDef {
        ActorTable::active().get(name).unwrap_or_else(|| panic!("{name}"))
    }

    #[test]
    fn builds_follow_the_roster() {
        let b = |n| build_of(actor(n));
        assert_eq!(b("imp"), Build::Walker);
        assert_eq!(b("cacodemon"), Build::Floater);
        assert_eq!(b("lost_soul"), Build::Floater);
        assert_eq!(b("spiderdemon"), Build::Crawler);
        assert_eq!(b("arachnotron"), Build::Crawler);
        assert_eq!(b("shotgun"), Build::Pickup(Pickup::Gun));
        assert_eq!(b("box_of_bullets"), Build::Pickup(Pickup::Ammo));
        assert_eq!(b("imp_fireball"), Build::Missile);
        assert_eq!(b("tall_red_column"), Build::Prop);
        assert_eq!(b("hanging_leg"), Build::Hanging);
    }

    #[test]
    fn poses_come_from_the_labels() {
        let t = ActorTable::active();
        let imp = actor("imp");
        let troo = t.sprites.iter().position(|s| s == "TROO").unwrap() as u16;
        let pose = |f: u8| pose_of(t, imp, troo, f - b'A', build_of(imp)).0;
        // A and C stride opposite ways; E-G throw; the last death frame lies in blood.
        assert_eq!((pose(b'A').stride, pose(b'C').stride), (1.0, -1.0));
        assert!(pose(b'G').aim > 0.0, "{:?}", pose(b'G'));
        assert!(pose(b'H').lean < 0.0, "{:?}", pose(b'H'));
        assert_eq!(pose(b'M').fall, 1.0);
        assert!(pose(b'J').fall > 0.0 && pose(b'J').fall < 1.0);
        // Eight views walking, one lying dead.
        assert_eq!(views(t, imp, troo, 0).len(), 8);
        assert_eq!(views(t, imp, troo, (b'M' - b'A') as u8).len(), 1);
    }
}
