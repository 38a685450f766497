//! `sightline bench`: timing the engine headless, one study per subcommand.
//! `bench tour` times `render_frame` over a fixed tour of one map; further
//! studies (a suite over many maps writing a report) sit beside it as
//! subcommands of their own.

mod tour;

use anyhow::Result;

use crate::cli::{BenchArgs, BenchCommand};

pub fn run(args: &BenchArgs) -> Result<()> {
    match &args.command {
        BenchCommand::Tour(tour) => tour::run(tour),
    }
}
