//! `sightline compile`: RON map in, compiled BSP map out (atomically).

use anyhow::Result;
use sightline::bsp::{build, file, BuildOptions};
use sightline::campaign::MapRef;
use sightline::level::{check_not_input, write_atomic, LevelError};
use sightline::map::load_map;

use crate::cli::CompileArgs;

pub fn run(args: &CompileArgs) -> Result<()> {
    check_not_input(&args.map, &args.output)?;
    if matches!(MapRef::parse(&args.map.to_string_lossy(), None), MapRef::Wad { .. }) {
        anyhow::bail!(
            "{}: compile takes a RON map; a WAD's maps are compiled as they are played \
             (`sightline import` writes one out as RON with its textures)",
            args.map.display()
        );
    }
    if is_compiled_file(&args.map) {
        anyhow::bail!("{}: is already a compiled map; compile its .ron source", args.map.display());
    }
    let map = load_map(&args.map)?;
    let options = BuildOptions { splitter: args.splitter, seed: args.seed };
    let compiled =
        build(&map, &options).map_err(|error| LevelError::Compile { path: args.map.display().to_string(), error })?;
    write_atomic(&args.output, &file::to_bytes(&compiled))?;
    let s = &compiled.stats;
    if args.json {
        println!("{}", serde_json::to_string(s)?);
    } else {
        println!(
            "{}: {} lines, {} sides -> {} segs ({} splits), {} nodes, {} leaves, depth {}, {:.1} ms ({} splitter) -> {}",
            args.map.display(),
            s.lines_in,
            s.sides_in,
            s.sides_out,
            s.splits,
            s.nodes,
            s.leaves,
            s.depth,
            s.build_ms,
            s.splitter,
            args.output.display()
        );
    }
    Ok(())
}

/// Does `path` start with the compiled-map header? (Unreadable files are left
/// to the loader, which reports them properly.)
fn is_compiled_file(path: &std::path::Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 32];
    let n = std::fs::File::open(path).and_then(|mut f| f.read(&mut head)).unwrap_or(0);
    file::is_compiled(&head[..n])
}
