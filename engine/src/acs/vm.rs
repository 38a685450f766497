//! The ACS virtual machine's state and scheduler: a module's variables, the
//! running scripts in ZDoom's order, and the per-tic loop. `exec` runs one
//! script's instructions; this file decides which script runs when.
//!
//! Order, as ZDoom's `DACSThinker`: running scripts form a list; a started
//! script goes to the front (`DLevelScript::Link`), and `tick` walks the list
//! from the front, taking each script's successor before running it, so a
//! script started during the tic first runs on the next one (unless started
//! with a result wanted, which runs it at once). A script that begins waiting
//! for another goes to the back (`PutLast`) and returns to the front when the
//! wait ends (`PutFirst`).

use std::collections::HashMap;
use std::sync::Arc;

use super::decode::script_label;
use super::host::{Activator, Host, Strings};
use super::load::{LoadError, Module, Problem};
use super::pcodes;
use super::ScriptKind;

/// World variables and arrays (ZDoom's `NUM_WORLDVARS`).
pub const WORLD_VARS: usize = 256;
/// Global variables and arrays (ZDoom's `NUM_GLOBALVARS`).
pub const GLOBAL_VARS: usize = 64;
/// Instructions one script may run in one tic before it is stopped as a
/// runaway: ZDoom's `RunScript` counts to 2,000,000 per call.
pub const RUNAWAY_LIMIT: u32 = 2_000_000;

/// Variables that outlive a map: world variables last a hub, global ones the
/// whole game. Move them from one map's VM to the next with [`Vm::globals`].
#[derive(Clone, Debug)]
pub struct Globals {
    pub world: Vec<i32>,
    pub global: Vec<i32>,
    /// Sparse, as ZDoom's `FWorldGlobalArray`: any index, absent means 0.
    pub world_arrays: Vec<HashMap<i32, i32>>,
    pub global_arrays: Vec<HashMap<i32, i32>>,
}

impl Default for Globals {
    fn default() -> Globals {
        Globals {
            world: vec![0; WORLD_VARS],
            global: vec![0; GLOBAL_VARS],
            world_arrays: vec![HashMap::new(); WORLD_VARS],
            global_arrays: vec![HashMap::new(); GLOBAL_VARS],
        }
    }
}

/// What a script is doing between tics (ZDoom's `EScriptState`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    Running,
    Suspended,
    /// Waiting out the tics in `Thread::wait`.
    Delayed,
    /// Waiting for the sectors tagged `Thread::wait` to stop moving.
    TagWait,
    PolyWait,
    /// Waiting for script `Thread::wait` to start, then to finish.
    ScriptWaitPre,
    ScriptWait,
    /// Finished; removed when its turn comes.
    Remove,
}

/// Whose locals (and local arrays) an instruction sees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Owner {
    Script(usize),
    Function(usize),
}

/// A function call's return: where to go back and the caller's locals.
#[derive(Clone, Debug)]
pub struct Frame {
    pub ret: usize,
    pub locals: Vec<i32>,
    pub owner: Owner,
    pub discard: bool,
    /// Stack height after the arguments were taken; a return cuts back to it.
    pub base: usize,
}

/// One running script.
#[derive(Clone, Debug)]
pub struct Thread {
    pub number: i32,
    /// Index in `Module::scripts`.
    pub script: usize,
    pub pc: usize,
    pub locals: Vec<i32>,
    pub owner: Owner,
    /// Kept between tics (ZDoom drops it) so a `delay` inside a function
    /// resumes correctly instead of corrupting the caller.
    pub stack: Vec<i32>,
    pub frames: Vec<Frame>,
    pub state: State,
    pub wait: i32,
    pub activator: Activator,
    /// Text being built between BEGINPRINT and its end, innermost last.
    pub print: Vec<String>,
    /// Stack height at OPTHUDMESSAGE.
    pub hud_optional: Option<usize>,
}

/// A list node: the thread (taken out while it runs) and its neighbours.
#[derive(Clone, Debug, Default)]
struct Slot {
    thread: Option<Box<Thread>>,
    next: Option<usize>,
    prev: Option<usize>,
    linked: bool,
    /// A state set by another script while this one was running.
    pending: Option<State>,
}

/// A loaded module, its variables and its running scripts.
#[derive(Clone)]
pub struct Vm {
    /// Shared so a running script can read its code while it changes the VM.
    pub module: Arc<Module>,
    pub map_vars: Vec<i32>,
    pub map_arrays: Vec<Vec<i32>>,
    pub globals: Globals,
    pub strings: Strings,
    /// The level number `ACS_Execute`'s map argument names as "this map"
    /// (0 always does). Requests for other maps go to the host as specials.
    pub level_number: i32,
    /// Messages about scripts stopped at run time (runaway, division by
    /// zero, bad variable index, unknown script), oldest first.
    pub warnings: Vec<String>,
    slots: Vec<Slot>,
    head: Option<usize>,
    tail: Option<usize>,
    free: Vec<usize>,
    /// Scripts started without "always", by number (ZDoom's `RunningScripts`).
    running: HashMap<i32, usize>,
    /// Scripts running inside other scripts' instructions (result calls).
    pub(super) nesting: u32,
}

impl Vm {
    /// A VM for `module`, refusing it if it calls an extended function that
    /// neither the VM nor `host` provides.
    pub fn new(module: Module, host: &dyn Host) -> Result<Vm, LoadError> {
        for (&id, &offset) in &module.code.functions {
            if !super::calls::vm_function(id) && !host.supports_function(id) {
                let name = pcodes::function_name(id).unwrap_or("unknown");
                let problem = Problem::UnsupportedFunction { id, name, offset: offset as usize };
                return Err(LoadError { lump: module.lump.clone(), problem });
            }
        }
        let map_arrays = module
            .arrays
            .iter()
            .map(|a| {
                let mut v = a.init.clone();
                v.resize(a.size, 0);
                v
            })
            .collect();
        Ok(Vm {
            map_vars: module.map_vars.clone(),
            map_arrays,
            globals: Globals::default(),
            strings: Strings::new(module.strings.clone()),
            module: Arc::new(module),
            level_number: 0,
            nesting: 0,
            warnings: Vec::new(),
            slots: Vec::new(),
            head: None,
            tail: None,
            free: Vec::new(),
            running: HashMap::new(),
        })
    }

    /// Starts every script of `kind` in number order (ZDoom's
    /// `StartTypedScripts`): OPEN scripts with the world as activator when
    /// the level starts, ENTER scripts with `always` for each player that
    /// enters. Each gets `arg` as its first argument. Since each goes to the
    /// front, the highest number runs first.
    pub fn start_typed(&mut self, kind: ScriptKind, activator: Activator, always: bool, arg: i32) {
        let numbers: Vec<i32> = self.module.scripts.iter().filter(|s| s.kind == kind).map(|s| s.number).collect();
        for n in numbers {
            self.start(n, &[arg], activator, always);
        }
    }

    /// `ACS_Execute` (`always` false: not if the script already runs, but a
    /// suspended one resumes) and `ACS_ExecuteAlways`. The script first runs
    /// at the next tick. Returns whether a script was started or resumed.
    pub fn execute(&mut self, number: i32, args: &[i32], activator: Activator, always: bool) -> bool {
        self.start(number, args, activator, always).is_some()
    }

    /// `ACS_ExecuteWithResult`: starts the script (always) and runs it at
    /// once until it waits or ends; returns its `SetResultValue` (1 if none).
    pub fn execute_with_result(&mut self, number: i32, args: &[i32], activator: Activator, host: &mut dyn Host) -> i32 {
        match self.start(number, args, activator, true) {
            Some(id) => self.run(id, host),
            None => 0,
        }
    }

    /// `ACS_Suspend`: the script stops until executed again.
    pub fn suspend(&mut self, number: i32) {
        self.set_state(number, State::Suspended);
    }

    /// `ACS_Terminate`.
    pub fn terminate(&mut self, number: i32) {
        self.set_state(number, State::Remove);
    }

    /// Whether a script started without "always" still runs.
    pub fn is_running(&self, number: i32) -> bool {
        self.running.contains_key(&number)
    }

    /// Numbers of the scripts in the list, front first.
    pub fn scripts_in_order(&self) -> Vec<i32> {
        let mut out = Vec::new();
        let mut cur = self.head;
        while let Some(id) = cur {
            if let Some(t) = &self.slots[id].thread {
                out.push(t.number);
            }
            cur = self.slots[id].next;
        }
        out
    }

    /// One tic: every listed script runs in list order until it waits, ends
    /// or exceeds [`RUNAWAY_LIMIT`].
    pub fn tick(&mut self, host: &mut dyn Host) {
        let mut cur = self.head;
        while let Some(id) = cur {
            cur = self.slots[id].next;
            if self.slots[id].linked {
                self.run(id, host);
            }
        }
        // Slots freed during the tic are reused only now, so the successor
        // taken above never names a recycled slot.
        self.free
            .extend(self.slots.iter().enumerate().filter(|(_, s)| !s.linked && s.thread.is_none()).map(|(i, _)| i));
        self.free.sort_unstable();
        self.free.dedup();
    }

    pub(super) fn start(&mut self, number: i32, args: &[i32], activator: Activator, always: bool) -> Option<usize> {
        let Some(index) = self.module.scripts.iter().position(|s| s.number == number) else {
            self.warnings.push(format!("{} does not exist", script_label(number, None)));
            return None;
        };
        if !always {
            if let Some(&id) = self.running.get(&number) {
                let slot = &mut self.slots[id];
                return match &mut slot.thread {
                    Some(t) if t.state == State::Suspended => {
                        t.state = State::Running;
                        Some(id)
                    }
                    _ => None,
                };
            }
        }
        let script = &self.module.scripts[index];
        let mut locals = vec![0; script.vars.max(usize::from(script.args))];
        for (l, a) in locals.iter_mut().zip(args.iter().take(usize::from(script.args))) {
            *l = *a;
        }
        let pc = self.module.code.at(script.address).unwrap_or(usize::MAX);
        let thread = Thread {
            number,
            script: index,
            pc,
            locals,
            owner: Owner::Script(index),
            stack: Vec::new(),
            frames: Vec::new(),
            state: State::Running,
            wait: 0,
            activator,
            print: Vec::new(),
            hud_optional: None,
        };
        let id = match self.free.pop() {
            Some(id) => id,
            None => {
                self.slots.push(Slot::default());
                self.slots.len() - 1
            }
        };
        self.slots[id] = Slot { thread: Some(Box::new(thread)), ..Slot::default() };
        if !always {
            self.running.insert(number, id);
        }
        self.link_front(id);
        Some(id)
    }

    pub(super) fn set_state(&mut self, number: i32, state: State) {
        if let Some(&id) = self.running.get(&number) {
            let slot = &mut self.slots[id];
            match &mut slot.thread {
                Some(t) => t.state = state,
                None => slot.pending = Some(state),
            }
        }
    }

    /// A state another script set on `id` while it ran, taken once.
    pub(super) fn take_pending(&mut self, id: usize) -> Option<State> {
        self.slots.get_mut(id).and_then(|s| s.pending.take())
    }

    /// Runs the thread in `id` for this tic; returns its result value.
    fn run(&mut self, id: usize, host: &mut dyn Host) -> i32 {
        // A script already running further up (a result call that reached its
        // own caller) is left alone, as ZDoom's state check would.
        let Some(mut t) = self.slots[id].thread.take() else { return 0 };
        let mut result = 1;
        if self.wake(id, &mut t, host) {
            result = super::exec::run(self, id, &mut t, host);
        }
        if let Some(s) = self.slots[id].pending.take() {
            t.state = s;
        }
        if t.state == State::Remove {
            self.unlink(id);
            if self.running.get(&t.number) == Some(&id) {
                self.running.remove(&t.number);
            }
        } else {
            self.slots[id].thread = Some(t);
        }
        result
    }

    /// The wait states' checks at the start of a turn (ZDoom's `RunScript`
    /// prologue); whether the script runs now.
    fn wake(&mut self, id: usize, t: &mut Thread, host: &mut dyn Host) -> bool {
        match t.state {
            State::Delayed => {
                t.wait -= 1;
                if t.wait <= 0 {
                    t.state = State::Running;
                }
            }
            State::TagWait if !host.sectors_busy(t.wait) => t.state = State::Running,
            State::PolyWait if !host.polyobj_busy(t.wait) => t.state = State::Running,
            State::ScriptWaitPre if self.running.contains_key(&t.wait) => t.state = State::ScriptWait,
            State::ScriptWait if !self.running.contains_key(&t.wait) => {
                t.state = State::Running;
                self.unlink(id);
                self.link_front(id);
            }
            _ => {}
        }
        t.state == State::Running
    }

    fn link_front(&mut self, id: usize) {
        let old = self.head;
        let slot = &mut self.slots[id];
        slot.next = old;
        slot.prev = None;
        slot.linked = true;
        if let Some(h) = old {
            self.slots[h].prev = Some(id);
        }
        self.head = Some(id);
        if self.tail.is_none() {
            self.tail = Some(id);
        }
    }

    /// Takes `id` out of the list; its `next` is kept so a walk that stands
    /// on it can go on.
    fn unlink(&mut self, id: usize) {
        if !self.slots[id].linked {
            return;
        }
        let (prev, next) = (self.slots[id].prev, self.slots[id].next);
        match prev {
            Some(p) => self.slots[p].next = next,
            None => self.head = next,
        }
        match next {
            Some(n) => self.slots[n].prev = prev,
            None => self.tail = prev,
        }
        self.slots[id].linked = false;
        self.slots[id].prev = None;
    }

    /// `PutLast`: to the back of the list, where this tic's walk meets it again.
    pub(super) fn put_last(&mut self, id: usize) {
        if self.tail == Some(id) {
            return;
        }
        self.unlink(id);
        let old = self.tail;
        self.slots[id].prev = old;
        self.slots[id].next = None;
        self.slots[id].linked = true;
        match old {
            Some(t) => self.slots[t].next = Some(id),
            None => self.head = Some(id),
        }
        self.tail = Some(id);
    }
}
