//! Doom's "random" numbers (`m_random.c`): two cursors stepping through
//! one fixed table of 256 bytes. `P_Random` serves the game simulation and
//! must be called exactly when vanilla calls it, or a demo desyncs at once;
//! `M_Random` serves everything that must not disturb the game (menus,
//! screen wipes, sound pitch), so those can differ freely.
//!
//! The state is the two indices and nothing else, owned by whoever owns the
//! game (no globals), serialisable for savegames and sync dumps.

use serde::{Deserialize, Serialize};

/// `rndtable[256]` from `m_random.c`, Chocolate Doom commit 941dd35f.
/// Both cursors start at 0 and step before reading, so the first number
/// drawn is `RNDTABLE[1]`, 8.
#[rustfmt::skip]
pub const RNDTABLE: [u8; 256] = [
      0,   8, 109, 220, 222, 241, 149, 107,  75, 248, 254, 140,  16,  66,  74,  21,
    211,  47,  80, 242, 154,  27, 205, 128, 161,  89,  77,  36,  95, 110,  85,  48,
    212, 140, 211, 249,  22,  79, 200,  50,  28, 188,  52, 140, 202, 120,  68, 145,
     62,  70, 184, 190,  91, 197, 152, 224, 149, 104,  25, 178, 252, 182, 202, 182,
    141, 197,   4,  81, 181, 242, 145,  42,  39, 227, 156, 198, 225, 193, 219,  93,
    122, 175, 249,   0, 175, 143,  70, 239,  46, 246, 163,  53, 163, 109, 168, 135,
      2, 235,  25,  92,  20, 145, 138,  77,  69, 166,  78, 176, 173, 212, 166, 113,
     94, 161,  41,  50, 239,  49, 111, 164,  70,  60,   2,  37, 171,  75, 136, 156,
     11,  56,  42, 146, 138, 229,  73, 146,  77,  61,  98, 196, 135, 106,  63, 197,
    195,  86,  96, 203, 113, 101, 170, 247, 181, 113,  80, 250, 108,   7, 255, 237,
    129, 226,  79, 107, 112, 166, 103, 241,  24, 223, 239, 120, 198,  58,  60,  82,
    128,   3, 184,  66, 143, 224, 145, 224,  81, 206, 163,  45,  63,  90, 168, 114,
     59,  33, 159,  95,  28, 139, 123,  98, 125, 196,  15,  70, 194, 253,  54,  14,
    109, 226,  71,  17, 161,  93, 186,  87, 244, 138,  20,  52, 123, 251,  26,  36,
     17,  46,  52, 231, 232,  76,  31, 221,  84,  37, 216, 165, 212, 106, 197, 242,
     98,  43,  39, 175, 254, 145, 190,  84, 118, 222, 187, 136, 120, 163, 236, 249,
];

/// The two cursors into [`RNDTABLE`]: `prndindex` (the game's) and
/// `rndindex` (everything else's). Each is a byte, so stepping past 255
/// wraps to 0 as Doom's `(index+1)&0xff` does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct DoomRandom {
    prnd: u8,
    rnd: u8,
    /// One entry of the game's table replaced (index, value): how a test
    /// proves that the sync check catches a single wrong number.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    altered: Option<(u8, u8)>,
}

impl DoomRandom {
    /// Both cursors at 0, as at start-up and after [`clear`](Self::clear).
    pub const fn new() -> DoomRandom {
        DoomRandom { prnd: 0, rnd: 0, altered: None }
    }

    /// The same generator with `P_Random`'s entry `index` reading `value`
    /// instead of Doom's (for tests that must see a desync where it happens).
    pub const fn with_altered_entry(self, index: u8, value: u8) -> DoomRandom {
        DoomRandom { altered: Some((index, value)), ..self }
    }

    /// A state with the given cursors, e.g. restored from a sync dump.
    pub const fn from_indices(p_index: u8, m_index: u8) -> DoomRandom {
        DoomRandom { prnd: p_index, rnd: m_index, altered: None }
    }

    /// `P_Random`: the game's next number, 0 to 255. Returned as `i32`, as
    /// Doom's `int`, because callers shift it and subtract from it.
    pub fn p_random(&mut self) -> i32 {
        self.prnd = self.prnd.wrapping_add(1);
        match self.altered {
            Some((index, value)) if index == self.prnd => i32::from(value),
            _ => i32::from(RNDTABLE[usize::from(self.prnd)]),
        }
    }

    /// `M_Random`: the next number for everything outside the simulation.
    pub fn m_random(&mut self) -> i32 {
        self.rnd = self.rnd.wrapping_add(1);
        i32::from(RNDTABLE[usize::from(self.rnd)])
    }

    /// `P_SubRandom`: `P_Random() - P_Random()`, -255 to 255, the first call
    /// being the one subtracted from.
    ///
    /// C leaves the order of the two calls unspecified; Watcom, which built
    /// vanilla Doom, evaluated left to right, and Chocolate Doom pinned that
    /// order in `P_SubRandom` (commit eccc7950, "Add P_SubRandom and fix
    /// P_Random ambiguities"), after Eternity. Each `P_Random() - P_Random()`
    /// in vanilla's source is a call to this.
    pub fn p_subrandom(&mut self) -> i32 {
        let first = self.p_random();
        first - self.p_random()
    }

    /// `M_ClearRandom`: both cursors back to 0, as `G_InitNew` does when a
    /// game (or a demo) starts.
    pub fn clear(&mut self) {
        *self = DoomRandom { altered: self.altered, ..DoomRandom::new() };
    }

    /// `prndindex`: where the game's cursor stands (the index last read).
    pub const fn p_index(&self) -> u8 {
        self.prnd
    }

    /// `rndindex`: where the other cursor stands.
    pub const fn m_index(&self) -> u8 {
        self.rnd
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_matches_m_random_c() {
        assert_eq!(RNDTABLE[0], 0);
        assert_eq!(RNDTABLE[255], 249);
        // CRC-32 of the 256 bytes and their sum, from m_random.c with Python's zlib.
        assert_eq!(crc32fast::hash(&RNDTABLE), 0x5b1e_6d49);
        assert_eq!(RNDTABLE.iter().map(|&b| u32::from(b)).sum::<u32>(), 32986);
    }

    #[test]
    fn p_random_steps_before_reading() {
        let mut r = DoomRandom::new();
        let first: Vec<i32> = (0..6).map(|_| r.p_random()).collect();
        assert_eq!(first, [8, 109, 220, 222, 241, 149]);
        assert_eq!(r.p_index(), 6);
        assert_eq!(r.m_index(), 0);
    }

    #[test]
    fn the_two_cursors_are_independent() {
        let mut r = DoomRandom::new();
        assert_eq!(r.p_random(), 8);
        assert_eq!(r.p_random(), 109);
        assert_eq!(r.m_random(), 8);
        assert_eq!(r.p_random(), 220);
        assert_eq!(r.m_random(), 109);
        assert_eq!((r.p_index(), r.m_index()), (3, 2));
    }

    #[test]
    fn wraps_after_256_calls() {
        let mut r = DoomRandom::new();
        let lap: Vec<i32> = (0..256).map(|_| r.p_random()).collect();
        assert_eq!(lap[254], 249);
        // The 256th call reads index 0, the table's 0, and the lap starts again.
        assert_eq!(lap[255], 0);
        assert_eq!(r.p_index(), 0);
        assert_eq!(r.p_random(), 8);
        let mut m = DoomRandom::from_indices(0, 255);
        assert_eq!(m.m_random(), 0);
        assert_eq!(m.m_index(), 0);
    }

    #[test]
    fn subrandom_subtracts_the_second_draw_from_the_first() {
        let mut r = DoomRandom::new();
        assert_eq!(r.p_subrandom(), 8 - 109);
        assert_eq!(r.p_subrandom(), 220 - 222);
        assert_eq!(r.p_index(), 4);
    }

    #[test]
    fn clear_resets_both_cursors() {
        let mut r = DoomRandom::from_indices(17, 200);
        r.clear();
        assert_eq!(r, DoomRandom::new());
        assert_eq!(r.p_random(), 8);
    }

    #[test]
    fn state_round_trips_through_serde() {
        let r = DoomRandom::from_indices(42, 7);
        let text = ron::to_string(&r).expect("a DoomRandom serialises");
        let back: DoomRandom = ron::from_str(&text).expect("and reads back");
        assert_eq!(back, r);
    }
}
