//! Validation's last phase: what the map's specials and things mean, checked
//! once the geometry is known to be sound. A special must name something
//! (its tag a sector, its missing tag a sector behind its line, its
//! teleporter a destination, its lock a key the map holds); a version-2
//! thing must be of a known type.

use super::load::{Problem, SpecialAt};
use super::special::{Action, KeyColour, LineSpecial};
use super::Map;
use crate::actors::{ActorTable, Category};

/// The thing kind teleporters aim for.
pub const TELEPORT_DESTINATION: &str = "teleport_destination";

pub fn check(map: &Map) -> Vec<Problem> {
    let mut problems = Vec::new();
    let types = ActorTable::active();
    if map.version >= 2 {
        for (i, t) in map.things.iter().enumerate() {
            if types.get(&t.kind).is_none() {
                problems.push(Problem::UnknownThing {
                    thing: i,
                    kind: t.kind.clone(),
                    nearest: types.nearest(&t.kind).map(str::to_string),
                });
            }
        }
    }
    let keys: Vec<KeyColour> = map.things.iter().filter_map(|t| types.get(&t.kind)?.key()).collect();
    let specials = map
        .lines
        .iter()
        .enumerate()
        .filter_map(|(i, l)| l.special.as_ref().map(|s| (SpecialAt::Line(i), s, l.back.is_some())));
    let triggers = map.trigger_lines.iter().enumerate().map(|(i, t)| (SpecialAt::TriggerLine(i), &t.special, false));
    for (at, special, two_sided) in specials.chain(triggers) {
        check_special(map, at, special, two_sided, &keys, &mut problems);
    }
    problems
}

fn check_special(
    map: &Map,
    at: SpecialAt,
    special: &LineSpecial,
    two_sided: bool,
    keys: &[KeyColour],
    problems: &mut Vec<Problem>,
) {
    let action = &special.action;
    let name = action.name();
    if action.moves_sectors() {
        if special.tag == 0 && !two_sided {
            problems.push(Problem::NoBackSector { at, action: name });
        }
        if special.tag != 0 && map.sectors_tagged(special.tag).next().is_none() {
            problems.push(Problem::TagMatchesNothing { at, action: name, tag: special.tag });
        }
    }
    match *action {
        Action::Door { key: Some(colour), .. } if !keys.contains(&colour) => {
            problems.push(Problem::MissingKey { at, colour: colour.name() });
        }
        Action::Teleport => {
            let sector_of = |i: usize| {
                let p = map.things[i].pos;
                map.sectors_near(p).into_iter().find(|&s| map.sectors[s].tag == special.tag)
            };
            if teleport_destination(map, special.tag, sector_of).is_none() {
                problems.push(Problem::NoTeleportDestination { at, tag: special.tag });
            }
        }
        Action::LineTeleport { to } => {
            let ok = map.lines.get(to).is_some_and(|l| l.back.is_some()) && at != SpecialAt::Line(to);
            if !ok {
                problems.push(Problem::BadTeleportLine { at, to });
            }
        }
        _ => {}
    }
}

/// Is `kind` a teleport destination? (Both versions use the type's name.)
pub fn is_teleport_destination(kind: &str) -> bool {
    kind == TELEPORT_DESTINATION
        || ActorTable::active().get(kind).is_some_and(|t| t.category == Category::TeleportDestination)
}

/// The teleport destination Doom's EV_Teleport would pick: in the first
/// sector tagged `tag` (by index) that holds one, the first in thing order.
/// `sector_of` places a thing (validation has no BSP yet; play locates
/// through it), or answers `None` for one the game did not spawn (a
/// destination for other skills or for multiplayer only is no destination).
pub fn teleport_destination(map: &Map, tag: u16, sector_of: impl Fn(usize) -> Option<usize>) -> Option<usize> {
    let destinations: Vec<(usize, usize)> = (0..map.things.len())
        .filter(|&i| is_teleport_destination(&map.things[i].kind))
        .filter_map(|i| Some((sector_of(i)?, i)))
        .collect();
    map.sectors_tagged(tag).find_map(|s| destinations.iter().find(|d| d.0 == s).map(|d| d.1))
}
