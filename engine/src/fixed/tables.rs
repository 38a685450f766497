//! Doom's lookup tables (`tables.h`): `finesine` (with `finecosine` a
//! quarter turn into it), `finetangent` and `tantoangle`, read through
//! typed accessors.
//!
//! The values are stored, not computed. Rounding the f64 functions does not
//! give them back: truncating `sin((i + 0.5) * 2pi / 8192) * 65536` misses 33
//! of the 10240 sines (rounding misses 5377), the same for `tan` misses 204
//! tangents and `atan(i / 2048) * 2^31 / pi` misses 1881 of the 2049
//! arctangents by up to 16 binary angles. The tables are not even
//! self-consistent, which no formula would reproduce: 10 sines break the
//! mirror `finesine[i] == finesine[4095 - i]`, 17 the half-turn
//! `finesine[i + 4096] == -finesine[i]`, and 12 of the fifth quarter (which
//! only `finecosine` reads) differ from the first. The data sits in
//! `tables_data.rs` as Rust source, laid out row for row like Chocolate
//! Doom's `tables.c`, rather than as a binary file under `engine/data/`: a
//! reviewer can diff it against the C, and nothing has to be decoded at
//! start-up.

use super::angle::Angle;
use super::number::{Fixed, FRACBITS};
use super::tables_data::{FINESINE, FINETANGENT, TANTOANGLE};

/// Fine angles in a turn: the resolution of the sine and tangent tables.
pub const FINEANGLES: usize = 8192;
/// `FINEANGLES - 1`, to wrap a fine index.
pub const FINEMASK: usize = FINEANGLES - 1;
/// Entries in `tantoangle` less one: slopes from 0 to 1 in steps of 1/2048.
pub const SLOPERANGE: usize = 2048;
/// `log2(SLOPERANGE)`.
pub const SLOPEBITS: u32 = 11;
/// `FRACBITS - SLOPEBITS`: the shift from a 16.16 slope to a `tantoangle` index.
pub const DBITS: u32 = FRACBITS - SLOPEBITS;

/// `finesine[index]`, for `index < 10240` (five quarter turns). Panics past
/// the end, where Doom would read whatever the linker put next.
pub fn finesine(index: usize) -> Fixed {
    Fixed(FINESINE[index])
}

/// `finecosine[index]` = `finesine[index + FINEANGLES / 4]`, for
/// `index < 8192` (any [`Angle::fine_index`]).
pub fn finecosine(index: usize) -> Fixed {
    Fixed(FINESINE[index + FINEANGLES / 4])
}

/// `finetangent[index]`, for `index < 4096`: the tangent of fine angle
/// `index - 2048`, from -90 to +90 degrees. Panics past the end.
pub fn finetangent(index: usize) -> Fixed {
    Fixed(FINETANGENT[index])
}

/// `tantoangle[index]`, for `index <= SLOPERANGE`: the angle whose tangent
/// is `index / 2048`, from 0 to [`ANG45`](super::angle::ANG45).
pub fn tantoangle(index: usize) -> Angle {
    Angle(TANTOANGLE[index])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed::angle::ANG45;

    fn crc_i32(values: &[i32]) -> u32 {
        let mut hasher = crc32fast::Hasher::new();
        for v in values {
            hasher.update(&v.to_le_bytes());
        }
        hasher.finalize()
    }

    #[test]
    fn table_sizes_are_dooms() {
        assert_eq!(FINESINE.len(), 5 * FINEANGLES / 4);
        assert_eq!(FINETANGENT.len(), FINEANGLES / 2);
        assert_eq!(TANTOANGLE.len(), SLOPERANGE + 1);
        assert_eq!(DBITS, 5);
    }

    // The expected values below were read from Chocolate Doom's src/tables.c
    // (commit 941dd35f); the CRC-32s are over each table's entries as
    // little-endian 32-bit words, computed from that file with Python's zlib.

    #[test]
    fn finesine_matches_tables_c() {
        assert_eq!(finesine(0), Fixed(25));
        assert_eq!(finesine(1), Fixed(75));
        assert_eq!(finesine(2047), Fixed(65535));
        assert_eq!(finesine(4096), Fixed(-25));
        assert_eq!(finesine(10239), Fixed(65535));
        assert_eq!(finecosine(0), Fixed(65535));
        assert_eq!(finecosine(FINEMASK), Fixed(65535));
        assert_eq!(crc_i32(&FINESINE), 0x2fe0_55da);
    }

    #[test]
    fn finetangent_matches_tables_c() {
        assert_eq!(finetangent(0), Fixed(-170_910_304));
        assert_eq!(finetangent(1), Fixed(-56_965_752));
        assert_eq!(finetangent(2047), Fixed(-25));
        assert_eq!(finetangent(2048), Fixed(25));
        assert_eq!(finetangent(4095), Fixed(170_910_304));
        assert_eq!(crc_i32(&FINETANGENT), 0x35f9_664b);
    }

    #[test]
    fn tantoangle_matches_tables_c() {
        assert_eq!(tantoangle(0), Angle(0));
        assert_eq!(tantoangle(1), Angle(333_772));
        assert_eq!(tantoangle(1024), Angle(316_933_408));
        assert_eq!(tantoangle(2047), Angle(536_704_000));
        assert_eq!(tantoangle(SLOPERANGE), ANG45);
        let words: Vec<i32> = TANTOANGLE.iter().map(|&a| a as i32).collect();
        assert_eq!(crc_i32(&words), 0xee42_ab92);
    }

    #[test]
    fn the_stored_values_are_the_functions_they_claim() {
        // A guard on the data's shape (no row slipped or repeated): each entry
        // is near the f64 function, within the tables' own error
        // (measured: 1.01 for sine, 0.53% for tangent, 16.4 angles for arctangent).
        let step = std::f64::consts::TAU / FINEANGLES as f64;
        for (i, &s) in FINESINE.iter().enumerate() {
            let want = ((i as f64 + 0.5) * step).sin() * 65536.0;
            assert!((f64::from(s) - want).abs() < 2.0, "finesine[{i}] = {s}, sin gives {want}");
        }
        for (i, &t) in FINETANGENT.iter().enumerate() {
            let want = ((i as f64 - 2048.0 + 0.5) * step).tan() * 65536.0;
            assert!((f64::from(t) - want).abs() <= want.abs() * 0.01 + 2.0, "finetangent[{i}] = {t}, tan gives {want}");
        }
        for (i, &a) in TANTOANGLE.iter().enumerate() {
            let want = (i as f64 / 2048.0).atan() * 2f64.powi(31) / std::f64::consts::PI;
            assert!((f64::from(a) - want).abs() < 32.0, "tantoangle[{i}] = {a}, atan gives {want}");
        }
    }

    #[test]
    fn no_rounding_of_sine_reproduces_the_table() {
        // Why the table is data (see the module docs): truncation, the closest
        // rounding, still disagrees with Doom in dozens of places.
        let step = std::f64::consts::TAU / FINEANGLES as f64;
        let misses = FINESINE
            .iter()
            .enumerate()
            .filter(|&(i, &s)| (((i as f64 + 0.5) * step).sin() * 65536.0).trunc() as i32 != s)
            .count();
        assert!(misses > 20, "only {misses} sines differ from the truncated formula");
    }
}
