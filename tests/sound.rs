//! Sound from Freedoom's WADs: every sound lump of both IWADs decodes (or,
//! for the few empty ones, is the error that says so), every music lump is
//! MIDI or MUS the synthesizer takes and plays; a replayed demo's audio is
//! the same bytes twice through the binary's own path (`tests/outpost.rs`
//! checks what a run sounds like: sound at the events, silence between).

use sightline::sound::bank::midi_of;
use sightline::sound::dmx::{decode, DmxError};
use sightline::sound::music::{find_soundfont, load_soundfont, Music};
use sightline::wad::Wad;

fn iwad(name: &str) -> Wad {
    Wad::open(&sightline_tests::freedoom_wads::path(name)).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn every_sound_lump_of_both_iwads_decodes_or_has_no_samples() {
    for name in ["freedoom1.wad", "freedoom2.wad"] {
        let wad = iwad(name);
        let (mut decoded, mut empty, mut rates) = (0, Vec::new(), std::collections::BTreeSet::new());
        for (i, lump) in wad.lumps.iter().enumerate().filter(|(_, l)| l.name.starts_with("DS")) {
            match decode(wad.bytes(i)) {
                Ok(s) => {
                    decoded += 1;
                    rates.insert(s.rate);
                    assert!(
                        !s.data.is_empty() && s.data.iter().all(|v| (-1.0..1.0).contains(v)),
                        "{name}: {}",
                        lump.name
                    );
                }
                // Freedoom leaves a few sounds without samples (0 or 4 bytes).
                Err(e @ (DmxError::Empty | DmxError::TooShort(_) | DmxError::NoSamples)) => {
                    empty.push(format!("{} ({e})", lump.name))
                }
                Err(e) => panic!("{name}: {}: {e}", lump.name),
            }
        }
        println!("{name}: {decoded} sounds at rates {rates:?}; empty: {empty:?}");
        assert!(decoded > 60, "{name}: only {decoded} sounds");
        assert!(empty.len() < 5, "{name}: {empty:?}");
    }
}

#[test]
#[cfg_attr(freedoom_missing, ignore = "needs Freedoom's WADs: apt-get install freedoom, or set SIGHTLINE_DOOM_DIR")]
fn every_music_lump_of_both_iwads_plays() {
    // CI requires a SoundFont (it installs one); elsewhere the synthesis part
    // says it is skipped and why.
    let font = find_soundfont(None).map(|p| load_soundfont(&p).unwrap_or_else(|e| panic!("{e}")));
    if font.is_none() {
        assert!(std::env::var_os("SIGHTLINE_REQUIRE_SOUNDFONT").is_none(), "no SoundFont installed");
        println!("SKIPPED the synthesis: no SoundFont (apt-get install timgm6mb-soundfont)");
    }
    for name in ["freedoom1.wad", "freedoom2.wad"] {
        let wad = iwad(name);
        let mut songs = 0;
        for (i, lump) in wad.lumps.iter().enumerate().filter(|(_, l)| l.name.starts_with("D_")) {
            let midi = midi_of(wad.bytes(i)).unwrap_or_else(|e| panic!("{name}: {}: {e}", lump.name));
            songs += 1;
            if let Some(font) = &font {
                let mut music = Music::new(font, sightline::sound::OUTPUT_RATE).unwrap();
                music.play(&midi).unwrap_or_else(|e| panic!("{name}: {}: {e}", lump.name));
                // Three seconds: every song is playing by then.
                let mut out = vec![0.0f32; 2 * 3 * 44_100];
                music.mix(&mut out);
                let rms = (out.iter().map(|v| v * v).sum::<f32>() / out.len() as f32).sqrt();
                assert!(rms > 0.001 && out.iter().all(|v| v.is_finite()), "{name}: {}: rms {rms}", lump.name);
            }
        }
        println!("{name}: {songs} songs");
        assert!(songs >= 30, "{name}: {songs} songs");
    }
}

#[test]
fn corrupt_music_is_an_error_not_a_panic() {
    assert!(midi_of(b"").is_err());
    assert!(midi_of(b"RIFF").is_err());
    let Some(path) = find_soundfont(None) else {
        assert!(std::env::var_os("SIGHTLINE_REQUIRE_SOUNDFONT").is_none(), "no SoundFont installed");
        println!("SKIPPED: no SoundFont (apt-get install timgm6mb-soundfont)");
        return;
    };
    let font = load_soundfont(&path).unwrap();
    let mut music = Music::new(&font, 44_100).unwrap();
    let no_tracks = b"MThd\0\0\0\x06\0\0\0\0\0\x46";
    for bad in
        [&b"MThd"[..], b"MThd\0\0\0\x06\0\0\0\x01\0", b"MThd\0\0\0\x06\0\0\0\x01\0\x46MTrk\xff\xff\xff\xff", no_tracks]
    {
        assert!(music.play(bad).is_err(), "{bad:?}");
        let mut out = vec![0.0; 64];
        music.mix(&mut out);
        assert!(out.iter().all(|&v| v == 0.0));
    }
    assert!(load_soundfont(std::path::Path::new("/no/such.sf2")).is_err());
    let junk = std::env::temp_dir().join(format!("sightline-junk-{}.sf2", std::process::id()));
    std::fs::write(&junk, b"RIFF\x04\0\0\0sfbk").unwrap();
    assert!(load_soundfont(&junk).is_err());
    let _ = std::fs::remove_file(junk);
}

#[test]
fn a_ron_map_s_music_is_the_midi_file_it_names_and_a_missing_one_is_a_warning() {
    use sightline::campaign::MapRef;
    use sightline::play::playthrough::Playthrough;
    use sightline::play::GameOptions;
    use sightline::sound::Sounds;

    let map = MapRef::File(sightline_tests::map_path("outpost.ron"));
    let play = Playthrough::of(&map, GameOptions::default()).unwrap();
    let mut sounds = Sounds::new();
    let cues = sounds.cues(&play);
    let midi = cues.music.clone().flatten().expect("the outpost names its music");
    assert!(midi.starts_with(b"MThd"), "{:?}", &midi[..8]);
    assert!(sounds.warnings.is_empty(), "{:?}", sounds.warnings);
    // The next tick: no change.
    assert!(sounds.cues(&play).music.is_none());

    // A map naming music that is not there: one warning, and silence.
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(sightline_tests::map_path("room.ron")).unwrap();
    let path = dir.path().join("room.ron");
    std::fs::write(&path, text.replacen("Map(", "Map(music: \"gone.mid\", ", 1)).unwrap();
    let play = Playthrough::of(&MapRef::File(path), GameOptions::default()).unwrap();
    let mut sounds = Sounds::new();
    let cues = sounds.cues(&play);
    assert!(matches!(cues.music, Some(None)));
    assert_eq!(sounds.warnings.len(), 1, "{:?}", sounds.warnings);
    assert!(sounds.warnings[0].contains("gone.mid"), "{:?}", sounds.warnings);
}
