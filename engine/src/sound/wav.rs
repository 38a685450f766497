//! Writing rendered audio to a WAV file (16-bit stereo at the output
//! rate), atomically: a temporary file, then a rename.

use std::path::Path;

/// Writes interleaved stereo `samples` (-1..1) to `path` as 16-bit PCM.
pub fn write(path: &Path, samples: &[f32], rate: u32) -> Result<(), String> {
    let spec =
        hound::WavSpec { channels: 2, sample_rate: rate, bits_per_sample: 16, sample_format: hound::SampleFormat::Int };
    let mut bytes = std::io::Cursor::new(Vec::with_capacity(44 + samples.len() * 2));
    {
        let mut writer = hound::WavWriter::new(&mut bytes, spec).map_err(|e| e.to_string())?;
        for &s in samples {
            writer.write_sample((s.clamp(-1.0, 1.0) * 32767.0).round() as i16).map_err(|e| e.to_string())?;
        }
        writer.finalize().map_err(|e| e.to_string())?;
    }
    crate::level::write_file_atomic(path, bytes.get_ref()).map_err(|e| e.to_string())
}
