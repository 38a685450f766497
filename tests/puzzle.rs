//! Random puzzle levels in map format version 2, deterministic from a seed
//! (issue 42's tests): a chain of rooms from the start to an exit switch,
//! each joined to the next by one mechanism, with keys, switches, ledges and
//! decoys beside the way.
//!
//! - **Links** between one room and the next ([`Link`]): a door, a door a
//!   switch elsewhere opens, a keyed door (its key in a side room or up on a
//!   ledge), a lift up, a raised floor a switch lowers, stairs a switch
//!   builds (Doom's 8-unit builder and its 16-unit turbo one), and a
//!   teleporter into a closed room whose way out is its own link.
//! - **Ledges**: a switch or a key may sit on a dead-end ledge up a lift
//!   called only from below; the way back down is stepping off the raised
//!   lift.
//! - **Decoys**: switches that change a light and nothing else, and side
//!   rooms that lead nowhere.
//! - **Monsters** (when asked for) from [`MONSTERS`], the actors a
//!   version-2 map can name with no WAD today, and a little ammunition and
//!   health.
//!
//! Every sector is an axis-aligned rectangle; the lines are worked out from
//! the rectangles (each edge split at every corner that lies on it), so the
//! map is valid by construction. [`generate`] gives the RON text and what
//! the level holds; `cargo run -p sightline-tests --example puzzle -- SEED`
//! writes one for a person to look at.

use std::collections::BTreeMap;
use std::fmt::Write;

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};

/// The monsters a generated level may hold: every one a version-2 map can
/// name with no WAD today (their pictures are built in). The one place to
/// widen when every Doom actor is nameable.
pub const MONSTERS: &[&str] = &["zombieman", "sentry", "stalker", "spitter"];

/// How one room leads to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Link {
    /// A door opened by hand.
    Door,
    /// A door only a switch elsewhere opens.
    RemoteDoor,
    /// A door that needs a key.
    KeyDoor,
    /// A lift up to the next room, called by a switch on its face.
    Lift,
    /// A raised floor across the way, lowered by a switch.
    LowerFloor,
    /// Stairs of 8-unit steps built by a switch (Doom's slow builder).
    Stairs8,
    /// Stairs of 16-unit steps built by a switch (Doom's turbo builder).
    Stairs16,
    /// A teleporter into the next room, which no other way reaches.
    Teleport,
}

/// Every kind of link, in the order seeds start on.
pub const LINKS: [Link; 8] = [
    Link::Door,
    Link::RemoteDoor,
    Link::KeyDoor,
    Link::Lift,
    Link::LowerFloor,
    Link::Stairs8,
    Link::Stairs16,
    Link::Teleport,
];

/// A generated level.
#[derive(Clone, Debug)]
pub struct Puzzle {
    pub seed: u64,
    /// The map, in map format version 2.
    pub ron: String,
    /// The links from the start to the exit room, in order.
    pub links: Vec<Link>,
    /// The keys placed (`blue_card`, ...).
    pub keys: Vec<&'static str>,
    /// Switches or keys on dead-end ledges up a lift.
    pub ledges: usize,
    /// Switches that do nothing useful, and side rooms that lead nowhere.
    pub decoys: usize,
    pub monsters: usize,
}

impl Puzzle {
    /// Has switch-built stairs on the way.
    pub fn has_stairs(&self) -> bool {
        self.links.iter().any(|l| matches!(l, Link::Stairs8 | Link::Stairs16))
    }

    /// A line for a test's failure message.
    pub fn describe(&self) -> String {
        format!(
            "seed {}: links {:?}, keys {:?}, {} ledges, {} decoys, {} monsters",
            self.seed, self.links, self.keys, self.ledges, self.decoys, self.monsters
        )
    }
}

type P = (i64, i64);

#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: i64,
    y0: i64,
    x1: i64,
    y1: i64,
}

fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Rect {
    Rect { x0, y0, x1, y1 }
}

impl Rect {
    fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// The corners, clockwise (y up): the sector is on the right of each
    /// edge walked from one to the next.
    fn clockwise(&self) -> [P; 4] {
        [(self.x0, self.y0), (self.x0, self.y1), (self.x1, self.y1), (self.x1, self.y0)]
    }

    fn centre(&self) -> P {
        ((self.x0 + self.x1) / 2, (self.y0 + self.y1) / 2)
    }
}

struct Sector {
    rect: Rect,
    floor: i64,
    ceiling: i64,
    light: u8,
    texture: &'static str,
    tag: u32,
    note: String,
}

/// A special on a one-sided wall from `p` to `q` (a switch).
struct WallSpecial {
    p: P,
    q: P,
    special: String,
    texture: &'static str,
    note: String,
}

/// The rectangles of a level and what its lines do; [`Builder::ron`] works
/// out the lines.
#[derive(Default)]
struct Builder {
    sectors: Vec<Sector>,
    /// (front, back): the lines between them face the first.
    fronts: Vec<(usize, usize)>,
    /// Specials on every line between (front, back).
    between: Vec<(usize, usize, String, &'static str)>,
    walls: Vec<WallSpecial>,
    things: Vec<(&'static str, i64, i64, i64)>,
    next_tag: u32,
}

impl Builder {
    fn sector(&mut self, rect: Rect, floor: i64, ceiling: i64, texture: &'static str, note: String) -> usize {
        for (i, s) in self.sectors.iter().enumerate() {
            assert!(!s.rect.overlaps(&rect), "generator bug: {note} {rect:?} overlaps sector {i} ({})", s.note);
        }
        self.sectors.push(Sector { rect, floor, ceiling, light: 160, texture, tag: 0, note });
        self.sectors.len() - 1
    }

    fn tag(&mut self, s: usize) -> u32 {
        if self.sectors[s].tag == 0 {
            self.next_tag += 1;
            self.sectors[s].tag = self.next_tag;
        }
        self.sectors[s].tag
    }

    fn front(&mut self, a: usize, b: usize) {
        self.fronts.push((a, b));
    }

    fn between(&mut self, front: usize, back: usize, special: String, texture: &'static str) {
        self.front(front, back);
        self.between.push((front, back, special, texture));
    }

    fn wall(&mut self, p: P, q: P, special: String, texture: &'static str, note: &str) {
        self.walls.push(WallSpecial { p, q, special, texture, note: note.to_string() });
    }

    fn thing(&mut self, kind: &'static str, p: P, angle: i64) {
        self.things.push((kind, p.0, p.1, angle));
    }

    /// The map's RON text.
    fn ron(&self, name: &str, header: &[String]) -> String {
        // Every corner and switch end: the points edges are split at.
        let mut points: Vec<P> = self.sectors.iter().flat_map(|s| s.rect.clockwise()).collect();
        points.extend(self.walls.iter().flat_map(|w| [w.p, w.q]));
        points.sort();
        points.dedup();
        // Each sector's edges, split: (from, to, sector), by undirected key.
        let mut segments: BTreeMap<(P, P), Vec<(P, P, usize)>> = BTreeMap::new();
        let mut order: Vec<(P, P)> = Vec::new();
        for (s, sector) in self.sectors.iter().enumerate() {
            let c = sector.rect.clockwise();
            for k in 0..4 {
                let (a, b) = (c[k], c[(k + 1) % 4]);
                let mut on: Vec<P> = points
                    .iter()
                    .copied()
                    .filter(|&p| {
                        if a.0 == b.0 {
                            p.0 == a.0 && p.1 > a.1.min(b.1) && p.1 < a.1.max(b.1)
                        } else {
                            p.1 == a.1 && p.0 > a.0.min(b.0) && p.0 < a.0.max(b.0)
                        }
                    })
                    .collect();
                on.push(a);
                on.push(b);
                let along = |p: &P| (p.0 - a.0).abs() + (p.1 - a.1).abs();
                on.sort_by_key(along);
                for w in on.windows(2) {
                    let key = (w[0].min(w[1]), w[0].max(w[1]));
                    let list = segments.entry(key).or_default();
                    if list.is_empty() {
                        order.push(key);
                    }
                    list.push((w[0], w[1], s));
                }
            }
        }
        let mut vertices: BTreeMap<P, usize> = BTreeMap::new();
        let mut vertex_list: Vec<P> = Vec::new();
        let mut vertex = |p: P| {
            *vertices.entry(p).or_insert_with(|| {
                vertex_list.push(p);
                vertex_list.len() - 1
            })
        };
        let mut lines = String::new();
        for key in &order {
            let list = &segments[key];
            match list.as_slice() {
                &[(p, q, s)] => {
                    let wall = self.walls.iter().find(|w| (w.p.min(w.q), w.p.max(w.q)) == *key);
                    let (a, b) = (vertex(p), vertex(q));
                    match wall {
                        Some(w) => {
                            let _ = writeln!(lines, "        // {}", w.note);
                            let _ = writeln!(
                                lines,
                                "        Line(from: {a}, to: {b}, front: Side(sector: {s}, middle: \"{}\"), special: {}),",
                                w.texture, w.special
                            );
                        }
                        None => {
                            let _ = writeln!(
                                lines,
                                "        Line(from: {a}, to: {b}, front: Side(sector: {s}, middle: \"BRICK\")),"
                            );
                        }
                    }
                }
                &[x, y] => {
                    let (sx, sy) = (x.2, y.2);
                    let x_front = if self.fronts.contains(&(sx, sy)) {
                        true
                    } else if self.fronts.contains(&(sy, sx)) {
                        false
                    } else {
                        sx < sy
                    };
                    let ((p, q, f), (_, _, b)) = if x_front { (x, y) } else { (y, x) };
                    let special = self.between.iter().find(|t| t.0 == f && t.1 == b);
                    let upper = special.map_or("STONE", |t| t.3);
                    let (va, vb) = (vertex(p), vertex(q));
                    let side = |s: usize| format!("Side(sector: {s}, upper: \"{upper}\", lower: \"STEP\")");
                    let extra = special.map_or(String::new(), |t| format!(", special: {}", t.2));
                    let _ = writeln!(
                        lines,
                        "        Line(from: {va}, to: {vb}, front: {}, back: Some({}){extra}),",
                        side(f),
                        side(b)
                    );
                }
                more => panic!("generator bug: {} sectors share the edge {key:?}", more.len()),
            }
        }
        let mut out = String::new();
        for h in header {
            let _ = writeln!(out, "// {h}");
        }
        let _ = writeln!(out, "Map(\n    version: 2,\n    name: \"{name}\",\n    vertices: [");
        for (k, (x, y)) in vertex_list.iter().enumerate() {
            let _ = writeln!(out, "        ({x}.0, {y}.0), // {k}");
        }
        let _ = writeln!(out, "    ],\n    sectors: [");
        for (k, s) in self.sectors.iter().enumerate() {
            let tag = if s.tag > 0 { format!(", tag: {}", s.tag) } else { String::new() };
            let _ = writeln!(out, "        // {k}: {}", s.note);
            let _ = writeln!(
                out,
                "        Sector(floor: {}.0, ceiling: {}.0, light: {}, floor_texture: \"{}\", ceiling_texture: \"CEIL\"{tag}),",
                s.floor, s.ceiling, s.light, s.texture
            );
        }
        let _ = writeln!(out, "    ],\n    lines: [");
        out.push_str(&lines);
        let _ = writeln!(out, "    ],\n    things: [");
        for (kind, x, y, angle) in &self.things {
            let _ = writeln!(out, "        Thing(kind: \"{kind}\", x: {x}.0, y: {y}.0, angle: {angle}.0),");
        }
        let _ = writeln!(out, "    ],\n)");
        out
    }
}

/// A room's size: rooms run east from the start, one every room and link.
const ROOM_W: i64 = 320;
const ROOM_H: i64 = 256;
/// A room's ceiling above its floor.
const ROOM_CEILING: i64 = 160;
/// The corridor a link runs along: y from .. to.
const WAY: (i64, i64) = (64, 192);
/// How high a dead-end ledge stands above its room.
const LEDGE_RISE: i64 = 96;

/// What goes where: the level being laid out.
struct Layout {
    b: Builder,
    rng: ChaCha8Rng,
    /// Each room's sector, x, floor, north slots taken, south side taken.
    rooms: Vec<Room>,
    ledges: usize,
    decoys: usize,
    /// The first room the player can still walk back to from the last one
    /// (a teleporter is one way).
    reachable_from: usize,
}

struct Room {
    sector: usize,
    x: i64,
    floor: i64,
    north: [bool; 2],
    south: bool,
}

impl Layout {
    fn room(&mut self, x: i64, floor: i64, note: String) -> usize {
        let sector = self.b.sector(rect(x, 0, x + ROOM_W, ROOM_H), floor, floor + ROOM_CEILING, "FLOOR", note);
        self.rooms.push(Room { sector, x, floor, north: [false; 2], south: false });
        self.rooms.len() - 1
    }

    /// A free north slot of room `r` (its x), taken.
    fn north_slot(&mut self, r: usize) -> Option<i64> {
        let room = &mut self.rooms[r];
        let free: Vec<usize> = (0..2).filter(|&k| !room.north[k]).collect();
        let &k = free.get(self.rng.random_range(0..free.len().max(1)))?;
        room.north[k] = true;
        Some(room.x + 32 + 144 * k as i64)
    }

    /// A dead-end ledge up a lift in the north slot at `x` of room `r`: the
    /// lift is called only by a switch on its face, from the room; nothing
    /// up there calls it back. Its sector.
    fn ledge(&mut self, r: usize, x: i64) -> usize {
        let (room, floor) = (self.rooms[r].sector, self.rooms[r].floor);
        let top = floor + LEDGE_RISE;
        let lift = self.b.sector(
            rect(x, ROOM_H, x + 128, ROOM_H + 64),
            top,
            top + 128,
            "TILE",
            format!("Lift up to room {r}'s ledge"),
        );
        let ledge = self.b.sector(
            rect(x, ROOM_H + 64, x + 128, ROOM_H + 160),
            top,
            top + 128,
            "FLOOR",
            format!("Room {r}'s dead-end ledge, {LEDGE_RISE} up: no line up here calls the lift"),
        );
        let tag = self.b.tag(lift);
        self.b.between(room, lift, format!("LineSpecial(on: Use, repeat: true, tag: {tag}, action: Lift())"), "STONE");
        self.ledges += 1;
        ledge
    }

    /// A switch doing `special` in room `r` (or up on a ledge of it, now and
    /// then, or when `ledge`).
    fn switch(&mut self, r: usize, special: String, note: &str, ledge: bool) {
        let x = self.north_slot(r).expect("generator bug: no free north slot for a switch");
        if ledge {
            let top = self.ledge(r, x);
            let y = self.b.sectors[top].rect.y1;
            self.b.wall((x + 32, y), (x + 96, y), special, "SWITCH1", &format!("{note} (on room {r}'s ledge)"));
        } else {
            self.b.wall((x + 32, ROOM_H), (x + 96, ROOM_H), special, "SWITCH1", &format!("{note} (in room {r})"));
        }
    }

    /// A side room south of room `r`, through a doorway (or a door); its
    /// sector.
    fn side_room(&mut self, r: usize, note: &str) -> usize {
        let Room { sector: room, x, floor, .. } = self.rooms[r];
        self.rooms[r].south = true;
        let way = self.b.sector(rect(x + 128, -64, x + 192, 0), floor, floor + 128, "FLOOR", format!("Way to {note}"));
        let side = self.b.sector(rect(x + 64, -256, x + 256, -64), floor, floor + 128, "FLOOR", note.to_string());
        if self.rng.random_bool(0.5) {
            // A door halfway along the way.
            self.b.sectors[way].ceiling = floor;
            self.b.sectors[way].note = format!("Door to {note}");
            let door = "LineSpecial(on: Use, repeat: true, action: Door(kind: Raise))".to_string();
            self.b.between(room, way, door.clone(), "DOOR");
            self.b.between(side, way, door, "DOOR");
        }
        side
    }
}

/// The level of `seed`, with monsters or not.
pub fn generate(seed: u64, monsters: bool) -> Puzzle {
    let mut l = Layout {
        b: Builder::default(),
        rng: ChaCha8Rng::seed_from_u64(seed),
        rooms: Vec::new(),
        ledges: 0,
        decoys: 0,
        reachable_from: 0,
    };
    // The links: the seed's own kind first (a run of seeds covers them all),
    // then at random; never two teleporters in a row (the room one lands in
    // is left by its own door or switch).
    let count = l.rng.random_range(3..=5);
    let mut links = vec![LINKS[(seed % LINKS.len() as u64) as usize]];
    while links.len() < count {
        let next = LINKS[l.rng.random_range(0..LINKS.len())];
        if !(next == Link::Teleport && links.last() == Some(&Link::Teleport)) {
            links.push(next);
        }
    }
    // A ledge at least every third seed.
    let force_ledge = seed % 3 == 0;
    let mut colours = vec!["blue", "yellow", "red"];
    let mut keys = Vec::new();
    let mut x = 0;
    let mut r = l.room(0, 0, "Room 0: the start".to_string());
    l.b.thing("player_start", (48, 128), 0);
    for (i, link) in links.clone().into_iter().enumerate() {
        let Room { sector: here, floor, .. } = l.rooms[r];
        let x0 = x + ROOM_W;
        let want_ledge = l.rng.random_bool(0.3) || (force_ledge && l.ledges == 0);
        let (next_floor, width) = match link {
            Link::Lift => (floor + [64, 96, 128][l.rng.random_range(0..3)], 128),
            Link::Stairs8 => {
                let n = l.rng.random_range(5..=8);
                (floor + 8 * n, 32 * n)
            }
            Link::Stairs16 => {
                let n = l.rng.random_range(3..=5);
                (floor + 16 * n, 32 * n)
            }
            Link::Teleport => (floor + [-32, 0, 64][l.rng.random_range(0..3)], 128),
            Link::LowerFloor => (floor, 160),
            _ => (floor, 128),
        };
        let nx = x0 + width;
        let next = l.room(nx, next_floor, format!("Room {}", i + 1));
        let there = l.rooms[next].sector;
        let (y0, y1) = WAY;
        let ceiling = floor.max(next_floor) + 128;
        match link {
            Link::Door | Link::RemoteDoor | Link::KeyDoor => {
                let a = l.b.sector(rect(x0, y0, x0 + 56, y1), floor, ceiling, "FLOOR", format!("Way from room {i}"));
                let kind = format!("{link:?}");
                let door = l.b.sector(rect(x0 + 56, y0, x0 + 72, y1), floor, floor, "FLOOR", format!("{kind}, shut"));
                let c =
                    l.b.sector(rect(x0 + 72, y0, nx, y1), floor, ceiling, "FLOOR", format!("Way to room {}", i + 1));
                match link {
                    Link::RemoteDoor => {
                        let tag = l.b.tag(door);
                        l.b.front(a, door);
                        l.b.front(c, door);
                        let special = format!("LineSpecial(on: Use, tag: {tag}, action: Door(kind: Open))");
                        l.switch(r, special, &format!("the switch that opens the door to room {}", i + 1), want_ledge);
                    }
                    _ => {
                        let key = if link == Link::KeyDoor && !colours.is_empty() {
                            let colour = colours.remove(l.rng.random_range(0..colours.len()));
                            let card: &'static str = match colour {
                                "blue" => "blue_card",
                                "yellow" => "yellow_card",
                                _ => "red_card",
                            };
                            keys.push(card);
                            // Where: up on this room's ledge, or in a side
                            // room of a room still reachable.
                            let free: Vec<usize> = (l.reachable_from..=r).filter(|&k| !l.rooms[k].south).collect();
                            let on_ledge = free.is_empty() || (want_ledge && l.rooms[r].north.contains(&false));
                            if on_ledge {
                                let sx = l.north_slot(r).expect("generator bug: no slot for a key ledge");
                                let top = l.ledge(r, sx);
                                let p = l.b.sectors[top].rect.centre();
                                l.b.thing(card, p, 0);
                            } else {
                                let k = free[l.rng.random_range(0..free.len())];
                                let side = l.side_room(k, &format!("the side room with the {colour} key"));
                                let p = l.b.sectors[side].rect.centre();
                                l.b.thing(card, p, 0);
                            }
                            format!(", key: Some({}{})", colour[..1].to_uppercase(), &colour[1..])
                        } else {
                            String::new()
                        };
                        let special = format!("LineSpecial(on: Use, repeat: true, action: Door(kind: Raise{key}))");
                        l.b.between(a, door, special.clone(), "DOOR");
                        l.b.between(c, door, special, "DOOR");
                    }
                }
                l.b.sectors[door].note = format!("{} between rooms {i} and {}, shut", l.b.sectors[door].note, i + 1);
            }
            Link::Lift => {
                let lift = l.b.sector(
                    rect(x0, y0, nx, y1),
                    next_floor,
                    next_floor + 128,
                    "TILE",
                    format!("Lift up from room {i} to room {}", i + 1),
                );
                let tag = l.b.tag(lift);
                let special = format!("LineSpecial(on: Use, repeat: true, tag: {tag}, action: Lift())");
                l.b.between(here, lift, special, "STONE");
            }
            Link::LowerFloor => {
                l.b.sector(rect(x0, y0, x0 + 48, y1), floor, ceiling, "FLOOR", format!("Way from room {i}"));
                let block = l.b.sector(
                    rect(x0 + 48, y0, x0 + 112, y1),
                    floor + 64,
                    floor + ROOM_CEILING,
                    "FLOOR",
                    format!("Raised floor between rooms {i} and {}: a switch lowers it", i + 1),
                );
                l.b.sector(rect(x0 + 112, y0, nx, y1), floor, ceiling, "FLOOR", format!("Way to room {}", i + 1));
                let tag = l.b.tag(block);
                let special = format!("LineSpecial(on: Use, tag: {tag}, action: Floor(to: LowestNeighbourFloor))");
                l.switch(r, special, &format!("the switch that lowers the floor to room {}", i + 1), want_ledge);
            }
            Link::Stairs8 | Link::Stairs16 => {
                let (step, n) = if link == Link::Stairs8 { (8, width / 32) } else { (16, width / 32) };
                let mut steps = Vec::new();
                for k in 0..n {
                    let s = l.b.sector(
                        rect(x0 + 32 * k, y0, x0 + 32 * (k + 1), y1),
                        floor,
                        next_floor + 128,
                        "DIRT",
                        format!("Step {} of the stairs to room {} (rises to {})", k + 1, i + 1, floor + step * (k + 1)),
                    );
                    if let Some(&last) = steps.last() {
                        l.b.front(last, s);
                    }
                    steps.push(s);
                }
                let tag = l.b.tag(steps[0]);
                let action = if step == 8 { "Stairs()" } else { "Stairs(step: 16, speed: 4, crush: true)" };
                let special = format!("LineSpecial(on: Use, tag: {tag}, action: {action})");
                l.switch(r, special, &format!("the switch that builds the stairs to room {}", i + 1), want_ledge);
            }
            Link::Teleport => {
                let pad = l.b.sector(
                    rect(x0, 96, x0 + 64, 160),
                    floor,
                    floor + 128,
                    "TELEPAD",
                    format!("Teleporter from room {i} into room {} (closed)", i + 1),
                );
                let tag = l.b.tag(there);
                let special = format!("LineSpecial(on: Walk, repeat: true, tag: {tag}, action: Teleport)");
                l.b.between(here, pad, special, "STONE");
                l.b.thing("teleport_destination", (nx + 64, 128), 0);
                l.reachable_from = next;
            }
        }
        x = nx;
        r = next;
    }
    // The exit switch, in the middle of the last room's east wall.
    let end = x + ROOM_W;
    l.b.wall((end, 96), (end, 160), "LineSpecial(on: Use, action: Exit)".into(), "EXITSW1", "the exit switch");
    // Decoys: a switch that changes a room's light, a side room that leads
    // nowhere.
    for k in 0..l.rooms.len() {
        if l.rng.random_bool(0.35) && l.rooms[k].north.contains(&false) {
            let tag = l.b.tag(l.rooms[k].sector);
            let special = format!("LineSpecial(on: Use, tag: {tag}, action: Light(Set(96)))");
            let ledge = l.rng.random_bool(0.25);
            l.switch(k, special, "a decoy: it only dims the room", ledge);
            l.decoys += 1;
        }
        if l.rng.random_bool(0.3) && !l.rooms[k].south {
            let side = l.side_room(k, &format!("a dead-end side room off room {k}"));
            let p = l.b.sectors[side].rect.centre();
            l.b.thing("stimpack", p, 0);
            l.decoys += 1;
        }
    }
    // Monsters in the rooms after the first, facing the way the player
    // comes; a clip and a stimpack at the start.
    let mut placed = 0;
    if monsters {
        l.b.thing("clip", (96, 48), 0);
        l.b.thing("stimpack", (96, 208), 0);
        for k in 1..l.rooms.len() {
            // One monster at most a room, and a clip beside the way in
            // for each: a fair fight with the pistol.
            if l.rng.random_bool(0.7) {
                let kind = MONSTERS[l.rng.random_range(0..MONSTERS.len())];
                let p = (l.rooms[k].x + l.rng.random_range(8..17) * 16, l.rng.random_range(3..13) * 16);
                l.b.thing(kind, p, 180);
                l.b.thing("clip", (l.rooms[k].x + 32, 224), 0);
                placed += 1;
            }
        }
    }
    let header = vec![
        format!("A generated puzzle level: tests/puzzle.rs, seed {seed}, monsters {monsters}."),
        format!("Links from the start to the exit room: {links:?}."),
    ];
    let ron = l.b.ron(&format!("Puzzle {seed}"), &header);
    Puzzle { seed, ron, links, keys, ledges: l.ledges, decoys: l.decoys, monsters: placed }
}

/// A map for the ways-back test: the player starts on a bare ledge 96 up,
/// between a pit with no way out (nearer the start) and a room with an
/// alcove; the exit is in a closed room no way reaches. A bot with nothing
/// to do on the ledge should drop into the room, not the pit, before it
/// gives up.
pub fn ledge_over_two_pits() -> String {
    let mut b = Builder::default();
    b.sector(rect(-256, 0, 0, 256), 0, 256, "FLOOR", "A pit with no way out".into());
    b.sector(rect(0, 0, 128, 256), 96, 256, "FLOOR", "The start: a bare ledge 96 up".into());
    b.sector(rect(128, 0, 384, 256), 0, 256, "FLOOR", "A room below the ledge".into());
    b.sector(rect(384, 64, 448, 192), 0, 256, "DIRT", "The room's alcove".into());
    b.sector(rect(640, 0, 768, 256), 0, 128, "FLOOR", "A closed room with the exit".into());
    b.wall((768, 96), (768, 160), "LineSpecial(on: Use, action: Exit)".into(), "EXITSW1", "the exit, out of reach");
    b.thing("player_start", (32, 128), 0);
    b.ron("Ways back", &["Generated by tests/puzzle.rs (ledge_over_two_pits).".to_string()])
}
