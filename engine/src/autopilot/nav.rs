//! The navigation grid: the map cut into [`CELL`]-unit squares, each
//! knowing the sector under its centre and every sector the player's circle
//! would overlap there, and which of its eight neighbours a wall cuts off
//! (or a gap the body would wedge in: `wedged`). Moves up a stair of steps
//! narrower than a cell also know the sectors under the circle at points
//! along them ([`NavGrid::climbable`]).
//!
//! What never changes (walls, which sectors a cell touches, which special
//! lines a move between two cells crosses) is computed once per map; what
//! does (floor and ceiling heights) is read from a [`Heights`] at search
//! time, so the same grid answers "can I go there now?" and "could I, once
//! that door is open and that lift is down?".

use glam::DVec2;

use super::blockmap::{Blockmap, LineQuery};
use crate::bsp::CompiledMap;
use crate::geom::crossing;
use crate::map::Map;
use crate::play::player::{HEIGHT, MAX_STEP, RADIUS};

/// Side of a cell, map units.
pub const CELL: f64 = 16.0;
/// A cell's centre must be this far from every solid wall to be stood on.
/// Less than the body's radius on purpose: a 32-unit corridor has no cell
/// centre on its middle line, and the body slides along walls anyway.
pub const CLEAR: f64 = 7.5;
/// Walls nearer than this make a cell cost more to pass.
const ROOMY: f64 = 32.0;
/// Points between two cells' centres at which a move is tried more
/// closely (a quarter of a straight move apart): the floors under the
/// circle on a stair of narrow steps, the walls beside it in a gap.
const MOVE_POINTS: usize = 3;
/// A gap between solid walls as wide as the body, or this much wider, stops
/// it: its circle would have to be centred in the gap exactly.
const SNUG: f64 = 1.0;
/// A cell whose nearest solid wall is closer than this is near walls: a
/// move between two such cells is tried for a gap the body wedges in.
const NEAR_WALLS: f64 = RADIUS + CELL / 2.0;
/// A cell index.
pub type Cell = u32;
/// No sector (outside the map).
pub const NONE: u32 = u32::MAX;

/// The eight neighbours: east, north, west, south, then the diagonals.
pub const DIRS: [(i32, i32); 8] = [(1, 0), (0, 1), (-1, 0), (0, -1), (1, 1), (-1, 1), (-1, -1), (1, -1)];
/// The two straight moves a diagonal needs open (no corner cutting).
const SIDES: [(usize, usize); 4] = [(0, 1), (2, 1), (2, 3), (0, 3)];

/// A line with a special: a wall (its index) or a trigger line
/// (`lines.len()` plus its index), as one number.
pub type LineId = u32;

/// Sector heights as a search sees them. A sector with a `range` can be at
/// any floor height in it (a lift the bot can ride).
#[derive(Clone, Debug)]
pub struct Heights {
    pub floor: Vec<f64>,
    pub ceiling: Vec<f64>,
    /// Per sector: the lowest floor it can be lowered to, if it is a lift.
    pub low: Vec<f64>,
}

impl Heights {
    /// The map's heights now, as the player sees them.
    pub fn of(map: &Map) -> Heights {
        let floor: Vec<f64> = map.sectors.iter().map(|s| s.floor).collect();
        Heights { low: floor.clone(), floor, ceiling: map.sectors.iter().map(|s| s.ceiling).collect() }
    }
}

/// The floor (lowest and highest it can be) and ceiling under a cell.
#[derive(Clone, Copy, Debug)]
pub struct Span {
    pub low: f64,
    pub high: f64,
    pub ceiling: f64,
    /// The lowest floor under the circle: a body there is on a ledge when
    /// this is more than a step below `high`.
    pub bottom: f64,
}

impl Span {
    /// Part of the circle hangs over a drop: a body a little off the
    /// cell's centre falls.
    pub fn ledge(&self) -> bool {
        self.bottom < self.high - MAX_STEP
    }

    /// Is a move from here to `to` a drop no step climbs back?
    pub fn drops_to(&self, to: &Span) -> bool {
        self.high - to.high > MAX_STEP
    }

    /// Is `to` a full step lower or more, so that a running jump from here
    /// may clear a gap beyond it? A pit a step deep is no drop (a step
    /// climbs back), but its far side may be a ledge only a leap reaches
    /// (Freedoom's MAP28 reaches its blue key so). Shallower pits are not
    /// tried: asking at every step down cost `check` 10% more over
    /// Freedoom's 68 maps (asking here, 5%), for a secret and a few items
    /// more (MAP12) and no key or exit.
    pub fn leaps_off(&self, to: &Span) -> bool {
        to.high <= self.high - MAX_STEP
    }
}

/// The sector `p` is in, if it is in the map: the BSP's leaf, and `p` in
/// front of each of the leaf's segs (a leaf's segs bound its convex cell
/// facing into it, so a point behind one is outside the map). Linear in
/// the leaf's segs, where `CompiledMap::locate`'s exact test walks every
/// line of the map: the grid asks this of every cell. It agrees with
/// `locate` on all but 3 of 54,817 sample points of Freedoom's MAP20 (0 on
/// E1M1, MAP03, E3M9 and our maps): a leaf not closed by segs holds a sliver
/// outside, which no move reaches (walls still cut every move into it).
pub fn inside(compiled: &CompiledMap, p: DVec2) -> Option<usize> {
    let bsp = &compiled.bsp;
    let leaf = &bsp.leaves[bsp.leaf_at(p)];
    let segs = &bsp.segs[leaf.first..leaf.first + leaf.count];
    segs.iter().all(|s| crate::geom::front_distance(s.v1, s.v2, p) >= 0.0).then_some(leaf.sector)
}

/// A line the body cannot cross: one-sided, or marked impassable.
pub fn solid(line: &crate::map::Line) -> bool {
    line.back.is_none() || line.flags.impassable
}

/// What a body's circle centred at a point meets: see [`survey`].
struct Survey {
    /// The sector under the centre.
    sector: u32,
    /// The centre is far enough from every solid wall to be stood on.
    clear: bool,
    /// How far the nearest solid wall is, up to [`ROOMY`].
    room: f64,
}

/// The body's circle centred at `p`: the sectors it overlaps (into
/// `found`, sorted, the one under the centre among them), and whether it
/// can stand there. `None` outside the map.
fn survey(
    compiled: &CompiledMap,
    blockmap: &Blockmap,
    query: &mut LineQuery,
    p: DVec2,
    found: &mut Vec<u32>,
) -> Option<Survey> {
    let map = &compiled.map;
    let sector = inside(compiled, p)?;
    let r = DVec2::splat(ROOMY);
    let near = query.run(blockmap, map.lines.len(), p - r, p + r);
    found.clear();
    found.push(sector as u32);
    // The nearest solid wall: the body is pushed off it, so whatever
    // is across from it must leave room for the whole body.
    let mut room = ROOMY;
    let mut wall_at = p;
    for &i in near {
        let line = &map.lines[i as usize];
        if solid(line) {
            let (a, b) = map.line_points(line);
            let q = crate::autopilot::plan::nearest_on(p, a, b);
            if q.distance(p) < room {
                room = q.distance(p);
                wall_at = q;
            }
        }
    }
    let mut clear = room >= CLEAR;
    // How far across from that wall the body reaches (and `SNUG` more: a
    // gap exactly as wide as the body stops it, its circle wedged between
    // the two sides).
    let across = |q: DVec2| {
        if room < RADIUS && (q - p).dot(wall_at - p) < 0.0 {
            2.0 * RADIUS - room + SNUG
        } else {
            RADIUS
        }
    };
    for &i in near {
        let line = &map.lines[i as usize];
        let (a, b) = map.line_points(line);
        let q = crate::autopilot::plan::nearest_on(p, a, b);
        let d = q.distance(p);
        if solid(line) {
            // A solid line keeps the body off it (what is behind it
            // is never under the body), and two too close on either
            // side leave no room between.
            clear &= d >= CLEAR && (q == wall_at || d >= across(q) || across(q) == RADIUS);
            continue;
        }
        if d >= across(q) {
            continue;
        }
        found.extend(std::iter::once(&line.front).chain(&line.back).map(|s| s.sector as u32));
    }
    found.sort_unstable();
    found.dedup();
    Some(Survey { sector: sector as u32, clear, room })
}

/// Would the body's circle, centred at `p` and moving along the unit
/// vector `m`, be wedged in a gap: the nearest solid walls beside it (less
/// than half a cell ahead or behind), one on each side of its way, less
/// than its width and [`SNUG`] apart?
fn wedged(map: &Map, blockmap: &Blockmap, query: &mut LineQuery, p: DVec2, m: DVec2) -> bool {
    let reach = 2.0 * RADIUS + SNUG;
    let r = DVec2::splat(reach);
    // Per side of the way: the wall point nearest across it.
    let (mut left, mut right): (Option<DVec2>, Option<DVec2>) = (None, None);
    for &i in query.run(blockmap, map.lines.len(), p - r, p + r) {
        let line = &map.lines[i as usize];
        if !solid(line) {
            continue;
        }
        let (a, b) = map.line_points(line);
        let u = crate::autopilot::plan::nearest_on(p, a, b) - p;
        if u.dot(m).abs() > CELL / 2.0 {
            continue;
        }
        let across = m.perp_dot(u);
        let side = if across > 0.0 { &mut left } else { &mut right };
        if across != 0.0 && side.is_none_or(|v| across.abs() < m.perp_dot(v).abs()) {
            *side = Some(u);
        }
    }
    left.zip(right).is_some_and(|(u, v)| u.distance(v) < reach)
}

/// The points along the move from `p` to `q` it is tried at more closely.
fn points_along(p: DVec2, q: DVec2) -> impl Iterator<Item = DVec2> {
    (1..=MOVE_POINTS).map(move |k| p.lerp(q, k as f64 / (MOVE_POINTS + 1) as f64))
}

pub struct NavGrid {
    pub origin: DVec2,
    pub width: usize,
    pub height: usize,
    /// Per cell: the sector under the centre, or [`NONE`].
    pub centre: Vec<u32>,
    /// Per cell: `touch[touch_start[c]..touch_start[c + 1]]` are the sectors
    /// the body's circle overlaps with its centre there.
    touch_start: Vec<u32>,
    touch: Vec<u32>,
    /// Per cell: bit `d` set when the move to neighbour `d` is cut by a solid
    /// wall (or the neighbour cannot be stood on).
    walls: Vec<u8>,
    /// Per cell: extra cost of passing through it, for being close to a
    /// wall (routes keep to the middle of corridors where they can).
    pub narrow: Vec<u8>,
    /// Special lines a move crosses: `(cell * 8 + dir, line, from_front)`,
    /// sorted.
    crossings: Vec<(u32, LineId, bool)>,
    /// Moves up to a cell more than a step higher whose circles overlap
    /// three floor heights or more (a stair of narrow steps), as the map
    /// starts: `cell * 8 + dir`, sorted. For the `i`-th, the circle at the
    /// `k`-th of [`MOVE_POINTS`] points along the move overlaps the sectors
    /// `ramp_touch[ramp_start[j] as usize..ramp_start[j + 1] as usize]`,
    /// `j` being `i * MOVE_POINTS + k`.
    ramps: Vec<u32>,
    ramp_start: Vec<u32>,
    ramp_touch: Vec<u32>,
}

impl NavGrid {
    /// The grid of `compiled`, with the walk and trigger lines a move crosses.
    pub fn new(compiled: &CompiledMap) -> NavGrid {
        let map = &compiled.map;
        let (mut min, mut max) = (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN));
        for v in &map.vertices {
            min = min.min(*v);
            max = max.max(*v);
        }
        let origin = (min / CELL).floor() * CELL;
        let width = (((max.x - origin.x) / CELL).ceil() as usize).max(1);
        let height = (((max.y - origin.y) / CELL).ceil() as usize).max(1);
        let cells = width * height;
        let blockmap = Blockmap::new(map);
        let mut query = LineQuery::default();
        let mut centre = vec![NONE; cells];
        let mut touch_start = Vec::with_capacity(cells + 1);
        let mut touch = Vec::new();
        let mut clear = vec![false; cells];
        let mut narrow = vec![0u8; cells];
        let mut near_walls = vec![false; cells];
        let mut found = Vec::new();
        for c in 0..cells {
            touch_start.push(touch.len() as u32);
            let p = origin + DVec2::new((c % width) as f64 + 0.5, (c / width) as f64 + 0.5) * CELL;
            let Some(survey) = survey(compiled, &blockmap, &mut query, p, &mut found) else { continue };
            centre[c] = survey.sector;
            touch.extend_from_slice(&found);
            clear[c] = survey.clear;
            near_walls[c] = survey.room < NEAR_WALLS;
            narrow[c] = if survey.room < RADIUS {
                12
            } else if survey.room < RADIUS + 8.0 {
                4
            } else if survey.room < ROOMY {
                1
            } else {
                0
            };
        }
        touch_start.push(touch.len() as u32);
        let mut grid = NavGrid {
            origin,
            width,
            height,
            centre,
            touch_start,
            touch,
            walls: vec![0xff; cells],
            narrow,
            crossings: Vec::new(),
            ramps: Vec::new(),
            ramp_start: Vec::new(),
            ramp_touch: Vec::new(),
        };
        let triggers = Blockmap::of_trigger_lines(map);
        let walls_count = map.lines.len() as u32;
        for c in 0..cells {
            if !clear[c] {
                continue;
            }
            // Diagonals start shut; the next pass opens those that are clear.
            let mut bits = 0xf0u8;
            let p = grid.centre_of(c as Cell);
            for (d, &(dx, dy)) in DIRS.iter().enumerate().take(4) {
                let Some(n) = grid.neighbour(c as Cell, d) else {
                    bits |= 1 << d;
                    continue;
                };
                let q = grid.centre_of(n);
                if !clear[n as usize] {
                    bits |= 1 << d;
                    continue;
                }
                // Between two cells near walls, a gap the body wedges in
                // (Freedoom MAP29's 32 units between a post's corner and a
                // wall's: both cells clear of it, the move through it not).
                if near_walls[c]
                    && near_walls[n as usize]
                    && points_along(p, q)
                        .any(|at| wedged(map, &blockmap, &mut query, at, DVec2::new(dx as f64, dy as f64)))
                {
                    bits |= 1 << d;
                    continue;
                }
                let (lo, hi) = (p.min(q) - DVec2::ONE, p.max(q) + DVec2::ONE);
                for &i in query.run(&blockmap, map.lines.len(), lo, hi) {
                    let line = &map.lines[i as usize];
                    let (a, b) = map.line_points(line);
                    let Some(_) = crossing(p, q, a, b) else { continue };
                    if solid(line) {
                        bits |= 1 << d;
                    } else if line.special.is_some() {
                        let front = crate::geom::front_distance(a, b, p) > 0.0;
                        grid.crossings.push((c as u32 * 8 + d as u32, i, front));
                    }
                }
                for &i in query.run(&triggers, map.trigger_lines.len(), lo, hi) {
                    let t = &map.trigger_lines[i as usize];
                    let (a, b) = (map.vertices[t.from], map.vertices[t.to]);
                    if crossing(p, q, a, b).is_some() {
                        let front = crate::geom::front_distance(a, b, p) > 0.0;
                        grid.crossings.push((c as u32 * 8 + d as u32, walls_count + i, front));
                    }
                }
            }
            grid.walls[c] = bits;
        }
        // Diagonals: both straight moves around the corner must be open, and
        // the diagonal itself must not cross a wall or a special line (the
        // straight moves carry those).
        for c in 0..cells {
            if !clear[c] {
                continue;
            }
            for k in 0..4 {
                let d = 4 + k;
                let (s1, s2) = SIDES[k];
                let open = grid.walls[c] & (1 << s1) == 0 && grid.walls[c] & (1 << s2) == 0;
                let Some(n) = grid.neighbour(c as Cell, d) else { continue };
                let via1 = grid.neighbour(c as Cell, s1).unwrap();
                let via2 = grid.neighbour(c as Cell, s2).unwrap();
                let crossed = grid.crossings_of(c as Cell, s1).next().is_some()
                    || grid.crossings_of(c as Cell, s2).next().is_some()
                    || grid.crossings_of(via1, s2).next().is_some()
                    || grid.crossings_of(via2, s1).next().is_some();
                let far = grid.walls[via1 as usize] & (1 << s2) == 0 && grid.walls[via2 as usize] & (1 << s1) == 0;
                if open && far && !crossed && clear[n as usize] {
                    grid.walls[c] &= !(1 << d);
                }
            }
            if grid.walls[c] & 0x0f == 0x0f {
                grid.walls[c] = 0xff;
            }
        }
        grid.crossings.sort_unstable();
        grid.survey_ramps(compiled, &blockmap, &mut query);
        grid
    }

    /// Stairs of steps narrower than a cell: a move between two cells can
    /// climb more than a step in all, one step at a time. The circle is
    /// surveyed at points along the moves that might: where, as the map
    /// starts, the cell moved to is more than a step above the one moved
    /// from and the two circles overlap floors at three heights or more
    /// (with two, the climb is one rise of more than a step whatever lies
    /// between). Stairs are built so; a floor moved later is not surveyed
    /// for.
    fn survey_ramps(&mut self, compiled: &CompiledMap, blockmap: &Blockmap, query: &mut LineQuery) {
        let map = &compiled.map;
        let floor = |s: &u32| map.sectors[*s as usize].floor;
        let high: Vec<f64> =
            (0..self.cells() as Cell).map(|c| self.touched(c).iter().map(floor).fold(f64::MIN, f64::max)).collect();
        let mut floors = Vec::new();
        let mut found = Vec::new();
        for c in 0..self.cells() as Cell {
            for d in 0..8 {
                let Some(n) = self.neighbour(c, d).filter(|_| self.open(c, d)) else { continue };
                if high[n as usize] - high[c as usize] <= MAX_STEP {
                    continue;
                }
                floors.clear();
                floors.extend(self.touched(c).iter().chain(self.touched(n)).map(floor));
                floors.sort_by(f64::total_cmp);
                floors.dedup();
                if floors.len() < 3 {
                    continue;
                }
                let first = self.ramp_start.len();
                let before = self.ramp_touch.len();
                let mut inside_map = true;
                for at in points_along(self.centre_of(c), self.centre_of(n)) {
                    self.ramp_start.push(self.ramp_touch.len() as u32);
                    inside_map &= survey(compiled, blockmap, query, at, &mut found).is_some();
                    self.ramp_touch.extend_from_slice(&found);
                }
                if inside_map {
                    self.ramps.push(c * 8 + d as u32);
                } else {
                    self.ramp_start.truncate(first);
                    self.ramp_touch.truncate(before);
                }
            }
        }
        self.ramp_start.push(self.ramp_touch.len() as u32);
    }

    /// The cells of the grid whose squares meet the box `lo`..`hi` (clipped
    /// to the grid), row by row.
    pub fn cells_in_box(&self, lo: DVec2, hi: DVec2) -> impl Iterator<Item = Cell> + '_ {
        let far = self.origin + DVec2::new(self.width as f64, self.height as f64) * CELL - 1.0;
        let corners = self.cell_at(lo.max(self.origin)).zip(self.cell_at(hi.min(far)));
        let (x0, y0, x1, y1) = corners.map_or((1, 1, 0, 0), |(c0, c1)| {
            let (c0, c1) = (c0 as usize, c1 as usize);
            (c0 % self.width, c0 / self.width, c1 % self.width, c1 / self.width)
        });
        (y0..=y1).flat_map(move |y| (x0..=x1).map(move |x| (y * self.width + x) as Cell))
    }

    pub fn cells(&self) -> usize {
        self.width * self.height
    }

    pub fn centre_of(&self, c: Cell) -> DVec2 {
        let c = c as usize;
        self.origin + DVec2::new((c % self.width) as f64 + 0.5, (c / self.width) as f64 + 0.5) * CELL
    }

    /// The cell `p` is in, if it is on the grid.
    pub fn cell_at(&self, p: DVec2) -> Option<Cell> {
        let q = (p - self.origin) / CELL;
        if !(q.x >= 0.0 && q.y >= 0.0) {
            return None;
        }
        let (x, y) = (q.x as usize, q.y as usize);
        (x < self.width && y < self.height).then(|| (y * self.width + x) as Cell)
    }

    /// The cell nearest `p` that can be stood on, within `reach` cells.
    pub fn standable_near(&self, p: DVec2, reach: i32) -> Option<Cell> {
        let q = ((p - self.origin) / CELL).floor();
        let mut best: Option<(f64, Cell)> = None;
        for dy in -reach..=reach {
            for dx in -reach..=reach {
                let (x, y) = (q.x as i64 + dx as i64, q.y as i64 + dy as i64);
                if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
                    continue;
                }
                let c = (y as usize * self.width + x as usize) as Cell;
                if !self.standable(c) {
                    continue;
                }
                let d = self.centre_of(c).distance_squared(p);
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, c));
                }
            }
        }
        best.map(|b| b.1)
    }

    /// The cell a body at `pos` with its feet at `z` is best taken to be
    /// in: the nearest standable one whose floor is within a step of the
    /// feet (a body pressed against a ledge is not on top of it), and not
    /// one `avoid` names where another will do (a cell a solid thing
    /// stands on: a body pressed against E4M9's column is beside it).
    pub fn start_cell(&self, pos: DVec2, z: f64, heights: &Heights, avoid: impl Fn(Cell) -> bool) -> Option<Cell> {
        let q = ((pos - self.origin) / CELL).floor();
        let mut best: Option<(f64, Cell)> = None;
        for dy in -3i64..=3 {
            for dx in -3i64..=3 {
                let (x, y) = (q.x as i64 + dx, q.y as i64 + dy);
                if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
                    continue;
                }
                let c = (y as usize * self.width + x as usize) as Cell;
                if !self.standable(c) {
                    continue;
                }
                let span = self.span(c, heights);
                let off = if z + MAX_STEP < span.low || z > span.high + MAX_STEP { 1e6 } else { 0.0 }
                    + if avoid(c) { 1e5 } else { 0.0 };
                let d = self.centre_of(c).distance_squared(pos) + off;
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, c));
                }
            }
        }
        best.map(|b| b.1)
    }

    /// Can a body stand with its centre in `c` (in the map, clear of walls)?
    pub fn standable(&self, c: Cell) -> bool {
        self.walls[c as usize] != 0xff
    }

    pub fn neighbour(&self, c: Cell, d: usize) -> Option<Cell> {
        let (x, y) = ((c as usize % self.width) as i32, (c as usize / self.width) as i32);
        let (nx, ny) = (x + DIRS[d].0, y + DIRS[d].1);
        (nx >= 0 && ny >= 0 && (nx as usize) < self.width && (ny as usize) < self.height)
            .then(|| (ny as usize * self.width + nx as usize) as Cell)
    }

    /// The direction from `c` to `n`, if `n` is one of its neighbours.
    pub fn direction(&self, c: Cell, n: Cell) -> Option<usize> {
        (0..8).find(|&d| self.neighbour(c, d) == Some(n))
    }

    /// Is the move from `c` to its neighbour `d` free of solid walls?
    pub fn open(&self, c: Cell, d: usize) -> bool {
        self.walls[c as usize] & (1 << d) == 0
    }

    pub fn touched(&self, c: Cell) -> &[u32] {
        let c = c as usize;
        &self.touch[self.touch_start[c] as usize..self.touch_start[c + 1] as usize]
    }

    /// The special lines the move from `c` to neighbour `d` crosses, and
    /// whether it starts on each one's front.
    pub fn crossings_of(&self, c: Cell, d: usize) -> impl Iterator<Item = (LineId, bool)> + '_ {
        let key = c * 8 + d as u32;
        let start = self.crossings.partition_point(|x| x.0 < key);
        self.crossings[start..].iter().take_while(move |x| x.0 == key).map(|x| (x.1, x.2))
    }

    /// The floor and ceiling under `c` with `heights`.
    pub fn span(&self, c: Cell, heights: &Heights) -> Span {
        self.span_where(c, heights, |_| None)
    }

    /// [`NavGrid::span`] with some sectors' floors held where `fixed` says
    /// (not able to go lower).
    pub fn span_where(&self, c: Cell, heights: &Heights, fixed: impl Fn(usize) -> Option<f64>) -> Span {
        span_over(self.touched(c), heights, fixed)
    }

    /// Can the body go from `c` to its neighbour `d`, under `from` and `to`:
    /// [`NavGrid::passable`], or a climb of more than a step in all over
    /// steps narrower than a cell, each point along the move a step at
    /// most above the last.
    pub fn climbable(&self, c: Cell, d: usize, from: Span, to: Span, heights: &Heights) -> bool {
        if NavGrid::passable(from, to) {
            return true;
        }
        // Only a climb (a body falls as it goes, and meets a low ceiling
        // before it is down), and only over floors that stay put (a lift's
        // range would let each point take it at a different height).
        let still = |s: &Span| s.low == s.high;
        if to.high <= from.high + MAX_STEP || !still(&from) || !still(&to) {
            return false;
        }
        let Ok(i) = self.ramps.binary_search(&(c * 8 + d as u32)) else { return false };
        let mut last = from;
        for k in i * MOVE_POINTS..(i + 1) * MOVE_POINTS {
            let touched = &self.ramp_touch[self.ramp_start[k] as usize..self.ramp_start[k + 1] as usize];
            let span = span_over(touched, heights, |_| None);
            if !still(&span) || span.high < last.high || !NavGrid::passable(last, span) {
                return false;
            }
            last = span;
        }
        NavGrid::passable(last, to)
    }

    /// Can the body go from a cell under `from` to one under `to`: a step of
    /// at most 24 (riding what can be ridden), any drop, and room for its
    /// height?
    pub fn passable(from: Span, to: Span) -> bool {
        // Feet as low as they can be on `from` while still stepping up to
        // `to` at its lowest.
        let feet = from.low.max(to.low - MAX_STEP);
        feet <= from.high && to.ceiling - to.low.max(feet) >= HEIGHT
    }
}

/// The floor and ceiling under a circle overlapping `touched`, with some
/// sectors' floors held where `fixed` says.
fn span_over(touched: &[u32], heights: &Heights, fixed: impl Fn(usize) -> Option<f64>) -> Span {
    let mut span = Span { low: f64::MIN, high: f64::MIN, ceiling: f64::MAX, bottom: f64::MAX };
    for &s in touched {
        let s = s as usize;
        let (floor, low) = fixed(s).map_or((heights.floor[s], heights.low[s]), |f| (f, f));
        span.bottom = span.bottom.min(floor);
        span.low = span.low.max(low);
        span.high = span.high.max(floor);
        span.ceiling = span.ceiling.min(heights.ceiling[s]);
    }
    span
}
