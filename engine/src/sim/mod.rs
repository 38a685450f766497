//! The game with Doom's own arithmetic: positions, heights, momentum and
//! angles in 16.16 fixed point and 32-bit angles ([`crate::fixed`]),
//! `P_Random` with Doom's table and call order, thinkers in Doom's order, a
//! level read from the WAD exactly as stored ([`level`]). Its purpose is to
//! compute what Doom's `p_*.c` computes, bit for bit, so vanilla demos play
//! in sync; `tests/demo_sync.rs` holds it to Chocolate Doom's own dumps
//! tic by tic (`tests/fixtures/demo-dumps/`).
//!
//! One file per mechanism, named for what it does and mapped onto Doom's
//! files (see `ARCHITECTURE.md`, "The simulation with Doom's arithmetic"):
//!
//! | file | Doom's | what |
//! | --- | --- | --- |
//! | `mod.rs` | `p_tick.c`, `g_game.c` | the world, a tic's order |
//! | `level.rs` | `p_setup.c` | the WAD's lumps as stored |
//! | `from_map.rs` | a node builder's output, `p_setup.c` | a compiled RON map as a level |
//! | `info.rs` | `info.c` | the actor table in Doom's units |
//! | `mobj.rs` | `p_mobj.c` (spawn, remove, states, links) | bodies |
//! | `setup.rs` | `p_setup.c`, `g_game.c` | spawning a level's things and players |
//! | `movement.rs` | `p_mobj.c` (thinker, momentum) | how bodies move |
//! | `maputl.rs` | `p_maputl.c` | block iterators, openings, path traversal |
//! | `collision.rs` | `p_map.c` | moves, teleport moves, crushers |
//! | `slide.rs` | `p_map.c` (`P_SlideMove`) | the player's wall slide |
//! | `hitscan.rs` | `p_map.c` (aim, shoot, use, blast) | traces along a line of fire |
//! | `sight.rs` | `p_sight.c` | line of sight over the BSP |
//! | `user.rs` | `p_user.c` | the player's own thinking |
//! | `weapons.rs` | `p_pspr.c` | weapons and their sprites |
//! | `interaction.rs` | `p_inter.c` | pickups, damage, death |
//! | `monsters.rs` | `p_enemy.c` | monster behaviour: waking, chasing, the action dispatch |
//! | `chase.rs` | `p_enemy.c` (`P_Move`, `P_NewChaseDir`) | walking by the eight directions |
//! | `attacks.rs` | `p_enemy.c` (`A_*Attack`) | monster attacks |
//! | `vile.rs` | `p_enemy.c` (`A_VileChase`, `A_Fire`) | the arch-vile's raising and fire |
//! | `bosses.rs` | `p_enemy.c` (`A_BossDeath`, `A_Brain*`) | boss deaths and the boss brain |
//! | `specials.rs` | `p_spec.c` | line and sector specials, animations |
//! | `doors.rs`, `plats.rs`, `floors.rs`, `ceilings.rs`, `lights.rs`, `switches.rs`, `teleport.rs` | `p_doors.c` .. `p_telept.c` | the movers |
//! | `generalized.rs` | Boom's `p_genlin.c` | a RON map's specials no vanilla number says, on the same movers |
//! | `intermission.rs` | `g_game.c` (`G_DoCompleted`, `G_WorldDone`), `wi_stuff.c`, `f_finale.c` (the skip) | between levels, timed as Doom times it |
//! | `demo.rs` | `g_game.c` (`G_DoPlayDemo`) | a demo's game, checked against a dump |
//! | `game.rs` | `g_game.c` (`G_InitNew`, `G_Ticker`) | a game for a person or the autopilot: input in, the game read out |
//! | `draw.rs` | | the simulation drawn by the renderer |
//! | `state.rs` | the patch in `scripts/chocolate-dump.patch` | a tic's state for the reference dumps |
//! | `save.rs` | `p_saveg.c`, `g_game.c` (`G_DoSaveGame`) | saved games that continue bit for bit |
//! | `zdoom.rs` | ZDoom's `AActor` fields | thing ids, thing specials and script-set properties (ViZDoom's scenarios) |

pub mod actions;
pub mod attacks;
pub mod bosses;
pub mod ceilings;
pub mod chase;
pub mod collision;
pub mod demo;
pub mod doors;
pub mod draw;
pub mod floors;
pub mod from_map;
pub mod game;
pub mod generalized;
pub mod hitscan;
pub mod info;
pub mod interaction;
pub mod intermission;
pub mod level;
pub mod lights;
pub mod maputl;
pub mod marines;
pub mod mobj;
pub mod monsters;
pub mod movement;
pub mod plats;
pub mod save;
pub mod setup;
pub mod sight;
pub mod slide;
pub mod specials;
pub mod starts;
pub mod state;
pub mod switches;
pub mod teleport;
pub mod think;
pub mod user;
pub mod vile;
pub mod weapons;
pub mod zdoom;

use std::sync::Arc;

use crate::fixed::{DoomRandom, Fixed};
use crate::play::lmp::Ticcmd;

pub use info::Info;
pub use level::Level;
pub use mobj::Mobj;
pub use think::{Thinker, ThinkerKind};

/// Player slots a game can hold: ViZDoom's and GZDoom's limit, sixteen.
/// Doom's own four are [`VANILLA_PLAYERS`]; which of the two counts a
/// game's rules walk is [`Sim::slots`].
pub const MAXPLAYERS: usize = 16;
/// Player slots in Doom's executables and in their demos' headers
/// (vanilla's `MAXPLAYERS`).
pub const VANILLA_PLAYERS: usize = 4;
/// Tics a second.
pub const TICRATE: u32 = 35;

/// A body, by its index in [`Sim::mobjs`]. Indices are never reused within
/// a level, so a reference to a removed body still reads what it was (as
/// vanilla's dangling pointers read freed memory until it is reused).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct MobjId(pub u32);

/// A thinker, by its index in [`Sim::thinkers`] (run in that order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct ThinkerId(pub u32);

/// Which executable's behaviour to reproduce (`gameversion`), as Chocolate
/// Doom chooses it from the IWAD: freedoom1 plays as The Ultimate Doom,
/// freedoom2 as Doom II 1.9.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum GameVersion {
    Doom19,
    Ultimate,
    Final,
}

/// What the IWAD holds (`gamemode`): Doom II's maps (`Commercial`), or
/// episodes (`Retail` has four).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum GameMode {
    Shareware,
    Registered,
    Retail,
    Commercial,
}

/// Which of Doom's bugs the rules keep (dsda-doom's compatibility levels).
/// `Vanilla` keeps those that demos depend on; `Sightline` fixes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Compat {
    Vanilla,
    Sightline,
}

/// The rules a game starts with (`G_InitNew`'s parameters and the command
/// line's).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Rules {
    /// Doom's skill number 0 (I'm too young to die) to 4 (Nightmare!).
    pub skill: u8,
    pub version: GameVersion,
    pub mode: GameMode,
    pub compat: Compat,
    /// 0 co-op, 1 deathmatch, 2 altdeath.
    pub deathmatch: u8,
    pub respawn: bool,
    pub fast: bool,
    pub no_monsters: bool,
    /// Several players share the game (`netgame`).
    pub netgame: bool,
    /// Players do not aim up, down or sideways at what they face (ZDoom's
    /// `sv_noautoaim`, which two ViZDoom scenarios set; never on Doom's
    /// maps).
    pub no_autoaim: bool,
}

impl Rules {
    pub const NIGHTMARE: u8 = 4;

    /// A single-player game at Doom's `skill` (0-4) as executable `version`
    /// on an IWAD of `mode`, keeping vanilla's bugs, with no command-line
    /// options (a demo's header or a test changes the rest).
    pub fn single(skill: u8, version: GameVersion, mode: GameMode) -> Rules {
        Rules {
            skill,
            version,
            mode,
            compat: Compat::Vanilla,
            deathmatch: 0,
            respawn: false,
            fast: false,
            no_monsters: false,
            netgame: false,
            no_autoaim: false,
        }
    }

    /// Monsters come back (Nightmare or `-respawn`).
    pub fn respawn_monsters(&self) -> bool {
        self.skill == Rules::NIGHTMARE || self.respawn
    }

    /// Fast monsters (Nightmare or `-fast`).
    pub fn fast_monsters(&self) -> bool {
        self.skill == Rules::NIGHTMARE || self.fast
    }
}

/// What a player is doing (`playerstate_t`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum PlayerState {
    Live,
    Dead,
    Reborn,
}

/// A weapon sprite: the weapon (0) or its flash (1) (`pspdef_t`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Psprite {
    /// `None` is Doom's NULL state: not drawn, not run.
    pub state: Option<crate::actors::StateId>,
    pub tics: i32,
    pub sx: Fixed,
    pub sy: Fixed,
}

pub const NUMPOWERS: usize = 6;
pub const NUMCARDS: usize = 6;
pub const NUMWEAPONS: usize = 9;
pub const NUMAMMO: usize = 4;

/// A player (`player_t`): the body is a mobj; this is what Doom keeps
/// beside it.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Player {
    pub mo: MobjId,
    pub playerstate: PlayerState,
    pub cmd: Ticcmd,
    /// The eye's height (`viewz`), and its rest height above the feet.
    pub viewz: Fixed,
    pub viewheight: Fixed,
    pub deltaviewheight: Fixed,
    pub bob: Fixed,
    pub health: i32,
    pub armorpoints: i32,
    /// 0 none, 1 green, 2 blue.
    pub armortype: i32,
    /// Tics left of each power (`powertype_t` order), or a flag.
    pub powers: [i32; NUMPOWERS],
    pub cards: [bool; NUMCARDS],
    pub backpack: bool,
    pub frags: [i32; MAXPLAYERS],
    /// Doom's weapon numbers (`weapontype_t`): 0 fist .. 8 super shotgun.
    pub readyweapon: usize,
    /// `None` is `wp_nochange`.
    pub pendingweapon: Option<usize>,
    pub weaponowned: [bool; NUMWEAPONS],
    pub ammo: [i32; NUMAMMO],
    pub maxammo: [i32; NUMAMMO],
    pub attackdown: bool,
    pub usedown: bool,
    /// `CF_*` bits.
    pub cheats: i32,
    /// Fire held since the last shot (accuracy falls off).
    pub refire: i32,
    pub killcount: i32,
    pub itemcount: i32,
    pub secretcount: i32,
    pub message: Option<String>,
    pub damagecount: i32,
    pub bonuscount: i32,
    pub attacker: Option<MobjId>,
    pub extralight: i32,
    pub fixedcolormap: i32,
    pub psprites: [Psprite; 2],
    pub didsecret: bool,
}

/// Something the game did that the outside world may show or play.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum SimEvent {
    /// A sound (index into Doom's sound list, `sfx_*`) from a body, or from
    /// a sector's sound origin.
    Sound { origin: Option<MobjId>, sector: Option<usize>, sound: usize },
    /// The level ended (normal or secret exit).
    Exit { secret: bool },
    /// A player used line `line` (a linedef): whether it set something
    /// going (a switch that flips), or did nothing.
    Special { line: usize, started: bool },
}

/// The whole game world.
#[derive(Clone, Debug)]
pub struct Sim {
    pub level: Level,
    pub info: Arc<Info>,
    pub rules: Rules,
    /// Every body spawned this level, removed ones included (see [`MobjId`]).
    pub mobjs: Vec<Mobj>,
    /// Thinkers in the order they run.
    pub thinkers: Vec<Thinker>,
    pub players: [Option<Player>; MAXPLAYERS],
    /// The player whose view is shown (`consoleplayer`).
    pub console: usize,
    /// Where each player started (`playerstarts`), for rebirth.
    pub starts: [Option<crate::wad::level::WadThing>; MAXPLAYERS],
    pub deathmatch_starts: Vec<crate::wad::level::WadThing>,
    pub rng: DoomRandom,
    pub gametic: u32,
    pub leveltime: u32,
    /// The bodies in each blockmap cell, most recently linked last (Doom
    /// links at the head, so iterators walk these backwards).
    pub blocklinks: Vec<Vec<MobjId>>,
    /// Doom's `validcount` and the per-line marks it is compared with.
    pub validcount: i32,
    pub line_valid: Vec<i32>,
    /// What the last move or trace found (`p_map.c`'s globals).
    pub tm: collision::MapCheck,
    /// The specials' own state (`p_spec.c`'s globals: active plats and
    /// ceilings, buttons, animations, scrollers).
    pub spec: specials::SpecialState,
    /// The boss brain's targets and state (`p_enemy.c`'s globals).
    pub brain: monsters::BrainState,
    /// The item respawn queue (`itemrespawnque`), for altdeath.
    pub item_respawn: Vec<(crate::wad::level::WadThing, u32)>,
    /// Corpses kept in deathmatch (`bodyque`).
    pub bodyque: Vec<MobjId>,
    pub total_kills: i32,
    pub total_items: i32,
    pub total_secrets: i32,
    /// Set when the level is left (`G_ExitLevel`, `G_SecretExitLevel`).
    pub exit: Option<bool>,
    pub events: Vec<SimEvent>,
    /// Counts the times play changed a side's texture or a sector's flat
    /// (switches, buttons popping back, floors and lifts that change
    /// their flat): what draws the game looks at textures again only when
    /// it moved. Not game state: a loaded game starts it at 0.
    pub textures_changed: u32,
    /// Thing ids, thing specials and script-set properties of a ZDoom
    /// map's bodies (empty on Doom's maps).
    pub zdoom: zdoom::Zdoom,
}

impl Sim {
    /// The body of `id`.
    pub fn mo(&self, id: MobjId) -> &Mobj {
        &self.mobjs[id.0 as usize]
    }

    pub fn mo_mut(&mut self, id: MobjId) -> &mut Mobj {
        &mut self.mobjs[id.0 as usize]
    }

    pub fn player(&self, n: usize) -> Option<&Player> {
        self.players.get(n).and_then(Option::as_ref)
    }

    /// The player slots the game's rules count in, where Doom counts in
    /// its `MAXPLAYERS`: a new body's `lastlook` (`P_Random() % slots`),
    /// the monsters' walk round the players, how many deathmatch starts a
    /// level keeps. Doom's four while every player is in them, so Doom's
    /// games, its demos and their saves get exactly Doom's numbers; all
    /// sixteen once a player is past them (GZDoom walks its `MAXPLAYERS`
    /// the same way). Players join only when a game is made and never
    /// leave, so a game's count never changes.
    pub fn slots(&self) -> usize {
        if self.players[VANILLA_PLAYERS..].iter().all(Option::is_none) {
            VANILLA_PLAYERS
        } else {
            MAXPLAYERS
        }
    }

    /// `P_Random`: the game's one random source, in Doom's table order.
    pub fn p_random(&mut self) -> i32 {
        self.rng.p_random()
    }

    /// `S_StartSound` from a body (`None`: everywhere). Sounds do not
    /// change the game; they are events for the outside world.
    pub fn sound(&mut self, origin: Option<MobjId>, sound: usize) {
        if sound != 0 {
            self.events.push(SimEvent::Sound { origin, sector: None, sound });
        }
    }

    /// A sound from a sector's sound origin (doors, lifts).
    pub fn sector_sound(&mut self, sector: usize, sound: usize) {
        if sound != 0 {
            self.events.push(SimEvent::Sound { origin: None, sector: Some(sector), sound });
        }
    }

    /// A sound by its Doom name (`"pistol"` for `sfx_pistol`).
    pub fn sound_named(&mut self, origin: Option<MobjId>, name: &str) {
        let sound = self.info.sound(name);
        self.sound(origin, sound);
    }

    /// One tic (`G_Ticker`'s commands, then `P_Ticker`): each player in the
    /// game takes its command, then the players think, then every thinker in
    /// order, then the specials; removed thinkers are passed over.
    pub fn tick(&mut self, cmds: &[Option<Ticcmd>; MAXPLAYERS]) {
        for (player, cmd) in self.players.iter_mut().zip(cmds) {
            if let (Some(p), Some(cmd)) = (player, cmd) {
                p.cmd = *cmd;
            }
        }
        for n in 0..MAXPLAYERS {
            if self.players[n].is_some() {
                user::player_think(self, n);
            }
        }
        think::run_thinkers(self);
        specials::update_specials(self);
        specials::respawn_specials(self);
        self.leveltime += 1;
        self.gametic += 1;
    }
}

/// Where a Freedoom IWAD is for the unit tests (`SIGHTLINE_DOOM_DIR`, else
/// Debian's directory); tests that need one are ignored without it
/// (`engine/build.rs`).
#[cfg(test)]
pub(crate) fn test_wad(name: &str) -> crate::wad::Wad {
    let dir = std::env::var_os("SIGHTLINE_DOOM_DIR")
        .map_or_else(|| std::path::PathBuf::from("/usr/share/games/doom"), std::path::PathBuf::from);
    let path = dir.join(name);
    crate::wad::Wad::open(&path).unwrap_or_else(|e| panic!("{} (apt-get install freedoom): {e}", path.display()))
}
