//! A UDMF map as Doom-format records ([`WadMap`]), so that one importer
//! ([`super::import::convert`]) turns either format into the map model, and
//! a UDMF map is drawn, checked and compiled as a Doom-format one is.
//!
//! What carries over as it is: vertices (at any fraction: the records keep
//! map units as floats), sides, sector heights, flats and light, line flags
//! (Doom's bits, Boom's pass-use), and things with their skill and mode
//! flags (UDMF's five skills fold into Doom's three bits, easy 1-2, normal
//! 3, hard 4-5; the modes into Boom's not-deathmatch and not-co-op bits).
//! In the `doom` namespace a line's special is Doom's number and its tag is
//! `arg0`, and a sector's special and tag (`id`) are Doom's.
//!
//! The `zdoom` namespace's sector specials are ZDoom's Hexen-style numbers:
//! those with a Doom meaning (Doom's types moved up by 64, the lava floors,
//! instant death, and the damage and secret bits 256-1024) become the map
//! model's [`SectorSpecial`] in [`Records::sector_specials`], which the
//! caller puts on the converted sectors; a thing's id, special and
//! arguments do not fit Doom's records and are read by the game from the
//! [`UdmfMap`] itself (`sim::from_map::level_from_udmf`).
//!
//! What does not yet: the `zdoom` namespace's line specials with their five
//! arguments, and the other sector specials (phased lights, ...). Each is
//! listed in [`Records::unread`], never dropped silently. A value Doom's
//! 16-bit records cannot hold (a height or offset past ±32767, a thing
//! type past 65535) is refused, naming the record.

use super::level::{flags, WadLine, WadMap, WadSector, WadSide, WadThing};
use super::udmf::{Namespace, UdmfMap};
use crate::map::special::{Damage, SectorSpecial, Suit};

/// A UDMF map's Doom-format records and what they leave out.
#[derive(Clone, Debug, PartialEq)]
pub struct Records {
    pub map: WadMap,
    /// One line for each special the records cannot say.
    pub unread: Vec<String>,
    /// A ZDoom sector special's meaning, by sector, for the sectors whose
    /// special Doom's numbers cannot say (the records hold 0 there).
    pub sector_specials: Vec<(usize, SectorSpecial)>,
}

/// Thing option bits (`MTF_*`): Doom's skills and ambush, its not-in-single
/// player bit, Boom's not-deathmatch and not-co-op, MBF's friend.
mod mtf {
    pub const EASY: u16 = 1;
    pub const NORMAL: u16 = 2;
    pub const HARD: u16 = 4;
    pub const AMBUSH: u16 = 8;
    pub const NOT_SINGLE: u16 = 16;
    pub const NOT_DEATHMATCH: u16 = 32;
    pub const NOT_COOP: u16 = 64;
    pub const FRIEND: u16 = 128;
}

/// Line flag bits past Doom's seven.
const ML_DONT_DRAW: u16 = 0x0080;
const ML_MAPPED: u16 = 0x0100;
/// Boom's pass-use.
const ML_PASS_USE: u16 = 0x0200;

/// `value` in Doom's 16-bit signed field, or why not.
fn short(what: &str, value: i64) -> Result<i16, String> {
    i16::try_from(value).map_err(|_| format!("{what} = {value} does not fit Doom's 16-bit field (-32768 to 32767)"))
}

/// `value` in an unsigned 16-bit field, or why not.
fn unsigned(what: &str, value: i64) -> Result<u16, String> {
    u16::try_from(value).map_err(|_| format!("{what} = {value} does not fit Doom's 16-bit field (0 to 65535)"))
}

/// The bits whose flag is set, or'ed together.
fn set_bits(bits: &[(bool, u16)]) -> u16 {
    bits.iter().filter(|(on, _)| *on).fold(0, |acc, (_, bit)| acc | bit)
}

impl UdmfMap {
    /// The map as Doom-format records, named `name`.
    pub fn to_records(&self, name: &str) -> Result<Records, String> {
        let doom = self.namespace == Namespace::Doom;
        let mut unread = Vec::new();
        let mut sector_specials = Vec::new();
        let vertices = self.vertices.iter().map(|v| (v.x, v.y)).collect();
        let mut sectors = Vec::with_capacity(self.sectors.len());
        for (i, s) in self.sectors.iter().enumerate() {
            let what = |field: &str| format!("sector {i}: {field}");
            let special = match (doom, s.special) {
                (_, 0) => 0,
                (true, n) => short(&what("special"), n)?,
                (false, n) => {
                    match zdoom_sector_special(n) {
                        Some(special) => sector_specials.push((i, special)),
                        None => unread.push(format!("sector {i}: ZDoom sector special {n} (not translated yet)")),
                    }
                    0
                }
            };
            sectors.push(WadSector {
                floor: short(&what("heightfloor"), s.floor)?,
                ceiling: short(&what("heightceiling"), s.ceiling)?,
                floor_flat: s.floor_texture.to_ascii_uppercase(),
                ceiling_flat: s.ceiling_texture.to_ascii_uppercase(),
                light: short(&what("lightlevel"), s.light)?,
                special,
                tag: unsigned(&what("id"), s.id)?,
            });
        }
        let mut sides = Vec::with_capacity(self.sides.len());
        for (i, s) in self.sides.iter().enumerate() {
            let what = |field: &str| format!("sidedef {i}: {field}");
            sides.push(WadSide {
                x_offset: short(&what("offsetx"), s.offset_x)?,
                y_offset: short(&what("offsety"), s.offset_y)?,
                upper: s.top.to_ascii_uppercase(),
                lower: s.bottom.to_ascii_uppercase(),
                middle: s.middle.to_ascii_uppercase(),
                sector: unsigned(&what("sector"), s.sector as i64)?,
            });
        }
        let mut lines = Vec::with_capacity(self.lines.len());
        for (i, l) in self.lines.iter().enumerate() {
            let what = |field: &str| format!("linedef {i}: {field}");
            let f = l.flags;
            let bits = [
                (f.blocking, flags::BLOCKING),
                (f.block_monsters, flags::BLOCK_MONSTERS),
                (f.two_sided, flags::TWO_SIDED),
                (f.upper_unpegged, flags::UPPER_UNPEGGED),
                (f.lower_unpegged, flags::LOWER_UNPEGGED),
                (f.secret, flags::SECRET),
                (f.block_sound, flags::BLOCK_SOUND),
                (f.dont_draw, ML_DONT_DRAW),
                (f.mapped, ML_MAPPED),
                (f.pass_use, ML_PASS_USE),
            ];
            let (special, tag) = match (doom, l.special) {
                (_, 0) => (0, 0),
                (true, n) => (unsigned(&what("special"), n)?, unsigned(&what("arg0 (the tag)"), l.args[0])?),
                (false, n) => {
                    unread.push(format!(
                        "linedef {i}: ZDoom line special {n} with arguments {:?} (not translated yet)",
                        l.args
                    ));
                    (0, 0)
                }
            };
            lines.push(WadLine {
                v1: unsigned(&what("v1"), l.v1 as i64)?,
                v2: unsigned(&what("v2"), l.v2 as i64)?,
                flags: set_bits(&bits),
                special,
                tag,
                right: Some(unsigned(&what("sidefront"), l.front as i64)?),
                left: l.back.map(|b| unsigned(&what("sideback"), b as i64)).transpose()?,
            });
        }
        let mut things = Vec::with_capacity(self.things.len());
        for (i, t) in self.things.iter().enumerate() {
            let what = |field: &str| format!("thing {i}: {field}");
            let g = t.flags;
            let bits = [
                (g.skills[0] || g.skills[1], mtf::EASY),
                (g.skills[2], mtf::NORMAL),
                (g.skills[3] || g.skills[4], mtf::HARD),
                (g.ambush, mtf::AMBUSH),
                (!g.single, mtf::NOT_SINGLE),
                (!g.deathmatch, mtf::NOT_DEATHMATCH),
                (!g.coop, mtf::NOT_COOP),
                (g.friend, mtf::FRIEND),
            ];
            things.push(WadThing {
                // Doom's mapthing_t holds whole units: the nearest.
                x: short(&what("x"), t.x.round() as i64)?,
                y: short(&what("y"), t.y.round() as i64)?,
                angle: t.angle.rem_euclid(360) as i16,
                kind: unsigned(&what("type"), t.kind)?,
                flags: set_bits(&bits),
            });
        }
        let map = WadMap { name: name.to_ascii_uppercase(), things, lines, sides, vertices, sectors };
        Ok(Records { map, unread, sector_specials })
    }
}

impl super::Wad {
    /// UDMF map `name` as Doom-format records ([`UdmfMap::to_records`]);
    /// errors name the file and the map's TEXTMAP.
    pub fn udmf_records(&self, name: &str) -> Result<Records, super::WadError> {
        let label = format!("{}/{}", name.to_ascii_uppercase(), super::udmf::TEXTMAP);
        self.udmf(name)?.to_records(name).map_err(|e| self.error(&label, e))
    }

    /// Map `name` as Doom-format records, whichever format the WAD keeps
    /// it in.
    pub fn map_records(&self, name: &str) -> Result<Records, super::WadError> {
        if self.is_udmf(name) {
            self.udmf_records(name)
        } else {
            Ok(Records { map: self.map(name)?, unread: Vec::new(), sector_specials: Vec::new() })
        }
    }
}

/// ZDoom's sector special `n` (Hexen numbering, as the `zdoom` namespace
/// keeps it) in the map model, when it says something Doom's rules do (as
/// ViZDoom's ZDoom 2.8 sets them up, `P_SpawnSpecials`; see
/// `docs/zdoom-facts.md`): Doom's types 1-17 moved up by 64, the lava
/// floors (82: 5, 83: 8 damage every 32 tics, through a suit), instant
/// death (115: ZDoom's million every tic, here the map model's
/// most, 1000), and the bits over the low byte (256,
/// 512, 768: Boom's 5, 10 and 20 damage every 32 tics; 1024: a secret).
/// `None` for the rest.
pub fn zdoom_sector_special(n: i64) -> Option<SectorSpecial> {
    let low = n & 0xff;
    let mut special = match low {
        0 => SectorSpecial::default(),
        65..=81 => super::specials::sector_special((low - 64) as i16).ok()?,
        82 | 83 => {
            let amount = if low == 82 { 5 } else { 8 };
            let damage = Damage { amount, every: 32, exit_below: 0, suit: Suit::Useless };
            SectorSpecial { damage: Some(damage), ..SectorSpecial::default() }
        }
        115 => {
            // ZDoom's million; the map model's most, 1000, kills as surely
            // (god mode too, as Doom's telefrag does).
            let damage = Damage { amount: 1000, every: 1, exit_below: 0, suit: Suit::Useless };
            SectorSpecial { damage: Some(damage), ..SectorSpecial::default() }
        }
        _ => return None,
    };
    let amount = match n & 0x300 {
        0x100 => Some(5),
        0x200 => Some(10),
        0x300 => Some(20),
        _ => None,
    };
    if let Some(amount) = amount {
        let suit = if amount >= 20 { Suit::Leaks } else { Suit::Shields };
        special.damage = Some(Damage { amount, every: 32, exit_below: 0, suit });
    }
    special.secret |= n & 0x400 != 0;
    (n & !0x7ff == 0).then_some(special)
}
