//! DECORATE's tokens: words, numbers, strings and punctuation, each with where
//! it starts and the line it ends on (a frame line's action must be on the
//! line its duration is). Comments are dropped here.

use super::{At, DecorateError};

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
    bytes: &'a [u8],
    pos: usize,
    line: usize,
    line_start: usize,
}

impl Lexer<'_> {
    fn at(&self) -> At {
        At { line: self.line, column: self.pos - self.line_start + 1 }
    }

    fn peek(&self, ahead: usize) -> Option<u8> {
        self.bytes.get(self.pos + ahead).copied()
    }

    fn bump(&mut self) {
        if self.peek(0) == Some(b'\n') {
            self.line += 1;
            self.line_start = self.pos + 1;
        }
        self.pos += 1;
    }

    /// Skips blanks and comments; an unclosed `/*` is an error where it opened.
    fn skip_blanks(&mut self) -> Result<(), DecorateError> {
        loop {
            match (self.peek(0), self.peek(1)) {
                (Some(b), _) if b.is_ascii_whitespace() => self.bump(),
                (Some(b'/'), Some(b'/')) => {
                    while self.peek(0).is_some_and(|b| b != b'\n') {
                        self.bump();
                    }
                }
                (Some(b'/'), Some(b'*')) => {
                    let at = self.at();
                    self.pos += 2;
                    loop {
                        match (self.peek(0), self.peek(1)) {
                            (Some(b'*'), Some(b'/')) => {
                                self.pos += 2;
                                break;
                            }
                            (Some(_), _) => self.bump(),
                            (None, _) => return Err(DecorateError::UnterminatedComment { at }),
                        }
                    }
                }
                _ => return Ok(()),
            }
        }
    }

    fn string(&mut self, at: At) -> Result<Token, DecorateError> {
        self.pos += 1;
        let start = self.pos;
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
        let text = self.text[start..self.pos].to_string();
        self.pos += 1;
        Ok(Token { kind: Kind::Str, text, at, end_line: self.line })
    }

    /// A run of letters, digits and underscores, with a decimal fraction if
    /// it is all digits and a `.` and digit follow.
    fn word_or_number(&mut self, at: At) -> Result<Token, DecorateError> {
        let start = self.pos;
        let is_word_byte = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
        while self.peek(0).is_some_and(is_word_byte) {
            self.pos += 1;
        }
        let all_digits = self.bytes[start..self.pos].iter().all(u8::is_ascii_digit);
        // `.5` starts a number too.
        let fraction = (all_digits || start == self.pos)
            && self.peek(0) == Some(b'.')
            && self.peek(1).is_some_and(|b| b.is_ascii_digit());
        if fraction {
            self.pos += 1;
            while self.peek(0).is_some_and(|b| b.is_ascii_digit()) {
                self.pos += 1;
            }
        }
        let text = self.text[start..self.pos].to_string();
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
        Ok(Token { kind, text, at, end_line: self.line })
    }

    fn token(&mut self) -> Result<Token, DecorateError> {
        self.skip_blanks()?;
        let at = self.at();
        let Some(b) = self.peek(0) else {
            return Ok(Token { kind: Kind::Eof, text: String::new(), at, end_line: self.line });
        };
        if b == b'"' {
            return self.string(at);
        }
        let starts_number = b == b'.' && self.peek(1).is_some_and(|b| b.is_ascii_digit());
        if b.is_ascii_alphanumeric() || b == b'_' || starts_number {
            return self.word_or_number(at);
        }
        if !b.is_ascii_punctuation() {
            let ch = self.text[self.pos..].chars().next().unwrap_or('\u{fffd}');
            return Err(DecorateError::BadCharacter { at, ch });
        }
        let pair = self.text.get(self.pos..self.pos + 2).filter(|pair| PAIRS.contains(pair));
        let text = pair.map_or_else(|| char::from(b).to_string(), str::to_string);
        self.pos += text.len();
        Ok(Token { kind: Kind::Punct, text, at, end_line: self.line })
    }
}

/// The tokens of `text`, ending with one `Eof` token.
pub(super) fn tokens(text: &str) -> Result<Vec<Token>, DecorateError> {
    let mut lexer = Lexer { text, bytes: text.as_bytes(), pos: 0, line: 1, line_start: 0 };
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
