//! `Weapon`, `Ammo` and `Misc` sections: onto the weapon actors, the
//! pickups that hold those values in the table, and the report's
//! [`Settings`](crate::actors::dehacked::Settings).

use super::{int32, Run};
use crate::actors::dehacked::doom::{self, doom_info, NO_AMMO, WEAPON_LABELS};
use crate::actors::dehacked::model::{AmmoField, Field, MiscField, WeaponField};
use crate::actors::dehacked::DehackedError;
use crate::actors::{ActorTable, Give, StateId};

impl Run<'_> {
    pub(super) fn weapon(&mut self, number: usize, fields: &[Field<WeaponField>]) -> Result<(), DehackedError> {
        let info = doom_info();
        let Some(w) = self.map.weapons[number] else {
            self.warn(fields.first().map_or(0, |f| f.line), format!("Weapon {number}: no weapon actor (ignored)"));
            return Ok(());
        };
        let element = format!("Weapon {number} ({})", info.weapons[number].name);
        for f in fields {
            let v = f.value;
            if f.key == WeaponField::Ammo {
                let ammo = match v {
                    0..=3 => Some(doom::AMMO[v as usize]),
                    NO_AMMO => None,
                    _ => {
                        self.warn(f.line, format!("{element}: Ammo type {v} is none of Doom's (ignored)"));
                        continue;
                    }
                };
                if let Some(def) = self.table.actors[w].weapon.as_mut() {
                    def.ammo = ammo;
                }
                continue;
            }
            let slot =
                [WeaponField::Up, WeaponField::Down, WeaponField::Ready, WeaponField::Attack, WeaponField::Flash]
                    .iter()
                    .position(|&x| x == f.key)
                    .unwrap_or(0);
            if v == 0 && f.key != WeaponField::Flash {
                let m = format!(
                    "{element}: {} = 0 leaves the weapon without its {} state",
                    f.key.key(),
                    WEAPON_LABELS[slot]
                );
                return Err(self.error(f.line, m));
            }
            self.set_label(w, WEAPON_LABELS[slot], v as usize);
            // The chaingun's and plasma gun's second flash is Flash+1 by
            // number, in Doom and in the simulation alike.
            if f.key == WeaponField::Flash && (number == 3 || number == 5) && v != 0 {
                let (first, second) = (self.state(v as usize), self.state(v as usize + 1));
                if first.map(|s| StateId(s.0 + 1)) != second {
                    let m = format!("{element}: Firing frame {v}: the state after it here is not frame {}", v + 1);
                    self.warn(f.line, m);
                }
            }
        }
        Ok(())
    }

    pub(super) fn ammo(&mut self, number: usize, fields: &[Field<AmmoField>]) {
        let kind = doom::AMMO[number].index();
        for f in fields {
            let v = f.value.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
            match f.key {
                AmmoField::Max => self.report.settings.max_ammo[kind] = v,
                AmmoField::PerClip => {
                    self.report.settings.clip_ammo[kind] = v;
                    for &(a, g, _, count) in self.clip_counts.iter().filter(|c| c.2 == number) {
                        if let Some(Give::Ammo(_, amount)) =
                            self.table.actors[a].pickup.as_mut().map(|p| &mut p.give[g])
                        {
                            *amount = count.saturating_mul(v);
                        }
                    }
                }
            }
        }
    }

    pub(super) fn misc(&mut self, fields: &[Field<MiscField>]) -> Result<(), DehackedError> {
        use MiscField::*;
        for f in fields {
            let v = int32(f.value, f.key.key()).map_err(|m| self.error(f.line, format!("Misc: {m}")))?;
            let s = &mut self.report.settings;
            match f.key {
                InitialHealth => s.initial_health = v,
                InitialBullets => s.initial_bullets = v,
                MaxHealth => s.max_health = v,
                MaxArmor => s.max_armor = v,
                GreenArmorClass => s.green_armor_class = v,
                BlueArmorClass => s.blue_armor_class = v,
                MaxSoulsphere => s.max_soulsphere = v,
                SoulsphereHealth => s.soulsphere_health = v,
                MegasphereHealth => s.megasphere_health = v,
                GodModeHealth => s.god_mode_health = v,
                IdfaArmor => s.idfa_armor = v,
                IdfaArmorClass => s.idfa_armor_class = v,
                IdkfaArmor => s.idkfa_armor = v,
                IdkfaArmorClass => s.idkfa_armor_class = v,
                BfgCellsPerShot => s.bfg_cells_per_shot = v,
                MonstersInfight => match v {
                    202 => s.species_infighting = false,
                    221 => s.species_infighting = true,
                    _ => self.warn(f.line, format!("Misc: Monsters Infight {v} is neither 202 (off) nor 221 (on)")),
                },
            }
            if matches!(f.key, GreenArmorClass | BlueArmorClass) && !(0..=255).contains(&v) {
                return Err(self.error(f.line, format!("Misc: {} {v} is not an armour class", f.key.key())));
            }
        }
        let set: Vec<MiscField> = fields.iter().map(|f| f.key).collect();
        self.misc_pickups(&set);
        Ok(())
    }

    /// The settings that pickups hold in the table (P_TouchSpecialThing's
    /// uses of them), those of `set` only: a modder's table may have its
    /// own values for the others.
    pub(super) fn misc_pickups(&mut self, set: &[MiscField]) {
        use MiscField::*;
        let s = self.report.settings.clone();
        let has = |keys: &[MiscField]| keys.iter().any(|k| set.contains(k));
        let info = doom_info();
        let actor = |mt: &str| info.thing(mt).and_then(|k| self.map.things[k]);
        let targets = [
            actor("MT_MISC2"),
            actor("MT_MISC3"),
            actor("MT_MISC0"),
            actor("MT_MISC1"),
            actor("MT_MISC12"),
            actor("MT_MEGA"),
        ];
        let [mut bonus, mut armor_bonus, mut green, mut blue, mut soul, mut mega] = targets;
        for (target, keys) in [
            (&mut bonus, &[MaxHealth][..]),
            (&mut armor_bonus, &[MaxArmor]),
            (&mut green, &[GreenArmorClass]),
            (&mut blue, &[BlueArmorClass]),
            (&mut soul, &[SoulsphereHealth, MaxSoulsphere]),
            (&mut mega, &[MegasphereHealth]),
        ] {
            if !has(keys) {
                *target = None;
            }
        }
        let gives = |table: &mut ActorTable, a: Option<usize>, f: &dyn Fn(&mut Give)| {
            if let Some(p) = a.and_then(|a| table.actors[a].pickup.as_mut()) {
                p.give.iter_mut().for_each(f);
            }
        };
        gives(self.table, bonus, &|g| {
            if let Give::Health { max, .. } = g {
                *max = s.max_health
            }
        });
        gives(self.table, armor_bonus, &|g| {
            if let Give::ArmorBonus { max, .. } = g {
                *max = s.max_armor
            }
        });
        // DOS DeHackEd changes the armours' classes, not the helmet's or the
        // megasphere's; P_GiveArmor gives 100 points a class.
        for (a, class) in [(green, s.green_armor_class), (blue, s.blue_armor_class)] {
            gives(self.table, a, &|g| {
                if let Give::Armor { points, class: c } = g {
                    (*points, *c) = (class * 100, class as u8)
                }
            });
        }
        gives(self.table, soul, &|g| {
            if let Give::Health { amount, max } = g {
                (*amount, *max) = (s.soulsphere_health, s.max_soulsphere)
            }
        });
        // The megasphere sets health to the value: so does giving that much,
        // capped at it.
        gives(self.table, mega, &|g| {
            if let Give::Health { amount, max } = g {
                (*amount, *max) = (s.megasphere_health, s.megasphere_health)
            }
        });
        let bfg = self.map.weapons[6].filter(|_| has(&[BfgCellsPerShot]));
        if let Some(def) = bfg.and_then(|w| self.table.actors[w].weapon.as_mut()) {
            def.ammo_use = s.bfg_cells_per_shot;
        }
    }
}
