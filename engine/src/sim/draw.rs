//! The simulation drawn by the renderer: its sectors' heights and light
//! and its bodies written into the converted map the renderer draws (a WAD
//! map opened through `campaign::open`, whose sectors the importer
//! renumbered: [`crate::campaign::Opened::sector_map`] says where each of
//! the WAD's went), and the console player's view. Positions are the
//! fixed-point values divided out, so the frame shows exactly the state
//! the simulation holds.

use glam::DVec2;

use super::Sim;
use crate::level::{DrawnThing, Level};
use crate::materials::Materials;
use crate::render::View;

/// How the simulation's numbering maps onto a converted map.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The converted map's sector for each of the WAD's sectors.
    sectors: Vec<Option<usize>>,
}

impl Scene {
    pub fn new(sector_map: Vec<Option<usize>>) -> Scene {
        Scene { sectors: sector_map }
    }

    /// The converted map's sector of the WAD's sector `s`.
    pub fn sector(&self, s: usize) -> Option<usize> {
        self.sectors.get(s).copied().flatten()
    }

    /// Writes the simulation's sector heights and light and its bodies
    /// (all but the viewing player's own) into `level`.
    pub fn draw(&self, sim: &Sim, level: &mut Level) {
        for (i, s) in sim.level.sectors.iter().enumerate() {
            let Some(j) = self.sector(i) else { continue };
            let Some(out) = level.compiled.map.sectors.get_mut(j) else { continue };
            out.floor = s.floorheight.to_f64();
            out.ceiling = s.ceilingheight.to_f64();
            out.light = s.lightlevel.clamp(0, 255) as u8;
        }
        let viewer = sim.player(sim.console).map(|p| p.mo);
        let table = &sim.info.table;
        let things = sim.live_mobjs().filter(|&id| Some(id) != viewer).filter_map(|id| {
            let m = sim.mo(id);
            let state = table.state(m.state?);
            let views =
                level.materials.sprite_views.get(Materials::view_index(state.sprite, state.frame)).copied()??;
            let sector = self.sector(sim.level.subsectors[m.subsector].sector)?;
            Some(DrawnThing {
                key: id.0 as usize,
                pos: DVec2::new(m.x.to_f64(), m.y.to_f64()),
                z: m.z.to_f64(),
                sector,
                angle: m.angle.to_degrees(),
                views,
                bright: m.frame & super::info::FF_FULLBRIGHT != 0,
                fuzz: m.has(super::mobj::mf::SHADOW),
            })
        });
        level.things = things.collect();
        level.time = u64::from(sim.leveltime);
    }

    /// The console player's eye (`viewz`, or the body's height plus the
    /// view height before the first tic has set it).
    pub fn view(&self, sim: &Sim) -> Option<View> {
        let p = sim.player(sim.console)?;
        let m = sim.mo(p.mo);
        let z = if p.viewz.0 != 0 { p.viewz } else { m.z + p.viewheight };
        Some(View::new(DVec2::new(m.x.to_f64(), m.y.to_f64()), z.to_f64(), m.angle.to_degrees()))
    }
}
