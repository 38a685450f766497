//! Fixed tours of poses through a map, for benchmarks and regression runs:
//! the same map always gives the same tour.

use glam::DVec2;
use rand::{RngExt, SeedableRng};

use crate::bsp::CompiledMap;
use crate::geom::Aabb;
use crate::level::Level;
use crate::render::View;

/// Poses no closer than this to a wall, so a tour shows rooms, not wallpaper.
const CLEARANCE: f64 = 8.0;

/// The player start facing eight directions, then `extra` seeded random poses
/// inside the map (each at least [`CLEARANCE`] from every line).
pub fn tour(compiled: &CompiledMap, extra: usize, seed: u64) -> Vec<View> {
    let map = &compiled.map;
    let mut views = Vec::with_capacity(8 + extra);
    let start = map.player_start();
    for k in 0..8 {
        let angle = start.angle + 45.0 * f64::from(k);
        if let Ok(v) = View::at_pose(compiled, start.pos.x, start.pos.y, angle, None) {
            views.push(v);
        }
    }
    let mut bbox = Aabb::EMPTY;
    for &p in &map.vertices {
        bbox.include(p);
    }
    let mut rng = rand::rngs::ChaCha8Rng::seed_from_u64(seed);
    let mut attempts = 0;
    while views.len() < 8 + extra && attempts < 10_000 * (extra + 1) {
        attempts += 1;
        let p = DVec2::new(rng.random_range(bbox.min.x..=bbox.max.x), rng.random_range(bbox.min.y..=bbox.max.y));
        let angle = rng.random_range(0.0..360.0);
        if map.distance_to_nearest_line(p) >= CLEARANCE {
            if let Ok(v) = View::at_pose(compiled, p.x, p.y, angle, None) {
                views.push(v);
            }
        }
    }
    views
}

/// The benchmark tour of `sightline bench tour`: the player start as it
/// faces, then the player start's and every drawn thing's position (things
/// stand where a player would meet them; only those `level` shows) looking
/// eight ways (0, 45, ..., 315 degrees), eye at the usual height above the
/// floor there. Things outside the map are skipped.
pub fn things_tour(level: &Level) -> Vec<View> {
    let compiled = &level.compiled;
    let map = &compiled.map;
    let mut views = Vec::with_capacity(1 + 8 * map.things.len());
    views.extend(View::at_start(compiled));
    let drawn = |i: usize| i == map.player_start || (level.thing_shown[i] && level.materials.sprites[i].is_some());
    for thing in map.things.iter().enumerate().filter(|&(i, _)| drawn(i)).map(|(_, t)| t) {
        for k in 0..8 {
            let angle = 45.0 * f64::from(k);
            views.extend(View::at_pose(compiled, thing.pos.x, thing.pos.y, angle, None));
        }
    }
    views
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn things_tour_visits_every_thing_eight_ways() {
        let text = include_str!("../../maps/pillars.ron");
        let map = crate::map::parse_map(text, "pillars.ron").expect("shipped map");
        let compiled = crate::bsp::build(&map, &Default::default()).expect("compiles");
        let level = Level::with_builtin_textures(compiled).expect("textures");
        let views = things_tour(&level);
        assert_eq!(views.len(), 1 + 8 * map.things.len());
        assert_eq!(views[0], View::at_start(&level).expect("start"));
        assert_eq!(views[1 + 8 + 3].angle, 135.0);
    }
}
