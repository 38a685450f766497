//! A `Frame` section onto every state that is the frame, and frame 966's
//! overflow into the fist.

use super::{int32, Run, LAST_FRAME};
use crate::actors::dehacked::doom::{self, doom_info, FULL_BRIGHT};
use crate::actors::dehacked::model::{Field, FrameField, WeaponField};
use crate::actors::dehacked::DehackedError;
use crate::actors::StateId;

impl Run<'_> {
    /// Applies a frame's fields to every state that is it; returns them.
    pub(super) fn frame(
        &mut self,
        line: usize,
        number: usize,
        fields: &[Field<FrameField>],
    ) -> Result<Vec<StateId>, DehackedError> {
        if number == 0 {
            self.warn(line, "Frame 0 is S_NULL, which is never shown (ignored)");
            return Ok(Vec::new());
        }
        if number == doom::NUM_STATES - 1 {
            self.frame_overflow(line, fields)?;
            return Ok(Vec::new());
        }
        self.state(number);
        let copies = self.map.frames[number].clone();
        let element = format!("Frame {number} ({})", doom_info().states[number].name);
        for f in fields {
            let v = f.value;
            match f.key {
                FrameField::Sprite => {
                    let sprite = self.sprite_index(v as usize);
                    copies.iter().for_each(|id| self.table.states[id.0 as usize].sprite = sprite);
                }
                FrameField::Subnumber => {
                    let frame = v & !FULL_BRIGHT;
                    if !(0..=LAST_FRAME).contains(&frame) {
                        let m = format!("{element}: Sprite subnumber {v}: frame {frame} is past `]` ({LAST_FRAME})");
                        return Err(self.error(f.line, m));
                    }
                    for id in &copies {
                        let s = &mut self.table.states[id.0 as usize];
                        (s.frame, s.bright) = (frame as u8, v & FULL_BRIGHT != 0);
                    }
                }
                FrameField::Duration => {
                    let mut tics = int32(v, "Duration").map_err(|m| self.error(f.line, format!("{element}: {m}")))?;
                    if tics < -1 {
                        // doom.exe counts such a state down from a negative
                        // number: it never reaches 0, so it stays for ever.
                        self.warn(f.line, format!("{element}: Duration {tics} is read as -1 (for ever)"));
                        tics = -1;
                    }
                    copies.iter().for_each(|id| self.table.states[id.0 as usize].tics = tics);
                    if tics != -1 && self.map.parked.contains(&number) {
                        self.map.parked.retain(|&f| f != number);
                        self.set_next(&copies, doom_info().states[number].next);
                    }
                }
                FrameField::Next => {
                    self.map.parked.retain(|&f| f != number);
                    self.set_next(&copies, v as usize);
                }
                FrameField::Unknown1 | FrameField::Unknown2 if v != 0 => {
                    self.warn(f.line, format!("{element}: {} is MBF's argument field (ignored)", f.key.key()))
                }
                FrameField::Unknown1 | FrameField::Unknown2 => {}
                FrameField::Codep => self.warn(
                    f.line,
                    format!(
                        "{element}: Codep frame is not a Frame field (Chocolate ignores it too; use a Pointer section)"
                    ),
                ),
            }
        }
        Ok(copies)
    }

    /// DOS DeHackEd allots 966 frames, not 967: writing "Frame 966" runs
    /// into weaponinfo[0], the fist's (Chocolate's DEH_FrameOverflow; Batman
    /// Doom cannot switch away from its fist because of it).
    pub(super) fn frame_overflow(&mut self, line: usize, fields: &[Field<FrameField>]) -> Result<(), DehackedError> {
        self.warn(line, "Frame 966 overflows DeHackEd's table into the fist's weapon entry, as in doom.exe");
        for f in fields {
            let field = match f.key {
                FrameField::Duration => WeaponField::Ammo,
                FrameField::Codep => WeaponField::Up,
                FrameField::Next => WeaponField::Down,
                FrameField::Unknown1 => WeaponField::Ready,
                FrameField::Unknown2 => WeaponField::Attack,
                other => {
                    return Err(
                        self.error(f.line, format!("Frame 966: cannot simulate the overflow of {}", other.key()))
                    )
                }
            };
            if field != WeaponField::Ammo && !(0..doom::NUM_STATES as i64).contains(&f.value) {
                return Err(self.error(f.line, format!("Frame 966: frame {} is out of range", f.value)));
            }
            self.weapon(0, &[Field { line: f.line, key: field, value: f.value }])?;
        }
        Ok(())
    }
}
