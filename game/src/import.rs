//! `sightline import`: Doom WAD maps to RON maps with their art as PNGs.

use anyhow::{Context, Result};
use sightline::bsp::{build, BuildOptions};
use sightline::map::validate::validate;
use sightline::map::MapError;
use sightline::wad::import::{convert, write_art, Art, Converted};
use sightline::wad::Wad;

use crate::cli::ImportArgs;

pub fn run(args: &ImportArgs) -> Result<()> {
    let wad = Wad::open(&args.wad)?;
    let names = match args.map.as_str() {
        "all" | "ALL" => wad.map_names(),
        one => vec![one.to_ascii_uppercase()],
    };
    if names.is_empty() {
        anyhow::bail!("{}: has no maps", wad.path);
    }
    let art = Art::read(&wad)?;
    std::fs::create_dir_all(&args.output).with_context(|| format!("{}: cannot create", args.output.display()))?;
    let mut converted: Vec<Converted> = Vec::with_capacity(names.len());
    let mut failed = Vec::new();
    for name in &names {
        match import_one(args, &wad, &art, name) {
            Ok(c) => converted.push(c),
            Err(e) => {
                eprintln!("sightline: {e:#}");
                failed.push(name.clone());
            }
        }
    }
    let files = write_art(&wad, &art, &converted, &args.output)?;
    println!("{}: {files} PNG files in textures/, flats/ and sprites/", args.output.display());
    if !failed.is_empty() {
        anyhow::bail!("{} of {} maps failed to import: {}", failed.len(), names.len(), failed.join(" "));
    }
    Ok(())
}

fn import_one(args: &ImportArgs, wad: &Wad, art: &Art, name: &str) -> Result<Converted> {
    let raw = wad.map(name)?;
    let c = convert(wad, &raw, art)?;
    let path = args.output.join(format!("{}.ron", name.to_ascii_lowercase()));
    let label = path.display().to_string();
    // Check before writing: an imported map that our validator or
    // compiler refuses is an importer bug, and the error should say so.
    let map = validate(&c.source).map_err(|problems| MapError::Invalid { path: label.clone(), problems })?;
    if args.check {
        build(&map, &BuildOptions::default()).with_context(|| format!("{label}: imported, but does not compile"))?;
    }
    let header = format!(
        "// {} from {}, imported by `sightline import`.\n{}",
        name,
        args.wad.file_name().map_or(wad.path.clone(), |f| f.to_string_lossy().into_owned()),
        c.repairs.iter().map(|r| format!("// repaired: {r}\n")).collect::<String>()
    );
    std::fs::write(&path, header + &c.source.to_ron() + "\n").with_context(|| format!("{label}: cannot write"))?;
    println!(
        "{label}: {} vertices, {} lines, {} sectors, {} things, {} textures, {} flats, {} sprites{}",
        c.source.vertices.len(),
        c.source.lines.len(),
        c.source.sectors.len(),
        c.source.things.len(),
        c.walls.len(),
        c.flats.len(),
        c.sprites.len(),
        match c.repairs.len() {
            0 => String::new(),
            n => format!(", {n} repairs (listed at the top of the file)"),
        }
    );
    Ok(c)
}
