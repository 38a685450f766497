//! The game being played, apart from the window: the simulation, where its
//! inputs come from (the keyboard and mouse, or a demo), and the recording of
//! what it was fed. The frame loop asks it to run whole ticks and for the
//! view between the last two.

use sightline::play::{Game, TickInput};
use sightline::View;

use super::input::Controls;
use crate::replay::position_line;

enum Source {
    Live(Controls),
    /// A demo's inputs and the index of the next one to play.
    Demo {
        inputs: Vec<TickInput>,
        next: usize,
    },
}

pub struct Session {
    pub game: Game,
    source: Source,
    /// Every input fed to the game, when recording.
    recording: Option<Vec<TickInput>>,
    /// The demo has run out; the game stands still on its last tick.
    finished: bool,
}

impl Session {
    pub fn live(game: Game, controls: Controls, record: bool) -> Session {
        Session { game, source: Source::Live(controls), recording: record.then(Vec::new), finished: false }
    }

    pub fn demo(game: Game, inputs: Vec<TickInput>) -> Session {
        Session { game, source: Source::Demo { inputs, next: 0 }, recording: None, finished: false }
    }

    /// The keyboard and mouse state, when they drive the game.
    pub fn controls(&mut self) -> Option<&mut Controls> {
        match &mut self.source {
            Source::Live(controls) => Some(controls),
            Source::Demo { .. } => None,
        }
    }

    /// Runs up to `ticks` ticks. When a demo runs out it says so (with the
    /// final position, in the same words `sightline replay` prints) and the
    /// game stops advancing.
    pub fn run(&mut self, ticks: u32) {
        for _ in 0..ticks {
            let input = match &mut self.source {
                Source::Live(controls) => controls.tick_input(),
                Source::Demo { inputs, next } => match inputs.get(*next) {
                    Some(&input) => {
                        *next += 1;
                        input
                    }
                    None => {
                        if !self.finished {
                            self.finished = true;
                            println!("demo finished: {}", position_line(&self.game));
                        }
                        return;
                    }
                },
            };
            self.game.tick(&input);
            if let Some(recording) = &mut self.recording {
                recording.push(input);
            }
        }
    }

    /// The view `alpha` of the way from the previous tick to the last; once a
    /// demo has finished, exactly the last tick (as `sightline replay`
    /// captures it).
    pub fn view(&self, alpha: f64) -> View {
        self.game.view(if self.finished { 1.0 } else { alpha })
    }

    pub fn take_recording(&mut self) -> Option<Vec<TickInput>> {
        self.recording.take()
    }
}
