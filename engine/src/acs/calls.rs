//! A script's calls out of its own code: line specials and extended
//! functions. The ones about scripts themselves (`ACS_Execute` and its
//! family, by number or by name) and about strings the VM answers; the rest
//! go to the [`Host`].

use super::exec::Fault;
use super::host::{Host, HostCx};
use super::load::Module;
use super::vm::{State, Thread, Vm};

/// Line specials that control scripts (ZDoom's p_lnspec.cpp numbers).
const ACS_EXECUTE: i32 = 80;
const ACS_SUSPEND: i32 = 81;
const ACS_TERMINATE: i32 = 82;
const ACS_LOCKED_EXECUTE: i32 = 83;
const ACS_EXECUTE_WITH_RESULT: i32 = 84;
const ACS_LOCKED_EXECUTE_DOOR: i32 = 85;
const ACS_EXECUTE_ALWAYS: i32 = 226;

/// Extended functions the VM answers itself (ZDoom's `ACSF_*` ids).
const GET_CHAR: u16 = 15;
const NAMED_EXECUTE: u16 = 39;
const NAMED_EXECUTE_ALWAYS: u16 = 45;
const STRCMP: u16 = 63;
const STRICMP: u16 = 64;
const STR_LEFT: u16 = 65;
const STR_RIGHT: u16 = 66;
const STR_MID: u16 = 67;

/// The specials `ACS_NamedExecute`... (39..=45) stand for, in id order
/// (ZDoom's `NamedACSToNormalACS`).
const NAMED_SPECIALS: [i32; 7] = [
    ACS_EXECUTE,
    ACS_SUSPEND,
    ACS_TERMINATE,
    ACS_LOCKED_EXECUTE,
    ACS_LOCKED_EXECUTE_DOOR,
    ACS_EXECUTE_WITH_RESULT,
    ACS_EXECUTE_ALWAYS,
];

/// Scripts running a result call inside another's instruction, at most;
/// deeper, the call returns 0 with a warning instead of overflowing the
/// machine's stack.
const NESTING_LIMIT: u32 = 64;

/// Whether the VM itself provides the extended function `id`.
pub fn vm_function(id: u16) -> bool {
    matches!(id, GET_CHAR | NAMED_EXECUTE..=NAMED_EXECUTE_ALWAYS | STRCMP..=STR_MID)
}

/// A line special with up to five arguments (missing ones are 0); returns its result.
pub(super) fn special(vm: &mut Vm, t: &mut Thread, host: &mut dyn Host, special: i32, args: &[i32]) -> i32 {
    let mut a = [0; 5];
    for (d, s) in a.iter_mut().zip(args) {
        *d = *s;
    }
    let here = a[1] == 0 || a[1] == vm.level_number;
    match special {
        ACS_EXECUTE | ACS_EXECUTE_ALWAYS if here => {
            i32::from(vm.execute(a[0], &a[2..5], t.activator, special == ACS_EXECUTE_ALWAYS))
        }
        ACS_LOCKED_EXECUTE | ACS_LOCKED_EXECUTE_DOOR if here => {
            if a[4] != 0 && !host.has_lock(a[4], t.activator) {
                return 0;
            }
            i32::from(vm.execute(a[0], &a[2..4], t.activator, false))
        }
        ACS_SUSPEND | ACS_TERMINATE if here => {
            let state = if special == ACS_SUSPEND { State::Suspended } else { State::Remove };
            // A script stopping itself is the thread in hand: the state waits
            // in its slot until the instruction ends (`exec::run`).
            vm.set_state(a[0], state);
            1
        }
        ACS_EXECUTE_WITH_RESULT => {
            if vm.nesting >= NESTING_LIMIT {
                vm.warnings
                    .push(format!("ACS_ExecuteWithResult nested deeper than {NESTING_LIMIT}; script {} not run", a[0]));
                return 0;
            }
            vm.nesting += 1;
            let value = vm.execute_with_result(a[0], &a[1..5], t.activator, host);
            vm.nesting -= 1;
            value
        }
        _ => {
            let mut cx = HostCx { activator: t.activator, script: t.number, strings: &mut vm.strings };
            host.line_special(special, a, &mut cx)
        }
    }
}

/// An extended function call (`PCD_CALLFUNC`).
pub(super) fn function(
    vm: &mut Vm,
    module: &Module,
    t: &mut Thread,
    host: &mut dyn Host,
    id: u16,
    args: &[i32],
) -> Result<i32, Fault> {
    let arg = |i: usize| args.get(i).copied().unwrap_or(0);
    let need = |n: usize| {
        if args.len() < n {
            Err(format!("extended function {id} called with {} arguments, needs {n}", args.len()))
        } else {
            Ok(())
        }
    };
    match id {
        GET_CHAR => {
            need(2)?;
            let s = vm.strings.get(arg(0)).unwrap_or("");
            Ok(usize::try_from(arg(1)).ok().and_then(|i| s.chars().nth(i)).map_or(0, |c| c as i32))
        }
        NAMED_EXECUTE..=NAMED_EXECUTE_ALWAYS => {
            need(1)?;
            let name = vm.strings.get(arg(0)).unwrap_or("").to_string();
            let Some(number) = module.named(&name) else {
                vm.warnings.push(format!("script \"{name}\" does not exist"));
                return Ok(0);
            };
            let special_args = [number, arg(1), arg(2), arg(3), arg(4)];
            Ok(special(vm, t, host, NAMED_SPECIALS[usize::from(id - NAMED_EXECUTE)], &special_args))
        }
        STRCMP | STRICMP => {
            need(2)?;
            if arg(0) == arg(1) {
                return Ok(0);
            }
            let fold = |s: &str| if id == STRICMP { s.to_ascii_lowercase() } else { s.to_string() };
            let mut a = fold(vm.strings.get(arg(0)).unwrap_or(""));
            let mut b = fold(vm.strings.get(arg(1)).unwrap_or(""));
            if args.len() > 2 {
                let n = usize::try_from(arg(2)).unwrap_or(0);
                a = a.chars().take(n).collect();
                b = b.chars().take(n).collect();
            }
            Ok(a.cmp(&b) as i32)
        }
        STR_LEFT | STR_RIGHT | STR_MID => {
            need(if id == STR_MID { 3 } else { 2 })?;
            let s: Vec<char> = vm.strings.get(arg(0)).unwrap_or("").chars().collect();
            let count = |v: i32| usize::try_from(v).unwrap_or(usize::MAX);
            let part: String = match id {
                STR_LEFT => s.iter().take(count(arg(1))).collect(),
                STR_RIGHT => s[s.len().saturating_sub(count(arg(1)))..].iter().collect(),
                _ => s.iter().skip(count(arg(1))).take(count(arg(2))).collect(),
            };
            Ok(vm.strings.add(&part))
        }
        _ => {
            let mut cx = HostCx { activator: t.activator, script: t.number, strings: &mut vm.strings };
            Ok(host.function(id, args, &mut cx))
        }
    }
}
