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
        out(&format!("{}\n", serde_json::to_string(&report)?))?;
    } else {
        out(&report.text())?;
    }
    if let (Some(out), Some(drawing)) = (&args.output, &drawing) {
        let fb = drawing.draw(args.plan_size as usize, args.partitions);
        write_atomic(out, &fb.to_png())?;
        if !args.json {
            self::out(&format!("wrote the plan to {}\n", out.display()))?;
        }
    }
    Ok(())
}

/// Writes `text` to standard output; a reader that has stopped reading
/// (`sightline check MAP | head`) is no error, and the plan is still drawn.
fn out(text: &str) -> Result<()> {
    write_quietly(&mut std::io::stdout().lock(), text)
}

fn write_quietly(to: &mut impl std::io::Write, text: &str) -> Result<()> {
    match to.write_all(text.as_bytes()).and_then(|()| to.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        written => Ok(written?),
    }
}

#[cfg(test)]
mod tests {
    use std::io::{Error, ErrorKind, Write};

    /// A reader that has gone.
    struct Gone(ErrorKind);

    impl Write for Gone {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(Error::from(self.0))
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_reader_that_stopped_reading_is_no_error_but_a_full_disk_is() {
        assert!(super::write_quietly(&mut Gone(ErrorKind::BrokenPipe), "the exit is reachable\n").is_ok());
        assert!(super::write_quietly(&mut Gone(ErrorKind::StorageFull), "the exit is reachable\n").is_err());
        let mut kept = Vec::new();
        super::write_quietly(&mut kept, "text").unwrap();
        assert_eq!(kept, b"text");
    }
}
