//! The window's event handler and the frame loop. Each redraw: wall time
//! into whole ticks (`TickClock`), the ticks run (`Session`), the view
//! interpolated between the last two ticks rendered into the one
//! `Framebuffer`, the automap and HUD drawn over it, and the result
//! presented (`Screen`). A redraw is requested again as soon as the event
//! queue is empty, so the frame rate is the display's with vsync and as fast
//! as rendering allows without.

use std::path::Path;
use std::time::{Duration, Instant};

use anyhow::Result;
use sightline::level::Level;
use sightline::play::playthrough::Playthrough;
use sightline::render::{render_frame, Frame, RenderOptions, Renderer};
use sightline::Framebuffer;
use winit::application::ApplicationHandler;
use winit::event::{DeviceEvent, DeviceId, ElementState, MouseButton, WindowEvent};
use winit::event_loop::ActiveEventLoop;
use winit::keyboard::PhysicalKey;
use winit::window::WindowId;

use super::clock::TickClock;
use super::hud::Hud;
use super::input::{digit, Action, Keymap};
use super::menus::{self, Front};
use super::saves::{self, Slot};
use super::screen::{Screen, ScreenOptions};
use super::screenshot;
use super::session::Session;
use super::timings::Timings;
use sightline::screen::automap::Automap;

pub struct App {
    screen_options: ScreenOptions,
    screen: Option<Screen>,
    session: Session,
    frame_limit: Option<u64>,
    options: RenderOptions,
    renderers: Vec<Renderer>,
    frame: Frame,
    fb: Framebuffer,
    clock: TickClock,
    hud: Hud,
    /// The status bar or the minimal HUD.
    status: sightline::screen::Hud,
    automap: Automap,
    pub timings: Timings,
    grabbed: bool,
    /// The window's title now (it names the map, which changes between levels).
    title: String,
    last_frame: Option<Instant>,
    frames: u64,
    /// Where saved games go, and a slot asked for (F2 or F3, waiting for a digit).
    save_dir: std::path::PathBuf,
    prompt: Option<Prompt>,
    /// The map file, watched for edits (live reload), and when it was last looked at.
    watch: Option<sightline::play::reload::Watch>,
    watched: Instant,
    /// A ViZDoom scenario being played: its reward is shown.
    scenario: Option<sightline::scenario::ScenarioConfig>,
    /// The keys' bindings (for the window's keys while a demo plays).
    keys: Keymap,
    /// Whether the window was last seen full screen.
    fullscreen: bool,
    /// The gamepads' events, if any pad was found.
    pads: Option<std::sync::mpsc::Receiver<super::gamepad::PadEvent>>,
    /// What stopped the loop, if something went wrong.
    pub error: Option<anyhow::Error>,
    /// The title and the menus over the game (Esc).
    front: Front,
    /// A WAD's attract loop behind its title (pages and demos).
    attract: Option<super::attract::Loop>,
    /// What a new game from the menu starts: the map and the options.
    new_game: (sightline::campaign::MapRef, sightline::play::GameOptions),
    /// The settings as read, for the keymap of rebound keys.
    config: crate::config::Config,
}

/// The settings the player can change in the game, as they are at exit.
#[derive(Clone, Debug, PartialEq)]
pub struct Changeable {
    /// The menu's options (controls, autoaim and the rest).
    pub menu: sightline::screen::menu::Settings,
    pub status_bar: bool,
    pub hud: bool,
    pub fullscreen: bool,
    /// Effects' and music's volumes, 0 to 1 (None: no sound).
    pub volumes: Option<(f32, f32)>,
}

/// F2 or F3 was pressed: the next digit names the slot.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Prompt {
    Save,
    Load,
}

pub struct AppOptions {
    pub screen: ScreenOptions,
    pub renderer: Renderer,
    /// Threads drawing each frame.
    pub threads: usize,
    pub frame_limit: Option<u64>,
    pub hud: bool,
    /// Doom's status bar (else the minimal HUD).
    pub status_bar: bool,
    pub keys: Keymap,
    pub pads: Option<std::sync::mpsc::Receiver<super::gamepad::PadEvent>>,
    pub save_dir: std::path::PathBuf,
    /// A ViZDoom scenario being played: its reward is shown.
    pub scenario: Option<sightline::scenario::ScenarioConfig>,
    /// Start on the title, the menu open (no map was named).
    pub title: bool,
    pub config: crate::config::Config,
    pub new_game: (sightline::campaign::MapRef, sightline::play::GameOptions),
}

impl App {
    pub fn new(session: Session, options: AppOptions) -> App {
        let (w, h) = options.screen.frame;
        let level = session.play.game.level();
        let renderers = renderers_for(level);
        let automap = Automap::new(&level.map);
        let episodes = menus::episodes(&options.new_game.0);
        let mut front = Front::new(&options.config, options.title, episodes, &options.save_dir);
        // A WAD's title runs its attract loop; a key opens the menu over it.
        let attract = match options.title.then(|| super::attract::Loop::of(&options.new_game.0)) {
            Some(Ok(found)) => found,
            Some(Err(e)) => {
                eprintln!("sightline: no attract loop: {e:#}");
                None
            }
            None => None,
        };
        front.open &= attract.is_none();
        let watch = if session.reloadable() { sightline::play::reload::Watch::new(&session.play.map) } else { None };
        App {
            screen_options: options.screen.clone(),
            screen: None,
            session,
            frame_limit: options.frame_limit,
            options: RenderOptions { renderer: options.renderer, threads: options.threads, ..Default::default() },
            renderers,
            frame: Frame::new(),
            fb: Framebuffer::new(w as usize, h as usize),
            clock: TickClock::new(sightline::play::TICRATE),
            hud: Hud::new(options.hud),
            status: if options.status_bar {
                sightline::screen::Hud::StatusBar
            } else {
                sightline::screen::Hud::Minimal
            },
            automap,
            timings: Timings::default(),
            grabbed: false,
            title: options.screen.title.clone(),
            last_frame: None,
            frames: 0,
            watch,
            watched: Instant::now(),
            save_dir: options.save_dir,
            scenario: options.scenario,
            prompt: None,
            keys: options.keys,
            pads: options.pads,
            fullscreen: options.screen.fullscreen,
            error: None,
            front,
            attract,
            new_game: options.new_game,
            config: options.config,
        }
    }

    /// Hands the gamepads' events since the last frame to the controls
    /// (a demo or the autopilot ignores them) and carries out the window
    /// actions their buttons ask for.
    fn read_pads(&mut self, event_loop: &ActiveEventLoop) -> Result<()> {
        let Some(pads) = &self.pads else { return Ok(()) };
        let events: Vec<_> = pads.try_iter().collect();
        for event in events {
            use super::gamepad::{PadButton, PadEvent};
            if self.attract.is_some() && !self.front.open {
                // On the attract loop any button opens the menu.
                if let PadEvent::Button { down: true, .. } = event {
                    self.open_menu();
                }
                continue;
            }
            if self.front.open {
                if let Some(command) = self.front.stick.command(&event) {
                    self.menu_command(event_loop, command);
                }
                continue;
            }
            if let PadEvent::Button { button: PadButton::Start, down: true } = event {
                self.open_menu();
                continue;
            }
            let action = self.session.controls().and_then(|c| c.pad(event));
            if let Some(action) = action {
                self.act(event_loop, action)?;
            }
        }
        Ok(())
    }

    /// The settings the player can change in the game, as they are now.
    pub fn changeable(&self) -> Changeable {
        let m = &self.front.menu.settings;
        let menu_volumes = (f32::from(m.effects_volume) / 100.0, f32::from(m.music_volume) / 100.0);
        Changeable {
            menu: m.clone(),
            status_bar: self.status == sightline::screen::Hud::StatusBar,
            hud: self.hud.visible,
            fullscreen: self.screen.as_ref().map_or(self.fullscreen, Screen::fullscreen),
            // Without sound the menu's volumes are still the player's choice.
            volumes: Some(self.session.sound.as_ref().map_or(menu_volumes, |s| s.volumes())),
        }
    }

    pub fn into_session(self) -> Session {
        self.session
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        self.error.get_or_insert(error);
        event_loop.exit();
    }

    fn redraw(&mut self, event_loop: &ActiveEventLoop) -> Result<()> {
        let now = Instant::now();
        let interval = self.last_frame.map_or(Duration::ZERO, |t| now - t);
        self.last_frame = Some(now);
        let (ticks, alpha) = self.clock.advance(interval);
        self.read_pads(event_loop)?;
        self.reload_if_edited(now);
        // The menu pauses the game; the attract loop plays its demos on
        // behind the menu, as Doom's does.
        match &mut self.attract {
            Some(attract) => attract.run(&mut self.session, ticks),
            None => self.session.run(if self.front.open { 0 } else { ticks }),
        }
        self.front.menu.ticks += u64::from(ticks);
        if let Some(e) = self.session.error.take() {
            return Err(e);
        }
        for m in self.session.take_messages() {
            self.hud.message(m);
        }
        self.follow_map();
        let view = self.session.view(alpha);

        let play = &self.session.play;
        let level = play.game.level();
        let start = Instant::now();
        let demo = self.attract.as_ref().is_some_and(super::attract::Loop::playing);
        if !self.front.title || demo {
            render_frame(level, &view, &self.options, &mut self.frame, &mut self.fb);
        }
        let render = start.elapsed();
        sightline::screen::draw(&mut self.fb, level, &play.game.sim.info.table, play.game.player(), self.status);
        self.automap.accumulate(self.frame.seen_lines());
        if self.automap.visible {
            self.automap.draw(&level.map, (view.pos.x, view.pos.y), view.angle, &mut self.fb);
        }
        self.hud.frame(interval, render);
        let name = map_label(play);
        // The attract loop's demos show the game alone, as Doom's do.
        if self.attract.is_none() {
            self.hud.draw(&mut self.fb, &name, self.options.renderer.name());
        }
        self.hud.draw_status(&mut self.fb, play.game.player());
        if let Some(config) = &self.scenario {
            let reward = sightline::scenario::reward_so_far(&play.game, config);
            self.hud.draw_reward(&mut self.fb, reward);
        }
        super::hud::draw_phase(&mut self.fb, &play.phase);
        match &self.attract {
            Some(attract) => attract.draw(&mut self.fb),
            None if self.front.title => sightline::screen::menu::title::backdrop(&mut self.fb),
            None => {}
        }
        if self.front.open {
            sightline::screen::menu::draw::draw(&mut self.fb, &self.front.menu);
        }

        let Some(screen) = &mut self.screen else { return Ok(()) };
        let start = Instant::now();
        screen.present(&self.fb)?;
        self.timings.push(render, start.elapsed());
        self.frames += 1;
        if self.frame_limit.is_some_and(|n| self.frames >= n) {
            event_loop.exit();
        }
        Ok(())
    }

    fn act(&mut self, event_loop: &ActiveEventLoop, action: Action) -> Result<()> {
        match action {
            Action::Quit => event_loop.exit(),
            Action::ReleaseCursor => self.grab(false),
            Action::ToggleFullscreen => {
                if let Some(screen) = &self.screen {
                    screen.toggle_fullscreen();
                }
            }
            Action::ToggleHud => self.hud.visible = !self.hud.visible,
            Action::ToggleStatusBar => {
                use sightline::screen::Hud;
                self.status = if self.status == Hud::StatusBar { Hud::Minimal } else { Hud::StatusBar };
            }
            Action::ToggleAutomap => self.automap.visible = !self.automap.visible,
            // A screenshot that cannot be written is reported, not fatal.
            Action::Screenshot => match screenshot::save(&self.fb, Path::new(".")) {
                Ok(path) => println!("screenshot: {}", path.display()),
                Err(e) => eprintln!("sightline: screenshot not saved: {e:#}"),
            },
            Action::EffectsVolume(step) | Action::MusicVolume(step) => {
                let (which, what) =
                    if matches!(action, Action::EffectsVolume(_)) { (0, "Effects") } else { (1, "Music") };
                match &mut self.session.sound {
                    Some(sound) => {
                        let level = sound.nudge(which, f32::from(step) / 10.0);
                        self.say(format!("{what} volume {}%", (level * 100.0).round()));
                    }
                    None => self.say("No sound (started with --no-sound, or no sound server)".into()),
                }
            }
            Action::QuickSave => self.save(Slot::Quick),
            Action::QuickLoad => {
                self.load(Slot::Quick);
            }
            Action::SaveSlot => self.ask(Prompt::Save),
            Action::LoadSlot => self.ask(Prompt::Load),
            Action::CycleRenderer => {
                let at = self.renderers.iter().position(|&r| r == self.options.renderer);
                let next = at.map_or(0, |i| (i + 1) % self.renderers.len());
                if let Some(&r) = self.renderers.get(next) {
                    self.options.renderer = r;
                }
            }
        }
        Ok(())
    }

    /// Four times a second, looks at the map file; an edit is played at
    /// once (the player kept where it stands), a broken one shown until fixed.
    fn reload_if_edited(&mut self, now: Instant) {
        use sightline::play::reload::Reload;
        if now - self.watched < Duration::from_millis(250) {
            return;
        }
        self.watched = now;
        let Some(watch) = &mut self.watch else { return };
        match watch.poll(&mut self.session.play) {
            Reload::Unchanged => {}
            Reload::Reloaded { kept_pose } => {
                self.hud.map_error = None;
                let name = watch.path().display().to_string();
                self.title.clear();
                self.follow_map();
                let at = if kept_pose { "where you stood" } else { "at its start (where you stood is outside it now)" };
                self.say(format!("Reloaded {name}: you are {at}"));
            }
            Reload::Broken(error) => {
                eprintln!("sightline: {error}");
                self.hud.map_error = Some(error);
            }
        }
    }

    /// A message on the HUD and on the terminal.
    fn say(&mut self, text: String) {
        println!("{text}");
        self.hud.message(text);
    }

    fn ask(&mut self, prompt: Prompt) {
        self.prompt = Some(prompt);
        let verb = if prompt == Prompt::Save { "Save to" } else { "Load from" };
        self.say(format!("{verb} which slot? Press 1 to 9 (any other key: cancel)"));
    }

    /// The key pressed after F2 or F3: a digit from 1 to 9 saves or loads
    /// that slot; anything else cancels.
    fn answer(&mut self, prompt: Prompt, key: winit::keyboard::KeyCode) {
        match digit(key).filter(|&d| d >= 1) {
            Some(d) if prompt == Prompt::Save => self.save(Slot::Numbered(d)),
            Some(d) => {
                self.load(Slot::Numbered(d));
            }
            None => self.say("Cancelled".into()),
        }
    }

    /// Saves the game to `slot`; a save that fails is reported, not fatal.
    fn save(&mut self, slot: Slot) {
        let path = saves::path(&self.save_dir, slot);
        match self.session.save(&path) {
            Ok(()) => self.say(format!("Game saved to {} ({})", slot.describe(), path.display())),
            Err(e) => self.say(format!("Not saved: {e:#}")),
        }
    }

    /// Loads the game in `slot`; a load that fails is reported and the game
    /// goes on (false).
    fn load(&mut self, slot: Slot) -> bool {
        let path = saves::path(&self.save_dir, slot);
        match self.session.load(&path) {
            Ok(()) => {
                // The map may be another: the title, automap and renderers follow it.
                self.title.clear();
                self.follow_map();
                let play = &self.session.play;
                let at = play.game.ticks() / u64::from(sightline::play::TICRATE);
                self.say(format!(
                    "Loaded {} ({}, {}:{:02} in)",
                    slot.describe(),
                    play.map.short_name(),
                    at / 60,
                    at % 60
                ));
                true
            }
            Err(e) => {
                self.say(format!("Not loaded: {e:#}"));
                false
            }
        }
    }

    /// A new map (the next level, or a restart): the title names it, the
    /// automap starts empty, and the renderer must be one that draws it.
    fn follow_map(&mut self) {
        let title = title(&self.session.play);
        if title == self.title {
            return;
        }
        let level = self.session.play.game.level();
        self.automap = Automap::new(&level.map);
        self.renderers = renderers_for(level);
        // Watch the file of the map now played (another after a load or the next level).
        let watching = self.watch.as_ref().map(|w| w.path().to_path_buf());
        if self.session.reloadable()
            && !matches!((&watching, &self.session.play.map), (Some(w), sightline::campaign::MapRef::File(p)) if w == p)
        {
            self.watch = sightline::play::reload::Watch::new(&self.session.play.map);
        }
        if !self.options.renderer.supports(level) {
            self.options.renderer = Renderer::default_for(level);
        }
        if let Some(screen) = &self.screen {
            screen.window.set_title(&title);
        }
        self.title = title;
    }

    /// Esc in the game: the menu opens on its main page and the game pauses.
    fn open_menu(&mut self) {
        self.front.menu.reset();
        self.front.menu.setup.slots = menus::slots(&self.save_dir);
        self.front.open = true;
        if let Some(controls) = self.session.controls() {
            controls.release_all();
        }
        self.grab(false);
        self.menu_sound(sightline::screen::menu::Sound::Open);
    }

    fn menu_sound(&mut self, sound: sightline::screen::menu::Sound) {
        if let Some(out) = &mut self.session.sound {
            out.menu_sound(sound.name());
        }
    }

    /// The pointer at window position (`x`, `y`): the item under it is chosen.
    fn point(&mut self, x: f64, y: f64) {
        if self.front.pointer.replace((x, y)).is_none_or(|was| was == (x, y)) {
            return;
        }
        let Some(screen) = &self.screen else { return };
        let size = screen.window.inner_size();
        let (fw, fh) = (self.fb.width as f64, self.fb.height as f64);
        // The frame is scaled to fit the window, centred (as `Screen` presents it).
        let k = (f64::from(size.width) / fw).min(f64::from(size.height) / fh).max(1e-9);
        let fx = (x - (f64::from(size.width) - fw * k) / 2.0) / k;
        let fy = (y - (f64::from(size.height) - fh * k) / 2.0) / k;
        if fx < 0.0 || fy < 0.0 {
            return;
        }
        let at = sightline::screen::menu::draw::item_at(
            &self.front.menu,
            self.fb.width,
            self.fb.height,
            fx as usize,
            fy as usize,
        );
        if let Some(n) = at {
            self.menu_command_quiet(sightline::screen::menu::Command::Point(n));
        }
    }

    fn menu_command_quiet(&mut self, command: sightline::screen::menu::Command) {
        for event in self.front.menu.command(command) {
            if let sightline::screen::menu::Event::Sound(s) = event {
                self.menu_sound(s);
            }
        }
    }

    /// A menu command from the keys, the mouse or a gamepad, and what it asks for.
    pub fn menu_command(&mut self, event_loop: &ActiveEventLoop, command: sightline::screen::menu::Command) {
        use sightline::screen::menu::Event;
        for event in self.front.menu.command(command) {
            match event {
                Event::Sound(s) => self.menu_sound(s),
                // The title keeps its menu (the attract loop goes on without).
                Event::Closed => self.front.open = self.front.title && self.attract.is_none(),
                Event::Quit => event_loop.exit(),
                Event::Settings => self.apply_settings(),
                Event::NewGame { episode, skill } => self.start_new_game(episode, skill),
                Event::Load { slot } => {
                    self.stop_attract();
                    if self.load(Slot::Numbered(slot as u8 + 1)) {
                        self.attract = None;
                        self.front.title = false;
                        self.front.open = false;
                        self.front.menu.setup.in_game = true;
                    }
                }
                Event::Save { slot, name } => {
                    self.save(Slot::Numbered(slot as u8 + 1));
                    if let Err(e) = menus::label_slot(&self.save_dir, slot, &name, &self.fb) {
                        self.say(format!("The save's name and picture were not kept: {e:#}"));
                    }
                }
            }
        }
    }

    /// The menu's options put in force at once.
    fn apply_settings(&mut self) {
        use sightline::screen::Hud;
        let m = self.front.menu.settings.clone();
        self.status = if m.status_bar { Hud::StatusBar } else { Hud::Minimal };
        self.hud.visible = m.hud;
        if let Some(screen) = &self.screen {
            if screen.fullscreen() != m.fullscreen {
                screen.toggle_fullscreen();
            }
        }
        self.fullscreen = m.fullscreen;
        if let Some(sound) = &mut self.session.sound {
            sound.set_volumes(f32::from(m.effects_volume) / 100.0, f32::from(m.music_volume) / 100.0);
        }
        let mut config = self.config.clone();
        menus::controls_into(&m, &mut config);
        self.keys = Keymap::of(&config.bindings());
        if let Some(controls) = self.session.controls() {
            let s = controls.settings_mut();
            s.keys = Keymap::of(&config.bindings());
            s.sensitivity = m.mouse_sensitivity;
            s.always_run = m.always_run;
        }
    }

    /// New Game: the chosen episode's first map at the chosen skill.
    fn start_new_game(&mut self, episode: usize, skill: u8) {
        let (start, options) = &self.new_game;
        let map = menus::first_map(start, &self.front.menu.setup.episodes, episode);
        let options = sightline::play::GameOptions { skill, ..*options };
        let setup = sightline::sim::game::Setup {
            no_autoaim: !self.front.menu.settings.autoaim,
            ..sightline::sim::game::Setup::SINGLE
        };
        self.stop_attract();
        let started = Playthrough::of_set_up(&map, options, setup)
            .map_err(anyhow::Error::from)
            .and_then(|play| self.session.new_game(play));
        match started {
            Ok(()) => {
                self.attract = None;
                let name = sightline::screen::menu::SKILLS[usize::from(skill.clamp(1, 5)) - 1];
                self.say(format!("New game: {} on skill {skill} ({name})", map.short_name()));
                self.front.title = false;
                self.front.open = false;
                self.front.menu.setup.in_game = true;
                self.title.clear();
                self.follow_map();
            }
            Err(e) => self.say(format!("No new game: {e:#}")),
        }
    }

    /// A demo of the attract loop stops (a game is about to start): the
    /// player's session comes back; the loop goes on if the game does not.
    fn stop_attract(&mut self) {
        if let Some(attract) = &mut self.attract {
            attract.stop(&mut self.session);
        }
    }

    fn grab(&mut self, grab: bool) {
        if let Some(screen) = &self.screen {
            self.grabbed = screen.grab_cursor(grab);
        }
    }
}

/// The window's title: the map played, and its WAD or its name.
pub fn title(play: &Playthrough) -> String {
    format!("Sightline: {}", map_label(play))
}

/// The map played, and its WAD or its name: `E1M1 (freedoom1.wad)`.
fn map_label(play: &Playthrough) -> String {
    let from = match &play.map {
        sightline::campaign::MapRef::Wad { wads, .. } => wads
            .iter()
            .map(|w| w.file_name().map_or_else(|| w.display().to_string(), |n| n.to_string_lossy().into_owned()))
            .collect::<Vec<_>>()
            .join(" + "),
        sightline::campaign::MapRef::File(_) => play.game.level().map.name.clone(),
    };
    format!("{} ({from})", play.map.short_name())
}

/// The renderers that can draw `level`: all of them, but the ray-caster
/// only on grid maps.
fn renderers_for(level: &Level) -> Vec<Renderer> {
    Renderer::ALL.into_iter().filter(|r| r.supports(level)).collect()
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.screen.is_some() {
            return;
        }
        match Screen::open(event_loop, &self.screen_options) {
            Ok(screen) => self.screen = Some(screen),
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let result = match event {
            WindowEvent::CloseRequested => {
                event_loop.exit();
                Ok(())
            }
            WindowEvent::Resized(size) => match &mut self.screen {
                Some(screen) => screen.resize(size.width, size.height),
                None => Ok(()),
            },
            WindowEvent::RedrawRequested => self.redraw(event_loop),
            WindowEvent::Focused(false) => {
                if let Some(controls) = self.session.controls() {
                    controls.release_all();
                }
                self.grab(false);
                Ok(())
            }
            WindowEvent::CursorMoved { position, .. } if self.front.open => {
                self.point(position.x, position.y);
                Ok(())
            }
            WindowEvent::MouseInput { state: ElementState::Pressed, .. }
                if self.attract.is_some() && !self.front.open =>
            {
                self.open_menu();
                Ok(())
            }
            WindowEvent::MouseInput { state: ElementState::Pressed, button, .. } if self.front.open => {
                use sightline::screen::menu::Command;
                match button {
                    MouseButton::Left => self.menu_command(event_loop, Command::Select),
                    MouseButton::Right => self.menu_command(event_loop, Command::Back),
                    _ => {}
                }
                Ok(())
            }
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => {
                let down = state == ElementState::Pressed;
                if !self.grabbed {
                    // The click that grabs the mouse does not fire.
                    if down {
                        self.grab(true);
                    }
                } else if let Some(controls) = self.session.controls() {
                    controls.mouse_button(down);
                }
                Ok(())
            }
            WindowEvent::KeyboardInput { event, .. } => {
                let PhysicalKey::Code(code) = event.physical_key else { return };
                let down = event.state == ElementState::Pressed;
                if down && self.front.open {
                    if let Some(command) = menus::command(&self.front.menu, code, event.text.as_deref()) {
                        self.menu_command(event_loop, command);
                    }
                    return;
                }
                // On the attract loop any key opens the menu, as in Doom.
                let attract = self.attract.is_some();
                if down && !event.repeat && (code == winit::keyboard::KeyCode::Escape || attract) {
                    self.open_menu();
                    return;
                }
                if down && !event.repeat {
                    if let Some(prompt) = self.prompt.take() {
                        self.answer(prompt, code);
                        return;
                    }
                }
                let action = match self.session.controls() {
                    Some(controls) => controls.key(code, down, event.repeat),
                    // A demo drives the player; the window keys still work.
                    None => self.keys.window_action(code, down, event.repeat),
                };
                match action {
                    Some(action) => self.act(event_loop, action),
                    None => Ok(()),
                }
            }
            _ => Ok(()),
        };
        if let Err(e) = result {
            self.fail(event_loop, e);
        }
    }

    fn device_event(&mut self, _event_loop: &ActiveEventLoop, _id: DeviceId, event: DeviceEvent) {
        if let DeviceEvent::MouseMotion { delta: (dx, _) } = event {
            if self.grabbed {
                if let Some(controls) = self.session.controls() {
                    controls.mouse(dx);
                }
            }
        }
    }

    fn about_to_wait(&mut self, _event_loop: &ActiveEventLoop) {
        if let Some(screen) = &self.screen {
            screen.window.request_redraw();
        }
    }

    fn exiting(&mut self, _event_loop: &ActiveEventLoop) {
        // The surface must go before the window it draws into.
        self.screen = None;
    }
}
