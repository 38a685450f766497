//! Doom's attract loop, with no window: what the title shows while nobody
//! plays a WAD's game. Pages (TITLEPIC, CREDIT, HELP2) stand for a set
//! number of tics, the WAD's demos play between them, and after the last
//! the loop starts again. The order is Doom's (`D_DoAdvanceDemo`):
//!
//! | game | loop |
//! |---|---|
//! | Doom II (a `MAP01`) | TITLEPIC 11 s, DEMO1, CREDIT 200 tics, DEMO2, TITLEPIC 11 s, DEMO3 |
//! | Ultimate Doom (an `E4M1`) | TITLEPIC 170 tics, DEMO1, CREDIT 200, DEMO2, CREDIT 200, DEMO3, DEMO4 |
//! | Doom, shareware Doom | TITLEPIC 170 tics, DEMO1, CREDIT 200, DEMO2, HELP2 200, DEMO3 |
//!
//! A step whose lump the WAD lacks is left out (a PWAD may carry no demos;
//! then the loop is its pages alone). A demo that cannot be played (not a
//! vanilla demo, a map the WAD lacks) is the game's to skip with
//! [`Attract::advance`]. [`draw_page`] draws a page over the whole frame,
//! scaled as Doom's 320x200 screen and centred.

use crate::framebuffer::{rgb, Framebuffer};
use crate::screen::scale;
use crate::wad::art::{picture, Image, Palette};
use crate::wad::Wad;

/// Doom's page times, in tics.
pub const TITLE_TICS: u32 = 170;
pub const COMMERCIAL_TITLE_TICS: u32 = 11 * 35;
pub const PAGE_TICS: u32 = 200;

/// One step of the loop.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Step {
    /// A full-screen picture (its lump's name), shown for `tics`.
    Page { lump: String, tics: u32 },
    /// A demo lump, played to its end.
    Demo(String),
}

/// Which of Doom's games a WAD is, as far as the loop cares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Doom II and the games built like it (`MAPxx`).
    Commercial,
    /// The Ultimate Doom (four episodes).
    Retail,
    /// Doom before Ultimate, and its shareware episode.
    Registered,
}

impl Mode {
    /// Doom's test, by the maps present: `MAP01` is commercial, `E4M1` retail.
    pub fn of(wad: &Wad) -> Mode {
        if wad.find("MAP01").is_some() {
            Mode::Commercial
        } else if wad.find("E4M1").is_some() {
            Mode::Retail
        } else {
            Mode::Registered
        }
    }

    /// The loop in full, before lumps the WAD lacks are left out.
    pub fn steps(self) -> Vec<Step> {
        let page = |lump: &str, tics| Step::Page { lump: lump.to_string(), tics };
        let demo = |lump: &str| Step::Demo(lump.to_string());
        match self {
            Mode::Commercial => vec![
                page("TITLEPIC", COMMERCIAL_TITLE_TICS),
                demo("DEMO1"),
                page("CREDIT", PAGE_TICS),
                demo("DEMO2"),
                page("TITLEPIC", COMMERCIAL_TITLE_TICS),
                demo("DEMO3"),
            ],
            Mode::Retail => vec![
                page("TITLEPIC", TITLE_TICS),
                demo("DEMO1"),
                page("CREDIT", PAGE_TICS),
                demo("DEMO2"),
                page("CREDIT", PAGE_TICS),
                demo("DEMO3"),
                demo("DEMO4"),
            ],
            Mode::Registered => vec![
                page("TITLEPIC", TITLE_TICS),
                demo("DEMO1"),
                page("CREDIT", PAGE_TICS),
                demo("DEMO2"),
                page("HELP2", PAGE_TICS),
                demo("DEMO3"),
            ],
        }
    }

    /// The title's music: Doom II's `D_DM2TTL`, Doom's `D_INTRO`.
    pub fn music(self) -> &'static str {
        match self {
            Mode::Commercial => "D_DM2TTL",
            Mode::Retail | Mode::Registered => "D_INTRO",
        }
    }
}

/// Where the loop is.
#[derive(Clone, Debug)]
pub struct Attract {
    pub mode: Mode,
    steps: Vec<Step>,
    at: usize,
    /// Tics the page now shown has left (0 for a demo).
    left: u32,
    /// Whether the step now shown has just begun (the game starts its demo
    /// or its music); cleared by [`Attract::begun`].
    fresh: bool,
}

impl Attract {
    /// The loop of `wad`, or None when it has not even a TITLEPIC to show.
    pub fn of(wad: &Wad) -> Option<Attract> {
        let mode = Mode::of(wad);
        let steps: Vec<Step> = mode
            .steps()
            .into_iter()
            .filter(|s| match s {
                Step::Page { lump, .. } | Step::Demo(lump) => wad.find(lump).is_some(),
            })
            .collect();
        if !steps.iter().any(|s| matches!(s, Step::Page { .. })) {
            return None;
        }
        Some(Attract::with(mode, steps))
    }

    /// A loop of `steps` (at least one page).
    pub fn with(mode: Mode, steps: Vec<Step>) -> Attract {
        let mut a = Attract { mode, steps, at: 0, left: 0, fresh: true };
        a.left = a.tics_of(0);
        a
    }

    fn tics_of(&self, at: usize) -> u32 {
        match &self.steps[at] {
            Step::Page { tics, .. } => *tics,
            Step::Demo(_) => 0,
        }
    }

    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// The step shown now.
    pub fn current(&self) -> &Step {
        &self.steps[self.at]
    }

    /// The step shown now, when it has only just begun (once).
    pub fn begun(&mut self) -> Option<&Step> {
        std::mem::take(&mut self.fresh).then(|| &self.steps[self.at])
    }

    /// One tic: a page counts down and gives way to the next step; a demo
    /// waits for the game to say it has ended ([`Attract::advance`]).
    pub fn tick(&mut self) {
        if let Step::Page { .. } = self.current() {
            self.left = self.left.saturating_sub(1);
            if self.left == 0 {
                self.advance();
            }
        }
    }

    /// On to the next step (a demo ended, or could not be played), from the
    /// first after the last.
    pub fn advance(&mut self) {
        self.at = (self.at + 1) % self.steps.len();
        self.left = self.tics_of(self.at);
        self.fresh = true;
    }
}

/// A page of `wad` (`lump`, a picture in Doom's patch format) as an image.
pub fn page(wad: &Wad, lump: &str) -> Result<Image, String> {
    let palette = Palette::read(wad).map_err(|e| e.to_string())?;
    let bytes = wad.lump(lump, " (a page of the title's loop)").map_err(|e| e.to_string())?;
    picture(bytes, &palette).map_err(|e| format!("{}: {lump}: {e}", wad.path))
}

/// Draws `image` over the whole of `fb`: its 320x200 placed as Doom's
/// screen (scaled by the frame's height, centred; black margins), its
/// transparent pixels black.
pub fn draw_page(fb: &mut Framebuffer, image: &Image) {
    let (s, margin) = scale(fb);
    let top = ((fb.height as f64 - 200.0 * s) / 2.0).max(0.0);
    for y in 0..fb.height {
        let v = ((y as f64 + 0.5 - top) / s).floor();
        for x in 0..fb.width {
            let u = ((x as f64 + 0.5 - margin) / s).floor();
            let inside = u >= 0.0 && v >= 0.0 && (u as usize) < image.width && (v as usize) < image.height;
            let c = if inside {
                let [r, g, b, a] = image.rgba[v as usize * image.width + u as usize];
                if a == 0 {
                    rgb(0, 0, 0)
                } else {
                    rgb(r, g, b)
                }
            } else {
                rgb(0, 0, 0)
            };
            fb.pixels[y * fb.width + x] = c;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lumps(names: &[&str]) -> Wad {
        let lumps: Vec<(&str, [u8; 4])> = names.iter().map(|n| (*n, [0u8; 4])).collect();
        Wad::from_bytes(crate::wad::wad_bytes(b"IWAD", &lumps), "test.wad").unwrap()
    }

    fn lumps_of(a: &Attract) -> Vec<String> {
        a.steps()
            .iter()
            .map(|s| match s {
                Step::Page { lump, .. } | Step::Demo(lump) => lump.clone(),
            })
            .collect()
    }

    #[test]
    fn each_game_has_doom_s_order() {
        let all = ["TITLEPIC", "CREDIT", "HELP2", "DEMO1", "DEMO2", "DEMO3", "DEMO4"];
        let doom2 = lumps(&[&all[..], &["MAP01"]].concat());
        let ultimate = lumps(&[&all[..], &["E1M1", "E4M1"]].concat());
        let doom = lumps(&[&all[..], &["E1M1"]].concat());
        let a = Attract::of(&doom2).unwrap();
        assert_eq!(a.mode, Mode::Commercial);
        assert_eq!(lumps_of(&a), ["TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "TITLEPIC", "DEMO3"]);
        assert_eq!(a.current(), &Step::Page { lump: "TITLEPIC".into(), tics: 385 });
        let a = Attract::of(&ultimate).unwrap();
        assert_eq!(lumps_of(&a), ["TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "CREDIT", "DEMO3", "DEMO4"]);
        assert_eq!(a.current(), &Step::Page { lump: "TITLEPIC".into(), tics: 170 });
        let a = Attract::of(&doom).unwrap();
        assert_eq!(lumps_of(&a), ["TITLEPIC", "DEMO1", "CREDIT", "DEMO2", "HELP2", "DEMO3"]);
    }

    #[test]
    fn missing_lumps_are_left_out_and_no_title_is_no_loop() {
        let a = Attract::of(&lumps(&["TITLEPIC", "DEMO2", "MAP01"])).unwrap();
        assert_eq!(lumps_of(&a), ["TITLEPIC", "DEMO2", "TITLEPIC"]);
        assert!(Attract::of(&lumps(&["DEMO1", "DEMO2", "MAP01"])).is_none());
    }

    #[test]
    fn pages_count_down_and_demos_wait_for_their_end() {
        let mut a = Attract::with(
            Mode::Retail,
            vec![Step::Page { lump: "TITLEPIC".into(), tics: 3 }, Step::Demo("DEMO1".into())],
        );
        assert_eq!(a.begun(), Some(&Step::Page { lump: "TITLEPIC".into(), tics: 3 }));
        assert_eq!(a.begun(), None, "a step begins once");
        a.tick();
        a.tick();
        assert!(matches!(a.current(), Step::Page { .. }));
        a.tick();
        assert_eq!(a.begun(), Some(&Step::Demo("DEMO1".into())));
        for _ in 0..1000 {
            a.tick();
        }
        assert_eq!(a.current(), &Step::Demo("DEMO1".into()), "a demo is not timed");
        a.advance();
        assert_eq!(a.begun(), Some(&Step::Page { lump: "TITLEPIC".into(), tics: 3 }), "round again");
    }

    #[test]
    fn a_page_fills_the_frame_scaled_and_centred() {
        let mut image = Image { width: 320, height: 200, rgba: vec![[200, 10, 10, 255]; 320 * 200], left: 0, top: 0 };
        image.rgba[0] = [0, 0, 0, 0];
        image.rgba[319] = [10, 200, 10, 255];
        let mut fb = Framebuffer::new(800, 400);
        draw_page(&mut fb, &image);
        // 2x, with 80 columns of margin each side.
        assert_eq!(fb.get(79, 200), rgb(0, 0, 0));
        assert_eq!(fb.get(80, 0), rgb(0, 0, 0), "a transparent pixel is black");
        assert_eq!(fb.get(82, 0), rgb(200, 10, 10));
        assert_eq!(fb.get(719, 0), rgb(10, 200, 10));
        assert_eq!(fb.get(720, 0), rgb(0, 0, 0));
        assert_eq!(fb.get(400, 399), rgb(200, 10, 10));
    }

    #[test]
    fn a_broken_page_is_an_error_naming_the_lump() {
        let lumps: Vec<(&str, Vec<u8>)> = vec![("PLAYPAL", vec![0u8; 768]), ("TITLEPIC", vec![1u8, 2, 3])];
        let wad = Wad::from_bytes(crate::wad::wad_bytes(b"IWAD", &lumps), "bad.wad").unwrap();
        let e = page(&wad, "TITLEPIC").unwrap_err();
        assert!(e.contains("bad.wad") && e.contains("TITLEPIC"), "{e}");
    }
}
