//! The vector environment's threads: one call's games are stepped by the
//! calling thread and a few helper threads together, each game taken by
//! whoever is free first.
//!
//! Why not a rayon pool (the first form): `install` hands the whole call to
//! the pool's threads and puts the caller to sleep until they are done, so
//! every step paid two thread wake-ups, and on a machine busy with other
//! work a woken thread waits for the scheduler. Measured on the 2-core dev
//! VM at a load of about 5: basic at 160x120, one game in `Games` made 1,600
//! steps a second using 18% of a core (the rest waiting), against 13,000 for
//! the same game stepped on the caller. Here the caller works from the
//! start and takes every game no helper has taken yet, so a helper that
//! wakes late costs nothing but its own share; the caller waits only for
//! games a helper is already playing.
//!
//! A helper that has finished a call watches for the next one for a short
//! while ([`WATCH`]) before it sleeps: the caller's Python between two steps
//! (the actions drawn, the screens copied) takes tens of microseconds, and a
//! sleeping helper woken on this VM often came too late to take a game of
//! the next call at all (basic at 160x120, four games on two cores: 1.18
//! times one game's steps a second with sleeping helpers).

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use pyo3::PyResult;

use sightline::scenario::observe::Observer;

use crate::env::Env;

/// What a call asks of every game.
#[derive(Clone, Copy, Debug)]
pub enum Task {
    /// Play `tics` tics holding the game's `action` (or start the new
    /// episode its `reset` asks for); then, if `screen`, draw the screen
    /// into the game's part of the call's output.
    Step { tics: u32, screen: bool },
    /// Draw the screen into the game's part of the call's output.
    Screen,
    /// Ask the autopilot for its action, into the game's `expert`.
    Expert,
}

/// One game of the vector and what the last call left in it.
pub struct Slot {
    pub env: Env,
    /// The action the next step holds.
    pub action: Vec<f64>,
    /// A seed for the next step to start a new episode with instead of
    /// playing (taken by that step).
    pub reset: Option<u64>,
    /// The last step's reward.
    pub reward: f64,
    /// The autopilot's last action.
    pub expert: Vec<f64>,
    /// Whether the last task succeeded.
    pub result: PyResult<()>,
}

impl Slot {
    /// Runs `task`, drawing into `out` (the game's part of the call's
    /// output; empty for a task that draws nothing) with `observer`, the
    /// thread's.
    fn run(&mut self, task: Task, out: &mut [u8], observer: &mut Observer) {
        self.result = match task {
            Task::Step { tics, screen } => {
                let played = match self.reset.take() {
                    Some(seed) => self.env.new_episode(seed).map(|()| 0.0),
                    None => self.env.step(&self.action, tics),
                };
                played.and_then(|reward| {
                    self.reward = reward;
                    if screen {
                        self.env.screen_into_using(observer, out)
                    } else {
                        Ok(())
                    }
                })
            }
            Task::Screen => self.env.screen_into_using(observer, out),
            Task::Expert => self.env.expert_action().map(|a| self.expert = a),
        };
    }
}

/// The call's output: one buffer cut into equal parts, game `i` drawing
/// into part `i` on whichever thread takes it. A raw pointer because the
/// parts are written from several threads at once; they never overlap,
/// since each game is taken by one thread once per call, and the buffer
/// outlives the call ([`Crew::run`] returns only when every game is done).
#[derive(Clone, Copy)]
struct Output {
    start: *mut u8,
    each: usize,
}

// SAFETY: see [`Output`]: disjoint parts of a buffer that outlives the
// threads' use of it.
unsafe impl Send for Output {}

impl Output {
    /// Game `i`'s part.
    ///
    /// # Safety
    /// Called once per game per call, while the call's buffer lives.
    unsafe fn part<'a>(self, i: usize) -> &'a mut [u8] {
        if self.each == 0 {
            return &mut [];
        }
        // SAFETY: the caller's promise; part `i` lies inside the buffer
        // (`Crew::run` checked its length).
        unsafe { std::slice::from_raw_parts_mut(self.start.add(i * self.each), self.each) }
    }
}

/// The current call: which one it is, its task and the next game no one
/// has taken (how many are not finished is [`Shared::left`]).
struct Round {
    generation: u64,
    task: Task,
    out: Output,
    next: usize,
    quit: bool,
    /// Helpers asleep on `start`, and whether the caller is asleep on
    /// `done`: a signal no one waits for is not sent (each is a system
    /// call, and most calls find everyone watching).
    sleeping_helpers: usize,
    caller_sleeps: bool,
}

/// How long a thread watches for what it waits on before it sleeps.
const WATCH: Duration = Duration::from_micros(300);

/// Spins until `done` or [`WATCH`] has passed.
fn watch(done: impl Fn() -> bool) {
    let since = Instant::now();
    while !done() && since.elapsed() < WATCH {
        std::hint::spin_loop();
    }
}

struct Shared {
    games: Vec<Mutex<Slot>>,
    /// Each thread's observer, the caller's first ([`Env::screen_into_using`]).
    observers: Vec<Mutex<Observer>>,
    round: Mutex<Round>,
    /// The round's generation, readable without the lock (a watching
    /// helper's); written only with the round locked.
    generation: AtomicU64,
    /// The round's games not finished: read without the lock by the
    /// caller watching for the helpers' last games; changed only with the
    /// round locked, so a sleeper on `done` cannot miss its end.
    left: AtomicUsize,
    /// Signalled when a call starts (or the crew quits).
    start: Condvar,
    /// Signalled when a call's last game is finished.
    done: Condvar,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl Shared {
    /// Takes and plays games of call `generation` until none is left to
    /// take, as thread `worker` (0: the caller). Returns with the round
    /// locked.
    fn work<'a>(&'a self, mut round: MutexGuard<'a, Round>, generation: u64, worker: usize) -> MutexGuard<'a, Round> {
        let mut observer = lock(&self.observers[worker]);
        while round.generation == generation && round.next < self.games.len() {
            let (i, task, out) = (round.next, round.task, round.out);
            round.next += 1;
            drop(round);
            // SAFETY: game `i` is taken once this call (`round.next` moves
            // past it under the lock), and the call waits for it.
            lock(&self.games[i]).run(task, unsafe { out.part(i) }, &mut observer);
            round = lock(&self.round);
            let left = self.left.fetch_sub(1, Ordering::AcqRel) - 1;
            if left == 0 && round.caller_sleeps {
                self.done.notify_one();
            }
        }
        round
    }

    fn helper(&self, worker: usize) {
        let mut seen = 0;
        let mut round = lock(&self.round);
        loop {
            if round.generation == seen && !round.quit {
                drop(round);
                watch(|| self.generation.load(Ordering::Acquire) != seen);
                round = lock(&self.round);
            }
            while round.generation == seen && !round.quit {
                round.sleeping_helpers += 1;
                round = self.start.wait(round).unwrap_or_else(PoisonError::into_inner);
                round.sleeping_helpers -= 1;
            }
            if round.quit {
                return;
            }
            seen = round.generation;
            round = self.work(round, seen, worker);
        }
    }
}

/// The games and their helper threads.
pub struct Crew {
    shared: Arc<Shared>,
    helpers: Vec<JoinHandle<()>>,
}

impl Crew {
    /// `envs` stepped by the caller and `threads - 1` helpers (0: one
    /// thread per core; never more helpers than games after the first).
    pub fn new(envs: Vec<Env>, threads: usize) -> std::io::Result<Crew> {
        let threads = if threads == 0 { std::thread::available_parallelism().map_or(1, usize::from) } else { threads };
        let helpers = threads.saturating_sub(1).min(envs.len().saturating_sub(1));
        let observers = match envs.first() {
            Some(env) => (0..=helpers).map(|_| Mutex::new(Observer::new(env.config(), 1))).collect(),
            None => Vec::new(),
        };
        let games = envs
            .into_iter()
            .map(|env| {
                let action = vec![0.0; env.config().available_buttons.len()];
                Mutex::new(Slot { env, action, reset: None, reward: 0.0, expert: Vec::new(), result: Ok(()) })
            })
            .collect();
        let round = Round {
            generation: 0,
            task: Task::Screen,
            out: Output { start: std::ptr::null_mut(), each: 0 },
            next: 0,
            quit: false,
            sleeping_helpers: 0,
            caller_sleeps: false,
        };
        let shared = Arc::new(Shared {
            games,
            observers,
            round: Mutex::new(round),
            generation: AtomicU64::new(0),
            left: AtomicUsize::new(0),
            start: Condvar::new(),
            done: Condvar::new(),
        });
        let mut crew = Crew { shared, helpers: Vec::new() };
        for k in 0..helpers {
            let shared = crew.shared.clone();
            let handle =
                std::thread::Builder::new().name(format!("sightline-games-{k}")).spawn(move || shared.helper(k + 1))?;
            crew.helpers.push(handle);
        }
        Ok(crew)
    }

    pub fn len(&self) -> usize {
        self.shared.games.len()
    }

    /// Game `i` (none is being played between calls).
    pub fn slot(&self, i: usize) -> MutexGuard<'_, Slot> {
        lock(&self.shared.games[i])
    }

    /// Every game, in order.
    pub fn slots(&self) -> impl Iterator<Item = MutexGuard<'_, Slot>> {
        self.shared.games.iter().map(lock)
    }

    /// Runs `task` on every game and returns when all are done; a task
    /// that draws writes game `i`'s screen into the `i`-th of the equal
    /// parts of `out` (empty for a task that draws nothing).
    pub fn run(&self, task: Task, out: &mut [u8]) {
        let shared = &*self.shared;
        let each = out.len() / shared.games.len();
        assert_eq!(each * shared.games.len(), out.len(), "the output is not one equal part per game");
        let mut round = lock(&shared.round);
        round.generation += 1;
        shared.generation.store(round.generation, Ordering::Release);
        round.task = task;
        round.out = Output { start: out.as_mut_ptr(), each };
        round.next = 0;
        shared.left.store(shared.games.len(), Ordering::Release);
        let generation = round.generation;
        if round.sleeping_helpers > 0 {
            shared.start.notify_all();
        }
        let unfinished = || shared.left.load(Ordering::Acquire) > 0;
        let mut round = shared.work(round, generation, 0);
        if unfinished() {
            // A helper is finishing the call's last games: watch for the
            // end before sleeping, as the helpers watch for a call (a
            // sleeping caller woken by the last game's end came back tens
            // of microseconds late on this VM, at 160x120 a fifth of a
            // four-game call).
            drop(round);
            watch(|| !unfinished());
            round = lock(&shared.round);
        }
        while unfinished() {
            round.caller_sleeps = true;
            round = shared.done.wait(round).unwrap_or_else(PoisonError::into_inner);
            round.caller_sleeps = false;
        }
        round.out = Output { start: std::ptr::null_mut(), each: 0 };
    }
}

impl Drop for Crew {
    fn drop(&mut self) {
        let mut round = lock(&self.shared.round);
        round.quit = true;
        // A watching helper sees a new generation and takes the lock.
        self.shared.generation.store(round.generation + 1, Ordering::Release);
        drop(round);
        self.shared.start.notify_all();
        for handle in self.helpers.drain(..) {
            let _ = handle.join();
        }
    }
}
