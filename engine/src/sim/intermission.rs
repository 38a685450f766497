//! Between two levels, as Doom times it (`G_DoCompleted`, `wi_stuff.c`'s
//! ticker for one player, `G_WorldDone`, and the skip of `f_finale.c`'s text
//! screens). A demo goes on reading commands through an intermission, and
//! how many tics the intermission lasts depends on when the player presses
//! fire or use; a demo that goes on to the next level stays in sync only if
//! this counts exactly as Doom counts. The screens themselves are the front
//! end's to draw: this keeps the figures shown ([`Intermission::shown`]) and
//! the sounds Doom plays ([`Intermission::sounds`]).
//!
//! The stages, for one player:
//!
//! 1. The tallies count up (`StatCount`): a pause of 35 tics, kills 2% a
//!    tic, a pause, items, a pause, secrets, a pause, then the time and the
//!    par 3 seconds a tic, then the finished tallies wait. A press while they
//!    count shows them finished at once; a press once they are finished goes
//!    on.
//! 2. Doom 1 only: the episode's map with the next level marked
//!    (`ShowNextLoc`), 140 tics or until a press.
//! 3. Ten tics more (`NoState`); then the next level loads, on the tic after.
//! 4. Doom II after MAP06, MAP11, MAP20 and MAP30 (and MAP15's and MAP31's
//!    secret exits): a text screen, until any button after 50 tics.
//!
//! A press is a button going down: the player's `attackdown` and `usedown`
//! carry over from the level (use held on the exit switch does not skip the
//! tallies) and on into the next level, as in Doom.

use super::{GameMode, Player, Sim, MAXPLAYERS};
use crate::campaign::doom_map_number;
use crate::play::lmp::{buttons, Ticcmd};

const TICRATE: i32 = 35;

/// doom.exe's par times in seconds by episode and map (`pars` in g_game.c).
/// Chocolate Doom reads no BEX `[PARS]`, so neither does a vanilla game.
const PARS: [[i32; 10]; 4] = [
    [0; 10],
    [0, 30, 75, 120, 90, 165, 180, 180, 30, 165],
    [0, 90, 90, 90, 120, 90, 360, 240, 30, 170],
    [0, 90, 45, 90, 150, 90, 90, 165, 30, 135],
];

/// Doom II's par times in seconds, MAP01 to MAP32 (`cpars`).
const CPARS: [i32; 32] = [
    30, 90, 120, 120, 90, 150, 120, 120, 270, 90, 210, 150, 150, 150, 210, 150, 420, 150, 210, 150, 240, 150, 180, 150,
    150, 300, 330, 420, 300, 180, 120, 30,
];

/// Ticks the episode's map shows the next level (`SHOWNEXTLOCDELAY`).
const SHOW_NEXT_LOC: i32 = 4 * TICRATE;
/// The last tics before the next level (`WI_initNoState`).
const NO_STATE: i32 = 10;
/// Tics a Doom II text screen shows before a button skips it (`F_Ticker`).
const TEXT_MIN: i32 = 50;

/// What the intermission counts for the player (`wbplayerstruct_t` and
/// the level's totals of `wbstartstruct_t`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Tallies {
    pub kills: i32,
    pub items: i32,
    pub secrets: i32,
    /// The level's totals, at least 1 each (`WI_initVariables`).
    pub max_kills: i32,
    pub max_items: i32,
    pub max_secrets: i32,
    /// The level's time and its par, in tics.
    pub time: i32,
    pub par: i32,
}

/// The figures on screen while the tallies count (`cnt_kills`, ...):
/// percentages and seconds, -1 before they first show.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Shown {
    pub kills: i32,
    pub items: i32,
    pub secrets: i32,
    pub time: i32,
    pub par: i32,
}

/// Where the intermission is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Stage {
    /// The tallies count (`StatCount`); `step` is `sp_state`, 1 to 10, and
    /// `pause` counts down the odd steps.
    Tallies { step: u8, pause: i32 },
    /// Doom 1's episode map (`ShowNextLoc`), `left` tics to go.
    NextLocation { left: i32 },
    /// The last tics (`NoState`).
    Closing { left: i32 },
    /// A Doom II text screen (`GS_FINALE`), shown for `shown` tics.
    Text { shown: i32 },
    /// The next level loads on the next tic (`ga_worlddone`).
    Done,
}

/// A netgame's counting (`WI_updateNetgameStats`, and in deathmatch
/// `WI_updateDeathmatchStats`): every player's at once.
#[derive(Clone, Debug, PartialEq)]
struct Net {
    deathmatch: bool,
    /// Co-op counts frags too (`dofrags`: someone has some, in this or an
    /// earlier intermission of the game, since vanilla never clears it).
    frags: bool,
    players: [Option<NetPlayer>; MAXPLAYERS],
}

/// One player's figures in a netgame's intermission.
#[derive(Clone, Copy, Debug, PartialEq)]
struct NetPlayer {
    /// Kills, items and secrets: the percentages to reach, and shown.
    target: [i32; 3],
    count: [i32; 3],
    /// Frags of each other player (`frags[j]`), the sum (`WI_fragSum`),
    /// and shown: co-op's sum, deathmatch's table.
    frags: [i32; MAXPLAYERS],
    frag_sum: i32,
    count_frags: i32,
    table: [i32; MAXPLAYERS],
}

/// An intermission in progress.
#[derive(Clone, Debug, PartialEq)]
pub struct Intermission {
    pub tallies: Tallies,
    pub shown: Shown,
    pub stage: Stage,
    /// A netgame's counting, else one player's.
    net: Option<Box<Net>>,
    /// A press came this stage (`acceleratestage`).
    accelerate: bool,
    /// Tics since the intermission began (`bcnt`).
    pub tics: u32,
    commercial: bool,
    /// A text screen follows the tallies (`G_WorldDone`'s finales).
    text_after: bool,
    /// Doom's sound names played on the last tic (`pistol`, `barexp`,
    /// `sgcock`).
    pub sounds: Vec<&'static str>,
}

/// `G_PlayerFinishLevel`: what a player does not take to the next level
/// (powers, keys, a flash or a tint on the screen).
pub fn finish_level(player: &mut Player) {
    player.powers = [0; super::NUMPOWERS];
    player.cards = [false; super::NUMCARDS];
    player.extralight = 0;
    player.fixedcolormap = 0;
    player.damagecount = 0;
    player.bonuscount = 0;
}

/// The par time of map `name` in seconds, as doom.exe knows it (0 for a
/// name that is neither ExMy nor MAPnn). Episode 4 has no pars and reads
/// past its table into Doom II's, as vanilla does.
pub fn par_seconds(name: &str) -> i32 {
    match doom_map_number(name) {
        Some((Some(e @ 1..=3), m)) => PARS[e as usize].get(m as usize).copied().unwrap_or(0),
        Some((Some(_), m)) => CPARS.get(m as usize).copied().unwrap_or(0),
        Some((None, m)) => CPARS.get((m as usize).wrapping_sub(1)).copied().unwrap_or(0),
        None => 0,
    }
}

/// Whether Doom ends the game at map `name` instead of showing an
/// intermission (`G_DoCompleted`'s `ga_victory`: ExM8 in Doom 1).
pub fn ends_game(mode: GameMode, name: &str) -> bool {
    mode != GameMode::Commercial && matches!(doom_map_number(name), Some((_, 8)))
}

impl Intermission {
    /// `G_DoCompleted` and `WI_Start` for one player, on map `name` of a
    /// `mode` game, ended by the secret exit or not, with the player's
    /// tallies, the level's totals and its time in tics.
    pub fn start(mode: GameMode, name: &str, secret: bool, tallies: Tallies) -> Intermission {
        let commercial = mode == GameMode::Commercial;
        let text_after = commercial
            && match doom_map_number(name) {
                Some((None, 6 | 11 | 20 | 30)) => true,
                Some((None, 15 | 31)) => secret,
                _ => false,
            };
        let tallies = Tallies {
            max_kills: tallies.max_kills.max(1),
            max_items: tallies.max_items.max(1),
            max_secrets: tallies.max_secrets.max(1),
            ..tallies
        };
        Intermission {
            tallies,
            shown: Shown { kills: -1, items: -1, secrets: -1, time: -1, par: -1 },
            stage: Stage::Tallies { step: 1, pause: TICRATE },
            net: None,
            accelerate: false,
            tics: 0,
            commercial,
            text_after,
            sounds: Vec::new(),
        }
    }

    /// This intermission for a netgame of `players` (`WI_initNetgameStats`
    /// or `WI_initDeathmatchStats`), on a level with these totals; `frags`
    /// is whether an earlier intermission of the game counted frags.
    pub fn for_netgame(
        mut self,
        players: &[Option<Player>; MAXPLAYERS],
        totals: (i32, i32, i32),
        deathmatch: bool,
        frags: bool,
    ) -> Intermission {
        let (k, i, s) = (totals.0.max(1), totals.1.max(1), totals.2.max(1));
        let in_game: Vec<usize> = (0..MAXPLAYERS).filter(|&n| players[n].is_some()).collect();
        let mut net = Net { deathmatch, frags, players: [None; MAXPLAYERS] };
        for (n, p) in players.iter().enumerate() {
            let Some(p) = p else { continue };
            let others: i32 = in_game.iter().filter(|&&j| j != n).map(|&j| p.frags[j]).sum();
            let frag_sum = others - p.frags[n];
            net.frags |= frag_sum != 0;
            net.players[n] = Some(NetPlayer {
                target: [p.killcount * 100 / k, p.itemcount * 100 / i, p.secretcount * 100 / s],
                count: [0; 3],
                frags: p.frags,
                frag_sum,
                count_frags: 0,
                table: [0; MAXPLAYERS],
            });
        }
        self.net = Some(Box::new(net));
        self
    }

    /// A netgame's intermission counted frags (the next one will too).
    pub fn counted_frags(&self) -> bool {
        self.net.as_ref().is_some_and(|n| n.frags)
    }

    /// The tallies of `player` on a level with these totals, `leveltime`
    /// tics long, named `name`.
    fn tallies_of(player: &Player, totals: (i32, i32, i32), leveltime: u32, name: &str) -> Tallies {
        Tallies {
            kills: player.killcount,
            items: player.itemcount,
            secrets: player.secretcount,
            max_kills: totals.0,
            max_items: totals.1,
            max_secrets: totals.2,
            time: leveltime as i32,
            par: par_seconds(name) * TICRATE,
        }
    }

    /// The next level loads on the next tic.
    pub fn done(&self) -> bool {
        self.stage == Stage::Done
    }

    /// One tic (`G_Ticker` in `GS_INTERMISSION` or `GS_FINALE`): each
    /// player in the game takes its command, then the screen's ticker runs.
    pub fn tick(&mut self, players: &mut [Option<Player>; MAXPLAYERS], cmds: &[Option<Ticcmd>; MAXPLAYERS]) {
        self.sounds.clear();
        for (player, cmd) in players.iter_mut().zip(cmds) {
            if let (Some(p), Some(cmd)) = (player, cmd) {
                p.cmd = *cmd;
            }
        }
        match self.stage {
            Stage::Done => {}
            Stage::Text { shown } => {
                // `F_Ticker`: any button of anyone's, once 50 tics have shown.
                let pressed = players.iter().flatten().any(|p| p.cmd.buttons != 0);
                self.stage = if shown > TEXT_MIN && pressed { Stage::Done } else { Stage::Text { shown: shown + 1 } };
            }
            _ => {
                self.tics += 1;
                self.check_for_accelerate(players);
                self.update();
            }
        }
    }

    /// `WI_checkForAccelerate`: a button going down, by anyone.
    fn check_for_accelerate(&mut self, players: &mut [Option<Player>; MAXPLAYERS]) {
        for p in players.iter_mut().flatten() {
            let attack = p.cmd.buttons & buttons::ATTACK != 0;
            let use_ = p.cmd.buttons & buttons::USE != 0;
            if attack && !p.attackdown {
                self.accelerate = true;
            }
            if use_ && !p.usedown {
                self.accelerate = true;
            }
            p.attackdown = attack;
            p.usedown = use_;
        }
    }

    fn update(&mut self) {
        match self.stage {
            Stage::Tallies { step, pause } => match self.net.as_ref().map(|n| n.deathmatch) {
                None => self.update_tallies(step, pause),
                Some(false) => self.update_netgame(step, pause),
                Some(true) => self.update_deathmatch(step, pause),
            },
            Stage::NextLocation { left } => {
                // `WI_updateShowNextLoc`.
                if left - 1 == 0 || self.accelerate {
                    self.close();
                } else {
                    self.stage = Stage::NextLocation { left: left - 1 };
                }
            }
            Stage::Closing { left } => {
                // `WI_updateNoState`, then `G_WorldDone`.
                if left - 1 == 0 {
                    self.stage = if self.text_after { Stage::Text { shown: 0 } } else { Stage::Done };
                } else {
                    self.stage = Stage::Closing { left: left - 1 };
                }
            }
            Stage::Text { .. } | Stage::Done => {}
        }
    }

    /// `WI_initNoState`.
    fn close(&mut self) {
        self.accelerate = false;
        self.stage = Stage::Closing { left: NO_STATE };
    }

    /// `WI_updateStats`: one player's tallies counting up.
    fn update_tallies(&mut self, mut step: u8, mut pause: i32) {
        let t = self.tallies;
        let (kills, items, secrets) =
            (t.kills * 100 / t.max_kills, t.items * 100 / t.max_items, t.secrets * 100 / t.max_secrets);
        let (time, par) = (t.time / TICRATE, t.par / TICRATE);
        let tick_sound = self.tics & 3 == 0;
        if self.accelerate && step != 10 {
            self.accelerate = false;
            self.shown = Shown { kills, items, secrets, time, par };
            self.sounds.push("barexp");
            step = 10;
        }
        let s = &mut self.shown;
        let counted = |shown: &mut i32, to: i32, sounds: &mut Vec<&'static str>| {
            *shown += 2;
            if tick_sound {
                sounds.push("pistol");
            }
            let reached = *shown >= to;
            if reached {
                *shown = to;
                sounds.push("barexp");
            }
            reached
        };
        match step {
            2 | 4 | 6 => {
                let (shown, to) = match step {
                    2 => (&mut s.kills, kills),
                    4 => (&mut s.items, items),
                    _ => (&mut s.secrets, secrets),
                };
                if counted(shown, to, &mut self.sounds) {
                    step += 1;
                }
            }
            8 => {
                if tick_sound {
                    self.sounds.push("pistol");
                }
                s.time = (s.time + 3).min(time);
                s.par += 3;
                if s.par >= par {
                    s.par = par;
                    if s.time >= time {
                        self.sounds.push("barexp");
                        step += 1;
                    }
                }
            }
            10 => {
                if self.accelerate {
                    self.go_on("sgcock");
                    return;
                }
            }
            _ => (step, pause) = paused(step, pause),
        }
        self.stage = Stage::Tallies { step, pause };
    }

    /// The tallies shown, a press goes on: Doom 1's episode map, Doom II's
    /// last tics.
    fn go_on(&mut self, sound: &'static str) {
        self.sounds.push(sound);
        if self.commercial {
            self.close();
        } else {
            self.accelerate = false;
            self.stage = Stage::NextLocation { left: SHOW_NEXT_LOC };
        }
    }

    /// `WI_updateNetgameStats`: every player's kills, items, secrets (and
    /// frags, when anyone has some) counting together.
    fn update_netgame(&mut self, mut step: u8, mut pause: i32) {
        let tick_sound = self.tics & 3 == 0;
        let Some(net) = self.net.as_deref_mut() else { return };
        let players = net.players.iter_mut().flatten();
        if self.accelerate && step != 10 {
            self.accelerate = false;
            for p in players {
                p.count = p.target;
                if net.frags {
                    p.count_frags = p.frag_sum;
                }
            }
            self.sounds.push("barexp");
            step = 10;
        } else if matches!(step, 2 | 4 | 6 | 8) {
            if tick_sound {
                self.sounds.push("pistol");
            }
            let mut ticking = false;
            for p in players {
                let (count, to) = match step {
                    8 => (&mut p.count_frags, p.frag_sum),
                    _ => (&mut p.count[usize::from(step / 2 - 1)], p.target[usize::from(step / 2 - 1)]),
                };
                *count += if step == 8 { 1 } else { 2 };
                if *count >= to {
                    *count = to;
                } else {
                    ticking = true;
                }
            }
            if !ticking {
                self.sounds.push(if step == 8 { "pldeth" } else { "barexp" });
                // Past the frags when no one has any.
                step += if step == 6 && !net.frags { 3 } else { 1 };
            }
        } else if step == 10 {
            if self.accelerate {
                self.go_on("sgcock");
                return;
            }
        } else {
            (step, pause) = paused(step, pause);
        }
        self.stage = Stage::Tallies { step, pause };
    }

    /// `WI_updateDeathmatchStats`: the frags table counting, each entry one
    /// a tic towards its figure (held within -99 to 99, so a figure past
    /// them counts for ever, as in vanilla, until a press).
    fn update_deathmatch(&mut self, mut step: u8, mut pause: i32) {
        let tick_sound = self.tics & 3 == 0;
        let Some(net) = self.net.as_deref_mut() else { return };
        let in_game: Vec<usize> = (0..MAXPLAYERS).filter(|&n| net.players[n].is_some()).collect();
        let players = net.players.iter_mut().flatten();
        if self.accelerate && step != 4 {
            self.accelerate = false;
            for p in players {
                for &j in &in_game {
                    p.table[j] = p.frags[j];
                }
            }
            self.sounds.push("barexp");
            step = 4;
        } else if step == 2 {
            if tick_sound {
                self.sounds.push("pistol");
            }
            let mut ticking = false;
            for p in players {
                for &j in &in_game {
                    if p.table[j] != p.frags[j] {
                        p.table[j] = (p.table[j] + if p.frags[j] < 0 { -1 } else { 1 }).clamp(-99, 99);
                        ticking = true;
                    }
                }
            }
            if !ticking {
                self.sounds.push("barexp");
                step += 1;
            }
        } else if step == 4 {
            if self.accelerate {
                self.go_on("slop");
                return;
            }
        } else {
            (step, pause) = paused(step, pause);
        }
        self.stage = Stage::Tallies { step, pause };
    }
}

/// An odd step: a pause of a second between two counts.
fn paused(step: u8, pause: i32) -> (u8, i32) {
    if pause - 1 == 0 {
        (step + 1, TICRATE)
    } else {
        (step, pause - 1)
    }
}

impl Sim {
    /// The level has ended (`G_DoCompleted`): every player's keys and powers
    /// taken, and the intermission, for one player or a netgame's (`frags`:
    /// an earlier intermission of the game counted frags); or `None` where
    /// Doom ends the game without one (Doom 1's ExM8), or the level has not
    /// ended.
    pub fn complete_level(&mut self, frags: bool) -> Option<Intermission> {
        let secret = self.exit?;
        for p in self.players.iter_mut().flatten() {
            finish_level(p);
        }
        let name = &self.level.name;
        if ends_game(self.rules.mode, name) {
            return None;
        }
        let totals = (self.total_kills, self.total_items, self.total_secrets);
        let tallies = Intermission::tallies_of(self.player(self.console)?, totals, self.leveltime, name);
        let wi = Intermission::start(self.rules.mode, name, secret, tallies);
        Some(match self.rules.netgame {
            true => wi.for_netgame(&self.players, totals, self.rules.deathmatch != 0, frags),
            false => wi,
        })
    }

    /// One tic between levels: the intermission (or text screen) takes the
    /// players' commands, and the game's tic count goes on.
    pub fn tick_between(&mut self, wi: &mut Intermission, cmds: &[Option<Ticcmd>; MAXPLAYERS]) {
        wi.tick(&mut self.players, cmds);
        self.gametic += 1;
    }
}

#[cfg(test)]
#[path = "intermission_tests.rs"]
mod tests;
