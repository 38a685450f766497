//! A vanilla demo played on the simulation: the game its header starts
//! (`G_DoPlayDemo`, `G_InitNew`), the executable chosen from the IWAD as
//! Chocolate Doom chooses it, the IWAD's own DEHACKED applied, then every
//! tic's commands; and the comparison with a reference dump, tic by tic.

use std::path::PathBuf;
use std::sync::Arc;

use crate::actors::dehacked::Dehacked;

use super::intermission::Intermission;
use super::setup::Players;
use super::{GameMode, GameVersion, Rules, Sim, MAXPLAYERS};
use crate::actors::ActorTable;
use crate::campaign::next_doom_map;
use crate::play::lmp::{Ticcmd, VanillaDemo};
use crate::play::syncdump::{compare, FieldDiff, SyncDump, TicState};
use crate::play::world::Exit;
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
    let in_game = std::array::from_fn(|n| h.in_game.get(n).copied().unwrap_or(false));
    let players = Players { in_game, console: usize::from(h.console_player) };
    let map = h.map_name(mode == GameMode::Commercial);
    Sim::new(wad, &map, rules, players, table).map_err(|e| e.to_string())
}

/// A demo's game from tic to tic across levels, as `G_Ticker` runs it: a
/// reborn player first (a lone player's level reloaded, a netgame's
/// player respawned), then the game's actions (a level ended last tic: its
/// intermission; an intermission over: the next level loaded from the
/// WAD), then the tic itself, on the level or between levels.
pub struct DemoGame {
    pub sim: Sim,
    wad: Arc<Wad>,
    /// Between levels: the intermission and the map after it (`None`:
    /// the game ends after it).
    pub between: Option<(Intermission, Option<String>)>,
    /// The game has ended (Doom 1's ExM8, Doom II's MAP30, a campaign's
    /// last map): later tics only count.
    pub over: bool,
    /// A netgame's intermission has counted frags (vanilla's `dofrags`,
    /// never cleared).
    counted_frags: bool,
}

impl DemoGame {
    pub fn new(wad: Arc<Wad>, sim: Sim) -> DemoGame {
        DemoGame { sim, wad, between: None, over: false, counted_frags: false }
    }

    /// The last tic was a level's (what a reference dump holds a line for).
    pub fn on_level(&self) -> bool {
        self.between.is_none() && !self.over
    }

    /// One tic of every player's command. A next map the WAD lacks is an
    /// error naming it.
    pub fn tick(&mut self, cmds: &[Option<Ticcmd>; MAXPLAYERS]) -> Result<(), String> {
        if self.on_level() {
            self.actions()?;
        } else if let Some((wi, next)) = &self.between {
            if wi.done() {
                match next.clone() {
                    Some(name) => {
                        self.sim = self.sim.next_level_of(&self.wad, &name).map_err(|e| e.to_string())?;
                        self.between = None;
                    }
                    None => self.over = true,
                }
            }
        }
        match &mut self.between {
            _ if self.over => self.sim.gametic += 1,
            Some((wi, _)) => self.sim.tick_between(wi, cmds),
            None => self.sim.tick(cmds),
        }
        Ok(())
    }

    /// On a level: reborn players, and the level's end (`G_DoCompleted`).
    fn actions(&mut self) -> Result<(), String> {
        for n in 0..MAXPLAYERS {
            if self.sim.player(n).is_none_or(|p| p.playerstate != super::PlayerState::Reborn) {
                continue;
            }
            if self.sim.rules.netgame {
                self.sim.respawn_in_netgame(n);
            } else {
                let name = self.sim.level.name.clone();
                self.sim = self.sim.next_level_of(&self.wad, &name).map_err(|e| e.to_string())?;
                return Ok(());
            }
        }
        let Some(secret) = self.sim.exit else { return Ok(()) };
        let name = self.sim.level.name.clone();
        let Some(wi) = self.sim.complete_level(self.counted_frags) else {
            self.over = true;
            return Ok(());
        };
        self.counted_frags = wi.counted_frags();
        let exit = if secret { Exit::Secret } else { Exit::Normal };
        let next = next_doom_map(&name, exit, |m| self.wad.find(m).is_some());
        self.between = Some((wi, next));
        Ok(())
    }
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

/// Tic `t`'s commands of `demo` by player number.
pub fn commands(demo: &VanillaDemo, t: usize) -> [Option<Ticcmd>; MAXPLAYERS] {
    let mut cmds = [None; MAXPLAYERS];
    let players = (0..demo.header.in_game.len()).filter(|&n| demo.header.in_game[n]);
    for (k, n) in players.enumerate() {
        cmds[n] = demo.tic(t).get(k).copied();
    }
    cmds
}

/// A demo's game held to a reference dump, which has a line for each
/// level tic alone (the gametic in each line checks how long every
/// intermission lasted).
pub struct SyncCheck<'a> {
    lines: std::slice::Iter<'a, TicState>,
    total: usize,
}

impl<'a> SyncCheck<'a> {
    pub fn new(dump: &'a SyncDump) -> SyncCheck<'a> {
        SyncCheck { lines: dump.tics.iter(), total: dump.tics.len() }
    }

    /// After a tic of `game`: how it differs from the dump's next line, if
    /// it was a level tic (nothing between levels); `None` when the dump
    /// has no line left for it.
    pub fn tic(&mut self, game: &DemoGame) -> Option<Vec<FieldDiff>> {
        if !game.on_level() {
            return Some(Vec::new());
        }
        Some(compare(&game.sim.tic_state(), self.lines.next()?))
    }

    /// The dump's level tics.
    pub fn lines(&self) -> usize {
        self.total
    }
}

/// Plays `demo` on `game`, comparing every level tic with `dump`; stops
/// at the first difference.
pub fn check(game: &mut DemoGame, demo: &VanillaDemo, dump: &SyncDump) -> SyncReport {
    let tics = demo.tics();
    let mut sync = SyncCheck::new(dump);
    for t in 0..tics {
        let differ = |why: Vec<FieldDiff>| SyncReport { tics, in_sync: t, first_difference: Some((t + 1, why)) };
        if let Err(e) = game.tick(&commands(demo, t)) {
            return differ(vec![FieldDiff { field: "game".into(), ours: e, theirs: "played on".into() }]);
        }
        let diffs = sync.tic(game).unwrap_or_else(|| {
            vec![FieldDiff { field: "tics".into(), ours: tics.to_string(), theirs: sync.lines().to_string() }]
        });
        if !diffs.is_empty() {
            return differ(diffs);
        }
    }
    SyncReport { tics, in_sync: tics, first_difference: None }
}
