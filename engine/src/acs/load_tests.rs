//! The loader: every layout reads the same program the same way, every
//! chunk lands where it should, every malformed lump is refused with its
//! problem named, and no input makes it (or the VM after it) panic.

use proptest::prelude::*;

use super::asm_tests::run_in;
use super::load::Format;
use super::pcodes as p;
use super::record::RecordingHost;
use super::test_asm::{name_table, strl, words, Asm, Layout};
use super::*;

fn load(bytes: &[u8]) -> Result<Module, String> {
    Module::load(bytes, "BEHAVIOR").map_err(|e| e.to_string())
}

fn err(asm: &mut Asm) -> String {
    load(&asm.build()).expect_err("the lump is refused")
}

#[test]
fn every_layout_runs_the_same_program() {
    let body = |asm: &mut Asm| {
        let s = asm.string("hi");
        asm.push(2).push(3).op(p::MULTIPLY).op_i(p::ASSIGNGLOBALVAR, 0);
        asm.op(p::BEGINPRINT).push(s).op(p::PRINTSTRING).op(p::ENDPRINT).op(p::TERMINATE);
    };
    for (layout, format) in [
        (Layout::Compact, Format::LittleEnhanced),
        (Layout::Enhanced, Format::Enhanced),
        (Layout::BareEnhanced, Format::Enhanced),
        (Layout::Old, Format::Old),
    ] {
        let (vm, host) = run_in(layout, 1, &body);
        assert_eq!(vm.module.format, format, "{layout:?}");
        assert_eq!(vm.globals.global[0], 6, "{layout:?}");
        assert_eq!(host.printed(), vec!["hi"], "{layout:?}");
    }
}

#[test]
fn chunks_fill_the_module() {
    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 1, 2).op(p::TERMINATE);
    asm.script(2, 4, 0).op(p::TERMINATE);
    asm.named_script("door", 0, 0).op(p::TERMINATE);
    asm.function(2, 3, true);
    asm.push(0).op(p::RETURNVAL);
    asm.string("a\\x41\\n\\101");
    asm.chunks.push((*b"FNAM", name_table(&["twice".into()])));
    asm.chunks.push((*b"SVCT", [1u8, 0, 30, 0].to_vec()));
    asm.chunks.push((*b"SFLG", [2u8, 0, 1, 0].to_vec()));
    asm.chunks.push((*b"MINI", words(&[4, 7, 8])));
    asm.chunks.push((*b"ARAY", words(&[2, 3])));
    asm.chunks.push((*b"AINI", words(&[2, 5, 6, 7, 8])));
    asm.chunks.push((*b"MSTR", words(&[4])));
    asm.chunks.push((*b"ASTR", words(&[2])));
    asm.chunks.push((*b"MEXP", name_table(&["x".into(), "y".into()])));
    let m = load(&asm.build()).unwrap_or_else(|e| panic!("{e}"));
    let numbers: Vec<i32> = m.scripts.iter().map(|s| s.number).collect();
    assert_eq!(numbers, vec![-1, 1, 2]);
    assert_eq!(m.script(-1).and_then(|s| s.name.clone()).as_deref(), Some("door"));
    assert_eq!(m.named("DOOR"), Some(-1));
    let one = m.script(1).expect("script 1");
    assert_eq!((one.kind, one.args, one.vars), (ScriptKind::Open, 2, 30));
    let two = m.script(2).expect("script 2");
    assert_eq!((two.kind, two.flags, two.vars), (ScriptKind::Enter, 1, 20));
    assert_eq!(m.functions[0].name.as_deref(), Some("twice"));
    assert_eq!((m.functions[0].args, m.functions[0].locals, m.functions[0].returns), (2, 3, true));
    assert_eq!(m.strings, vec!["aA\nA"]);
    assert_eq!(&m.map_vars[..7], &[0, 0, 0, 0, 7, 8, 0]);
    assert_eq!(m.arrays[0].var, 2);
    assert_eq!(m.arrays[0].init, vec![5, 6, 7], "AINI's values beyond the size are dropped");
    assert_eq!((m.string_vars.clone(), m.string_arrays.clone()), (vec![4], vec![2]));
    assert_eq!(m.map_var_names.get(&1).map(String::as_str), Some("y"));
}

/// STRE scrambles each string with a key from its offset (ZDoom's
/// `UnencryptStrings`); scrambling a STRL by hand must read back the same.
#[test]
fn encrypted_strings_read_back() {
    let strings = vec!["Hello".to_string(), "world!".to_string()];
    let mut data = strl(&strings);
    for s in 0..2 {
        let ofs = u32::from_le_bytes(data[12 + s * 4..16 + s * 4].try_into().expect("4 bytes")) as usize;
        let key = ofs.wrapping_mul(157135) as u8;
        for i in 0..=strings[s].len() {
            data[ofs + i] ^= key.wrapping_add((i / 2) as u8);
        }
    }
    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    asm.chunks.push((*b"STRE", data));
    assert_eq!(load(&asm.build()).map(|m| m.strings), Ok(strings));
}

#[test]
fn refusals_name_the_problem() {
    assert_eq!(load(b"ACS").err(), Some("BEHAVIOR: 3 bytes is too short for an ACS header (8 bytes)".into()));
    assert_eq!(load(b"WAD2\0\0\0\0").err(), Some("BEHAVIOR: header \"WAD2\" is not ACS\\0, ACSE or ACSe".into()));
    let mut bare = b"ACSE".to_vec();
    bare.extend(words(&[1000]));
    assert_eq!(load(&bare).err(), Some("BEHAVIOR: directory offset 1000 lies outside the lump".into()));
    let mut overrun = b"ACSe".to_vec();
    overrun.extend(words(&[8]));
    overrun.extend(b"SPTR");
    overrun.extend(words(&[100]));
    assert_eq!(
        load(&overrun).err(),
        Some("BEHAVIOR: chunk SPTR at byte 8 declares 100 bytes, past the end of the chunks at byte 16".into())
    );
    let mut old = b"ACS\0".to_vec();
    old.extend(words(&[8, 1_000_000]));
    assert_eq!(
        load(&old).err(),
        Some(
            "BEHAVIOR: the old-format script directory at byte 8 lists 1000000 scripts, more than the lump holds"
                .into()
        )
    );
    let mut old_string = b"ACS\0".to_vec();
    old_string.extend(words(&[8, 0, 1, 20]));
    old_string.extend(b"abc");
    assert_eq!(
        load(&old_string).err(),
        Some("BEHAVIOR: string 0 at byte 20 is not terminated inside its table".into())
    );

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    asm.chunks.push((*b"LOAD", b"zcommon\0mylib\0".to_vec()));
    assert_eq!(
        err(&mut asm),
        "BEHAVIOR: the module loads the libraries zcommon, mylib; ACS libraries are not supported"
    );

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    asm.chunks.push((*b"FUNC", vec![0, 0, 0, 1, 0, 0, 0, 0]));
    asm.chunks.push((*b"FNAM", name_table(&["helper".into()])));
    assert_eq!(err(&mut asm), "BEHAVIOR: function helper is imported from a library; ACS libraries are not supported");

    let mut asm = Asm::new(Layout::Compact);
    asm.op(p::TERMINATE);
    asm.chunks.push((*b"SPTR", [2u8, 0, 0, 0].iter().copied().chain(words(&[4000])).collect()));
    assert_eq!(err(&mut asm), "BEHAVIOR: script 2 starts at byte 4000, outside the code (bytes 0..12)");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).byte(255).byte(1);
    assert_eq!(err(&mut asm), "BEHAVIOR: unknown pcode 4081 at byte 8");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(134);
    assert_eq!(err(&mut asm), "BEHAVIOR: pcode 134 (CONSOLECOMMAND) at byte 8 is not supported");

    let mut asm = Asm::new(Layout::Enhanced);
    asm.script(1, 0, 0).op(p::PUSHNUMBER);
    assert_eq!(err(&mut asm), "BEHAVIOR: PUSHNUMBER at byte 8 runs past the end of the code (byte 12)");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::NOP);
    assert_eq!(err(&mut asm), "BEHAVIOR: a pcode at byte 12 runs past the end of the code (byte 12)");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::GOTO).word(5000);
    assert_eq!(err(&mut asm), "BEHAVIOR: GOTO at byte 8 jumps to byte 5000, outside the code");

    let mut asm = Asm::new(Layout::Enhanced);
    asm.script(1, 0, 0).push(1).op_i(26, 200).op(p::TERMINATE);
    assert_eq!(err(&mut asm), "BEHAVIOR: ASSIGNMAPVAR at byte 16 uses map variable 200; only 128 exist");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op_i(p::CALL, 3).op(p::TERMINATE);
    assert_eq!(err(&mut asm), "BEHAVIOR: CALL at byte 8 uses function 3; only 0 exist");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    asm.chunks.push((*b"ARAY", words(&[200, 4])));
    let message = err(&mut asm);
    assert!(message.starts_with("BEHAVIOR: chunk ARAY at byte "), "{message}");
    assert!(message.ends_with(": array 0 is map variable 200; only 128 exist"), "{message}");

    let mut asm = Asm::new(Layout::Compact);
    asm.script(1, 0, 0).op(p::TERMINATE);
    asm.chunks.push((*b"MINI", words(&[127, 1, 2])));
    assert!(err(&mut asm).ends_with(": initialises map variables 127..129, only 128 exist"));
}

/// The program `every_layout_runs_the_same_program` runs, as a fuzzing seed.
fn seed_lump(layout: Layout) -> Vec<u8> {
    let mut asm = Asm::new(layout);
    let s = asm.string("text");
    asm.script(1, 1, 0).label("top").push(2).push(3).op(p::MULTIPLY).op_i(p::ASSIGNGLOBALVAR, 0);
    asm.op(p::BEGINPRINT).push(s).op(p::PRINTSTRING).op(p::ENDPRINT);
    asm.push(1)
        .op_i(p::CALL, 0)
        .op(p::DROP)
        .push(1)
        .op(p::DELAY)
        .push(7)
        .op(p::CASEGOTOSORTED)
        .align()
        .word(1)
        .word(7)
        .to("top");
    asm.function(1, 1, true);
    asm.op_i(p::PUSHSCRIPTVAR, 0).op(p::RETURNVAL);
    asm.chunks.push((*b"ARAY", words(&[3, 4])));
    asm.chunks.push((*b"SARY", [1u8, 0].iter().copied().chain(words(&[2])).collect()));
    asm.build()
}

/// Loads `bytes`; if they load, runs the OPEN scripts for a few tics.
fn load_and_run(bytes: &[u8]) {
    let Ok(module) = Module::load(bytes, "fuzz") else { return };
    let mut host = RecordingHost::default();
    let Ok(mut vm) = Vm::new(module, &host) else { return };
    vm.start_typed(ScriptKind::Open, Activator::World, false, 0);
    for number in vm.module.scripts.iter().map(|s| s.number).collect::<Vec<_>>() {
        vm.execute(number, &[1, 2, 3], Activator::Thing(1), true);
    }
    for _ in 0..2 {
        vm.tick(&mut host);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_bytes_never_panic(header in 0usize..4, body in proptest::collection::vec(any::<u8>(), 0..300)) {
        let mut bytes = [b"ACS\0".to_vec(), b"ACSE".to_vec(), b"ACSe".to_vec(), Vec::new()][header].clone();
        bytes.extend(body);
        load_and_run(&bytes);
    }

    #[test]
    fn corrupted_modules_never_panic(
        layout in 0usize..4,
        flips in proptest::collection::vec((any::<usize>(), any::<u8>()), 1..6),
        cut in any::<usize>(),
    ) {
        let layout = [Layout::Compact, Layout::Enhanced, Layout::BareEnhanced, Layout::Old][layout];
        let mut bytes = seed_lump(layout);
        for (at, value) in flips {
            let n = bytes.len();
            bytes[at % n] = value;
        }
        load_and_run(&bytes);
        let n = bytes.len();
        load_and_run(&bytes[..cut % n]);
    }
}

/// Every prefix and every single-byte change of the shipped lumps loads or
/// is refused without a panic (when the fixtures are present).
#[test]
fn truncated_and_altered_shipped_lumps_never_panic() {
    let Some(dir) = crate::scenario::shipped_dir() else { return };
    for file in ["basic.wad", "defend_the_center.wad", "deathmatch.wad", "basic_notifications.wad"] {
        let wad = crate::wad::Wad::open(&dir.join(file)).unwrap_or_else(|e| panic!("{e}"));
        let index = behavior_for_map(&wad, "MAP01").expect("BEHAVIOR");
        let lump = wad.bytes(index).to_vec();
        for cut in 0..lump.len() {
            load_and_run(&lump[..cut]);
        }
        for at in 0..lump.len() {
            let mut altered = lump.clone();
            altered[at] ^= 0xa5;
            load_and_run(&altered);
        }
    }
}
