//! `sightline check`: a map maker's question, "can this level be
//! finished?". The map is opened as play opens it (so every validation
//! error is reported first, with its file and element), then
//! [`sightline::autopilot::check`] says what the player can and cannot
//! reach, as text or JSON, and `-o` draws it from above.

use anyhow::{Context, Result};
use sightline::autopilot::check::{self, RouteFrom};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open_with, ArtOptions, MapRef};
use sightline::level::{check_not_input, write_atomic};

use crate::cli::CheckArgs;

pub fn run(args: &CheckArgs) -> Result<()> {
    let map = MapRef::parse(&args.map, args.iwad.as_deref());
    if let (MapRef::File(path), Some(out)) = (&map, &args.output) {
        check_not_input(path, out)?;
    }
    // Nothing is drawn but the plan: no sprite is looked up, so a map may
    // name any actor with no art for it. Walls and flats still load (their
    // sizes matter to play), from the map's folder, then the IWAD's.
    let art = ArtOptions { wads: crate::capture::art_wads(&map, args.iwad.as_deref()), ..ArtOptions::none() };
    let level = open_with(&map, &BuildOptions::default(), &art)
        .with_context(|| format!("{}: does not load", map.label()))?
        .level;
    // The route is drawn only into a picture, or for SIGHTLINE_CHECK_TRACE
    // (see `check::check_with`).
    let traced = std::env::var_os("SIGHTLINE_CHECK_TRACE").is_some();
    let (mut report, drawing) = match args.output.is_some() || traced {
        true => {
            let from = if args.bot_route { RouteFrom::Autopilot } else { RouteFrom::Closure };
            let (report, drawing) = check::check_with(level, args.skill, from);
            (report, Some(drawing))
        }
        false => (check::report(&level, args.skill), None),
    };
    report.map = map.label();
    if args.json {
        println!("{}", serde_json::to_string(&report)?);
    } else {
        print!("{}", report.text());
    }
    if let (Some(out), Some(drawing)) = (&args.output, &drawing) {
        let fb = drawing.draw(args.plan_size as usize, args.partitions);
        write_atomic(out, &fb.to_png())?;
        if !args.json {
            println!("wrote the plan to {}", out.display());
        }
    }
    Ok(())
}
