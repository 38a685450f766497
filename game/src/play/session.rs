//! The game being played, apart from the window: the playthrough (one map
//! after another, with intermissions), where its inputs come from (the
//! keyboard and mouse, or a demo), and the recording of what it was fed. The
//! frame loop asks it to run whole ticks and for the view between the last
//! two; messages the game sends are kept for the HUD.

use std::path::Path;

use anyhow::{bail, Context, Result};
use sightline::autopilot::Autopilot;
use sightline::campaign::MapRef;
use sightline::play::events::Event;
use sightline::play::playthrough::{Phase, Playthrough};
use sightline::play::{Exit, GameOptions, TickInput};
use sightline::sim::demo::DemoGame;
use sightline::View;

use super::input::Controls;
use crate::replay::position_line;
use crate::replay_lmp::VanillaRun;

enum Source {
    Live(Controls),
    /// A demo's inputs and the index of the next one to play.
    Demo {
        inputs: Vec<TickInput>,
        next: usize,
    },
    /// The autopilot, made afresh for each level (`None` between levels).
    Autopilot(Option<Box<Autopilot>>),
    /// A Doom demo on the simulation with Doom's arithmetic, drawn into the
    /// playthrough's level (which then only shows it), with the views at the
    /// start and end of the last tic.
    Vanilla(Box<VanillaRun>, View, View),
}

pub struct Session {
    pub play: Playthrough,
    source: Source,
    /// Every input fed to the game, when recording.
    recording: Option<Vec<TickInput>>,
    /// Recording to a `.lmp`: inputs are rounded as the file keeps them
    /// before the game is fed them, carrying this much turn (degrees).
    lmp_carry: Option<f64>,
    /// The demo has run out; the game stands still on its last tick.
    finished: bool,
    /// Messages for the player since the frame loop last took them.
    messages: Vec<String>,
    /// What went wrong loading the next map, once.
    pub error: Option<anyhow::Error>,
    /// Sound to the system's audio, when there is any.
    pub sound: Option<super::sound::SoundOut>,
}

impl Session {
    /// `lmp`: the recording goes to a Doom demo (see [`Session::lmp_carry`]).
    pub fn live(play: Playthrough, controls: Controls, record: bool, lmp: bool) -> Session {
        Session { lmp_carry: lmp.then_some(0.0), ..Session::with(play, Source::Live(controls), record) }
    }

    /// A Doom demo on the simulation with Doom's arithmetic; `play` is a
    /// playthrough of the demo's map, whose level shows it.
    pub fn vanilla(mut play: Playthrough, mut run: VanillaRun) -> Session {
        let view = run.scene.view(&run.game.sim).unwrap_or_else(|| play.game.view(1.0));
        run.scene.draw(&run.game.sim, play.game.level_mut());
        Session::with(play, Source::Vanilla(Box::new(run), view, view), false)
    }

    pub fn demo(play: Playthrough, inputs: Vec<TickInput>) -> Session {
        Session::with(play, Source::Demo { inputs, next: 0 }, false)
    }

    /// The autopilot plays; the window only watches.
    pub fn autopilot(play: Playthrough, record: bool, lmp: bool) -> Session {
        Session { lmp_carry: lmp.then_some(0.0), ..Session::with(play, Source::Autopilot(None), record) }
    }

    fn with(play: Playthrough, source: Source, record: bool) -> Session {
        Session {
            play,
            source,
            recording: record.then(Vec::new),
            lmp_carry: None,
            finished: false,
            messages: Vec::new(),
            error: None,
            sound: None,
        }
    }

    /// Keys drive the game and nothing is being recorded: the map may be
    /// reloaded under the player (a demo would no longer be the game).
    pub fn reloadable(&self) -> bool {
        matches!(self.source, Source::Live(_)) && self.recording.is_none()
    }

    /// Whether the demo played has run out.
    pub fn finished(&self) -> bool {
        self.finished
    }

    /// The keyboard and mouse state, when they drive the game.
    pub fn controls(&mut self) -> Option<&mut Controls> {
        match &mut self.source {
            Source::Live(controls) => Some(controls),
            Source::Demo { .. } | Source::Autopilot(_) | Source::Vanilla(..) => None,
        }
    }

    /// Runs up to `ticks` ticks. When a demo runs out it says so (with the
    /// final position, in the same words `sightline replay` prints) and the
    /// game stops advancing. A next map that cannot be loaded stops the
    /// session with its error.
    pub fn run(&mut self, ticks: u32) {
        if let Source::Vanilla(run, before, after) = &mut self.source {
            for _ in 0..ticks {
                match run.tick() {
                    Ok(true) => {}
                    Ok(false) => {
                        if !self.finished {
                            self.finished = true;
                            println!("demo finished after {} tics", run.next);
                        }
                        return;
                    }
                    Err(e) => {
                        self.error.get_or_insert(e);
                        return;
                    }
                }
                if let Some(map) = run.moved_to() {
                    // The demo went on to the next level: the window shows it.
                    match show_map(&map, self.play.options()) {
                        Ok((play, links)) => {
                            self.play = play;
                            run.show(map, links);
                        }
                        Err(e) => {
                            self.error.get_or_insert(e);
                            return;
                        }
                    }
                }
                self.play.phase = vanilla_phase(&run.game, &run.shown);
                let mut events = Vec::new();
                sightline::sim::game::outside_events(&mut run.game.sim, &run.scene, &mut events);
                let game = &run.game.sim;
                run.scene.draw(game, self.play.game.level_mut());
                show_status(game, self.play.game.player_mut());
                *before = *after;
                *after = run.scene.view(game).unwrap_or(*after);
                // The map's music and the tic's sounds, heard where the view is.
                if let Some(sound) = &mut self.sound {
                    let at = |a: u32| {
                        let m = game.mobjs.get(a as usize).filter(|m| !m.removed && m.state.is_some())?;
                        Some(glam::DVec2::new(m.x.to_f64(), m.y.to_f64()))
                    };
                    let listener = sightline::sound::mix::Listener { pos: after.pos, angle: after.angle };
                    let heard = sightline::sound::Heard { events: &events, listener, tick: run.next as u64, at: &at };
                    sound.tick_heard(&self.play, &heard);
                }
                for event in events {
                    if let Event::Message(text) = event {
                        self.messages.push(text);
                    }
                }
                if self.play.phase != Phase::Playing {
                    *before = *after;
                }
            }
            return;
        }
        for _ in 0..ticks {
            let input = match &mut self.source {
                Source::Vanilla(..) => return,
                Source::Live(controls) => controls.tick_input(),
                Source::Autopilot(bot) => autopilot_input(bot, &self.play),
                Source::Demo { inputs, next } => match inputs.get(*next) {
                    Some(&input) => {
                        *next += 1;
                        input
                    }
                    None => {
                        if !self.finished {
                            self.finished = true;
                            println!("demo finished: {}", position_line(&self.play));
                        }
                        return;
                    }
                },
            };
            let input = match &mut self.lmp_carry {
                Some(carry) => sightline::play::vanilla::as_recorded(&input, carry),
                None => input,
            };
            if let Err(e) = self.play.tick(&input) {
                self.error.get_or_insert(e.into());
                return;
            }
            if let Some(sound) = &mut self.sound {
                sound.tick(&self.play);
            }
            for event in self.play.game.events() {
                if let Event::Message(text) = event {
                    self.messages.push(text.clone());
                }
            }
            if let Some(recording) = &mut self.recording {
                recording.push(input);
            }
        }
    }

    /// The view `alpha` of the way from the previous tick to the last; once a
    /// demo has finished, or in an intermission, exactly the last tick.
    pub fn view(&self, alpha: f64) -> View {
        if let Source::Vanilla(_, before, after) = &self.source {
            let a = if self.finished || alpha.is_nan() { 1.0 } else { alpha.clamp(0.0, 1.0) };
            let turned = (after.angle - before.angle + 540.0).rem_euclid(360.0) - 180.0;
            return View::new(
                before.pos + (after.pos - before.pos) * a,
                before.z + (after.z - before.z) * a,
                (before.angle + turned * a).rem_euclid(360.0),
            );
        }
        let still = self.finished || self.play.phase != Phase::Playing;
        self.play.game.view(if still { 1.0 } else { alpha })
    }

    /// The messages since the last call.
    pub fn take_messages(&mut self) -> Vec<String> {
        std::mem::take(&mut self.messages)
    }

    /// Saves the game to `path`, making its directory if need be.
    pub fn save(&self, path: &Path) -> Result<()> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).with_context(|| format!("{}: cannot make the directory", dir.display()))?;
        }
        Ok(self.play.save(path)?)
    }

    /// Replaces the game with the one saved in `path`. On any error the
    /// game goes on as it was. Refused while a demo plays or is recorded
    /// (its inputs would no longer be the game's).
    pub fn load(&mut self, path: &Path) -> Result<()> {
        if matches!(self.source, Source::Demo { .. }) {
            bail!("a demo is playing: a loaded game would leave it");
        }
        if self.recording.is_some() {
            bail!("a demo is being recorded, and would not replay a loaded game (saving still works)");
        }
        let play = Playthrough::load(path)?;
        self.replace(play)
    }

    /// Replaces the game with `play` (a new game from the menu); refused
    /// while a demo plays or is recorded, as a load is.
    pub fn new_game(&mut self, play: Playthrough) -> Result<()> {
        if matches!(self.source, Source::Demo { .. }) || self.recording.is_some() {
            bail!("a demo is playing or being recorded: a new game would leave it");
        }
        self.replace(play)
    }

    fn replace(&mut self, play: Playthrough) -> Result<()> {
        self.play = play;
        self.finished = false;
        if let Source::Autopilot(bot) = &mut self.source {
            // A new bot for the loaded game.
            *bot = None;
        }
        if let Some(sound) = &mut self.sound {
            sound.restart();
        }
        if let Some(controls) = self.controls() {
            controls.release_all();
        }
        Ok(())
    }

    pub fn take_recording(&mut self) -> Option<Vec<TickInput>> {
        self.recording.take()
    }
}

/// The autopilot's input: on a level, the bot's (a new bot for a new level
/// or a restart); in an intermission or when dead, a press every other tick
/// to go on.
fn autopilot_input(bot: &mut Option<Box<Autopilot>>, play: &Playthrough) -> TickInput {
    let game = &play.game;
    if play.phase != Phase::Playing || game.player().dead() {
        *bot = None;
        return sightline::autopilot::press_on(play.ticks);
    }
    if game.ticks() == 0 {
        *bot = None;
    }
    bot.get_or_insert_with(|| Box::new(Autopilot::new(game))).tick(game)
}

/// A playthrough of `map`, only to show a Doom demo's game on, and how
/// the simulation's level maps onto it.
fn show_map(map: &MapRef, options: GameOptions) -> Result<(Playthrough, sightline::wad::import::Links)> {
    let play = Playthrough::of(map, options)?;
    let links = play.game.links().clone();
    Ok((play, links))
}

/// What the window shows of a Doom demo's game: the level, or the
/// intermission with its tallies, or the end.
fn vanilla_phase(game: &DemoGame, shown: &MapRef) -> Phase {
    let sim = &game.sim;
    let stats = sightline::sim::game::stats_of(sim);
    match &game.between {
        _ if game.over => Phase::Finished { stats },
        None => Phase::Playing,
        Some((wi, next)) => Phase::Intermission {
            map: shown.short_name(),
            stats,
            exit: if sim.exit == Some(true) { Exit::Secret } else { Exit::Normal },
            next: next.as_ref().map(|n| shown.in_same_wads(n)),
            wi: Box::new(wi.clone()),
        },
    }
}

/// The status bar's figures from the simulation's console player (the
/// playthrough's own player only stands in for it on screen).
fn show_status(game: &sightline::sim::Sim, shown: &mut sightline::play::player::Player) {
    let Some(p) = game.player(game.console) else { return };
    shown.health = p.health;
    shown.armor = p.armorpoints;
    shown.ammo = p.ammo;
    shown.max_ammo = p.maxammo;
}
