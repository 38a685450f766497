//! DECORATE, ZDoom's text lump that defines actors: [`parse`] reads the text
//! into a syntax tree, [`Decorate`]; [`build::apply`] maps the trees onto the
//! actor table (its own states, flags and actions), listing what it leaves
//! out.
//!
//! What the parser reads, after the ZDoom wiki's DECORATE pages:
//! - `//` and `/* */` comments, keywords in any case;
//! - at the top level `#include "file"` (recorded, not followed),
//!   `const int NAME = expr;`, `enum { A, B = 2 };` and actors;
//! - `actor Name [: Parent] [replaces Other] [doomednum] [native] { ... }`
//!   holding flags (`+SHOOTABLE`, `-INVENTORY.ALWAYSPICKUP`), properties
//!   (`Inventory.Amount -25`, `Health.LowMessage 25, "$GOTMEDINEED"`, bare
//!   `Projectile`) and a `States { ... }` block of labels, frame lines and
//!   flow keywords (`loop`, `stop`, `wait`, `fail`, `goto Super::Missile+2`).
//!
//! Expressions (a constant's value, a property's computed value, an action's
//! arguments, `random(1, 5)` as a duration) are kept as their tokens'
//! text: what they mean depends on the property or action, which is the
//! actor table's business. Every error names the line and column where the
//! text went wrong; no input panics.
//!
//! The parser is token-based, as ZDoom's is, with one use of line breaks,
//! also ZDoom's: a property's values and a frame's keywords and action are
//! on the line that started them (after a comma a value may follow on the
//! next line), since nothing else ends them.

pub mod build;
#[cfg(test)]
mod build_tests;
mod lex;
mod parse;
#[cfg(test)]
mod parse_tests;

use std::fmt;

pub use build::{apply, Built, DecorateBuildError};
pub use parse::{parse, parse_lump};

pub use crate::text_cursor::At;

/// What can go wrong reading DECORATE text; each names where.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DecorateError {
    #[error("{at}: unterminated string")]
    UnterminatedString { at: At },
    #[error("{at}: unterminated /* comment")]
    UnterminatedComment { at: At },
    #[error("{at}: unexpected character {ch:?}")]
    BadCharacter { at: At, ch: char },
    #[error("{at}: {text} is not a number DECORATE can hold")]
    BadNumber { at: At, text: String },
    #[error("{at}: expected {expected}, found {found}")]
    Unexpected { at: At, expected: &'static str, found: String },
    #[error("{at}: a frame's duration must be a whole number or random(min, max), found {found}")]
    BadDuration { at: At, found: String },
    #[error("{at}: goto without a label")]
    GotoWithoutLabel { at: At },
    #[error("{at}: the text ends inside actor {name} (opened at line {opened})")]
    UnclosedActor { at: At, name: String, opened: usize },
}

/// A whole DECORATE lump, its top-level items in the order written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Decorate {
    pub items: Vec<TopLevel>,
}

impl Decorate {
    /// The actors, in the order written.
    pub fn actors(&self) -> impl Iterator<Item = &Actor> {
        self.items.iter().filter_map(|item| match item {
            TopLevel::Actor(actor) => Some(actor),
            _ => None,
        })
    }

    /// The actor of this name (names are case-insensitive, as in ZDoom).
    pub fn actor(&self, name: &str) -> Option<&Actor> {
        self.actors().find(|actor| actor.name.eq_ignore_ascii_case(name))
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum TopLevel {
    /// `#include "file"`: another lump to read, by name.
    Include {
        path: String,
        at: At,
    },
    /// `const int NAME = expr;` (`ty` is the type word as written).
    Const {
        ty: String,
        name: String,
        value: Expr,
        at: At,
    },
    /// `enum { A, B = 2 };`
    Enum {
        entries: Vec<EnumEntry>,
        at: At,
    },
    Actor(Actor),
}

#[derive(Clone, Debug, PartialEq)]
pub struct EnumEntry {
    pub name: String,
    pub value: Option<Expr>,
}

/// An expression kept as the text of its tokens; strings keep their quotes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expr {
    pub tokens: Vec<String>,
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(&self.tokens.join(" "))
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Actor {
    pub name: String,
    pub parent: Option<String>,
    pub replaces: Option<String>,
    pub doomednum: Option<i64>,
    pub native: bool,
    pub body: Vec<ActorItem>,
    /// Where the `actor` keyword is.
    pub at: At,
}

impl Actor {
    /// The property of this name, case-insensitive (the last one written wins, as in ZDoom).
    pub fn property(&self, name: &str) -> Option<&Property> {
        self.body.iter().rev().find_map(|item| match item {
            ActorItem::Property(property) if property.name.eq_ignore_ascii_case(name) => Some(property),
            _ => None,
        })
    }

    /// The items of the actor's `States` blocks, in order.
    pub fn states(&self) -> impl Iterator<Item = &StateItem> {
        self.body.iter().flat_map(|item| match item {
            ActorItem::States(states) => states.as_slice(),
            _ => &[],
        })
    }

    /// The frames that follow `label` up to the next label or flow keyword.
    pub fn frames_of(&self, label: &str) -> Vec<&Frame> {
        let mut items = self
            .states()
            .skip_while(|item| !matches!(item, StateItem::Label { name, .. } if name.eq_ignore_ascii_case(label)));
        items.next();
        items
            .map_while(|item| match item {
                StateItem::Frame(frame) => Some(frame),
                _ => None,
            })
            .collect()
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum ActorItem {
    /// `+NAME` (set) or `-NAME` (cleared); dotted names keep their dots.
    Flag {
        name: String,
        set: bool,
        at: At,
    },
    Property(Property),
    States(Vec<StateItem>),
    /// A declaration the syntax accepts but nothing reads yet (`var int user_x;`,
    /// `action native ...;`, `const ...;` inside an actor): its tokens' text.
    Unknown {
        text: String,
        at: At,
    },
}

/// `Name.Sub value, value`; a bare property (`Projectile`) has no values.
#[derive(Clone, Debug, PartialEq)]
pub struct Property {
    pub name: String,
    pub values: Vec<Value>,
    pub at: At,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Int(i64),
    Float(f64),
    Str(String),
    /// A bare word: a name, a class, a sound, ...
    Name(String),
    /// Anything longer, kept as tokens.
    Expr(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub enum StateItem {
    /// `Spawn:` or `Missile.Rocket:`.
    Label {
        name: String,
        at: At,
    },
    Frame(Frame),
    Flow {
        flow: Flow,
        at: At,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub enum Flow {
    Loop,
    Stop,
    Wait,
    Fail,
    /// `goto [Scope::]Label[+offset]`; `scope` is `Super` or a class name.
    Goto {
        scope: Option<String>,
        label: String,
        offset: i64,
    },
}

/// `SPRT ABCD 6 [Bright] [Fast] [Offset(x, y)] [A_Action(args)]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The sprite as written, quotes dropped (`"####"` keeps the previous one).
    pub sprite: String,
    /// One frame letter per state this line makes.
    pub frames: String,
    pub duration: Duration,
    pub keywords: Vec<FrameKeyword>,
    pub offset: Option<(Expr, Expr)>,
    pub action: Option<Action>,
    pub at: At,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Duration {
    Tics(i64),
    /// `random(min, max)`, its two arguments.
    Random(Expr, Expr),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameKeyword {
    Bright,
    Fast,
    Slow,
    NoDelay,
    CanRaise,
}

/// `A_Name` or `A_Name(arg, arg)`; each argument kept as tokens.
#[derive(Clone, Debug, PartialEq)]
pub struct Action {
    pub name: String,
    pub args: Vec<Expr>,
}
