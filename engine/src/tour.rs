//! Fixed tours of poses through a map, for benchmarks and regression runs:
//! the same map always gives the same tour.

use glam::DVec2;
use rand::{RngExt, SeedableRng};

use crate::geom::Aabb;
use crate::map::Map;
use crate::render::View;

/// Poses no closer than this to a wall, so a tour shows rooms, not wallpaper.
const CLEARANCE: f64 = 8.0;

/// The player start facing eight directions, then `extra` seeded random poses
/// inside the map (each at least [`CLEARANCE`] from every line).
pub fn tour(map: &Map, extra: usize, seed: u64) -> Vec<View> {
    let mut views = Vec::with_capacity(8 + extra);
    let start = map.player_start();
    for k in 0..8 {
        let angle = start.angle + 45.0 * f64::from(k);
        if let Ok(v) = View::at_pose(map, start.pos.x, start.pos.y, angle, None) {
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
            if let Ok(v) = View::at_pose(map, p.x, p.y, angle, None) {
                views.push(v);
            }
        }
    }
    views
}
