//! What `check` found, and the report's text.

use super::super::nav::CELL;

/// What `check` found.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Report {
    pub map: String,
    /// Some exit can be reached (with every key and switch that can be).
    pub exit_reachable: bool,
    /// The map has an exit line (or a boss brain whose death ends it).
    pub has_exit: bool,
    /// Its exit lines (the other `exits` are boss brains).
    pub exit_lines: usize,
    pub exits: Vec<Place>,
    pub keys: Vec<KeyReport>,
    pub secrets: Vec<Place>,
    /// Items (pickups) that can and cannot be reached.
    pub items: Vec<Place>,
    pub soft_locks: Vec<SoftLock>,
    /// Special lines set off whose end cannot be foretold, and why: the
    /// closure assumes they change nothing.
    pub unforeseen: Vec<String>,
    /// The switches and walk lines the closure had to set off.
    pub triggers_used: usize,
    /// Reachable and standable cells.
    pub reachable_cells: usize,
    pub standable_cells: usize,
}

/// A place in the map and whether the player can get to it.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Place {
    pub what: String,
    pub x: f64,
    pub y: f64,
    pub reachable: bool,
    /// Unreachable: the first obstacle on the best way there.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub obstacle: Option<String>,
}

#[derive(Clone, Debug, serde::Serialize)]
pub struct KeyReport {
    pub colour: String,
    pub x: f64,
    pub y: f64,
    pub reachable: bool,
    /// Unreachable, but reachable if doors of its own colour opened without it.
    pub behind_own_door: bool,
    /// Unreachable: the first obstacle on the best way there.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub obstacle: Option<String>,
}

/// A one-way move (a drop, a running jump, a teleport) from where the exit can be reached
/// to where it cannot.
#[derive(Clone, Debug, serde::Serialize)]
pub struct SoftLock {
    pub from_sector: usize,
    pub to_sector: usize,
    pub x: f64,
    pub y: f64,
    pub how: String,
}

impl Report {
    /// The report as text, one finding per line.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let yes = |b: bool| if b { "reachable" } else { "NOT reachable" };
        let because = |o: &Option<String>| o.as_ref().map(|o| format!(": {o}")).unwrap_or_default();
        if self.has_exit && self.exit_lines == 0 {
            out += &format!(
                "{}: no exit line; the map ends when a boss brain dies, and killing one is {}\n",
                self.map,
                if self.exit_reachable { "within reach" } else { "NOT within reach" }
            );
        } else if self.has_exit {
            out += &format!("{}: the exit is {}\n", self.map, yes(self.exit_reachable));
        } else {
            out += &format!(
                "{}: this map has no exit (no exit line, switch or boss brain); it ends only by other means, if any \
                 (a boss's death on the maps Doom gives one, a death exit, a script)\n",
                self.map
            );
        }
        for e in &self.exits {
            out += &format!("  {} at ({:.0}, {:.0}): {}{}\n", e.what, e.x, e.y, yes(e.reachable), because(&e.obstacle));
        }
        for k in &self.keys {
            let own = if k.behind_own_door { " (it is behind a door of its own colour)" } else { "" };
            out += &format!(
                "  {} key at ({:.0}, {:.0}): {}{own}{}\n",
                k.colour,
                k.x,
                k.y,
                yes(k.reachable),
                because(&k.obstacle)
            );
        }
        for s in &self.secrets {
            out += &format!("  {} at ({:.0}, {:.0}): {}\n", s.what, s.x, s.y, yes(s.reachable));
        }
        let reached = self.items.iter().filter(|i| i.reachable).count();
        out += &format!("  items: {reached} of {} reachable\n", self.items.len());
        for i in self.items.iter().filter(|i| !i.reachable) {
            out += &format!("    {} at ({:.0}, {:.0}): NOT reachable\n", i.what, i.x, i.y);
        }
        for u in &self.unforeseen {
            out += &format!("  cannot be foretold, taken as changing nothing: {u}\n");
        }
        if self.soft_locks.is_empty() {
            out += "  no soft locks\n";
        }
        for s in &self.soft_locks {
            out += &format!(
                "  soft lock: {} from sector {} into sector {} at ({:.0}, {:.0}) leaves the exit unreachable\n",
                s.how, s.from_sector, s.to_sector, s.x, s.y
            );
        }
        out += &format!(
            "  {} of {} standable cells ({}x{} units) reachable, {} switches and walk lines used\n",
            self.reachable_cells, self.standable_cells, CELL, CELL, self.triggers_used
        );
        out
    }
}
