//! A vanilla demo played on the simulation: the game its header starts
//! (`G_DoPlayDemo`, `G_InitNew`), the executable chosen from the IWAD as
//! Chocolate Doom chooses it, the IWAD's own DEHACKED applied, then every
//! tic's commands; and the comparison with a reference dump, tic by tic.

use std::path::PathBuf;
use std::sync::Arc;

use crate::actors::dehacked::Dehacked;

use super::setup::Players;
use super::{GameMode, GameVersion, Rules, Sim, MAXPLAYERS};
use crate::actors::ActorTable;
use crate::play::lmp::VanillaDemo;
use crate::play::syncdump::{compare, FieldDiff, SyncDump};
use crate::wad::Wad;

/// What the IWAD is (`D_IdentifyVersion`): Doom II's maps make it
/// commercial, a fourth episode retail (The Ultimate Doom), a third
/// registered.
pub fn game_mode(wad: &Wad) -> GameMode {
    if wad.find("MAP01").is_some() {
        GameMode::Commercial
    } else if wad.find("E4M1").is_some() {
        GameMode::Retail
    } else if wad.find("E3M1").is_some() {
        GameMode::Registered
    } else {
        GameMode::Shareware
    }
}

/// The executable Chocolate Doom plays an IWAD as (`InitGameVersion`):
/// The Ultimate Doom for a retail IWAD, Doom 1.9 otherwise. `--gameversion`
/// overrides it.
pub fn game_version(mode: GameMode) -> GameVersion {
    match mode {
        GameMode::Retail => GameVersion::Ultimate,
        _ => GameVersion::Doom19,
    }
}

/// The actor table a game on `wad` plays with: `table` with the WAD's
/// DEHACKED lumps applied, as Chocolate applies an IWAD's.
pub fn table_for(wad: &Wad, table: &ActorTable) -> Result<Arc<ActorTable>, String> {
    table_with_patches(wad, table, &[])
}

/// [`table_for`], then the DeHackEd or BEX files `patches` (a PWAD's
/// `-deh`), in order, after the WAD's own lumps as Chocolate applies them;
/// warnings are printed to standard error. An error names the file and line.
pub fn table_with_patches(wad: &Wad, table: &ActorTable, patches: &[PathBuf]) -> Result<Arc<ActorTable>, String> {
    let mut patched = Dehacked::new(table.clone());
    patched.load_wad(wad).map_err(|e| e.to_string())?;
    for path in patches {
        let label = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| format!("{label}: cannot read: {e}"))?;
        patched.load(&bytes, &label).map_err(|e| e.to_string())?;
    }
    let (table, report) = patched.finish();
    // The IWAD's own warnings are Chocolate's business; a user's patch's
    // are the user's.
    let labels: Vec<String> = patches.iter().map(|p| p.display().to_string()).collect();
    for warning in report.warnings.iter().map(ToString::to_string) {
        if labels.iter().any(|l| warning.starts_with(l.as_str())) {
            eprintln!("sightline: {warning}");
        }
    }
    Ok(Arc::new(table))
}

/// A `--gameversion` name, as Chocolate Doom spells them: `1.9`,
/// `ultimate`, `final` (and `final2`, which plays as `final` here).
pub fn parse_game_version(name: &str) -> Result<GameVersion, String> {
    match name.to_ascii_lowercase().as_str() {
        "1.9" => Ok(GameVersion::Doom19),
        "ultimate" => Ok(GameVersion::Ultimate),
        "final" | "final2" => Ok(GameVersion::Final),
        other => Err(format!("unknown game version {other:?}: 1.9, ultimate or final")),
    }
}

/// The game `demo` starts on `wad`, as the executable Chocolate Doom
/// picks for the IWAD.
pub fn start(wad: &Wad, demo: &VanillaDemo, table: Arc<ActorTable>) -> Result<Sim, String> {
    start_as(wad, demo, table, None)
}

/// [`start`] as the executable `version` (`--gameversion`), if given.
pub fn start_as(
    wad: &Wad,
    demo: &VanillaDemo,
    table: Arc<ActorTable>,
    version: Option<GameVersion>,
) -> Result<Sim, String> {
    let h = &demo.header;
    let mode = game_mode(wad);
    let rules = Rules {
        deathmatch: h.deathmatch,
        respawn: h.respawn,
        fast: h.fast,
        no_monsters: h.no_monsters,
        netgame: h.players() > 1,
        ..Rules::single(h.skill, version.unwrap_or(game_version(mode)), mode)
    };
    let players = Players { in_game: h.in_game, console: usize::from(h.console_player) };
    let map = h.map_name(mode == GameMode::Commercial);
    Sim::new(wad, &map, rules, players, table).map_err(|e| e.to_string())
}

/// How far a demo kept in step with its reference.
#[derive(Clone, Debug, PartialEq)]
pub struct SyncReport {
    /// Tics the demo holds.
    pub tics: usize,
    /// Tics in sync before the first difference (all of them when none).
    pub in_sync: usize,
    /// The first tic that differs (numbered from 1) and how.
    pub first_difference: Option<(usize, Vec<FieldDiff>)>,
}

/// Plays `demo` on `sim`, comparing every tic with `dump`; stops at the
/// first difference.
pub fn check(sim: &mut Sim, demo: &VanillaDemo, dump: &SyncDump) -> SyncReport {
    let tics = demo.tics();
    let in_game: Vec<usize> = (0..MAXPLAYERS).filter(|&n| demo.header.in_game[n]).collect();
    for t in 0..tics {
        let mut cmds = [None; MAXPLAYERS];
        for (k, &n) in in_game.iter().enumerate() {
            cmds[n] = demo.tic(t).get(k).copied();
        }
        sim.tick(&cmds);
        let Some(theirs) = dump.tics.get(t) else {
            let why = FieldDiff { field: "tics".into(), ours: tics.to_string(), theirs: dump.tics.len().to_string() };
            return SyncReport { tics, in_sync: t, first_difference: Some((t + 1, vec![why])) };
        };
        let diffs = compare(&sim.tic_state(), theirs);
        if !diffs.is_empty() {
            return SyncReport { tics, in_sync: t, first_difference: Some((t + 1, diffs)) };
        }
    }
    SyncReport { tics, in_sync: tics, first_difference: None }
}
