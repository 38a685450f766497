//! Doom's sound lumps (`DS*`): the DMX format 3 header, then 8-bit unsigned
//! samples with 16 bytes of padding at each end (repeats of the first and
//! last sample, which the game never plays).
//!
//! | Bytes | Content |
//! | --- | --- |
//! | 0-1 | format, 3 (little-endian u16) |
//! | 2-3 | sample rate in Hz (u16): Freedoom's are 11,025, 22,050 and others |
//! | 4-7 | sample count `N`, the padding included (u32) |
//! | 8-(8+N) | samples, 0 to 255, 128 silent |

use super::Sample;

/// Bytes of padding at each end of the samples.
const PAD: usize = 16;

#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum DmxError {
    #[error("empty (0 bytes)")]
    Empty,
    #[error("{0} bytes, shorter than the 8-byte header")]
    TooShort(usize),
    #[error("format {0}, not 3 (a DMX digital sound)")]
    Format(u16),
    #[error("a sample rate of 0")]
    Rate,
    #[error("the header gives {declared} samples, only {present} bytes follow it")]
    Length { declared: u32, present: usize },
    #[error("no samples")]
    NoSamples,
}

/// The sound in a DMX lump, samples scaled to -1..1.
pub fn decode(bytes: &[u8]) -> Result<Sample, DmxError> {
    if bytes.is_empty() {
        return Err(DmxError::Empty);
    }
    let Some((header, body)) = bytes.split_first_chunk::<8>() else {
        return Err(DmxError::TooShort(bytes.len()));
    };
    let format = u16::from_le_bytes([header[0], header[1]]);
    if format != 3 {
        return Err(DmxError::Format(format));
    }
    let rate = u16::from_le_bytes([header[2], header[3]]);
    if rate == 0 {
        return Err(DmxError::Rate);
    }
    let declared = u32::from_le_bytes([header[4], header[5], header[6], header[7]]);
    if declared as usize > body.len() {
        return Err(DmxError::Length { declared, present: body.len() });
    }
    let samples = &body[..declared as usize];
    // Only a sound long enough to have them has its padding cut.
    let samples = if samples.len() > 2 * PAD { &samples[PAD..samples.len() - PAD] } else { samples };
    if samples.is_empty() {
        return Err(DmxError::NoSamples);
    }
    Ok(Sample { rate: u32::from(rate), data: samples.iter().map(|&s| (f32::from(s) - 128.0) / 128.0).collect() })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lump of `samples` (the padding added) at `rate`.
    pub fn lump(rate: u16, samples: &[u8]) -> Vec<u8> {
        let first = samples.first().copied().unwrap_or(128);
        let last = samples.last().copied().unwrap_or(128);
        let mut bytes = vec![3, 0];
        bytes.extend(rate.to_le_bytes());
        bytes.extend(((samples.len() + 2 * PAD) as u32).to_le_bytes());
        bytes.extend([first; PAD]);
        bytes.extend(samples);
        bytes.extend([last; PAD]);
        bytes
    }

    #[test]
    fn a_lump_decodes_to_its_rate_and_samples_without_the_padding() {
        let s = decode(&lump(11_025, &[128, 255, 0, 64])).unwrap();
        assert_eq!(s.rate, 11_025);
        assert_eq!(s.data, [0.0, 127.0 / 128.0, -1.0, -0.5]);
        let s = decode(&lump(22_050, &[200; 100])).unwrap();
        assert_eq!((s.rate, s.data.len()), (22_050, 100));
        // Bytes after the declared samples (some WADs' lumps have them) are ignored.
        let mut longer = lump(11_025, &[10, 20]);
        longer.extend([1, 2, 3]);
        assert_eq!(decode(&longer).unwrap().data.len(), 2);
        // A short sound without room for padding keeps what it has.
        let short = [3, 0, 0x11, 0x2b, 3, 0, 0, 0, 128, 0, 255];
        assert_eq!(decode(&short).unwrap().data.len(), 3);
    }

    #[test]
    fn bad_lumps_are_errors_saying_what_is_wrong() {
        assert_eq!(decode(&[]), Err(DmxError::Empty));
        assert_eq!(decode(&[3, 0, 0x11]), Err(DmxError::TooShort(3)));
        let mut other = lump(11_025, &[1, 2, 3]);
        other[0] = 2;
        assert_eq!(decode(&other), Err(DmxError::Format(2)));
        let mut no_rate = lump(11_025, &[1, 2, 3]);
        no_rate[2..4].copy_from_slice(&[0, 0]);
        assert_eq!(decode(&no_rate), Err(DmxError::Rate));
        let full = lump(11_025, &[1, 2, 3]);
        for cut in 8..full.len() {
            assert!(matches!(decode(&full[..cut]), Err(DmxError::Length { .. })), "cut at {cut}");
        }
        assert_eq!(decode(&[3, 0, 0x11, 0x2b, 0, 0, 0, 0]), Err(DmxError::NoSamples));
        // Every header field's extreme: never a panic.
        let mut huge = lump(11_025, &[1, 2, 3]);
        huge[4..8].copy_from_slice(&u32::MAX.to_le_bytes());
        assert!(matches!(decode(&huge), Err(DmxError::Length { declared: u32::MAX, .. })));
    }
}
