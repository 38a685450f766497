//! `sightline`: the engine's front end. With no arguments it plays the
//! default map in a window; subcommands compile maps, capture frames headless,
//! replay demos and time the renderer.

mod audio;
mod autoplay;
mod bench;
mod capture;
mod check;
mod cli;
mod compile;
mod config;
mod import;
mod play;
mod replay;
mod replay_lmp;
mod report;
mod scenario;
mod suite;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = cli::Cli::parse();
    if let Some(path) = &cli.actors {
        let installed = sightline::actors::ActorTable::with_file(path).and_then(sightline::actors::ActorTable::install);
        if let Err(e) = installed {
            eprintln!("sightline: --actors: {e}");
            return ExitCode::FAILURE;
        }
    }
    let result = match cli.command {
        Some(cli::Command::Compile(args)) => compile::run(&args),
        Some(cli::Command::Capture(args)) => capture::run(&args),
        Some(cli::Command::Play(args)) => play::run(&args),
        Some(cli::Command::Replay(args)) => replay::run(&args),
        Some(cli::Command::Import(args)) => import::run(&args),
        Some(cli::Command::Bench(args)) => bench::run(&args),
        Some(cli::Command::Autoplay(args)) => autoplay::run(&args),
        Some(cli::Command::Check(args)) => check::run(&args),
        None => play::run(&cli.play),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("sightline: {e:#}");
            ExitCode::FAILURE
        }
    }
}
