//! The window's side of a WAD's attract loop (`sightline::screen::attract`):
//! its pages drawn, its demos played on the simulation with Doom's
//! arithmetic, one after another, until the player opens the menu and
//! starts or loads a game.
//!
//! While a demo plays it is the window's session; the session the player
//! will play (the keys and mouse, the sound) waits aside and comes back
//! when the demo ends or a game starts. A demo that cannot be played (not
//! a vanilla demo, a map the WAD lacks, a desync that ends the game early)
//! is said once on the terminal and the loop goes on.

use std::path::PathBuf;

use anyhow::{anyhow, Result};
use sightline::campaign::MapRef;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;
use sightline::screen::attract::{self, Attract, Step};
use sightline::wad::art::Image;
use sightline::wad::Wad;
use sightline::Framebuffer;

use super::session::Session;
use crate::replay_lmp::VanillaRun;

pub struct Loop {
    pub attract: Attract,
    /// The WADs, first the IWAD, and all of them as one.
    wads: Vec<PathBuf>,
    wad: Wad,
    /// The page shown now, decoded (its lump's name beside it).
    page: Option<(String, Image)>,
    /// The session to play, set aside while a demo plays.
    parked: Option<Session>,
    /// The title's music has been asked for.
    music: bool,
    /// Each demo lump of the loop, and the WAD (of `wads`) it is read from:
    /// the last that has it.
    demos: Vec<(String, usize)>,
}

impl Loop {
    /// The loop of the WADs of `map` (a WAD's game), or None when they have
    /// no TITLEPIC.
    pub fn of(map: &MapRef) -> Result<Option<Loop>> {
        let MapRef::Wad { wads, .. } = map else { return Ok(None) };
        let opened = wads.iter().map(|w| Wad::open(w)).collect::<Result<Vec<_>, _>>()?;
        let demos = (1..=4)
            .filter_map(|n| {
                let lump = format!("DEMO{n}");
                let at = opened.iter().rposition(|w| w.find(&lump).is_some())?;
                Some((lump, at))
            })
            .collect();
        let wad = Wad::stack(opened);
        Ok(Attract::of(&wad).map(|attract| Loop {
            attract,
            wads: wads.clone(),
            wad,
            page: None,
            parked: None,
            music: false,
            demos,
        }))
    }

    /// Whether a demo is playing (the window draws the game, not a page).
    pub fn playing(&self) -> bool {
        self.parked.is_some()
    }

    /// Runs `ticks` tics of the loop: pages count down, a demo plays a tic
    /// (`session` is the demo's then) and, once ended, gives the window
    /// back its session; the next step begins. The game set aside stands still.
    pub fn run(&mut self, session: &mut Session, ticks: u32) {
        if let Some(step) = self.attract.begun().cloned() {
            self.begin(session, &step);
        }
        for _ in 0..ticks {
            if self.playing() {
                session.run(1);
                if session.finished() || session.error.is_some() {
                    if let Some(e) = session.error.take() {
                        eprintln!("sightline: the title's demo stopped: {e:#}");
                    }
                    self.stop(session);
                }
            } else {
                self.attract.tick();
            }
            if let Some(step) = self.attract.begun().cloned() {
                self.begin(session, &step);
            }
        }
    }

    /// Starts `step`: a demo becomes the window's session; a page is
    /// decoded (a page that cannot be is said and passed over).
    fn begin(&mut self, session: &mut Session, step: &Step) {
        match step {
            Step::Demo(lump) => match self.demo(lump) {
                Ok(demo) => {
                    let mut play = std::mem::replace(session, demo);
                    session.sound = play.sound.take();
                    if let Some(sound) = &mut session.sound {
                        sound.restart();
                    }
                    self.parked = Some(play);
                    self.music = false;
                    println!("title: playing {lump}");
                }
                Err(e) => {
                    eprintln!("sightline: the title's {lump} is left out: {e:#}");
                    self.attract.advance();
                }
            },
            Step::Page { lump, .. } => {
                if !self.music {
                    if let Some(sound) = &mut session.sound {
                        sound.music(&MapRef::Wad { wads: self.wads.clone(), map: None }, self.attract.mode.music());
                    }
                    self.music = true;
                }
                if self.page.as_ref().is_some_and(|(l, _)| l == lump) {
                    return;
                }
                match attract::page(&self.wad, lump) {
                    Ok(image) => self.page = Some((lump.clone(), image)),
                    Err(e) => {
                        eprintln!("sightline: the title's page is left out: {e}");
                        self.page = None;
                    }
                }
            }
        }
    }

    /// A session playing the demo lump `lump` of the WADs.
    fn demo(&self, lump: &str) -> Result<Session> {
        // The IWAD under the WAD that has it, when that is a PWAD.
        let at = self
            .demos
            .iter()
            .find(|(l, _)| l == lump)
            .map(|&(_, at)| at)
            .ok_or_else(|| anyhow!("no WAD has {lump}"))?;
        let spec = format!("{}:{lump}", self.wads[at].display());
        let iwad = (at > 0).then(|| self.wads[0].as_path());
        let (map, run) = VanillaRun::open(&spec, iwad, &[])?;
        let play = Playthrough::of(&map, GameOptions::default())?;
        Ok(Session::vanilla(play, run))
    }

    /// A demo playing stops and the loop moves on: the session set aside
    /// comes back, with the sound. Nothing while a page shows.
    pub fn stop(&mut self, session: &mut Session) {
        let Some(mut parked) = self.parked.take() else { return };
        parked.sound = session.sound.take();
        *session = parked;
        self.attract.advance();
    }

    /// Draws the page shown now over the whole frame (black when it could
    /// not be read); nothing while a demo plays.
    pub fn draw(&self, fb: &mut Framebuffer) {
        if self.playing() {
            return;
        }
        match &self.page {
            Some((_, image)) => attract::draw_page(fb, image),
            None => fb.pixels.fill(sightline::framebuffer::rgb(0, 0, 0)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::play::input::{Controls, Settings};

    fn freedoom(name: &str) -> Option<PathBuf> {
        let path = PathBuf::from("/usr/share/games/doom").join(name);
        if path.exists() {
            return Some(path);
        }
        assert!(
            std::env::var_os("SIGHTLINE_REQUIRE_FREEDOOM").is_none(),
            "{} is missing and SIGHTLINE_REQUIRE_FREEDOOM is set",
            path.display()
        );
        eprintln!("skipped: {} is not installed (apt install freedoom)", path.display());
        None
    }

    fn live() -> Session {
        let map = MapRef::File(crate::capture::default_map_path());
        let play = Playthrough::of(&map, GameOptions::default()).expect("the default level opens");
        Session::live(play, Controls::new(Settings::with_sensitivity(1.0)), false, false)
    }

    /// freedoom2's loop: TITLEPIC for 11 s, then DEMO1 plays to its end
    /// on its own map, then CREDIT; the session set aside comes back.
    #[test]
    fn freedoom2_s_loop_shows_its_title_then_plays_demo1_to_the_end() {
        let Some(wad) = freedoom("freedoom2.wad") else { return };
        let map = MapRef::Wad { wads: vec![wad], map: None };
        let mut l = Loop::of(&map).unwrap().expect("freedoom2 has a TITLEPIC");
        let mut session = live();
        l.run(&mut session, 0);
        assert_eq!(l.attract.current(), &Step::Page { lump: "TITLEPIC".into(), tics: 385 });
        let mut fb = Framebuffer::new(320, 200);
        l.draw(&mut fb);
        let colours: std::collections::HashSet<u32> = fb.pixels.iter().copied().collect();
        assert!(colours.len() > 50, "the title picture is drawn ({} colours)", colours.len());
        l.run(&mut session, 384);
        assert!(!l.playing());
        l.run(&mut session, 1);
        assert!(l.playing(), "DEMO1 begins after 385 tics");
        assert_eq!(session.play.map.short_name(), "MAP15");
        let mut tics = 0;
        while l.playing() {
            l.run(&mut session, 35);
            tics += 35;
            assert!(tics < 5_000, "DEMO1 (1,415 tics) never ended");
        }
        assert!((1_415..1_415 + 70).contains(&tics), "DEMO1 ended after {tics} tics");
        assert_eq!(l.attract.current(), &Step::Page { lump: "CREDIT".into(), tics: 200 });
        assert!(session.controls().is_some(), "the player's session is back");
        assert_eq!(session.play.map.short_name(), "outpost.ron");
    }

    /// The title's music is the WAD's own, as MIDI for the synthesizer.
    #[test]
    fn the_title_s_music_is_the_wad_s() {
        let Some(wad) = freedoom("freedoom1.wad") else { return };
        let map = MapRef::Wad { wads: vec![wad], map: None };
        let l = Loop::of(&map).unwrap().unwrap();
        let mut sounds = sightline::sound::Sounds::new();
        let cues = sounds.music(&map, l.attract.mode.music());
        assert!(cues.stop_all);
        let midi = cues.music.flatten().expect("D_INTRO plays");
        assert!(midi.starts_with(b"MThd") && midi.len() > 1000, "{} bytes", midi.len());
    }

    /// A demo that cannot be played is passed over.
    #[test]
    fn a_demo_that_cannot_be_played_is_passed_over() {
        let Some(wad) = freedoom("freedoom1.wad") else { return };
        let map = MapRef::Wad { wads: vec![wad], map: None };
        let mut l = Loop::of(&map).unwrap().unwrap();
        assert_eq!(l.attract.mode, attract::Mode::Retail);
        l.attract = Attract::with(
            attract::Mode::Retail,
            vec![
                Step::Page { lump: "TITLEPIC".into(), tics: 2 },
                Step::Demo("DEMO9".into()),
                Step::Page { lump: "CREDIT".into(), tics: 2 },
            ],
        );
        let mut session = live();
        l.run(&mut session, 2);
        assert!(!l.playing());
        assert_eq!(l.attract.current(), &Step::Page { lump: "CREDIT".into(), tics: 2 });
    }
}
