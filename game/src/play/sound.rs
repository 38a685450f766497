//! The window's sound: the game's cues each tick, sent to an audio thread
//! that mixes them (`sightline::sound::Audio`) into a PulseAudio playback
//! stream. The stream pulls samples as the server plays them, on the
//! client's own thread, so a frame never waits for audio. PulseAudio (or
//! PipeWire's PulseAudio server, on most desktops) is reached through a
//! pure-Rust client, so building needs no system audio headers. With no
//! server the game runs silent and says so once.

use std::sync::mpsc::{channel, Receiver, Sender};

use pulseaudio::{protocol, AsPlaybackSource, Client, PlaybackStream};
use sightline::play::playthrough::Playthrough;
use sightline::sound::{Audio, Cues, Sounds, OUTPUT_RATE};

use crate::config::Sound;

/// Bytes buffered in the server: 1/16 s of 16-bit stereo.
const TARGET_BYTES: u32 = OUTPUT_RATE / 16 * 4;

/// What the game sends the audio thread.
enum Message {
    Cues(Box<Cues>),
    /// Effects' and music's loudness, 0 to 1.
    Volumes(f32, f32),
}

/// Sound playing from the game to the system's audio.
pub struct SoundOut {
    sounds: Sounds,
    to_audio: Sender<Message>,
    volumes: (f32, f32),
    // Kept alive while the game runs: dropping them ends the stream.
    _stream: PlaybackStream,
    _client: Client,
}

impl SoundOut {
    /// Connects to the sound server and starts the stream; `Err` says why
    /// there is no sound (the game then runs silent).
    pub fn open(args: &Sound) -> Result<SoundOut, String> {
        let client = Client::from_env(c"sightline").map_err(|e| format!("no PulseAudio server to play to ({e})"))?;
        let audio = crate::audio::audio(args);
        let volumes = (audio.mixer.volume, audio.music.as_ref().map_or(0.0, |m| m.volume));
        let (to_audio, from_game) = channel();
        let mut feed = Feed { audio, from_game, scratch: Vec::new(), pending: Vec::new() };
        let source = move |bytes: &mut [u8]| feed.fill(bytes);
        let params = protocol::PlaybackStreamParams {
            sample_spec: protocol::SampleSpec {
                format: protocol::SampleFormat::S16Le,
                channels: 2,
                sample_rate: OUTPUT_RATE,
            },
            channel_map: protocol::ChannelMap::stereo(),
            cvolume: Some(protocol::ChannelVolume::norm(2)),
            sink_name: Some(protocol::DEFAULT_SINK.to_owned()),
            // About 60 ms buffered (a sound starts that long after its
            // tick), asked for a quarter at a time; playing starts at once
            // (the server's default, waiting for a full buffer, can stall a
            // stream that is fed exactly what it asks).
            buffer_attr: protocol::stream::BufferAttr {
                max_length: u32::MAX,
                target_length: TARGET_BYTES,
                pre_buffering: 0,
                minimum_request_length: TARGET_BYTES / 4,
                fragment_size: u32::MAX,
            },
            ..Default::default()
        };
        let stream = futures::executor::block_on(client.create_playback_stream(params, source.as_playback_source()))
            .map_err(|e| format!("the sound server refused a playback stream ({e})"))?;
        Ok(SoundOut { sounds: Sounds::new(), to_audio, volumes, _stream: stream, _client: client })
    }

    /// The tick `play` just ran, to the audio thread; the warnings printed once.
    pub fn tick(&mut self, play: &Playthrough) {
        let cues = self.sounds.cues(play);
        self.send(cues);
    }

    /// `cues` to the audio thread, with the warnings making them printed once.
    fn send(&mut self, cues: Cues) {
        crate::audio::warn(&mut self.sounds);
        let _ = self.to_audio.send(Message::Cues(Box::new(cues)));
    }

    /// A tic heard elsewhere and shown on `play` (a Doom demo), to the
    /// audio thread.
    pub fn tick_heard(&mut self, play: &Playthrough, heard: &sightline::sound::Heard) {
        let cues = self.sounds.cues_heard(play, heard);
        self.send(cues);
    }

    /// A game loaded in place of this one: every sound stops and the music
    /// starts again with the next tick, as on a new map.
    pub fn restart(&mut self) {
        self.sounds = Sounds::new();
    }

    /// Plays the music lump `lump` of `map`'s WADs (the title's), until
    /// the next map's music.
    pub fn music(&mut self, map: &sightline::campaign::MapRef, lump: &str) {
        let cues = self.sounds.music(map, lump);
        self.send(cues);
    }

    /// Plays the menu's sound `name` (not placed in the world).
    pub fn menu_sound(&mut self, name: &str) {
        let Some(voice) = self.sounds.voice(name) else { return };
        let start = sightline::sound::Start { voice, key: sightline::sound::mix::Key::Listener, pos: None };
        self.send(Cues { starts: vec![start], ..Cues::default() });
    }

    /// Sets the effects' and music's volumes, 0 to 1.
    pub fn set_volumes(&mut self, effects: f32, music: f32) {
        self.volumes = (effects, music);
        let _ = self.to_audio.send(Message::Volumes(effects, music));
    }

    /// The effects' and music's volumes, 0 to 1.
    pub fn volumes(&self) -> (f32, f32) {
        self.volumes
    }

    /// Changes the effects' (`which` 0) or music's (1) volume by `step`;
    /// returns the new level, 0 to 1.
    pub fn nudge(&mut self, which: usize, step: f32) -> f32 {
        let v = if which == 0 { &mut self.volumes.0 } else { &mut self.volumes.1 };
        *v = ((*v + step) * 10.0).round().clamp(0.0, 10.0) / 10.0;
        let level = *v;
        let _ = self.to_audio.send(Message::Volumes(self.volumes.0, self.volumes.1));
        level
    }
}

/// The audio thread's side: the game's messages in, samples out.
struct Feed {
    audio: Audio,
    from_game: Receiver<Message>,
    scratch: Vec<f32>,
    /// Bytes of the last frame rendered that the server has not asked for yet.
    pending: Vec<u8>,
}

impl Feed {
    /// Fills `bytes` with 16-bit stereo samples, every byte asked for: a
    /// request that ends inside a frame gets the frame's first bytes and the
    /// rest start the next (returning less, 0 above all, would end the stream).
    fn fill(&mut self, bytes: &mut [u8]) -> usize {
        while let Ok(m) = self.from_game.try_recv() {
            match m {
                Message::Cues(cues) => {
                    // A song the synthesizer will not play is silence, said once.
                    if let Err(e) = self.audio.apply(&cues) {
                        eprintln!("sightline: warning: music: {e}; no music");
                    }
                }
                Message::Volumes(effects, music) => {
                    self.audio.mixer.volume = effects;
                    if let Some(m) = &mut self.audio.music {
                        m.volume = music;
                    }
                }
            }
        }
        let wanted = bytes.len().saturating_sub(self.pending.len());
        let frames = wanted.div_ceil(4);
        self.scratch.resize(frames * 2, 0.0);
        self.audio.render(&mut self.scratch);
        for v in &self.scratch {
            self.pending.extend(((v * 32767.0).round() as i16).to_le_bytes());
        }
        bytes.copy_from_slice(&self.pending[..bytes.len()]);
        self.pending.drain(..bytes.len());
        bytes.len()
    }
}
