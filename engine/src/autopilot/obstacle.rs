//! Why `check` cannot reach a place: the first obstacle on the best way
//! there. From every cell the closure reached, a search that ignores
//! heights (only walls stop it; teleports carry it) finds the shortest way
//! to the place; its first move out of the reached cells is the obstacle,
//! named by what stands there: a locked door, a door that opens from the
//! other side only, a ledge, a closed sector, a solid thing, with the line
//! that would move it when there is one.

use std::collections::{BTreeSet, VecDeque};

use super::nav::{Cell, Heights, LineId, NavGrid, NONE};
use super::plan::{line_of, Mechanisms, Targets};
use super::sectors::target_sectors;
use crate::level::Level;
use crate::map::special::{Action, Activation, KeyColour};
use crate::play::player::{HEIGHT, MAX_STEP};

/// What the obstacle search reads: the closure's fixed point.
pub struct Reach<'a> {
    pub nav: &'a NavGrid,
    pub level: &'a Level,
    pub mech: &'a Mechanisms,
    pub heights: &'a Heights,
    pub keys: &'a [KeyColour],
    pub reached: &'a [bool],
    /// Manual doors still shut to those who cannot use them.
    pub shut: &'a [bool],
    pub solid: &'a BTreeSet<Cell>,
    /// The special lines the closure set off.
    pub applied: &'a BTreeSet<LineId>,
}

impl Reach<'_> {
    /// The first obstacle on the shortest way from the reached cells to
    /// `targets` (or across `walk`), in words.
    pub fn first_obstacle(&self, targets: &Targets, walk: Option<LineId>) -> String {
        let nav = self.nav;
        let mut prev = vec![NONE; nav.cells()];
        let mut seen = vec![false; nav.cells()];
        let mut queue = VecDeque::new();
        for c in 0..nav.cells() as Cell {
            if self.reached[c as usize] {
                seen[c as usize] = true;
                queue.push_back(c);
            }
        }
        let mut end = None;
        'search: while let Some(c) = queue.pop_front() {
            for d in 0..8 {
                if !nav.open(c, d) {
                    continue;
                }
                let Some(mut n) = nav.neighbour(c, d) else { continue };
                if nav.centre[n as usize] == NONE {
                    continue;
                }
                let mut crossed_goal = false;
                for (line, front) in nav.crossings_of(c, d) {
                    crossed_goal |= walk == Some(line);
                    let walked = line_of(&self.level.compiled.map, line).3.is_some_and(|s| s.on == Activation::Walk);
                    if let (true, true, Some(&dest)) = (walked, front, self.mech.teleports.get(&line)) {
                        if let Some(t) = nav.standable_near(dest, 2) {
                            n = t;
                        }
                    }
                }
                if seen[n as usize] {
                    continue;
                }
                seen[n as usize] = true;
                prev[n as usize] = c;
                if crossed_goal || targets.contains_cell(n) {
                    end = Some(n);
                    break 'search;
                }
                queue.push_back(n);
            }
        }
        let Some(mut b) = end else {
            return "walled off: no way in from anywhere the player can reach".into();
        };
        while !self.reached[prev[b as usize] as usize] {
            b = prev[b as usize];
        }
        self.describe(prev[b as usize], b)
    }

    /// The move from reached `a` into `b`, in words.
    fn describe(&self, a: Cell, b: Cell) -> String {
        let nav = self.nav;
        let p = nav.centre_of(b);
        let at = format!("at ({:.0}, {:.0})", p.x, p.y);
        if self.solid.contains(&b) {
            return format!("a solid thing {at}");
        }
        let (from, to) = (nav.span(a, self.heights), nav.span(b, self.heights));
        let here = nav.touched(a);
        let new: Vec<usize> = nav.touched(b).iter().filter(|s| !here.contains(s)).map(|&s| s as usize).collect();
        let under: Vec<usize> = if new.is_empty() { nav.touched(b).iter().map(|&s| s as usize).collect() } else { new };
        for &s in &under {
            let doors = &self.mech.doors[s];
            let locked: Vec<KeyColour> =
                doors.iter().filter_map(|&(_, k)| k).filter(|k| !self.keys.contains(k)).collect();
            if !doors.is_empty() && locked.len() == doors.len() {
                let k = locked[0].name();
                return format!("a {k} door (sector {s}) {at}, and no {k} key within reach");
            }
            if self.shut[s] && self.mech.door_use[s].binary_search(&a).is_err() {
                return format!("a door (sector {s}) {at} that opens only from the other side");
            }
        }
        let highest = under.iter().copied().max_by(|&x, &y| self.heights.floor[x].total_cmp(&self.heights.floor[y]));
        if let Some(s) = under.iter().copied().find(|&s| self.heights.ceiling[s] - self.heights.low[s] < HEIGHT) {
            return format!(
                "a closed sector {s} {at} ({:.0} units between floor and ceiling){}",
                (self.heights.ceiling[s] - self.heights.low[s]).max(0.0),
                self.opener(s)
            );
        }
        if let Some(s) = highest.filter(|_| to.low > from.high + MAX_STEP) {
            return format!("a ledge {:.0} units high {at} (sector {s}){}", to.low - from.high, self.opener(s));
        }
        if to.ceiling - to.low.max(from.low) < HEIGHT {
            return format!("a gap too low for the body {at}");
        }
        let (sa, sb) = (nav.centre[a as usize], nav.centre[b as usize]);
        format!("the way from sector {sa} into sector {sb} {at}")
    }

    /// What could move sector `s` but was not set off, in words.
    fn opener(&self, s: usize) -> String {
        let map = &self.level.compiled.map;
        if !self.mech.lift_lines[s].is_empty() {
            let (id, _) = self.mech.lift_lines[s][0];
            let (_, a, b, _) = line_of(map, id);
            let m = (a + b) / 2.0;
            return format!(", a lift called by line {id} at ({:.0}, {:.0}), out of reach from below", m.x, m.y);
        }
        for &id in &self.mech.triggers {
            if self.applied.contains(&id) {
                continue;
            }
            let (sl, a, b, special) = line_of(map, id);
            let Some(special) = special else { continue };
            if !target_sectors(self.level, sl, special).contains(&s) {
                continue;
            }
            let m = (a + b) / 2.0;
            let key = match special.action {
                Action::Door { key: Some(k), .. } if !self.keys.contains(&k) => {
                    format!(" with the {} key, which is out of reach", k.name())
                }
                _ => ", which is out of reach".into(),
            };
            return format!("; line {id} at ({:.0}, {:.0}) would move it ({}){key}", m.x, m.y, special.action.name());
        }
        ", and no line moves it".into()
    }
}
