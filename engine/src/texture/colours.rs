//! Player colours: a sprite's green suit redrawn in another player's
//! colour, as Doom's translation tables redraw it (`R_InitTranslationTables`,
//! `R_DrawTranslatedColumn`). It hands [`crate::materials::Materials`] a
//! recoloured copy of a texture, which the renderers draw like any other.
//!
//! Doom maps the green ramp of its palette (indices 0x70 to 0x7f) onto
//! another sixteen-entry ramp, offset for offset: the gray ramp (0x60,
//! player 2, "indigo"), the brown (0x40, player 3) and the dark red (0x20,
//! player 4). Our textures hold colours, not indices, so a texel is
//! recoloured when its colour is one of the green ramp's (no other index of
//! Doom's palette, which Freedoom shares, has one of those colours). Players
//! 5 to 16 have no ramp in Doom: as ZDoom builds a player's ramp from the
//! colour it picked, each gets a colour of its own scaled by the green
//! ramp's brightness, entry for entry.

use super::Texture;
use crate::framebuffer::channels;

/// Colours there are: one for each of sixteen players (0 is Doom's own green).
pub const PLAYER_COLOURS: usize = 16;

/// Doom's palette, 0x70 to 0x7f: the green suit.
const GREEN: [[u8; 3]; 16] = [
    [119, 255, 111],
    [111, 239, 103],
    [103, 223, 95],
    [95, 207, 87],
    [91, 191, 79],
    [83, 175, 71],
    [75, 159, 63],
    [67, 147, 55],
    [63, 131, 47],
    [55, 115, 43],
    [47, 99, 35],
    [39, 83, 27],
    [31, 67, 23],
    [23, 51, 15],
    [19, 35, 11],
    [11, 23, 7],
];

/// Doom's palette, 0x60 to 0x6f: player 2's gray.
const GRAY: [[u8; 3]; 16] = [
    [131, 131, 131],
    [127, 127, 127],
    [119, 119, 119],
    [111, 111, 111],
    [107, 107, 107],
    [99, 99, 99],
    [91, 91, 91],
    [87, 87, 87],
    [79, 79, 79],
    [71, 71, 71],
    [67, 67, 67],
    [59, 59, 59],
    [55, 55, 55],
    [47, 47, 47],
    [39, 39, 39],
    [35, 35, 35],
];

/// Doom's palette, 0x40 to 0x4f: player 3's brown.
const BROWN: [[u8; 3]; 16] = [
    [191, 123, 75],
    [179, 115, 71],
    [171, 111, 67],
    [163, 107, 63],
    [155, 99, 59],
    [143, 95, 55],
    [135, 87, 51],
    [127, 83, 47],
    [119, 79, 43],
    [107, 71, 39],
    [95, 67, 35],
    [83, 63, 31],
    [75, 55, 27],
    [63, 47, 23],
    [51, 43, 19],
    [43, 35, 15],
];

/// Doom's palette, 0x20 to 0x2f: player 4's red.
const RED: [[u8; 3]; 16] = [
    [155, 51, 51],
    [151, 47, 47],
    [143, 43, 43],
    [139, 35, 35],
    [131, 31, 31],
    [127, 27, 27],
    [119, 23, 23],
    [115, 19, 19],
    [107, 15, 15],
    [103, 11, 11],
    [95, 7, 7],
    [91, 7, 7],
    [83, 7, 7],
    [79, 0, 0],
    [71, 0, 0],
    [67, 0, 0],
];

/// Players 5 to 16: blue, yellow, orange, white, cyan, magenta, purple,
/// pink, olive, teal, navy and tan, told apart by hue before brightness.
const OTHERS: [[u8; 3]; 12] = [
    [64, 96, 255],
    [255, 232, 48],
    [255, 128, 16],
    [240, 240, 240],
    [48, 232, 232],
    [240, 64, 240],
    [144, 64, 255],
    [255, 144, 176],
    [176, 176, 64],
    [32, 160, 128],
    [64, 64, 160],
    [208, 160, 96],
];

/// The sixteen colours that take the place of [`GREEN`]'s for `colour`
/// (1 to 15; 0 and anything past the last are Doom's green).
fn ramp(colour: usize) -> [[u8; 3]; 16] {
    match colour {
        1 => GRAY,
        2 => BROWN,
        3 => RED,
        c if c < PLAYER_COLOURS => {
            let base = OTHERS[c - 4];
            // The green ramp's brightness is its green channel, 255 down to 23.
            std::array::from_fn(|i| base.map(|v| (u32::from(v) * u32::from(GREEN[i][1]) / 255) as u8))
        }
        _ => GREEN,
    }
}

/// `texture` with its green suit in player colour `colour` (1 to 15, the
/// player's number less one, as Doom's translation bits hold it), or
/// `None` for Doom's own green (0, or past the last colour) and for a
/// texture with no texel of the green ramp.
pub fn in_colour(texture: &Texture, colour: usize) -> Option<Texture> {
    if colour == 0 || colour >= PLAYER_COLOURS {
        return None;
    }
    let to = ramp(colour);
    let mut changed = false;
    let texels = texture
        .texels
        .iter()
        .map(|&t| {
            let [r, g, b, a] = channels(t);
            match GREEN.iter().position(|&c| c == [r, g, b]) {
                Some(i) if a != 0 => {
                    changed = true;
                    let [r, g, b] = to[i];
                    u32::from_le_bytes([r, g, b, a])
                }
                _ => t,
            }
        })
        .collect();
    changed.then(|| Texture { texels, ..texture.clone() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::rgb;

    fn suit() -> Texture {
        let mut t = Texture::from_fn(16, 2, |u, v| {
            let [r, g, b] = GREEN[u];
            [r, g, b, if v == 0 { 255 } else { 0 }]
        });
        t.texels.push(rgb(1, 2, 3));
        t
    }

    #[test]
    fn players_two_to_four_take_dooms_ramps_and_player_one_keeps_green() {
        let suit = suit();
        assert_eq!(in_colour(&suit, 0), None);
        for (colour, want) in [(1, GRAY), (2, BROWN), (3, RED)] {
            let out = in_colour(&suit, colour).unwrap();
            for (u, c) in want.iter().enumerate() {
                assert_eq!(out.texel(u, 0), rgb(c[0], c[1], c[2]), "colour {colour}, entry {u}");
            }
            // Transparent texels and other colours stay as they were.
            assert_eq!(out.texel(3, 1), suit.texel(3, 1));
            assert_eq!(out.texels.last(), suit.texels.last());
        }
    }

    /// The ramps are Doom's palette as Freedoom ships it, and no other
    /// colour of it is one of the green suit's.
    #[test]
    #[cfg_attr(freedoom_missing, ignore = "needs freedoom2.wad: apt-get install freedoom")]
    fn the_ramps_are_the_palettes_own() {
        let palette = crate::wad::art::Palette::read(&crate::sim::test_wad("freedoom2.wad")).unwrap().0;
        for (ramp, at) in [(GREEN, 0x70), (GRAY, 0x60), (BROWN, 0x40), (RED, 0x20)] {
            assert_eq!(ramp[..], palette[at..at + 16], "the ramp at {at:#x}");
        }
        let elsewhere = (0..256).filter(|i| !(0x70..0x80).contains(i)).filter(|&i| GREEN.contains(&palette[i]));
        assert_eq!(elsewhere.count(), 0);
    }

    #[test]
    fn sixteen_players_have_sixteen_different_suits() {
        let suit = suit();
        let mut suits: Vec<Vec<u32>> = vec![suit.texels.clone()];
        suits.extend((1..PLAYER_COLOURS).map(|c| in_colour(&suit, c).unwrap().texels));
        for i in 0..suits.len() {
            for j in 0..i {
                assert_ne!(suits[i], suits[j], "players {} and {} look alike", j + 1, i + 1);
            }
        }
        assert_eq!(in_colour(&suit, PLAYER_COLOURS), None);
        let plain = Texture::from_fn(2, 2, |_, _| [1, 2, 3, 255]);
        assert_eq!(in_colour(&plain, 5), None, "nothing green, nothing to redraw");
    }
}
