//! A small assembler for tests: writes BEHAVIOR lumps (ACSe or ACSE, behind
//! acc's ACS0 header or bare, or Hexen's ACS0) from pcodes and operands, with
//! labels for jumps, so each pcode can be tested without a compiler.

use std::collections::HashMap;

use super::pcodes as p;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// ACSe behind an ACS0 header, as acc writes it (the fixtures' layout).
    Compact,
    /// ACSE behind an ACS0 header.
    Enhanced,
    /// An ACSE lump with no ACS0 header (12-byte SPTR entries).
    BareEnhanced,
    /// Hexen's format.
    Old,
}

pub struct Asm {
    pub layout: Layout,
    code: Vec<u8>,
    labels: HashMap<String, usize>,
    fixups: Vec<(usize, String)>,
    /// (number, type, argument count, label)
    scripts: Vec<(i16, u8, u8, String)>,
    names: Vec<String>,
    /// (args, locals, returns, label)
    functions: Vec<(u8, u8, bool, String)>,
    strings: Vec<String>,
    pub chunks: Vec<([u8; 4], Vec<u8>)>,
}

impl Asm {
    pub fn new(layout: Layout) -> Asm {
        Asm {
            layout,
            code: vec![0; 8],
            labels: HashMap::new(),
            fixups: Vec::new(),
            scripts: Vec::new(),
            names: Vec::new(),
            functions: Vec::new(),
            strings: Vec::new(),
            chunks: Vec::new(),
        }
    }

    fn compact(&self) -> bool {
        self.layout == Layout::Compact
    }

    pub fn label(&mut self, name: &str) -> &mut Asm {
        self.labels.insert(name.to_string(), self.code.len());
        self
    }

    /// The byte offset of a label already placed.
    pub fn label_offset(&self, name: &str) -> i32 {
        self.labels[name] as i32
    }

    /// Starts a numbered script here.
    pub fn script(&mut self, number: i16, kind: u8, args: u8) -> &mut Asm {
        let label = format!("script {number}");
        self.scripts.push((number, kind, args, label.clone()));
        self.label(&label)
    }

    /// Starts a named script here (numbered -1, -2, ... in SNAM order).
    pub fn named_script(&mut self, name: &str, kind: u8, args: u8) -> &mut Asm {
        self.names.push(name.to_string());
        let number = -(self.names.len() as i16);
        self.script(number, kind, args)
    }

    /// Starts function `index` (returned) here.
    pub fn function(&mut self, args: u8, locals: u8, returns: bool) -> usize {
        let label = format!("function {}", self.functions.len());
        self.functions.push((args, locals, returns, label.clone()));
        self.label(&label);
        self.functions.len() - 1
    }

    pub fn string(&mut self, s: &str) -> i32 {
        self.strings.push(s.to_string());
        self.strings.len() as i32 - 1
    }

    pub fn op(&mut self, pcode: u16) -> &mut Asm {
        if self.compact() {
            if pcode >= 240 {
                self.code.push((240 + (pcode - 240) / 256) as u8);
                self.code.push(((pcode - 240) % 256) as u8);
            } else {
                self.code.push(pcode as u8);
            }
        } else {
            self.word(i32::from(pcode));
        }
        self
    }

    pub fn word(&mut self, v: i32) -> &mut Asm {
        self.code.extend_from_slice(&v.to_le_bytes());
        self
    }

    pub fn byte(&mut self, v: u8) -> &mut Asm {
        self.code.push(v);
        self
    }

    /// An index operand: a byte in ACSe, a word otherwise.
    pub fn index(&mut self, v: i32) -> &mut Asm {
        if self.compact() {
            self.byte(v as u8)
        } else {
            self.word(v)
        }
    }

    /// A jump target operand, filled in at `build`.
    pub fn to(&mut self, label: &str) -> &mut Asm {
        self.fixups.push((self.code.len(), label.to_string()));
        self.word(0)
    }

    pub fn align(&mut self) -> &mut Asm {
        while !self.code.len().is_multiple_of(4) {
            self.code.push(0);
        }
        self
    }

    pub fn push(&mut self, v: i32) -> &mut Asm {
        self.op(p::PUSHNUMBER).word(v)
    }

    /// A pcode with one index operand.
    pub fn op_i(&mut self, pcode: u16, v: i32) -> &mut Asm {
        self.op(pcode).index(v)
    }

    pub fn jump(&mut self, pcode: u16, label: &str) -> &mut Asm {
        self.op(pcode).to(label)
    }

    /// `CALLFUNC` with `argc` arguments (a two-byte id in ACSe).
    pub fn callfunc(&mut self, argc: i32, id: i16) -> &mut Asm {
        self.op(p::CALLFUNC).index(argc);
        if self.compact() {
            self.code.extend_from_slice(&id.to_le_bytes());
            self
        } else {
            self.word(i32::from(id))
        }
    }

    fn resolve(&mut self) {
        for (at, label) in &self.fixups {
            let target = self.labels[label] as i32;
            self.code[*at..*at + 4].copy_from_slice(&target.to_le_bytes());
        }
    }

    fn address(&self, label: &str) -> u32 {
        self.labels[label] as u32
    }

    pub fn build(&mut self) -> Vec<u8> {
        self.resolve();
        if self.layout == Layout::Old {
            return self.build_old();
        }
        let wrapped = self.layout != Layout::BareEnhanced;
        let mut chunks: Vec<([u8; 4], Vec<u8>)> = Vec::new();
        let mut sptr = Vec::new();
        for (number, kind, args, label) in &self.scripts {
            sptr.extend_from_slice(&number.to_le_bytes());
            if wrapped {
                sptr.extend_from_slice(&[*kind, *args]);
                sptr.extend_from_slice(&self.address(label).to_le_bytes());
            } else {
                sptr.extend_from_slice(&u16::from(*kind).to_le_bytes());
                sptr.extend_from_slice(&self.address(label).to_le_bytes());
                sptr.extend_from_slice(&u32::from(*args).to_le_bytes());
            }
        }
        if !self.scripts.is_empty() {
            chunks.push((*b"SPTR", sptr));
        }
        if !self.names.is_empty() {
            chunks.push((*b"SNAM", name_table(&self.names)));
        }
        if !self.functions.is_empty() {
            let mut func = Vec::new();
            for (args, locals, returns, label) in &self.functions {
                func.extend_from_slice(&[*args, *locals, u8::from(*returns), 0]);
                func.extend_from_slice(&self.address(label).to_le_bytes());
            }
            chunks.push((*b"FUNC", func));
        }
        if !self.strings.is_empty() {
            chunks.push((*b"STRL", strl(&self.strings)));
        }
        chunks.extend(self.chunks.iter().cloned());

        let mut out = self.code.clone();
        out[0..4].copy_from_slice(if wrapped {
            b"ACS\0"
        } else if self.compact() {
            b"ACSe"
        } else {
            b"ACSE"
        });
        while !out.len().is_multiple_of(4) {
            out.push(0);
        }
        let chunks_at = out.len() as u32;
        for (id, data) in &chunks {
            out.extend_from_slice(id);
            out.extend_from_slice(&(data.len() as u32).to_le_bytes());
            out.extend_from_slice(data);
        }
        if wrapped {
            out.extend_from_slice(&chunks_at.to_le_bytes());
            out.extend_from_slice(if self.compact() { b"ACSe" } else { b"ACSE" });
            let dir = out.len() as u32;
            out[4..8].copy_from_slice(&dir.to_le_bytes());
            // The old-format directory acc leaves for Hexen: no scripts, no strings.
            out.extend_from_slice(&[0; 8]);
        } else {
            out[4..8].copy_from_slice(&chunks_at.to_le_bytes());
        }
        out
    }

    fn build_old(&self) -> Vec<u8> {
        let mut out = self.code.clone();
        out[0..4].copy_from_slice(b"ACS\0");
        let mut offsets = Vec::new();
        for s in &self.strings {
            offsets.push(out.len() as u32);
            out.extend_from_slice(s.as_bytes());
            out.push(0);
        }
        while !out.len().is_multiple_of(4) {
            out.push(0);
        }
        let dir = out.len() as u32;
        out[4..8].copy_from_slice(&dir.to_le_bytes());
        out.extend_from_slice(&(self.scripts.len() as u32).to_le_bytes());
        for (number, kind, args, label) in &self.scripts {
            let n = u32::from(*kind) * 1000 + *number as u32;
            out.extend_from_slice(&n.to_le_bytes());
            out.extend_from_slice(&self.address(label).to_le_bytes());
            out.extend_from_slice(&u32::from(*args).to_le_bytes());
        }
        out.extend_from_slice(&(offsets.len() as u32).to_le_bytes());
        for o in offsets {
            out.extend_from_slice(&o.to_le_bytes());
        }
        out
    }
}

/// A count, offsets relative to the data, NUL-terminated names (FNAM, SNAM, MEXP).
pub fn name_table(names: &[String]) -> Vec<u8> {
    let mut out = (names.len() as u32).to_le_bytes().to_vec();
    let mut at = 4 + 4 * names.len();
    let mut text = Vec::new();
    for n in names {
        out.extend_from_slice(&(at as u32).to_le_bytes());
        text.extend_from_slice(n.as_bytes());
        text.push(0);
        at += n.len() + 1;
    }
    out.extend(text);
    out
}

/// STRL: padding, count, padding, offsets relative to the data, strings.
pub fn strl(strings: &[String]) -> Vec<u8> {
    let mut out = vec![0; 4];
    out.extend_from_slice(&(strings.len() as u32).to_le_bytes());
    out.extend_from_slice(&[0; 4]);
    let mut at = 12 + 4 * strings.len();
    let mut text = Vec::new();
    for s in strings {
        out.extend_from_slice(&(at as u32).to_le_bytes());
        text.extend_from_slice(s.as_bytes());
        text.push(0);
        at += s.len() + 1;
    }
    out.extend(text);
    out
}

/// Four-byte little-endian values, for chunk bodies.
pub fn words(values: &[i32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
