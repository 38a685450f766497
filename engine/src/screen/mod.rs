//! What is drawn over the rendered view, in screen space: the weapon in
//! hand (Doom's player sprites), the palette flashes as tints, and the
//! status bar or the minimal full-screen HUD. The renderers draw the world;
//! [`draw`] finishes a frame of play the same way for the window, `replay`
//! captures and the golden-frame tests.
//!
//! Screen positions are Doom's 320x200, scaled by the frame's height and
//! centred across its width (a wide frame has margins beside the weapon,
//! not a stretched one). The status bar and the HUD also fit the width (a
//! narrow frame such as 320x240 shows them whole, above an empty band);
//! the weapon without the status bar always takes the height's scale, as
//! ZDoom draws it, its sides cut off on a narrow frame ([`view_scale`]).

pub mod attract;
pub mod automap;
pub mod menu;
pub mod status;
pub mod text;
pub mod tint;
pub mod weapon;

use crate::framebuffer::Framebuffer;
use crate::level::Level;
use crate::play::Player;

/// How the bottom of the screen shows the player's state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Hud {
    /// Doom's status bar across the bottom (32 of 200 rows).
    #[default]
    StatusBar,
    /// Figures in the corners over the full view.
    Minimal,
    /// Nothing (captures of the world alone).
    Off,
}

/// Draws the weapon, the tints and the HUD of `player` over a rendered
/// view of `level`; `table` is the game's actor table (the weapon's states).
pub fn draw(fb: &mut Framebuffer, level: &Level, table: &crate::actors::ActorTable, player: &Player, hud: Hud) {
    tint::apply(fb, player);
    weapon::draw(fb, level, table, player, hud == Hud::StatusBar);
    match hud {
        Hud::StatusBar => status::status_bar(fb, level, table, player),
        Hud::Minimal => status::minimal(fb, level, table, player),
        Hud::Off => {}
    }
}

/// Doom's screen scale for `fb`: pixels per 320x200 unit, and the left
/// margin that centres the 320 units.
pub fn scale(fb: &Framebuffer) -> (f64, f64) {
    let s = fb.height as f64 / 200.0;
    let margin = ((fb.width as f64 - 320.0 * s) / 2.0).max(0.0);
    (s.min(fb.width as f64 / 320.0).max(1e-9), margin)
}

/// The scale of the full-screen view's pictures (the weapon with no status
/// bar): the frame's height over 200 whatever its width, and the margin
/// that centres the 320 units, negative on a frame narrower than 16:10
/// (ZDoom's placement of the player's sprites, which ViZDoom's screens
/// show: at 320x240 the weapon is 1.2 times Doom's size, its bottom on the
/// frame's bottom).
pub fn view_scale(fb: &Framebuffer) -> (f64, f64) {
    let s = (fb.height as f64 / 200.0).max(1e-9);
    (s, (fb.width as f64 - 320.0 * s) / 2.0)
}
