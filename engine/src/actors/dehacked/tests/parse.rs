//! Each section kind read from a small patch; every refusal with its file
//! and line; warnings for what a patch says that Sightline does not take;
//! and no panic on any bytes.

use proptest::prelude::*;

use super::*;

const HEAD: &str = "Patch File for DeHackEd v3.0\nDoom version = 19\nPatch format = 6\n\n";

fn patch(body: &str) -> Patch {
    parse(format!("{HEAD}{body}").as_bytes(), "test.deh").unwrap_or_else(|e| panic!("{e}"))
}

fn error(body: &str) -> String {
    parse(format!("{HEAD}{body}").as_bytes(), "test.deh").expect_err("the patch should be refused").to_string()
}

fn kinds(p: &Patch) -> Vec<&SectionKind> {
    p.sections.iter().map(|s| &s.kind).collect()
}

#[test]
fn the_header_and_a_thing() {
    let p =
        patch("# a comment\nThing 12 (Imp)\nHit points = 75\nSpeed = 10 # faster\nBits = SOLID+SHOOTABLE|COUNTKILL\n");
    assert_eq!(p.header, Header { version: Some("v3.0".into()), doom_version: Some(19), patch_format: Some(6) });
    let fields = vec![
        Field { line: 7, key: ThingField::Health, value: 75 },
        Field { line: 8, key: ThingField::Speed, value: 10 },
        Field { line: 9, key: ThingField::Bits, value: 0x400006 },
    ];
    assert_eq!(kinds(&p), [&SectionKind::Thing { number: 12, name: Some("Imp".into()), fields }]);
    assert_eq!(p.sections[0].line, 6);
    assert!(p.warnings.is_empty());
}

#[test]
fn frames_pointers_sounds_ammo_weapons_cheats_and_misc() {
    let p = patch(
        "Frame 185\nSprite subnumber = 32773\nNext frame = 0\n\n\
         Pointer 23 (Frame 100)\nCodep Frame = 185\n\n\
         Sound 1\nValue = 80\n\n\
         Ammo 2\nMax ammo = 400\nPer ammo = 40\n\n\
         Weapon 3\nAmmo type = 1\nFiring frame = 52\n\n\
         Cheat 0\nGod mode = iddqx\nNo Clipping 1 = idclip\n\n\
         Misc 0\nMax Health = 300\nMonsters Infight = 221\n",
    );
    let k = kinds(&p);
    assert_eq!(k.len(), 7);
    assert_eq!(
        k[0],
        &SectionKind::Frame {
            number: 185,
            fields: vec![
                Field { line: 6, key: FrameField::Subnumber, value: 32773 },
                Field { line: 7, key: FrameField::Next, value: 0 }
            ]
        }
    );
    assert_eq!(k[1], &SectionKind::Pointer { frame: 100, code_frames: vec![Field { line: 10, key: (), value: 185 }] });
    assert_eq!(
        k[2],
        &SectionKind::Sound { number: 1, fields: vec![Field { line: 13, key: SoundField::Priority, value: 80 }] }
    );
    let SectionKind::Ammo { number: 2, fields } = k[3] else { panic!("{:?}", k[3]) };
    assert_eq!(
        fields.iter().map(|f| (f.key, f.value)).collect::<Vec<_>>(),
        [(AmmoField::Max, 400), (AmmoField::PerClip, 40)]
    );
    let SectionKind::Weapon { number: 3, fields } = k[4] else { panic!("{:?}", k[4]) };
    assert_eq!(fields[1].key, WeaponField::Flash);
    let cheats = vec![(24, "God mode".to_string(), "iddqx".to_string()), (25, "No Clipping 1".into(), "idclip".into())];
    assert_eq!(k[5], &SectionKind::Cheat { cheats });
    let SectionKind::Misc { fields } = k[6] else { panic!() };
    assert_eq!((fields[0].key, fields[0].value, fields[1].value), (MiscField::MaxHealth, 300, 221));
}

#[test]
fn a_text_block_counts_raw_characters_across_lines() {
    // 12 characters "E1M1: Hangar" become 12, a newline among them; CR LF
    // counts as one character, as in Chocolate.
    let p = patch("Text 12 12\r\nE1M1: HangarC1M1:\r\nPrison\r\n\r\nText 4 4\nTROOFOOB\n");
    assert_eq!(
        kinds(&p),
        [
            &SectionKind::Text { from: "E1M1: Hangar".into(), to: "C1M1:\nPrison".into() },
            &SectionKind::Text { from: "TROO".into(), to: "FOOB".into() },
        ]
    );
    assert_eq!(p.sections[1].line, 9);
}

#[test]
fn bex_strings_pars_code_pointers_and_renames() {
    let p = patch(
        "[STRINGS]\nHUSTR_E1M1 = C1M1: Outer Prison\n# inside\nE1TEXT = one \\\n    two\\nthree\n\n\
         [PARS]\npar 1 1 30 # 00:30\npar 7 90\n\n\
         [CODEPTR]\nFRAME 185 = SPosAttack\nFrame 186 = NULL\n\n\
         [SPRITES]\nTROO = FOOB\n",
    );
    let k = kinds(&p);
    let strings = vec![
        (6, "HUSTR_E1M1".to_string(), "C1M1: Outer Prison".to_string()),
        (8, "E1TEXT".into(), "one two\nthree".into()),
    ];
    assert_eq!(k[0], &SectionKind::Strings { entries: strings });
    let pars = vec![
        Par { line: 12, episode: Some(1), map: 1, seconds: 30 },
        Par { line: 13, episode: None, map: 7, seconds: 90 },
    ];
    assert_eq!(k[1], &SectionKind::Pars { entries: pars });
    assert_eq!(
        k[2],
        &SectionKind::CodePointers { entries: vec![(16, 185, Some("SPosAttack".into())), (17, 186, None)] }
    );
    assert_eq!(
        k[3],
        &SectionKind::Renames { kind: RenameKind::Sprites, entries: vec![(20, "TROO".into(), "FOOB".into())] }
    );
}

#[test]
fn unknown_fields_and_stray_lines_are_warnings() {
    let p = patch("Thing 1\nHit points = 90\nFlavour = 3\nthis is not an assignment\n\nSprite 3\nOffset = 1234\n");
    let w: Vec<String> = p.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(
        w,
        [
            "test.deh:7: warning: Thing 1: no field named `Flavour` (ignored)",
            "test.deh:8: warning: `this is not an assignment` is not `key = value` (ignored)",
            "test.deh:10: warning: Sprite sections (offsets into doom.exe) are not supported: rename sprites with Text or [SPRITES]",
        ]
    );
    let no_header = parse(b"[PARS]\npar 1 2 3\n", "bex.deh").unwrap();
    assert_eq!(no_header.header.version, None);
    assert_eq!(no_header.warnings.len(), 1);
}

#[test]
fn refusals_name_the_file_the_line_and_the_element() {
    let cases = [
        ("Thing 3\nHit points = lots\n", "test.deh:6: Hit points: `lots` is not a number"),
        ("Thing 138\n", "test.deh:5: Thing 138 is out of range (1 to 137)"),
        ("Thing 0\n", "test.deh:5: Thing 0 is out of range (1 to 137)"),
        ("Frame 967\nDuration = 3\n", "test.deh:5: Frame 967 is out of range (0 to 966)"),
        ("Frame 12\nNext frame = 2000\n", "test.deh:6: Next frame: frame 2000 is out of range (0 to 966)"),
        ("Thing 5\nDeath sound = 109\n", "test.deh:6: Death sound: sound 109 is out of range (0 to 108)"),
        ("Frame 12\nSprite number = 138\n", "test.deh:6: Sprite number: sprite 138 is out of range (0 to 137)"),
        ("Thing 5\nBits = SOLID+WOBBLY\n", "test.deh:6: Bits: `WOBBLY` is neither a number nor a flag name"),
        ("Monster 5\nHit points = 3\n", "test.deh:5: unknown section `Monster 5`"),
        ("[FROBS]\n", "test.deh:5: unknown section `[FROBS]`"),
        ("Weapon 9\n", "test.deh:5: Weapon 9 is out of range (0 to 8)"),
        ("Pointer 3 (Thing 4)\n", "test.deh:5: `Pointer 3 (Thing 4)`: a pointer is `Pointer N (Frame M)`"),
        ("Text 10 10\nshort\n", "test.deh:5: Text 10 10: the file ends after 6 of its 20 characters"),
        ("Include other.deh\n", "test.deh:5: Include is not supported: give the included patch as its own --deh file"),
        ("[PARS]\npar 1 x 30\n", "test.deh:6: `x` is not a number"),
        ("[CODEPTR]\nFRAME 5000 = Look\n", "test.deh:6: FRAME 5000: frame 5000 is out of range (0 to 966)"),
        ("Thing 2\nSpeed = 99999999999\n", "test.deh:6: Speed: `99999999999` is not a number doom.exe can hold"),
    ];
    for (body, message) in cases {
        assert_eq!(error(body), message, "{body}");
    }
    let old = parse(b"Patch File for DeHackEd v2.0\n", "old.deh").unwrap_err();
    assert_eq!(old.to_string(), "old.deh:1: DeHackEd v2.0 patch: only v2.3 and v3.0 text patches can be read");
}

/// A patch of every kind, for the fuzzing below.
const SAMPLE: &str = "Patch File for DeHackEd v3.0\nDoom version = 19\nPatch format = 6\n\n\
    Thing 12 (Imp)\nHit points = 75\nSpeed = 10\nWidth = 1310720\nBits = 4194310\nInitial frame = 442\n\
    Alert sound = 39\nRespawn frame = 0\n\n\
    Frame 185\nSprite subnumber = 32773\nDuration = 2\nNext frame = 186\n\n\
    Frame 1\nDuration = 0\nNext frame = 0\n\n\
    Pointer 5 (Frame 174)\nCodep Frame = 185\n\n\
    Weapon 3\nAmmo type = 2\nFiring frame = 52\n\n\
    Ammo 0\nPer ammo = 20\nMax ammo = 300\n\n\
    Misc 0\nGreen Armor Class = 2\nBFG Cells/Shot = 30\nMonsters Infight = 221\n\n\
    Cheat 0\nGod mode = iddqx\n\n\
    Text 4 4\nTROOFOOB\n\n\
    Frame 966\nDuration = 1\n\n\
    [STRINGS]\nHUSTR_E1M1 = Somewhere \\\n  else\nGOTARMOR = Vest.\n\n\
    [PARS]\npar 1 1 30\npar 12 200\n\n\
    [CODEPTR]\nFRAME 176 = Scream\nFRAME 177 = NULL\n";

#[test]
fn the_sample_patch_applies() {
    let (table, report) = ActorTable::doom().with_dehacked(SAMPLE, "sample.deh").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(table.get("imp").unwrap().health, 75);
    assert_eq!(report.pars.map(12), Some(200));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Any prefix of the sample, with bytes overwritten, parses to a patch
    /// or an error and applies to a table or an error: never a panic.
    #[test]
    fn no_bytes_make_it_panic(
        cut in 0..SAMPLE.len(),
        edits in prop::collection::vec((0..SAMPLE.len(), any::<u8>()), 0..8),
    ) {
        let mut bytes = SAMPLE.as_bytes()[..cut].to_vec();
        for (at, b) in edits {
            if at < bytes.len() {
                bytes[at] = b;
            }
        }
        if let Ok(p) = parse(&bytes, "fuzz.deh") {
            let mut d = Dehacked::new(ActorTable::doom().as_ref().clone());
            let _ = d.apply(&p);
        }
    }

    #[test]
    fn random_bytes_do_not_make_it_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let _ = parse(&bytes, "noise.deh");
        let mut text = HEAD.as_bytes().to_vec();
        text.extend(&bytes);
        if let Ok(p) = parse(&text, "noise.deh") {
            let _ = Dehacked::new(ActorTable::doom().as_ref().clone()).apply(&p);
        }
    }
}
