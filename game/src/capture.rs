//! `sightline capture`: render one frame of a map headless and write a PNG.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use sightline::bsp::BuildOptions;
use sightline::campaign::{open_with, ArtOptions, MapRef};
use sightline::level::{check_not_input, write_atomic};
use sightline::render::{render_frame, Frame, RenderOptions, Renderer, View};
use sightline::Framebuffer;

use crate::cli::CaptureArgs;

/// The map a new user sees first.
pub const DEFAULT_MAP: &str = "maps/outpost.ron";

pub fn run(args: &CaptureArgs) -> Result<()> {
    let map = MapRef::parse(&args.map, args.iwad.as_deref());
    if let MapRef::File(path) = &map {
        check_not_input(path, &args.output)?;
    }
    let art = ArtOptions { wads: art_wads(&map, args.iwad.as_deref()), missing: None };
    let mut level = open_with(&map, &BuildOptions::default(), &art)?.level;
    warn(&level.materials.warnings);
    level.show_skill(sightline::play::DEFAULT_SKILL);
    let map_name = &args.map;
    let view = match args.pose {
        Some(p) => View::at_pose(&level, p.x, p.y, p.angle, p.z),
        None => View::at_start(&level),
    }
    .with_context(|| format!("{map_name}: bad pose"))?;
    let (width, height) = args.size;
    let mut fb = Framebuffer::new(width, height);
    let renderer = args.renderer.unwrap_or_else(|| Renderer::default_for(&level));
    if !renderer.supports(&level) {
        bail!("{map_name}: the {} renderer draws grid maps only; this is a sector map", renderer.name());
    }
    let options =
        RenderOptions { renderer, shade: args.shade, ray: args.ray, threads: args.threads, ..Default::default() };
    render_frame(&level, &view, &options, &mut Frame::new(), &mut fb);
    write_atomic(&args.output, &fb.to_png())?;
    Ok(())
}

/// The WADs a RON map's pictures come from: `--iwad`'s (a WAD map has
/// it under itself already).
pub fn art_wads(map: &MapRef, iwad: Option<&Path>) -> Vec<PathBuf> {
    match map {
        MapRef::File(_) => iwad.map(Path::to_path_buf).into_iter().collect(),
        MapRef::Wad { .. } => Vec::new(),
    }
}

/// Says on stderr what the art lacked (frames drawn as placeholders).
pub fn warn(warnings: &[String]) {
    for w in warnings {
        eprintln!("sightline: warning: {w}");
    }
}

/// The default level, `maps/outpost.ron`, under the current directory, else in the source tree.
pub fn default_map_path() -> PathBuf {
    let here = PathBuf::from(DEFAULT_MAP);
    if here.exists() {
        return here;
    }
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(DEFAULT_MAP)
}
