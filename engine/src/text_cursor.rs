//! What the lexers of the text formats share (UDMF's TEXTMAP, DECORATE): a
//! place in the text for errors, and a cursor over the bytes that keeps the
//! line and column and skips blanks and C comments.

use std::fmt;

/// A place in the text: 1-based line and column (columns count bytes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct At {
    pub line: usize,
    pub column: usize,
}

impl fmt::Display for At {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "line {}, column {}", self.line, self.column)
    }
}

/// A position in some bytes. `pos` may be moved on directly past bytes
/// that are not line breaks; [`Cursor::bump`] keeps the line count.
pub struct Cursor<'a> {
    pub bytes: &'a [u8],
    pub pos: usize,
    line: usize,
    line_start: usize,
}

impl<'a> Cursor<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Cursor { bytes, pos: 0, line: 1, line_start: 0 }
    }

    pub fn at(&self) -> At {
        At { line: self.line, column: self.pos - self.line_start + 1 }
    }

    pub fn line(&self) -> usize {
        self.line
    }

    pub fn peek(&self, ahead: usize) -> Option<u8> {
        self.bytes.get(self.pos + ahead).copied()
    }

    /// The byte here, stepping past it.
    pub fn bump(&mut self) -> Option<u8> {
        let b = self.peek(0)?;
        if b == b'\n' {
            self.line += 1;
            self.line_start = self.pos + 1;
        }
        self.pos += 1;
        Some(b)
    }

    /// The longest run of bytes from here that `keep`.
    pub fn run(&mut self, keep: impl Fn(u8) -> bool) -> &'a [u8] {
        let start = self.pos;
        while self.peek(0).is_some_and(&keep) {
            self.bump();
        }
        &self.bytes[start..self.pos]
    }

    /// Skips whitespace and `//` and `/* */` comments; a `/*` never closed
    /// is an error at the place it opened.
    pub fn skip_blanks(&mut self) -> Result<(), At> {
        loop {
            match (self.peek(0), self.peek(1)) {
                (Some(b), _) if b.is_ascii_whitespace() => {
                    self.bump();
                }
                (Some(b'/'), Some(b'/')) => {
                    self.run(|b| b != b'\n');
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
                            (Some(_), _) => {
                                self.bump();
                            }
                            (None, _) => return Err(at),
                        }
                    }
                }
                _ => return Ok(()),
            }
        }
    }
}
