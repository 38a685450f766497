//! The thinker list (`p_tick.c`): every body and every moving sector or
//! light runs once a tic, in the order it was added. A thinker added during
//! a tic runs in that same tic when the walk reaches it; one removed is
//! passed over from then on (Doom marks it and frees it when the walk
//! passes). A plat or ceiling put "in stasis" stays in the list but does
//! not run. Indices never move within a level, so a sector's
//! `specialdata` and a plat list can hold a [`ThinkerId`].

use super::{ceilings, doors, floors, lights, movement, plats, MobjId, Sim, ThinkerId};

/// What a thinker is, with its data.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum ThinkerKind {
    Mobj(MobjId),
    Door(doors::Door),
    Plat(plats::Plat),
    Floor(floors::FloorMove),
    Ceiling(ceilings::Ceiling),
    Light(lights::Light),
}

/// Whether a thinker runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Status {
    Active,
    /// In the list, not run (Doom's NULL function: a plat or crusher in
    /// stasis).
    Stasis,
    /// Removed (Doom's -1 function).
    Removed,
}

#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Thinker {
    pub kind: ThinkerKind,
    pub status: Status,
}

impl Sim {
    /// `P_AddThinker`: appended, so it runs after every thinker already there.
    pub fn add_thinker(&mut self, kind: ThinkerKind) -> ThinkerId {
        self.thinkers.push(Thinker { kind, status: Status::Active });
        ThinkerId(self.thinkers.len() as u32 - 1)
    }

    /// `P_RemoveThinker`.
    pub fn remove_thinker(&mut self, id: ThinkerId) {
        self.thinkers[id.0 as usize].status = Status::Removed;
    }

    pub fn thinker(&self, id: ThinkerId) -> &Thinker {
        &self.thinkers[id.0 as usize]
    }

    pub fn thinker_mut(&mut self, id: ThinkerId) -> &mut Thinker {
        &mut self.thinkers[id.0 as usize]
    }

    /// The bodies in the game, in thinker order.
    pub fn live_mobjs(&self) -> impl Iterator<Item = MobjId> + '_ {
        self.thinkers.iter().filter_map(|t| match (&t.kind, t.status) {
            (ThinkerKind::Mobj(id), Status::Active) => Some(*id),
            _ => None,
        })
    }
}

/// `P_RunThinkers`: each active thinker's function, in order; the list may
/// grow while it runs.
pub fn run_thinkers(sim: &mut Sim) {
    let mut i = 0;
    while i < sim.thinkers.len() {
        let t = &sim.thinkers[i];
        if t.status == Status::Active {
            let id = ThinkerId(i as u32);
            match &t.kind {
                ThinkerKind::Mobj(mobj) => movement::mobj_thinker(sim, *mobj),
                ThinkerKind::Door(_) => doors::think(sim, id),
                ThinkerKind::Plat(_) => plats::think(sim, id),
                ThinkerKind::Floor(_) => floors::think(sim, id),
                ThinkerKind::Ceiling(_) => ceilings::think(sim, id),
                ThinkerKind::Light(_) => lights::think(sim, id),
            }
        }
        i += 1;
    }
}
