//! Between Doom's commands and the simulation's: what a vanilla demo's
//! ticcmds ask of the game, and the ticcmds a game of ours records. Also the
//! game a demo header starts (which map of which WAD, at which skill).
//!
//! Doom's moves come in its own units: forward ±25 walking and ±50 running
//! (`forwardmove[]` in `g_game.c`), sideways ±24 and ±40 (`sidemove[]`),
//! turns as the high 16 bits of a 32-bit angle. The simulation's
//! [`TickInput`] says the same in words: a direction, running or not, a turn
//! in degrees. Moves between the two speeds (a joystick's, or `-turbo`) have
//! no word yet; they read as the nearer speed.

use std::path::{Path, PathBuf};

use super::input::TickInput;
use super::lmp::{buttons, DemoHeader, LmpError, Ticcmd, VanillaDemo};
use crate::campaign::{find_wad, wad_dirs, MapRef};
use crate::wad::Wad;

/// Doom's keyboard moves (`forwardmove[]`, `sidemove[]` in `g_game.c`):
/// walking, running.
pub const FORWARD_MOVE: [i8; 2] = [0x19, 0x32];
pub const SIDE_MOVE: [i8; 2] = [0x18, 0x28];
/// Degrees in one unit of a ticcmd's turn (2^16 units to the circle).
const TURN_DEGREES: f64 = 360.0 / 65536.0;

/// The simulation's input for one Doom command.
pub fn input_of(cmd: &Ticcmd) -> TickInput {
    let moves = |v: i8, walk: i8| {
        let speed = i32::from(v).abs();
        (v.signum(), speed > i32::from(walk))
    };
    let (forward, run_forward) = moves(cmd.forward, FORWARD_MOVE[0]);
    let (strafe, run_side) = moves(cmd.side, SIDE_MOVE[0]);
    let special = cmd.buttons & buttons::SPECIAL != 0;
    let has = |bit: u8| !special && cmd.buttons & bit != 0;
    let weapon =
        if has(buttons::CHANGE) { slot_of((cmd.buttons & buttons::WEAPON_MASK) >> buttons::WEAPON_SHIFT) } else { 0 };
    TickInput {
        forward,
        strafe,
        turn: (f64::from(cmd.turn) * TURN_DEGREES) as f32,
        run: run_forward || run_side,
        use_line: has(buttons::USE),
        fire: has(buttons::ATTACK),
        weapon,
    }
}

/// The Doom command that asks for what `input` asks, with the turn rounded
/// to a 1.9 demo's resolution and the remainder carried in `carry` (degrees)
/// to the next tic, so slow turns still add up.
pub fn command_of(input: &TickInput, carry: &mut f64) -> Ticcmd {
    let input = input.sanitized();
    let speed = usize::from(input.run);
    let wanted = f64::from(input.turn) / TURN_DEGREES + *carry;
    let turn = ((wanted.round() as i64 + 128) & !0xff).clamp(i64::from(i16::MIN), 0x7f00) as i16;
    *carry = wanted - f64::from(turn);
    let mut b = 0;
    if input.fire {
        b |= buttons::ATTACK;
    }
    if input.use_line {
        b |= buttons::USE;
    }
    if let Some(weapon) = weapon_of(input.weapon) {
        b |= buttons::CHANGE | (weapon << buttons::WEAPON_SHIFT);
    }
    Ticcmd { forward: input.forward * FORWARD_MOVE[speed], side: input.strafe * SIDE_MOVE[speed], turn, buttons: b }
}

/// `input` as a 1.9 demo will give it back (the turn rounded, the
/// remainder carried): a game recorded to a `.lmp` is fed this, so the
/// game played is the game the file replays.
pub fn as_recorded(input: &TickInput, carry: &mut f64) -> TickInput {
    input_of(&command_of(input, carry))
}

/// A single-player 1.9 demo of `inputs` played on the WAD map `map` (whose
/// name gives the episode and map: `E1M4`, `MAP15`) with `options`. The
/// inputs should be what the game was fed ([`as_recorded`]).
pub fn demo_of(map: &str, options: crate::play::GameOptions, inputs: &[TickInput]) -> Result<VanillaDemo, String> {
    let name = map.to_ascii_uppercase();
    let number = |s: &str| s.parse::<u8>().ok();
    let (episode, level) = if let Some(n) = name.strip_prefix("MAP").and_then(number) {
        (1, n)
    } else {
        let episode_map = name.strip_prefix('E').and_then(|r| r.split_once('M'));
        match episode_map.and_then(|(e, m)| Some((number(e)?, number(m)?))) {
            Some(pair) => pair,
            None => return Err(format!("{map} is not a Doom map name (ExMy or MAPnn): a .lmp cannot name it")),
        }
    };
    let mut header = DemoHeader::single(options.skill.saturating_sub(1).min(4), episode, level);
    header.no_monsters = options.no_monsters;
    let mut demo = VanillaDemo::new(header);
    let mut carry = 0.0;
    demo.commands = inputs.iter().map(|i| command_of(i, &mut carry)).collect();
    Ok(demo)
}

/// The number key (slot) of Doom's weapon number `n` (`weapontype_t`: fist,
/// pistol, shotgun, chaingun, rocket launcher, plasma rifle, BFG, chainsaw;
/// the super shotgun, 8, does not fit a demo's three bits).
fn slot_of(n: u8) -> u8 {
    match n {
        0 | 7 => 1,
        n => n + 1,
    }
}

/// Doom's weapon number for a number key (1 to 7), as the keys ask for it.
fn weapon_of(slot: u8) -> Option<u8> {
    (1..=7).contains(&slot).then(|| slot - 1)
}

/// The game a demo header starts: its map's lump name in a WAD that has
/// Doom II's maps (`commercial`) or episodes, its skill as the simulation
/// numbers it (1 to 5), and whether monsters are left out.
pub fn game_of(header: &DemoHeader, commercial: bool) -> (String, crate::play::GameOptions) {
    let options = crate::play::GameOptions { skill: header.skill + 1, seed: 0, no_monsters: header.no_monsters };
    (header.map_name(commercial), options)
}

/// A demo named on the command line, and the WADs its game is played on.
pub struct DemoSource {
    pub demo: VanillaDemo,
    /// The IWAD first, then PWADs.
    pub wads: Vec<PathBuf>,
    /// How the demo was named (`file.lmp` or `WAD:LUMP`), for messages.
    pub label: String,
}

/// Opens `spec`: `WAD:LUMP` (a demo lump inside a WAD, played on that WAD
/// over `iwad` if given) or a `.lmp` file (played on `iwad`, which it then
/// needs), with `pwads` stacked over the IWAD.
pub fn open_demo(spec: &str, iwad: Option<&Path>, pwads: &[PathBuf]) -> Result<DemoSource, LmpError> {
    let dirs = wad_dirs();
    let unsupported = |what: String| LmpError::Unsupported { path: spec.to_string(), what };
    let wad_lump = spec.rsplit_once(':').filter(|(w, l)| w.to_ascii_lowercase().ends_with(".wad") && !l.is_empty());
    let (demo, mut wads) = match wad_lump {
        Some((wad, lump)) => {
            let path = find_wad(Path::new(wad), &dirs);
            let opened = Wad::open(&path).map_err(|e| unsupported(e.to_string()))?;
            let lump = lump.to_ascii_uppercase();
            let index =
                opened.find(&lump).ok_or_else(|| unsupported(format!("{} has no lump {lump}", path.display())))?;
            let demo = VanillaDemo::from_bytes(opened.bytes(index), spec)?;
            (demo, iwad.map(Path::to_path_buf).into_iter().chain([path]).collect::<Vec<_>>())
        }
        None => {
            let demo = VanillaDemo::load(Path::new(spec))?;
            let Some(iwad) = iwad else {
                return Err(unsupported(
                    "a .lmp file names no WAD: give the IWAD it was recorded on with --iwad".into(),
                ));
            };
            (demo, vec![iwad.to_path_buf()])
        }
    };
    wads.extend(pwads.iter().cloned());
    wads = wads.iter().map(|w| find_wad(w, &dirs)).collect();
    Ok(DemoSource { demo, wads, label: spec.to_string() })
}

impl DemoSource {
    /// The WADs as one, later over earlier.
    pub fn wad(&self) -> Result<Wad, LmpError> {
        let stacked = self.wads.iter().map(|w| Wad::open(w)).collect::<Result<Vec<_>, _>>();
        let error = |e: crate::wad::WadError| LmpError::Unsupported { path: self.label.clone(), what: e.to_string() };
        Ok(Wad::stack(stacked.map_err(error)?))
    }

    /// The map the demo plays, checked against the WADs (`E1M4` or
    /// `MAP15`, by whether the WADs hold Doom II's maps), and its options.
    pub fn game(&self) -> Result<(MapRef, crate::play::GameOptions), LmpError> {
        let error = |what: String| LmpError::Unsupported { path: self.label.clone(), what };
        let wad = self.wad()?;
        let commercial = wad.find("MAP01").is_some();
        let (name, options) = game_of(&self.demo.header, commercial);
        if !wad.map_names().contains(&name) {
            return Err(error(format!("the demo plays {name}, which {} does not have", wad.path)));
        }
        Ok((MapRef::Wad { wads: self.wads.clone(), map: Some(name) }, options))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doom_moves_read_as_directions_and_speeds() {
        let walk = input_of(&Ticcmd { forward: 25, side: -24, turn: 0, buttons: 0 });
        assert_eq!((walk.forward, walk.strafe, walk.run), (1, -1, false));
        let run = input_of(&Ticcmd { forward: -50, side: 0, turn: 0x4000, buttons: buttons::ATTACK | buttons::USE });
        assert_eq!((run.forward, run.run, run.fire, run.use_line), (-1, true, true, true));
        assert_eq!(run.turn, 90.0);
        let change = input_of(&Ticcmd { buttons: buttons::CHANGE | (2 << buttons::WEAPON_SHIFT), ..Ticcmd::default() });
        assert_eq!(change.weapon, 3, "Doom's weapon 2 (the shotgun) is key 3");
        let saw = input_of(&Ticcmd { buttons: buttons::CHANGE | (7 << buttons::WEAPON_SHIFT), ..Ticcmd::default() });
        assert_eq!(saw.weapon, 1);
        let pause = input_of(&Ticcmd { buttons: buttons::SPECIAL | buttons::ATTACK, ..Ticcmd::default() });
        assert!(!pause.fire, "a special event is not a button");
    }

    #[test]
    fn our_inputs_round_trip_through_commands() {
        let mut carry = 0.0;
        let input = TickInput { forward: 1, strafe: -1, run: true, fire: true, weapon: 3, ..TickInput::default() };
        let cmd = command_of(&input, &mut carry);
        assert_eq!((cmd.forward, cmd.side), (50, -40));
        let back = input_of(&cmd);
        assert_eq!((back.forward, back.strafe, back.run, back.fire, back.weapon), (1, -1, true, true, 3));
    }

    #[test]
    fn a_recorded_game_is_fed_what_the_file_replays() {
        let mut carry = 0.0;
        let inputs: Vec<TickInput> = (0..50)
            .map(|i| TickInput { forward: 1, turn: 0.3 * i as f32, run: i % 2 == 0, ..TickInput::default() })
            .map(|i| as_recorded(&i, &mut carry))
            .collect();
        let options = crate::play::GameOptions { skill: 3, seed: 0, no_monsters: true };
        let demo = demo_of("e1m4", options, &inputs).unwrap();
        assert_eq!((demo.header.skill, demo.header.episode, demo.header.map), (2, 1, 4));
        assert!(demo.header.no_monsters);
        let back = VanillaDemo::from_bytes(&demo.to_bytes(), "rec.lmp").unwrap();
        let replayed: Vec<TickInput> = back.commands.iter().map(input_of).collect();
        assert_eq!(replayed, inputs);
        assert_eq!(demo_of("MAP07", options, &[]).unwrap().header.map, 7);
        assert!(demo_of("outpost", options, &[]).unwrap_err().contains("not a Doom map name"));
    }

    #[test]
    fn slow_turns_add_up_through_the_carry() {
        // 0.5 degrees a tic is 91 units: under half of a 1.9 demo's 256.
        let mut carry = 0.0;
        let input = TickInput { turn: 0.5, ..TickInput::default() };
        let total: i32 = (0..100).map(|_| i32::from(command_of(&input, &mut carry).turn)).sum();
        let degrees = f64::from(total) * TURN_DEGREES;
        assert!((degrees - 50.0).abs() < 1.5, "100 tics of half a degree turned {degrees} degrees");
    }
}
