//! Doom's palette flashes as tints over the whole view: red when hurt (and,
//! fading, with berserk), gold on a pickup, green in a radiation suit, and
//! the world in inverted greys while invulnerable. Doom swaps palettes in
//! steps; a tint blends each pixel towards the colour by the same steps.

use crate::actors::Power;
use crate::framebuffer::Framebuffer;
use crate::play::Player;

/// The tint a player's state calls for: colour and share (0 to 1), or the
/// invulnerability greys.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tint {
    None,
    Blend([u8; 3], f32),
    Inverse,
}

/// Doom's choice (ST_doPaletteStuff): the red of hurt or berserk first,
/// then the gold of a pickup, then the suit's green (blinking in its last
/// seconds); invulnerability (also blinking out) overrides them.
pub fn of(player: &Player) -> Tint {
    // The read-out keeps Doom's power order (`powertype_t`), as `Power` does.
    let power = |p: Power| player.powers[p as usize];
    let invulnerable = power(Power::Invulnerability);
    if invulnerable > 4 * 32 || invulnerable & 8 != 0 {
        return Tint::Inverse;
    }
    let mut red = player.damage_count;
    if power(Power::Strength) > 0 {
        // Berserk's red fades over its first few seconds (Doom counts up).
        let fade = 12 - (power(Power::Strength) >> 6);
        red = red.max(fade);
    }
    if red > 0 {
        let step = ((red + 7) >> 3).min(8);
        return Tint::Blend([255, 0, 0], step as f32 / 9.0);
    }
    if player.bonus_count > 0 {
        let step = ((player.bonus_count + 7) >> 3).min(4);
        return Tint::Blend([215, 186, 69], step as f32 / 8.0);
    }
    let suit = power(Power::IronFeet);
    if suit > 4 * 32 || suit & 8 != 0 {
        return Tint::Blend([0, 255, 0], 0.125);
    }
    Tint::None
}

/// Applies the player's tint to the frame.
pub fn apply(fb: &mut Framebuffer, player: &Player) {
    match of(player) {
        Tint::None => {}
        Tint::Blend(c, share) => {
            let k = (share.clamp(0.0, 1.0) * 256.0) as u32;
            for p in &mut fb.pixels {
                let [r, g, b, a] = p.to_le_bytes();
                let mix = |x: u8, t: u8| ((u32::from(x) * (256 - k) + u32::from(t) * k) >> 8) as u8;
                *p = u32::from_le_bytes([mix(r, c[0]), mix(g, c[1]), mix(b, c[2]), a]);
            }
        }
        Tint::Inverse => {
            for p in &mut fb.pixels {
                let [r, g, b, a] = p.to_le_bytes();
                let grey = (u32::from(r) * 77 + u32::from(g) * 150 + u32::from(b) * 29) >> 8;
                let v = 255 - grey as u8;
                *p = u32::from_le_bytes([v, v, v, a]);
            }
        }
    }
}
