//! Where players come into a level (`P_SpawnPlayer` and the spots
//! `g_game.c` picks with `G_CheckSpot`): each player's own start, a
//! deathmatch start, a reborn player's spot in a net game, and a spot for
//! a player the map has no start for (the fifth of sixteen players on a
//! map made for four). It hands the next stage a player's body linked into
//! the level with its weapon coming up (`weapons::setup_psprites`).
//!
//! Doom's maps have four player starts (types 1 to 4) and any number of
//! deathmatch starts (type 11, of which vanilla keeps ten); ZDoom adds
//! types 4001 to 4004 for players 5 to 8. A player without a start of its
//! own takes the first free start of the other players' and then the
//! deathmatch starts (deathmatch starts first in deathmatch), where GZDoom's
//! `PickPlayerStart` takes a random free one from another generator: the
//! choice here spends no `P_Random`. When none is free it is put beside
//! the first of them, in the nearest place its body fits and could walk to
//! ([`Sim::step_aside`]), where GZDoom leaves it on a taken start ("the
//! player will probably get stuck") or telefrags what is there.

use super::info::mt;
use super::level::ml;
use super::maputl::{self, Hit, PT_ADDLINES};
use super::mobj::{mf, ONFLOORZ};
use super::setup::{thing_angle, VIEWHEIGHT};
use super::{collision, MobjId, Player, PlayerState, Sim, VANILLA_PLAYERS};
use crate::fixed::{Fixed, FRACUNIT};
use crate::wad::level::WadThing;

/// ZDoom's editor numbers for the starts of players 5 to 8.
const ZDOOM_STARTS: std::ops::RangeInclusive<u16> = 4001..=4004;
/// Deathmatch starts vanilla keeps (`deathmatchstarts[10]`).
const VANILLA_DEATHMATCH_STARTS: usize = 10;
/// Random deathmatch starts tried before giving up
/// (`G_DeathMatchSpawnPlayer`).
const DEATHMATCH_TRIES: usize = 20;
/// How far apart the places tried beside a taken start are, in map units:
/// more than a player's width (two radii of 16), so bodies put in
/// neighbouring places never touch (Doom's bodies collide as boxes).
const BESIDE_STEP: i32 = 40;
/// Square rings of places tried around a taken start: 48 places, within
/// 120 units on each axis.
const BESIDE_RINGS: i32 = 3;
/// The highest step a player climbs (`P_TryMove`'s 24 units).
const STEP: Fixed = Fixed(24 * FRACUNIT);

/// The player a start of editor number `kind` is for: Doom's 1 to 4 are
/// players 0 to 3, ZDoom's 4001 to 4004 players 4 to 7.
pub fn start_player(kind: u16) -> Option<usize> {
    match kind {
        1..=4 => Some(usize::from(kind - 1)),
        k if ZDOOM_STARTS.contains(&k) => Some(usize::from(k - ZDOOM_STARTS.start()) + VANILLA_PLAYERS),
        _ => None,
    }
}

impl Sim {
    /// `P_SpawnMapThing` on player `n`'s start: kept for rebirth (with
    /// Doom's type, the player's number plus one, which `playerstarts`
    /// holds and [`Sim::spawn_player`] reads), and in co-op the player's
    /// body spawned there (if the player is in the game).
    pub(super) fn player_start(&mut self, n: usize, thing: &WadThing) {
        let start = WadThing { kind: n as u16 + 1, ..thing.clone() };
        self.starts[n] = Some(start.clone());
        if self.rules.deathmatch == 0 {
            self.spawn_player(&start);
        }
    }

    /// `P_SpawnMapThing` on a deathmatch start: vanilla keeps ten, a game
    /// past Doom's four slots every one (as GZDoom does), so sixteen
    /// players find sixteen starts where the map has them.
    pub(super) fn deathmatch_start(&mut self, thing: &WadThing) {
        if self.slots() > VANILLA_PLAYERS || self.deathmatch_starts.len() < VANILLA_DEATHMATCH_STARTS {
            self.deathmatch_starts.push(thing.clone());
        }
    }

    /// `P_SpawnPlayer`: player `thing.kind - 1`'s body at its start, in
    /// the colour of its number (Doom's translation bits, see
    /// [`mf::TRANSLATION`]).
    pub fn spawn_player(&mut self, thing: &WadThing) {
        let n = usize::from(thing.kind.saturating_sub(1));
        let Some(player) = self.players.get(n).and_then(Option::as_ref) else {
            return;
        };
        if player.playerstate == PlayerState::Reborn {
            let kept = (player.killcount, player.itemcount, player.secretcount);
            let frags = player.frags;
            self.players[n] = Some(Player::reborn(&self.info, frags, kept));
        }
        let kind = self.kind_of(mt::PLAYER);
        let id = self.spawn_mobj(Fixed::from_int(thing.x.into()), Fixed::from_int(thing.y.into()), ONFLOORZ, kind);
        let health = self.players[n].as_ref().map_or(100, |p| p.health);
        let mo = self.mo_mut(id);
        if thing.kind > 1 {
            mo.flags |= u32::from(thing.kind - 1) << mf::TRANSSHIFT;
        }
        mo.angle = thing_angle(thing);
        mo.player = Some(n);
        mo.health = health;
        let deathmatch = self.rules.deathmatch != 0;
        if let Some(p) = self.players[n].as_mut() {
            p.mo = id;
            p.playerstate = PlayerState::Live;
            p.refire = 0;
            p.message = None;
            p.damagecount = 0;
            p.bonuscount = 0;
            p.extralight = 0;
            p.fixedcolormap = 0;
            p.viewheight = VIEWHEIGHT;
            if deathmatch {
                p.cards = [true; super::NUMCARDS];
            }
        }
        super::weapons::setup_psprites(self, n);
    }

    /// `G_DoReborn` in a netgame: player `n`'s body is left as a corpse
    /// and a new one spawns at a deathmatch start (deathmatch), else at
    /// the player's own start if it is clear, else at the first other
    /// player's start that is, else at its own start anyway; a player
    /// without a start of its own as [`Sim::spawn_without_start`] puts it.
    pub fn respawn_in_netgame(&mut self, n: usize) {
        let Some(body) = self.players[n].as_ref().map(|p| p.mo) else { return };
        self.mo_mut(body).player = None;
        if self.rules.deathmatch != 0 {
            self.deathmatch_respawn_player(n, Some(body));
            return;
        }
        let own = self.starts[n].clone();
        let others = (0..self.slots()).filter_map(|i| self.starts[i].clone());
        for spot in own.iter().cloned().chain(others.collect::<Vec<_>>()) {
            if collision::check_spot(self, n, Some(body), &spot) {
                // Another's start, taken as this player's.
                self.spawn_player(&WadThing { kind: n as u16 + 1, ..spot });
                return;
            }
        }
        match own {
            Some(start) => self.spawn_player(&start),
            None => self.spawn_without_start(n, Some(body)),
        }
    }

    /// `G_DeathMatchSpawnPlayer`: up to 20 random deathmatch starts (a
    /// `P_Random` each) until one is clear (`G_CheckSpot`, which also
    /// queues the old body and spawns the fog), else the player's own start.
    /// Vanilla refuses a map with fewer than four deathmatch starts; here
    /// any number plays. At a level's start the player has no old body.
    pub fn deathmatch_spawn_player(&mut self, n: usize) {
        self.deathmatch_respawn_player(n, None);
    }

    /// [`Self::deathmatch_spawn_player`] for a player whose old body is
    /// `body` (a respawn: the body is queued as a corpse). A player without
    /// a start of its own goes where [`Sim::spawn_without_start`] puts it.
    pub fn deathmatch_respawn_player(&mut self, n: usize, body: Option<MobjId>) {
        let selections = self.deathmatch_starts.len();
        if selections > 0 {
            for _ in 0..DEATHMATCH_TRIES {
                let i = self.p_random() as usize % selections;
                let spot = self.deathmatch_starts[i].clone();
                if collision::check_spot(self, n, body, &spot) {
                    // Doom writes the player's number into the start itself.
                    self.deathmatch_starts[i].kind = n as u16 + 1;
                    let spot = self.deathmatch_starts[i].clone();
                    self.spawn_player(&spot);
                    return;
                }
            }
        }
        match self.starts[n].clone() {
            Some(start) => self.spawn_player(&start),
            None => self.spawn_without_start(n, body),
        }
    }

    /// Player `n`, whose old body is `body` (`None` at a level's start),
    /// has no start of its own on this map: it spawns at the first clear
    /// start (`G_CheckSpot` deciding, as for any spot) of the players'
    /// then the deathmatch starts, or in deathmatch the other way round;
    /// if none is clear, at the first of them, stepped aside
    /// ([`Sim::step_aside`]). On a map with no start of either kind it
    /// does not spawn (no map the importer or the validator passes).
    pub fn spawn_without_start(&mut self, n: usize, body: Option<MobjId>) {
        let players = self.starts.iter().flatten();
        let deathmatch = self.deathmatch_starts.iter();
        let spots: Vec<WadThing> = match self.rules.deathmatch {
            0 => players.chain(deathmatch).cloned().collect(),
            _ => deathmatch.chain(players).cloned().collect(),
        };
        let as_own = |spot: &WadThing| WadThing { kind: n as u16 + 1, ..spot.clone() };
        for spot in &spots {
            if collision::check_spot(self, n, body, spot) {
                self.spawn_player(&as_own(spot));
                return;
            }
        }
        let Some(first) = spots.first() else { return };
        self.spawn_player(&as_own(first));
        if let Some(mo) = self.player(n).map(|p| p.mo) {
            self.step_aside(mo);
        }
    }

    /// Moves `body`, just spawned on a taken spot, to the nearest place
    /// where it fits ([`Sim::fits`]), trying places [`BESIDE_STEP`] units
    /// apart on square rings around the spot, nearest ring first; it stays
    /// where it is if it fits there or no place does. The search picks
    /// nothing up and leaves `p_map.c`'s globals as they were.
    fn step_aside(&mut self, body: MobjId) {
        let saved = self.tm.clone();
        let flags = self.mo(body).flags;
        self.mo_mut(body).flags &= !mf::PICKUP;
        let from = (self.mo(body).x, self.mo(body).y);
        let ring = |r: i32| {
            let side = -r..=r;
            side.clone()
                .flat_map(move |dx| side.clone().map(move |dy| (dx, dy)))
                .filter(move |&(dx, dy)| dx.abs().max(dy.abs()) == r)
        };
        let places = (1..=BESIDE_RINGS).flat_map(ring).map(|(dx, dy)| {
            let step = |d: i32| Fixed::from_int(d * BESIDE_STEP);
            (from.0 + step(dx), from.1 + step(dy))
        });
        if !self.fits(body, from, from) {
            let places: Vec<(Fixed, Fixed)> = places.collect();
            if let Some(&(x, y)) = places.iter().find(|&&to| self.fits(body, from, to)) {
                collision::check_position(self, body, x, y);
                self.unset_thing_position(body);
                let (floorz, ceilingz) = (self.tm.floorz, self.tm.ceilingz);
                let mo = self.mo_mut(body);
                (mo.x, mo.y, mo.floorz, mo.ceilingz, mo.z) = (x, y, floorz, ceilingz, floorz);
                self.set_thing_position(body);
            }
        }
        self.mo_mut(body).flags = flags;
        self.tm = saved;
    }

    /// Whether `body`, standing at `from`, fits at `to` and could walk
    /// there in a straight line: nothing solid and no line in its way
    /// there (`P_CheckPosition`), room for its height, a floor at most a
    /// step above its own, and every line between two-sided, not blocking,
    /// with room to pass and at most a step up. So a place beyond a wall,
    /// in another room or outside the map, never fits.
    fn fits(&mut self, body: MobjId, from: (Fixed, Fixed), to: (Fixed, Fixed)) -> bool {
        let (height, floor) = (self.mo(body).height, self.mo(body).floorz);
        if !collision::check_position(self, body, to.0, to.1) {
            return false;
        }
        if self.tm.ceilingz - self.tm.floorz < height || self.tm.floorz - floor > STEP {
            return false;
        }
        if from == to {
            return true;
        }
        maputl::path_traverse(self, from.0, from.1, to.0, to.1, PT_ADDLINES, |sim, intercept, _| {
            let Hit::Line(line) = intercept.hit else { return true };
            if sim.level.lines.get(line).is_none_or(|l| l.flags & ml::BLOCKING != 0) {
                return false;
            }
            maputl::line_opening(sim, line);
            let o = sim.tm.opening;
            o.range >= height && o.bottom - floor <= STEP
        })
    }
}
