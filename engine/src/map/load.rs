//! Reading a map file: bytes -> text -> [`MapSource`] -> validated [`Map`], with
//! every failure an error value naming the file and, where there is one, the RON
//! position or the map element.

use std::fmt;
use std::path::Path;

use glam::DVec2;

use super::source::MapSource;
use super::{validate, Map};

/// Why a map file could not be turned into a [`Map`].
#[derive(Debug, thiserror::Error)]
pub enum MapError {
    #[error("{path}: cannot read: {error}")]
    Io { path: String, error: std::io::Error },
    #[error("{path}: the file is empty")]
    Empty { path: String },
    #[error("{path}: not a text map: byte {offset} is binary data")]
    Binary { path: String, offset: usize },
    #[error("{path}:{line}:{col}: {message}")]
    Syntax { path: String, line: usize, col: usize, message: String },
    #[error("{path}: {}", list_problems(problems))]
    Invalid { path: String, problems: Vec<Problem> },
    #[error("{path}: {}", list_problems(problems))]
    InvalidGrid { path: String, problems: Vec<crate::grid::GridProblem> },
}

impl MapError {
    /// The validation problems, if that is what went wrong.
    pub fn problems(&self) -> &[Problem] {
        match self {
            MapError::Invalid { problems, .. } => problems,
            _ => &[],
        }
    }
}

fn list_problems<P: fmt::Display>(problems: &[P]) -> String {
    const SHOWN: usize = 12;
    let mut text = match problems.len() {
        1 => String::new(),
        n => format!("{n} problems:"),
    };
    for p in problems.iter().take(SHOWN) {
        if problems.len() > 1 {
            text.push_str("\n  ");
        }
        text.push_str(&p.to_string());
    }
    if problems.len() > SHOWN {
        text.push_str(&format!("\n  ... and {} more", problems.len() - SHOWN));
    }
    text
}

/// The line that carries a special: one of the map's lines, or one of its
/// trigger lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpecialAt {
    Line(usize),
    TriggerLine(usize),
}

impl fmt::Display for SpecialAt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpecialAt::Line(i) => write!(f, "line {i}"),
            SpecialAt::TriggerLine(i) => write!(f, "trigger line {i}"),
        }
    }
}

/// One thing wrong with a map, naming the element it concerns.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    Missing {
        what: &'static str,
    },
    BadVertex {
        vertex: usize,
        x: f64,
        y: f64,
    },
    SharedPosition {
        vertex: usize,
        first: usize,
    },
    BadHeight {
        sector: usize,
        which: &'static str,
        value: f64,
    },
    FloorAboveCeiling {
        sector: usize,
        floor: f64,
        ceiling: f64,
    },
    BadLight {
        sector: usize,
        light: i64,
    },
    /// A sector's tag or a trigger's tag outside 0..=65535.
    BadTag {
        element: String,
        tag: i64,
    },
    DanglingVertex {
        line: usize,
        end: &'static str,
        vertex: i64,
        count: usize,
    },
    DanglingSector {
        line: usize,
        side: &'static str,
        sector: i64,
        count: usize,
    },
    BadOffset {
        line: usize,
        side: &'static str,
    },
    OneSidedDoor {
        line: usize,
    },
    ZeroLength {
        line: usize,
    },
    DuplicateLine {
        line: usize,
        first: usize,
    },
    Crossing {
        line: usize,
        other: usize,
        at: DVec2,
    },
    Touching {
        line: usize,
        other: usize,
        at: DVec2,
    },
    Overlap {
        line: usize,
        other: usize,
    },
    Unclosed {
        sector: usize,
        vertex: usize,
        into: usize,
        out_of: usize,
    },
    InsideOut {
        sector: usize,
    },
    SideMismatch {
        line: usize,
        side: &'static str,
        expected: Option<usize>,
        found: Vec<usize>,
    },
    NoLines {
        sector: usize,
    },
    BadThing {
        thing: usize,
    },
    NoPlayerStart,
    BadFog {
        distance: f64,
    },
    StartOutside {
        thing: usize,
        x: f64,
        y: f64,
    },
    /// A special's or a sector's parameter out of range: `element` names
    /// it ("line 4 lift special", "sector 2").
    BadSpecial {
        element: String,
        message: String,
    },
    BadVersion {
        version: i64,
    },
    /// A special acts on a tag no sector has.
    TagMatchesNothing {
        at: SpecialAt,
        action: &'static str,
        tag: u16,
    },
    /// A special with no tag acts on the sector behind its line; this line has none.
    NoBackSector {
        at: SpecialAt,
        action: &'static str,
    },
    /// A door locked with a key no thing in the map gives.
    MissingKey {
        at: SpecialAt,
        colour: &'static str,
    },
    /// A teleporter whose tagged sectors hold no teleport destination.
    NoTeleportDestination {
        at: SpecialAt,
        tag: u16,
    },
    /// A line teleporter whose exit is not another two-sided line.
    BadTeleportLine {
        at: SpecialAt,
        to: usize,
    },
    /// A version-2 thing kind that is not in the actor table.
    UnknownThing {
        thing: usize,
        kind: String,
        nearest: Option<String>,
    },
}

/// Numbers print with `{:?}`, which is exact and short (`1e300`, not 301 digits).
impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let max = crate::geom::MAX_COORD;
        match self {
            Problem::Missing { what } => write!(f, "the map has no {what}"),
            Problem::BadVertex { vertex, x, y } => write!(
                f,
                "vertex {vertex}: ({x:?}, {y:?}) is not a finite coordinate within the supported range -{max}..={max}"
            ),
            Problem::SharedPosition { vertex, first } => {
                write!(f, "vertex {vertex}: same position as vertex {first}; use one vertex")
            }
            Problem::BadHeight { sector, which, value } => write!(
                f,
                "sector {sector}: {which} height {value:?} is not finite within the supported range -{max}..={max}"
            ),
            Problem::FloorAboveCeiling { sector, floor, ceiling } => {
                write!(f, "sector {sector}: floor {floor:?} is above ceiling {ceiling:?}")
            }
            Problem::BadLight { sector, light } => {
                write!(f, "sector {sector}: light {light} is outside 0..=255")
            }
            Problem::BadTag { element, tag } => write!(f, "{element}: tag {tag} is outside 0..=65535"),
            Problem::DanglingVertex { line, end, vertex, count } => {
                write!(f, "line {line}: `{end}` refers to vertex {vertex}, but the vertices are numbered 0..{count}")
            }
            Problem::DanglingSector { line, side, sector, count } => {
                write!(f, "line {line}: {side} side refers to sector {sector}, but the sectors are numbered 0..{count}")
            }
            Problem::BadOffset { line, side } => {
                write!(f, "line {line}: {side} side has a texture offset that is not finite")
            }
            Problem::OneSidedDoor { line } => {
                write!(f, "line {line}: a door must be two-sided (its back sector is the door that opens)")
            }
            Problem::ZeroLength { line } => write!(f, "line {line}: has zero length"),
            Problem::DuplicateLine { line, first } => {
                write!(f, "line {line}: duplicates line {first} (same two end points)")
            }
            Problem::Crossing { line, other, at } => {
                write!(f, "line {line}: crosses line {other} at ({:?}, {:?})", at.x, at.y)
            }
            Problem::Touching { line, other, at } => write!(
                f,
                "line {line}: meets line {other} at ({:?}, {:?}), inside one of them; split the line there",
                at.x, at.y
            ),
            Problem::Overlap { line, other } => write!(f, "line {line}: overlaps line {other}"),
            Problem::Unclosed { sector, vertex, into, out_of } => write!(
                f,
                "sector {sector}: its lines do not close at vertex {vertex} \
                 ({into} of its boundary edges arrive there, {out_of} leave; they must match)"
            ),
            Problem::InsideOut { sector } => {
                write!(f, "sector {sector}: its sides face away from it (the front of a line is its right-hand side)")
            }
            Problem::SideMismatch { line, side, expected, found } => {
                let name = |s: &[usize]| match s {
                    [] => "no sector".to_string(),
                    [one] => format!("sector {one}"),
                    many => format!("sectors {many:?} at once"),
                };
                write!(
                    f,
                    "line {line}: just off its {side} side lies {}, but the line says {}; \
                     check the winding of its loop (rooms clockwise, holes counter-clockwise) \
                     and its sector numbers",
                    name(found),
                    match expected {
                        Some(s) => format!("sector {s}"),
                        None => "nothing (a solid one-sided wall)".to_string(),
                    }
                )
            }
            Problem::NoLines { sector } => write!(f, "sector {sector}: no line side refers to it"),
            Problem::BadThing { thing } => {
                write!(f, "thing {thing}: position or angle is not finite or out of range")
            }
            Problem::BadFog { distance } => {
                write!(f, "fog: distance {distance:?} must be a finite number above 0")
            }
            Problem::NoPlayerStart => {
                write!(f, "the map has no thing of kind \"{}\"", super::PLAYER_START)
            }
            Problem::StartOutside { thing, x, y } => {
                write!(
                    f,
                    "thing {thing}: the player start ({x:?}, {y:?}) is not inside any sector \
                     (in a hole, outside the map, or on a one-sided wall)"
                )
            }
            Problem::BadSpecial { element, message } => write!(f, "{element}: {message}"),
            Problem::BadVersion { version } => write!(
                f,
                "version {version}: this build reads map format versions 1 and 2 (version 2 names things by type)"
            ),
            Problem::TagMatchesNothing { at, action, tag } => {
                write!(f, "{at} {action} special: acts on sectors tagged {tag}, but no sector has tag {tag}")
            }
            Problem::NoBackSector { at, action } => write!(
                f,
                "{at} {action} special: with no tag it acts on the sector behind the line, but the line has no \
                 back side; give it a tag or a back side"
            ),
            Problem::MissingKey { at, colour } => write!(
                f,
                "{at} door special: the door needs the {colour} key, but no thing in the map is a {colour} card or skull"
            ),
            Problem::NoTeleportDestination { at, tag } => write!(
                f,
                "{at} teleporter special: teleports to a destination in a sector tagged {tag}, \
                 but none of those sectors holds a \"teleport_destination\" thing"
            ),
            Problem::BadTeleportLine { at, to } => write!(
                f,
                "{at} teleporter special: teleports to line {to}, which must be another two-sided line of the map"
            ),
            Problem::UnknownThing { thing, kind, nearest } => {
                write!(f, "thing {thing}: no thing type is named {kind:?}")?;
                match nearest {
                    Some(n) => write!(f, "; did you mean {n:?}?"),
                    None => write!(f, " (the actors are listed in engine/data/actors.ron)"),
                }
            }
        }
    }
}

/// Reads, parses and validates a map file (a grid map reads as the sector map it compiles to).
pub fn load_map(path: &Path) -> Result<Map, MapError> {
    let label = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|error| MapError::Io { path: label.clone(), error })?;
    parse_map_bytes(&bytes, &label)
}

/// Parses and validates map text; `label` names the source in errors.
pub fn parse_map(text: &str, label: &str) -> Result<Map, MapError> {
    parse_map_bytes(text.as_bytes(), label)
}

/// A grid map reads as the sector map it compiles to (see [`crate::grid`]).
pub(crate) fn parse_map_bytes(bytes: &[u8], label: &str) -> Result<Map, MapError> {
    parse_any_map(bytes, label).map(|(map, _)| map)
}

/// Parses and validates either kind of map text: a sector map, or a grid map
/// with the sector map it compiles to.
pub(crate) fn parse_any_map(bytes: &[u8], label: &str) -> Result<(Map, Option<crate::grid::Grid>), MapError> {
    let text = as_text(bytes, label)?;
    let invalid = |problems| MapError::Invalid { path: label.to_string(), problems };
    if crate::grid::is_grid_source(text) {
        let grid = crate::grid::parse_grid(text, label)?;
        let map = validate::validate(&crate::grid::compile(&grid).0).map_err(invalid)?;
        return Ok((map, Some(grid)));
    }
    let source = parse_source(bytes, label)?;
    Ok((validate::validate(&source).map_err(invalid)?, None))
}

/// Checks that `bytes` are non-empty text and returns them as `&str`.
pub(crate) fn as_text<'a>(bytes: &'a [u8], label: &str) -> Result<&'a str, MapError> {
    if let Some(offset) = bytes.iter().position(|&b| b == 0) {
        return Err(MapError::Binary { path: label.to_string(), offset });
    }
    let text = std::str::from_utf8(bytes)
        .map_err(|e| MapError::Binary { path: label.to_string(), offset: e.valid_up_to() })?;
    // Editors on Windows may start UTF-8 files with a byte-order mark.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.trim().is_empty() {
        return Err(MapError::Empty { path: label.to_string() });
    }
    Ok(text)
}

/// Parses the RON source form without validating it.
pub fn parse_source(bytes: &[u8], label: &str) -> Result<MapSource, MapError> {
    let text = as_text(bytes, label)?;
    // IMPLICIT_SOME lets optional fields be written bare (`middle: "BRICK"`)
    // while `back: Some(Side(...))` keeps working.
    let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    options.from_str::<MapSource>(text).map_err(|e| MapError::Syntax {
        path: label.to_string(),
        line: e.span.start.line,
        col: e.span.start.col,
        message: e.code.to_string(),
    })
}
