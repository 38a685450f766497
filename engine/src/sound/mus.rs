//! Doom's MUS music lumps converted to Standard MIDI Files, for the
//! synthesizer. MUS is MIDI cut down for the DMX library: a header, then a
//! single stream of events on 16 channels (15 is percussion), each a byte
//! of kind and channel with one or two bytes of data, with a delay after the
//! events that end a group, counted at 140 ticks per second.
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-3 | `MUS` and 0x1A |
//! | 4-5 | length of the score in bytes (little-endian u16) |
//! | 6-7 | where the score starts (u16) |
//! | 8-9, 10-11 | primary and secondary channels used (u16) |
//! | 12-13 | instruments used `I` (u16); 14-15 reserved |
//! | 16-(16+2I) | the instruments' numbers (u16 each) |
//!
//! Events: bit 7 of the first byte says a delay follows the event, bits 4-6
//! are the kind, bits 0-3 the channel. 0: release note (note); 1: play note
//! (note, with bit 7 set a volume byte follows, else the channel's last
//! volume); 2: pitch bend (0-255, 128 centred); 3: system event (a
//! controller number 10-14 with no value); 4: controller (number, value;
//! 0 is the instrument); 5: end of a measure; 6: the score's end. A delay
//! is a variable-length number, 7 bits a byte, bit 7 set on all but the last.
//!
//! The MIDI file written is format 0 with one track at 70 ticks per quarter
//! note and the default tempo of 120 beats a minute: 140 ticks a second, as
//! MUS counts them. MUS channel 15 becomes MIDI channel 9 (percussion), and
//! 9 to 14 move up one to make room.

pub const MAGIC: &[u8] = b"MUS\x1a";

#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum MusError {
    #[error("not a MUS lump (no MUS header)")]
    Magic,
    #[error("{0} bytes, shorter than the 16-byte header")]
    TooShort(usize),
    #[error("the score ({length} bytes at {start}) runs past the lump's end ({size} bytes)")]
    Score { start: usize, length: usize, size: usize },
    #[error("event {event} of kind {kind} at byte {at} is cut short by the score's end")]
    Truncated { event: usize, kind: u8, at: usize },
    #[error("event {event} at byte {at} is of unknown kind 7")]
    Kind { event: usize, at: usize },
    #[error("a delay at byte {at} is longer than four bytes")]
    Delay { at: usize },
}

/// MUS controller numbers 0-9 as MIDI controllers (0, the instrument, is a
/// program change instead).
const CONTROLLERS: [u8; 10] = [0, 0, 1, 7, 10, 11, 91, 93, 64, 67];
/// MUS system events 10-14 as MIDI channel-mode controllers: all sounds
/// off, all notes off, mono, poly, reset all controllers.
const SYSTEM: [u8; 5] = [120, 123, 126, 127, 121];

/// The longest MIDI delta time (a four-byte variable-length number).
const MAX_DELTA: u32 = 0x0fff_ffff;

fn midi_channel(mus: u8) -> u8 {
    match mus {
        15 => 9,
        9..=14 => mus + 1,
        c => c,
    }
}

/// Appends `value` as a MIDI variable-length quantity.
fn push_vlq(out: &mut Vec<u8>, value: u32) {
    let mut bytes = [0u8; 5];
    let mut n = 0;
    let mut v = value;
    loop {
        bytes[n] = (v & 0x7f) as u8;
        n += 1;
        v >>= 7;
        if v == 0 {
            break;
        }
    }
    for i in (0..n).rev() {
        out.push(bytes[i] | if i > 0 { 0x80 } else { 0 });
    }
}

/// The Standard MIDI File of a MUS lump.
pub fn to_midi(lump: &[u8]) -> Result<Vec<u8>, MusError> {
    if !lump.starts_with(MAGIC) {
        return Err(if MAGIC.starts_with(lump) && lump.len() < 4 {
            MusError::TooShort(lump.len())
        } else {
            MusError::Magic
        });
    }
    if lump.len() < 16 {
        return Err(MusError::TooShort(lump.len()));
    }
    let u16_at = |i: usize| usize::from(u16::from_le_bytes([lump[i], lump[i + 1]]));
    let (length, start) = (u16_at(4), u16_at(6));
    if start.checked_add(length).is_none_or(|end| end > lump.len()) {
        return Err(MusError::Score { start, length, size: lump.len() });
    }
    let score = &lump[start..start + length];
    let mut track = Vec::with_capacity(score.len() * 2);
    let mut volumes = [127u8; 16];
    let mut delay: u32 = 0;
    let mut at = 0;
    let mut event = 0;
    // Each event: its MIDI bytes after the delta time.
    while at < score.len() {
        let head = score[at];
        let (last, kind, channel) = (head & 0x80 != 0, (head >> 4) & 7, head & 15);
        let cut = || MusError::Truncated { event, kind, at };
        let data = |n: usize| score.get(at + 1..at + 1 + n).ok_or_else(cut);
        let ch = midi_channel(channel);
        let mut message: Option<[u8; 3]> = None;
        let mut size = 1;
        match kind {
            0 => {
                let d = data(1)?;
                message = Some([0x80 | ch, d[0] & 0x7f, 0]);
                size += 1;
            }
            1 => {
                let d = data(1)?;
                if d[0] & 0x80 != 0 {
                    let v = data(2)?;
                    volumes[usize::from(channel)] = v[1] & 0x7f;
                    size += 1;
                }
                message = Some([0x90 | ch, d[0] & 0x7f, volumes[usize::from(channel)]]);
                size += 1;
            }
            2 => {
                let d = data(1)?;
                let bend = u16::from(d[0]) << 6;
                message = Some([0xe0 | ch, (bend & 0x7f) as u8, (bend >> 7) as u8]);
                size += 1;
            }
            3 => {
                let d = data(1)?;
                if let Some(&c) = SYSTEM.get(usize::from(d[0]).wrapping_sub(10)) {
                    message = Some([0xb0 | ch, c, 0]);
                }
                size += 1;
            }
            4 => {
                let d = data(2)?;
                // Values over 127 are clamped, as Chocolate Doom does.
                let value = d[1].min(127);
                message = match d[0] {
                    0 => Some([0xc0 | ch, value, 0]),
                    c @ 1..=9 => Some([0xb0 | ch, CONTROLLERS[usize::from(c)], value]),
                    _ => None,
                };
                size += 2;
            }
            5 => {}
            6 => break,
            _ => return Err(MusError::Kind { event, at }),
        }
        if let Some(m) = message {
            // A MIDI delta time has at most 28 bits; a longer silence (only
            // a broken lump has one) is cut to that.
            push_vlq(&mut track, delay.min(MAX_DELTA));
            delay = 0;
            let len = if m[0] & 0xf0 == 0xc0 { 2 } else { 3 };
            track.extend(&m[..len]);
        }
        at += size;
        if last {
            let mut value: u32 = 0;
            for k in 0.. {
                if k == 4 {
                    return Err(MusError::Delay { at });
                }
                let b = *score.get(at).ok_or(MusError::Truncated { event, kind, at })?;
                at += 1;
                value = (value << 7) | u32::from(b & 0x7f);
                if b & 0x80 == 0 {
                    break;
                }
            }
            delay = delay.saturating_add(value);
        }
        event += 1;
    }
    push_vlq(&mut track, delay.min(MAX_DELTA));
    track.extend([0xff, 0x2f, 0x00]);
    let mut midi = b"MThd".to_vec();
    midi.extend(6u32.to_be_bytes());
    midi.extend([0, 0, 0, 1, 0, 70]);
    midi.extend(b"MTrk");
    midi.extend((track.len() as u32).to_be_bytes());
    midi.extend(track);
    Ok(midi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A MUS lump of `score` with `instruments`.
    fn lump(score: &[u8], instruments: &[u16]) -> Vec<u8> {
        let start = 16 + 2 * instruments.len();
        let mut bytes = MAGIC.to_vec();
        bytes.extend((score.len() as u16).to_le_bytes());
        bytes.extend((start as u16).to_le_bytes());
        bytes.extend([1, 0, 0, 0]);
        bytes.extend((instruments.len() as u16).to_le_bytes());
        bytes.extend([0, 0]);
        for i in instruments {
            bytes.extend(i.to_le_bytes());
        }
        bytes.extend(score);
        bytes
    }

    /// The track's bytes of a MIDI file.
    fn track(midi: &[u8]) -> &[u8] {
        assert_eq!(&midi[..14], b"MThd\0\0\0\x06\0\0\0\x01\0\x46");
        assert_eq!(&midi[14..18], b"MTrk");
        let len = u32::from_be_bytes(midi[18..22].try_into().unwrap()) as usize;
        assert_eq!(midi.len(), 22 + len);
        &midi[22..]
    }

    #[test]
    fn every_event_kind_becomes_its_midi_message_with_its_delay() {
        let score = [
            0x40,
            0,
            30, // controller: instrument 30 on channel 0
            0x41,
            3,
            100, // controller: volume 100 on channel 1
            0x90,
            0x80 | 60,
            90,
            0x81,
            0x10, // play note 60 at volume 90, then a delay of 0x90 (two bytes)
            0x10,
            62, // play note 62 (last volume, 90)
            0x9f,
            35,
            5, // percussion channel 15: note 35 at the last volume (127), delay 5
            0x00,
            60, // release 60
            0x22,
            128 + 64, // pitch bend on channel 2
            0x3a,
            11,   // system: all notes off on channel 10 (MIDI 11)
            0x50, // end of measure
            0x60, // score end
            0x10,
            99, // after the end: ignored
        ];
        let midi = to_midi(&lump(&score, &[30])).unwrap();
        let expected = [
            0, 0xc0, 30, //
            0, 0xb1, 7, 100, //
            0, 0x90, 60, 90, //
            0x81, 0x10, 0x90, 62, 90, //
            0, 0x99, 35, 127, //
            5, 0x80, 60, 0, //
            0, 0xe2, 0, 96, //
            0, 0xbb, 123, 0, //
            0, 0xff, 0x2f, 0,
        ];
        assert_eq!(track(&midi), expected);
    }

    #[test]
    fn bad_lumps_are_errors_never_panics() {
        assert_eq!(to_midi(b"MThd...."), Err(MusError::Magic));
        assert_eq!(to_midi(b"MU"), Err(MusError::TooShort(2)));
        assert_eq!(to_midi(MAGIC), Err(MusError::TooShort(4)));
        let mut long = lump(&[0x60], &[]);
        long[4] = 200;
        assert!(matches!(to_midi(&long), Err(MusError::Score { .. })));
        assert!(matches!(to_midi(&lump(&[0x10], &[])), Err(MusError::Truncated { kind: 1, .. })));
        assert!(matches!(to_midi(&lump(&[0x10, 0x80 | 5], &[])), Err(MusError::Truncated { .. })));
        assert!(matches!(to_midi(&lump(&[0x70, 0], &[])), Err(MusError::Kind { .. })));
        assert!(matches!(to_midi(&lump(&[0xd0, 0xff, 0xff, 0xff, 0xff, 1], &[])), Err(MusError::Delay { .. })));
        assert!(matches!(to_midi(&lump(&[0x90, 60, 0x80], &[])), Err(MusError::Truncated { .. })));
        // Every prefix of a good score: an error or a file, never a panic.
        let good = lump(&[0x40, 0, 30, 0x90, 0x80 | 60, 90, 0x81, 0x10, 0x60], &[30]);
        for cut in 0..good.len() {
            let _ = to_midi(&good[..cut]);
        }
        // A score with no end event ends where its bytes do.
        assert!(to_midi(&lump(&[0x10, 60], &[])).is_ok());
    }

    #[test]
    fn overlong_silences_are_cut_and_controller_values_clamped() {
        // Two of the longest delays, then a note: one delta of the most MIDI allows.
        let score = [0xd0, 0xff, 0xff, 0xff, 0x7f, 0xd0, 0xff, 0xff, 0xff, 0x7f, 0x10, 60, 0x40, 3, 0x80, 0x60];
        let midi = to_midi(&lump(&score, &[])).unwrap();
        let t = track(&midi);
        assert_eq!(&t[..7], [0xff, 0xff, 0xff, 0x7f, 0x90, 60, 127]);
        // Volume 0x80 is 127, not 0.
        assert_eq!(&t[7..11], [0, 0xb0, 7, 127]);
    }
}
