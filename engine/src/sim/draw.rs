//! The simulation drawn by the renderer: its sectors' heights, light and
//! flats, its switches' textures and its bodies written into the converted
//! map the renderer draws (a WAD map opened through `campaign::open`, whose
//! sectors and lines the importer renumbered, merged or left out:
//! [`Links`] says where each of the WAD's went; a RON map's numbering is
//! the simulation's own), and the console player's view. Positions are the
//! fixed-point values divided out, so the frame shows exactly the state
//! the simulation holds.

use glam::DVec2;

use super::level::NameId;
use super::mobj::mf;
use super::{MobjId, Sim};
use crate::level::{DrawnThing, Level};
use crate::materials::Materials;
use crate::render::View;
use crate::texture::{TextureId, TextureKind};
use crate::wad::import::Links;

/// How the simulation's numbering maps onto a converted map, and the
/// textures last written (only changes are looked up again).
#[derive(Clone, Debug)]
pub struct Scene {
    links: Links,
    /// Per converted line, its front side's texture names as last drawn.
    sides: Vec<[NameId; 3]>,
    /// Per WAD sector, its flats as last drawn.
    flats: Vec<[NameId; 2]>,
    /// [`Sim::textures_changed`] when they were last looked at.
    changes: Option<u32>,
}

impl Scene {
    /// A scene on a converted WAD map.
    pub fn new(links: Links) -> Scene {
        Scene { links, sides: Vec::new(), flats: Vec::new(), changes: None }
    }

    /// How the simulation's level maps onto the converted one.
    pub fn links(&self) -> &Links {
        &self.links
    }

    /// A scene on a map the simulation numbers as the renderer does (a RON
    /// map through `from_map`): sectors and lines are their own, and its
    /// trigger lines follow its lines.
    pub fn identity(map: &crate::map::Map) -> Scene {
        let lines = map.lines.len();
        Scene::new(Links {
            sectors: (0..map.sectors.len()).map(Some).collect(),
            lines: (0..lines).map(|l| vec![l]).collect(),
            triggers: (lines..lines + map.trigger_lines.len()).collect(),
        })
    }

    /// Makes the next draw look at every texture (the simulation was
    /// replaced, by a loaded game, and its change count with it).
    pub fn look_again(&mut self) {
        self.changes = None;
    }

    /// The converted map's sector of the WAD's sector `s`.
    pub fn sector(&self, s: usize) -> Option<usize> {
        self.links.sectors.get(s).copied().flatten()
    }

    /// The WAD's linedef behind the converted map's line `line` (the first,
    /// when several were merged into it: the one whose front side shows).
    pub fn linedef(&self, line: usize) -> Option<usize> {
        self.linedefs(line).first().copied()
    }

    /// Every WAD linedef merged into the converted map's line `line` (the
    /// line's special is whichever of them had one).
    pub fn linedefs(&self, line: usize) -> &[usize] {
        self.links.lines.get(line).map_or(&[], Vec::as_slice)
    }

    /// The WAD's linedef behind trigger line `t`.
    pub fn trigger_linedef(&self, t: usize) -> Option<usize> {
        self.links.triggers.get(t).copied()
    }

    /// The converted map's line (or trigger line, `Err`) a WAD linedef became.
    pub fn line_of_linedef(&self, linedef: usize) -> Option<Result<usize, usize>> {
        if let Some(l) = self.links.lines.iter().position(|d| d.contains(&linedef)) {
            return Some(Ok(l));
        }
        self.links.triggers.iter().position(|&d| d == linedef).map(Err)
    }

    /// Writes the simulation's sector heights, light and flats, the
    /// switches' textures and its bodies (all but the viewing player's own)
    /// into `level`.
    pub fn draw(&mut self, sim: &Sim, level: &mut Level) {
        for (i, s) in sim.level.sectors.iter().enumerate() {
            let Some(j) = self.sector(i) else { continue };
            let Some(out) = level.compiled.map.sectors.get_mut(j) else { continue };
            out.floor = s.floorheight.to_f64();
            out.ceiling = s.ceilingheight.to_f64();
            out.light = s.lightlevel.clamp(0, 255) as u8;
        }
        slide_grid_doors(level);
        self.draw_textures(sim, level);
        let viewer = sim.player(sim.console).map(|p| p.mo);
        let drawn = sim.live_mobjs().filter(|&id| Some(id) != viewer && !sim.invisible(id));
        let mut things = std::mem::take(&mut level.things);
        things.clear();
        let mut coloured = Vec::new();
        for id in drawn {
            let Some(thing) = self.drawn_thing(sim, level, id) else { continue };
            let colour = (sim.mo(id).flags & mf::TRANSLATION) >> mf::TRANSSHIFT;
            if colour != 0 {
                coloured.push((things.len(), colour as u8));
            }
            things.push(thing);
        }
        // Players 2 to 16 in their colours (`R_DrawTranslatedColumn`).
        for (k, colour) in coloured {
            things[k].views = things[k].views.map(|v| level.materials.in_colour(v, colour));
        }
        level.things = things;
        level.time = u64::from(sim.leveltime);
        // `P_UpdateSpecials` ran before the tic's `leveltime++`.
        level.materials.animate(u64::from(sim.leveltime.saturating_sub(1)));
    }

    /// Body `id` as the renderers draw it, if its state has a sprite the
    /// art has and it stands in a sector of the converted map.
    fn drawn_thing(&self, sim: &Sim, level: &Level, id: MobjId) -> Option<DrawnThing> {
        let m = sim.mo(id);
        let state = sim.info.table.state(m.state?);
        let views = level.materials.sprite_views.get(Materials::view_index(state.sprite, state.frame)).copied()??;
        let sector = self.sector(sim.level.subsectors[m.subsector].sector)?;
        Some(DrawnThing {
            key: id.0 as usize,
            pos: DVec2::new(m.x.to_f64(), m.y.to_f64()),
            z: m.z.to_f64(),
            sector,
            angle: m.angle.to_degrees(),
            views,
            bright: m.frame & super::info::FF_FULLBRIGHT != 0,
            fuzz: m.has(mf::SHADOW),
        })
    }

    /// The textures play changed (switches flipped, floors changed by a
    /// lift or a donut) written where they show; a name the renderer never
    /// loaded is left as it was. The first call only remembers; later ones
    /// look only when the simulation says a texture changed.
    fn draw_textures(&mut self, sim: &Sim, level: &mut Level) {
        if self.changes == Some(sim.textures_changed) {
            return;
        }
        self.changes = Some(sim.textures_changed);
        let front = |l: usize| {
            let s = sim.level.lines.get(l)?.sidenum[0]?;
            let s = sim.level.sides.get(s)?;
            Some([s.toptexture, s.midtexture, s.bottomtexture])
        };
        let first = self.sides.is_empty() && self.flats.is_empty();
        let sides: Vec<[NameId; 3]> =
            (0..self.links.lines.len()).map(|l| self.linedef(l).and_then(front).unwrap_or_default()).collect();
        let flats: Vec<[NameId; 2]> = sim.level.sectors.iter().map(|s| [s.floorpic, s.ceilingpic]).collect();
        if first {
            (self.sides, self.flats) = (sides, flats);
            return;
        }
        let find = |id: NameId, kind| level.materials.textures.find(sim.level.name(id), kind);
        let mut side_changes: Vec<(usize, usize, Option<TextureId>)> = Vec::new();
        for (l, (now, was)) in sides.iter().zip(&self.sides).enumerate() {
            for part in (0..3).filter(|&p| now[p] != was[p]) {
                if let Some(id) = find(now[part], TextureKind::Wall) {
                    side_changes.push((l, part, Some(id)));
                }
            }
        }
        let mut flat_changes: Vec<(usize, usize, TextureId)> = Vec::new();
        for (s, (now, was)) in flats.iter().zip(&self.flats).enumerate() {
            let Some(j) = self.sector(s) else { continue };
            for part in (0..2).filter(|&p| now[p] != was[p]) {
                if let Some(id) = find(now[part], TextureKind::Flat) {
                    flat_changes.push((j, part, id));
                }
            }
        }
        for (l, part, id) in side_changes {
            let Some(side) = level.materials.sides.get_mut(l) else { continue };
            let slot = [&mut side[0].upper, &mut side[0].middle, &mut side[0].lower];
            if let Some(slot) = slot.into_iter().nth(part) {
                *slot = id;
            }
        }
        for (j, part, id) in flat_changes {
            let Some(sector) = level.materials.sectors.get_mut(j) else { continue };
            if part == 0 {
                sector.floor = Some(id);
            } else {
                sector.ceiling = Some(id);
            }
        }
        (self.sides, self.flats) = (sides, flats);
    }

    /// The console player's eye (`viewz`, or the body's height plus the
    /// view height before the level's first tic has set it: `P_SetupLevel`
    /// leaves it at 1, a level gone on to at the last level's height).
    pub fn view(&self, sim: &Sim) -> Option<View> {
        let p = sim.player(sim.console)?;
        let m = sim.mo(p.mo);
        let z = if sim.leveltime > 0 { p.viewz } else { m.z + p.viewheight };
        Some(View::new(DVec2::new(m.x.to_f64(), m.y.to_f64()), z.to_f64(), m.angle.to_degrees()))
    }
}

/// A grid map's doors slide (Wolfenstein's): the simulation raises each as
/// a Doom door (to 4 below the grid's ceiling, its one neighbour's), and
/// the ray-caster draws the panel slid into its jamb by the share of that
/// rise. The sector's heights stay the simulation's (what the body meets,
/// and what the autopilot plans by). Door `k` is sector `k + 1`
/// (`grid::compile`'s numbering, checked).
fn slide_grid_doors(level: &mut Level) {
    let Some(full) = level.compiled.grid.as_ref().map(|g| g.ceiling) else { return };
    let Some(grid) = level.grid.as_mut() else { return };
    for (k, &cell) in grid.faces.doors.iter().enumerate() {
        let sector = k + 1;
        if grid.faces.door_sectors.get(cell).map(|&s| s as usize) != Some(sector) {
            continue;
        }
        let Some(s) = level.compiled.map.sectors.get(sector) else { continue };
        // Doom's doors stop 4 below the lowest ceiling around them.
        let rise = full - 4.0 - s.floor;
        let open = if rise > 0.0 { ((s.ceiling - s.floor) / rise).clamp(0.0, 1.0) } else { 1.0 };
        if let Some(o) = grid.open.get_mut(k) {
            *o = open;
        }
    }
}
