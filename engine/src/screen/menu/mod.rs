//! The menus as a state machine with no window: the front end's pages
//! (main, new game's episode and skill, load and save with named slots,
//! options with their four sections, the quit confirmation), moved through
//! by [`Command`]s (up, down, left, right, select, back, a typed character,
//! a key for rebinding) and answering with [`Event`]s for the game to carry
//! out (start a game, save, load, quit, a setting changed, a sound to play).
//! [`draw`] draws the page open now over whatever the frame already shows;
//! [`title`] draws our own title picture.
//!
//! Keyboard, mouse and gamepad all come to the menu as commands, so one
//! machine serves them all and the tests drive it as a player would.

pub mod draw;
pub mod title;

/// What the player asks of the menu.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    Up,
    Down,
    Left,
    Right,
    Select,
    Back,
    /// A character typed (a save's name, or Y and N at the quit prompt).
    Text(char),
    /// Backspace: the last character typed, or a binding's keys.
    Erase,
    /// A key pressed while the menu waits for one to bind (its name in the
    /// settings file, such as `KeyW`).
    Key(String),
    /// The pointer is over item `n` of the page (the mouse; see
    /// [`draw::item_at`]).
    Point(usize),
}

/// Doom's menu sounds, by their names in the sound table: the WAD's
/// `DSPSTOP`, `DSPISTOL`, `DSSWTCHN`, `DSSWTCHX` and `DSSTNMOV` when it has
/// them, our own voices otherwise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sound {
    /// The cursor moved (`pstop`).
    Move,
    /// An item chosen (`pistol`).
    Choose,
    /// The menu opened, or a page went back (`swtchn`).
    Open,
    /// The menu closed (`swtchx`).
    Close,
    /// A slider moved (`stnmov`).
    Slide,
}

impl Sound {
    pub fn name(self) -> &'static str {
        match self {
            Sound::Move => "pstop",
            Sound::Choose => "pistol",
            Sound::Open => "swtchn",
            Sound::Close => "swtchx",
            Sound::Slide => "stnmov",
        }
    }
}

/// What the game must do.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A new game: episode (0-based, into [`Setup::episodes`]) and skill 1 to 5.
    NewGame {
        episode: usize,
        skill: u8,
    },
    /// Save to slot (0-based) under a name.
    Save {
        slot: usize,
        name: String,
    },
    Load {
        slot: usize,
    },
    Quit,
    /// [`Menu::settings`] changed (the game applies and keeps them).
    Settings,
    /// The menu closed.
    Closed,
    Sound(Sound),
}

/// Doom's five skills, as its menu names them.
pub const SKILLS: [&str; 5] =
    ["I'm too young to die", "Hey, not too rough", "Hurt me plenty", "Ultra-Violence", "Nightmare!"];

/// Slots on the load and save pages.
pub const SLOTS: usize = 8;

/// One action's keys, as the settings file names them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Binding {
    /// The action's name in the settings file (`forward`).
    pub action: String,
    /// At most two keys.
    pub keys: Vec<String>,
}

/// What the options pages show and change.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Degrees of turn per mouse count.
    pub mouse_sensitivity: f32,
    pub always_run: bool,
    /// 0 to 100.
    pub effects_volume: u8,
    pub music_volume: u8,
    pub status_bar: bool,
    pub hud: bool,
    pub fullscreen: bool,
    pub autoaim: bool,
    pub bindings: Vec<Binding>,
}

/// A saved game as its slot shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct SlotInfo {
    pub name: String,
    /// The map's short name (`E1M1`, `outpost`).
    pub map: String,
    /// Seconds played.
    pub seconds: u64,
    pub skill: u8,
    /// A small picture of the game when it was saved.
    pub thumbnail: Option<crate::Framebuffer>,
}

/// What the menu knows of the game around it.
#[derive(Clone, Debug, Default)]
pub struct Setup {
    /// The episodes a new game can start (one or none: no episode page).
    pub episodes: Vec<String>,
    /// [`SLOTS`] slots, `None` where empty or unreadable.
    pub slots: Vec<Option<SlotInfo>>,
    /// A game is being played (Save Game can be chosen).
    pub in_game: bool,
}

/// A page of the menu.
#[derive(Clone, Debug, PartialEq)]
pub enum Page {
    Main,
    Episode,
    Skill {
        episode: usize,
    },
    Load,
    Save,
    /// Typing the name of a save to `slot`.
    SaveName {
        slot: usize,
        text: String,
    },
    Options,
    Controls,
    Keys,
    Sound,
    Video,
    Gameplay,
    QuitConfirm,
}

/// Longest save name.
pub const NAME_LEN: usize = 24;

/// The menu: the pages open (the last is shown), each with its cursor.
#[derive(Clone, Debug)]
pub struct Menu {
    pub settings: Settings,
    pub setup: Setup,
    stack: Vec<(Page, usize)>,
    /// Waiting for a key to bind to action `n` of the key page.
    pub binding: Option<usize>,
    /// Ticks the menu has been drawn (the cursor's blink).
    pub ticks: u64,
}

/// One line of a page.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// Goes somewhere when chosen.
    Link(&'static str),
    /// A link that cannot be chosen now (Save Game on the title).
    Disabled(&'static str),
    Toggle(&'static str, bool),
    /// A value from 0 to `steps` shown as a bar, and its text.
    Slider(&'static str, usize, usize, String),
    /// An action and its keys.
    Keys(String, String),
    Slot(usize),
    Text(String),
}

impl Menu {
    pub fn new(settings: Settings, setup: Setup) -> Menu {
        Menu { settings, setup, stack: vec![(Page::Main, 0)], binding: None, ticks: 0 }
    }

    pub fn page(&self) -> &Page {
        &self.stack.last().expect("the menu always has a page").0
    }

    pub fn cursor(&self) -> usize {
        self.stack.last().map_or(0, |p| p.1)
    }

    /// Back to the main page (the menu opened afresh).
    pub fn reset(&mut self) {
        self.stack = vec![(Page::Main, 0)];
        self.binding = None;
    }

    /// Opens `page` on top (tests and the game's shortcuts: F2 opens Save).
    pub fn open(&mut self, page: Page) {
        let cursor = match page {
            Page::Skill { .. } => 2,
            _ => 0,
        };
        self.stack.push((page, cursor));
    }

    /// The menu waits for typed text (a save's name): the game sends
    /// characters as [`Command::Text`], not as movement.
    pub fn wants_text(&self) -> bool {
        matches!(self.page(), Page::SaveName { .. })
    }

    /// The menu waits for any key to bind ([`Command::Key`]).
    pub fn wants_key(&self) -> bool {
        self.binding.is_some()
    }

    /// The items of the page shown.
    pub fn items(&self) -> Vec<Item> {
        let s = &self.settings;
        let percent = |v: u8| Item::Slider("", usize::from(v / 10), 10, format!("{v}%"));
        let named = |item: Item, name: &'static str| match item {
            Item::Slider(_, a, b, t) => Item::Slider(name, a, b, t),
            other => other,
        };
        match self.page() {
            Page::Main => vec![
                Item::Link("New Game"),
                Item::Link("Options"),
                Item::Link("Load Game"),
                if self.setup.in_game { Item::Link("Save Game") } else { Item::Disabled("Save Game") },
                Item::Link("Quit Game"),
            ],
            Page::Episode => self.setup.episodes.iter().map(|e| Item::Text(e.clone())).collect(),
            Page::Skill { .. } => SKILLS.iter().map(|s| Item::Text(s.to_string())).collect(),
            Page::Load | Page::Save => (0..SLOTS).map(Item::Slot).collect(),
            Page::SaveName { text, .. } => vec![Item::Text(text.clone())],
            Page::Options => {
                vec![Item::Link("Controls"), Item::Link("Sound"), Item::Link("Video"), Item::Link("Gameplay")]
            }
            Page::Controls => vec![
                Item::Link("Key Bindings"),
                Item::Slider(
                    "Mouse Sensitivity",
                    sensitivity_step(s.mouse_sensitivity),
                    SENSITIVITY_STEPS,
                    format!("{:.2}", s.mouse_sensitivity),
                ),
                Item::Toggle("Always Run", s.always_run),
            ],
            Page::Keys => s.bindings.iter().map(|b| Item::Keys(b.action.clone(), b.keys.join(", "))).collect(),
            Page::Sound => {
                vec![named(percent(s.effects_volume), "Effects Volume"), named(percent(s.music_volume), "Music Volume")]
            }
            Page::Video => vec![
                Item::Toggle("Status Bar", s.status_bar),
                Item::Toggle("HUD Messages", s.hud),
                Item::Toggle("Full Screen", s.fullscreen),
            ],
            Page::Gameplay => vec![Item::Toggle("Autoaim", s.autoaim)],
            Page::QuitConfirm => vec![Item::Link("Yes, quit"), Item::Link("No")],
        }
    }

    /// The page's heading.
    pub fn heading(&self) -> &'static str {
        match self.page() {
            Page::Main => "",
            Page::Episode => "Which Episode?",
            Page::Skill { .. } => "Choose Skill Level",
            Page::Load => "Load Game",
            Page::Save | Page::SaveName { .. } => "Save Game",
            Page::Options => "Options",
            Page::Controls => "Controls",
            Page::Keys => "Key Bindings",
            Page::Sound => "Sound",
            Page::Video => "Video",
            Page::Gameplay => "Gameplay",
            Page::QuitConfirm => "Quit Sightline?",
        }
    }

    /// Carries out `command`; what the game must do comes back in order.
    pub fn command(&mut self, command: Command) -> Vec<Event> {
        let mut events = Vec::new();
        if let Some(n) = self.binding {
            match command {
                Command::Key(key) => {
                    self.bind(n, key);
                    events.extend([Event::Settings, Event::Sound(Sound::Choose)]);
                }
                // Esc (sent as Back when no key name is known) cancels.
                Command::Back => events.push(Event::Sound(Sound::Open)),
                _ => return events,
            }
            self.binding = None;
            return events;
        }
        if let Page::SaveName { slot, text } = self.page().clone() {
            match command {
                Command::Text(c) if text.chars().count() < NAME_LEN && (c.is_ascii_graphic() || c == ' ') => {
                    self.set_name(format!("{text}{c}"));
                }
                Command::Erase => {
                    let mut t = text;
                    t.pop();
                    self.set_name(t);
                }
                Command::Select if !text.trim().is_empty() => {
                    events.extend([Event::Save { slot, name: text.trim().to_string() }, Event::Sound(Sound::Choose)]);
                    self.close(&mut events);
                }
                Command::Back => self.back(&mut events),
                _ => {}
            }
            return events;
        }
        let count = self.items().len();
        match command {
            Command::Up | Command::Down if count > 0 => {
                let at = self.cursor();
                let next = if command == Command::Up { (at + count - 1) % count } else { (at + 1) % count };
                self.set_cursor(next);
                events.push(Event::Sound(Sound::Move));
            }
            Command::Point(n) if n < count && n != self.cursor() => {
                self.set_cursor(n);
                events.push(Event::Sound(Sound::Move));
            }
            Command::Left | Command::Right => {
                let step: i32 = if command == Command::Left { -1 } else { 1 };
                if self.adjust(step) {
                    events.extend([Event::Settings, Event::Sound(Sound::Slide)]);
                }
            }
            Command::Select => self.select(&mut events),
            Command::Back => self.back(&mut events),
            Command::Erase if *self.page() == Page::Keys => {
                let at = self.cursor();
                if let Some(b) = self.settings.bindings.get_mut(at) {
                    b.keys.clear();
                    events.extend([Event::Settings, Event::Sound(Sound::Slide)]);
                }
            }
            Command::Text(c) if *self.page() == Page::QuitConfirm => match c.to_ascii_lowercase() {
                'y' => events.extend([Event::Sound(Sound::Choose), Event::Quit]),
                'n' => self.back(&mut events),
                _ => {}
            },
            _ => {}
        }
        events
    }

    fn set_cursor(&mut self, n: usize) {
        if let Some(top) = self.stack.last_mut() {
            top.1 = n;
        }
    }

    fn set_name(&mut self, name: String) {
        if let Some((Page::SaveName { text, .. }, _)) = self.stack.last_mut() {
            *text = name;
        }
    }

    /// Back a page; from the main page (or the only page) the menu closes.
    fn back(&mut self, events: &mut Vec<Event>) {
        if self.stack.len() <= 1 {
            self.close(events);
        } else {
            self.stack.pop();
            events.push(Event::Sound(Sound::Open));
        }
    }

    fn close(&mut self, events: &mut Vec<Event>) {
        self.reset();
        events.extend([Event::Sound(Sound::Close), Event::Closed]);
    }

    fn select(&mut self, events: &mut Vec<Event>) {
        let at = self.cursor();
        let chosen = Event::Sound(Sound::Choose);
        match self.page().clone() {
            Page::Main => match at {
                0 if self.setup.episodes.len() > 1 => self.go(Page::Episode, events),
                0 => self.go(Page::Skill { episode: 0 }, events),
                1 => self.go(Page::Options, events),
                2 => self.go(Page::Load, events),
                3 if self.setup.in_game => self.go(Page::Save, events),
                4 => self.go(Page::QuitConfirm, events),
                _ => {}
            },
            Page::Episode => self.go(Page::Skill { episode: at }, events),
            Page::Skill { episode } => {
                events.extend([chosen, Event::NewGame { episode, skill: at as u8 + 1 }]);
                self.close_quietly(events);
            }
            Page::Load => {
                if self.setup.slots.get(at).is_some_and(Option::is_some) {
                    events.extend([chosen, Event::Load { slot: at }]);
                    self.close_quietly(events);
                }
            }
            Page::Save => {
                let text = self.setup.slots.get(at).and_then(|s| s.as_ref()).map_or(String::new(), |s| s.name.clone());
                self.go(Page::SaveName { slot: at, text }, events);
            }
            Page::Options => {
                let page = [Page::Controls, Page::Sound, Page::Video, Page::Gameplay][at.min(3)].clone();
                self.go(page, events);
            }
            Page::Controls if at == 0 => self.go(Page::Keys, events),
            Page::Keys => {
                self.binding = Some(at);
                events.push(chosen);
            }
            Page::QuitConfirm if at == 0 => events.extend([chosen, Event::Quit]),
            Page::QuitConfirm => self.back(events),
            // Toggles flip on select as on left and right.
            _ => {
                if self.adjust(1) {
                    events.extend([Event::Settings, chosen]);
                }
            }
        }
    }

    fn go(&mut self, page: Page, events: &mut Vec<Event>) {
        self.open(page);
        events.push(Event::Sound(Sound::Choose));
    }

    /// The menu closes as a game starts or loads: no closing sound.
    fn close_quietly(&mut self, events: &mut Vec<Event>) {
        self.reset();
        events.push(Event::Closed);
    }

    /// Moves the slider or flips the toggle under the cursor; false when
    /// the item has no value or is already at its end.
    fn adjust(&mut self, step: i32) -> bool {
        let s = &mut self.settings;
        let at = self.stack.last().map_or(0, |p| p.1);
        let volume = |v: &mut u8| {
            let new = (i32::from(*v) + step * 10).clamp(0, 100) as u8;
            std::mem::replace(v, new) != new
        };
        match (self.stack.last().map(|p| &p.0), at) {
            (Some(Page::Controls), 1) => {
                let new = SENSITIVITY
                    [(sensitivity_step(s.mouse_sensitivity) as i32 + step).clamp(0, SENSITIVITY_STEPS as i32) as usize];
                std::mem::replace(&mut s.mouse_sensitivity, new) != new
            }
            (Some(Page::Controls), 2) => flip(&mut s.always_run),
            (Some(Page::Sound), 0) => volume(&mut s.effects_volume),
            (Some(Page::Sound), 1) => volume(&mut s.music_volume),
            (Some(Page::Video), 0) => flip(&mut s.status_bar),
            (Some(Page::Video), 1) => flip(&mut s.hud),
            (Some(Page::Video), 2) => flip(&mut s.fullscreen),
            (Some(Page::Gameplay), 0) => flip(&mut s.autoaim),
            _ => false,
        }
    }

    /// `key` becomes action `n`'s first key (its old first key its second),
    /// and leaves any other action that had it: one key, one action.
    fn bind(&mut self, n: usize, key: String) {
        for b in &mut self.settings.bindings {
            b.keys.retain(|k| *k != key);
        }
        if let Some(b) = self.settings.bindings.get_mut(n) {
            b.keys.insert(0, key);
            b.keys.truncate(2);
        }
    }
}

fn flip(b: &mut bool) -> bool {
    *b = !*b;
    true
}

/// The mouse sensitivities the slider steps through (degrees per count):
/// 0.05 to 0.5, the default 0.15 among them.
const SENSITIVITY: [f32; 10] = [0.05, 0.075, 0.1, 0.125, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5];
const SENSITIVITY_STEPS: usize = SENSITIVITY.len() - 1;

/// The slider's step nearest `v`.
fn sensitivity_step(v: f32) -> usize {
    let mut best = 0;
    for (i, s) in SENSITIVITY.iter().enumerate() {
        if (s - v).abs() < (SENSITIVITY[best] - v).abs() {
            best = i;
        }
    }
    best
}
