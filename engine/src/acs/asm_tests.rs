//! Each pcode the VM supports, assembled by hand and run: in the compact
//! ACSe encoding and in ACSE, which must agree.

use super::pcodes as p;
use super::record::{HostCall, RecordingHost};
use super::test_asm::{words, Asm, Layout};
use super::*;

/// Script 1 (closed) of a module built by `body` in `layout`, started and
/// run for `tics` tics.
pub(super) fn run_in(layout: Layout, tics: usize, body: &dyn Fn(&mut Asm)) -> (Vm, RecordingHost) {
    let mut asm = Asm::new(layout);
    asm.script(1, 0, 0);
    body(&mut asm);
    let module = Module::load(&asm.build(), "test").unwrap_or_else(|e| panic!("{e}"));
    let mut host = RecordingHost::default();
    let mut vm = Vm::new(module, &host).unwrap_or_else(|e| panic!("{e}"));
    assert!(vm.execute(1, &[], Activator::World, false));
    for _ in 0..tics {
        vm.tick(&mut host);
    }
    assert!(vm.warnings.is_empty(), "{:?}", vm.warnings);
    (vm, host)
}

/// `run_in` in both chunked encodings; the globals and host calls must agree.
pub(super) fn run(tics: usize, body: &dyn Fn(&mut Asm)) -> (Vm, RecordingHost) {
    let (vm, host) = run_in(Layout::Compact, tics, body);
    let (wide, wide_host) = run_in(Layout::Enhanced, tics, body);
    assert_eq!(vm.globals.global, wide.globals.global, "ACSe and ACSE disagree");
    assert_eq!(host.calls, wide_host.calls, "ACSe and ACSE disagree");
    (vm, host)
}

/// Pops the stack top into global `g`.
fn store(asm: &mut Asm, g: i32) -> &mut Asm {
    asm.op_i(p::ASSIGNGLOBALVAR, g)
}

#[test]
fn binary_operators() {
    type Case = (u16, fn(i32, i32) -> i32);
    let cases: [Case; 18] = [
        (p::ADD, |a, b| a + b),
        (p::SUBTRACT, |a, b| a - b),
        (p::MULTIPLY, |a, b| a * b),
        (p::DIVIDE, |a, b| a / b),
        (p::MODULUS, |a, b| a % b),
        (p::EQ, |a, b| i32::from(a == b)),
        (p::NE, |a, b| i32::from(a != b)),
        (p::LT, |a, b| i32::from(a < b)),
        (p::GT, |a, b| i32::from(a > b)),
        (p::LE, |a, b| i32::from(a <= b)),
        (p::GE, |a, b| i32::from(a >= b)),
        (p::ANDLOGICAL, |a, b| i32::from(a != 0 && b != 0)),
        (p::ORLOGICAL, |a, b| i32::from(a != 0 || b != 0)),
        (p::ANDBITWISE, |a, b| a & b),
        (p::ORBITWISE, |a, b| a | b),
        (p::EORBITWISE, |a, b| a ^ b),
        (p::LSHIFT, |a, b| a << b),
        (p::RSHIFT, |a, b| a >> b),
    ];
    for (a, b) in [(-7, 3), (12, 5), (0, 1)] {
        let (vm, _) = run(1, &|asm| {
            for (i, (op, _)) in cases.iter().enumerate() {
                asm.push(a).push(b).op(*op);
                store(asm, i as i32);
            }
            asm.op(p::TERMINATE);
        });
        for (i, (op, f)) in cases.iter().enumerate() {
            assert_eq!(vm.globals.global[i], f(a, b), "{} {a} {b}", p::name(*op));
        }
    }
}

#[test]
fn unary_operators_and_stack_shuffles() {
    let (vm, _) = run(1, &|asm| {
        asm.push(5).op(p::NEGATELOGICAL);
        store(asm, 0).push(0).op(p::NEGATELOGICAL);
        store(asm, 1).push(5).op(p::NEGATEBINARY);
        store(asm, 2).push(5).op(p::UNARYMINUS);
        store(asm, 3).push(8).op(p::DUP).op(p::ADD);
        store(asm, 4).push(1).push(2).op(p::SWAP).op(p::SUBTRACT);
        store(asm, 5).push(9).push(10).op(p::DROP);
        store(asm, 6).op(p::NOP).op(p::TERMINATE);
    });
    assert_eq!(&vm.globals.global[..7], &[0, 1, !5, -5, 16, 1, 9]);
}

#[test]
fn compact_pushes() {
    let (vm, _) = run(1, &|asm| {
        asm.op(p::PUSHBYTE).byte(200);
        store(asm, 0).op(p::PUSH2BYTES).byte(1).byte(2).op(p::ADD);
        store(asm, 1).op(p::PUSH3BYTES).byte(1).byte(2).byte(3).op(p::ADD).op(p::ADD);
        store(asm, 2).op(p::PUSH4BYTES).byte(1).byte(2).byte(3).byte(4).op(p::ADD).op(p::ADD).op(p::ADD);
        store(asm, 3).op(p::PUSH5BYTES).byte(1).byte(2).byte(3).byte(4).byte(5);
        for _ in 0..4 {
            asm.op(p::ADD);
        }
        store(asm, 4).op(p::PUSHBYTES).byte(3).byte(7).byte(8).byte(9).op(p::SUBTRACT);
        store(asm, 5).op(p::DROP).op(p::TERMINATE);
    });
    assert_eq!(&vm.globals.global[..6], &[200, 3, 6, 10, 15, -1]);
}

#[test]
fn fixed_point_and_trigonometry() {
    let one = 1 << 16;
    let (vm, _) = run(1, &|asm| {
        asm.push(one + one / 2).push(2 * one).op(p::FIXEDMUL);
        store(asm, 0).push(one).push(4 * one).op(p::FIXEDDIV);
        store(asm, 1).push(one).push(0).op(p::FIXEDDIV);
        store(asm, 2).push(one / 4).op(p::SIN);
        store(asm, 3).push(one / 2).op(p::COS);
        store(asm, 4).push(0).push(one).op(p::VECTORANGLE);
        store(asm, 5).push(-one).push(0).op(p::VECTORANGLE);
        store(asm, 6).op(p::TERMINATE);
    });
    assert_eq!(&vm.globals.global[..7], &[3 * one, one / 4, i32::MAX, one, -one, one / 4, one / 2]);
}

/// Every variable pcode on every storage class: assign 12, apply the
/// operation with 5 (arrays at element 3), read back into global 63.
#[test]
fn variables_and_arrays_of_every_class() {
    use super::pcodes::{Store, VarOp};
    let expect = |op: VarOp| match op {
        VarOp::Assign => 5,
        VarOp::Push => 12,
        VarOp::Add => 17,
        VarOp::Sub => 7,
        VarOp::Mul => 60,
        VarOp::Div => 2,
        VarOp::Mod => 2,
        VarOp::Inc => 13,
        VarOp::Dec => 11,
        VarOp::And => 4,
        VarOp::Eor => 9,
        VarOp::Or => 13,
        VarOp::Shl => 12 << 5,
        VarOp::Shr => 0,
    };
    for pcode in 0..p::COUNT {
        let Some((op, store_class)) = p::var_op(pcode) else { continue };
        let array =
            matches!(store_class, Store::ScriptArray | Store::MapArray | Store::WorldArray | Store::GlobalArray);
        let find = |o: VarOp| (0..p::COUNT).find(|&q| p::var_op(q) == Some((o, store_class))).expect("pcode");
        let (assign, read) = (find(VarOp::Assign), find(VarOp::Push));
        let body = |asm: &mut Asm| {
            asm.chunks.push((*b"SARY", [1u8, 0].iter().copied().chain(words(&[8, 8])).collect()));
            asm.chunks.push((*b"ARAY", words(&[1, 8])));
            let index = 1;
            if array {
                asm.push(3);
            }
            asm.push(12).op_i(assign, index);
            if array {
                asm.push(3);
            }
            if !matches!(op, VarOp::Push | VarOp::Inc | VarOp::Dec) {
                asm.push(5);
            }
            asm.op_i(pcode, index);
            if op != VarOp::Push {
                if array {
                    asm.push(3);
                }
                asm.op_i(read, index);
            }
            store(asm, 63).op(p::TERMINATE);
        };
        let (vm, _) = run(1, &body);
        assert_eq!(vm.globals.global[63], expect(op), "{}", p::name(pcode));
    }
}

#[test]
fn jumps_and_case_tables() {
    let (vm, _) = run(1, &|asm| {
        asm.jump(p::GOTO, "a").push(99);
        store(asm, 0).label("a").push(1).jump(p::IFGOTO, "b").push(99);
        store(asm, 1).label("b").push(0).jump(p::IFNOTGOTO, "c").push(99);
        store(asm, 2).label("c").push(7).op(p::CASEGOTO).word(6).to("bad").op(p::CASEGOTO).word(7).to("d");
        asm.label("bad").push(99);
        store(asm, 3).label("d").push(30).op(p::CASEGOTOSORTED).align().word(3);
        asm.word(10).to("bad2").word(20).to("bad2").word(30).to("e");
        asm.label("bad2").push(99);
        store(asm, 4).label("e").push(1).op(p::GOTOSTACK);
        asm.label("j0").push(99);
        store(asm, 5).label("j1").push(42);
        store(asm, 6).push(5).op(p::CASEGOTOSORTED).align().word(1).word(4).to("bad");
        store(asm, 7).op(p::TERMINATE);
        let (j0, j1) = (asm.label_offset("j0"), asm.label_offset("j1"));
        asm.chunks.push((*b"JUMP", words(&[j0, j1])));
    });
    assert_eq!(&vm.globals.global[..8], &[0, 0, 0, 0, 0, 0, 42, 5]);
}

#[test]
fn delays_wait_their_tics() {
    for (pcode, operand) in [(p::DELAY, None), (p::DELAYDIRECT, Some(false)), (p::DELAYDIRECTB, Some(true))] {
        let body = |asm: &mut Asm| {
            match operand {
                None => asm.push(3).op(pcode),
                Some(false) => asm.op(pcode).word(3),
                Some(true) => asm.op(pcode).byte(3),
            };
            asm.op_i(p::INCGLOBALVAR, 0).op(p::TERMINATE);
        };
        // Started before tic 1, the script delays in tic 1 and resumes in tic 4.
        let (vm, _) = run(3, &body);
        assert_eq!(vm.globals.global[0], 0, "{}", p::name(pcode));
        let (vm, _) = run(4, &body);
        assert_eq!(vm.globals.global[0], 1, "{}", p::name(pcode));
    }
}

#[test]
fn random_asks_the_host_with_ordered_bounds() {
    let (vm, host) = run(1, &|asm| {
        asm.push(10).push(-5).op(p::RANDOM);
        store(asm, 0).op(p::RANDOMDIRECT).word(1).word(2);
        store(asm, 1).op(p::RANDOMDIRECTB).byte(7).byte(9);
        store(asm, 2).op(p::TERMINATE);
    });
    let draws: Vec<(i32, i32, i32)> = host
        .calls
        .iter()
        .filter_map(|c| match c {
            HostCall::Random { min, max, value } => Some((*min, *max, *value)),
            _ => None,
        })
        .collect();
    assert_eq!(draws.iter().map(|d| (d.0, d.1)).collect::<Vec<_>>(), vec![(-5, 10), (1, 2), (7, 9)]);
    for (i, (lo, hi, v)) in draws.into_iter().enumerate() {
        assert!((lo..=hi).contains(&v));
        assert_eq!(vm.globals.global[i], v);
    }
}

#[test]
fn line_specials_reach_the_host_with_their_arguments() {
    let (vm, host) = run(1, &|asm| {
        asm.push(1).op_i(p::LSPEC1, 132);
        asm.push(1).push(2).push(3).push(4).push(5).op_i(p::LSPEC5, 119);
        asm.op_i(p::LSPEC2DIRECT, 177).word(10).word(100);
        asm.op(p::LSPEC3DIRECTB).byte(229).byte(1).byte(2).byte(3);
        asm.push(1).push(2).push(3).push(4).push(5).op_i(p::LSPEC5RESULT, 176);
        store(asm, 0).push(0).push(0).push(0).push(0).push(0).op(p::LSPEC5EX).word(300);
        asm.push(0).push(0).push(0).push(0).push(9).op(p::LSPEC5EXRESULT).word(301);
        store(asm, 1).op(p::TERMINATE);
    });
    assert_eq!(host.specials(132), vec![[1, 0, 0, 0, 0]]);
    assert_eq!(host.specials(119), vec![[1, 2, 3, 4, 5]]);
    assert_eq!(host.specials(177), vec![[10, 100, 0, 0, 0]]);
    assert_eq!(host.specials(229), vec![[1, 2, 3, 0, 0]]);
    assert_eq!(host.specials(176), vec![[1, 2, 3, 4, 5]]);
    assert_eq!(host.specials(300), vec![[0; 5]]);
    assert_eq!(host.specials(301), vec![[0, 0, 0, 0, 9]]);
    assert_eq!(&vm.globals.global[..2], &[1, 1], "the recording host's specials return 1");
}

/// Every game pcode's stack form gets its arguments in source order, and
/// leaves the host's value when it should; direct forms arrive as stack forms.
#[test]
fn game_pcodes_reach_the_host() {
    for pcode in 0..p::COUNT {
        let Some((op, direct)) = p::game_op(pcode) else { continue };
        let n = i32::from(op.args);
        let (_, host) = run(1, &|asm| {
            if direct {
                asm.op(pcode);
                let immediates = match p::operands(pcode) {
                    p::Operands::Words(k) => i32::from(k),
                    other => panic!("{other:?}"),
                };
                for i in 0..immediates {
                    asm.word(i + 1);
                }
            } else {
                for i in 0..n {
                    asm.push(i + 1);
                }
                asm.op(pcode);
            }
            if op.pushes {
                store(asm, 0);
            }
            asm.op(p::TERMINATE);
        });
        let calls = host.game_calls(op.pcode);
        assert_eq!(calls.len(), 1, "{}", p::name(pcode));
        let HostCall::Game { args, .. } = calls[0] else { unreachable!() };
        assert_eq!(args.len(), usize::from(op.args), "{}", p::name(pcode));
        assert_eq!(args.first().copied(), if n > 0 { Some(1) } else { None }, "{}", p::name(pcode));
    }
}

#[test]
fn printing_builds_text_for_the_host() {
    let (vm, host) = run(1, &|asm| {
        let hello = asm.string("hello ");
        asm.op(p::BEGINPRINT).push(hello).op(p::PRINTSTRING).push(42).op(p::PRINTNUMBER);
        asm.push(i32::from(b'!')).op(p::PRINTCHARACTER).op(p::ENDPRINT);
        asm.op(p::BEGINPRINT).push(3 << 15).op(p::PRINTFIXED).push(5).op(p::PRINTBINARY);
        asm.push(255).op(p::PRINTHEX).push(hello).op(p::PRINTLOCALIZED).op(p::ENDPRINTBOLD);
        asm.op(p::BEGINPRINT).push(hello).op(p::PRINTSTRING).op(p::ENDLOG);
        asm.op(p::BEGINPRINT).push(hello).op(p::PRINTSTRING).op(p::SAVESTRING).op(p::DUP).op(p::STRLEN);
        store(asm, 0);
        store(asm, 1).push(hello).op(p::TAGSTRING).op(p::STRLEN);
        store(asm, 2);
        // HudMessage(s:"hi"; 1, 2, 3, 0.5, 0.5, 2.0, 0.25): six parameters, one optional.
        asm.op(p::BEGINPRINT).push(hello).op(p::PRINTSTRING).op(p::MOREHUDMESSAGE);
        for v in [1, 2, 3, 1 << 15, 1 << 15, 2 << 16] {
            asm.push(v);
        }
        asm.op(p::OPTHUDMESSAGE).push(1 << 14).op(p::ENDHUDMESSAGEBOLD);
        // Characters of map array 0 ("ok"), then of its second element on.
        asm.op(p::BEGINPRINT).push(0).push(0).op(p::PRINTMAPCHARARRAY);
        asm.push(0).push(0).push(1).push(1).op(p::PRINTMAPCHRANGE).op(p::ENDPRINT).op(p::TERMINATE);
        asm.chunks.push((*b"ARAY", words(&[0, 4])));
        asm.chunks.push((*b"AINI", words(&[0, i32::from(b'o'), i32::from(b'k')])));
    });
    assert_eq!(host.printed(), vec!["hello 42!", "1.5101FFhello ", "hello ", "hello ", "okk"]);
    let kinds: Vec<PrintKind> = host
        .calls
        .iter()
        .filter_map(|c| match c {
            HostCall::Print { kind, .. } => Some(kind.clone()),
            _ => None,
        })
        .collect();
    let hud = PrintKind::HudMessage { bold: true, params: vec![1, 2, 3, 1 << 15, 1 << 15, 2 << 16, 1 << 14] };
    assert_eq!(kinds, vec![PrintKind::Print, PrintKind::Bold, PrintKind::Log, hud, PrintKind::Print]);
    assert_eq!(vm.globals.global[0], 6, "SAVESTRING's string is 6 long");
    assert_eq!(vm.strings.get(vm.globals.global[1]), Some("hello "));
    assert_eq!(vm.globals.global[2], 6);
}

#[test]
fn functions_call_return_and_recurse() {
    let (vm, _) = run(1, &|asm| {
        asm.push(5).op_i(p::CALL, 0);
        store(asm, 0).push(3).op_i(p::CALLDISCARD, 0).op_i(p::CALL, 1);
        store(asm, 1).op_i(p::PUSHFUNCTION, 0).push(4).op(p::SWAP).op(p::CALLSTACK);
        store(asm, 2).op(p::TERMINATE);
        // function 0: factorial(n) with one local
        let f = asm.function(1, 1, true) as i32;
        asm.op_i(p::PUSHSCRIPTVAR, 0).jump(p::IFGOTO, "rec").push(1).op(p::RETURNVAL);
        asm.label("rec").op_i(p::PUSHSCRIPTVAR, 0).op_i(p::ASSIGNSCRIPTVAR, 1);
        asm.op_i(p::PUSHSCRIPTVAR, 0).push(1).op(p::SUBTRACT).op_i(p::CALL, f);
        asm.op_i(p::PUSHSCRIPTVAR, 1).op(p::MULTIPLY).op(p::RETURNVAL);
        // function 1: returns nothing; a value call of it leaves 0
        asm.function(0, 0, false);
        asm.op_i(p::INCGLOBALVAR, 5).op(p::RETURNVOID);
    });
    assert_eq!(&vm.globals.global[..3], &[120, 0, 24]);
    assert_eq!(vm.globals.global[5], 1);
}

#[test]
fn extended_functions_go_to_the_vm_or_the_host() {
    let (vm, host) = run(1, &|asm| {
        let (abc, abd, closed) = (asm.string("abc"), asm.string("ABD"), asm.string("two"));
        asm.push(abc).push(1).callfunc(2, 15);
        store(asm, 0).push(abc).push(abd).callfunc(2, 64);
        store(asm, 1).push(abc).push(abd).push(2).callfunc(3, 64);
        store(asm, 2).push(abc).push(2).callfunc(2, 65);
        store(asm, 3).push(abc).push(1).push(5).callfunc(3, 67);
        store(asm, 4).push(7).push(8).callfunc(2, 61);
        store(asm, 5).push(closed).push(0).push(11).callfunc(3, 45);
        store(asm, 6).op(p::TERMINATE);
        asm.named_script("two", 0, 1).op_i(p::PUSHSCRIPTVAR, 0);
        store(asm, 7).op(p::TERMINATE);
    });
    assert_eq!(vm.globals.global[0], i32::from(b'b'));
    assert_eq!(vm.globals.global[1], -1, "stricmp(abc, ABD)");
    assert_eq!(vm.globals.global[2], 0, "stricmp(abc, ABD, 2)");
    assert_eq!(vm.strings.get(vm.globals.global[3]), Some("ab"));
    assert_eq!(vm.strings.get(vm.globals.global[4]), Some("bc"));
    assert_eq!(host.calls.iter().filter(|c| matches!(c, HostCall::Function { id: 61, .. })).count(), 1);
    assert_eq!(vm.globals.global[6], 1, "ACS_NamedExecuteAlways started \"two\"");
    assert!(vm.scripts_in_order().contains(&-1));
}

/// Every pcode `supported` admits has an implementation: each runs once,
/// with zeros on the stack and zero (or next-instruction) operands, and may
/// fault on those values but never for want of a case in the interpreter.
#[test]
fn every_supported_pcode_is_implemented() {
    let supported: Vec<u16> = (0..p::COUNT).filter(|&q| p::supported(q)).collect();
    let game = supported.iter().filter(|&&q| p::game_op(q).is_some()).count();
    let missing: Vec<&str> = (0..p::COUNT).filter(|&q| !p::supported(q)).map(p::name).collect();
    eprintln!("not supported: {}", missing.join(" "));
    assert_eq!((supported.len(), game), (330, 107), "update ARCHITECTURE.md's counts");
    let mut unimplemented = Vec::new();
    for pcode in supported {
        let mut asm = Asm::new(Layout::Compact);
        asm.script(1, 0, 0);
        for _ in 0..12 {
            asm.push(0);
        }
        asm.op(pcode);
        match p::operands(pcode) {
            p::Operands::None => {}
            p::Operands::Index => {
                asm.index(0);
            }
            p::Operands::Words(n) | p::Operands::SpecialDirect(n) => {
                if matches!(p::operands(pcode), p::Operands::SpecialDirect(_)) {
                    asm.index(0);
                }
                for _ in 0..n {
                    asm.word(0);
                }
            }
            p::Operands::Jump => {
                asm.to("next");
            }
            p::Operands::CaseGoto => {
                asm.word(0).to("next");
            }
            p::Operands::SortedCases => {
                asm.align().word(0);
            }
            p::Operands::Bytes(n) => {
                for _ in 0..n {
                    asm.byte(0);
                }
            }
            p::Operands::CountedBytes => {
                asm.byte(0);
            }
            p::Operands::CallFunc => {
                asm.index(0).byte(61).byte(0);
            }
        }
        asm.label("next").op(p::TERMINATE);
        asm.function(0, 0, false);
        asm.op(p::RETURNVOID);
        asm.chunks.push((*b"JUMP", words(&[8])));
        let module = Module::load(&asm.build(), "test").unwrap_or_else(|e| panic!("{}: {e}", p::name(pcode)));
        let mut host = RecordingHost::default();
        let mut vm = Vm::new(module, &host).unwrap_or_else(|e| panic!("{e}"));
        vm.execute(1, &[], Activator::World, false);
        vm.tick(&mut host);
        if vm.warnings.iter().any(|w| w.contains("no implementation")) {
            unimplemented.push(p::name(pcode));
        }
    }
    assert!(unimplemented.is_empty(), "{unimplemented:?}");
}
