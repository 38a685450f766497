//! A patch's bytes as lines, read the way Chocolate Doom's deh_io.c reads
//! them: CR LF is one LF (a lone CR stays), NUL bytes are dropped from
//! lines, and lines are counted from 1 for errors. In BEX's `[STRINGS]`
//! ("extended" lines) `\n` is a line break in the text, a `\` at the end of
//! a line continues the value on the next (its indentation skipped), and
//! a `\` before any other character is dropped. A `Text` block is read as
//! raw characters instead, newlines included, since its header counts
//! them.

pub struct Reader<'a> {
    bytes: &'a [u8],
    pos: usize,
    /// The line the next character is on.
    line: usize,
}

impl<'a> Reader<'a> {
    pub fn new(bytes: &'a [u8]) -> Reader<'a> {
        // A UTF-8 byte-order mark would spoil the signature line.
        let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        Reader { bytes, pos: 0, line: 1 }
    }

    /// The next character, with CR LF as LF; `None` at the end.
    pub fn char(&mut self) -> Option<u8> {
        let c = *self.bytes.get(self.pos)?;
        self.pos += 1;
        let c = if c == b'\r' && self.bytes.get(self.pos) == Some(&b'\n') {
            self.pos += 1;
            b'\n'
        } else {
            c
        };
        if c == b'\n' {
            self.line += 1;
        }
        Some(c)
    }

    /// The next line without its newline, and the line number it starts
    /// on; `None` at the end of the file.
    pub fn next_line(&mut self, extended: bool) -> Option<(usize, Vec<u8>)> {
        if self.pos >= self.bytes.len() {
            return None;
        }
        let start = self.line;
        let mut out = Vec::new();
        let mut continued = false;
        while let Some(mut c) = self.char() {
            if extended && c == b'\\' {
                match self.char() {
                    Some(b'n') => {
                        out.push(b'\n');
                        continue;
                    }
                    Some(b'\n') => {
                        continued = true;
                        continue;
                    }
                    Some(other) => c = other,
                    None => break,
                }
            }
            // Blanks before the backslash belong to the text; the next
            // line's indentation does not.
            if continued && c != b'\n' && c.is_ascii_whitespace() {
                continue;
            }
            continued = false;
            match c {
                b'\n' => break,
                0 => {}
                c => out.push(c),
            }
        }
        Some((start, out))
    }

    /// `n` raw characters (a `Text` block's), or how many there were
    /// before the file ended.
    pub fn raw(&mut self, n: usize) -> Result<Vec<u8>, usize> {
        let mut out = Vec::with_capacity(n.min(self.bytes.len()));
        while out.len() < n {
            match self.char() {
                Some(c) => out.push(c),
                None => return Err(out.len()),
            }
        }
        Ok(out)
    }
}

/// Text from a patch: UTF-8 when it is valid UTF-8, else each byte as the
/// character of that code point (Latin-1), so nothing is lost; doom.exe's
/// own strings are ASCII.
pub fn decode(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_string(),
        Err(_) => bytes.iter().map(|&b| char::from(b)).collect(),
    }
}
