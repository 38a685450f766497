//! The parser proper: DECORATE's tokens (from `lex`) into the syntax tree of
//! `mod.rs`, the top level, actors and their `States` blocks.

use super::lex::{tokens, Kind, Token};
use super::{
    Action, Actor, ActorItem, At, Decorate, DecorateError, Duration, EnumEntry, Expr, Flow, Frame, FrameKeyword,
    Property, StateItem, TopLevel, Value,
};

/// Parses DECORATE text.
pub fn parse(text: &str) -> Result<Decorate, DecorateError> {
    let mut parser = Parser { tokens: tokens(text)?, pos: 0, actor: None };
    let mut items = Vec::new();
    while parser.peek().kind != Kind::Eof {
        items.push(parser.top_level()?);
    }
    Ok(Decorate { items })
}

/// Parses a DECORATE lump's bytes. Lumps are usually ASCII; any other byte
/// is read as a replacement character, which is an error outside a string
/// or comment.
pub fn parse_lump(bytes: &[u8]) -> Result<Decorate, DecorateError> {
    parse(&String::from_utf8_lossy(bytes))
}

struct Parser {
    tokens: Vec<Token>,
    pos: usize,
    /// The actor being read, its name and line, for the error at end of file.
    actor: Option<(String, usize)>,
}

/// Where an expression ends: at a line break too (a property's value), or
/// only at punctuation (a constant, an action's argument).
#[derive(Clone, Copy, PartialEq)]
enum Lines {
    End,
    Continue,
}

impl Parser {
    fn peek(&self) -> &Token {
        self.peek_at(0)
    }

    fn peek_at(&self, ahead: usize) -> &Token {
        // The list always ends with Eof, and `next` never moves past it.
        let last = self.tokens.len() - 1;
        &self.tokens[(self.pos + ahead).min(last)]
    }

    fn next(&mut self) -> Token {
        let token = self.peek().clone();
        if token.kind != Kind::Eof {
            self.pos += 1;
        }
        token
    }

    /// Whether the next token is on the line the previous one ended on.
    fn on_same_line(&self) -> bool {
        let next = self.peek();
        next.kind != Kind::Eof && self.pos > 0 && next.at.line == self.tokens[self.pos - 1].end_line
    }

    fn unexpected(&self, expected: &'static str) -> DecorateError {
        let found = self.peek();
        if found.kind == Kind::Eof {
            if let Some((name, opened)) = &self.actor {
                return DecorateError::UnclosedActor { at: found.at, name: name.clone(), opened: *opened };
            }
        }
        DecorateError::Unexpected { at: found.at, expected, found: found.describe() }
    }

    fn expect(&mut self, punct: &str, expected: &'static str) -> Result<Token, DecorateError> {
        if self.peek().is(punct) {
            Ok(self.next())
        } else {
            Err(self.unexpected(expected))
        }
    }

    fn word(&mut self, expected: &'static str) -> Result<Token, DecorateError> {
        if self.peek().kind == Kind::Word {
            Ok(self.next())
        } else {
            Err(self.unexpected(expected))
        }
    }

    /// `Name` or `Name.Sub.More`, the dots kept.
    fn dotted(&mut self, expected: &'static str) -> Result<(String, At), DecorateError> {
        let first = self.word(expected)?;
        let mut name = first.text;
        while self.peek().is(".") && self.peek_at(1).kind == Kind::Word {
            self.next();
            name.push('.');
            name.push_str(&self.next().text);
        }
        Ok((name, first.at))
    }

    fn top_level(&mut self) -> Result<TopLevel, DecorateError> {
        let token = self.peek().clone();
        if token.is("#") {
            self.next();
            if !self.peek().is_word("include") {
                return Err(self.unexpected("`include` after `#`"));
            }
            self.next();
            if self.peek().kind != Kind::Str {
                return Err(self.unexpected("a quoted file name after #include"));
            }
            return Ok(TopLevel::Include { path: self.next().text, at: token.at });
        }
        if token.is_word("const") {
            self.next();
            let ty = self.word("a type after `const`")?.text;
            let name = self.word("the constant's name")?.text;
            self.expect("=", "`=` after the constant's name")?;
            let value = self.expr(Lines::Continue, "the constant's value")?;
            self.expect(";", "`;` after the constant's value")?;
            return Ok(TopLevel::Const { ty, name, value, at: token.at });
        }
        if token.is_word("enum") {
            self.next();
            return self.enumeration(token.at);
        }
        if token.is_word("actor") {
            self.next();
            return Ok(TopLevel::Actor(self.actor(token.at)?));
        }
        Err(self.unexpected("`actor`, `const`, `enum` or `#include`"))
    }

    fn enumeration(&mut self, at: At) -> Result<TopLevel, DecorateError> {
        self.expect("{", "`{` after `enum`")?;
        let mut entries = Vec::new();
        while !self.peek().is("}") {
            let name = self.word("an enum entry's name or `}`")?.text;
            let value = if self.peek().is("=") {
                self.next();
                Some(self.expr(Lines::Continue, "the entry's value")?)
            } else {
                None
            };
            entries.push(EnumEntry { name, value });
            if !self.peek().is(",") {
                break;
            }
            self.next();
        }
        self.expect("}", "`,` or `}` in the enum")?;
        if self.peek().is(";") {
            self.next();
        }
        Ok(TopLevel::Enum { entries, at })
    }

    fn actor(&mut self, at: At) -> Result<Actor, DecorateError> {
        let name = self.word("the actor's name")?.text;
        let mut actor = Actor {
            name: name.clone(),
            parent: None,
            replaces: None,
            doomednum: None,
            native: false,
            body: vec![],
            at,
        };
        if self.peek().is(":") {
            self.next();
            actor.parent = Some(self.word("the parent's name after `:`")?.text);
        }
        if self.peek().is_word("replaces") {
            self.next();
            actor.replaces = Some(self.word("the name of the actor replaced")?.text);
        }
        if self.peek().kind == Kind::Int {
            let token = self.next();
            actor.doomednum = Some(int(&token)?);
        }
        if self.peek().is_word("native") {
            self.next();
            actor.native = true;
        }
        self.expect("{", "`{` after the actor's header")?;
        self.actor = Some((name, at.line));
        while !self.peek().is("}") {
            if let Some(item) = self.actor_item()? {
                actor.body.push(item);
            }
        }
        self.next();
        self.actor = None;
        Ok(actor)
    }

    /// One flag, property, `States` block or declaration; `None` for a stray `;`.
    fn actor_item(&mut self) -> Result<Option<ActorItem>, DecorateError> {
        let token = self.peek().clone();
        if token.is(";") {
            self.next();
            return Ok(None);
        }
        if token.is("+") || token.is("-") {
            self.next();
            let (name, _) = self.dotted("a flag's name after `+` or `-`")?;
            return Ok(Some(ActorItem::Flag { name, set: token.is("+"), at: token.at }));
        }
        if token.kind != Kind::Word {
            return Err(self.unexpected("a flag, a property, `States` or `}`"));
        }
        if token.is_word("states") && self.peek_at(1).is("{") {
            self.next();
            self.next();
            return Ok(Some(ActorItem::States(self.states()?)));
        }
        if ["var", "action", "const", "enum"].iter().any(|word| token.is_word(word)) {
            return Ok(Some(self.unknown()?));
        }
        let (name, at) = self.dotted("a property's name")?;
        let mut values = Vec::new();
        if self.on_same_line() && !self.peek().is(";") && !self.peek().is("}") {
            loop {
                values.push(value(self.expr(Lines::End, "a property's value")?));
                if !self.peek().is(",") {
                    break;
                }
                self.next();
            }
        }
        Ok(Some(ActorItem::Property(Property { name, values, at })))
    }

    /// A declaration up to its `;` (braces and all), kept as text.
    fn unknown(&mut self) -> Result<ActorItem, DecorateError> {
        let at = self.peek().at;
        let mut words = Vec::new();
        let mut depth = 0usize;
        loop {
            let token = self.peek();
            if token.kind == Kind::Eof {
                return Err(self.unexpected("`;`"));
            }
            if token.is("}") && depth == 0 {
                break;
            }
            let token = self.next();
            words.push(token.source());
            match token.text.as_str() {
                _ if token.kind != Kind::Punct => {}
                "{" => depth += 1,
                "}" => depth -= 1,
                ";" if depth == 0 => break,
                _ => {}
            }
        }
        Ok(ActorItem::Unknown { text: words.join(" "), at })
    }

    /// Tokens up to a `,`, `;`, `{`, `}` or unmatched `)`, parentheses
    /// nested; with `Lines::End`, also up to a line break outside them.
    fn expr(&mut self, lines: Lines, expected: &'static str) -> Result<Expr, DecorateError> {
        let mut tokens = Vec::new();
        let mut depth = 0usize;
        loop {
            let token = self.peek();
            let ends = token.kind == Kind::Eof
                || (depth == 0 && [",", ";", "{", "}", ")"].iter().any(|p| token.is(p)))
                || (depth == 0 && lines == Lines::End && !tokens.is_empty() && !self.on_same_line());
            if ends {
                if token.kind == Kind::Eof && depth > 0 {
                    return Err(self.unexpected("`)`"));
                }
                break;
            }
            if token.is("(") {
                depth += 1;
            } else if token.is(")") {
                depth -= 1;
            }
            tokens.push(self.next().source());
        }
        if tokens.is_empty() {
            return Err(self.unexpected(expected));
        }
        Ok(Expr { tokens })
    }

    /// `( expr, expr, ... )`, the `(` next.
    fn arguments(&mut self) -> Result<Vec<Expr>, DecorateError> {
        self.expect("(", "`(`")?;
        let mut args = Vec::new();
        if !self.peek().is(")") {
            loop {
                args.push(self.expr(Lines::Continue, "an argument")?);
                if !self.peek().is(",") {
                    break;
                }
                self.next();
            }
        }
        self.expect(")", "`,` or `)` after an argument")?;
        Ok(args)
    }

    fn states(&mut self) -> Result<Vec<StateItem>, DecorateError> {
        let mut items = Vec::new();
        loop {
            let token = self.peek().clone();
            if token.is("}") {
                self.next();
                return Ok(items);
            }
            if token.is(";") {
                self.next();
                continue;
            }
            let flow = [("loop", Flow::Loop), ("stop", Flow::Stop), ("wait", Flow::Wait), ("fail", Flow::Fail)];
            if let Some((_, flow)) = flow.into_iter().find(|(word, _)| token.is_word(word)) {
                self.next();
                items.push(StateItem::Flow { flow, at: token.at });
            } else if token.is_word("goto") {
                self.next();
                items.push(StateItem::Flow { flow: self.goto(token.at)?, at: token.at });
            } else if self.is_label() {
                let (name, at) = self.dotted("a label")?;
                self.next();
                items.push(StateItem::Label { name, at });
            } else if token.kind == Kind::Word || token.kind == Kind::Str {
                items.push(StateItem::Frame(self.frame()?));
            } else {
                return Err(self.unexpected("a label, a frame, a flow keyword or `}`"));
            }
        }
    }

    /// Whether a dotted name and `:` come next.
    fn is_label(&self) -> bool {
        let mut ahead = 0;
        while self.peek_at(ahead).kind == Kind::Word {
            if self.peek_at(ahead + 1).is(":") {
                return true;
            }
            if !self.peek_at(ahead + 1).is(".") {
                return false;
            }
            ahead += 2;
        }
        false
    }

    fn goto(&mut self, at: At) -> Result<Flow, DecorateError> {
        if self.peek().kind != Kind::Word {
            return Err(DecorateError::GotoWithoutLabel { at });
        }
        let mut scope = None;
        if self.peek_at(1).is("::") {
            scope = Some(self.next().text);
            self.next();
        }
        let (label, _) = self.dotted("a label after `::`")?;
        let mut offset = 0;
        if self.peek().is("+") {
            self.next();
            if self.peek().kind != Kind::Int {
                return Err(self.unexpected("a whole number after `+`"));
            }
            offset = int(&self.next())?;
        }
        Ok(Flow::Goto { scope, label, offset })
    }

    fn frame(&mut self) -> Result<Frame, DecorateError> {
        let sprite = self.next();
        let frames = self.peek().clone();
        if !matches!(frames.kind, Kind::Word | Kind::Str | Kind::Int) {
            return Err(self.unexpected("the frame letters after the sprite"));
        }
        self.next();
        let duration = self.duration()?;
        let mut frame = Frame {
            sprite: sprite.text,
            frames: frames.text,
            duration,
            keywords: vec![],
            offset: None,
            action: None,
            at: sprite.at,
        };
        let keywords = [
            ("bright", FrameKeyword::Bright),
            ("fast", FrameKeyword::Fast),
            ("slow", FrameKeyword::Slow),
            ("nodelay", FrameKeyword::NoDelay),
            ("canraise", FrameKeyword::CanRaise),
        ];
        while self.on_same_line() && self.peek().kind == Kind::Word {
            let token = self.peek().clone();
            if let Some((_, keyword)) = keywords.iter().find(|(word, _)| token.is_word(word)) {
                self.next();
                frame.keywords.push(*keyword);
            } else if token.is_word("offset") && self.peek_at(1).is("(") {
                self.next();
                let args = self.arguments()?;
                let [x, y] = <[Expr; 2]>::try_from(args).map_err(|_| DecorateError::Unexpected {
                    at: token.at,
                    expected: "two arguments to offset",
                    found: "another count".to_string(),
                })?;
                frame.offset = Some((x, y));
            } else {
                // The action ends the line: ZDoom reads nothing after it.
                self.next();
                let args = if self.peek().is("(") { self.arguments()? } else { vec![] };
                frame.action = Some(Action { name: token.text, args });
                break;
            }
        }
        Ok(frame)
    }

    fn duration(&mut self) -> Result<Duration, DecorateError> {
        let token = self.peek().clone();
        let bad = |found: &Token| DecorateError::BadDuration { at: found.at, found: found.describe() };
        if token.kind == Kind::Int {
            self.next();
            return Ok(Duration::Tics(int(&token)?));
        }
        if token.is("-") && self.peek_at(1).kind == Kind::Int {
            self.next();
            return Ok(Duration::Tics(-int(&self.next())?));
        }
        if token.is_word("random") && self.peek_at(1).is("(") {
            self.next();
            let args = self.arguments()?;
            return match <[Expr; 2]>::try_from(args) {
                Ok([min, max]) => Ok(Duration::Random(min, max)),
                Err(_) => Err(bad(&token)),
            };
        }
        Err(bad(&token))
    }
}

fn int(token: &Token) -> Result<i64, DecorateError> {
    let text = &token.text;
    let parsed = match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => i64::from_str_radix(hex, 16),
        None => text.parse(),
    };
    parsed.map_err(|_| DecorateError::BadNumber { at: token.at, text: text.clone() })
}

/// A property value: one token or a negated number is typed, anything else kept as tokens.
fn value(expr: Expr) -> Value {
    let number = |text: &str, sign: f64| {
        if let Ok(int) = text.parse::<i64>() {
            return Some(Value::Int(if sign < 0.0 { -int } else { int }));
        }
        text.parse::<f64>().ok().filter(|_| text.contains('.')).map(|float| Value::Float(sign * float))
    };
    let typed = match expr.tokens.as_slice() {
        [one] if one.starts_with('"') && one.len() >= 2 => Some(Value::Str(one[1..one.len() - 1].to_string())),
        [one] => number(one, 1.0).or_else(|| {
            one.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_').then(|| Value::Name(one.clone()))
        }),
        [minus, one] if minus == "-" => number(one, -1.0),
        _ => None,
    };
    typed.unwrap_or(Value::Expr(expr))
}
