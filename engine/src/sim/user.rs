//! The player's own thinking (`p_user.c`): `P_PlayerThink`, moving by the
//! command (`P_MovePlayer`, `P_Thrust`), the view's height and bob
//! (`P_CalcHeight`), and dying (`P_DeathThink`). It runs before the
//! thinkers each tic, so the momentum it gives is spent by the body's own
//! `P_MobjThinker` later in the same tic ([`super::movement`]).

use super::mobj::mf;
use super::setup::VIEWHEIGHT;
use super::weapons::wp;
use super::{collision, specials, weapons, GameMode, PlayerState, Sim};
use crate::fixed::{
    finesine, point_to_angle2, Angle, Fixed, ANG180, ANG90, ANGLETOFINESHIFT, FINEANGLES, FINEMASK, FRACUNIT,
};
use crate::play::lmp::buttons;

/// `CF_*`: the cheat bits in [`super::Player::cheats`].
pub mod cf {
    pub const NOCLIP: i32 = 1;
    pub const GODMODE: i32 = 2;
    pub const NOMOMENTUM: i32 = 4;
}

/// `powertype_t`: indices into [`super::Player::powers`].
pub mod pw {
    pub const INVULNERABILITY: usize = 0;
    pub const STRENGTH: usize = 1;
    pub const INVISIBILITY: usize = 2;
    pub const IRONFEET: usize = 3;
    pub const ALLMAP: usize = 4;
    pub const INFRARED: usize = 5;
}

/// `MAXBOB`: 16 pixels of bob at most.
const MAXBOB: Fixed = Fixed(0x10_0000);
/// `INVERSECOLORMAP`: the invulnerability colormap.
const INVERSECOLORMAP: i32 = 32;
/// `ANG5`, the dead player's turn a tic towards the killer.
const ANG5: Angle = Angle(ANG90.0 / 18);

/// `P_Thrust`: pushes player `n`'s body by `move_` along `angle`.
pub fn thrust(sim: &mut Sim, n: usize, angle: Angle, move_: Fixed) {
    let Some(p) = sim.player(n) else { return };
    let fine = (angle.0 >> ANGLETOFINESHIFT) as usize;
    let mo = sim.mo_mut(p.mo);
    mo.momx += move_ * crate::fixed::finecosine(fine);
    mo.momy += move_ * finesine(fine);
}

/// `P_CalcHeight`: the bob from the body's speed, then the eye's height
/// (`viewz`), which squats after a hard landing and climbs back by
/// `deltaviewheight`. `onground` is `p_user.c`'s global of that name as
/// the last `P_MovePlayer` or `P_DeathThink` left it.
pub fn calc_height(sim: &mut Sim, n: usize, onground: bool) {
    let leveltime = sim.leveltime;
    let Some(p) = sim.player(n) else { return };
    let mo = sim.mo(p.mo);
    let (z, ceilingz, momx, momy) = (mo.z, mo.ceilingz, mo.momx, mo.momy);
    let Some(p) = sim.players[n].as_mut() else { return };
    // Needed for the weapon's swing even in the air.
    p.bob = ((momx * momx) + (momy * momy)) >> 2;
    if p.bob > MAXBOB {
        p.bob = MAXBOB;
    }
    if p.cheats & cf::NOMOMENTUM != 0 || !onground {
        // Doom clips a first value to the ceiling and then overwrites it.
        p.viewz = z + p.viewheight;
        return;
    }
    // FINEANGLES/20*leveltime in C's int arithmetic: 409 * leveltime.
    let angle = ((FINEANGLES / 20) as u32).wrapping_mul(leveltime) as usize & FINEMASK;
    let bob = Fixed(p.bob.0 / 2) * finesine(angle);
    if p.playerstate == PlayerState::Live {
        p.viewheight += p.deltaviewheight;
        if p.viewheight > VIEWHEIGHT {
            p.viewheight = VIEWHEIGHT;
            p.deltaviewheight = Fixed::ZERO;
        }
        if p.viewheight < Fixed(VIEWHEIGHT.0 / 2) {
            p.viewheight = Fixed(VIEWHEIGHT.0 / 2);
            if p.deltaviewheight <= Fixed::ZERO {
                p.deltaviewheight = Fixed(1);
            }
        }
        if p.deltaviewheight != Fixed::ZERO {
            p.deltaviewheight += Fixed(FRACUNIT / 4);
            if p.deltaviewheight == Fixed::ZERO {
                p.deltaviewheight = Fixed(1);
            }
        }
    }
    p.viewz = z + p.viewheight + bob;
    if p.viewz > ceilingz - Fixed::from_int(4) {
        p.viewz = ceilingz - Fixed::from_int(4);
    }
}

/// `P_MovePlayer`: the command's turn, then thrust forward and sideways
/// when standing on the floor, and the running frames. Returns `onground`.
pub fn move_player(sim: &mut Sim, n: usize) -> bool {
    let Some(p) = sim.player(n) else { return false };
    let (cmd, id) = (p.cmd, p.mo);
    let mo = sim.mo_mut(id);
    // angleturn is a short shifted up as an int, added to an unsigned angle.
    mo.angle += Angle((i32::from(cmd.turn) << 16) as u32);
    let onground = mo.z <= mo.floorz;
    let angle = mo.angle;
    if cmd.forward != 0 && onground {
        thrust(sim, n, angle, Fixed(i32::from(cmd.forward) * 2048));
    }
    if cmd.side != 0 && onground {
        thrust(sim, n, angle - ANG90, Fixed(i32::from(cmd.side) * 2048));
    }
    let kind = sim.mo(id).kind;
    let info = &sim.info.things[kind];
    let (standing, running) = (info.spawnstate, info.seestate);
    if (cmd.forward != 0 || cmd.side != 0) && sim.mo(id).state == standing && standing.is_some() {
        sim.set_mobj_state(id, running);
    }
    onground
}

/// `P_DeathThink`: the weapon goes on down, the eye sinks to 6 units
/// above the floor, the body turns to face its killer, and use asks for
/// rebirth.
pub fn death_think(sim: &mut Sim, n: usize) {
    weapons::move_psprites(sim, n);
    let Some(p) = sim.players[n].as_mut() else { return };
    let six = Fixed::from_int(6);
    if p.viewheight > six {
        p.viewheight -= Fixed::ONE;
    }
    if p.viewheight < six {
        p.viewheight = six;
    }
    p.deltaviewheight = Fixed::ZERO;
    let id = p.mo;
    let attacker = p.attacker;
    let onground = sim.mo(id).z <= sim.mo(id).floorz;
    calc_height(sim, n, onground);
    let mut fade = false;
    match attacker {
        Some(a) if a != id => {
            let (mx, my, ax, ay) = (sim.mo(id).x, sim.mo(id).y, sim.mo(a).x, sim.mo(a).y);
            let angle = point_to_angle2(mx, my, ax, ay);
            let mo = sim.mo_mut(id);
            let delta = angle - mo.angle;
            if delta < ANG5 || delta.0 > ANG5.0.wrapping_neg() {
                // Looking at the killer: the damage flash fades.
                mo.angle = angle;
                fade = true;
            } else if delta < ANG180 {
                mo.angle += ANG5;
            } else {
                mo.angle -= ANG5;
            }
        }
        _ => fade = true,
    }
    let Some(p) = sim.players[n].as_mut() else { return };
    if fade && p.damagecount != 0 {
        p.damagecount -= 1;
    }
    if p.cmd.buttons & buttons::USE != 0 {
        p.playerstate = PlayerState::Reborn;
    }
}

/// `P_PlayerThink` for player `n`: cheats, the chainsaw's lunge, moving,
/// the view, the sector's special, weapon changes, use, the weapon
/// sprites, and the power counters, in Doom's order.
pub fn player_think(sim: &mut Sim, n: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    let id = p.mo;
    let noclip = p.cheats & cf::NOCLIP != 0;
    let mo = sim.mo_mut(id);
    if noclip {
        mo.flags |= mf::NOCLIP;
    } else {
        mo.flags &= !mf::NOCLIP;
    }
    if sim.mo(id).has(mf::JUSTATTACKED) {
        // The chainsaw's hit pulls the player forward this tic.
        if let Some(p) = sim.players[n].as_mut() {
            p.cmd.turn = 0;
            p.cmd.forward = (0xc800 / 512) as i8;
            p.cmd.side = 0;
        }
        sim.mo_mut(id).flags &= !mf::JUSTATTACKED;
    }
    if sim.player(n).is_some_and(|p| p.playerstate == PlayerState::Dead) {
        death_think(sim, n);
        return;
    }
    // A teleport freezes the player for a while (reactiontime). Doom's
    // `onground` is then the global's value from the last P_MovePlayer;
    // the body stands on the floor it was teleported to, so the test is
    // made again here (it differs only for a teleport landing in the air,
    // which Doom's teleport never does before Final Doom).
    let onground = if sim.mo(id).reactiontime != 0 {
        sim.mo_mut(id).reactiontime -= 1;
        sim.mo(id).z <= sim.mo(id).floorz
    } else {
        move_player(sim, n)
    };
    calc_height(sim, n, onground);
    if sim.level.sectors[sim.sector_of(id)].special != 0 {
        specials::player_in_special_sector(sim, n);
    }
    change_weapon(sim, n);
    let Some(p) = sim.players[n].as_mut() else { return };
    if p.cmd.buttons & buttons::USE != 0 {
        if !p.usedown {
            collision::use_lines(sim, n);
            if let Some(p) = sim.players[n].as_mut() {
                p.usedown = true;
            }
        }
    } else {
        p.usedown = false;
    }
    weapons::move_psprites(sim, n);
    count_down_powers(sim, n);
}

/// The command's weapon change (`BT_CHANGE`), made pending; the weapon
/// sprite carries it out when it is ready. A special event has no other
/// buttons.
fn change_weapon(sim: &mut Sim, n: usize) {
    let mode = sim.rules.mode;
    let Some(p) = sim.players[n].as_mut() else { return };
    if p.cmd.buttons & buttons::SPECIAL != 0 {
        p.cmd.buttons = 0;
    }
    if p.cmd.buttons & buttons::CHANGE == 0 {
        return;
    }
    let mut newweapon = usize::from((p.cmd.buttons & buttons::WEAPON_MASK) >> buttons::WEAPON_SHIFT);
    if newweapon == wp::FIST
        && p.weaponowned[wp::CHAINSAW]
        && !(p.readyweapon == wp::CHAINSAW && p.powers[pw::STRENGTH] != 0)
    {
        newweapon = wp::CHAINSAW;
    }
    if mode == GameMode::Commercial
        && newweapon == wp::SHOTGUN
        && p.weaponowned[wp::SUPERSHOTGUN]
        && p.readyweapon != wp::SUPERSHOTGUN
    {
        newweapon = wp::SUPERSHOTGUN;
    }
    if p.weaponowned.get(newweapon).copied().unwrap_or(false)
        && newweapon != p.readyweapon
        && ((newweapon != wp::PLASMA && newweapon != wp::BFG) || mode != GameMode::Shareware)
    {
        p.pendingweapon = Some(newweapon);
    }
}

/// The power counters (strength counts up, to fade its red), the damage
/// and bonus flashes, and the colormap invulnerability or the visor give.
fn count_down_powers(sim: &mut Sim, n: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    let id = p.mo;
    if p.powers[pw::STRENGTH] != 0 {
        p.powers[pw::STRENGTH] += 1;
    }
    if p.powers[pw::INVULNERABILITY] != 0 {
        p.powers[pw::INVULNERABILITY] -= 1;
    }
    let mut visible = false;
    if p.powers[pw::INVISIBILITY] != 0 {
        p.powers[pw::INVISIBILITY] -= 1;
        visible = p.powers[pw::INVISIBILITY] == 0;
    }
    if p.powers[pw::INFRARED] != 0 {
        p.powers[pw::INFRARED] -= 1;
    }
    if p.powers[pw::IRONFEET] != 0 {
        p.powers[pw::IRONFEET] -= 1;
    }
    if p.damagecount != 0 {
        p.damagecount -= 1;
    }
    if p.bonuscount != 0 {
        p.bonuscount -= 1;
    }
    let flicker = |tics: i32| tics > 4 * 32 || tics & 8 != 0;
    p.fixedcolormap = if p.powers[pw::INVULNERABILITY] != 0 {
        if flicker(p.powers[pw::INVULNERABILITY]) {
            INVERSECOLORMAP
        } else {
            0
        }
    } else if p.powers[pw::INFRARED] != 0 {
        i32::from(flicker(p.powers[pw::INFRARED]))
    } else {
        0
    };
    if visible {
        sim.mo_mut(id).flags &= !mf::SHADOW;
    }
}

#[cfg(test)]
#[path = "player_tests.rs"]
mod tests;
