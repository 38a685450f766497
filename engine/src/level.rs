//! Opening a level for rendering: a RON source (validated and compiled on the
//! spot) or a compiled map file (loaded as is), told apart by content, plus
//! its materials (every texture it names, resolved beside the map file).

use std::path::Path;

use crate::bsp::{build, file, BuildOptions, CompileError, CompiledMap};
use crate::grid::{self, FaceLines, Grid};
use crate::map::load::parse_any_map;
use crate::map::MapError;
use crate::materials::{MaterialError, Materials};

#[derive(Debug, thiserror::Error)]
pub enum LevelError {
    #[error(transparent)]
    Map(#[from] MapError),
    #[error("{path}: cannot compile: {error}")]
    Compile { path: String, error: CompileError },
    #[error("{path}: {message}")]
    Compiled { path: String, message: String },
    #[error("{path}: cannot write: {error}")]
    Write { path: String, error: std::io::Error },
    #[error(transparent)]
    Materials(#[from] MaterialError),
    #[error("{path}: refusing to overwrite the input map")]
    OverwriteInput { path: String },
}

/// A map ready to render: its geometry and BSP, its materials, and the
/// state play changes and the renderers draw (sector heights and light in
/// `compiled.map`, the tick, which things are there).
#[derive(Clone)]
pub struct Level {
    pub compiled: CompiledMap,
    pub materials: Materials,
    /// The sector each thing stands in (things do not move yet).
    pub thing_sectors: Vec<usize>,
    /// Whether each thing is drawn: a thing not on the game's skill, or
    /// picked up, is not. All are, until a game says otherwise.
    pub thing_shown: Vec<bool>,
    /// The things drawn this tick: the map's shown things until a game
    /// starts, then its actors as they stand ([`crate::play::Game`] writes it).
    pub things: Vec<DrawnThing>,
    /// Ticks since play began: scrolling walls are drawn scrolled by it.
    pub time: u64,
    /// Per sector, the lines with it on either side, in line order (Doom's
    /// `sector->lines`): the neighbour searches of the world's movers walk them.
    pub sector_lines: Vec<Vec<u32>>,
    /// Per sector, the bounding box of its lines (where its sounds come
    /// from: the middle; which actors a moving floor may carry).
    pub sector_boxes: Vec<crate::geom::Aabb>,
    /// What the ray-caster needs of a grid map.
    pub grid: Option<GridLevel>,
}

/// A thing as the renderers draw it.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct DrawnThing {
    /// Orders things at equal depth and names the thing in `ids` shading:
    /// the map thing's index, or an index past the map's things for what
    /// play spawned.
    pub key: usize,
    pub pos: glam::DVec2,
    /// The height its sprite's origin (the bottom middle) stands at.
    pub z: f64,
    /// The sector whose light it takes.
    pub sector: usize,
    /// Where it faces, degrees anticlockwise from east.
    pub angle: f64,
    /// The textures seen from Doom's eight directions (0: from in front).
    pub views: [crate::texture::TextureId; 8],
    /// Drawn at full brightness.
    pub bright: bool,
    /// Drawn as Doom's spectre is: not its texels, but the picture behind
    /// its shape, shifted a row up or down and darkened (textured shading
    /// only; `ids` and flat draw it solid, so the renderers stay comparable).
    pub fuzz: bool,
}

impl DrawnThing {
    /// Whether it looks different from different sides (a monster; an
    /// item looks the same from all eight).
    pub fn turns(&self) -> bool {
        self.views.iter().any(|&v| v != self.views[0])
    }

    /// The view an eye at `eye` sees (Doom's R_ProjectSprite): the
    /// direction from the eye to the thing against the way it faces, in
    /// eighths centred on the eight directions. An eye in front of it sees
    /// view 0. Both renderers ask this, so their sprites agree.
    pub fn texture_seen_from(&self, eye: glam::DVec2) -> crate::texture::TextureId {
        // Most things (every item) look the same from all sides: no angle.
        if !self.turns() {
            return self.views[0];
        }
        let d = self.pos - eye;
        let towards = d.y.atan2(d.x).to_degrees();
        let eighth = ((towards - self.angle + 180.0 + 22.5) / 45.0).floor();
        self.views[eighth.rem_euclid(8.0) as usize % 8]
    }
}

/// A grid map's faces and doors, for the ray-caster.
#[derive(Clone, Debug)]
pub struct GridLevel {
    pub faces: FaceLines,
    /// How far each door (in [`FaceLines::doors`] order) has slid open, 0..=1.
    pub open: Vec<f64>,
    /// The distance field sphere tracing needs, built on first use.
    pub field: std::sync::OnceLock<crate::render::rays::DistanceField>,
}

impl GridLevel {
    /// How far the door in cell `cell` has slid open, 0..=1 (0 for a cell with no door).
    pub fn open_share(&self, cell: usize) -> f64 {
        let door = self.faces.door_sectors[cell] as usize;
        self.open.get(door.wrapping_sub(1)).copied().unwrap_or(0.0).clamp(0.0, 1.0)
    }

    /// The faces of `grid` (as [`grid::compile`] numbers them), doors closed.
    pub fn new(grid: &Grid) -> GridLevel {
        let faces = grid::compile(grid).1;
        let open = vec![0.0; faces.doors.len()];
        GridLevel { faces, open, field: std::sync::OnceLock::new() }
    }
}

impl std::fmt::Debug for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Level")
            .field("name", &self.compiled.map.name)
            .field("stats", &self.compiled.stats)
            .field("textures", &self.materials.textures.len())
            .finish()
    }
}

/// A level is first of all its compiled map: `level.map`, `level.bsp`.
impl std::ops::Deref for Level {
    type Target = CompiledMap;

    fn deref(&self) -> &CompiledMap {
        &self.compiled
    }
}

impl Level {
    /// A level whose textures come from the built-in set only (tests, generated maps).
    pub fn with_builtin_textures(compiled: CompiledMap) -> Result<Level, MaterialError> {
        let materials = Materials::resolve(&compiled.map, &[], &compiled.map.name)?;
        Ok(Level::new(compiled, materials))
    }

    pub fn new(compiled: CompiledMap, materials: Materials) -> Level {
        let map = &compiled.map;
        let thing_sectors = map.things.iter().map(|t| compiled.sector_at(t.pos)).collect();
        let thing_shown = vec![true; map.things.len()];
        let mut sector_lines = vec![Vec::new(); map.sectors.len()];
        let mut boxes = vec![crate::geom::Aabb::EMPTY; map.sectors.len()];
        for (i, line) in map.lines.iter().enumerate() {
            let (a, b) = map.line_points(line);
            let mut sides = vec![line.front.sector];
            sides.extend(line.back.as_ref().map(|b| b.sector).filter(|&s| s != line.front.sector));
            for s in sides {
                sector_lines[s].push(i as u32);
                boxes[s].include(a);
                boxes[s].include(b);
            }
        }
        let grid = compiled.grid.as_ref().map(GridLevel::new);
        let mut level = Level {
            compiled,
            materials,
            thing_sectors,
            thing_shown,
            things: Vec::new(),
            time: 0,
            sector_lines,
            sector_boxes: boxes,
            grid,
        };
        level.draw_map_things();
        level
    }

    /// Draws the map's shown things as they stand in the map: their first
    /// frame, on their sector's floor (before a game moves them).
    pub fn draw_map_things(&mut self) {
        self.things = (0..self.compiled.map.things.len()).filter_map(|i| self.map_thing_drawn(i)).collect();
    }

    /// Map thing `i` drawn as it stands in the map, if it is shown and has
    /// a sprite: its first frame, on its sector's floor (or, hanging, from
    /// its ceiling, where play puts it).
    pub fn map_thing_drawn(&self, i: usize) -> Option<DrawnThing> {
        let texture = self.materials.sprites[i].filter(|_| self.thing_shown[i])?;
        let map = &self.compiled.map;
        let (t, sector) = (&map.things[i], self.thing_sectors[i]);
        use crate::actors::{ActorFlag, ActorTable};
        let actor = ActorTable::active().get(&t.kind).filter(|_| map.version >= 2);
        let s = &map.sectors[sector];
        // Where play puts it: hanging things hang from the ceiling.
        let z = match actor {
            Some(a) if a.has(ActorFlag::SpawnCeiling) => s.ceiling - a.height,
            _ => s.floor,
        };
        let fuzz = actor.is_some_and(|a| a.has(ActorFlag::Shadow));
        Some(DrawnThing { key: i, pos: t.pos, z, sector, angle: t.angle, views: [texture; 8], bright: false, fuzz })
    }

    /// Shows the things a single-player game at `skill` (1 to 5) has, by
    /// their skill and mode flags, and hides the rest.
    pub fn show_skill(&mut self, skill: u8) {
        for (shown, t) in self.thing_shown.iter_mut().zip(&self.compiled.map.things) {
            *shown = t.in_single_player(skill);
        }
        self.draw_map_things();
    }

    /// The grid and its ray-casting data, for a grid map.
    pub fn grid(&self) -> Option<(&Grid, &GridLevel)> {
        self.compiled.grid.as_ref().zip(self.grid.as_ref())
    }
}

/// Reads `path` and returns its level, compiling a source map with `options`;
/// textures are looked up in `textures/` and `sprites/` beside the map.
pub fn open_level(path: &Path, options: &BuildOptions) -> Result<Level, LevelError> {
    let compiled = open_compiled(path, options)?;
    let label = path.display().to_string();
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let materials = Materials::resolve(&compiled.map, &[dir], &label)?;
    Ok(Level::new(compiled, materials))
}

/// Reads `path` and returns the compiled map alone (no textures).
pub fn open_compiled(path: &Path, options: &BuildOptions) -> Result<CompiledMap, LevelError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| MapError::Io { path: label.clone(), error })?;
    level_from_bytes(&bytes, &label, options)
}

pub fn level_from_bytes(bytes: &[u8], label: &str, options: &BuildOptions) -> Result<CompiledMap, LevelError> {
    if file::is_compiled(bytes) {
        return file::from_bytes(bytes).map_err(|message| LevelError::Compiled { path: label.to_string(), message });
    }
    let (map, grid) = parse_any_map(bytes, label)?;
    let mut compiled = build(&map, options).map_err(|error| LevelError::Compile { path: label.to_string(), error })?;
    compiled.grid = grid;
    Ok(compiled)
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, then a
/// rename. A failure leaves any existing file at `path` untouched.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), LevelError> {
    write_file_atomic(path, bytes).map_err(|error| LevelError::Write { path: path.display().to_string(), error })
}

/// [`write_atomic`] with the I/O error as it is, for writers with errors of
/// their own (demos, saves, audio).
pub fn write_file_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().ok_or_else(|| std::io::Error::other("not a file name"))?;
    let tmp = dir.join(format!(".{}.tmp{}", name.to_string_lossy(), std::process::id()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Refuses an output path that names the same file as the input.
pub fn check_not_input(input: &Path, output: &Path) -> Result<(), LevelError> {
    let same = match (input.canonicalize(), output.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same {
        return Err(LevelError::OverwriteInput { path: output.display().to_string() });
    }
    Ok(())
}
