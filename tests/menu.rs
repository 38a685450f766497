//! The menus headless: every path a player can take through them (a new
//! game on each episode and skill, a save under a typed name, a load, each
//! option changed and read back, a key rebound, quit confirmed and
//! cancelled), driven by the same commands the window sends, and a golden
//! image of each page (`tests/images/menu-*.png`; regenerate with
//! `SIGHTLINE_BLESS=1 cargo test -p sightline-tests --test menu` and look at
//! every changed image).

use sightline::screen::menu::draw::{draw, item_at};
use sightline::screen::menu::{title, Binding, Command, Event, Menu, Page, Settings, Setup, SlotInfo, Sound, SLOTS};
use sightline::Framebuffer;
use sightline_tests::golden;

use Command::*;

fn settings() -> Settings {
    let b = |a: &str, k: &[&str]| Binding { action: a.into(), keys: k.iter().map(|s| s.to_string()).collect() };
    Settings {
        mouse_sensitivity: 0.15,
        always_run: false,
        effects_volume: 80,
        music_volume: 60,
        status_bar: true,
        hud: true,
        fullscreen: false,
        autoaim: true,
        bindings: vec![
            b("forward", &["KeyW", "ArrowUp"]),
            b("back", &["KeyS", "ArrowDown"]),
            b("strafe_left", &["KeyA"]),
            b("strafe_right", &["KeyD"]),
            b("turn_left", &["ArrowLeft"]),
            b("turn_right", &["ArrowRight"]),
            b("run", &["ShiftLeft", "ShiftRight"]),
            b("use", &["KeyE", "Space"]),
            b("fire", &["ControlLeft", "KeyF"]),
            b("weapon1", &["Digit1"]),
            b("weapon2", &["Digit2"]),
            b("weapon3", &["Digit3"]),
            b("weapon4", &["Digit4"]),
            b("weapon5", &["Digit5"]),
            b("weapon6", &["Digit6"]),
            b("weapon7", &["Digit7"]),
            b("quit", &["KeyQ"]),
            b("automap", &["Tab"]),
            b("screenshot", &["F12"]),
        ],
    }
}

/// A thumbnail that is not flat: a gradient with a bar across.
fn thumbnail() -> Framebuffer {
    let mut fb = Framebuffer::new(160, 100);
    for y in 0..100 {
        for x in 0..160 {
            let bar = (40..60).contains(&y);
            fb.pixels[y * 160 + x] = if bar {
                sightline::framebuffer::rgb(200, 180, 40)
            } else {
                sightline::framebuffer::rgb(x as u8, (y * 2) as u8, 90)
            };
        }
    }
    fb
}

fn setup(episodes: usize, in_game: bool) -> Setup {
    let mut slots = vec![None; SLOTS];
    slots[0] = Some(SlotInfo {
        name: "Before the blue door".into(),
        map: "E1M2".into(),
        seconds: 754,
        skill: 4,
        thumbnail: Some(thumbnail()),
    });
    slots[2] =
        Some(SlotInfo { name: "Old save".into(), map: "outpost".into(), seconds: 61, skill: 3, thumbnail: None });
    Setup { episodes: (1..=episodes).map(|e| format!("Episode {e}")).collect(), slots, in_game }
}

/// Runs `commands`, returning every event but the sounds.
fn run(menu: &mut Menu, commands: &[Command]) -> Vec<Event> {
    commands.iter().flat_map(|c| menu.command(c.clone())).filter(|e| !matches!(e, Event::Sound(_))).collect()
}

#[test]
fn new_game_on_every_episode_and_skill() {
    for episodes in [1, 4] {
        for episode in 0..episodes {
            for skill in 1..=5u8 {
                let mut menu = Menu::new(settings(), setup(episodes, false));
                let mut path = vec![Select];
                if episodes > 1 {
                    path.extend(std::iter::repeat_n(Down, episode));
                    path.push(Select);
                }
                // The skill page opens on Hurt me plenty (3), as Doom's.
                assert!(matches!(run(&mut menu, &path)[..], []));
                assert_eq!(menu.page(), &Page::Skill { episode });
                assert_eq!(menu.cursor(), 2);
                let moves =
                    if skill >= 3 { vec![Down; usize::from(skill - 3)] } else { vec![Up; usize::from(3 - skill)] };
                run(&mut menu, &moves);
                let events = run(&mut menu, &[Select]);
                assert_eq!(
                    events,
                    vec![Event::NewGame { episode, skill }, Event::Closed],
                    "{episodes} {episode} {skill}"
                );
                assert_eq!(menu.page(), &Page::Main, "the menu is back at its start");
            }
        }
    }
}

#[test]
fn save_with_a_typed_name_and_load() {
    let mut menu = Menu::new(settings(), setup(1, true));
    // Main -> Save Game -> slot 2 (empty) -> type, erase, type -> Enter.
    run(&mut menu, &[Down, Down, Down, Select, Down, Select]);
    assert_eq!(menu.page(), &Page::SaveName { slot: 1, text: String::new() });
    assert!(menu.wants_text());
    // An empty name is not saved.
    assert_eq!(run(&mut menu, &[Select]), vec![]);
    let typed: Vec<Command> = "Red key!x".chars().map(Text).chain([Erase]).collect();
    run(&mut menu, &typed);
    assert_eq!(run(&mut menu, &[Select]), vec![Event::Save { slot: 1, name: "Red key!".into() }, Event::Closed]);
    // A filled slot offers its name to edit.
    let mut menu = Menu::new(settings(), setup(1, true));
    run(&mut menu, &[Down, Down, Down, Select, Select]);
    assert_eq!(menu.page(), &Page::SaveName { slot: 0, text: "Before the blue door".into() });
    // Back returns to the slots, then to the main page.
    run(&mut menu, &[Back, Back]);
    assert_eq!(menu.page(), &Page::Main);
    // Load: an empty slot does nothing, a filled one loads.
    let mut menu = Menu::new(settings(), setup(1, false));
    run(&mut menu, &[Down, Down, Select, Down]);
    assert_eq!(run(&mut menu, &[Select]), vec![]);
    assert_eq!(run(&mut menu, &[Down, Select]), vec![Event::Load { slot: 2 }, Event::Closed]);
    // On the title there is no game to save.
    let mut menu = Menu::new(settings(), setup(1, false));
    run(&mut menu, &[Down, Down, Down, Select]);
    assert_eq!(menu.page(), &Page::Main);
}

#[test]
fn options_change_and_read_back() {
    let mut menu = Menu::new(settings(), setup(1, true));
    // Options -> Sound: effects down two steps, music up one.
    run(&mut menu, &[Down, Select, Down, Select]);
    assert_eq!(menu.page(), &Page::Sound);
    let events = run(&mut menu, &[Left, Left, Down, Right]);
    assert_eq!(events, vec![Event::Settings; 3]);
    // Volumes stop at their ends without a change.
    assert_eq!(run(&mut menu, &[Right, Right, Right, Right, Right]), vec![Event::Settings; 3]);
    assert_eq!((menu.settings.effects_volume, menu.settings.music_volume), (60, 100));
    // Video: each toggle; Gameplay: autoaim; Controls: sensitivity and always run.
    run(&mut menu, &[Back, Down, Select, Select, Down, Right, Down, Left, Back]);
    assert_eq!((menu.settings.status_bar, menu.settings.hud, menu.settings.fullscreen), (false, false, true));
    run(&mut menu, &[Down, Select, Select, Back]);
    assert!(!menu.settings.autoaim);
    run(&mut menu, &[Up, Up, Up, Select]);
    assert_eq!(menu.page(), &Page::Controls);
    run(&mut menu, &[Down, Right, Right, Down, Select]);
    assert_eq!((menu.settings.mouse_sensitivity, menu.settings.always_run), (0.25, true));
    // The settings read back from the menu are what was set; a new menu
    // made from them shows them.
    let again = Menu::new(menu.settings.clone(), setup(1, true));
    assert_eq!(again.settings, menu.settings);
    // Every sound the menu asks for is one of Doom's menu sounds.
    let sounds: Vec<Sound> =
        menu.command(Up).into_iter().filter_map(|e| if let Event::Sound(s) = e { Some(s) } else { None }).collect();
    assert_eq!(sounds, vec![Sound::Move]);
}

#[test]
fn a_key_is_rebound_by_pressing_it() {
    let mut menu = Menu::new(settings(), setup(1, true));
    run(&mut menu, &[Down, Select, Select, Select]);
    assert_eq!(menu.page(), &Page::Keys);
    // Forward gets KeyI: first of two, ArrowUp dropped... KeyW kept second.
    run(&mut menu, &[Select]);
    assert!(menu.wants_key());
    assert_eq!(run(&mut menu, &[Key("KeyI".into())]), vec![Event::Settings]);
    assert_eq!(menu.settings.bindings[0].keys, ["KeyI", "KeyW"]);
    // A key taken from another action leaves it: Back gets KeyW.
    run(&mut menu, &[Down, Select, Key("KeyW".into())]);
    assert_eq!(menu.settings.bindings[0].keys, ["KeyI"]);
    assert_eq!(menu.settings.bindings[1].keys, ["KeyW", "KeyS"]);
    // Esc while waiting cancels; Backspace clears.
    run(&mut menu, &[Down, Select, Back]);
    assert_eq!(menu.settings.bindings[2].keys, ["KeyA"]);
    run(&mut menu, &[Erase]);
    assert!(menu.settings.bindings[2].keys.is_empty());
}

#[test]
fn quit_asks_first() {
    let mut menu = Menu::new(settings(), setup(1, true));
    run(&mut menu, &[Up, Select]);
    assert_eq!(menu.page(), &Page::QuitConfirm);
    // No, then N, then Esc each stay; Yes and Y quit.
    run(&mut menu, &[Down, Select]);
    assert_eq!(menu.page(), &Page::Main);
    run(&mut menu, &[Select, Text('n')]);
    assert_eq!(menu.page(), &Page::Main);
    assert_eq!(run(&mut menu, &[Select, Back]), vec![]);
    assert_eq!(run(&mut menu, &[Select, Select]), vec![Event::Quit]);
    let mut menu = Menu::new(settings(), setup(1, true));
    assert_eq!(run(&mut menu, &[Up, Select, Text('Y')]), vec![Event::Quit]);
    // Esc on the main page closes the menu.
    let mut menu = Menu::new(settings(), setup(1, true));
    assert_eq!(run(&mut menu, &[Back]), vec![Event::Closed]);
}

#[test]
fn the_pointer_chooses_what_it_is_over() {
    let mut menu = Menu::new(settings(), setup(1, true));
    let (w, h) = (640, 400);
    // Each main item's own row: the pointer at its middle finds it.
    let found: Vec<Option<usize>> = (0..5).map(|i| item_at(&menu, w, h, 320, 2 * (78 + 20 * i) + 8)).collect();
    assert_eq!(found, (0..5).map(Some).collect::<Vec<_>>());
    assert_eq!(item_at(&menu, w, h, 320, 10), None);
    menu.command(Point(4));
    assert_eq!(menu.cursor(), 4);
}

/// Each page, drawn at 640x400 over the title's backdrop, against its golden image.
#[test]
fn pages_match_golden_images() {
    let pages: Vec<(&str, Vec<Command>, usize)> = vec![
        ("main", vec![], 1),
        ("episode", vec![Select], 4),
        ("skill", vec![Select, Down, Select], 4),
        ("load", vec![Down, Down, Select], 1),
        ("save-name", vec![Down, Down, Down, Select, Down, Select, Text('E'), Text('1'), Text('M'), Text('3')], 1),
        ("options", vec![Down, Select], 1),
        ("controls", vec![Down, Select, Select, Down], 1),
        ("keys", vec![Down, Select, Select, Select, Down, Down, Select], 1),
        ("sound", vec![Down, Select, Down, Select, Left], 1),
        ("video", vec![Down, Select, Down, Down, Select, Select], 1),
        ("gameplay", vec![Down, Select, Up, Select], 1),
        ("quit", vec![Up, Select], 1),
    ];
    let mut failures = Vec::new();
    for (name, path, episodes) in pages {
        let mut menu = Menu::new(settings(), setup(episodes, true));
        run(&mut menu, &path);
        let mut fb = Framebuffer::new(640, 400);
        title::backdrop(&mut fb);
        draw(&mut fb, &menu);
        if let Err(e) = golden(&format!("menu-{name}"), &fb) {
            failures.push(e);
        }
    }
    // The title alone.
    let mut fb = Framebuffer::new(640, 400);
    title::draw(&mut fb);
    if let Err(e) = golden("menu-title", &fb) {
        failures.push(e);
    }
    assert!(failures.is_empty(), "menu pages changed:\n{}", failures.join("\n"));
}
