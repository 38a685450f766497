//! Bodies (`mobj_t`) and their life: spawning (`P_SpawnMobj`), state
//! changes (`P_SetMobjState`, running each state's action), removal
//! (`P_RemoveMobj`), and the links that place a body in its subsector and
//! blockmap cell (`P_SetThingPosition`, `P_UnsetThingPosition`). How a body
//! moves is `movement.rs`; what touches what is `collision.rs`.

use super::level::{Level, MAPBLOCKSHIFT, NF_SUBSECTOR};
use super::{MobjId, Sim, ThinkerKind};
use crate::actors::StateId;
use crate::fixed::{point_on_node_side, Angle, Divline, Fixed};
use crate::wad::level::WadThing;

/// Doom's `MF_*` bits (`p_mobj.h`).
pub mod mf {
    pub const SPECIAL: u32 = 0x1;
    pub const SOLID: u32 = 0x2;
    pub const SHOOTABLE: u32 = 0x4;
    pub const NOSECTOR: u32 = 0x8;
    pub const NOBLOCKMAP: u32 = 0x10;
    pub const AMBUSH: u32 = 0x20;
    pub const JUSTHIT: u32 = 0x40;
    pub const JUSTATTACKED: u32 = 0x80;
    pub const SPAWNCEILING: u32 = 0x100;
    pub const NOGRAVITY: u32 = 0x200;
    pub const DROPOFF: u32 = 0x400;
    pub const PICKUP: u32 = 0x800;
    pub const NOCLIP: u32 = 0x1000;
    pub const SLIDE: u32 = 0x2000;
    pub const FLOAT: u32 = 0x4000;
    pub const TELEPORT: u32 = 0x8000;
    pub const MISSILE: u32 = 0x10000;
    pub const DROPPED: u32 = 0x20000;
    pub const SHADOW: u32 = 0x40000;
    pub const NOBLOOD: u32 = 0x80000;
    pub const CORPSE: u32 = 0x100000;
    pub const INFLOAT: u32 = 0x200000;
    pub const COUNTKILL: u32 = 0x400000;
    pub const COUNTITEM: u32 = 0x800000;
    pub const SKULLFLY: u32 = 0x1000000;
    pub const NOTDMATCH: u32 = 0x2000000;
    /// The player colour: Doom's two bits (players 2 to 4: indigo, brown,
    /// red), widened to four for sixteen players. Doom never sets the two
    /// above them (28 and 29), so its bodies' flags are unchanged.
    pub const TRANSLATION: u32 = 0x3c00_0000;
    pub const TRANSSHIFT: u32 = 26;
}

/// `ONFLOORZ` and `ONCEILINGZ`: spawn heights that mean "on the floor" and
/// "hanging from the ceiling".
pub const ONFLOORZ: Fixed = Fixed::MIN;
pub const ONCEILINGZ: Fixed = Fixed::MAX;

/// A body (`mobj_t`), without Doom's list pointers: its place in the
/// thinker list is [`Mobj::thinker`], its blockmap cell [`Mobj::block`].
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Mobj {
    pub x: Fixed,
    pub y: Fixed,
    pub z: Fixed,
    pub angle: Angle,
    /// Doom's sprite number and frame (with the full-bright bit).
    pub sprite: i32,
    pub frame: i32,
    /// The subsector it stands in.
    pub subsector: usize,
    pub floorz: Fixed,
    pub ceilingz: Fixed,
    pub radius: Fixed,
    pub height: Fixed,
    pub momx: Fixed,
    pub momy: Fixed,
    pub momz: Fixed,
    /// Its kind: an index into the actor table ([`super::Info::things`]).
    pub kind: usize,
    pub tics: i32,
    /// `None` once removed (`S_NULL`).
    pub state: Option<StateId>,
    pub flags: u32,
    pub health: i32,
    /// 0-7 a direction (`dirtype_t`), 8 none.
    pub movedir: i32,
    pub movecount: i32,
    pub target: Option<MobjId>,
    pub reactiontime: i32,
    pub threshold: i32,
    /// The player number, when this is a player's body.
    pub player: Option<usize>,
    pub lastlook: i32,
    pub spawnpoint: WadThing,
    pub tracer: Option<MobjId>,
    /// Its thinker.
    pub thinker: super::ThinkerId,
    /// The blockmap cell it is linked in, if any.
    pub block: Option<usize>,
    /// Removed from the game (its thinker is gone).
    pub removed: bool,
}

impl Mobj {
    pub fn has(&self, flag: u32) -> bool {
        self.flags & flag != 0
    }
}

/// `R_PointInSubsector`: the subsector holding a point, down the WAD's nodes.
pub fn point_in_subsector(level: &Level, x: Fixed, y: Fixed) -> usize {
    if level.nodes.is_empty() {
        return 0;
    }
    let mut n = level.nodes.len() - 1;
    loop {
        let node = &level.nodes[n];
        let div = Divline { x: node.x, y: node.y, dx: node.dx, dy: node.dy };
        let child = node.children[point_on_node_side(x, y, &div).index()];
        if child & NF_SUBSECTOR != 0 {
            return usize::from(child & !NF_SUBSECTOR);
        }
        n = usize::from(child);
    }
}

impl Sim {
    /// The sector of the subsector a body stands in.
    pub fn sector_of(&self, id: MobjId) -> usize {
        self.level.subsectors[self.mo(id).subsector].sector
    }

    /// `P_SpawnMobj`: a body of `kind` at `x`, `y` and `z` (or
    /// [`ONFLOORZ`], [`ONCEILINGZ`]), in its spawn state (whose action does
    /// not run), linked into the world and appended to the thinkers. Spends
    /// one `P_Random` on `lastlook`, as every spawn does.
    pub fn spawn_mobj(&mut self, x: Fixed, y: Fixed, z: Fixed, kind: usize) -> MobjId {
        let info = &self.info.things[kind];
        let id = MobjId(self.mobjs.len() as u32);
        let reactiontime = if self.rules.skill != super::Rules::NIGHTMARE { info.reactiontime } else { 0 };
        let (spawnstate, radius, height, flags, health) =
            (info.spawnstate, info.radius, info.height, info.flags, info.spawnhealth);
        let lastlook = self.p_random() % self.slots() as i32;
        let (sprite, frame, tics) = match spawnstate {
            Some(s) => {
                let st = self.info.state(s);
                (st.sprite, st.frame, st.tics)
            }
            None => (0, 0, -1),
        };
        let thinker = self.add_thinker(ThinkerKind::Mobj(id));
        self.mobjs.push(Mobj {
            x,
            y,
            z: Fixed::ZERO,
            angle: Angle::ZERO,
            sprite,
            frame,
            subsector: 0,
            floorz: Fixed::ZERO,
            ceilingz: Fixed::ZERO,
            radius,
            height,
            momx: Fixed::ZERO,
            momy: Fixed::ZERO,
            momz: Fixed::ZERO,
            kind,
            tics,
            state: spawnstate,
            flags,
            health,
            movedir: 0,
            movecount: 0,
            target: None,
            reactiontime,
            threshold: 0,
            player: None,
            lastlook,
            spawnpoint: WadThing { x: 0, y: 0, angle: 0, kind: 0, flags: 0 },
            tracer: None,
            thinker,
            block: None,
            removed: false,
        });
        self.set_thing_position(id);
        let sector = &self.level.sectors[self.sector_of(id)];
        let (floor, ceiling) = (sector.floorheight, sector.ceilingheight);
        let mo = self.mo_mut(id);
        mo.floorz = floor;
        mo.ceilingz = ceiling;
        mo.z = if z == ONFLOORZ {
            floor
        } else if z == ONCEILINGZ {
            ceiling - height
        } else {
            z
        };
        id
    }

    /// `P_SetMobjState`: enters `state`, running its action, and goes on
    /// through states of zero tics. `None` (or a state whose next is
    /// `S_NULL` reached this way) removes the body; returns whether it is
    /// still in the game.
    pub fn set_mobj_state(&mut self, id: MobjId, mut state: Option<StateId>) -> bool {
        loop {
            let Some(s) = state else {
                self.mo_mut(id).state = None;
                self.remove_mobj(id);
                return false;
            };
            let st = self.info.state(s);
            let (sprite, frame, tics, next) = (st.sprite, st.frame, st.tics, st.next);
            let action = st.action.clone();
            let mo = self.mo_mut(id);
            mo.state = Some(s);
            mo.tics = tics;
            mo.sprite = sprite;
            mo.frame = frame;
            if let Some(call) = action {
                super::actions::call_mobj(self, id, &call);
            }
            state = next;
            if self.mo(id).tics != 0 {
                return true;
            }
        }
    }

    /// `P_RemoveMobj`: an item that can come back goes on the respawn
    /// queue; the body leaves the blockmap and its thinker is removed.
    pub fn remove_mobj(&mut self, id: MobjId) {
        let mo = self.mo(id);
        if mo.removed {
            return;
        }
        let mt = self.info.things[mo.kind].mt;
        if mo.has(mf::SPECIAL)
            && !mo.has(mf::DROPPED)
            && mt != Some(super::info::mt::INV)
            && mt != Some(super::info::mt::INS)
        {
            self.item_respawn.push((mo.spawnpoint.clone(), self.leveltime));
            // Doom's queue holds 128 (ITEMQUESIZE); the oldest is dropped.
            if self.item_respawn.len() > 127 {
                self.item_respawn.remove(0);
            }
        }
        self.unset_thing_position(id);
        let thinker = self.mo(id).thinker;
        self.remove_thinker(thinker);
        self.mo_mut(id).removed = true;
    }

    /// `P_SetThingPosition`: finds the subsector, and links the body into
    /// its blockmap cell unless it has `MF_NOBLOCKMAP` (or stands outside
    /// the blockmap).
    pub fn set_thing_position(&mut self, id: MobjId) {
        let (x, y) = (self.mo(id).x, self.mo(id).y);
        let subsector = point_in_subsector(&self.level, x, y);
        let bm = &self.level.blockmap;
        let block = if self.mo(id).has(mf::NOBLOCKMAP) {
            None
        } else {
            let bx = (x - bm.orgx).0 >> MAPBLOCKSHIFT;
            let by = (y - bm.orgy).0 >> MAPBLOCKSHIFT;
            (bx >= 0 && by >= 0 && bx < bm.width && by < bm.height).then(|| (by * bm.width + bx) as usize)
        };
        if let Some(b) = block {
            self.blocklinks[b].push(id);
        }
        let mo = self.mo_mut(id);
        mo.subsector = subsector;
        mo.block = block;
    }

    /// `P_UnsetThingPosition`: unlinks the body from its blockmap cell.
    pub fn unset_thing_position(&mut self, id: MobjId) {
        if let Some(b) = self.mo_mut(id).block.take() {
            let cell = &mut self.blocklinks[b];
            if let Some(at) = cell.iter().rposition(|&m| m == id) {
                cell.remove(at);
            }
        }
    }

    /// The body's kind's Doom `mobjtype_t`, if it is one of Doom's.
    pub fn mt(&self, id: MobjId) -> Option<usize> {
        self.info.things[self.mo(id).kind].mt
    }

    /// Whether the body is Doom's kind `mt`.
    pub fn is(&self, id: MobjId, mt: usize) -> bool {
        self.mt(id) == Some(mt)
    }

    /// The actor index of Doom's kind `mt`, for spawning it. The shipped
    /// table has all of Doom's kinds; a modder's table missing one makes
    /// this fall back to the player's kind (0), never panic.
    pub fn kind_of(&self, mt: usize) -> usize {
        self.info.actor_of(mt).unwrap_or(0)
    }
}
