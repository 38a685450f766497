//! `sightline`: the engine's command-line front end. With no arguments it
//! captures the default map to a PNG (the window arrives with the play issue).

mod capture;
mod cli;
mod compile;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    let result = match cli.command {
        Some(cli::Command::Compile(args)) => compile::run(&args),
        Some(cli::Command::Capture(args)) => capture::run(&args),
        None => capture::run_default(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("sightline: {e:#}");
            ExitCode::FAILURE
        }
    }
}
