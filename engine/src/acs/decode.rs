//! Decodes a module's code once, at load: starting from every script,
//! function and GOTOSTACK entry it follows the flow (fall-through, jumps,
//! case tables) and turns each reachable instruction into an [`Insn`] with
//! its operands read and its jump targets resolved to instruction indices.
//! Anything the VM could not run (an unknown or unsupported pcode, a jump
//! out of the code, a variable index past its table, a call to a function
//! that does not exist) is an error here, so the VM never meets it.
//!
//! Following the flow rather than sweeping the bytes matters for Hexen's
//! format, whose strings sit between the code and the directory.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use super::load::{Format, Module, Problem, MAP_VARS};
use super::pcodes::{self, Operands, Store};
use super::vm::{GLOBAL_VARS, WORLD_VARS};

/// One decoded instruction.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Insn {
    /// Byte offset in the lump, for messages.
    pub offset: u32,
    pub pcode: u16,
    /// The operands in stream order. Jump targets (GOTO, IFGOTO, IFNOTGOTO,
    /// CASEGOTO's second, CASEGOTOSORTED's every second) are instruction
    /// indices, not byte offsets.
    pub args: Vec<i32>,
    /// Index of the instruction that follows, `usize::MAX` after one that
    /// never falls through.
    pub next: usize,
}

/// A module's decoded code.
#[derive(Clone, Debug, Default)]
pub struct Code {
    pub insns: Vec<Insn>,
    by_offset: HashMap<u32, usize>,
    /// Every pcode the code uses.
    pub used: BTreeSet<u16>,
    /// Every extended function called (PCD_CALLFUNC), with its first call's offset.
    pub functions: BTreeMap<u16, u32>,
}

impl Code {
    /// The instruction at a byte offset, if decoding reached it.
    pub fn at(&self, offset: u32) -> Option<usize> {
        self.by_offset.get(&offset).copied()
    }
}

/// A cursor over the code bytes, bounded by the end of the code.
struct Reader<'a> {
    b: &'a [u8],
    end: usize,
    pos: usize,
    start: usize,
    name: &'static str,
}

impl Reader<'_> {
    fn truncated(&self) -> Problem {
        Problem::Truncated { name: self.name, offset: self.start, end: self.end }
    }

    fn byte(&mut self) -> Result<i32, Problem> {
        if self.pos >= self.end {
            return Err(self.truncated());
        }
        self.pos += 1;
        Ok(i32::from(self.b[self.pos - 1]))
    }

    fn word(&mut self) -> Result<i32, Problem> {
        if self.pos + 4 > self.end {
            return Err(self.truncated());
        }
        let s = &self.b[self.pos..self.pos + 4];
        self.pos += 4;
        Ok(i32::from_le_bytes([s[0], s[1], s[2], s[3]]))
    }

    fn short(&mut self) -> Result<i32, Problem> {
        let lo = self.byte()?;
        let hi = self.byte()?;
        Ok(i32::from(((hi << 8) | lo) as u16 as i16))
    }
}

/// Decodes everything reachable in `b[..end]` from `module`'s entry points.
pub fn decode(b: &[u8], end: usize, module: &Module) -> Result<Code, Problem> {
    let end = end.min(b.len());
    let mut todo: Vec<u32> = Vec::new();
    let entries = module
        .scripts
        .iter()
        .map(|s| (s.address, script_label(s.number, s.name.as_deref())))
        .chain(module.functions.iter().enumerate().map(|(i, f)| (f.address, function_label(i, f.name.as_deref()))))
        .chain(module.jumps.iter().enumerate().map(|(i, &j)| (j, format!("jump target {i}"))));
    for (address, owner) in entries {
        if address as usize >= end {
            return Err(Problem::BadEntry { owner, offset: address, end });
        }
        todo.push(address);
    }

    let compact = module.format == Format::LittleEnhanced;
    let mut found: BTreeMap<u32, (Insn, u32)> = BTreeMap::new();
    let mut code = Code::default();
    while let Some(at) = todo.pop() {
        if found.contains_key(&at) {
            continue;
        }
        let (insn, next, targets) = decode_one(b, at as usize, end, compact)?;
        check(&insn, module)?;
        code.used.insert(insn.pcode);
        if insn.pcode == pcodes::CALLFUNC {
            code.functions.entry(insn.args[1] as u16).or_insert(at);
        }
        for &t in &targets {
            if t < 0 || t as usize >= end {
                return Err(Problem::BadJump {
                    name: pcodes::name(insn.pcode),
                    offset: at as usize,
                    target: i64::from(t),
                });
            }
            todo.push(t as u32);
        }
        if falls_through(insn.pcode) {
            todo.push(next);
        }
        found.insert(at, (insn, next));
    }

    code.by_offset = found.keys().enumerate().map(|(i, &o)| (o, i)).collect();
    for (_, (mut insn, next)) in found {
        // Every fall-through and target was decoded above, so each lookup
        // succeeds; a miss would leave an index the VM reports, not a panic.
        let index = |o: u32| code.by_offset.get(&o).copied().unwrap_or(usize::MAX);
        insn.next = if falls_through(insn.pcode) { index(next) } else { usize::MAX };
        for i in jump_slots(&insn) {
            insn.args[i] = index(insn.args[i] as u32) as i32;
        }
        code.insns.push(insn);
    }
    Ok(code)
}

pub fn script_label(number: i32, name: Option<&str>) -> String {
    match name {
        Some(n) => format!("script \"{n}\""),
        None => format!("script {number}"),
    }
}

fn function_label(index: usize, name: Option<&str>) -> String {
    match name {
        Some(n) => format!("function {n}"),
        None => format!("function {index}"),
    }
}

fn falls_through(pcode: u16) -> bool {
    !matches!(
        pcode,
        pcodes::TERMINATE | pcodes::RESTART | pcodes::GOTO | pcodes::RETURNVOID | pcodes::RETURNVAL | pcodes::GOTOSTACK
    )
}

/// Which operands are jump targets.
fn jump_slots(insn: &Insn) -> Vec<usize> {
    match pcodes::operands(insn.pcode) {
        Operands::Jump => vec![0],
        Operands::CaseGoto => vec![1],
        Operands::SortedCases => (1..insn.args.len()).step_by(2).collect(),
        _ => Vec::new(),
    }
}

/// Reads one instruction at `at`; returns it, the offset after it and its jump targets.
fn decode_one(b: &[u8], at: usize, end: usize, compact: bool) -> Result<(Insn, u32, Vec<i32>), Problem> {
    let mut r = Reader { b, end, pos: at, start: at, name: "a pcode" };
    let pcode = if compact {
        let first = r.byte()?;
        if first >= 240 {
            240 + ((first - 240) << 8) + r.byte()?
        } else {
            first
        }
    } else {
        r.word()?
    };
    if !(0..i32::from(pcodes::COUNT)).contains(&pcode) {
        return Err(Problem::UnknownPcode { pcode: pcode as u32, offset: at });
    }
    let pcode = pcode as u16;
    r.name = pcodes::name(pcode);
    if !pcodes::supported(pcode) {
        return Err(Problem::UnsupportedPcode { pcode, name: r.name, offset: at });
    }
    let index = |r: &mut Reader| if compact { r.byte() } else { r.word() };
    let mut args = Vec::new();
    let mut targets = Vec::new();
    match pcodes::operands(pcode) {
        Operands::None => {}
        Operands::Index => args.push(index(&mut r)?),
        Operands::Words(n) => {
            for _ in 0..n {
                args.push(r.word()?);
            }
        }
        Operands::Jump => {
            args.push(r.word()?);
            targets.push(args[0]);
        }
        Operands::CaseGoto => {
            args.push(r.word()?);
            args.push(r.word()?);
            targets.push(args[1]);
        }
        Operands::SortedCases => {
            // The table is aligned to four bytes from the lump's start.
            r.pos = (r.pos + 3) & !3;
            let count = r.word()?;
            if count < 0 || (count as usize).saturating_mul(8) > end.saturating_sub(r.pos) {
                return Err(r.truncated());
            }
            for _ in 0..count {
                args.push(r.word()?);
                let t = r.word()?;
                args.push(t);
                targets.push(t);
            }
        }
        Operands::SpecialDirect(n) => {
            args.push(index(&mut r)?);
            for _ in 0..n {
                args.push(r.word()?);
            }
        }
        Operands::Bytes(n) => {
            for _ in 0..n {
                args.push(r.byte()?);
            }
        }
        Operands::CountedBytes => {
            let n = r.byte()?;
            for _ in 0..n {
                args.push(r.byte()?);
            }
        }
        Operands::CallFunc => {
            args.push(index(&mut r)?);
            args.push(if compact { r.short()? } else { r.word()? });
        }
    }
    let insn = Insn { offset: at as u32, pcode, args, next: usize::MAX };
    Ok((insn, r.pos as u32, targets))
}

/// Index operands against the tables they index.
fn check(insn: &Insn, module: &Module) -> Result<(), Problem> {
    let bad = |what: &'static str, index: i32, limit: usize| {
        if index < 0 || index as usize >= limit {
            Err(Problem::BadIndex {
                name: pcodes::name(insn.pcode),
                offset: insn.offset as usize,
                what,
                index: i64::from(index),
                limit,
            })
        } else {
            Ok(())
        }
    };
    if let Some((_, store)) = pcodes::var_op(insn.pcode) {
        let i = insn.args[0];
        return match store {
            Store::MapVar | Store::MapArray => bad("map variable", i, MAP_VARS),
            Store::WorldVar | Store::WorldArray => bad("world variable", i, WORLD_VARS),
            Store::GlobalVar | Store::GlobalArray => bad("global variable", i, GLOBAL_VARS),
            // Script variables are checked when run: the same bytes can
            // belong to scripts with different local counts.
            Store::ScriptVar | Store::ScriptArray => bad("script variable", i, 1 << 16),
        };
    }
    match insn.pcode {
        pcodes::CALL | pcodes::CALLDISCARD | pcodes::PUSHFUNCTION => {
            bad("function", insn.args[0], module.functions.len())
        }
        pcodes::CALLFUNC => bad("argument count", insn.args[0], 256),
        _ => Ok(()),
    }
}
