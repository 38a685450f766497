//! UDMF, the text map format of ZDoom and the ports after it: a map whose
//! marker is followed by a TEXTMAP lump (then port-specific lumps such as
//! ZNODES and BEHAVIOR, and ENDMAP). [`parse`] reads the text into typed
//! records, [`UdmfMap`], as the "Universal Doom Map Format Specification
//! v1.1" defines them, for the namespaces `doom` and `zdoom`.
//!
//! Two layers:
//! - the syntax: `name = value;` assignments at the top level and in
//!   `name { ... }` blocks; values are integers (decimal, octal with a
//!   leading 0, hex with 0x), floats, quoted strings and the keywords
//!   `true` and `false`; `//` and `/* */` comments; names case-insensitive.
//!   Every error says the line and column where the text went wrong.
//! - the fields: the standard ones of `vertex`, `linedef`, `sidedef`,
//!   `sector` and `thing`, typed and with the specification's defaults;
//!   the fields without a default (a vertex's `x`, a line's `v1`, ...) are
//!   required. Unknown blocks and fields are ignored, as the specification
//!   asks, and counted in [`UdmfMap::ignored`] so a tool can say what the
//!   map sets that Sightline does not read. Indices (a line's vertices and
//!   sides, a side's sector) are checked, so what follows may index freely.
//!
//! In the `doom` namespace a line's tag is its `arg0` (and `id` defaults to
//! 0), as the specification's conversion rule has it; in `zdoom` a line has
//! a Hexen-style special with five arguments and an `id` of its own.

use std::collections::BTreeMap;

pub use crate::text_cursor::At;
use crate::text_cursor::Cursor;

/// What is wrong with a TEXTMAP, and where.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{at}: {message}")]
pub struct UdmfError {
    pub at: At,
    pub message: String,
}

fn error<T>(at: At, message: impl Into<String>) -> Result<T, UdmfError> {
    Err(UdmfError { at, message: message.into() })
}

/// A field's value as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Int(i64),
    Float(f64),
    Str(String),
    Bool(bool),
}

impl Value {
    fn describe(&self) -> String {
        match self {
            Value::Int(i) => format!("the integer {i}"),
            Value::Float(x) => format!("the float {x}"),
            Value::Str(s) => format!("the string {s:?}"),
            Value::Bool(b) => format!("{b}"),
        }
    }
}

/// One `name = value;`, its name in lower case.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    pub name: String,
    pub value: Value,
    pub at: At,
}

/// One `kind { fields }` block, its kind in lower case.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    pub kind: String,
    pub at: At,
    pub fields: Vec<Field>,
}

/// The syntax of a whole TEXTMAP: its global assignments and its blocks, in
/// the order written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    pub globals: Vec<Field>,
    pub blocks: Vec<Block>,
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Name(String),
    Value(Value),
    Open,
    Close,
    Equals,
    Semicolon,
    End,
}

impl Token {
    fn describe(&self) -> String {
        match self {
            Token::Name(n) => format!("the name {n:?}"),
            Token::Value(v) => v.describe(),
            Token::Open => "'{'".into(),
            Token::Close => "'}'".into(),
            Token::Equals => "'='".into(),
            Token::Semicolon => "';'".into(),
            Token::End => "the end of the text".into(),
        }
    }
}

struct Lexer<'a> {
    text: Cursor<'a>,
}

impl<'a> Lexer<'a> {
    fn new(text: &'a [u8]) -> Self {
        Lexer { text: Cursor::new(text) }
    }

    /// The next token and where it starts.
    fn next(&mut self) -> Result<(Token, At), UdmfError> {
        self.text.skip_blanks().or_else(|at| error(at, "a /* comment is never closed"))?;
        let at = self.text.at();
        let Some(c) = self.text.peek(0) else { return Ok((Token::End, at)) };
        let token = match c {
            b'{' => Token::Open,
            b'}' => Token::Close,
            b'=' => Token::Equals,
            b';' => Token::Semicolon,
            b'"' => return Ok((Token::Value(Value::Str(self.string(at)?)), at)),
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let word = self.run(|c| c.is_ascii_alphanumeric() || c == b'_');
                let lower = word.to_ascii_lowercase();
                return Ok((
                    match lower.as_str() {
                        "true" => Token::Value(Value::Bool(true)),
                        "false" => Token::Value(Value::Bool(false)),
                        _ => Token::Name(lower),
                    },
                    at,
                ));
            }
            c if c.is_ascii_digit() || c == b'+' || c == b'-' || c == b'.' => {
                let word = self.run(|c| c.is_ascii_alphanumeric() || matches!(c, b'.' | b'+' | b'-'));
                return Ok((Token::Value(number(&word, at)?), at));
            }
            c => {
                let shown = if c.is_ascii_graphic() { format!("{:?}", c as char) } else { format!("byte 0x{c:02x}") };
                return error(at, format!("unexpected character {shown}"));
            }
        };
        self.text.bump();
        Ok((token, at))
    }

    /// The longest run of bytes from here that `keep`, as text.
    fn run(&mut self, keep: impl Fn(u8) -> bool) -> String {
        String::from_utf8_lossy(self.text.run(keep)).into_owned()
    }

    /// A quoted string from its opening quote; `\x` stands for `x`.
    fn string(&mut self, at: At) -> Result<String, UdmfError> {
        self.text.bump();
        let mut bytes = Vec::new();
        loop {
            match self.text.bump() {
                Some(b'"') => return Ok(String::from_utf8_lossy(&bytes).into_owned()),
                Some(b'\\') => match self.text.bump() {
                    Some(c) => bytes.push(c),
                    None => return error(at, "a string is never closed (no '\"' before the end)"),
                },
                Some(c) => bytes.push(c),
                None => return error(at, "a string is never closed (no '\"' before the end)"),
            }
        }
    }
}

/// An integer or float as the grammar spells them.
fn number(word: &str, at: At) -> Result<Value, UdmfError> {
    let bad = || error(at, format!("{word:?} is not a number"));
    let (negative, digits) = match word.as_bytes().first() {
        Some(b'-') => (true, &word[1..]),
        Some(b'+') => (false, &word[1..]),
        _ => (false, word),
    };
    let hex = digits.strip_prefix("0x").or_else(|| digits.strip_prefix("0X"));
    let is_float = hex.is_none() && digits.contains(['.', 'e', 'E']);
    if is_float {
        // [0-9]+ '.' [0-9]* ([eE] [+-]? [0-9]+)?, and a leading '.' as
        // editors write it (Rust's parse alone would also take "inf").
        let shaped = digits.bytes().next().is_some_and(|c| c.is_ascii_digit() || c == b'.');
        return match digits.parse::<f64>() {
            Ok(x) if shaped && x.is_finite() => Ok(Value::Float(if negative { -x } else { x })),
            Ok(_) if shaped => error(at, format!("{word} is too large for a float")),
            _ => bad(),
        };
    }
    let (radix, digits) = match hex {
        Some(h) => (16, h),
        None if digits.len() > 1 && digits.starts_with('0') => (8, &digits[1..]),
        None => (10, digits),
    };
    if digits.is_empty() || !digits.chars().all(|c| c.is_digit(radix)) {
        return bad();
    }
    match i64::from_str_radix(digits, radix) {
        Ok(i) if i <= i64::from(u32::MAX) => Ok(Value::Int(if negative { -i } else { i })),
        _ => error(at, format!("{word} is too large for an integer (UDMF integers are 32 bits)")),
    }
}

/// The syntax layer: TEXTMAP's text into assignments and blocks.
pub fn parse_document(text: &[u8]) -> Result<Document, UdmfError> {
    let mut lexer = Lexer::new(text);
    let mut document = Document::default();
    loop {
        let (token, at) = lexer.next()?;
        let name = match token {
            Token::End => return Ok(document),
            Token::Name(name) => name,
            other => return error(at, format!("expected a block or an assignment, found {}", other.describe())),
        };
        match lexer.next()? {
            (Token::Equals, _) => document.globals.push(assignment_value(&mut lexer, name, at)?),
            (Token::Open, _) => {
                let mut fields = Vec::new();
                loop {
                    match lexer.next()? {
                        (Token::Close, _) => break,
                        (Token::Name(field), field_at) => match lexer.next()? {
                            (Token::Equals, _) => fields.push(assignment_value(&mut lexer, field, field_at)?),
                            (other, at) => {
                                return error(at, format!("expected '=' after {field:?}, found {}", other.describe()))
                            }
                        },
                        (Token::End, end) => {
                            return error(end, format!("the {name} block opened at {at} is never closed (no '}}')"))
                        }
                        (other, at) => {
                            return error(
                                at,
                                format!("expected a field or '}}' in the {name} block, found {}", other.describe()),
                            )
                        }
                    }
                }
                document.blocks.push(Block { kind: name, at, fields });
            }
            (other, at) => {
                return error(at, format!("expected '=' or '{{' after {name:?}, found {}", other.describe()))
            }
        }
    }
}

/// The `value ;` after `name =`.
fn assignment_value(lexer: &mut Lexer, name: String, at: At) -> Result<Field, UdmfError> {
    let value = match lexer.next()? {
        (Token::Value(v), _) => v,
        (Token::Name(word), at) => {
            return error(at, format!("{name} = {word}: a value is a number, a quoted string, true or false"))
        }
        (other, at) => return error(at, format!("expected a value for {name:?}, found {}", other.describe())),
    };
    match lexer.next()? {
        (Token::Semicolon, _) => Ok(Field { name, value, at }),
        (other, at) => error(at, format!("expected ';' after {name}'s value, found {}", other.describe())),
    }
}

/// The namespaces this reader gives a meaning to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Namespace {
    /// Doom's own specials and thing types (and Boom's and MBF's).
    Doom,
    /// ZDoom's: Hexen-style specials with arguments, thing ids and specials.
    ZDoom,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct UdmfVertex {
    pub x: f64,
    pub y: f64,
}

/// A linedef's flags: the standard ones and ZDoom's activation (SPAC) flags.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LineFlags {
    pub blocking: bool,
    pub block_monsters: bool,
    pub two_sided: bool,
    pub upper_unpegged: bool,
    pub lower_unpegged: bool,
    pub secret: bool,
    pub block_sound: bool,
    pub dont_draw: bool,
    pub mapped: bool,
    pub pass_use: bool,
    pub player_cross: bool,
    pub player_use: bool,
    pub monster_cross: bool,
    pub monster_use: bool,
    pub impact: bool,
    pub player_push: bool,
    pub monster_push: bool,
    pub missile_cross: bool,
    pub repeat_special: bool,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct UdmfLine {
    /// The line's id (`-1`: none; in the `doom` namespace 0 and the tag).
    pub id: i64,
    pub v1: usize,
    pub v2: usize,
    pub front: usize,
    pub back: Option<usize>,
    pub flags: LineFlags,
    pub special: i64,
    /// The special's arguments; in the `doom` namespace `args[0]` is the tag.
    pub args: [i64; 5],
    pub at: At,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct UdmfSide {
    pub offset_x: i64,
    pub offset_y: i64,
    /// Texture names as written; `-` is none.
    pub top: String,
    pub bottom: String,
    pub middle: String,
    pub sector: usize,
    pub at: At,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct UdmfSector {
    pub floor: i64,
    pub ceiling: i64,
    pub floor_texture: String,
    pub ceiling_texture: String,
    pub light: i64,
    pub special: i64,
    /// The sector's tag.
    pub id: i64,
}

/// Which games a thing is in: by skill (1-5, Doom's numbering) and by mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ThingFlags {
    pub skills: [bool; 5],
    pub ambush: bool,
    pub single: bool,
    pub deathmatch: bool,
    pub coop: bool,
    pub friend: bool,
    pub dormant: bool,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct UdmfThing {
    pub id: i64,
    pub x: f64,
    pub y: f64,
    /// Above the floor (below the ceiling for things that hang).
    pub height: f64,
    /// Degrees, counter-clockwise from east.
    pub angle: i64,
    pub kind: i64,
    pub flags: ThingFlags,
    pub special: i64,
    pub args: [i64; 5],
    pub at: At,
}

/// A UDMF map's records, in the order written (the indices lines and
/// sides refer to), all references checked.
#[derive(Clone, Debug, PartialEq)]
pub struct UdmfMap {
    pub namespace: Namespace,
    pub vertices: Vec<UdmfVertex>,
    pub lines: Vec<UdmfLine>,
    pub sides: Vec<UdmfSide>,
    pub sectors: Vec<UdmfSector>,
    pub things: Vec<UdmfThing>,
    /// Fields and blocks the map sets that this reader does not read
    /// (`linedef.alpha`, `block:udmfextension`), with how often.
    pub ignored: BTreeMap<String, usize>,
}

/// Fields that mean nothing to Doom's rules and are not worth reporting:
/// comments, Hexen's player classes and the skills past Doom's five.
fn is_inert(kind: &str, name: &str) -> bool {
    let number = |prefix: &str| name.strip_prefix(prefix).and_then(|n| n.parse::<u32>().ok());
    name == "comment" || (kind == "thing" && (number("class").is_some() || number("skill").is_some_and(|k| k >= 6)))
}

/// Reads a TEXTMAP: the syntax, then the records.
pub fn parse(text: &[u8]) -> Result<UdmfMap, UdmfError> {
    let document = parse_document(text)?;
    let namespace = match document.globals.iter().find(|g| g.name == "namespace") {
        None => return error(At { line: 1, column: 1 }, "no namespace: a TEXTMAP starts with namespace = \"...\";"),
        Some(Field { value: Value::Str(s), at, .. }) => match s.to_ascii_lowercase().as_str() {
            "doom" => Namespace::Doom,
            "zdoom" => Namespace::ZDoom,
            other => {
                return error(
                    *at,
                    format!(
                        "namespace {other:?} is not supported (Sightline reads the \"doom\" and \"zdoom\" namespaces)"
                    ),
                )
            }
        },
        Some(Field { value, at, .. }) => return error(*at, format!("namespace is {}, not a string", value.describe())),
    };
    let mut map = UdmfMap {
        namespace,
        vertices: Vec::new(),
        lines: Vec::new(),
        sides: Vec::new(),
        sectors: Vec::new(),
        things: Vec::new(),
        ignored: BTreeMap::new(),
    };
    for g in document.globals.iter().filter(|g| g.name != "namespace") {
        *map.ignored.entry(format!("global:{}", g.name)).or_default() += 1;
    }
    for block in &document.blocks {
        let index = match block.kind.as_str() {
            "vertex" => map.vertices.len(),
            "linedef" => map.lines.len(),
            "sidedef" => map.sides.len(),
            "sector" => map.sectors.len(),
            _ => map.things.len(),
        };
        let mut fields = Fields { block, index, read: Vec::new() };
        match block.kind.as_str() {
            "vertex" => map.vertices.push(UdmfVertex { x: fields.float("x")?, y: fields.float("y")? }),
            "linedef" => map.lines.push(fields.line(namespace)?),
            "sidedef" => map.sides.push(fields.side()?),
            "sector" => map.sectors.push(fields.sector()?),
            "thing" => map.things.push(fields.thing()?),
            other => {
                *map.ignored.entry(format!("block:{other}")).or_default() += 1;
                continue;
            }
        }
        for name in fields.unread() {
            *map.ignored.entry(format!("{}.{name}", block.kind)).or_default() += 1;
        }
    }
    check_references(&map)?;
    Ok(map)
}

/// The fields of one block, read by name: the last assignment of a name
/// counts; the names read are remembered, so the rest can be reported.
struct Fields<'a> {
    block: &'a Block,
    /// The block's index among the blocks of its kind, for errors.
    index: usize,
    read: Vec<&'static str>,
}

impl<'a> Fields<'a> {
    fn what(&self) -> String {
        format!("{} {} (the block at {})", self.block.kind, self.index, self.block.at)
    }

    fn get(&mut self, name: &'static str) -> Option<&'a Field> {
        self.read.push(name);
        self.block.fields.iter().rev().find(|f| f.name == name)
    }

    fn missing<T>(&self, name: &str) -> Result<T, UdmfError> {
        error(self.block.at, format!("{} has no {name}, which has no default", self.what()))
    }

    fn wrong<T>(&self, field: &Field, wanted: &str) -> Result<T, UdmfError> {
        error(field.at, format!("{}: {} is {}, not {wanted}", self.what(), field.name, field.value.describe()))
    }

    /// A float field (an integer will do).
    fn float(&mut self, name: &'static str) -> Result<f64, UdmfError> {
        match self.get(name) {
            None => self.missing(name),
            Some(f) => match f.value {
                Value::Float(x) => Ok(x),
                Value::Int(i) => Ok(i as f64),
                _ => self.wrong(f, "a number"),
            },
        }
    }

    fn float_or(&mut self, name: &'static str, default: f64) -> Result<f64, UdmfError> {
        if self.block.fields.iter().any(|f| f.name == name) {
            self.float(name)
        } else {
            self.read.push(name);
            Ok(default)
        }
    }

    /// An integer field (a float with no fraction will do: editors write
    /// `heightfloor = 0.000;`).
    fn int_or(&mut self, name: &'static str, default: Option<i64>) -> Result<i64, UdmfError> {
        match (self.get(name), default) {
            (None, Some(d)) => Ok(d),
            (None, None) => self.missing(name),
            (Some(f), _) => match f.value {
                Value::Int(i) => Ok(i),
                Value::Float(x) if x.fract() == 0.0 && x.abs() <= f64::from(u32::MAX) => Ok(x as i64),
                _ => self.wrong(f, "a whole number"),
            },
        }
    }

    fn int(&mut self, name: &'static str) -> Result<i64, UdmfError> {
        self.int_or(name, None)
    }

    /// An index field: a whole number from 0 (or -1 for none, when `optional`).
    fn index(&mut self, name: &'static str, optional: bool) -> Result<Option<usize>, UdmfError> {
        let value = self.int_or(name, optional.then_some(-1))?;
        match value {
            -1 if optional => Ok(None),
            v if v >= 0 => Ok(Some(v as usize)),
            v => {
                let at = self.block.fields.iter().rev().find(|f| f.name == name).map_or(self.block.at, |f| f.at);
                error(at, format!("{}: {name} = {v} is not an index", self.what()))
            }
        }
    }

    fn string_or(&mut self, name: &'static str, default: Option<&str>) -> Result<String, UdmfError> {
        match (self.get(name), default) {
            (None, Some(d)) => Ok(d.to_string()),
            (None, None) => self.missing(name),
            (Some(f), _) => match &f.value {
                Value::Str(s) => Ok(s.clone()),
                _ => self.wrong(f, "a string"),
            },
        }
    }

    fn flag(&mut self, name: &'static str) -> Result<bool, UdmfError> {
        match self.get(name) {
            None => Ok(false),
            Some(f) => match f.value {
                Value::Bool(b) => Ok(b),
                _ => self.wrong(f, "true or false"),
            },
        }
    }

    fn args(&mut self) -> Result<[i64; 5], UdmfError> {
        Ok([
            self.int_or("arg0", Some(0))?,
            self.int_or("arg1", Some(0))?,
            self.int_or("arg2", Some(0))?,
            self.int_or("arg3", Some(0))?,
            self.int_or("arg4", Some(0))?,
        ])
    }

    fn line(&mut self, namespace: Namespace) -> Result<UdmfLine, UdmfError> {
        let flags = LineFlags {
            blocking: self.flag("blocking")?,
            block_monsters: self.flag("blockmonsters")?,
            two_sided: self.flag("twosided")?,
            upper_unpegged: self.flag("dontpegtop")?,
            lower_unpegged: self.flag("dontpegbottom")?,
            secret: self.flag("secret")?,
            block_sound: self.flag("blocksound")?,
            dont_draw: self.flag("dontdraw")?,
            mapped: self.flag("mapped")?,
            pass_use: self.flag("passuse")?,
            player_cross: self.flag("playercross")?,
            player_use: self.flag("playeruse")?,
            monster_cross: self.flag("monstercross")?,
            monster_use: self.flag("monsteruse")?,
            impact: self.flag("impact")?,
            player_push: self.flag("playerpush")?,
            monster_push: self.flag("monsterpush")?,
            missile_cross: self.flag("missilecross")?,
            repeat_special: self.flag("repeatspecial")?,
        };
        let default_id = if namespace == Namespace::Doom { 0 } else { -1 };
        Ok(UdmfLine {
            id: self.int_or("id", Some(default_id))?,
            v1: self.index("v1", false)?.unwrap_or_default(),
            v2: self.index("v2", false)?.unwrap_or_default(),
            front: self.index("sidefront", false)?.unwrap_or_default(),
            back: self.index("sideback", true)?,
            flags,
            special: self.int_or("special", Some(0))?,
            args: self.args()?,
            at: self.block.at,
        })
    }

    fn side(&mut self) -> Result<UdmfSide, UdmfError> {
        Ok(UdmfSide {
            offset_x: self.int_or("offsetx", Some(0))?,
            offset_y: self.int_or("offsety", Some(0))?,
            top: self.string_or("texturetop", Some("-"))?,
            bottom: self.string_or("texturebottom", Some("-"))?,
            middle: self.string_or("texturemiddle", Some("-"))?,
            sector: self.index("sector", false)?.unwrap_or_default(),
            at: self.block.at,
        })
    }

    fn sector(&mut self) -> Result<UdmfSector, UdmfError> {
        Ok(UdmfSector {
            floor: self.int_or("heightfloor", Some(0))?,
            ceiling: self.int_or("heightceiling", Some(0))?,
            floor_texture: self.string_or("texturefloor", None)?,
            ceiling_texture: self.string_or("textureceiling", None)?,
            light: self.int_or("lightlevel", Some(160))?,
            special: self.int_or("special", Some(0))?,
            id: self.int_or("id", Some(0))?,
        })
    }

    fn thing(&mut self) -> Result<UdmfThing, UdmfError> {
        let flags = ThingFlags {
            skills: [
                self.flag("skill1")?,
                self.flag("skill2")?,
                self.flag("skill3")?,
                self.flag("skill4")?,
                self.flag("skill5")?,
            ],
            ambush: self.flag("ambush")?,
            single: self.flag("single")?,
            deathmatch: self.flag("dm")?,
            coop: self.flag("coop")?,
            friend: self.flag("friend")?,
            dormant: self.flag("dormant")?,
        };
        Ok(UdmfThing {
            id: self.int_or("id", Some(0))?,
            x: self.float("x")?,
            y: self.float("y")?,
            height: self.float_or("height", 0.0)?,
            angle: self.int_or("angle", Some(0))?,
            kind: self.int("type")?,
            flags,
            special: self.int_or("special", Some(0))?,
            args: self.args()?,
            at: self.block.at,
        })
    }

    /// The names the block sets that were never read (each once).
    fn unread(&self) -> Vec<&'a str> {
        let mut names: Vec<&str> = self
            .block
            .fields
            .iter()
            .map(|f| f.name.as_str())
            .filter(|n| !self.read.contains(n) && !is_inert(&self.block.kind, n))
            .collect();
        names.sort_unstable();
        names.dedup();
        names
    }
}

/// Every line's vertices and sides, and every side's sector, exist.
fn check_references(map: &UdmfMap) -> Result<(), UdmfError> {
    let out_of = |what: &str, count: usize| format!("names no {what} (the map has {count})");
    for (i, line) in map.lines.iter().enumerate() {
        for (name, v) in [("v1", line.v1), ("v2", line.v2)] {
            if v >= map.vertices.len() {
                return error(line.at, format!("linedef {i}: {name} = {v} {}", out_of("vertex", map.vertices.len())));
            }
        }
        for (name, s) in [("sidefront", Some(line.front)), ("sideback", line.back)] {
            if let Some(s) = s.filter(|&s| s >= map.sides.len()) {
                return error(line.at, format!("linedef {i}: {name} = {s} {}", out_of("sidedef", map.sides.len())));
            }
        }
    }
    for (i, side) in map.sides.iter().enumerate() {
        if side.sector >= map.sectors.len() {
            return error(
                side.at,
                format!("sidedef {i}: sector = {} {}", side.sector, out_of("sector", map.sectors.len())),
            );
        }
    }
    Ok(())
}

/// The lump that holds a UDMF map's text, right after its marker.
pub const TEXTMAP: &str = "TEXTMAP";

impl super::Wad {
    /// Whether map `name` is a UDMF map (its marker followed by TEXTMAP).
    pub fn is_udmf(&self, name: &str) -> bool {
        let upper = name.to_ascii_uppercase();
        self.lumps.windows(2).rev().find(|w| w[0].name == upper).is_some_and(|w| w[1].name == TEXTMAP)
    }

    /// Reads UDMF map `name` (any case): its TEXTMAP, parsed and checked.
    /// Errors name the file, the map's TEXTMAP and the line and column.
    pub fn udmf(&self, name: &str) -> Result<UdmfMap, super::WadError> {
        let upper = name.to_ascii_uppercase();
        let label = format!("{upper}/{TEXTMAP}");
        let Some(marker) = self.lumps.iter().rposition(|l| l.name == upper) else {
            return Err(super::WadError::NoMap {
                path: self.path.clone(),
                name: name.to_string(),
                available: self.map_names().join(" "),
            });
        };
        if self.lumps.get(marker + 1).is_none_or(|l| l.name != TEXTMAP) {
            return Err(self.error(&label, "not a UDMF map: no TEXTMAP right after the map's marker"));
        }
        parse(self.bytes(marker + 1)).map_err(|e| self.error(&label, e.to_string()))
    }
}
