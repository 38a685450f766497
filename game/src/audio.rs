//! Sound for the binary: the engine's `Audio` set up from the command
//! line (volumes, channels, the SoundFont), and rendered offline into a WAV
//! (`replay --audio`). The window's live output is in `play::sound`.

use sightline::sound::music::{find_soundfont, load_soundfont, Music, NO_SOUNDFONT};
use sightline::sound::{Audio, OUTPUT_RATE};

use crate::config::Sound;

/// The audio side as the settings ask; music is off (with one line saying
/// why on stderr) when asked or when no SoundFont can be had.
pub fn audio(args: &Sound) -> Audio {
    let music = if args.music { music(args) } else { None };
    let mut audio = Audio::new(usize::from(args.channels), music);
    audio.mixer.volume = f32::from(args.effects_volume) / 100.0;
    audio
}

fn music(args: &Sound) -> Option<Music> {
    let Some(path) = find_soundfont(args.soundfont.as_deref()) else {
        eprintln!("sightline: {NO_SOUNDFONT}");
        return None;
    };
    let made = load_soundfont(&path).and_then(|font| Music::new(&font, OUTPUT_RATE));
    match made {
        Ok(mut music) => {
            music.volume = f32::from(args.music_volume) / 100.0;
            Some(music)
        }
        Err(e) => {
            eprintln!("sightline: music is off: {e}");
            None
        }
    }
}

/// Prints the warnings the sounds gathered (missing or bad sounds and music), once each.
pub fn warn(sounds: &mut sightline::sound::Sounds) {
    for w in sounds.warnings.drain(..) {
        eprintln!("sightline: warning: {w}");
    }
}
