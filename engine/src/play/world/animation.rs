//! Animated textures and flats (Doom's P_UpdateSpecials): every texture of
//! an animation shows frame `(k + time / tics) mod n` where it is frame `k`,
//! so all of them run in step. The translation lives in
//! [`crate::materials::Materials::translation`], which the renderers apply
//! where they look a texture up: only what is drawn pays for it.

use crate::level::Level;

/// Sets every animated texture's current frame for tick `time`.
pub fn tick(level: &mut Level, time: u64) {
    let materials = &mut level.materials;
    for anim in &materials.animations {
        let n = anim.frames.len();
        let step = (time / u64::from(anim.tics)) as usize % n;
        for (k, &frame) in anim.frames.iter().enumerate() {
            if let Some(slot) = materials.translation.get_mut(frame.0 as usize) {
                *slot = anim.frames[(k + step) % n];
            }
        }
    }
}
