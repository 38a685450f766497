//! A `Thing` section onto its actor: mobjinfo's fields in Sightline's
//! units, its `MF_` bits as flags, its sounds and its eight states as
//! labels.

use super::{int32, size, Run};
use crate::actors::dehacked::doom::{self, doom_info, FRACUNIT, THING_LABELS};
use crate::actors::dehacked::model::{Field, ThingField};
use crate::actors::dehacked::DehackedError;
use crate::actors::{ActorFlag, ActorFlags, Category};

impl Run<'_> {
    pub(super) fn thing(
        &mut self,
        line: usize,
        number: usize,
        fields: &[Field<ThingField>],
    ) -> Result<(), DehackedError> {
        let info = doom_info();
        let k = number - 1;
        let Some(a) = self.map.things[k] else {
            self.warn(line, format!("Thing {number}: the table has no {} (ignored)", info.things[k].actor));
            return Ok(());
        };
        let element = format!("Thing {number} ({})", self.table.actors[a].name);
        let mut speed = None;
        for f in fields {
            let fail = |m: String| DehackedError::At {
                path: self.path.to_string(),
                line: f.line,
                message: format!("{element}: {m}"),
            };
            let v = f.value;
            let def = &mut self.table.actors[a];
            use ThingField::*;
            match f.key {
                Doomednum => {
                    def.doomednum = match v {
                        -1 => None,
                        0..=65535 => Some(v as u16),
                        _ => return Err(fail(format!("ID # {v} is not an editor number (0 to 65535, or -1)"))),
                    }
                }
                Health if v < 0 => return Err(fail(format!("Hit points {v} is negative"))),
                Health => def.health = int32(v, "Hit points").map_err(fail)?,
                ReactionTime => def.reaction_time = int32(v, "Reaction time").map_err(fail)?,
                // Doom compares P_Random() (0 to 255) against it: beyond
                // 256 always, below 0 never, as 256 and 0 do.
                PainChance => def.pain_chance = v.clamp(0, 256) as i32,
                Speed => speed = Some((f.line, v)),
                Width => def.radius = size(v, "Width").map_err(fail)?,
                Height => def.height = size(v, "Height").map_err(fail)?,
                Mass => def.mass = int32(v, "Mass").map_err(fail)?,
                Damage => def.damage = int32(v, "Missile damage").map_err(fail)?,
                Bits => {
                    let unsupported = set_bits(&mut def.flags, v as u32);
                    if !unsupported.is_empty() {
                        let m =
                            format!("{element}: Bits {} have no flag in Sightline (ignored)", unsupported.join(", "));
                        self.warn(f.line, m);
                    }
                }
                SeeSound | AttackSound | PainSound | DeathSound | ActiveSound => {
                    let sound = match v {
                        0 => None,
                        n => self.table.sounds.iter().position(|s| *s == info.sounds[n as usize]),
                    };
                    let sounds = &mut self.table.actors[a].sounds;
                    match f.key {
                        SeeSound => sounds.see = sound,
                        AttackSound => sounds.attack = sound,
                        PainSound => sounds.pain = sound,
                        DeathSound => sounds.death = sound,
                        _ => sounds.active = sound,
                    }
                }
                // The player's Melee label is its firing frame (Doom's
                // S_PLAY_ATK2, which doom.exe enters by number); Doom never
                // reads the player's meleestate.
                MeleeFrame if k == 0 => {
                    self.warn(f.line, format!("{element}: Close attack frame is not applied to the player"))
                }
                frame_field => {
                    let slot = [
                        SpawnFrame,
                        SeeFrame,
                        PainFrame,
                        MeleeFrame,
                        MissileFrame,
                        DeathFrame,
                        XDeathFrame,
                        RaiseFrame,
                    ]
                    .iter()
                    .position(|&x| x == frame_field)
                    .unwrap_or(0);
                    self.set_label(a, THING_LABELS[slot], v as usize);
                }
            }
        }
        // A missile's speed is 16.16 map units a tick (P_SpawnMissile); a
        // walker's, whole map units a step (P_Move). Which one is a matter
        // of how Doom moves the thing, judged after the section's Bits.
        if let Some((l, v)) = speed {
            let def = &mut self.table.actors[a];
            let missile = def.category == Category::Projectile || def.has(ActorFlag::Missile);
            let units = if missile { v as f64 / FRACUNIT } else { v as f64 };
            if !(0.0..=4096.0).contains(&units) {
                return Err(self.error(l, format!("{element}: Speed {v} ({units} units) is not within 0 to 4096")));
            }
            def.speed = units;
        }
        Ok(())
    }
}

/// Sets the flags `bits` maps to and clears the others of Doom's; the
/// table's own flags (Boss, E1M8Boss, ...) are Doom's hard-coded
/// behaviours by kind and stay. Returns the bits set that have no flag.
fn set_bits(flags: &mut ActorFlags, bits: u32) -> Vec<&'static str> {
    let mut unsupported = Vec::new();
    let translation = 0xC00_0000;
    for &(bit, name, flag) in &doom::MF_BITS {
        match flag {
            Some(ActorFlag::Translation) => {}
            Some(flag) => flags.set(flag, bits & bit != 0),
            None if bits & bit != 0 => unsupported.push(name),
            None => {}
        }
    }
    flags.set(ActorFlag::Translation, bits & translation != 0);
    unsupported
}
