//! Doom's numbers paired with a table's: each mobjinfo entry with the
//! actor `doom_info.ron` names for it, each weaponinfo entry with its
//! weapon actor, and each of Doom's frames with the table states that are
//! it.
//!
//! The frames are paired by walking both state machines together from
//! their roots: a mobjinfo's eight states against its actor's labels
//! (`Spawn`, `See`, ...), a weapon's five against `Select`, `Deselect`,
//! `Ready`, `Fire`, `Flash`, and the few states Doom's code enters by
//! number ([`CODE_ROOTS`]). Each step checks that the pair agrees (sprite,
//! frame, brightness, tics, action) and follows `next` on both sides. A
//! computed pairing, not a stored list, so it survives edits to
//! `actors.ron` that keep Doom's behaviour, and it reports any that do not.
//!
//! One Doom frame may be several table states: Doom's weapons share
//! S_LIGHTDONE and its dead decorations reuse the monsters' last death
//! frames, where the table writes a copy into each actor. A patch to such
//! a frame changes every copy, which keeps them alike, and a `next` or a
//! label that names the frame points at the first. A frame no actor
//! reaches (Doom has a few unused ones) has no state until a patch names
//! it; `apply.rs` then adds it as Doom has it.

use std::collections::HashMap;

use super::doom::{doom_info, DoomState, NUM_STATES, NUM_THINGS, NUM_WEAPONS, THING_LABELS, WEAPON_LABELS};
use crate::actors::{actions, ActorTable, State, StateId};

/// States Doom's code enters by number rather than through mobjinfo or
/// weaponinfo, and where the table keeps each: (frame, actor, label,
/// offset).
pub const CODE_ROOTS: [(&str, &str, &str, u32); 5] = [
    // A_FirePistol, A_FireShotgun, ...: P_SetMobjState(mo, S_PLAY_ATK2),
    // the body's firing frame; the table's player has it as `Melee`.
    ("S_PLAY_ATK2", "player", "Melee", 0),
    // A_VileChase sets S_VILE_HEAL1 when it raises a corpse.
    ("S_VILE_HEAL1", "arch_vile", "Heal", 0),
    // A_FireCGun: flashstate + (the firing state - S_CHAIN1).
    ("S_CHAINFLASH2", "chaingun", "Flash", 1),
    // A_FirePlasma: flashstate + (P_Random() & 1).
    ("S_PLASMAFLASH2", "plasma_gun", "Flash", 1),
    // A_BrainScream spawns a rocket and sets it to S_BRAINEXPLODE1; the
    // table gives those explosions their own actor.
    ("S_BRAINEXPLODE1", "brain_explosion", "Spawn", 0),
];

/// The pairing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DoomMap {
    /// Per Doom frame, the table's states that are it; the first is the
    /// one a label or a `next` is set to. S_NULL (0) has none: it means
    /// "no state", a removed thing.
    pub frames: Vec<Vec<StateId>>,
    /// Per mobjinfo index ("Thing N" is N - 1), the actor.
    pub things: Vec<Option<usize>>,
    /// Per weaponinfo index, the actor.
    pub weapons: Vec<Option<usize>>,
    /// Frames the table had no state for, added since because a patch
    /// named them.
    pub added: Vec<usize>,
    /// Frames that last for ever (-1 tics) whose `next` the table does not
    /// have as Doom does, since it is never reached: S_KEENSTND.
    pub parked: Vec<usize>,
    /// Where the table and Doom disagree, in words (none for the shipped
    /// table: the tests hold it to that).
    pub problems: Vec<String>,
    /// Per table state (as the table was paired), the first actor whose
    /// labels reach it: its home, which picks among a frame's copies.
    pub home: Vec<Option<usize>>,
}

impl DoomMap {
    /// The state a label or `next` naming Doom's `frame` points at.
    pub fn state(&self, frame: usize) -> Option<StateId> {
        self.frames.get(frame).and_then(|f| f.first().copied())
    }

    /// Frames (S_NULL aside) with no state in the table.
    pub fn unmapped(&self) -> Vec<usize> {
        (1..self.frames.len()).filter(|&f| self.frames[f].is_empty()).collect()
    }

    /// The copy of `frame` whose home is `home` (the demon's S_SARG_RUN1
    /// for the demon, the spectre's for the spectre), else the first.
    /// Copies are alike, so either would run the same; keeping each actor
    /// on its own keeps the table as it was written.
    pub fn state_near(&self, frame: usize, home: Option<usize>) -> Option<StateId> {
        let copies = self.frames.get(frame)?;
        let own = copies.iter().find(|id| home.is_some() && self.home.get(id.0 as usize).copied().flatten() == home);
        own.or(copies.first()).copied()
    }

    /// The home of a table state.
    pub fn home_of(&self, id: StateId) -> Option<usize> {
        self.home.get(id.0 as usize).copied().flatten()
    }

    /// The Doom frame a table state is, if any.
    pub fn frame_of(&self, id: StateId) -> Option<usize> {
        self.frames.iter().position(|f| f.contains(&id))
    }
}

/// Pairs `table` with Doom's numbering.
pub fn map(table: &ActorTable) -> DoomMap {
    let info = doom_info();
    let mut m = DoomMap {
        frames: vec![Vec::new(); NUM_STATES],
        things: vec![None; NUM_THINGS],
        weapons: vec![None; NUM_WEAPONS],
        ..DoomMap::default()
    };
    // (actor, frame, state), in mobjinfo's order, then weaponinfo's, then
    // the code's.
    let mut roots: Vec<(usize, usize, StateId)> = Vec::new();
    let mut root = |m: &mut DoomMap, actor: usize, label: &str, offset: u32, frame: usize, what: &str| match table
        .actors[actor]
        .label(label)
    {
        Some(s) => roots.push((actor, frame, StateId(s.0 + offset))),
        None => m.problems.push(format!("{what}: {} has no {label} label", table.actors[actor].name)),
    };
    for (k, t) in info.things.iter().enumerate() {
        m.things[k] = table.index(&t.actor);
        let Some(a) = m.things[k] else {
            m.problems.push(format!("Thing {} ({}): no actor {}", k + 1, t.mt, t.actor));
            continue;
        };
        for (i, &frame) in t.states.iter().enumerate() {
            if frame != 0 {
                root(&mut m, a, THING_LABELS[i], 0, frame, &t.mt);
            }
        }
    }
    for (k, w) in info.weapons.iter().enumerate() {
        m.weapons[k] = table.index(&w.actor).filter(|&a| table.actors[a].weapon.is_some());
        let Some(a) = m.weapons[k] else {
            m.problems.push(format!("Weapon {k} ({}): no weapon actor {}", w.name, w.actor));
            continue;
        };
        for (i, &frame) in w.states.iter().enumerate() {
            if frame != 0 {
                root(&mut m, a, WEAPON_LABELS[i], 0, frame, &w.name);
            }
        }
    }
    for (name, actor, label, offset) in CODE_ROOTS {
        match (info.state(name), table.index(actor)) {
            (Some(frame), Some(a)) => root(&mut m, a, label, offset, frame, name),
            _ => m.problems.push(format!("{name}: no actor {actor}")),
        }
    }
    walk(table, &mut m, &roots);
    m.home = vec![None; table.states.len()];
    for (a, actor) in table.actors.iter().enumerate() {
        for id in table.states_of(actor) {
            m.home[id.0 as usize].get_or_insert(a);
        }
    }
    // Flash+1 is no label's: its home is its actor's all the same.
    for (_, actor, label, offset) in CODE_ROOTS {
        let Some(a) = table.index(actor) else { continue };
        let mut at = table.actors[a].label(label).map(|s| StateId(s.0 + offset));
        while let Some(id) = at.filter(|id| m.home.get(id.0 as usize).is_some_and(Option::is_none)) {
            m.home[id.0 as usize] = Some(a);
            at = table.state(id).next;
        }
    }
    m
}

/// Follows each actor's roots' `next` chains on both sides, pairing as it
/// goes. An actor whose machine departs from Doom's anywhere (a modder's
/// replacement) keeps none of its pairs: a patch to those frames means
/// Doom's states, which `apply.rs` then adds, not a look-alike's.
fn walk(table: &ActorTable, m: &mut DoomMap, roots: &[(usize, usize, StateId)]) {
    let info = doom_info();
    let mut owner: HashMap<StateId, usize> = HashMap::new();
    let mut actors: Vec<usize> = Vec::new();
    for &(a, _, _) in roots {
        if !actors.contains(&a) {
            actors.push(a);
        }
    }
    for actor in actors {
        let mut todo: Vec<(usize, StateId)> =
            roots.iter().rev().filter(|r| r.0 == actor).map(|&(_, f, id)| (f, id)).collect();
        let mut paired: Vec<(usize, StateId)> = Vec::new();
        let mut problems: Vec<String> = Vec::new();
        while let Some((frame, id)) = todo.pop() {
            let doom = &info.states[frame];
            let Some(state) = table.states.get(id.0 as usize) else {
                problems.push(format!("{}: state {} is past the table's end", doom.name, id.0));
                continue;
            };
            match owner.get(&id) {
                Some(&f) if f == frame => continue,
                Some(&f) => {
                    problems.push(format!("state {} is both {} and {}", id.0, info.states[f].name, doom.name));
                    continue;
                }
                None => {}
            }
            if let Some(why) = disagreement(table, state, doom) {
                problems.push(format!("{} (frame {frame}) against state {}: {why}", doom.name, id.0));
                continue;
            }
            owner.insert(id, frame);
            paired.push((frame, id));
            match (doom.next, state.next) {
                (0, None) => {}
                (next, Some(to)) if next != 0 => todo.push((next, to)),
                // A state that lasts for ever never reaches its next:
                // S_KEENSTND names itself, the table stops. Equal until a
                // patch gives it a duration, when `apply/` sets Doom's next.
                _ if doom.tics == -1 => m.parked.push(frame),
                (next, to) => problems.push(format!(
                    "{}: Doom goes on to {}, the table to {}",
                    doom.name,
                    info.states[next].name,
                    to.map_or("nothing (stop)".to_string(), |t| format!("state {}", t.0))
                )),
            }
        }
        if problems.is_empty() {
            paired.into_iter().for_each(|(f, id)| m.frames[f].push(id));
        } else {
            let name = &table.actors[actor].name;
            m.problems.extend(problems.into_iter().map(|p| format!("{name}: {p}")));
            for (_, id) in &paired {
                owner.remove(id);
            }
            m.parked.retain(|f| !paired.iter().any(|p| p.0 == *f));
        }
    }
}

/// How a table state differs from Doom's, if it does.
fn disagreement(table: &ActorTable, state: &State, doom: &DoomState) -> Option<String> {
    let info = doom_info();
    let sprite = table.sprites.get(usize::from(state.sprite)).map_or("?", String::as_str);
    let doom_sprite = &info.sprites[doom.sprite];
    let bright = doom.frame & super::doom::FULL_BRIGHT != 0;
    let frame = doom.frame & !super::doom::FULL_BRIGHT;
    let action = state.action.as_ref().map(|c| actions::spec(c.action).name);
    let same_action = match (action, &doom.action) {
        (None, None) => true,
        (Some(a), Some(b)) => a.eq_ignore_ascii_case(b),
        _ => false,
    };
    if sprite != doom_sprite || i64::from(state.frame) != frame || state.bright != bright {
        return Some(format!("sprite {sprite} {} against {doom_sprite} {frame}", state.frame));
    }
    if state.tics != doom.tics {
        return Some(format!("{} tics against {}", state.tics, doom.tics));
    }
    if !same_action {
        return Some(format!("action {action:?} against {:?}", doom.action));
    }
    None
}
