//! A [`Host`] with no game behind it: it records every call and answers with
//! plausible values (a small inventory it keeps, spawns that succeed, a
//! seeded random generator), so modules can be run and checked without a
//! simulation.

use std::collections::{BTreeSet, HashMap};

use super::host::{Activator, Host, HostCx, PrintKind};
use super::pcodes;

/// One call the VM made, string arguments resolved where the call is known
/// to take them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum HostCall {
    Random { min: i32, max: i32, value: i32 },
    Special { special: i32, args: [i32; 5], activator: Activator },
    Game { pcode: u16, name: &'static str, args: Vec<i32>, text: Option<String>, activator: Activator },
    Function { id: u16, args: Vec<i32> },
    Print { kind: PrintKind, text: String },
}

/// Game pcodes whose first argument is a string (an actor class, an item,
/// a sound, ...), resolved into `HostCall::Game::text`.
const STRING_FIRST: &[u16] = &[143, 145, 147, 149, 151, 153, 155, 165, 223, 224, 288, 289];

#[derive(Clone, Debug)]
pub struct RecordingHost {
    pub calls: Vec<HostCall>,
    /// Item counts `CheckInventory` reports, by item name.
    pub inventory: HashMap<String, i32>,
    /// Sector tags `TagWait` finds busy.
    pub busy_tags: BTreeSet<i32>,
    /// Extended functions reported as supported (all that ZDoom defines by default).
    pub functions: Option<BTreeSet<u16>>,
    /// Keys `has_lock` grants.
    pub locks: BTreeSet<i32>,
    seed: u64,
}

impl Default for RecordingHost {
    fn default() -> RecordingHost {
        RecordingHost {
            calls: Vec::new(),
            inventory: HashMap::new(),
            busy_tags: BTreeSet::new(),
            functions: None,
            locks: BTreeSet::new(),
            seed: 0x9e37_79b9_7f4a_7c15,
        }
    }
}

impl RecordingHost {
    /// The recorded game calls of one pcode (by its stack form's number).
    pub fn game_calls(&self, pcode: u16) -> Vec<&HostCall> {
        self.calls.iter().filter(|c| matches!(c, HostCall::Game { pcode: p, .. } if *p == pcode)).collect()
    }

    /// The recorded line specials of one number.
    pub fn specials(&self, special: i32) -> Vec<[i32; 5]> {
        self.calls
            .iter()
            .filter_map(|c| match c {
                HostCall::Special { special: s, args, .. } if *s == special => Some(*args),
                _ => None,
            })
            .collect()
    }

    /// Printed text, in order.
    pub fn printed(&self) -> Vec<String> {
        self.calls
            .iter()
            .filter_map(|c| match c {
                HostCall::Print { text, .. } => Some(text.clone()),
                _ => None,
            })
            .collect()
    }
}

impl Host for RecordingHost {
    fn random(&mut self, min: i32, max: i32) -> i32 {
        // SplitMix64: deterministic, and every value of the range reachable.
        self.seed = self.seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        let span = (i64::from(max) - i64::from(min) + 1) as u64;
        let value = (i64::from(min) + (z % span) as i64) as i32;
        self.calls.push(HostCall::Random { min, max, value });
        value
    }

    fn line_special(&mut self, special: i32, args: [i32; 5], cx: &mut HostCx) -> i32 {
        self.calls.push(HostCall::Special { special, args, activator: cx.activator });
        1
    }

    fn game(&mut self, pcode: u16, args: &[i32], cx: &mut HostCx) -> i32 {
        let text = if STRING_FIRST.contains(&pcode) {
            args.first().and_then(|&s| cx.strings.get(s)).map(str::to_string)
        } else {
            None
        };
        let item = text.clone().unwrap_or_default();
        let amount = args.get(1).copied().unwrap_or(0);
        let value = match pcode {
            142 => {
                self.inventory.clear();
                0
            }
            143 => {
                *self.inventory.entry(item).or_insert(0) += amount;
                0
            }
            145 => {
                let n = self.inventory.entry(item).or_insert(0);
                *n = (*n - amount).max(0);
                0
            }
            147 => self.inventory.get(&item).copied().unwrap_or(0),
            // Spawns and SetActorPosition succeed; ThingCount finds one thing.
            149 | 151 | 283 | 59 | 288 => 1,
            // PlayerNumber: the first player; a player activator otherwise -1.
            247 => 0,
            _ => 0,
        };
        let name = pcodes::name(pcode);
        self.calls.push(HostCall::Game { pcode, name, args: args.to_vec(), text, activator: cx.activator });
        value
    }

    fn supports_function(&self, id: u16) -> bool {
        match &self.functions {
            Some(set) => set.contains(&id),
            None => pcodes::function_name(id).is_some(),
        }
    }

    fn function(&mut self, id: u16, args: &[i32], _cx: &mut HostCx) -> i32 {
        self.calls.push(HostCall::Function { id, args: args.to_vec() });
        0
    }

    fn print(&mut self, kind: PrintKind, text: &str, _activator: Activator) {
        self.calls.push(HostCall::Print { kind, text: text.to_string() });
    }

    fn sectors_busy(&mut self, tag: i32) -> bool {
        self.busy_tags.contains(&tag)
    }

    fn polyobj_busy(&mut self, _po: i32) -> bool {
        false
    }

    fn has_lock(&mut self, lock: i32, _activator: Activator) -> bool {
        self.locks.contains(&lock)
    }
}
