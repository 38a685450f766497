//! The game's state after a tic in the reference dumps' terms
//! (`tests/fixtures/demo-dumps/README.md`): `P_Random`'s index, each
//! player's body and tallies, a hash of every body in thinker order and one
//! of every sector, as the patched Chocolate Doom prints them.

use super::Sim;
use crate::play::syncdump::{Fnv, PlayerState, TicState};

/// Kinds that are not Doom's hash as this number plus their actor index.
const NOT_DOOM: i32 = 10_000;

impl Sim {
    /// The state after the tic just run (the dump's line for it: Doom's
    /// `gametic` before its increment, `leveltime` after).
    pub fn tic_state(&self) -> TicState {
        // The dumps are Doom's: its four players.
        let mut players = [None; super::VANILLA_PLAYERS];
        for (n, p) in self.players.iter().enumerate().take(super::VANILLA_PLAYERS) {
            if let Some(p) = p {
                let mo = self.mo(p.mo);
                players[n] = Some(PlayerState {
                    x: mo.x.0,
                    y: mo.y.0,
                    z: mo.z.0,
                    angle: mo.angle.0,
                    momx: mo.momx.0,
                    momy: mo.momy.0,
                    health: p.health,
                    armor: p.armorpoints,
                    ammo: p.ammo,
                });
            }
        }
        let mut mobjs = Fnv::default();
        let mut count = 0;
        for id in self.live_mobjs() {
            let m = self.mo(id);
            let kind = self.info.things[m.kind].mt.map_or(NOT_DOOM + m.kind as i32, |t| t as i32);
            for v in [
                m.x.0,
                m.y.0,
                m.z.0,
                m.angle.0 as i32,
                m.momx.0,
                m.momy.0,
                m.momz.0,
                kind,
                m.sprite,
                m.frame,
                m.tics,
                m.health,
                m.flags as i32,
            ] {
                mobjs.int(v);
            }
            count += 1;
        }
        let mut sectors = Fnv::default();
        for s in &self.level.sectors {
            for v in [s.floorheight.0, s.ceilingheight.0, s.lightlevel.into(), s.special.into()] {
                sectors.int(v);
            }
        }
        TicState {
            gametic: self.gametic.saturating_sub(1),
            leveltime: Some(self.leveltime),
            rnd: Some(self.rng.p_index()),
            players,
            mobjs: Some((count, mobjs.0)),
            sectors: Some(sectors.0),
        }
    }
}
