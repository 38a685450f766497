//! Music: a MIDI file played by a SoundFont synthesizer (rustysynth, pure
//! Rust) into stereo at the output rate, looping. The SoundFont is the one
//! the user names, else the first General MIDI font found where Linux
//! packages put them; with none, music is off and [`find_soundfont`] says how
//! to get one.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rustysynth::{MidiFile, MidiFileSequencer, SoundFont, Synthesizer, SynthesizerSettings};

/// Where General MIDI SoundFonts are looked for, in order (Debian's
/// `timgm6mb-soundfont`, `fluid-soundfont-gm`, and the usual links).
pub const SOUNDFONT_PATHS: [&str; 6] = [
    "/usr/share/sounds/sf2/TimGM6mb.sf2",
    "/usr/share/sounds/sf2/FluidR3_GM.sf2",
    "/usr/share/sounds/sf2/default-GM.sf2",
    "/usr/share/soundfonts/default.sf2",
    "/usr/share/soundfonts/FluidR3_GM.sf2",
    "/usr/share/sounds/sf3/default-GM.sf3",
];

/// How to get a SoundFont, for the one line saying music is off.
pub const NO_SOUNDFONT: &str = "no General MIDI SoundFont found, so music is off: install one \
     (Debian: sudo apt-get install timgm6mb-soundfont) or give one with --soundfont FILE.sf2";

/// The SoundFont to use: `given`, else the first of [`SOUNDFONT_PATHS`] there.
pub fn find_soundfont(given: Option<&Path>) -> Option<PathBuf> {
    match given {
        Some(p) => Some(p.to_path_buf()),
        None => SOUNDFONT_PATHS.iter().map(PathBuf::from).find(|p| p.is_file()),
    }
}

/// A SoundFont read from a file.
pub fn load_soundfont(path: &Path) -> Result<Arc<SoundFont>, String> {
    let mut file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    SoundFont::new(&mut file).map(Arc::new).map_err(|e| format!("{}: not a SoundFont: {e}", path.display()))
}

/// The synthesizer's output is quiet beside the effects (a General MIDI
/// song's mix leaves headroom for many voices): at full volume it is raised
/// this much, which puts a song at about a third of the effects' loudness
/// at the default volumes, as in Doom.
const GAIN: f32 = 3.0;

/// A song playing, or silence.
pub struct Music {
    sequencer: MidiFileSequencer,
    playing: bool,
    left: Vec<f32>,
    right: Vec<f32>,
    /// Loudness, 0 to 1.
    pub volume: f32,
}

impl Music {
    pub fn new(font: &Arc<SoundFont>, rate: u32) -> Result<Music, String> {
        let settings = SynthesizerSettings::new(rate as i32);
        let synth = Synthesizer::new(font, &settings).map_err(|e| format!("the synthesizer: {e}"))?;
        Ok(Music {
            sequencer: MidiFileSequencer::new(synth),
            playing: false,
            left: Vec::new(),
            right: Vec::new(),
            volume: 1.0,
        })
    }

    /// Plays the MIDI file `midi` from its start, looping; `Err` (and
    /// silence) when it is not one.
    pub fn play(&mut self, midi: &[u8]) -> Result<(), String> {
        self.stop();
        // The parser is a third party's and the file may be a user's: a
        // panic in it is a bad file, not a crash.
        let parsed = std::panic::catch_unwind(|| MidiFile::new(&mut std::io::Cursor::new(midi)))
            .map_err(|_| "the MIDI parser failed on it".to_string())?;
        let file = Arc::new(parsed.map_err(|e| format!("not a MIDI file: {e}"))?);
        // The sequencer cannot play a file with no tracks (it would panic on
        // its first render).
        let tracks = midi.get(10..12).map_or(0, |b| u16::from_be_bytes([b[0], b[1]]));
        if tracks == 0 {
            return Err("a MIDI file with no tracks".into());
        }
        self.sequencer.play(&file, true);
        self.playing = true;
        Ok(())
    }

    pub fn stop(&mut self) {
        self.sequencer.stop();
        self.playing = false;
    }

    pub fn playing(&self) -> bool {
        self.playing
    }

    /// Adds the next `out.len() / 2` frames of music into `out` (interleaved stereo).
    pub fn mix(&mut self, out: &mut [f32]) {
        if !self.playing {
            return;
        }
        let frames = out.len() / 2;
        self.left.resize(frames, 0.0);
        self.right.resize(frames, 0.0);
        // Rendered even when muted, so that the song goes on meanwhile. A
        // file the synthesizer chokes on stops the music, not the game.
        let (sequencer, left, right) = (&mut self.sequencer, &mut self.left, &mut self.right);
        let rendered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| sequencer.render(left, right)));
        if rendered.is_err() {
            self.stop();
            return;
        }
        let gain = self.volume * GAIN;
        for (i, frame) in out.chunks_exact_mut(2).enumerate() {
            frame[0] += self.left[i] * gain;
            frame[1] += self.right[i] * gain;
        }
    }
}
