//! Runs one script for one turn: decoded instructions, one at a time, until
//! the script waits, ends or runs away. Arithmetic is 32-bit and wraps, as
//! ZDoom's does on every machine it runs on; a fault ZDoom would stop the
//! script for (division by zero, a bad variable index) stops it here too,
//! with a warning naming the script and the instruction's offset.

use std::sync::Arc;

use super::calls;
use super::decode::{script_label, Insn};
use super::host::{Host, HostCx, PrintKind};
use super::load::{LocalArray, Module, MAP_VARS};
use super::pcodes::{self as p, Store, VarOp};
use super::vm::{Frame, Owner, State, Thread, Vm, GLOBAL_VARS, RUNAWAY_LIMIT, WORLD_VARS};

/// Values on one script's stack (ZDoom's `STACK_SIZE`).
const STACK_LIMIT: usize = 4096;
/// Nested function calls; ZDoom's limit is its stack, which this depth of
/// the smallest frames would fill.
const CALL_DEPTH_LIMIT: usize = 1000;

/// Why a script was stopped.
pub(super) type Fault = String;

/// Runs `t` (the thread of slot `id`) until it leaves the running state;
/// returns its result value (`SetResultValue`, 1 if never set).
pub(super) fn run(vm: &mut Vm, id: usize, t: &mut Thread, host: &mut dyn Host) -> i32 {
    let module = Arc::clone(&vm.module);
    let mut result = 1;
    let mut count = 0u32;
    while t.state == State::Running {
        count += 1;
        if count > RUNAWAY_LIMIT {
            let label = label(&module, t);
            vm.warnings.push(format!("runaway {label} terminated after {RUNAWAY_LIMIT} instructions in one tic"));
            t.state = State::Remove;
            break;
        }
        let Some(insn) = module.code.insns.get(t.pc) else {
            vm.warnings.push(format!("{} ran off its code", label(&module, t)));
            t.state = State::Remove;
            break;
        };
        if let Err(fault) = step(vm, &module, id, t, insn, host, &mut result) {
            vm.warnings.push(format!(
                "{} stopped by {} at byte {}: {fault}",
                label(&module, t),
                p::name(insn.pcode),
                insn.offset
            ));
            t.state = State::Remove;
        }
        if let Some(s) = vm.take_pending(id) {
            t.state = s;
        }
    }
    result
}

fn label(module: &Module, t: &Thread) -> String {
    script_label(t.number, module.scripts.get(t.script).and_then(|s| s.name.as_deref()))
}

pub(super) fn pop(t: &mut Thread) -> Result<i32, Fault> {
    t.stack.pop().ok_or_else(|| "stack underflow".to_string())
}

pub(super) fn push(t: &mut Thread, v: i32) -> Result<(), Fault> {
    if t.stack.len() >= STACK_LIMIT {
        return Err(format!("stack overflow ({STACK_LIMIT} values)"));
    }
    t.stack.push(v);
    Ok(())
}

/// Pops `n` values, returned in the order they were pushed.
pub(super) fn pop_n(t: &mut Thread, n: usize) -> Result<Vec<i32>, Fault> {
    let len = t.stack.len();
    if n > len {
        return Err(format!("stack underflow ({n} values wanted, {len} there)"));
    }
    Ok(t.stack.split_off(len - n))
}

fn print_buffer(t: &mut Thread) -> &mut String {
    if t.print.is_empty() {
        t.print.push(String::new());
    }
    let last = t.print.len() - 1;
    &mut t.print[last]
}

fn binary(t: &mut Thread, f: impl Fn(i32, i32) -> Result<i32, Fault>) -> Result<(), Fault> {
    let b = pop(t)?;
    let a = pop(t)?;
    push(t, f(a, b)?)
}

fn unary(t: &mut Thread, f: impl Fn(i32) -> i32) -> Result<(), Fault> {
    let a = pop(t)?;
    push(t, f(a))
}

fn divide(a: i32, b: i32) -> Result<i32, Fault> {
    if b == 0 {
        Err("division by zero".into())
    } else {
        Ok(a.wrapping_div(b))
    }
}

fn modulo(a: i32, b: i32) -> Result<i32, Fault> {
    if b == 0 {
        Err("modulus by zero".into())
    } else {
        Ok(a.wrapping_rem(b))
    }
}

/// `FixedMul` (ZDoom's `MulScale(a, b, 16)`).
pub fn fixed_mul(a: i32, b: i32) -> i32 {
    ((i64::from(a) * i64::from(b)) >> 16) as i32
}

/// `FixedDiv`, saturating where the quotient would overflow, as ZDoom's does
/// (which also makes a zero divisor saturate rather than fault).
pub fn fixed_div(a: i32, b: i32) -> i32 {
    if a.unsigned_abs() >> 15 >= b.unsigned_abs() {
        if (a ^ b) < 0 {
            i32::MIN
        } else {
            i32::MAX
        }
    } else {
        ((i64::from(a) << 16) / i64::from(b)) as i32
    }
}

/// `Sin`/`Cos`: the angle is a 16.16 fraction of a turn, the result 16.16,
/// computed in double as ZDoom does and rounded to nearest.
pub fn fixed_sin(angle: i32, cos: bool) -> i32 {
    let radians = f64::from(angle) / 65536.0 * std::f64::consts::TAU;
    let v = if cos { radians.cos() } else { radians.sin() };
    (v * 65536.0).round() as i32
}

/// `VectorAngle(x, y)`: the direction of (x, y) as a 16.16 fraction of a turn in 0..1.
pub fn vector_angle(x: i32, y: i32) -> i32 {
    let turns = f64::from(y).atan2(f64::from(x)) / std::f64::consts::TAU;
    let turns = if turns < 0.0 { turns + 1.0 } else { turns };
    ((turns * 65536.0).round() as i32) & 0xffff
}

/// C's `%g` for `PrintFixed`: six significant digits, trailing zeros dropped.
fn format_g(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let exp = v.abs().log10().floor() as i32;
    let mut s = if !(-4..6).contains(&exp) { format!("{v:.5e}") } else { format!("{v:.*}", (5 - exp).max(0) as usize) };
    if s.contains('.') && !s.contains('e') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    s
}

pub(super) fn local_arrays(module: &Module, owner: Owner) -> &[LocalArray] {
    match owner {
        Owner::Script(i) => module.scripts.get(i).map(|s| s.arrays.as_slice()).unwrap_or(&[]),
        Owner::Function(i) => module.functions.get(i).map(|f| f.arrays.as_slice()).unwrap_or(&[]),
    }
}

/// Where a variable pcode reads and writes. Array elements out of range
/// read 0 and ignore writes, as ZDoom's bounds-checked arrays do.
enum Cell {
    Local(usize),
    Map(usize),
    World(usize),
    Global(usize),
    Nowhere,
    MapElem(usize, usize),
    WorldElem(usize, i32),
    GlobalElem(usize, i32),
}

fn cell(vm: &Vm, module: &Module, t: &Thread, store: Store, index: usize, elem: i32) -> Result<Cell, Fault> {
    Ok(match store {
        Store::ScriptVar if index < t.locals.len() => Cell::Local(index),
        Store::ScriptVar => return Err(format!("script variable {index} of {}", t.locals.len())),
        Store::MapVar => Cell::Map(index),
        Store::WorldVar => Cell::World(index),
        Store::GlobalVar => Cell::Global(index),
        Store::ScriptArray => match local_arrays(module, t.owner).get(index) {
            Some(a) if elem >= 0 && (elem as usize) < a.size && a.offset + (elem as usize) < t.locals.len() => {
                Cell::Local(a.offset + elem as usize)
            }
            _ => Cell::Nowhere,
        },
        Store::MapArray => {
            let array = vm.map_vars[index] as usize;
            match vm.map_arrays.get(array) {
                Some(a) if elem >= 0 && (elem as usize) < a.len() => Cell::MapElem(array, elem as usize),
                _ => Cell::Nowhere,
            }
        }
        Store::WorldArray => Cell::WorldElem(index, elem),
        Store::GlobalArray => Cell::GlobalElem(index, elem),
    })
}

fn read(vm: &Vm, t: &Thread, c: &Cell) -> i32 {
    match *c {
        Cell::Local(i) => t.locals[i],
        Cell::Map(i) => vm.map_vars[i],
        Cell::World(i) => vm.globals.world[i],
        Cell::Global(i) => vm.globals.global[i],
        Cell::Nowhere => 0,
        Cell::MapElem(a, e) => vm.map_arrays[a][e],
        Cell::WorldElem(a, e) => vm.globals.world_arrays[a].get(&e).copied().unwrap_or(0),
        Cell::GlobalElem(a, e) => vm.globals.global_arrays[a].get(&e).copied().unwrap_or(0),
    }
}

fn write(vm: &mut Vm, t: &mut Thread, c: &Cell, v: i32) {
    match *c {
        Cell::Local(i) => t.locals[i] = v,
        Cell::Map(i) => vm.map_vars[i] = v,
        Cell::World(i) => vm.globals.world[i] = v,
        Cell::Global(i) => vm.globals.global[i] = v,
        Cell::Nowhere => {}
        Cell::MapElem(a, e) => vm.map_arrays[a][e] = v,
        Cell::WorldElem(a, e) => {
            vm.globals.world_arrays[a].insert(e, v);
        }
        Cell::GlobalElem(a, e) => {
            vm.globals.global_arrays[a].insert(e, v);
        }
    }
}

/// The variable pcodes: scalars take their operand from the stack top,
/// arrays an element index under it (ZDoom's `STACK(2)`).
fn var_op(vm: &mut Vm, module: &Module, t: &mut Thread, op: VarOp, store: Store, index: usize) -> Result<(), Fault> {
    let is_array = matches!(store, Store::ScriptArray | Store::MapArray | Store::WorldArray | Store::GlobalArray);
    let operand = if matches!(op, VarOp::Push | VarOp::Inc | VarOp::Dec) { 0 } else { pop(t)? };
    let elem = if is_array { pop(t)? } else { 0 };
    let c = cell(vm, module, t, store, index, elem)?;
    let old = read(vm, t, &c);
    let new = match op {
        VarOp::Push => return push(t, old),
        VarOp::Assign => operand,
        VarOp::Add => old.wrapping_add(operand),
        VarOp::Sub => old.wrapping_sub(operand),
        VarOp::Mul => old.wrapping_mul(operand),
        VarOp::Div => divide(old, operand)?,
        VarOp::Mod => modulo(old, operand)?,
        VarOp::Inc => old.wrapping_add(1),
        VarOp::Dec => old.wrapping_sub(1),
        VarOp::And => old & operand,
        VarOp::Eor => old ^ operand,
        VarOp::Or => old | operand,
        VarOp::Shl => old.wrapping_shl(operand as u32),
        VarOp::Shr => old.wrapping_shr(operand as u32),
    };
    write(vm, t, &c, new);
    Ok(())
}

/// The `Print...CharArray` and `...ChRange` pcodes: characters of an array
/// up to a NUL (or `capacity`), from an offset.
fn print_array(vm: &Vm, module: &Module, t: &mut Thread, store: Store, ranged: bool) -> Result<(), Fault> {
    let (capacity, mut offset) = if ranged {
        let capacity = pop(t)?;
        let offset = pop(t)?;
        if capacity < 1 || offset < 0 {
            pop_n(t, 2)?;
            return Ok(());
        }
        (capacity as usize, offset)
    } else {
        (usize::MAX, 0)
    };
    let array = pop(t)?;
    offset = offset.wrapping_add(pop(t)?);
    let limit = match store {
        Store::MapArray => MAP_VARS,
        Store::WorldArray => WORLD_VARS,
        Store::GlobalArray => GLOBAL_VARS,
        _ => usize::MAX,
    };
    let index =
        usize::try_from(array).ok().filter(|&i| i < limit).ok_or_else(|| format!("array {array} does not exist"))?;
    let mut text = String::new();
    for _ in 0..capacity.min(1 << 16) {
        let c = read(vm, t, &cell(vm, module, t, store, index, offset)?);
        if c == 0 {
            break;
        }
        text.push(char::from(c as u8));
        offset = offset.wrapping_add(1);
    }
    print_buffer(t).push_str(&text);
    Ok(())
}

/// Executes `insn` and moves the thread to the next instruction.
fn step(
    vm: &mut Vm,
    module: &Module,
    id: usize,
    t: &mut Thread,
    insn: &Insn,
    host: &mut dyn Host,
    result: &mut i32,
) -> Result<(), Fault> {
    let a = &insn.args;
    let mut next = insn.next;
    match insn.pcode {
        p::NOP | p::TAGSTRING => {}
        p::TERMINATE => t.state = State::Remove,
        p::SUSPEND => t.state = State::Suspended,
        p::PUSHNUMBER | p::PUSHFUNCTION => push(t, a[0])?,
        p::PUSHBYTE | p::PUSH2BYTES..=p::PUSH5BYTES | p::PUSHBYTES => {
            for &v in a {
                push(t, v)?;
            }
        }
        p::ADD => binary(t, |x, y| Ok(x.wrapping_add(y)))?,
        p::SUBTRACT => binary(t, |x, y| Ok(x.wrapping_sub(y)))?,
        p::MULTIPLY => binary(t, |x, y| Ok(x.wrapping_mul(y)))?,
        p::DIVIDE => binary(t, divide)?,
        p::MODULUS => binary(t, modulo)?,
        p::EQ => binary(t, |x, y| Ok(i32::from(x == y)))?,
        p::NE => binary(t, |x, y| Ok(i32::from(x != y)))?,
        p::LT => binary(t, |x, y| Ok(i32::from(x < y)))?,
        p::GT => binary(t, |x, y| Ok(i32::from(x > y)))?,
        p::LE => binary(t, |x, y| Ok(i32::from(x <= y)))?,
        p::GE => binary(t, |x, y| Ok(i32::from(x >= y)))?,
        p::ANDLOGICAL => binary(t, |x, y| Ok(i32::from(x != 0 && y != 0)))?,
        p::ORLOGICAL => binary(t, |x, y| Ok(i32::from(x != 0 || y != 0)))?,
        p::ANDBITWISE => binary(t, |x, y| Ok(x & y))?,
        p::ORBITWISE => binary(t, |x, y| Ok(x | y))?,
        p::EORBITWISE => binary(t, |x, y| Ok(x ^ y))?,
        p::LSHIFT => binary(t, |x, y| Ok(x.wrapping_shl(y as u32)))?,
        p::RSHIFT => binary(t, |x, y| Ok(x.wrapping_shr(y as u32)))?,
        p::NEGATELOGICAL => unary(t, |x| i32::from(x == 0))?,
        p::NEGATEBINARY => unary(t, |x| !x)?,
        p::UNARYMINUS => unary(t, i32::wrapping_neg)?,
        p::FIXEDMUL => binary(t, |x, y| Ok(fixed_mul(x, y)))?,
        p::FIXEDDIV => binary(t, |x, y| Ok(fixed_div(x, y)))?,
        p::SIN => unary(t, |x| fixed_sin(x, false))?,
        p::COS => unary(t, |x| fixed_sin(x, true))?,
        p::VECTORANGLE => binary(t, |x, y| Ok(vector_angle(x, y)))?,
        p::DUP => {
            let v = *t.stack.last().ok_or("stack underflow")?;
            push(t, v)?;
        }
        p::SWAP => {
            let (y, x) = (pop(t)?, pop(t)?);
            push(t, y)?;
            push(t, x)?;
        }
        p::DROP => {
            pop(t)?;
        }
        p::SETRESULTVALUE => *result = pop(t)?,
        p::GOTO => next = a[0] as usize,
        p::IFGOTO if pop(t)? != 0 => next = a[0] as usize,
        p::IFNOTGOTO if pop(t)? == 0 => next = a[0] as usize,
        p::IFGOTO | p::IFNOTGOTO => {}
        p::CASEGOTO => {
            if t.stack.last() == Some(&a[0]) {
                pop(t)?;
                next = a[1] as usize;
            }
        }
        p::CASEGOTOSORTED => {
            let top = *t.stack.last().ok_or("stack underflow")?;
            let cases: Vec<(i32, i32)> = a.chunks_exact(2).map(|c| (c[0], c[1])).collect();
            if let Ok(i) = cases.binary_search_by_key(&top, |c| c.0) {
                pop(t)?;
                next = cases[i].1 as usize;
            }
        }
        p::GOTOSTACK => {
            let j = pop(t)?;
            let target = usize::try_from(j).ok().and_then(|j| module.jumps.get(j)).and_then(|&o| module.code.at(o));
            next = target.ok_or_else(|| format!("jump target {j} does not exist"))?;
        }
        p::DELAY | p::DELAYDIRECT | p::DELAYDIRECTB => {
            let tics = if insn.pcode == p::DELAY { pop(t)? } else { a[0] };
            if tics > 0 {
                t.wait = tics;
                t.state = State::Delayed;
            }
        }
        p::RANDOM | p::RANDOMDIRECT | p::RANDOMDIRECTB => {
            let (lo, hi) = if insn.pcode == p::RANDOM {
                let hi = pop(t)?;
                (pop(t)?, hi)
            } else {
                (a[0], a[1])
            };
            push(t, host.random(lo.min(hi), lo.max(hi)))?;
        }
        p::TAGWAIT | p::TAGWAITDIRECT | p::POLYWAIT | p::POLYWAITDIRECT => {
            t.wait = if matches!(insn.pcode, p::TAGWAIT | p::POLYWAIT) { pop(t)? } else { a[0] };
            t.state =
                if matches!(insn.pcode, p::TAGWAIT | p::TAGWAITDIRECT) { State::TagWait } else { State::PolyWait };
        }
        p::SCRIPTWAIT | p::SCRIPTWAITDIRECT | p::SCRIPTWAITNAMED => {
            t.wait = match insn.pcode {
                p::SCRIPTWAIT => pop(t)?,
                p::SCRIPTWAITDIRECT => a[0],
                _ => {
                    let name = pop(t)?;
                    vm.strings.get(name).and_then(|n| module.named(n)).unwrap_or(0)
                }
            };
            t.state = if vm.is_running(t.wait) { State::ScriptWait } else { State::ScriptWaitPre };
            vm.put_last(id);
        }
        p::RESTART => {
            // Back to the script's first instruction, out of any function.
            if let Some(first) = t.frames.first() {
                t.locals = first.locals.clone();
            }
            t.frames.clear();
            t.stack.clear();
            t.owner = Owner::Script(t.script);
            let address = module.scripts.get(t.script).map(|s| s.address).unwrap_or(u32::MAX);
            next = module.code.at(address).ok_or("the script's start is not code")?;
        }
        p::CALL | p::CALLDISCARD | p::CALLSTACK => {
            let index = if insn.pcode == p::CALLSTACK { (pop(t)? & 0xffff) as usize } else { a[0] as usize };
            let f = module.functions.get(index).ok_or_else(|| format!("function {index} does not exist"))?;
            if t.frames.len() >= CALL_DEPTH_LIMIT {
                return Err(format!("calls nested deeper than {CALL_DEPTH_LIMIT}"));
            }
            let mut locals = pop_n(t, usize::from(f.args))?;
            locals.resize(usize::from(f.args) + f.locals, 0);
            let caller = std::mem::replace(&mut t.locals, locals);
            t.frames.push(Frame {
                ret: next,
                locals: caller,
                owner: t.owner,
                discard: insn.pcode == p::CALLDISCARD,
                base: t.stack.len(),
            });
            t.owner = Owner::Function(index);
            next = module.code.at(f.address).ok_or("the function's start is not code")?;
        }
        p::RETURNVOID | p::RETURNVAL => {
            let value = if insn.pcode == p::RETURNVAL { pop(t)? } else { 0 };
            let frame = t.frames.pop().ok_or("return outside a function")?;
            t.stack.truncate(frame.base);
            t.locals = frame.locals;
            t.owner = frame.owner;
            next = frame.ret;
            if !frame.discard {
                push(t, value)?;
            }
        }
        p::BEGINPRINT => t.print.push(String::new()),
        p::PRINTSTRING | p::PRINTLOCALIZED => {
            let s = pop(t)?;
            let text = vm.strings.get(s).unwrap_or("").to_string();
            print_buffer(t).push_str(&text);
        }
        p::PRINTNUMBER | p::PRINTCHARACTER | p::PRINTFIXED | p::PRINTBINARY | p::PRINTHEX => {
            let v = pop(t)?;
            let text = match insn.pcode {
                p::PRINTNUMBER => v.to_string(),
                p::PRINTCHARACTER => char::from(v as u8).to_string(),
                p::PRINTFIXED => format_g(f64::from(v) / 65536.0),
                p::PRINTBINARY => format!("{:b}", v as u32),
                _ => format!("{:X}", v as u32),
            };
            print_buffer(t).push_str(&text);
        }
        p::PRINTSCRIPTCHARARRAY | p::PRINTSCRIPTCHRANGE => {
            print_array(vm, module, t, Store::ScriptArray, insn.pcode == p::PRINTSCRIPTCHRANGE)?
        }
        p::PRINTMAPCHARARRAY | p::PRINTMAPCHRANGE => {
            print_array(vm, module, t, Store::MapArray, insn.pcode == p::PRINTMAPCHRANGE)?
        }
        p::PRINTWORLDCHARARRAY | p::PRINTWORLDCHRANGE => {
            print_array(vm, module, t, Store::WorldArray, insn.pcode == p::PRINTWORLDCHRANGE)?
        }
        p::PRINTGLOBALCHARARRAY | p::PRINTGLOBALCHRANGE => {
            print_array(vm, module, t, Store::GlobalArray, insn.pcode == p::PRINTGLOBALCHRANGE)?
        }
        p::ENDPRINT | p::ENDPRINTBOLD | p::ENDLOG => {
            let text = t.print.pop().unwrap_or_default();
            let kind = match insn.pcode {
                p::ENDPRINT => PrintKind::Print,
                p::ENDPRINTBOLD => PrintKind::Bold,
                _ => PrintKind::Log,
            };
            host.print(kind, &text, t.activator);
        }
        p::MOREHUDMESSAGE => t.hud_optional = None,
        p::OPTHUDMESSAGE => t.hud_optional = Some(t.stack.len()),
        p::ENDHUDMESSAGE | p::ENDHUDMESSAGEBOLD => {
            let optional = t.hud_optional.take().unwrap_or(t.stack.len()).min(t.stack.len());
            let first = optional.checked_sub(6).ok_or("a HudMessage without its six parameters")?;
            let params = t.stack.split_off(first);
            let text = t.print.pop().unwrap_or_default();
            let kind = PrintKind::HudMessage { bold: insn.pcode == p::ENDHUDMESSAGEBOLD, params };
            host.print(kind, &text, t.activator);
        }
        p::SAVESTRING => {
            let text = t.print.pop().unwrap_or_default();
            let s = vm.strings.add(&text);
            push(t, s)?;
        }
        p::STRLEN => {
            let s = pop(t)?;
            let len = vm.strings.get(s).map_or(0, |s| s.chars().count() as i32);
            push(t, len)?;
        }
        p::CALLFUNC => {
            let args = pop_n(t, a[0] as usize)?;
            let value = calls::function(vm, module, t, host, a[1] as u16, &args)?;
            push(t, value)?;
        }
        p::LSPEC1..=p::LSPEC5 => {
            let args = pop_n(t, usize::from(insn.pcode - p::LSPEC1 + 1))?;
            calls::special(vm, t, host, a[0], &args);
        }
        p::LSPEC5RESULT | p::LSPEC5EX | p::LSPEC5EXRESULT => {
            let args = pop_n(t, 5)?;
            let value = calls::special(vm, t, host, a[0], &args);
            if insn.pcode != p::LSPEC5EX {
                push(t, value)?;
            }
        }
        p::LSPEC1DIRECT..=p::LSPEC5DIRECT | p::LSPEC1DIRECTB..=p::LSPEC5DIRECTB => {
            calls::special(vm, t, host, a[0], &a[1..]);
        }
        pcode => {
            if let Some((op, store)) = p::var_op(pcode) {
                var_op(vm, module, t, op, store, a[0] as usize)?;
            } else if let Some((op, direct)) = p::game_op(pcode) {
                let n = usize::from(op.args);
                let mut args = if direct { a.clone() } else { pop_n(t, n)? };
                args.resize(n, 0);
                let mut cx = HostCx { activator: t.activator, script: t.number, strings: &mut vm.strings };
                let value = host.game(op.pcode, &args, &mut cx);
                if op.pushes {
                    push(t, value)?;
                }
            } else {
                return Err(format!("pcode {pcode} has no implementation"));
            }
        }
    }
    t.pc = next;
    Ok(())
}
