//! Turns actor files into one checked [`ActorTable`]: later files add
//! actors or replace those of the same name; `based_on` copies a resolved
//! parent before the child's fields apply; every name (label, sprite,
//! sound, action, actor) becomes an index, and what cannot run is refused
//! with the file, the actor and the state named:
//!
//! - a `goto` to a label the actor does not have, a `loop` with nothing to
//!   loop to, states that end without `loop`, `stop`, `wait` or `goto`;
//! - an unknown sprite, sound, action or actor (with a "did you mean");
//! - an action given too many or too few arguments, or one of the wrong type;
//! - states of 0 tics that lead back to themselves (the simulation would
//!   spin for ever within one tick);
//! - a weapon without its `Ready`, `Select`, `Deselect` and `Fire` labels,
//!   `replaces` or `based_on` chains that loop, duplicate names or numbers
//!   within a file, sizes that are not finite.

// Errors are made once, when a table is refused; their size does not matter.
#![allow(clippy::result_large_err)]

use std::collections::HashMap;

use super::actions::{self, ArgKind, Default};
use super::source::{ActorSource, SoundsSource, TableSource};
use super::states::{self, EntryKind, RawArg};
use super::{nearest, ActionCall, ActorDef, ActorFlags, ActorTable, Arg, Category, Give, Sounds, State, StateId};

/// Why an actor table could not be loaded.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ActorTableError {
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    #[error("{path}:{line}:{col}: {message}")]
    Syntax { path: String, line: usize, col: usize, message: String },
    #[error("{path}: sprite {sprite:?}: a sprite name is four letters or digits")]
    Sprite { path: String, sprite: String },
    #[error("{path}: actor {actor}: {message}")]
    Actor { path: String, actor: String, message: String },
    #[error("{path}: actor {actor}, state {label} (states line {line}: `{text}`): {message}")]
    State { path: String, actor: String, label: String, line: usize, text: String, message: String },
    #[error("an actor table is already in use: install a user's table before anything reads the active one")]
    AlreadyActive,
}

/// Doom's mobjinfo defaults for a property left out (DECORATE's too).
const DEFAULT_HEALTH: i32 = 1000;
const DEFAULT_REACTION_TIME: i32 = 8;
const DEFAULT_RADIUS: f64 = 20.0;
const DEFAULT_HEIGHT: f64 = 16.0;
const DEFAULT_MASS: i32 = 100;

/// An actor's source and the file it came from.
struct Written {
    source: ActorSource,
    path: String,
}

pub fn load(files: &[(&str, &str)]) -> Result<ActorTable, ActorTableError> {
    let parsed = files
        .iter()
        .map(|&(text, path)| Ok((parse_source(text, path)?, path.to_string())))
        .collect::<Result<Vec<_>, ActorTableError>>()?;
    layer(None, parsed)
}

/// One actor file's RON, read but not resolved.
pub fn parse_source(text: &str, path: &str) -> Result<TableSource, ActorTableError> {
    // Optional fields are written bare (`drop: "clip"`), as in maps.
    let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    options.from_str(text).map_err(|e| ActorTableError::Syntax {
        path: path.to_string(),
        line: e.span.start.line,
        col: e.span.start.col,
        message: e.code.to_string(),
    })
}

/// `files` layered on a table already resolved: its actors, states and
/// sprites keep their indices, and the files' actors may be `based_on` or
/// replace them (DECORATE's lumps and ZDoom's base classes go in this way).
pub fn extend(base: &ActorTable, files: Vec<(TableSource, String)>) -> Result<ActorTable, ActorTableError> {
    layer(Some(base), files)
}

/// Where an actor of the base table came from, in errors.
const BASE_PATH: &str = "(the table extended)";

fn layer(base: Option<&ActorTable>, files: Vec<(TableSource, String)>) -> Result<ActorTable, ActorTableError> {
    let mut sprites: Vec<String> = base.map_or_else(Vec::new, |b| b.sprites.clone());
    let mut written: Vec<Written> = Vec::new();
    let mut by_name: HashMap<String, usize> = HashMap::new();
    for def in base.iter().flat_map(|b| &b.actors) {
        by_name.insert(def.name.clone(), written.len());
        let source = ActorSource { name: def.name.clone(), ..ActorSource::default() };
        written.push(Written { source, path: BASE_PATH.to_string() });
    }
    let base_count = written.len();
    let mut overridden = vec![false; base_count];
    for (table, path) in files {
        let path = path.as_str();
        for sprite in table.sprites {
            if sprite.len() != 4 || !sprite.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                return Err(ActorTableError::Sprite { path: path.to_string(), sprite });
            }
            let sprite = sprite.to_ascii_uppercase();
            if !sprites.contains(&sprite) {
                sprites.push(sprite);
            }
        }
        let mut in_file: HashMap<String, ()> = HashMap::new();
        let mut numbers: HashMap<u16, String> = HashMap::new();
        for source in table.actors {
            let fail = |message: String| ActorTableError::Actor {
                path: path.to_string(),
                actor: source.name.clone(),
                message,
            };
            let plain = |c: char| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_';
            if source.name.is_empty() || !source.name.chars().all(plain) {
                return Err(fail("a name is lower-case letters, digits and _".into()));
            }
            if in_file.insert(source.name.clone(), ()).is_some() {
                return Err(fail("defined twice in this file".into()));
            }
            if let Some(n) = source.doomednum {
                if let Some(other) = numbers.insert(n, source.name.clone()) {
                    return Err(fail(format!("doomednum {n} is also {other}'s")));
                }
            }
            let entry = Written { source, path: path.to_string() };
            match by_name.get(&entry.source.name) {
                Some(&i) => {
                    if i < base_count {
                        overridden[i] = true;
                    }
                    written[i] = entry;
                }
                None => {
                    by_name.insert(entry.source.name.clone(), written.len());
                    written.push(entry);
                }
            }
        }
    }
    let sounds: Vec<String> = match base {
        Some(b) => b.sounds.clone(),
        None => super::sounds::doom().iter().map(|s| s.name.clone()).collect(),
    };
    let mut resolver = Resolver {
        written: &written,
        by_name: &by_name,
        sprites: &sprites,
        sounds: &sounds,
        merged: vec![None; written.len()],
        actors: vec![None; written.len()],
        states: base.map_or_else(Vec::new, |b| b.states.clone()),
    };
    // The base's actors stand resolved, unless a file replaced them.
    for (i, def) in base.iter().flat_map(|b| b.actors.iter().map(move |d| (b, d))).enumerate() {
        if !overridden[i] {
            let (table, def) = def;
            resolver.merged[i] = Some(source_of(table, i, def));
            resolver.actors[i] = Some(def.clone());
        }
    }
    for i in 0..written.len() {
        resolver.resolve(i, &mut Vec::new())?;
    }
    let Resolver { actors, states, merged, .. } = resolver;
    let mut actors: Vec<ActorDef> = actors.into_iter().map(|a| a.expect("every actor was resolved")).collect();

    // Replacement: `replaces` marks the replaced actor; chains must end.
    for (i, w) in written.iter().enumerate() {
        let replaces = merged[i].as_ref().and_then(|m: &ActorSource| m.replaces.clone());
        if let Some(target) = replaces {
            let t = lookup(&by_name, &written, &target).map_err(|m| actor_error(w, format!("replaces: {m}")))?;
            if t == i {
                return Err(actor_error(w, "replaces itself".into()));
            }
            actors[t].replaced_by = Some(i);
        }
    }
    for (i, w) in written.iter().enumerate() {
        let (mut at, mut steps) = (i, 0);
        while let Some(next) = actors[at].replaced_by {
            at = next;
            steps += 1;
            if steps > actors.len() {
                return Err(actor_error(w, "its replacements loop back to it".into()));
            }
        }
    }

    let mut by_number = HashMap::new();
    for (i, a) in actors.iter().enumerate() {
        if let Some(n) = a.doomednum {
            // A later file's actor takes over a number (DECORATE's rule).
            by_number.insert(n, i);
        }
    }
    Ok(ActorTable { actors, states, sprites, sounds, by_name, by_number })
}

fn actor_error(w: &Written, message: String) -> ActorTableError {
    ActorTableError::Actor { path: w.path.clone(), actor: w.source.name.clone(), message }
}

fn lookup(by_name: &HashMap<String, usize>, written: &[Written], name: &str) -> Result<usize, String> {
    by_name.get(name).copied().ok_or_else(|| {
        let hint = nearest(name, written.iter().map(|w| w.source.name.as_str()))
            .map(|n| format!(" (did you mean {n}?)"))
            .unwrap_or_default();
        format!("no actor named {name:?}{hint}")
    })
}

fn find_sound(sounds: &[String], name: &str) -> Result<usize, String> {
    sounds.iter().position(|s| s.eq_ignore_ascii_case(name)).ok_or_else(|| {
        let hint = nearest(name, sounds.iter().map(String::as_str))
            .map(|n| format!(" (did you mean {n}?)"))
            .unwrap_or_default();
        format!("no sound named {name:?}{hint}")
    })
}

struct Resolver<'a> {
    written: &'a [Written],
    by_name: &'a HashMap<String, usize>,
    sprites: &'a [String],
    sounds: &'a [String],
    /// Each actor's source with its parents' fields filled in.
    merged: Vec<Option<ActorSource>>,
    actors: Vec<Option<ActorDef>>,
    states: Vec<State>,
}

impl Resolver<'_> {
    fn resolve(&mut self, i: usize, chain: &mut Vec<usize>) -> Result<(), ActorTableError> {
        if self.actors[i].is_some() {
            return Ok(());
        }
        let w = &self.written[i];
        if chain.contains(&i) {
            return Err(actor_error(w, "its based_on chain loops back to it".into()));
        }
        let mut source = w.source.clone();
        let mut labels = Vec::new();
        let mut flags = ActorFlags::default();
        if let Some(parent) = &w.source.based_on {
            let p = lookup(self.by_name, self.written, parent).map_err(|m| actor_error(w, format!("based_on: {m}")))?;
            chain.push(i);
            self.resolve(p, chain)?;
            chain.pop();
            let parent_source = self.merged[p].clone().expect("resolved");
            source = inherit(source, &parent_source);
            let parent_def = self.actors[p].as_ref().expect("resolved");
            labels = parent_def.labels.clone();
            // `goto Super::Label`: the parent's state, even when the child
            // defines a label of the same name (DECORATE's scope).
            let supers: Vec<(String, StateId)> = labels.iter().map(|(l, s)| (format!("{SUPER}{l}"), *s)).collect();
            labels.extend(supers);
            flags = parent_def.flags;
        }
        if let Some(list) = &w.source.flags {
            flags = ActorFlags::of(list);
        }
        for &f in &w.source.add_flags {
            flags.set(f, true);
        }
        for &f in &w.source.remove_flags {
            flags.set(f, false);
        }
        if let Some(text) = &w.source.states {
            self.add_states(i, text, &mut labels)?;
        }
        labels.retain(|(l, _)| !l.starts_with(SUPER));
        let def = self.define(i, &source, flags, labels)?;
        self.merged[i] = Some(source);
        self.actors[i] = Some(def);
        Ok(())
    }

    /// Checks the properties and turns names into indices.
    fn define(
        &self,
        i: usize,
        s: &ActorSource,
        flags: ActorFlags,
        labels: Vec<(String, StateId)>,
    ) -> Result<ActorDef, ActorTableError> {
        let w = &self.written[i];
        let fail = |message: String| actor_error(w, message);
        let size = |what: &str, v: Option<f64>, default: f64| match v.unwrap_or(default) {
            v if v.is_finite() && (0.0..=4096.0).contains(&v) => Ok(v),
            v => Err(fail(format!("{what} {v} is not within 0..=4096"))),
        };
        let radius = size("radius", s.radius, DEFAULT_RADIUS)?;
        let height = size("height", s.height, DEFAULT_HEIGHT)?;
        let speed = size("speed", s.speed, 0.0)?;
        let fast_speed = s.fast_speed.map(|v| size("fast_speed", Some(v), 0.0)).transpose()?;
        let pain_chance = s.pain_chance.unwrap_or(0);
        if !(0..=256).contains(&pain_chance) {
            return Err(fail(format!("pain_chance {pain_chance} is not within 0..=256 (out of 256)")));
        }
        let health = s.health.unwrap_or(DEFAULT_HEALTH);
        if health < 0 {
            return Err(fail(format!("health {health} is negative")));
        }
        let sound = |role: &str, name: &Option<String>| {
            name.as_ref()
                .map(|n| find_sound(self.sounds, n).map_err(|m| fail(format!("sounds.{role}: {m}"))))
                .transpose()
        };
        let SoundsSource { see, attack, pain, death, active } = s.sounds.clone().unwrap_or_default();
        let sounds = Sounds {
            see: sound("see", &see)?,
            attack: sound("attack", &attack)?,
            pain: sound("pain", &pain)?,
            death: sound("death", &death)?,
            active: sound("active", &active)?,
        };
        let actor = |what: &str, name: &Option<String>| {
            name.as_ref()
                .map(|n| lookup(self.by_name, self.written, n).map_err(|m| fail(format!("{what}: {m}"))))
                .transpose()
        };
        let species = actor("species", &s.species)?.unwrap_or(i);
        let drop = actor("drop", &s.drop)?;
        if let Some(pickup) = &s.pickup {
            find_sound(self.sounds, &pickup.sound).map_err(|m| fail(format!("pickup.sound: {m}")))?;
            for give in &pickup.give {
                if let Give::Weapon(name) = give {
                    let t = lookup(self.by_name, self.written, name).map_err(|m| fail(format!("pickup: {m}")))?;
                    let is_weapon = self.written[t].source.weapon.is_some()
                        || self.merged[t].as_ref().is_some_and(|m| m.weapon.is_some());
                    if !is_weapon && t != i {
                        return Err(fail(format!("pickup gives {name:?}, which has no weapon definition")));
                    }
                }
            }
        }
        if s.weapon.is_some() {
            for needed in ["Ready", "Select", "Deselect", "Fire"] {
                if !labels.iter().any(|(l, _)| l.eq_ignore_ascii_case(needed)) {
                    return Err(fail(format!("a weapon needs a {needed}: label")));
                }
            }
        }
        Ok(ActorDef {
            name: w.source.name.clone(),
            doomednum: s.doomednum,
            category: s.category.unwrap_or(Category::Decoration),
            health,
            reaction_time: s.reaction_time.unwrap_or(DEFAULT_REACTION_TIME),
            pain_chance,
            speed,
            fast_speed,
            radius,
            height,
            mass: s.mass.unwrap_or(DEFAULT_MASS),
            damage: s.damage.unwrap_or(0),
            sounds,
            flags,
            species,
            drop,
            pickup: s.pickup.clone(),
            weapon: s.weapon.clone(),
            labels,
            replaced_by: None,
        })
    }

    /// Parses an actor's state text and appends its states; its labels
    /// replace inherited ones of the same name.
    fn add_states(&mut self, i: usize, text: &str, labels: &mut Vec<(String, StateId)>) -> Result<(), ActorTableError> {
        let w = &self.written[i];
        let entries = states::parse(text).map_err(|e| ActorTableError::State {
            path: w.path.clone(),
            actor: w.source.name.clone(),
            label: "?".into(),
            line: e.line,
            text: e.text,
            message: e.message,
        })?;
        let base = self.states.len() as u32;
        // What each new state's `next` becomes once labels are known.
        enum Next {
            Fall,
            Stop,
            Wait,
            To(u32),
            Goto { label: String, offset: u32, entry: usize },
        }
        struct Pending {
            state: State,
            next: Next,
            /// The entry it came from, and the label it is under, for errors.
            entry: usize,
            label: String,
        }
        let mut made: Vec<Pending> = Vec::new();
        let mut own: Vec<(String, u32)> = Vec::new();
        let mut waiting: Vec<String> = Vec::new();
        let mut aliases: Vec<(String, usize)> = Vec::new();
        let mut removed: Vec<String> = Vec::new();
        let mut label_start: Option<u32> = None;
        let mut current = String::from("(no label)");
        let mut closed = true;
        let state_error = |entry: usize, label: &str, message: String| {
            let e = &entries[entry];
            ActorTableError::State {
                path: w.path.clone(),
                actor: w.source.name.clone(),
                label: label.to_string(),
                line: e.line,
                text: e.text.clone(),
                message,
            }
        };
        for (k, entry) in entries.iter().enumerate() {
            match &entry.kind {
                EntryKind::Label(name) => {
                    if own.iter().any(|(l, _)| l.eq_ignore_ascii_case(name)) || waiting.contains(name) {
                        return Err(state_error(k, name, format!("label {name} is defined twice")));
                    }
                    waiting.push(name.clone());
                    current = name.clone();
                }
                EntryKind::States(line) => {
                    let sprite = self
                        .sprites
                        .iter()
                        .position(|s| *s == line.sprite)
                        .ok_or_else(|| state_error(k, &current, format!("unknown sprite {}", line.sprite)))?;
                    let action = match &line.action {
                        None => None,
                        Some((name, args)) => {
                            let made_so_far = made.len() as u32;
                            let call = self.action(name, args, labels, (&own, made_so_far));
                            Some(call.map_err(|m| state_error(k, &current, m))?)
                        }
                    };
                    let first = made.len() as u32;
                    for name in waiting.drain(..) {
                        own.push((name, first));
                    }
                    if own.last().is_some_and(|&(_, s)| s == first) {
                        label_start = Some(first);
                    }
                    for &frame in &line.frames {
                        made.push(Pending {
                            state: State {
                                sprite: sprite as u16,
                                frame,
                                tics: line.tics,
                                bright: line.bright,
                                fast: line.fast,
                                action: action.clone(),
                                next: None,
                            },
                            next: Next::Fall,
                            entry: k,
                            label: current.clone(),
                        });
                    }
                    closed = false;
                }
                flow => {
                    if !waiting.is_empty() {
                        // `Label: goto Other` (or `stop`): an alias.
                        match flow {
                            EntryKind::Goto { .. } => {
                                for name in waiting.drain(..) {
                                    aliases.push((name, k));
                                }
                                continue;
                            }
                            // `Missile: stop`: DECORATE's way of saying the
                            // actor has no such state (an inherited label
                            // is dropped).
                            EntryKind::Stop => {
                                removed.append(&mut waiting);
                                continue;
                            }
                            _ => {
                                return Err(state_error(
                                    k,
                                    &current,
                                    "a label needs a state before `loop` or `wait`".into(),
                                ))
                            }
                        }
                    }
                    if closed {
                        return Err(state_error(k, &current, "nothing before it to continue from".into()));
                    }
                    let last = made.last_mut().expect("a state was made");
                    last.next = match flow {
                        EntryKind::Loop => match label_start {
                            Some(s) => Next::To(s),
                            None => return Err(state_error(k, &current, "`loop` with no label before it".into())),
                        },
                        EntryKind::Stop => Next::Stop,
                        EntryKind::Wait => Next::Wait,
                        EntryKind::Goto { label, offset } => {
                            Next::Goto { label: label.clone(), offset: *offset, entry: k }
                        }
                        _ => unreachable!("labels and states are matched above"),
                    };
                    closed = true;
                }
            }
        }
        if let Some(name) = waiting.first() {
            let k = entries.len() - 1;
            return Err(state_error(k, name, format!("label {name} has no states after it")));
        }
        if !closed {
            let k = made.last().map_or(0, |p| p.entry);
            return Err(state_error(k, &current, "the states end without `loop`, `stop`, `wait` or `goto`".into()));
        }
        // The labels: this actor's own, then aliases, over the inherited.
        let mut resolved: Vec<(String, StateId)> = labels.clone();
        let set = |resolved: &mut Vec<(String, StateId)>, name: &str, id: StateId| match resolved
            .iter_mut()
            .find(|(l, _)| l.eq_ignore_ascii_case(name))
        {
            Some(slot) => slot.1 = id,
            None => resolved.push((name.to_string(), id)),
        };
        for (name, s) in &own {
            set(&mut resolved, name, StateId(base + s));
        }
        let count = made.len() as u32;
        let existing = self.states.len();
        let target = |resolved: &[(String, StateId)], label: &str, offset: u32| -> Result<StateId, String> {
            let start =
                resolved.iter().find(|(l, _)| l.eq_ignore_ascii_case(label)).map(|&(_, s)| s).ok_or_else(|| {
                    let known: Vec<&str> = resolved.iter().map(|(l, _)| l.as_str()).collect();
                    format!("no label {label} (this actor has {})", known.join(", "))
                })?;
            let end = if start.0 >= base { base + count } else { existing as u32 };
            match start.0.checked_add(offset).filter(|&id| id < end) {
                Some(id) => Ok(StateId(id)),
                None => Err(format!("{label}+{offset} is past the last state")),
            }
        };
        for (name, k) in &aliases {
            let EntryKind::Goto { label, offset } = &entries[*k].kind else { unreachable!("aliases are gotos") };
            let id = target(&resolved, label, *offset).map_err(|m| state_error(*k, name, m))?;
            set(&mut resolved, name, id);
        }
        resolved.retain(|(l, _)| !removed.iter().any(|r| r.eq_ignore_ascii_case(l)));
        for (n, p) in made.iter().enumerate() {
            let id = base + n as u32;
            let next = match &p.next {
                Next::Fall if n + 1 < made.len() => Some(StateId(id + 1)),
                Next::Fall => unreachable!("the last state is closed"),
                Next::Stop => None,
                Next::Wait => Some(StateId(id)),
                Next::To(s) => Some(StateId(base + s)),
                Next::Goto { label, offset, entry } => {
                    Some(target(&resolved, label, *offset).map_err(|m| state_error(*entry, &p.label, m))?)
                }
            };
            let mut state = p.state.clone();
            state.next = next;
            self.states.push(state);
        }
        // States of 0 tics run within the tick of the state before them; a
        // loop of them would never end.
        for (n, p) in made.iter().enumerate() {
            let mut seen = Vec::new();
            let mut at = Some(StateId(base + n as u32));
            while let Some(id) = at {
                let state = &self.states[id.0 as usize];
                if state.tics != 0 {
                    break;
                }
                if seen.contains(&id) {
                    let message = "states of 0 tics lead back to themselves: the actor would never leave the tick";
                    return Err(state_error(p.entry, &p.label, message.into()));
                }
                seen.push(id);
                at = state.next;
            }
        }
        *labels = resolved;
        Ok(())
    }

    /// Checks a call against the registry and resolves its arguments.
    fn action(
        &self,
        name: &str,
        args: &[RawArg],
        inherited: &[(String, StateId)],
        own: (&[(String, u32)], u32),
    ) -> Result<ActionCall, String> {
        let id = actions::find(name).ok_or_else(|| {
            let hint = nearest(name, actions::REGISTRY.iter().map(|a| a.name))
                .map(|n| format!(" (did you mean {n}?)"))
                .unwrap_or_default();
            format!("unknown action {name}{hint}")
        })?;
        let spec = actions::spec(id);
        if args.len() > spec.args.len() {
            return Err(format!(
                "{} takes {} argument{}, given {}: {}",
                spec.name,
                spec.args.len(),
                if spec.args.len() == 1 { "" } else { "s" },
                args.len(),
                actions::signature(spec)
            ));
        }
        let mut out = Vec::new();
        for (k, a) in spec.args.iter().enumerate() {
            let wrong = |given: &RawArg| {
                format!(
                    "argument {} ({}) must be {}, given {given:?}: {}",
                    k + 1,
                    a.name,
                    a.kind.describe(),
                    actions::signature(spec)
                )
            };
            let arg = match (args.get(k), a.default) {
                (Some(given), _) => given.clone(),
                (None, Some(Default::Int(v))) => RawArg::Int(v),
                (None, Some(Default::Name(n))) => RawArg::Str(n.to_string()),
                (None, None) => {
                    return Err(format!("argument {} ({}) is missing: {}", k + 1, a.name, actions::signature(spec)))
                }
            };
            out.push(match (a.kind, &arg) {
                (ArgKind::Int, RawArg::Int(v)) => Arg::Int(i32::try_from(*v).map_err(|_| wrong(&arg))?),
                (ArgKind::Number, RawArg::Int(v)) => Arg::Number(*v as f64),
                (ArgKind::Number, RawArg::Number(v)) => Arg::Number(*v),
                (ArgKind::Actor, RawArg::Str(n)) => Arg::Actor(lookup(self.by_name, self.written, n)?),
                (ArgKind::Sound, RawArg::Str(n)) => Arg::Sound(find_sound(self.sounds, n)?),
                (ArgKind::State, RawArg::Word(w) | RawArg::Str(w)) => Arg::State(
                    self.label_arg(w, inherited, own).ok_or_else(|| format!("no label {w} before this state"))?,
                ),
                _ => return Err(wrong(&arg)),
            });
        }
        Ok(ActionCall { action: id, args: out })
    }

    /// A label argument: an inherited label, or one of this actor's labels
    /// with a state written before this line (`own`: its labels and how
    /// many states it has so far; a later label is not yet known: write
    /// jumps forward with `goto`). `None` when no such state exists.
    fn label_arg(&self, word: &str, inherited: &[(String, StateId)], own: (&[(String, u32)], u32)) -> Option<StateId> {
        let (label, offset) = match word.split_once('+') {
            Some((l, o)) => (l, o.parse::<u32>().ok()?),
            None => (word, 0),
        };
        let base = self.states.len() as u32;
        let (labels, made) = own;
        let same = |l: &&(String, u32)| l.0.eq_ignore_ascii_case(label);
        if let Some(&(_, s)) = labels.iter().find(same) {
            return s.checked_add(offset).filter(|&k| k < made).map(|k| StateId(base + k));
        }
        let (_, s) = inherited.iter().find(|(l, _)| l.eq_ignore_ascii_case(label))?;
        s.0.checked_add(offset).filter(|&id| id < base).map(StateId)
    }
}

/// The prefix under which a child's state text sees its parent's labels.
const SUPER: &str = "Super::";

/// A resolved actor as a source its children can inherit from: the
/// properties only (flags and labels are taken from the definition).
fn source_of(table: &ActorTable, index: usize, def: &ActorDef) -> ActorSource {
    let sound = |s: Option<usize>| s.and_then(|i| table.sounds.get(i).cloned());
    let name = |a: Option<usize>| a.and_then(|i| table.actors.get(i)).map(|a| a.name.clone());
    ActorSource {
        name: def.name.clone(),
        doomednum: def.doomednum,
        category: Some(def.category),
        health: Some(def.health),
        reaction_time: Some(def.reaction_time),
        pain_chance: Some(def.pain_chance),
        speed: Some(def.speed),
        fast_speed: def.fast_speed,
        radius: Some(def.radius),
        height: Some(def.height),
        mass: Some(def.mass),
        damage: Some(def.damage),
        sounds: Some(SoundsSource {
            see: sound(def.sounds.see),
            attack: sound(def.sounds.attack),
            pain: sound(def.sounds.pain),
            death: sound(def.sounds.death),
            active: sound(def.sounds.active),
        }),
        // A species of its own stays the child's own.
        species: name(Some(def.species).filter(|&s| s != index)),
        drop: name(def.drop),
        pickup: def.pickup.clone(),
        weapon: def.weapon.clone(),
        ..ActorSource::default()
    }
}

/// A child's fields over its parent's.
fn inherit(child: ActorSource, parent: &ActorSource) -> ActorSource {
    let p = parent.clone();
    ActorSource {
        name: child.name,
        based_on: child.based_on,
        replaces: child.replaces,
        // An editor number belongs to one actor: a child needs its own.
        doomednum: child.doomednum,
        category: child.category.or(p.category),
        health: child.health.or(p.health),
        reaction_time: child.reaction_time.or(p.reaction_time),
        pain_chance: child.pain_chance.or(p.pain_chance),
        speed: child.speed.or(p.speed),
        fast_speed: child.fast_speed.or(p.fast_speed),
        radius: child.radius.or(p.radius),
        height: child.height.or(p.height),
        mass: child.mass.or(p.mass),
        damage: child.damage.or(p.damage),
        sounds: child.sounds.or(p.sounds),
        flags: child.flags.or(p.flags),
        add_flags: child.add_flags,
        remove_flags: child.remove_flags,
        species: child.species.or(p.species),
        drop: child.drop.or(p.drop),
        pickup: child.pickup.or(p.pickup),
        weapon: child.weapon.or(p.weapon),
        states: child.states,
    }
}
