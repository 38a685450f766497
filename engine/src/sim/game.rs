//! A game for a person or the autopilot on the simulation with Doom's
//! arithmetic (`g_game.c`'s part: a new game on a map, a tic from the
//! player's input, the level's end): [`SimGame`] holds the [`Sim`], the
//! converted map the renderer draws (written each tic by [`Scene`]), and
//! what the outside reads of the game in map units and degrees (the
//! player, the things, sounds and messages, the tallies), all the
//! fixed-point values divided out.
//!
//! Input arrives as the keyboard's [`TickInput`] and is turned into Doom's
//! command (`ticcmd_t`) as a 1.9 demo keeps it (turns to 1/256 of the
//! circle, the rest carried to the next tic), and every command is kept:
//! [`SimGame::commands`] is the game as a vanilla demo, which Chocolate
//! Doom plays to the same end.

use std::borrow::Cow;

use glam::DVec2;

use super::draw::Scene;
use super::intermission::Intermission;
use super::setup::Players;
use super::{demo, from_map, Compat, MobjId, PlayerState, Rules, Sim, SimEvent, MAXPLAYERS};
use crate::actors::{sounds, zdoom, ActorTable, KeyForm};
use crate::autopilot::observe::{Observe, Seen};
use crate::campaign::{MapRef, Opened};
use crate::level::Level;
use crate::map::special::KeyColour;
use crate::map::LineSpecial;
use crate::play::events::{Event, Origin};
use crate::play::lmp::Ticcmd;
use crate::play::player::{Key, PSprite};
use crate::play::world::{Exit, SpecialLine};
use crate::play::{vanilla, GameOptions, Player, Stats, TickInput};
use crate::render::View;
use crate::scenario::Scripts;

use super::mobj::mf;

#[derive(Debug, thiserror::Error)]
pub enum SimGameError {
    #[error("{map}: {what}")]
    Start { map: String, what: String },
}

/// A game on one level of the simulation with Doom's arithmetic.
#[derive(Clone)]
pub struct SimGame {
    pub sim: Sim,
    level: Level,
    scene: Scene,
    options: GameOptions,
    /// What the outside reads, refreshed after every tic.
    player: Player,
    seen: Vec<Seen>,
    /// Per sector of the converted map: a mover is at work there.
    busy: Vec<bool>,
    events: Vec<Event>,
    /// The eye at the start and the end of the last tic.
    before: View,
    after: View,
    commands: Vec<Ticcmd>,
    /// The part of a turn a command could not carry yet (degrees).
    carry: f64,
    /// The converted map's fingerprint as opened, before play (a save
    /// names the map by it: `play::save::map_fingerprint`).
    fingerprint: u32,
    /// A ZDoom map's ACS scripts, run after each tic.
    scripts: Option<Box<Scripts>>,
}

impl SimGame {
    /// A new game on `opened` (a WAD's map, or a RON map through
    /// [`from_map`]) with `options`. A WAD map plays by the rules of the
    /// executable Chocolate Doom picks for its IWAD, with the IWAD's
    /// DEHACKED applied and vanilla's bugs kept (its commands then replay
    /// in Chocolate Doom); a RON map plays with Sightline's fixes.
    pub fn new(opened: Opened, options: GameOptions) -> Result<SimGame, SimGameError> {
        SimGame::with_table(opened, options, ActorTable::active().clone())
    }

    /// A new game on a RON level already loaded (not from a file: a test's
    /// map, a reloaded one), named `label` in errors.
    pub fn on_level(level: Level, label: &str, options: GameOptions) -> Result<SimGame, SimGameError> {
        SimGame::new(Opened::of_level(level, label), options)
    }

    /// [`SimGame::new`] with the actor table `table` (a mod's, a test's)
    /// for a RON map; a WAD map takes `table` with the IWAD's DEHACKED
    /// applied.
    pub fn with_table(
        opened: Opened,
        options: GameOptions,
        table: std::sync::Arc<ActorTable>,
    ) -> Result<SimGame, SimGameError> {
        SimGame::begin(opened, options, table, None, Setup::SINGLE)
    }

    /// A net game of `setup.players` players (1 to [`MAXPLAYERS`]), deathmatch or
    /// co-operative, on `opened`; the console player is player 1.
    /// [`SimGame::command_all`] feeds every player.
    pub fn netgame(opened: Opened, options: GameOptions, setup: Setup) -> Result<SimGame, SimGameError> {
        SimGame::begin(opened, options, ActorTable::active().clone(), None, setup)
    }

    /// A game on `opened`: a new one, or `from`'s going on there (its
    /// players, random index and tic count, [`Sim::next_level`]).
    fn begin(
        mut opened: Opened,
        options: GameOptions,
        table: std::sync::Arc<ActorTable>,
        from: Option<&Sim>,
        setup: Setup,
    ) -> Result<SimGame, SimGameError> {
        let label = opened.map.label();
        let error = |what: String| SimGameError::Start { map: label.clone(), what };
        let fingerprint = crate::play::save::map_fingerprint(&opened.level);
        if !(1..=5).contains(&options.skill) {
            return Err(error(format!("skill {} is not 1 to 5", options.skill)));
        }
        let skill = options.skill - 1;
        if !(1..=MAXPLAYERS).contains(&setup.players) {
            return Err(error(format!("{} players: a game holds 1 to {MAXPLAYERS}", setup.players)));
        }
        let players = setup.players();
        let mut scripts = None;
        // The WADs as opened (read again only for a map opened otherwise).
        let read;
        let stacked = match (&opened.map, &opened.wad) {
            (MapRef::Wad { .. }, Some(art)) => Some(&art.wad),
            (MapRef::Wad { wads, .. }, None) => {
                read = crate::campaign::stack(wads).map_err(|e| error(e.to_string()))?;
                Some(&read)
            }
            _ => None,
        };
        let udmf = match (&opened.map, &stacked) {
            (MapRef::Wad { map: Some(name), .. }, Some(wad)) if wad.is_udmf(name) => Some((wad, name.clone())),
            _ => None,
        };
        let (sim, scene) = match (&opened.map, opened.links, udmf) {
            (_, _, Some((wad, name))) => {
                let library = crate::texture::Library { dirs: Vec::new(), wad: opened.wad.clone() };
                let map = ZdoomMap { wad, name: &name, level: &mut opened.level, library: &library };
                let (sim, loaded) = zdoom_sim(map, &options, table, from, setup).map_err(&error)?;
                scripts = loaded;
                (sim, Scene::identity(&opened.level.compiled.map))
            }
            (MapRef::Wad { map: Some(name), .. }, Some(links), None) => {
                let Some(wad) = stacked else { unreachable!("a WAD map's WADs are stacked above") };
                let sim = match from {
                    Some(from) => from.next_level_of(wad, name),
                    None => {
                        let table = demo::table_for(wad, &table).map_err(&error)?;
                        let mode = demo::game_mode(wad);
                        let version = demo::game_version(mode);
                        let rules = setup
                            .rules(Rules { no_monsters: options.no_monsters, ..Rules::single(skill, version, mode) });
                        Sim::new(wad, name, rules, players, table)
                    }
                };
                let sim = sim.map_err(|e| error(e.to_string()))?;
                (sim, Scene::new(links))
            }
            _ => {
                let compiled = &opened.level.compiled;
                let level = from_map::level_from_map(compiled, &table).map_err(|e| error(e.to_string()))?;
                let sim = sightline_game(level, &opened.level, &options, table, from, setup);
                (sim, Scene::identity(&compiled.map))
            }
        };
        let mut game = SimGame {
            sim,
            level: opened.level,
            scene,
            options,
            player: Player::new(DVec2::ZERO, 0.0, 0, 0.0, 0.0),
            seen: Vec::new(),
            busy: Vec::new(),
            events: Vec::new(),
            before: View::new(DVec2::ZERO, 0.0, 0.0),
            after: View::new(DVec2::ZERO, 0.0, 0.0),
            commands: Vec::new(),
            carry: 0.0,
            fingerprint,
            scripts,
        };
        game.level.show_skill(options.skill);
        game.refresh();
        game.before = game.after;
        Ok(game)
    }

    /// This game, new and unplayed, as it would have begun with `seed`:
    /// a copy with the generators moved as [`SimGame::new`] moves them (a
    /// RON or ZDoom map's Doom table cursors, the scripts' generator). A
    /// scenario sets its game up once with seed 0 and copies it for each
    /// episode. `None` for a game already played or not begun with seed 0.
    pub fn reseeded(&self, seed: u64) -> Option<SimGame> {
        if self.options.seed != 0 || self.ticks() != 0 {
            return None;
        }
        let mut game = self.clone();
        if game.sim.rules.compat == Compat::Sightline {
            seed_random(&mut game.sim, seed);
        }
        if let Some(s) = game.scripts.as_mut() {
            s.reseed(seed);
        }
        game.options.seed = seed;
        Some(game)
    }

    /// The game going on to the next map of a campaign, or to its own map
    /// again for a player reborn (`G_DoLoadLevel`): the players as the last
    /// level and the intermission left them (Doom's `G_PlayerFinishLevel`
    /// took their keys and powers as the level ended), the random index and
    /// the tic count carried on, as vanilla carries them.
    pub fn next_level(opened: Opened, options: GameOptions, from: &SimGame) -> Result<SimGame, SimGameError> {
        let table = from.sim.info.table.clone();
        let rules = from.sim.rules;
        let players = from.sim.players.iter().flatten().count();
        let setup = Setup { players, deathmatch: rules.deathmatch, no_autoaim: rules.no_autoaim };
        SimGame::begin(opened, options, table, Some(&from.sim), setup)
    }

    /// The console player died and pressed use (`PST_REBORN`): the game
    /// reloads its level on the next tic.
    pub fn reborn(&self) -> bool {
        self.sim.player(self.sim.console).is_some_and(|p| p.playerstate == PlayerState::Reborn)
    }

    /// The level has ended: `G_DoCompleted` and the intermission, or
    /// `None` where Doom ends the game without one (Doom 1's ExM8).
    pub fn complete(&mut self) -> Option<Intermission> {
        self.sim.complete_level(false)
    }

    /// One tic of the intermission `wi` from the player's input.
    pub fn tick_between(&mut self, wi: &mut Intermission, input: &TickInput) {
        self.events.clear();
        let cmd = vanilla::command_of(input, &mut self.carry);
        self.sim.tick_between(wi, &first_player(cmd));
        // The tallies' ticks and thumps, heard as the player's own.
        self.events.extend(wi.sounds.iter().map(|&sound| Event::Sound { sound, origin: Origin::Player }));
    }

    /// The game's whole state as bytes (what a save holds): the part of a
    /// turn not yet carried into a command (8 bytes, an `f64`, little
    /// endian), then the simulation's saved state ([`super::save::to_bytes`]).
    pub fn state_bytes(&self) -> Vec<u8> {
        let mut bytes = self.carry.to_le_bytes().to_vec();
        bytes.extend(super::save::to_bytes(&self.sim));
        bytes
    }

    /// Puts the game in the state `bytes` hold ([`SimGame::state_bytes`]),
    /// checked against this game's map and actor table; on an error the
    /// game is as it was. `label` names the file in errors.
    pub fn restore(&mut self, bytes: &[u8], label: &str) -> Result<(), super::save::SaveError> {
        let truncated = || super::save::SaveError::Truncated { path: label.to_string(), what: "no turn carry".into() };
        let (carry, rest) = bytes.split_first_chunk::<8>().ok_or_else(truncated)?;
        let carry = f64::from_le_bytes(*carry);
        if !carry.is_finite() || carry.abs() > 360.0 {
            let what = format!("a turn carry of {carry} degrees");
            return Err(super::save::SaveError::Invalid { path: label.to_string(), element: "the game".into(), what });
        }
        let (level, info) = (self.sim.level.clone(), self.sim.info.clone());
        self.sim = super::save::from_bytes(rest, label, level, info)?;
        self.carry = carry;
        self.scene.look_again();
        self.refresh();
        self.before = self.after;
        Ok(())
    }

    /// Puts the player at `pos` facing `angle` (degrees), standing still on
    /// the floor there (a map reloaded under a map maker keeps their pose).
    /// Returns `false`, and leaves the game as it was, when `pos` is outside
    /// every sector or the body does not fit there (`P_CheckPosition`).
    pub fn place_player(&mut self, pos: DVec2, angle: f64) -> bool {
        let limit = f64::from(i16::MAX);
        if !pos.is_finite() || pos.abs().max_element() > limit || self.level.compiled.locate(pos).is_none() {
            return false;
        }
        let Some(mo) = self.sim.player(self.sim.console).map(|p| p.mo) else { return false };
        let (x, y) = (crate::fixed::Fixed::from_f64(pos.x), crate::fixed::Fixed::from_f64(pos.y));
        // Asked of a copy: `P_CheckPosition` picks up what it touches and
        // leaves `p_map.c`'s globals set, and this is no move of the game's.
        let mut probe = self.sim.clone();
        if !super::collision::check_position(&mut probe, mo, x, y) {
            return false;
        }
        let (floorz, ceilingz) = (probe.tm.floorz, probe.tm.ceilingz);
        if ceilingz - floorz < self.sim.mo(mo).height {
            return false;
        }
        self.sim.unset_thing_position(mo);
        let m = self.sim.mo_mut(mo);
        (m.x, m.y, m.z, m.floorz, m.ceilingz) = (x, y, floorz, floorz, ceilingz);
        (m.momx, m.momy, m.momz) = (crate::fixed::Fixed::ZERO, crate::fixed::Fixed::ZERO, crate::fixed::Fixed::ZERO);
        m.angle = crate::fixed::Angle::from_degrees(angle.rem_euclid(360.0));
        self.sim.set_thing_position(mo);
        if let Some(p) = self.sim.players[self.sim.console].as_mut() {
            p.viewz = floorz + p.viewheight;
        }
        self.refresh();
        self.before = self.after;
        true
    }

    /// Sets the player's health, in the game and on its body (tests and
    /// tools: a player about to die, one that cannot).
    pub fn set_health(&mut self, health: i32) {
        let console = self.sim.console;
        let Some(p) = self.sim.players[console].as_mut() else { return };
        p.health = health;
        let mo = p.mo;
        self.sim.mo_mut(mo).health = health;
        self.refresh_player();
    }

    /// How the simulation's level maps onto the converted one drawn.
    pub fn links(&self) -> &crate::wad::import::Links {
        self.scene.links()
    }

    /// The level to draw into (a Doom demo played elsewhere is drawn here).
    pub fn level_mut(&mut self) -> &mut Level {
        &mut self.level
    }

    /// The player as the outside reads it, to change for what is shown
    /// only: the next tic reads it afresh from the simulation.
    pub fn player_mut(&mut self) -> &mut Player {
        &mut self.player
    }

    /// One tic from the player's input, as a 1.9 demo keeps it.
    pub fn tick(&mut self, input: &TickInput) {
        let cmd = vanilla::command_of(input, &mut self.carry);
        self.command(cmd);
    }

    /// One tic from a Doom command. After the level has ended tics do
    /// nothing.
    pub fn command(&mut self, cmd: Ticcmd) {
        self.command_all(&first_player(cmd));
    }

    /// One tic of a net game: each player's command (`None`: as before).
    /// A player reborn in a net game respawns first (`G_DoReborn`), and a
    /// ZDoom map's RESPAWN scripts start for it. The console player's
    /// commands are the ones kept.
    pub fn command_all(&mut self, cmds: &[Option<Ticcmd>; MAXPLAYERS]) {
        self.events.clear();
        if self.sim.exit.is_some() {
            return;
        }
        if self.sim.rules.netgame {
            for n in 0..MAXPLAYERS {
                if self.sim.player(n).is_some_and(|p| p.playerstate == PlayerState::Reborn) {
                    self.sim.respawn_in_netgame(n);
                    if let (Some(scripts), Some(p)) = (self.scripts.as_mut(), self.sim.player(n)) {
                        scripts.respawned(p.mo);
                    }
                }
            }
        }
        self.before = self.after;
        let console = self.sim.console;
        self.commands.push(cmds[console].unwrap_or_default());
        self.sim.tick(cmds);
        if let Some(scripts) = self.scripts.as_mut() {
            scripts.tick(&mut self.sim);
        }
        self.refresh();
        if self.after.pos.distance(self.before.pos) > 64.0 {
            // A teleport: do not draw the way between.
            self.before = self.after;
        }
    }

    /// Draws the game as player `n` sees it (`level`, `view` and
    /// `player` become that player's: the others' bodies drawn, its own
    /// not), for a game with several agents each with its own screen. The
    /// simulation is untouched: only the picture's side of the game
    /// changes, until the next tic or the next look. `false` for a player
    /// not in the game.
    pub fn look_as(&mut self, n: usize) -> bool {
        if self.sim.player(n).is_none() {
            return false;
        }
        let console = self.sim.console;
        self.sim.console = n;
        self.scene.draw(&self.sim, &mut self.level);
        if let Some(view) = self.scene.view(&self.sim) {
            self.after = view;
            self.before = view;
        }
        self.refresh_player();
        self.sim.console = console;
        true
    }

    /// A ZDoom map's scripts (`None` on other maps, or a map without any).
    pub fn scripts(&self) -> Option<&Scripts> {
        self.scripts.as_deref()
    }

    /// The fingerprint of the map as opened, before play.
    pub fn fingerprint(&self) -> u32 {
        self.fingerprint
    }

    /// The commands played so far: the game as a vanilla demo.
    pub fn commands(&self) -> &[Ticcmd] {
        &self.commands
    }

    pub fn options(&self) -> GameOptions {
        self.options
    }

    /// The eye, interpolated between the start (`alpha` 0) and the end
    /// (`alpha` 1) of the last tic.
    pub fn view(&self, alpha: f64) -> View {
        let a = if alpha.is_nan() { 1.0 } else { alpha.clamp(0.0, 1.0) };
        let (p, q) = (self.before, self.after);
        let turned = (q.angle - p.angle + 540.0).rem_euclid(360.0) - 180.0;
        View::new(p.pos + (q.pos - p.pos) * a, p.z + (q.z - p.z) * a, (p.angle + turned * a).rem_euclid(360.0))
    }

    /// The converted map's sector of a body.
    fn sector_of(&self, id: MobjId) -> usize {
        let m = self.sim.mo(id);
        let s = self.sim.level.subsectors.get(m.subsector).map_or(0, |s| s.sector);
        self.scene.sector(s).unwrap_or(0)
    }

    /// Reads the game out after a tic: the level drawn, the player, the
    /// things, the busy sectors, the tic's sounds and messages.
    fn refresh(&mut self) {
        self.scene.draw(&self.sim, &mut self.level);
        if let Some(view) = self.scene.view(&self.sim) {
            self.after = view;
        }
        self.refresh_player();
        self.seen.clear();
        let players: Vec<MobjId> = self.sim.players.iter().flatten().map(|p| p.mo).collect();
        for m in &self.sim.mobjs {
            let by_player = m.has(mf::MISSILE) && m.target.is_some_and(|t| players.contains(&t));
            self.seen.push(Seen {
                kind: m.kind,
                pos: DVec2::new(m.x.to_f64(), m.y.to_f64()),
                z: m.z.to_f64(),
                vel: DVec2::new(m.momx.to_f64(), m.momy.to_f64()),
                health: m.health,
                removed: m.removed || m.state.is_none(),
                solid: m.has(mf::SOLID),
                shootable: m.has(mf::SHOOTABLE),
                missile: m.has(mf::MISSILE),
                by_player,
            });
        }
        self.busy.clear();
        self.busy.resize(self.level.compiled.map.sectors.len(), false);
        for (i, s) in self.sim.level.sectors.iter().enumerate() {
            if let (Some(_), Some(j)) = (s.specialdata, self.scene.sector(i)) {
                if let Some(b) = self.busy.get_mut(j) {
                    *b = true;
                }
            }
        }
        self.take_events();
    }

    fn refresh_player(&mut self) {
        let console = self.sim.console;
        let Some(p) = self.sim.player(console) else { return };
        let mo = p.mo;
        let m = self.sim.mo(mo);
        let info = &self.sim.info;
        let weapon = |n: usize| info.weapons.get(n).and_then(Option::as_ref).map(|w| w.actor);
        let colours = [KeyColour::Blue, KeyColour::Yellow, KeyColour::Red];
        let keys = (0..6)
            .filter(|&k| p.cards[k])
            .map(|k| Key { colour: colours[k % 3], form: if k < 3 { KeyForm::Card } else { KeyForm::Skull } })
            .collect();
        // Doom's ammunition order is bullets, shells, cells, rockets.
        let ammo = |a: [i32; 4]| [a[0], a[1], a[3], a[2]];
        let psprite =
            |s: &super::Psprite| PSprite { state: s.state, tics: s.tics, sx: s.sx.to_f64(), sy: s.sy.to_f64() };
        let dead = p.playerstate != PlayerState::Live;
        let q = &mut self.player;
        q.pos = DVec2::new(m.x.to_f64(), m.y.to_f64());
        q.z = m.z.to_f64();
        q.angle = m.angle.to_degrees();
        q.velocity = DVec2::new(m.momx.to_f64(), m.momy.to_f64());
        q.vz = m.momz.to_f64();
        q.floor = m.floorz.to_f64();
        q.ceiling = m.ceilingz.to_f64();
        q.view_height = p.viewheight.to_f64();
        q.view_delta = p.deltaviewheight.to_f64();
        q.health = if dead { p.health.min(0) } else { p.health.max(1) };
        q.keys = keys;
        q.armor = p.armorpoints;
        q.armor_class = p.armortype.clamp(0, 2) as u8;
        q.ammo = ammo(p.ammo);
        q.max_ammo = ammo(p.maxammo);
        q.backpack = p.backpack;
        q.weapons = (0..super::NUMWEAPONS).filter(|&n| p.weaponowned[n]).filter_map(weapon).collect();
        q.powers = p.powers;
        q.freeze = m.reactiontime.max(0) as u32;
        q.use_held = p.usedown;
        q.fire_held = p.attackdown;
        q.ready_weapon = weapon(p.readyweapon);
        q.pending_weapon = p.pendingweapon.and_then(weapon);
        q.psprites = [psprite(&p.psprites[0]), psprite(&p.psprites[1])];
        q.refire = p.refire;
        q.attack_down = p.attackdown;
        q.extra_light = p.extralight;
        q.damage_count = p.damagecount;
        q.bonus_count = p.bonuscount;
        self.player.sector = self.sector_of(mo);
    }

    /// The tic's sounds, switches and messages in the outside's terms.
    fn take_events(&mut self) {
        outside_events(&mut self.sim, &self.scene, &mut self.events);
    }

    /// Whether a line of the converted map still has its special in the
    /// simulation: one of the WAD linedefs behind it does (lines with the
    /// same ends are merged, and the merged line takes the special of the
    /// one that had it).
    fn live(&self, line: SpecialLine) -> bool {
        let has = |d: usize| self.sim.level.lines.get(d).is_some_and(|l| l.special != 0);
        match line {
            SpecialLine::Wall(i) => self.scene.linedefs(i).iter().any(|&d| has(d)),
            SpecialLine::Trigger(i) => self.scene.trigger_linedef(i).is_some_and(has),
        }
    }

    /// The converted map's special on `line`, as the map has it.
    fn map_special(&self, line: SpecialLine) -> Option<&LineSpecial> {
        let map = &self.level.compiled.map;
        match line {
            SpecialLine::Wall(i) => map.lines.get(i)?.special.as_ref(),
            SpecialLine::Trigger(i) => Some(&map.trigger_lines.get(i)?.special),
        }
    }

    /// The level as drawn: the converted map with the simulation's heights,
    /// light, textures and things written in after every tic.
    pub fn level(&self) -> &Level {
        &self.level
    }

    /// The player in map units and degrees.
    pub fn player(&self) -> &Player {
        &self.player
    }

    /// Tics played on this level (Doom's `leveltime`).
    pub fn ticks(&self) -> u64 {
        u64::from(self.sim.leveltime)
    }

    /// The last tic's sounds, switches and messages.
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// The console player's tallies and the level's totals.
    pub fn stats(&self) -> Stats {
        stats_of(&self.sim)
    }

    /// How the level ended, once it has.
    pub fn exit(&self) -> Option<Exit> {
        self.sim.exit.map(|secret| if secret { Exit::Secret } else { Exit::Normal })
    }
}

/// `sim`'s console player's tallies and the level's totals and time.
pub fn stats_of(sim: &Sim) -> Stats {
    let p = sim.player(sim.console);
    let count = |f: fn(&super::Player) -> i32| p.map_or(0, f).max(0) as u32;
    let total = |n: i32| n.max(0) as u32;
    Stats {
        kills: (count(|p| p.killcount), total(sim.total_kills)),
        items: (count(|p| p.itemcount), total(sim.total_items)),
        secrets: (count(|p| p.secretcount), total(sim.total_secrets)),
        ticks: u64::from(sim.leveltime),
    }
}

impl Observe for SimGame {
    fn level(&self) -> &Level {
        SimGame::level(self)
    }

    fn ticks(&self) -> u64 {
        SimGame::ticks(self)
    }

    fn player(&self) -> &Player {
        SimGame::player(self)
    }

    fn seen(&self) -> Cow<'_, [Seen]> {
        Cow::Borrowed(&self.seen)
    }

    fn table(&self) -> &ActorTable {
        &self.sim.info.table
    }

    fn exit(&self) -> Option<Exit> {
        SimGame::exit(self)
    }

    fn events(&self) -> &[Event] {
        SimGame::events(self)
    }

    fn stats(&self) -> Stats {
        SimGame::stats(self)
    }

    fn is_busy(&self, sector: usize) -> bool {
        self.busy.get(sector).copied().unwrap_or(false)
    }

    /// Commands keep a turn's high byte, as a 1.9 demo does.
    fn turn_step(&self) -> f64 {
        360.0 / 256.0
    }

    fn special(&self, line: SpecialLine) -> Option<LineSpecial> {
        self.map_special(line).filter(|_| self.live(line)).cloned()
    }

    /// Doom's `PTR_UseTraverse` on the converted map: the first line with
    /// a special (any, as vanilla stops at walk lines too), or a wall whose
    /// opening is shut.
    fn use_stop(&self, from: DVec2, to: DVec2) -> Option<SpecialLine> {
        let map = &self.level.compiled.map;
        let mut hits: Vec<(f64, SpecialLine)> = Vec::new();
        let mut cross = |a: DVec2, b: DVec2, line: SpecialLine| {
            if let Some(t) = crate::geom::crossing(from, to, a, b) {
                hits.push((t, line));
            }
        };
        for (i, l) in map.lines.iter().enumerate() {
            cross(map.vertices[l.from], map.vertices[l.to], SpecialLine::Wall(i));
        }
        for (i, t) in map.trigger_lines.iter().enumerate() {
            cross(map.vertices[t.from], map.vertices[t.to], SpecialLine::Trigger(i));
        }
        hits.sort_by(|a, b| a.0.total_cmp(&b.0));
        hits.into_iter().map(|(_, l)| l).find(|&l| {
            self.live(l)
                || match l {
                    SpecialLine::Wall(i) => {
                        let line = &map.lines[i];
                        line.back.as_ref().is_none_or(|back| {
                            let (f, b) = (&map.sectors[line.front.sector], &map.sectors[back.sector]);
                            f.ceiling.min(b.ceiling) <= f.floor.max(b.floor)
                        })
                    }
                    SpecialLine::Trigger(_) => false,
                }
        })
    }
}

/// The tic's sounds, switches and messages of `sim` in the outside's terms
/// (`scene` maps the WAD's sectors and lines onto the converted map),
/// appended to `out`; the simulation's own list is emptied. A game and a
/// Doom demo shown in the window both read their tics so.
pub fn outside_events(sim: &mut Sim, scene: &Scene, out: &mut Vec<Event>) {
    let viewer = sim.player(sim.console).map(|p| p.mo);
    for e in std::mem::take(&mut sim.events) {
        match e {
            SimEvent::Sound { origin, sector, sound } => {
                // Events carry Doom's names from the shipped sound list (the
                // table's names are checked against it when it loads).
                let name = sim.info.table.sounds.get(sound.wrapping_sub(1));
                let Some(name) = name.and_then(|n| sounds::doom().iter().find(|d| d.name == *n)) else { continue };
                let origin = match (origin, sector) {
                    (Some(id), _) if Some(id) == viewer => Origin::Player,
                    (Some(id), _) => {
                        let m = sim.mo(id);
                        Origin::Actor { index: id.0, pos: DVec2::new(m.x.to_f64(), m.y.to_f64()) }
                    }
                    (None, Some(s)) => Origin::Sector(scene.sector(s).unwrap_or(0)),
                    (None, None) => Origin::Player,
                };
                out.push(Event::Sound { sound: name.name.as_str(), origin });
            }
            SimEvent::Special { line, started } => {
                if let Some(line) = scene.line_of_linedef(line) {
                    let line = line.map_or_else(SpecialLine::Trigger, SpecialLine::Wall);
                    out.push(Event::Special { line, started });
                }
            }
            SimEvent::Exit { .. } => {}
        }
    }
    let console = sim.console;
    if let Some(message) = sim.players[console].as_mut().and_then(|p| p.message.take()) {
        out.push(Event::Message(message));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsp::BuildOptions;
    use crate::campaign::open;

    fn e1m1() -> SimGame {
        let dir = std::env::var_os("SIGHTLINE_DOOM_DIR")
            .map_or_else(|| std::path::PathBuf::from("/usr/share/games/doom"), std::path::PathBuf::from);
        let map = MapRef::Wad { wads: vec![dir.join("freedoom1.wad")], map: Some("E1M1".into()) };
        let opened = open(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        SimGame::new(opened, GameOptions { skill: 3, ..GameOptions::default() }).unwrap_or_else(|e| panic!("{e}"))
    }

    /// A switch the simulation flips shows flipped on the converted map's
    /// line, found through the importer's links.
    #[test]
    #[cfg_attr(freedoom_missing, ignore = "needs freedoom1.wad: apt-get install freedoom")]
    fn a_flipped_switch_shows_on_the_converted_map() {
        let mut game = e1m1();
        let list = super::super::switches::switch_list(game.sim.rules.mode, game.sim.rules.compat);
        let is_switch = |name: &str| list.iter().any(|s| s.eq_ignore_ascii_case(name));
        let level = &game.sim.level;
        let linedef = (0..level.lines.len())
            .find(|&l| {
                level.lines[l].special != 0
                    && level.lines[l].sidenum[0].is_some_and(|s| {
                        let side = &level.sides[s];
                        [side.toptexture, side.midtexture, side.bottomtexture].iter().any(|&t| is_switch(level.name(t)))
                    })
            })
            .expect("E1M1 has a switch");
        let Some(Ok(line)) = game.scene.line_of_linedef(linedef) else { panic!("linedef {linedef} is a wall") };
        let shown = |game: &SimGame| game.level.materials.sides[line][0];
        let before = shown(&game);
        super::super::switches::change_switch_texture(&mut game.sim, linedef, true);
        game.tick(&TickInput::default());
        let after = shown(&game);
        assert_ne!(before, after, "the switch on line {line} (linedef {linedef}) did not flip on screen");
        let names = |s: crate::materials::SideTextures| {
            [s.upper, s.middle, s.lower].map(|t| t.map(|t| game.level.materials.textures.name(t).to_string()))
        };
        assert!(names(after).iter().flatten().any(|n| is_switch(n)), "{:?}", names(after));
        // A button pops back after a second.
        for _ in 0..36 {
            game.tick(&TickInput::default());
        }
        assert_eq!(shown(&game), before, "the button did not pop back");
    }

    fn cursors(g: &SimGame) -> (u8, u8) {
        (g.sim.rng.p_index(), g.sim.rng.m_index())
    }

    /// A RON map's seed moves where Doom's random table is read from on
    /// from where the level's setup left it.
    #[test]
    fn a_seed_moves_a_ron_map_s_random_cursors() {
        let ron = |seed: u64| {
            let map = MapRef::File(std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../maps/outpost.ron"));
            let opened = open(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
            SimGame::new(opened, GameOptions { seed, ..GameOptions::default() }).unwrap_or_else(|e| panic!("{e}"))
        };
        let (p, m) = cursors(&ron(0));
        assert_eq!(cursors(&ron(0x0201)), (p.wrapping_add(1), m.wrapping_add(2)));
        assert_eq!(cursors(&ron(0x0201)), cursors(&ron(0x0201)), "the same seed, the same game");
    }

    /// A WAD's map starts the table at 0 whatever the seed, as vanilla does
    /// (its demos need it).
    #[test]
    #[cfg_attr(freedoom_missing, ignore = "needs freedoom1.wad: apt-get install freedoom")]
    fn a_wad_map_s_random_cursors_do_not_follow_the_seed() {
        let dir = std::env::var_os("SIGHTLINE_DOOM_DIR")
            .map_or_else(|| std::path::PathBuf::from("/usr/share/games/doom"), std::path::PathBuf::from);
        let map = MapRef::Wad { wads: vec![dir.join("freedoom1.wad")], map: Some("E1M1".into()) };
        let opened = open(&map, &BuildOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        let options = GameOptions { seed: 0x0201, ..GameOptions::default() };
        let seeded = SimGame::new(opened, options).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(cursors(&seeded), cursors(&e1m1()));
    }

    /// The player read out is the simulation's: its ammunition in our
    /// order (bullets, shells, rockets, cells), its weapons as actors.
    #[test]
    #[cfg_attr(freedoom_missing, ignore = "needs freedoom1.wad: apt-get install freedoom")]
    fn the_player_reads_out_in_map_units_and_our_order() {
        let mut game = e1m1();
        let console = game.sim.console;
        let p = game.sim.players[console].as_mut().unwrap();
        p.ammo = [10, 20, 30, 40];
        game.tick(&TickInput::default());
        let player = Observe::player(&game);
        assert_eq!(player.ammo, [10, 20, 40, 30], "Doom's cells are its third ammo, rockets its fourth");
        let pistol = &game.sim.info.table.actors[player.ready_weapon.expect("a weapon in hand")];
        assert_eq!(pistol.weapon.as_ref().map(|w| w.slot), Some(2));
        let m = game.sim.mo(game.sim.players[console].as_ref().unwrap().mo);
        assert_eq!(player.pos, DVec2::new(m.x.to_f64(), m.y.to_f64()));
        assert_eq!(player.health, 100);
    }
}

/// A UDMF map opened for a game: the WADs, the map's name, the converted
/// level (its sprites completed for what the scripts spawn) and its art.
struct ZdoomMap<'a> {
    wad: &'a crate::wad::Wad,
    name: &'a str,
    level: &'a mut Level,
    library: &'a crate::texture::Library,
}

/// A game on UDMF map `name` of `wad` (opened as `level`): the level built
/// from its compiled conversion with its things' ZDoom fields
/// ([`from_map::level_from_udmf`]), played by Sightline's rules as Doom II
/// 1.9, with its DECORATE actors on `table`, and its ACS scripts started
/// (their generator seeded from the game's seed).
fn zdoom_sim(
    map: ZdoomMap,
    options: &GameOptions,
    table: std::sync::Arc<ActorTable>,
    from: Option<&Sim>,
    setup: Setup,
) -> Result<(Sim, Option<Box<Scripts>>), String> {
    let ZdoomMap { wad, name, level, library } = map;
    let udmf = wad.udmf(name).map_err(|e| e.to_string())?;
    let records = udmf.to_records(name).map_err(|e| format!("{}: {name}: {e}", wad.path))?;
    let (table, _unread) = crate::scenario::actor_table(wad, &table)?;
    let sim_level =
        from_map::level_from_udmf(&level.compiled, &table, &udmf, &records.map).map_err(|e| e.to_string())?;
    let sim = sightline_game(sim_level, level, options, table, from, setup);
    let mut scripts = Scripts::load(wad, name, options.seed).map_err(|e| e.to_string())?.map(Box::new);
    if let Some(s) = scripts.as_mut() {
        s.begin(&sim);
    }
    // What the scripts may spawn by name, and the WAD's own actors, are
    // drawn too (the map's things alone brought the others' art in).
    let table = &sim.info.table;
    let named = scripts.iter().flat_map(|s| s.vm.module.strings.iter()).filter_map(|s| zdoom::find(table, s));
    let own = ActorTable::active().actors.len()..table.actors.len();
    level.materials.add_actor_views(table, named.chain(own).collect(), library);
    Ok((sim, scripts))
}

/// Raise-to-texture floors measure the converted map's own textures.
fn measure_textures(sim: &mut Sim, level: &Level) {
    let textures = &level.materials.textures;
    let heights = sim.level.names.iter().filter_map(|name| {
        let id = textures.find(name, crate::texture::TextureKind::Wall)?;
        Some((name.clone(), crate::fixed::Fixed::from_int(textures.get(id).height as i32)))
    });
    sim.spec.texture_heights = heights.collect();
}

/// Player 1's command alone (the others' as before).
fn first_player(cmd: Ticcmd) -> [Option<Ticcmd>; MAXPLAYERS] {
    let mut cmds = [None; MAXPLAYERS];
    cmds[0] = Some(cmd);
    cmds
}

/// How a game is set up beyond its skill: how many players, whether it is
/// deathmatch, and the server settings a ViZDoom scenario's `game_args`
/// give (`+sv_noautoaim 1`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Setup {
    pub players: usize,
    /// 0 co-operative, 1 deathmatch, 2 altdeath.
    pub deathmatch: u8,
    /// Players' shots and missiles go where they face (ZDoom's
    /// `sv_noautoaim`).
    pub no_autoaim: bool,
}

impl Setup {
    pub const SINGLE: Setup = Setup { players: 1, deathmatch: 0, no_autoaim: false };

    fn players(self) -> Players {
        Players::first(self.players)
    }

    fn rules(self, rules: Rules) -> Rules {
        let netgame = self.players > 1 || self.deathmatch != 0;
        Rules { deathmatch: self.deathmatch, netgame, no_autoaim: self.no_autoaim, ..rules }
    }
}

/// Doom's generator is one table read in turn: a seed moves `P_Random`'s
/// and `M_Random`'s cursors on from where the level's setup left them, so
/// a RON or ZDoom map's games differ by seed. (A Doom-format WAD's map does
/// not move them, as vanilla does not and its demos need.)
fn seed_random(sim: &mut Sim, seed: u64) {
    let [p, m, ..] = seed.to_le_bytes();
    let (p0, m0) = (sim.rng.p_index(), sim.rng.m_index());
    sim.rng = crate::fixed::DoomRandom::from_indices(p0.wrapping_add(p), m0.wrapping_add(m));
}

/// A game by Sightline's rules (as Doom II 1.9) on `sim_level`, built from
/// the converted map `level` (a RON map's or a UDMF map's): a new one with
/// its seed in Doom's table, or `from`'s going on there.
fn sightline_game(
    sim_level: super::Level,
    level: &Level,
    options: &GameOptions,
    table: std::sync::Arc<ActorTable>,
    from: Option<&Sim>,
    setup: Setup,
) -> Sim {
    let skill = options.skill.saturating_sub(1);
    let rules = setup.rules(Rules {
        compat: Compat::Sightline,
        no_monsters: options.no_monsters,
        ..Rules::single(skill, super::GameVersion::Doom19, super::GameMode::Commercial)
    });
    let mut sim = match from {
        Some(from) => from.next_level(sim_level, |_| {}),
        None => {
            let mut sim = from_map::sim_on_map(sim_level, rules, setup.players(), table);
            seed_random(&mut sim, options.seed);
            sim
        }
    };
    measure_textures(&mut sim, level);
    sim
}
