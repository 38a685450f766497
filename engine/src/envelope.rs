//! The envelope both save formats share (a playthrough's, `play::save`, and
//! the simulation's, `sim::save`): a magic string, a format version byte,
//! the body's CRC-32 and its length (little-endian `u64`), then the body,
//! CBOR. Each format names its own errors; this module says only what is
//! wrong with the envelope.

use serde::de::DeserializeOwned;
use serde::Serialize;

/// What is wrong with an envelope.
#[derive(Debug)]
pub enum EnvelopeError {
    /// Not this format's magic.
    Magic,
    /// Another format version than the one asked for.
    Version(u8),
    /// Cut short: what is missing.
    Truncated(String),
    /// Bytes that cannot be the format's: what is wrong.
    Corrupt(String),
}

/// `body` sealed behind `magic`, `version`, its checksum and its length.
pub fn seal(magic: &[u8], version: u8, body: &[u8]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(magic.len() + 1 + 4 + 8 + body.len());
    bytes.extend(magic);
    bytes.push(version);
    bytes.extend(crc32fast::hash(body).to_le_bytes());
    bytes.extend((body.len() as u64).to_le_bytes());
    bytes.extend(body);
    bytes
}

/// The body of the envelope `bytes`, its magic, version, length and
/// checksum checked.
pub fn open<'a>(bytes: &'a [u8], magic: &[u8], version: u8) -> Result<&'a [u8], EnvelopeError> {
    let header = (magic.len() + 1 + 4 + 8) as u64;
    let truncated = |what: String| EnvelopeError::Truncated(what);
    if bytes.len() < magic.len() && magic.starts_with(bytes) && !bytes.is_empty() {
        return Err(truncated(format!("{} bytes, not even the header", bytes.len())));
    }
    let rest = bytes.strip_prefix(magic).ok_or(EnvelopeError::Magic)?;
    let (&found, rest) = rest.split_first().ok_or_else(|| truncated("no version after the magic".into()))?;
    if found != version {
        return Err(EnvelopeError::Version(found));
    }
    let (checksum, rest) = rest.split_first_chunk::<4>().ok_or_else(|| truncated("no checksum".into()))?;
    let (length, body) = rest.split_first_chunk::<8>().ok_or_else(|| truncated("no length".into()))?;
    let (length, present) = (u64::from_le_bytes(*length), body.len() as u64);
    if length > present {
        return Err(truncated(format!("{} bytes, the header says {}", header + present, header + length)));
    }
    if length < present {
        return Err(EnvelopeError::Corrupt(format!("{} bytes after the end the header gives", present - length)));
    }
    if crc32fast::hash(body) != u32::from_le_bytes(*checksum) {
        return Err(EnvelopeError::Corrupt("checksum mismatch".into()));
    }
    Ok(body)
}

/// [`open`], then the description the body starts with (CBOR) decoded;
/// returns it and the rest of the body.
pub fn open_described<'a, T: DeserializeOwned>(
    bytes: &'a [u8],
    magic: &[u8],
    version: u8,
) -> Result<(T, &'a [u8]), EnvelopeError> {
    let mut body = open(bytes, magic, version)?;
    let description = ciborium::from_reader(&mut body)
        .map_err(|e| EnvelopeError::Corrupt(format!("the save's description does not decode: {e}")))?;
    Ok((description, body))
}

/// CBOR of `value` (writing to memory cannot fail; a value serde refuses,
/// which none of ours is, would give an empty encoding and a load error).
pub fn encode<T: Serialize>(value: &T) -> Vec<u8> {
    let mut bytes = Vec::new();
    ciborium::into_writer(value, &mut bytes).unwrap_or_default();
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sealed_body_opens_and_each_damage_is_named() {
        let sealed = seal(b"MAGIC\n", 3, b"body");
        assert_eq!(open(&sealed, b"MAGIC\n", 3).unwrap(), b"body");
        assert!(matches!(open(&sealed, b"OTHER\n", 3), Err(EnvelopeError::Magic)));
        assert!(matches!(open(&sealed, b"MAGIC\n", 4), Err(EnvelopeError::Version(3))));
        assert!(matches!(open(&sealed[..sealed.len() - 1], b"MAGIC\n", 3), Err(EnvelopeError::Truncated(_))));
        assert!(matches!(open(b"MAG", b"MAGIC\n", 3), Err(EnvelopeError::Truncated(_))));
        let mut longer = sealed.clone();
        longer.push(0);
        assert!(matches!(open(&longer, b"MAGIC\n", 3), Err(EnvelopeError::Corrupt(_))));
        let mut flipped = sealed;
        *flipped.last_mut().unwrap() ^= 1;
        assert!(matches!(open(&flipped, b"MAGIC\n", 3), Err(EnvelopeError::Corrupt(_))));
    }
}
