//! A new game on a level (`G_InitNew`, `G_DoLoadLevel`, `P_SetupLevel`):
//! the random indices cleared, the level read, its things spawned in the
//! WAD's order (each spawn spending `P_Random`), the players placed, then
//! the sector specials started.

use std::sync::Arc;

use super::info::{mt, Info};
use super::level::{Level, LevelError};
use super::mobj::{mf, ONCEILINGZ, ONFLOORZ};
use super::{collision, monsters, specials, Player, PlayerState, Psprite, Rules, Sim, MAXPLAYERS};
use crate::actors::ActorTable;
use crate::fixed::{Angle, DoomRandom, Fixed, ANG45};
use crate::play::lmp::Ticcmd;
use crate::wad::level::WadThing;
use crate::wad::Wad;

/// The editor numbers of Doom II's monsters, which Doom 1's executables do
/// not spawn (`P_LoadThings`): the Wolfenstein SS, the arch-vile, ...
const DOOM2_ONLY: [u16; 10] = [68, 64, 88, 89, 69, 67, 71, 65, 66, 84];
/// `MTF_AMBUSH`: the thing waits deaf until it sees a player.
const MTF_AMBUSH: u16 = 8;
/// `MTF_NOTSINGLE`: only in netgames.
const MTF_NOTSINGLE: u16 = 16;
/// Doom's `VIEWHEIGHT`.
pub const VIEWHEIGHT: Fixed = Fixed(41 << 16);

/// What a game takes into a level: its players, the random index and the
/// tic count.
struct Carried {
    players: [Option<Player>; MAXPLAYERS],
    console: usize,
    rng: DoomRandom,
    gametic: u32,
}

/// The players in a new game.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Players {
    pub in_game: [bool; MAXPLAYERS],
    pub console: usize,
}

impl Players {
    /// Players 1 to `count` (at most [`MAXPLAYERS`]), player 1 at the
    /// console.
    pub fn first(count: usize) -> Players {
        Players { in_game: std::array::from_fn(|n| n < count), console: 0 }
    }
}

impl Sim {
    /// A new game of `rules` on map `name` of `wad`, with `table`'s actors.
    pub fn new(
        wad: &Wad,
        name: &str,
        rules: Rules,
        players: Players,
        table: Arc<ActorTable>,
    ) -> Result<Sim, LevelError> {
        let level = Level::load(wad, name)?;
        Ok(Sim::on_level(level, rules, players, table, |sim| specials::set_texture_heights(sim, wad)))
    }

    /// A new game on a loaded `level` (a WAD's, or a RON map's through
    /// `from_map`): the players made, the things spawned, then the sector
    /// specials started. `before_specials` runs just before them (the WAD's
    /// texture heights are read there).
    pub fn on_level(
        level: Level,
        rules: Rules,
        players: Players,
        table: Arc<ActorTable>,
        before_specials: impl FnOnce(&mut Sim),
    ) -> Sim {
        let info = Arc::new(Info::new(table, rules.fast_monsters()));
        let mut made: [Option<Player>; MAXPLAYERS] = Default::default();
        for (n, &playing) in players.in_game.iter().enumerate() {
            if playing {
                made[n] = Some(Player::reborn(&info, [0; MAXPLAYERS], (0, 0, 0)));
            }
        }
        // G_InitNew clears both random indices.
        let carried = Carried { players: made, console: players.console, rng: DoomRandom::new(), gametic: 0 };
        Sim::begin(level, rules, info, carried, before_specials)
    }

    /// The game going on to `level` (`G_DoWorldDone`, or a lone player's
    /// `G_DoReborn`, both through `G_DoLoadLevel`): the same rules and
    /// actors, the players as this level left them (a dead one reborn; the
    /// level's tallies and frags cleared), and the random index and tic
    /// count where they are, as vanilla keeps them.
    pub fn next_level(&self, level: Level, before_specials: impl FnOnce(&mut Sim)) -> Sim {
        let mut players = self.players.clone();
        for p in players.iter_mut().flatten() {
            if p.playerstate == PlayerState::Dead {
                p.playerstate = PlayerState::Reborn;
            }
            p.frags = [0; MAXPLAYERS];
            (p.killcount, p.itemcount, p.secretcount) = (0, 0, 0);
        }
        let carried = Carried { players, console: self.console, rng: self.rng, gametic: self.gametic };
        Sim::begin(level, self.rules, self.info.clone(), carried, before_specials)
    }

    /// [`Sim::next_level`] on map `name` of `wad`.
    pub fn next_level_of(&self, wad: &Wad, name: &str) -> Result<Sim, LevelError> {
        let level = Level::load(wad, name)?;
        Ok(self.next_level(level, |sim| specials::set_texture_heights(sim, wad)))
    }

    /// `P_SetupLevel` with the players made or carried.
    fn begin(
        level: Level,
        rules: Rules,
        info: Arc<Info>,
        carried: Carried,
        before_specials: impl FnOnce(&mut Sim),
    ) -> Sim {
        let cells = (level.blockmap.width * level.blockmap.height) as usize;
        let lines = level.lines.len();
        let mut sim = Sim {
            info,
            rules,
            mobjs: Vec::new(),
            thinkers: Vec::new(),
            players: carried.players,
            console: carried.console,
            starts: Default::default(),
            deathmatch_starts: Vec::new(),
            rng: carried.rng,
            gametic: carried.gametic,
            leveltime: 0,
            blocklinks: vec![Vec::new(); cells],
            validcount: 0,
            line_valid: vec![0; lines],
            tm: collision::MapCheck::default(),
            spec: specials::SpecialState::default(),
            brain: monsters::BrainState::default(),
            item_respawn: Vec::new(),
            bodyque: Vec::new(),
            total_kills: 0,
            total_items: 0,
            total_secrets: 0,
            exit: None,
            events: Vec::new(),
            textures_changed: 0,
            zdoom: Default::default(),
            level,
        };
        // P_SetupLevel: the console player's eye at 1 until the first tic
        // (no teleport sound for the level's first spawns).
        if let Some(p) = sim.players[sim.console].as_mut() {
            p.viewz = Fixed(1);
        }
        sim.spawn_things();
        for n in 0..MAXPLAYERS {
            if sim.players[n].is_none() {
                continue;
            }
            if sim.rules.deathmatch != 0 {
                sim.deathmatch_spawn_player(n);
            } else if sim.starts[n].is_none() {
                // Past the map's starts: Doom would have no body for it.
                sim.spawn_without_start(n, None);
            }
        }
        before_specials(&mut sim);
        specials::spawn_specials(&mut sim);
        sim
    }

    /// `P_LoadThings`: every map thing in the WAD's order. An executable
    /// that is not Doom II stops at the first Doom II monster (vanilla's
    /// `break`, which Chocolate Doom keeps).
    fn spawn_things(&mut self) {
        let things = self.level.things.clone();
        for (i, thing) in things.iter().enumerate() {
            if self.rules.mode != super::GameMode::Commercial && DOOM2_ONLY.contains(&thing.kind) {
                break;
            }
            let first = self.mobjs.len();
            self.spawn_map_thing(thing);
            if let Some(fields) = self.level.thing_fields.get(i).filter(|f| !f.is_none()) {
                for id in first..self.mobjs.len() {
                    fields.put(self.zdoom.entry(super::MobjId(id as u32)));
                }
            }
        }
    }

    /// `P_SpawnMapThing`.
    pub fn spawn_map_thing(&mut self, thing: &WadThing) {
        if thing.kind == 11 {
            self.deathmatch_start(thing);
            return;
        }
        if thing.kind == 0 {
            return;
        }
        if let Some(n) = super::starts::start_player(thing.kind) {
            self.player_start(n, thing);
            return;
        }
        if !self.rules.netgame && thing.flags & MTF_NOTSINGLE != 0 {
            return;
        }
        let bit = match self.rules.skill {
            0 => 1,
            Rules::NIGHTMARE => 4,
            s => 1 << (s - 1),
        };
        if thing.flags & bit == 0 {
            return;
        }
        // Vanilla stops with an error on an unknown number; we pass it over
        // (the importer's report names it).
        let Some(kind) = self.info.by_doomednum(i32::from(thing.kind)) else {
            return;
        };
        let info = &self.info.things[kind];
        if self.rules.deathmatch != 0 && info.flags & mf::NOTDMATCH != 0 {
            return;
        }
        if self.rules.no_monsters && (info.mt == Some(mt::SKULL) || info.flags & mf::COUNTKILL != 0) {
            return;
        }
        let z = if info.flags & mf::SPAWNCEILING != 0 { ONCEILINGZ } else { ONFLOORZ };
        let id = self.spawn_mobj(Fixed::from_int(thing.x.into()), Fixed::from_int(thing.y.into()), z, kind);
        self.mo_mut(id).spawnpoint = thing.clone();
        if self.mo(id).tics > 0 {
            let r = self.p_random();
            let mo = self.mo_mut(id);
            mo.tics = 1 + r % mo.tics;
        }
        self.count_in_totals(id);
        let mo = self.mo_mut(id);
        mo.angle = thing_angle(thing);
        if thing.flags & MTF_AMBUSH != 0 {
            mo.flags |= mf::AMBUSH;
        }
    }

    /// A body the level's tallies count: a monster to kill, an item to find.
    pub fn count_in_totals(&mut self, id: super::MobjId) {
        let flags = self.mo(id).flags;
        if flags & mf::COUNTKILL != 0 {
            self.total_kills += 1;
        }
        if flags & mf::COUNTITEM != 0 {
            self.total_items += 1;
        }
    }
}

/// A map thing's angle as Doom rounds it: down to a multiple of 45 degrees
/// (C's division, towards zero), times `ANG45`, wrapping.
pub(super) fn thing_angle(thing: &WadThing) -> Angle {
    Angle(ANG45.0.wrapping_mul((i32::from(thing.angle) / 45) as u32))
}

impl Player {
    /// `G_PlayerReborn`: a fresh player who keeps its frags and tallies
    /// (`kept`: kills, items, secrets). Fire and use start held, so nothing
    /// fires on the first tic.
    pub fn reborn(info: &Info, frags: [i32; MAXPLAYERS], kept: (i32, i32, i32)) -> Player {
        let mut weaponowned = [false; super::NUMWEAPONS];
        weaponowned[0] = true;
        weaponowned[1] = true;
        let _ = info;
        Player {
            mo: super::MobjId(0),
            playerstate: PlayerState::Live,
            cmd: Ticcmd::default(),
            viewz: Fixed::ZERO,
            viewheight: Fixed::ZERO,
            deltaviewheight: Fixed::ZERO,
            bob: Fixed::ZERO,
            health: 100,
            armorpoints: 0,
            armortype: 0,
            powers: [0; super::NUMPOWERS],
            cards: [false; super::NUMCARDS],
            backpack: false,
            frags,
            readyweapon: 1,
            pendingweapon: Some(1),
            weaponowned,
            ammo: [50, 0, 0, 0],
            maxammo: [200, 50, 300, 50],
            attackdown: true,
            usedown: true,
            cheats: 0,
            refire: 0,
            killcount: kept.0,
            itemcount: kept.1,
            secretcount: kept.2,
            message: None,
            damagecount: 0,
            bonuscount: 0,
            attacker: None,
            extralight: 0,
            fixedcolormap: 0,
            psprites: [Psprite::default(); 2],
            didsecret: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thing_angles_round_towards_zero_in_45s() {
        let at = |angle| thing_angle(&WadThing { x: 0, y: 0, angle, kind: 1, flags: 7 });
        assert_eq!(at(90), Angle(0x4000_0000));
        assert_eq!(at(100), Angle(0x4000_0000));
        assert_eq!(at(359), Angle(0xe000_0000));
        assert_eq!(at(-44), Angle(0));
        assert_eq!(at(-45), Angle(0xe000_0000));
    }
}
