//! Animated textures and flats (Doom's P_UpdateSpecials), stepped by
//! [`crate::materials::Materials::animate`].

use crate::level::Level;

/// Sets every animated texture's current frame for tick `time`.
pub fn tick(level: &mut Level, time: u64) {
    level.materials.animate(time);
}
