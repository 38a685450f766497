//! `sightline import`: Doom WAD maps to RON maps with their art as PNGs.

use anyhow::{Context, Result};
use sightline::bsp::{build, BuildOptions};
use sightline::map::validate::validate;
use sightline::map::MapError;
use sightline::wad::import::{convert_records, write_art, Art, Converted};
use sightline::wad::Wad;

use crate::cli::ImportArgs;

pub fn run(args: &ImportArgs) -> Result<()> {
    let pwad = Wad::open(&args.wad)?;
    // `all`: the given WAD's maps, not its IWAD's.
    let names = match args.map.as_str() {
        "all" | "ALL" => pwad.map_names(),
        one => vec![one.to_ascii_uppercase()],
    };
    let wad = match &args.iwad {
        Some(iwad) => Wad::stack(vec![Wad::open(iwad)?, pwad]),
        None => pwad,
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
    if !args.json {
        println!("{}: {files} PNG files in textures/, flats/ and sprites/", args.output.display());
    }
    if !failed.is_empty() {
        anyhow::bail!("{} of {} maps failed to import: {}", failed.len(), names.len(), failed.join(" "));
    }
    Ok(())
}

fn import_one(args: &ImportArgs, wad: &Wad, art: &Art, name: &str) -> Result<Converted> {
    let records = wad.map_records(name)?;
    let c = convert_records(wad, &records, art)?;
    let path = args.output.join(format!("{}.ron", name.to_ascii_lowercase()));
    let label = path.display().to_string();
    // Check before writing: an imported map that our validator or
    // compiler refuses is an importer bug, and the error should say so.
    let map = validate(&c.source).map_err(|problems| MapError::Invalid { path: label.clone(), problems })?;
    if args.check {
        build(&map, &BuildOptions::default()).with_context(|| format!("{label}: imported, but does not compile"))?;
    }
    let r = &c.report;
    let listed = |what: &str, items: &[String]| items.iter().map(|i| format!("// {what}: {i}\n")).collect::<String>();
    let header = format!(
        "// {} from {}, imported by `sightline import`.\n{}{}{}{}{}",
        name,
        args.wad.file_name().map_or(wad.path.clone(), |f| f.to_string_lossy().into_owned()),
        listed("repaired", &c.repairs),
        listed("not translated", &r.unsupported_specials),
        listed("unknown thing", &r.unknown_things),
        listed("ignored", &r.ignored),
        listed("names nothing", &r.dangling),
    );
    std::fs::write(&path, header + &c.source.to_ron() + "\n").with_context(|| format!("{label}: cannot write"))?;
    if args.json {
        println!("{}", report_json(name, &c));
        return Ok(c);
    }
    println!(
        "{label}: {} vertices, {} lines, {} trigger lines, {} sectors, {} things, {} specials, {} textures, {} flats, {} sprites{}",
        c.source.vertices.len(),
        c.source.lines.len(),
        c.source.trigger_lines.len(),
        c.source.sectors.len(),
        c.source.things.len(),
        r.specials + r.sector_specials,
        c.walls.len(),
        c.flats.len(),
        c.sprites.len(),
        match c.repairs.len() {
            0 => String::new(),
            n => format!(", {n} repairs"),
        }
    );
    let untranslated = r.unsupported_specials.len() + r.unknown_things.len() + r.dangling.len() + r.ignored.len();
    if untranslated > 0 {
        println!(
            "  {} specials not translated, {} unknown things, {} specials that name nothing, {} ignored (listed at the top of the file)",
            r.unsupported_specials.len(),
            r.unknown_things.len(),
            r.dangling.len(),
            r.ignored.len()
        );
    }
    Ok(c)
}

/// One map's import as one JSON object: its size, what was translated, and
/// what was not (counts, then the lists).
fn report_json(name: &str, c: &Converted) -> serde_json::Value {
    let r = &c.report;
    serde_json::json!({
        "map": name,
        "vertices": c.source.vertices.len(),
        "lines": c.source.lines.len(),
        "trigger_lines": c.source.trigger_lines.len(),
        "sectors": c.source.sectors.len(),
        "things": c.source.things.len(),
        "line_specials": r.specials,
        "sector_specials": r.sector_specials,
        "unsupported_specials": r.unsupported_specials.len(),
        "unknown_things": r.unknown_things.len(),
        "ignored_specials": r.ignored.len(),
        "dangling_specials": r.dangling.len(),
        "repairs": c.repairs.len(),
        "lists": {
            "unsupported_specials": r.unsupported_specials,
            "unknown_things": r.unknown_things,
            "ignored_specials": r.ignored,
            "dangling_specials": r.dangling,
            "repairs": c.repairs,
        },
    })
}
