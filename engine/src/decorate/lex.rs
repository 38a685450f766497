//! DECORATE's tokens: words, numbers, strings and punctuation, each with where
//! it starts and the line it ends on (a frame line's action must be on the
//! line its duration is). Comments are dropped here.

use super::{At, DecorateError};
use crate::text_cursor::Cursor;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// A name or keyword; also a word that starts with a digit but holds
    /// letters, such as a sprite `2BAL`.
    Word,
    Int,
    Float,
    /// A quoted string; `text` is the contents without quotes, escapes as written.
    Str,
    Punct,
    Eof,
}

#[derive(Clone, Debug, PartialEq)]
pub(super) struct Token {
    pub kind: Kind,
    pub text: String,
    pub at: At,
    pub end_line: usize,
}

impl Token {
    pub fn is(&self, punct: &str) -> bool {
        self.kind == Kind::Punct && self.text == punct
    }

    pub fn is_word(&self, word: &str) -> bool {
        self.kind == Kind::Word && self.text.eq_ignore_ascii_case(word)
    }

    /// How the token reads in an error message.
    pub fn describe(&self) -> String {
        match self.kind {
            Kind::Eof => "end of file".to_string(),
            Kind::Str => format!("string \"{}\"", self.text),
            _ => format!("`{}`", self.text),
        }
    }

    /// The token as it reads in an expression: strings keep their quotes.
    pub fn source(&self) -> String {
        match self.kind {
            Kind::Str => format!("\"{}\"", self.text),
            _ => self.text.clone(),
        }
    }
}

/// Two-character operators; anything else punctuation is one character.
const PAIRS: [&str; 9] = ["::", "==", "!=", "<=", ">=", "&&", "||", "<<", ">>"];

struct Lexer<'a> {
    text: &'a str,
    cur: Cursor<'a>,
}

impl Lexer<'_> {
    fn at(&self) -> At {
        self.cur.at()
    }

    fn peek(&self, ahead: usize) -> Option<u8> {
        self.cur.peek(ahead)
    }

    fn bump(&mut self) {
        self.cur.bump();
    }

    /// Skips blanks and comments; an unclosed `/*` is an error where it opened.
    fn skip_blanks(&mut self) -> Result<(), DecorateError> {
        self.cur.skip_blanks().map_err(|at| DecorateError::UnterminatedComment { at })
    }

    fn string(&mut self, at: At) -> Result<Token, DecorateError> {
        self.cur.pos += 1;
        let start = self.cur.pos;
        loop {
            match self.peek(0) {
                None => return Err(DecorateError::UnterminatedString { at }),
                Some(b'"') => break,
                Some(b'\\') if self.peek(1).is_some() => {
                    self.bump();
                    self.bump();
                }
                Some(_) => self.bump(),
            }
        }
        // Both ends are ASCII quotes, so the slice falls on character boundaries.
        let text = self.text[start..self.cur.pos].to_string();
        self.cur.pos += 1;
        Ok(Token { kind: Kind::Str, text, at, end_line: self.cur.line() })
    }

    /// A run of letters, digits and underscores, with a decimal fraction if
    /// it is all digits and a `.` and digit follow.
    fn word_or_number(&mut self, at: At) -> Result<Token, DecorateError> {
        let start = self.cur.pos;
        let is_word_byte = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
        while self.peek(0).is_some_and(is_word_byte) {
            self.cur.pos += 1;
        }
        let all_digits = self.cur.bytes[start..self.cur.pos].iter().all(u8::is_ascii_digit);
        // `.5` starts a number too.
        let fraction = (all_digits || start == self.cur.pos)
            && self.peek(0) == Some(b'.')
            && self.peek(1).is_some_and(|b| b.is_ascii_digit());
        if fraction {
            self.cur.pos += 1;
            while self.peek(0).is_some_and(|b| b.is_ascii_digit()) {
                self.cur.pos += 1;
            }
        }
        let text = self.text[start..self.cur.pos].to_string();
        let starts_with_digit = text.starts_with(|c: char| c.is_ascii_digit() || c == '.');
        let kind = if fraction {
            text.parse::<f64>().map_err(|_| DecorateError::BadNumber { at, text: text.clone() })?;
            Kind::Float
        } else if all_digits {
            text.parse::<i64>().map_err(|_| DecorateError::BadNumber { at, text: text.clone() })?;
            Kind::Int
        } else if starts_with_digit && (text.starts_with("0x") || text.starts_with("0X")) {
            i64::from_str_radix(&text[2..], 16).map_err(|_| DecorateError::BadNumber { at, text: text.clone() })?;
            Kind::Int
        } else {
            Kind::Word
        };
        Ok(Token { kind, text, at, end_line: self.cur.line() })
    }

    fn token(&mut self) -> Result<Token, DecorateError> {
        self.skip_blanks()?;
        let at = self.at();
        let Some(b) = self.peek(0) else {
            return Ok(Token { kind: Kind::Eof, text: String::new(), at, end_line: self.cur.line() });
        };
        if b == b'"' {
            return self.string(at);
        }
        let starts_number = b == b'.' && self.peek(1).is_some_and(|b| b.is_ascii_digit());
        if b.is_ascii_alphanumeric() || b == b'_' || starts_number {
            return self.word_or_number(at);
        }
        if !b.is_ascii_punctuation() {
            let ch = self.text[self.cur.pos..].chars().next().unwrap_or('\u{fffd}');
            return Err(DecorateError::BadCharacter { at, ch });
        }
        let pair = self.text.get(self.cur.pos..self.cur.pos + 2).filter(|pair| PAIRS.contains(pair));
        let text = pair.map_or_else(|| char::from(b).to_string(), str::to_string);
        self.cur.pos += text.len();
        Ok(Token { kind: Kind::Punct, text, at, end_line: self.cur.line() })
    }
}

/// The tokens of `text`, ending with one `Eof` token.
pub(super) fn tokens(text: &str) -> Result<Vec<Token>, DecorateError> {
    let mut lexer = Lexer { text, cur: Cursor::new(text.as_bytes()) };
    let mut tokens = Vec::new();
    loop {
        let token = lexer.token()?;
        let end = token.kind == Kind::Eof;
        tokens.push(token);
        if end {
            return Ok(tokens);
        }
    }
}
