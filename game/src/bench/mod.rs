//! `sightline bench`: measuring the engine headless. Without a subcommand it
//! runs the study suite over many maps and writes a report (see
//! [`crate::suite`]); `bench tour` times `render_frame` over a fixed tour of
//! one map, `bench autopilot` the bot and `bench check` `sightline check`.

mod autopilot;
mod check;
mod expert;
mod tour;

use anyhow::Result;

use crate::cli::{BenchArgs, BenchCommand};

pub fn run(args: &BenchArgs) -> Result<()> {
    match &args.command {
        Some(BenchCommand::Tour(tour)) => tour::run(tour),
        Some(BenchCommand::Autopilot(a)) => autopilot::run(a),
        Some(BenchCommand::Check(a)) => check::run(a),
        Some(BenchCommand::Expert(a)) => expert::run(a),
        None => crate::suite::run(&args.suite),
    }
}
