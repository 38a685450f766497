//! Where a map's sounds and music come from. A WAD map: the WAD's `DS*`
//! lumps (DMX) and `D_*` music (MIDI, or MUS converted); a lump that is
//! missing, empty or corrupt is a warning naming the sound, and silence. A
//! RON map: `sounds/NAME.wav` beside the map if there is one (any rate, 8 or
//! 16 bits, mono or stereo mixed down), else our own voice for the name
//! ([`super::procedural`]); its music is the MIDI file the map names.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use crate::actors::sounds::{doom, SoundDef};
use crate::campaign::MapRef;
use crate::wad::library::WadArt;
use crate::wad::Wad;

use super::{dmx, mus, procedural, Sample};

/// A sound ready to start: its samples and Doom's priority.
#[derive(Clone, Debug)]
pub struct Voice {
    pub sample: Arc<Sample>,
    pub priority: u8,
}

/// Where a bank's voices come from.
enum Source {
    Procedural,
    /// WAVs in this directory, else ours.
    Dir(std::path::PathBuf),
    Wad(Arc<Wad>),
    /// A WAD already open for a game's art (a scenario's, shared by its games).
    Art(Arc<WadArt>),
}

/// The sounds of one map, by name (links resolved: the chaingun is the
/// pistol), each loaded when first asked for: a sound that is never made is
/// never read, nor warned about.
pub struct SoundBank {
    source: Source,
    voices: BTreeMap<String, Option<Voice>>,
    /// What could not be loaded, one line each, naming the sound.
    pub warnings: Vec<String>,
}

impl SoundBank {
    /// Our own voices for every name.
    pub fn procedural() -> SoundBank {
        SoundBank::of(Source::Procedural)
    }

    /// The sounds of `map`: its WAD's, or for a file, WAVs beside it and ours.
    pub fn for_map(map: &MapRef) -> SoundBank {
        match map {
            MapRef::Wad { wads, .. } => match crate::campaign::stack(wads) {
                Ok(wad) => SoundBank::of_wad(Arc::new(wad)),
                Err(e) => {
                    let mut bank = SoundBank::procedural();
                    bank.warnings.push(format!("no sounds from the WAD ({e}); our own voices instead"));
                    bank
                }
            },
            MapRef::File(path) => SoundBank::of(Source::Dir(path.parent().unwrap_or(Path::new(".")).join("sounds"))),
        }
    }

    /// The `DS*` lumps of `wad`.
    pub fn of_wad(wad: Arc<Wad>) -> SoundBank {
        SoundBank::of(Source::Wad(wad))
    }

    /// The `DS*` lumps of a WAD opened for its art.
    pub fn of_art(art: Arc<WadArt>) -> SoundBank {
        SoundBank::of(Source::Art(art))
    }

    /// The WAD the voices come from, if any.
    fn wad(&self) -> Option<&Wad> {
        match &self.source {
            Source::Wad(wad) => Some(wad),
            Source::Art(art) => Some(&art.wad),
            Source::Procedural | Source::Dir(_) => None,
        }
    }

    fn of(source: Source) -> SoundBank {
        SoundBank { source, voices: BTreeMap::new(), warnings: Vec::new() }
    }

    fn load(&self, def: &SoundDef) -> Result<Sample, String> {
        match &self.source {
            Source::Procedural => Ok(procedural::voice(&def.name)),
            Source::Dir(dir) => {
                let wav = dir.join(format!("{}.wav", def.name));
                if wav.exists() {
                    read_wav(&wav).map_err(|e| format!("{}: {e}", wav.display()))
                } else {
                    Ok(procedural::voice(&def.name))
                }
            }
            Source::Wad(wad) => dmx_lump(wad, &def.name),
            Source::Art(art) => dmx_lump(&art.wad, &def.name),
        }
    }

    /// The voice of `name` (`None`: silent, or no such sound), loaded the
    /// first time; a sound that cannot be had is warned about once.
    pub fn get(&mut self, name: &str) -> Option<&Voice> {
        if !self.voices.contains_key(name) {
            let voice = self.resolve(name);
            self.voices.insert(name.to_string(), voice);
        }
        self.voices.get(name).and_then(Option::as_ref)
    }

    fn resolve(&mut self, name: &str) -> Option<Voice> {
        let Some(def) = doom().iter().find(|d| d.name == name) else {
            self.warnings.push(format!("sound {name}: not in the sound table; it is silent"));
            return None;
        };
        // A link plays another sound's samples at its own priority.
        let played = match &def.link {
            Some(link) => doom().iter().find(|d| d.name == link.sound)?,
            None => def,
        };
        match self.load(played) {
            Ok(sample) => Some(Voice { sample: Arc::new(sample), priority: def.priority }),
            Err(e) => {
                self.warnings.push(format!("sound {name}: {e}; it is silent"));
                None
            }
        }
    }

    /// The music lump `name` (`D_RUNNIN`) of a WAD map as a MIDI file
    /// (MUS converted); `Err` says why there is none.
    pub fn wad_music(&self, name: &str) -> Result<Vec<u8>, String> {
        let Some(wad) = self.wad() else { return Err("not a WAD map".into()) };
        let bytes = wad.find(name).map(|i| wad.bytes(i)).ok_or_else(|| format!("no lump {name}"))?;
        midi_of(bytes).map_err(|e| format!("lump {name}: {e}"))
    }
}

/// The `DS` lump of sound `name` in `wad`, decoded.
fn dmx_lump(wad: &Wad, name: &str) -> Result<Sample, String> {
    let lump = format!("DS{}", name.to_ascii_uppercase());
    let bytes = wad.find(&lump).map(|i| wad.bytes(i)).ok_or_else(|| format!("no lump {lump}"))?;
    dmx::decode(bytes).map_err(|e| format!("lump {lump}: {e}"))
}

/// A music lump's bytes as a MIDI file: MIDI as it is, MUS converted.
pub fn midi_of(bytes: &[u8]) -> Result<Vec<u8>, String> {
    if bytes.starts_with(b"MThd") {
        Ok(bytes.to_vec())
    } else if bytes.starts_with(mus::MAGIC) {
        mus::to_midi(bytes).map_err(|e| e.to_string())
    } else {
        Err("neither MIDI nor MUS".into())
    }
}

/// A WAV file's samples, mixed down to mono.
pub fn read_wav(path: &Path) -> Result<Sample, String> {
    let reader = hound::WavReader::open(path).map_err(|e| e.to_string())?;
    let spec = reader.spec();
    if spec.sample_rate == 0 || spec.channels == 0 {
        return Err("no sample rate or no channels".into());
    }
    let frames: Vec<f32> = match spec.sample_format {
        hound::SampleFormat::Float => {
            reader.into_samples::<f32>().collect::<Result<_, _>>().map_err(|e| e.to_string())?
        }
        hound::SampleFormat::Int => {
            let scale = 2f32.powi(i32::from(spec.bits_per_sample.clamp(1, 32)) - 1);
            let ints: Vec<i32> = reader.into_samples::<i32>().collect::<Result<_, _>>().map_err(|e| e.to_string())?;
            ints.into_iter().map(|v| v as f32 / scale).collect()
        }
    };
    let channels = usize::from(spec.channels);
    let data: Vec<f32> = frames.chunks(channels).map(|f| f.iter().sum::<f32>() / channels as f32).collect();
    if data.is_empty() {
        return Err("no samples".into());
    }
    Ok(Sample { rate: spec.sample_rate, data })
}
