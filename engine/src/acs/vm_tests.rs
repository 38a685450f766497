//! The scheduler: ZDoom's order within a tic, starting, suspending,
//! terminating and waiting, the runaway limit, and faults that stop a script.

use super::asm_tests::run;
use super::pcodes as p;
use super::record::RecordingHost;
use super::test_asm::{Asm, Layout};
use super::*;

fn vm_of(asm: &mut Asm) -> (Vm, RecordingHost) {
    let module = Module::load(&asm.build(), "test").unwrap_or_else(|e| panic!("{e}"));
    let host = RecordingHost::default();
    let vm = Vm::new(module, &host).unwrap_or_else(|e| panic!("{e}"));
    (vm, host)
}

/// A script that appends its number to global array 0 (at the count in
/// global 1) each tic, forever.
fn logger(asm: &mut Asm, number: i16, kind: u8) {
    asm.script(number, kind, 0).label(&format!("loop {number}"));
    asm.op_i(p::PUSHGLOBALVAR, 1).push(i32::from(number)).op_i(236, 0).op_i(p::INCGLOBALVAR, 1);
    asm.push(1).op(p::DELAY).jump(p::GOTO, &format!("loop {number}"));
}

fn log(vm: &Vm) -> Vec<i32> {
    (0..vm.globals.global[1]).map(|i| vm.globals.global_arrays[0].get(&i).copied().unwrap_or(0)).collect()
}

#[test]
fn typed_scripts_run_highest_number_first_and_new_scripts_wait_a_tic() {
    let mut asm = Asm::new(Layout::Compact);
    logger(&mut asm, 1, 1);
    logger(&mut asm, 2, 1);
    logger(&mut asm, 5, 1);
    logger(&mut asm, 9, 0);
    let (mut vm, mut host) = vm_of(&mut asm);
    vm.start_typed(ScriptKind::Open, Activator::World, false, 0);
    assert_eq!(vm.scripts_in_order(), vec![5, 2, 1]);
    vm.tick(&mut host);
    assert!(vm.execute(9, &[], Activator::World, false));
    vm.tick(&mut host);
    assert_eq!(log(&vm), vec![5, 2, 1, 9, 5, 2, 1]);
}

#[test]
fn execute_does_not_start_a_running_script_twice_but_always_does() {
    let mut asm = Asm::new(Layout::Compact);
    logger(&mut asm, 3, 0);
    let (mut vm, mut host) = vm_of(&mut asm);
    assert!(vm.execute(3, &[], Activator::World, false));
    assert!(!vm.execute(3, &[], Activator::World, false));
    assert!(vm.execute(3, &[], Activator::World, true));
    vm.tick(&mut host);
    assert_eq!(log(&vm), vec![3, 3]);
}

#[test]
fn suspend_resume_terminate_and_restart() {
    let mut asm = Asm::new(Layout::Compact);
    logger(&mut asm, 3, 0);
    // Script 4 counts in global 2, restarting itself after each count.
    asm.script(4, 0, 0).op_i(p::INCGLOBALVAR, 2).push(1).op(p::DELAY).op(p::RESTART);
    let (mut vm, mut host) = vm_of(&mut asm);
    vm.execute(3, &[], Activator::World, false);
    vm.execute(4, &[], Activator::World, false);
    vm.tick(&mut host);
    vm.suspend(3);
    vm.tick(&mut host);
    vm.tick(&mut host);
    assert_eq!(log(&vm), vec![3], "suspended");
    assert!(vm.execute(3, &[], Activator::World, false), "a suspended script resumes");
    vm.tick(&mut host);
    assert_eq!(log(&vm), vec![3, 3]);
    vm.terminate(3);
    vm.tick(&mut host);
    assert!(!vm.is_running(3));
    assert_eq!(log(&vm), vec![3, 3]);
    assert_eq!(vm.globals.global[2], 5, "RESTART went back to the top each tic");
}

#[test]
fn scripts_control_scripts_through_the_acs_specials() {
    let (vm, host) = run(3, &|asm| {
        // Script 1: ACS_Execute(2, 0, 7), then ACS_Terminate(1) on itself.
        asm.push(2).push(0).push(7).op_i(p::LSPEC3, 80);
        asm.push(1).push(0).op_i(p::LSPEC2, 82);
        asm.op_i(p::INCGLOBALVAR, 9).op(p::TERMINATE);
        asm.script(2, 0, 1).op_i(p::PUSHSCRIPTVAR, 0).op_i(p::ASSIGNGLOBALVAR, 0);
        // Its result through ACS_ExecuteWithResult of script 3.
        asm.push(3).push(5).push(0).push(0).push(0).op_i(p::LSPEC5RESULT, 84).op_i(p::ASSIGNGLOBALVAR, 1);
        asm.op(p::TERMINATE);
        asm.script(3, 0, 1).op_i(p::PUSHSCRIPTVAR, 0).push(2).op(p::MULTIPLY).op(p::SETRESULTVALUE).op(p::TERMINATE);
    });
    assert_eq!(vm.globals.global[9], 0, "ACS_Terminate stopped script 1 after that instruction");
    assert_eq!(vm.globals.global[0], 7);
    assert_eq!(vm.globals.global[1], 10);
    assert!(host.specials(80).is_empty(), "the VM's own specials never reach the host");
}

#[test]
fn waits_for_sectors_and_scripts() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).push(12).op(p::TAGWAIT).op_i(p::INCGLOBALVAR, 0).op(p::TERMINATE);
    asm.script(2, 0, 0).op(p::SCRIPTWAITDIRECT).word(3).op_i(p::INCGLOBALVAR, 1).op(p::TERMINATE);
    asm.script(3, 0, 0).push(2).op(p::DELAY).op(p::TERMINATE);
    let (mut vm, mut host) = vm_of(&mut asm);
    host.busy_tags.insert(12);
    vm.execute(1, &[], Activator::World, false);
    vm.execute(2, &[], Activator::World, false);
    vm.tick(&mut host);
    vm.tick(&mut host);
    assert_eq!(vm.globals.global[0], 0, "tag 12 still moving");
    host.busy_tags.clear();
    vm.tick(&mut host);
    assert_eq!(vm.globals.global[0], 1);
    assert_eq!(vm.globals.global[1], 0, "script 3 never started");
    vm.execute(3, &[], Activator::World, false);
    vm.tick(&mut host);
    vm.tick(&mut host);
    assert_eq!(vm.globals.global[1], 0, "script 3 still delays");
    vm.tick(&mut host);
    assert_eq!(vm.globals.global[1], 1, "script 3 ended, the waiter went on in the same tic");
}

#[test]
fn a_runaway_script_is_stopped_with_a_warning() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(7, 0, 0).label("spin").jump(p::GOTO, "spin");
    logger(&mut asm, 8, 0);
    let (mut vm, mut host) = vm_of(&mut asm);
    vm.execute(7, &[], Activator::World, false);
    vm.execute(8, &[], Activator::World, false);
    vm.tick(&mut host);
    assert_eq!(vm.warnings, vec![format!("runaway script 7 terminated after {RUNAWAY_LIMIT} instructions in one tic")]);
    assert!(!vm.is_running(7));
    vm.tick(&mut host);
    assert_eq!(log(&vm), vec![8, 8], "the other script runs on");
}

#[test]
fn faults_stop_the_script_and_name_it() {
    type Case<'a> = (&'a dyn Fn(&mut Asm), &'a str);
    let cases: [Case; 5] = [
        (
            &|a| {
                a.push(1).push(0).op(p::DIVIDE);
            },
            "script 1 stopped by DIVIDE at byte 18: division by zero",
        ),
        (
            &|a| {
                a.push(1).push(0).op(p::MODULUS);
            },
            "script 1 stopped by MODULUS at byte 18: modulus by zero",
        ),
        (
            &|a| {
                a.op(p::ADD);
            },
            "script 1 stopped by ADD at byte 8: stack underflow",
        ),
        (
            &|a| {
                a.op_i(p::PUSHSCRIPTVAR, 30);
            },
            "script 1 stopped by PUSHSCRIPTVAR at byte 8: script variable 30 of 20",
        ),
        (
            &|a| {
                a.op(p::RETURNVOID);
            },
            "script 1 stopped by RETURNVOID at byte 8: return outside a function",
        ),
    ];
    for (body, message) in cases {
        let mut asm = Asm::new(Layout::Compact);
        asm.script(1, 0, 0);
        body(&mut asm);
        asm.op(p::TERMINATE);
        let (mut vm, mut host) = vm_of(&mut asm);
        vm.execute(1, &[], Activator::World, false);
        vm.tick(&mut host);
        assert_eq!(vm.warnings, vec![message.to_string()]);
        assert!(!vm.is_running(1));
    }
}

#[test]
fn starting_an_unknown_script_warns() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    let (mut vm, _) = vm_of(&mut asm);
    assert!(!vm.execute(44, &[], Activator::World, false));
    assert_eq!(vm.warnings, vec!["script 44 does not exist"]);
}

#[test]
fn an_extended_function_the_host_lacks_is_refused_when_the_vm_is_built() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).push(1).callfunc(1, 61).op(p::DROP).op(p::TERMINATE);
    let module = Module::load(&asm.build(), "BEHAVIOR of MAP01").unwrap_or_else(|e| panic!("{e}"));
    let mut host = RecordingHost::default();
    host.functions = Some(Default::default());
    let err = Vm::new(module, &host).err().expect("refused");
    assert_eq!(
        err.to_string(),
        "BEHAVIOR of MAP01: extended function 61 (PlaySound) called at byte 13 is not supported by the host"
    );
}

#[test]
fn script_arguments_fill_the_first_locals() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(6, 0, 2).op_i(p::PUSHSCRIPTVAR, 0).op_i(p::PUSHSCRIPTVAR, 1).op(p::SUBTRACT);
    asm.op_i(p::ASSIGNGLOBALVAR, 0).op_i(p::PUSHSCRIPTVAR, 2).op_i(p::ASSIGNGLOBALVAR, 1).op(p::TERMINATE);
    let (mut vm, mut host) = vm_of(&mut asm);
    vm.execute(6, &[10, 4, 99], Activator::World, false);
    vm.tick(&mut host);
    assert_eq!(&vm.globals.global[..2], &[6, 0], "only the script's two arguments are copied");
}
