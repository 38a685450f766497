//! The world as ViZDoom's state lists it when asked (`objects_info_enabled`,
//! `sectors_info_enabled`): every body in the level with its place and
//! motion, and every sector with its heights and lines. Read from the
//! simulation's own level (Doom's sectors and linedefs in the WAD's order),
//! so ids and coordinates are the map's, in map units.

use crate::sim::game::SimGame;
use crate::sim::level::ml;
use crate::sim::mobj::mf;

/// A body in the level (ViZDoom's `Object`).
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The body's index, as a label's `object_id` names it.
    pub id: u32,
    /// ZDoom's class name (`Cacodemon`, `DoomPlayer`), else the actor
    /// table's.
    pub name: String,
    pub position: [f64; 3],
    /// Degrees anticlockwise from east.
    pub angle: f64,
    /// Map units a tic.
    pub velocity: [f64; 3],
    /// The sector it stands in (by the simulation's nodes).
    pub sector: usize,
}

/// A line of a sector (ViZDoom's `Line`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line {
    pub from: [f64; 2],
    pub to: [f64; 2],
    /// One-sided, or flagged to block (`ML_BLOCKING`): nothing walks through.
    pub blocking: bool,
}

/// A sector (ViZDoom's `Sector`).
#[derive(Clone, Debug, PartialEq)]
pub struct Sector {
    pub id: usize,
    pub floor: f64,
    pub ceiling: f64,
    /// Its lines, in Doom's order (`P_GroupLines`): a two-sided line is
    /// in both its sectors' lists.
    pub lines: Vec<Line>,
}

/// Every body of `game`'s level that is still in it and in a sector, by id.
pub fn objects(game: &SimGame) -> Vec<Object> {
    let sim = &game.sim;
    sim.mobjs
        .iter()
        .enumerate()
        // Bodies not linked into a sector (MapSpot, a teleport's
        // destination) are not listed: ViZDoom 1.3.2 lists my_way_home's
        // player and armour and none of its 17 map spots.
        .filter(|(_, m)| !m.removed && !m.has(mf::NOSECTOR))
        .map(|(i, m)| Object {
            id: i as u32,
            name: name_of(sim, m.kind),
            position: [m.x.to_f64(), m.y.to_f64(), m.z.to_f64()],
            angle: m.angle.to_degrees(),
            velocity: [m.momx.to_f64(), m.momy.to_f64(), m.momz.to_f64()],
            sector: sim.level.subsectors.get(m.subsector).map_or(0, |s| s.sector),
        })
        .collect()
}

/// ZDoom's class name of actor `kind` (`DoomImp`), as ViZDoom names
/// objects; an actor ZDoom does not have (one of a scenario's DECORATE)
/// goes by its table name.
fn name_of(sim: &crate::sim::Sim, kind: usize) -> String {
    match crate::actors::zdoom::class_name(&sim.info.table, kind) {
        Some(class) => class.to_string(),
        None => sim.info.table.actors.get(kind).map_or_else(String::new, |a| a.name.clone()),
    }
}

/// Every sector of `game`'s level with its heights now and its lines.
pub fn sectors(game: &SimGame) -> Vec<Sector> {
    let level = &game.sim.level;
    let point = |(x, y): (crate::fixed::Fixed, crate::fixed::Fixed)| [x.to_f64(), y.to_f64()];
    level
        .sectors
        .iter()
        .enumerate()
        .map(|(id, s)| Sector {
            id,
            floor: s.floorheight.to_f64(),
            ceiling: s.ceilingheight.to_f64(),
            lines: s
                .lines
                .iter()
                .filter_map(|&l| level.lines.get(l))
                .map(|l| Line {
                    from: point(l.v1),
                    to: point(l.v2),
                    blocking: l.backsector.is_none() || l.flags & ml::BLOCKING != 0,
                })
                .collect(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::{Scenario, ScenarioConfig};
    use super::*;

    #[test]
    fn basic_is_one_room_with_the_player_and_a_cacodemon() {
        let Some(dir) = super::super::shipped_dir() else { return };
        let config = ScenarioConfig::load(dir.join("basic.cfg")).unwrap();
        let scenario = Scenario::open(&config, None).unwrap();
        let mut e = scenario.episode(3).unwrap();
        e.step(&[0.0, 0.0, 0.0]);
        // ViZDoom 1.3.2 lists, for basic: one sector, floor 0 and ceiling
        // 104, four blocking walls around (-448, -192)-(64, 256); the
        // player at (-384, 32, 0) facing east, a cacodemon on x = 0.
        let sectors = sectors(&e.game);
        assert_eq!(sectors.len(), 1);
        assert_eq!((sectors[0].floor, sectors[0].ceiling), (0.0, 104.0));
        let mut corners: Vec<[i64; 2]> =
            sectors[0].lines.iter().map(|l| [l.from[0] as i64, l.from[1] as i64]).collect();
        corners.sort_unstable();
        assert_eq!(corners, [[-448, -192], [-448, 256], [64, -192], [64, 256]]);
        assert!(sectors[0].lines.iter().all(|l| l.blocking));
        let objects = objects(&e.game);
        let names: Vec<&str> = objects.iter().map(|o| o.name.as_str()).collect();
        assert!(names.contains(&"DoomPlayer") && names.contains(&"Cacodemon"), "{names:?}");
        let player = objects.iter().find(|o| o.name == "DoomPlayer").unwrap();
        assert_eq!((player.position, player.angle, player.sector), ([-384.0, 32.0, 0.0], 0.0, 0));
        let caco = objects.iter().find(|o| o.name == "Cacodemon").unwrap();
        assert_eq!(caco.position[0], 0.0);
    }
}
