//! The player's weapons (`p_pspr.c`): the weapon and flash sprites'
//! states (`P_SetPsprite`, `P_MovePsprites`), raising and lowering
//! (`P_BringUpWeapon`, `A_Raise`, `A_Lower`), the trigger (`A_WeaponReady`,
//! `P_FireWeapon`, `A_ReFire`, `P_CheckAmmo`), and every weapon action. A
//! weapon's state machine is its actor's states ([`super::info::WeaponInfo`]);
//! shots go out through [`super::collision`] and missiles through
//! [`super::movement`].

use super::info::mt;
use super::movement::{self, MELEERANGE};
use super::user::pw;
use super::{collision, interaction, monsters, MobjId, PlayerState, Sim, NUMAMMO};
use crate::actors::{ActionCall, Arg, StateId};
use crate::fixed::{
    finecosine, finesine, point_to_angle2, Angle, Fixed, ANG180, ANG90, ANGLETOFINESHIFT, FINEANGLES, FINEMASK,
    FRACUNIT,
};
use crate::play::lmp::buttons;

/// How fast a weapon goes down and comes up, a tic.
const LOWERSPEED: Fixed = Fixed(6 * FRACUNIT);
const RAISESPEED: Fixed = Fixed(6 * FRACUNIT);
/// The weapon sprite's height when away and when up.
pub const WEAPONBOTTOM: Fixed = Fixed(128 * FRACUNIT);
pub const WEAPONTOP: Fixed = Fixed(32 * FRACUNIT);
/// `MISSILERANGE`: a hitscan's reach.
pub const MISSILERANGE: Fixed = Fixed(32 * 64 * FRACUNIT);
/// How far auto-aim looks.
const AIMRANGE: Fixed = Fixed(16 * 64 * FRACUNIT);
/// `deh_bfg_cells_per_shot`'s default.
const BFG_CELLS_PER_SHOT: i32 = 40;

/// The two weapon sprites.
pub const PS_WEAPON: usize = 0;
pub const PS_FLASH: usize = 1;

/// Doom's weapon numbers (`weapontype_t`).
pub mod wp {
    pub const FIST: usize = 0;
    pub const PISTOL: usize = 1;
    pub const SHOTGUN: usize = 2;
    pub const CHAINGUN: usize = 3;
    pub const MISSILE: usize = 4;
    pub const PLASMA: usize = 5;
    pub const BFG: usize = 6;
    pub const CHAINSAW: usize = 7;
    pub const SUPERSHOTGUN: usize = 8;
}

/// Doom's ammo numbers (`ammotype_t`).
pub mod am {
    pub const CLIP: usize = 0;
    pub const SHELL: usize = 1;
    pub const CELL: usize = 2;
    pub const MISL: usize = 3;
}

/// Runs weapon action `name` for player `player`'s sprite `psp`.
pub fn action(sim: &mut Sim, player: usize, psp: usize, name: &str, call: &ActionCall) {
    match name {
        "A_WeaponReady" => weapon_ready(sim, player, psp),
        "A_ReFire" => refire(sim, player),
        "A_CheckReload" => _ = check_ammo(sim, player),
        "A_Lower" => lower(sim, player, psp),
        "A_Raise" => raise(sim, player, psp),
        "A_GunFlash" => gun_flash(sim, player),
        "A_Light0" => set_extralight(sim, player, 0),
        "A_Light1" => set_extralight(sim, player, 1),
        "A_Light2" => set_extralight(sim, player, 2),
        "A_Punch" => punch(sim, player),
        "A_Saw" => saw(sim, player),
        "A_FirePistol" => fire_pistol(sim, player),
        "A_FireShotgun" => fire_shotgun(sim, player),
        "A_FireShotgun2" => fire_shotgun2(sim, player),
        "A_FireCGun" => fire_cgun(sim, player, psp),
        "A_FireMissile" => fire_missile(sim, player, missile_arg(sim, call, mt::ROCKET), 1),
        // ZDoom's: the named missile, one round (ZDoom spends the weapon's
        // AmmoUse; rocket_basic's launcher uses 1).
        "A_FireCustomMissile" => fire_missile(sim, player, missile_arg(sim, call, mt::ROCKET), 1),
        "A_FireBFG" => fire_missile(sim, player, missile_arg(sim, call, mt::BFG), BFG_CELLS_PER_SHOT),
        "A_FirePlasma" => fire_plasma(sim, player, missile_arg(sim, call, mt::PLASMA)),
        "A_BFGsound" => body_sound(sim, player, "bfg"),
        "A_OpenShotgun2" => body_sound(sim, player, "dbopn"),
        "A_LoadShotgun2" => body_sound(sim, player, "dbload"),
        "A_CloseShotgun2" => {
            body_sound(sim, player, "dbcls");
            refire(sim, player);
        }
        _ => {}
    }
}

/// The actor an action's first argument names, or Doom's kind `fallback`.
fn missile_arg(sim: &Sim, call: &ActionCall, fallback: usize) -> usize {
    match call.args.first() {
        Some(Arg::Actor(kind)) if *kind < sim.info.things.len() => *kind,
        _ => sim.kind_of(fallback),
    }
}

/// Player `n`'s body, if the player is in the game.
fn body(sim: &Sim, n: usize) -> Option<MobjId> {
    sim.player(n).map(|p| p.mo)
}

fn body_sound(sim: &mut Sim, n: usize, sound: &str) {
    if let Some(mo) = body(sim, n) {
        sim.sound_named(Some(mo), sound);
    }
}

fn set_extralight(sim: &mut Sim, n: usize, light: i32) {
    if let Some(p) = sim.players[n].as_mut() {
        p.extralight = light;
    }
}

/// The table's weapon `w` (`weaponinfo[w]`), if it has one.
fn weapon_info(sim: &Sim, w: usize) -> Option<&super::info::WeaponInfo> {
    sim.info.weapons.get(w).and_then(Option::as_ref)
}

/// A state of the ready weapon's table entry.
fn ready_state(sim: &Sim, n: usize, pick: fn(&super::info::WeaponInfo) -> Option<StateId>) -> Option<StateId> {
    let w = sim.player(n)?.readyweapon;
    weapon_info(sim, w).and_then(pick)
}

/// `P_SetPsprite`: sprite `position` of player `n` enters `state`, runs
/// its action, and goes on through states of zero tics; `None` (`S_NULL`)
/// puts the sprite away. An action may set the sprite itself; the walk
/// goes on from whatever state it left.
pub fn set_psprite(sim: &mut Sim, n: usize, position: usize, mut state: Option<StateId>) {
    loop {
        let Some(s) = state else {
            if let Some(p) = sim.players[n].as_mut() {
                p.psprites[position].state = None;
            }
            return;
        };
        let st = sim.info.state(s);
        let (tics, action) = (st.tics, st.action.clone());
        let Some(p) = sim.players[n].as_mut() else { return };
        p.psprites[position].state = Some(s);
        p.psprites[position].tics = tics;
        if let Some(call) = action {
            super::actions::call_weapon(sim, n, position, &call);
        }
        let Some(p) = sim.player(n) else { return };
        let psp = p.psprites[position];
        let Some(now) = psp.state else { return };
        state = sim.info.state(now).next;
        if psp.tics != 0 {
            return;
        }
    }
}

/// `P_BringUpWeapon`: the pending weapon (or the ready one again) starts
/// coming up from the bottom of the screen.
pub fn bring_up_weapon(sim: &mut Sim, n: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    let pending = p.pendingweapon.unwrap_or(p.readyweapon);
    p.pendingweapon = None;
    p.psprites[PS_WEAPON].sy = WEAPONBOTTOM;
    let mo = p.mo;
    if pending == wp::CHAINSAW {
        sim.sound_named(Some(mo), "sawup");
    }
    let up = weapon_info(sim, pending).and_then(|w| w.upstate);
    set_psprite(sim, n, PS_WEAPON, up);
}

/// Ammo of type `ammo` the player holds; Doom's `am_noammo` (5) reads past
/// `ammo[]` into `maxammo[1]`, as vanilla's unchecked index does.
fn ammo_held(p: &super::Player, ammo: Option<usize>) -> i32 {
    match ammo {
        Some(a) => p.ammo.get(a).copied().unwrap_or(0),
        None => p.maxammo[5 - NUMAMMO],
    }
}

/// `DecreaseAmmo`: spends `amount` of the ready weapon's ammo (a weapon
/// without ammo spends from `maxammo[1]`, as Chocolate emulates vanilla's
/// unchecked index).
fn decrease_ammo(sim: &mut Sim, n: usize, amount: i32) {
    let Some(w) = sim.player(n).map(|p| p.readyweapon) else { return };
    let ammo = weapon_info(sim, w).and_then(|w| w.ammo);
    let Some(p) = sim.players[n].as_mut() else { return };
    match ammo {
        Some(a) => p.ammo[a] -= amount,
        None => p.maxammo[5 - NUMAMMO] -= amount,
    }
}

/// `P_CheckAmmo`: whether the ready weapon has ammo for a shot; if not,
/// the next weapon by Doom's preference becomes pending and this one goes
/// down.
pub fn check_ammo(sim: &mut Sim, n: usize) -> bool {
    let mode = sim.rules.mode;
    let Some(p) = sim.player(n) else { return false };
    let ammo = weapon_info(sim, p.readyweapon).and_then(|w| w.ammo);
    let count = match p.readyweapon {
        wp::BFG => BFG_CELLS_PER_SHOT,
        wp::SUPERSHOTGUN => 2,
        _ => 1,
    };
    if ammo.is_none() || ammo_held(p, ammo) >= count {
        return true;
    }
    let shareware = mode == super::GameMode::Shareware;
    let commercial = mode == super::GameMode::Commercial;
    let (owned, held) = (p.weaponowned, p.ammo);
    let next = if owned[wp::PLASMA] && held[am::CELL] != 0 && !shareware {
        wp::PLASMA
    } else if owned[wp::SUPERSHOTGUN] && held[am::SHELL] > 2 && commercial {
        wp::SUPERSHOTGUN
    } else if owned[wp::CHAINGUN] && held[am::CLIP] != 0 {
        wp::CHAINGUN
    } else if owned[wp::SHOTGUN] && held[am::SHELL] != 0 {
        wp::SHOTGUN
    } else if held[am::CLIP] != 0 {
        wp::PISTOL
    } else if owned[wp::CHAINSAW] {
        wp::CHAINSAW
    } else if owned[wp::MISSILE] && held[am::MISL] != 0 {
        wp::MISSILE
    } else if owned[wp::BFG] && held[am::CELL] > 40 && !shareware {
        wp::BFG
    } else {
        wp::FIST
    };
    if let Some(p) = sim.players[n].as_mut() {
        p.pendingweapon = Some(next);
    }
    let down = ready_state(sim, n, |w| w.downstate);
    set_psprite(sim, n, PS_WEAPON, down);
    false
}

/// The player body's attack frames (`S_PLAY_ATK1` and `S_PLAY_ATK2`: the
/// player kind's missile and melee states) and its standing state.
fn body_states(sim: &Sim, mo: MobjId) -> (Option<StateId>, Option<StateId>, Option<StateId>) {
    let info = &sim.info.things[sim.mo(mo).kind];
    (info.missilestate, info.meleestate, info.spawnstate)
}

/// `P_FireWeapon`: with ammo, the body's attack frame, the weapon's attack
/// states, and the noise that wakes monsters.
pub fn fire_weapon(sim: &mut Sim, n: usize) {
    if !check_ammo(sim, n) {
        return;
    }
    let Some(mo) = body(sim, n) else { return };
    let (atk1, _, _) = body_states(sim, mo);
    sim.set_mobj_state(mo, atk1);
    let attack = ready_state(sim, n, |w| w.atkstate);
    set_psprite(sim, n, PS_WEAPON, attack);
    monsters::noise_alert(sim, mo, mo);
}

/// `P_DropWeapon`: player `player`'s weapon goes down (death, a change).
pub fn drop_weapon(sim: &mut Sim, player: usize) {
    let down = ready_state(sim, player, |w| w.downstate);
    set_psprite(sim, player, PS_WEAPON, down);
}

/// `A_WeaponReady`: the body leaves its attack frames, the chainsaw idles,
/// a pending change (or death) lowers the weapon, fire fires (the rocket
/// launcher and BFG not again while held), else the weapon bobs.
fn weapon_ready(sim: &mut Sim, n: usize, psp: usize) {
    let leveltime = sim.leveltime;
    let Some(mo) = body(sim, n) else { return };
    let (atk1, atk2, standing) = body_states(sim, mo);
    let state = sim.mo(mo).state;
    if state.is_some() && (state == atk1 || state == atk2) {
        sim.set_mobj_state(mo, standing);
    }
    let Some(p) = sim.player(n) else { return };
    let saw_ready = weapon_info(sim, wp::CHAINSAW).and_then(|w| w.readystate);
    if p.readyweapon == wp::CHAINSAW && saw_ready.is_some() && p.psprites[psp].state == saw_ready {
        sim.sound_named(Some(mo), "sawidl");
    }
    let Some(p) = sim.players[n].as_mut() else { return };
    if p.pendingweapon.is_some() || p.health == 0 {
        drop_weapon(sim, n);
        return;
    }
    if p.cmd.buttons & buttons::ATTACK != 0 {
        if !p.attackdown || (p.readyweapon != wp::MISSILE && p.readyweapon != wp::BFG) {
            p.attackdown = true;
            fire_weapon(sim, n);
            return;
        }
    } else {
        p.attackdown = false;
    }
    // Bob the weapon with the body's speed.
    let angle = (128u32.wrapping_mul(leveltime) as usize) & FINEMASK;
    let sprite = &mut p.psprites[psp];
    sprite.sx = Fixed::ONE + p.bob * finecosine(angle);
    let angle = angle & (FINEANGLES / 2 - 1);
    sprite.sy = WEAPONTOP + p.bob * finesine(angle);
}

/// `A_ReFire`: fire again while the trigger is held (and no change is
/// pending), counting the shots in a row; else the count resets and the
/// ammo is checked.
fn refire(sim: &mut Sim, n: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    if p.cmd.buttons & buttons::ATTACK != 0 && p.pendingweapon.is_none() && p.health != 0 {
        p.refire += 1;
        fire_weapon(sim, n);
    } else {
        p.refire = 0;
        check_ammo(sim, n);
    }
}

/// `A_Lower`: down 6 units a tic; at the bottom, a dead player's weapon
/// stays away, else the pending weapon becomes ready and comes up.
fn lower(sim: &mut Sim, n: usize, psp: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    p.psprites[psp].sy += LOWERSPEED;
    if p.psprites[psp].sy < WEAPONBOTTOM {
        return;
    }
    if p.playerstate == PlayerState::Dead {
        p.psprites[psp].sy = WEAPONBOTTOM;
        return;
    }
    if p.health == 0 {
        set_psprite(sim, n, PS_WEAPON, None);
        return;
    }
    // wp_nochange here would index past the table in Doom; keep the weapon.
    if let Some(w) = p.pendingweapon {
        p.readyweapon = w;
    }
    bring_up_weapon(sim, n);
}

/// `A_Raise`: up 6 units a tic; at the top, the weapon is ready.
fn raise(sim: &mut Sim, n: usize, psp: usize) {
    let Some(p) = sim.players[n].as_mut() else { return };
    p.psprites[psp].sy -= RAISESPEED;
    if p.psprites[psp].sy > WEAPONTOP {
        return;
    }
    p.psprites[psp].sy = WEAPONTOP;
    let ready = ready_state(sim, n, |w| w.readystate);
    set_psprite(sim, n, PS_WEAPON, ready);
}

/// The body's firing frame (`S_PLAY_ATK2`).
fn body_flash(sim: &mut Sim, n: usize) {
    let Some(mo) = body(sim, n) else { return };
    let (_, atk2, _) = body_states(sim, mo);
    sim.set_mobj_state(mo, atk2);
}

/// The ready weapon's flash state, `offset` states on.
fn flash_state(sim: &Sim, n: usize, offset: u32) -> Option<StateId> {
    let first = ready_state(sim, n, |w| w.flashstate)?;
    // Doom reads past its table for a bad offset; a table too short for it
    // shows the first flash.
    let later = first.0.checked_add(offset).filter(|&s| (s as usize) < sim.info.states.len());
    Some(later.map_or(first, StateId))
}

/// `A_GunFlash`.
fn gun_flash(sim: &mut Sim, n: usize) {
    body_flash(sim, n);
    let flash = flash_state(sim, n, 0);
    set_psprite(sim, n, PS_FLASH, flash);
}

/// `A_Punch`: 2 to 20 damage (ten times with berserk), a little off
/// straight, turning the player to what it hit.
fn punch(sim: &mut Sim, n: usize) {
    let Some(mo) = body(sim, n) else { return };
    let mut damage = (sim.p_random() % 10 + 1) << 1;
    if sim.player(n).is_some_and(|p| p.powers[pw::STRENGTH] != 0) {
        damage *= 10;
    }
    let angle = sim.mo(mo).angle + Angle((sim.rng.p_subrandom() << 18) as u32);
    let slope = collision::aim_line_attack(sim, mo, angle, MELEERANGE);
    collision::line_attack(sim, mo, angle, MELEERANGE, slope, damage);
    if let Some(t) = sim.tm.linetarget {
        sim.sound_named(Some(mo), "punch");
        let (m, t) = (sim.mo(mo), sim.mo(t));
        let to = point_to_angle2(m.x, m.y, t.x, t.y);
        sim.mo_mut(mo).angle = to;
    }
}

/// `A_Saw`: 2 to 20 damage at one unit past melee range (so the puff does
/// not skip the flash), the player turned towards what it hit by at most
/// `ANG90/20` a tic and pulled forward next tic (`MF_JUSTATTACKED`).
fn saw(sim: &mut Sim, n: usize) {
    let Some(mo) = body(sim, n) else { return };
    let damage = 2 * (sim.p_random() % 10 + 1);
    let angle = sim.mo(mo).angle + Angle((sim.rng.p_subrandom() << 18) as u32);
    let range = MELEERANGE + Fixed(1);
    let slope = collision::aim_line_attack(sim, mo, angle, range);
    collision::line_attack(sim, mo, angle, range, slope, damage);
    let Some(t) = sim.tm.linetarget else {
        sim.sound_named(Some(mo), "sawful");
        return;
    };
    sim.sound_named(Some(mo), "sawhit");
    let (m, t) = (sim.mo(mo), sim.mo(t));
    let angle = point_to_angle2(m.x, m.y, t.x, t.y);
    let step = Angle(ANG90.0 / 20);
    let snap = Angle(ANG90.0 / 21);
    let m = sim.mo_mut(mo);
    let diff = angle - m.angle;
    if diff > ANG180 {
        // Doom compares the difference as a signed int with -ANG90/20.
        if (diff.0 as i32) < -((ANG90.0 / 20) as i32) {
            m.angle = angle + snap;
        } else {
            m.angle -= step;
        }
    } else if diff > step {
        m.angle = angle - snap;
    } else {
        m.angle += step;
    }
    m.flags |= super::mobj::mf::JUSTATTACKED;
}

/// `A_FireMissile` and `A_FireBFG`: spends `cost` and launches `kind`.
fn fire_missile(sim: &mut Sim, n: usize, kind: usize, cost: i32) {
    decrease_ammo(sim, n, cost);
    if let Some(mo) = body(sim, n) {
        movement::spawn_player_missile(sim, mo, kind);
    }
}

/// `A_FirePlasma`: one of the two flashes, at random, then the bolt.
fn fire_plasma(sim: &mut Sim, n: usize, kind: usize) {
    decrease_ammo(sim, n, 1);
    let which = (sim.p_random() & 1) as u32;
    let flash = flash_state(sim, n, which);
    set_psprite(sim, n, PS_FLASH, flash);
    if let Some(mo) = body(sim, n) {
        movement::spawn_player_missile(sim, mo, kind);
    }
}

/// `P_BulletSlope`: the slope to a monster straight ahead, or a little to
/// the right, or to the left (the last try's slope when none is found).
fn bullet_slope(sim: &mut Sim, mo: MobjId) -> Fixed {
    if sim.rules.no_autoaim {
        return Fixed::ZERO;
    }
    let mut an = sim.mo(mo).angle;
    let mut slope = collision::aim_line_attack(sim, mo, an, AIMRANGE);
    if sim.tm.linetarget.is_none() {
        an += Angle(1 << 26);
        slope = collision::aim_line_attack(sim, mo, an, AIMRANGE);
        if sim.tm.linetarget.is_none() {
            an -= Angle(2 << 26);
            slope = collision::aim_line_attack(sim, mo, an, AIMRANGE);
        }
    }
    slope
}

/// `P_GunShot`: 5, 10 or 15 damage along the body's angle, spread unless
/// `accurate`.
fn gun_shot(sim: &mut Sim, mo: MobjId, accurate: bool, slope: Fixed) {
    let damage = 5 * (sim.p_random() % 3 + 1);
    let mut angle = sim.mo(mo).angle;
    if !accurate {
        angle += Angle((sim.rng.p_subrandom() << 18) as u32);
    }
    collision::line_attack(sim, mo, angle, MISSILERANGE, slope, damage);
}

/// The start every gun's shot shares: its sound, the body's firing frame,
/// the ammo spent and the flash (`flash` states past the weapon's first).
fn gun_start(sim: &mut Sim, n: usize, sound: &str, cost: i32, flash: u32) {
    body_sound(sim, n, sound);
    gun_start_silent(sim, n, cost, flash);
}

/// `A_FirePistol`: one bullet, accurate unless fired again while held.
fn fire_pistol(sim: &mut Sim, n: usize) {
    gun_start(sim, n, "pistol", 1, 0);
    let Some(mo) = body(sim, n) else { return };
    let slope = bullet_slope(sim, mo);
    let accurate = sim.player(n).is_some_and(|p| p.refire == 0);
    gun_shot(sim, mo, accurate, slope);
}

/// `A_FireShotgun`: seven spread pellets.
fn fire_shotgun(sim: &mut Sim, n: usize) {
    gun_start(sim, n, "shotgn", 1, 0);
    let Some(mo) = body(sim, n) else { return };
    let slope = bullet_slope(sim, mo);
    for _ in 0..7 {
        gun_shot(sim, mo, false, slope);
    }
}

/// `A_FireShotgun2`: twenty pellets spread wide and up and down.
fn fire_shotgun2(sim: &mut Sim, n: usize) {
    gun_start(sim, n, "dshtgn", 2, 0);
    let Some(mo) = body(sim, n) else { return };
    let slope = bullet_slope(sim, mo);
    for _ in 0..20 {
        // Doom's order: the damage, the turn, then the slope's jitter.
        let damage = 5 * (sim.p_random() % 3 + 1);
        let angle = sim.mo(mo).angle + Angle((sim.rng.p_subrandom() << ANGLETOFINESHIFT) as u32);
        let jitter = Fixed(sim.rng.p_subrandom() << 5);
        collision::line_attack(sim, mo, angle, MISSILERANGE, slope + jitter, damage);
    }
}

/// `A_FireCGun`: the sound even when empty; a bullet with the flash that
/// matches the barrel (the attack state's place after the first).
fn fire_cgun(sim: &mut Sim, n: usize, psp: usize) {
    body_sound(sim, n, "pistol");
    let Some(p) = sim.player(n) else { return };
    let ammo = weapon_info(sim, p.readyweapon).and_then(|w| w.ammo);
    if ammo_held(p, ammo) == 0 {
        return;
    }
    let first = ready_state(sim, n, |w| w.atkstate);
    let offset = match (p.psprites[psp].state, first) {
        (Some(s), Some(f)) => s.0.wrapping_sub(f.0),
        _ => 0,
    };
    gun_start_silent(sim, n, 1, offset);
    let Some(mo) = body(sim, n) else { return };
    let slope = bullet_slope(sim, mo);
    let accurate = sim.player(n).is_some_and(|p| p.refire == 0);
    gun_shot(sim, mo, accurate, slope);
}

/// [`gun_start`] without the sound (the chaingun plays it first).
fn gun_start_silent(sim: &mut Sim, n: usize, cost: i32, flash: u32) {
    body_flash(sim, n);
    decrease_ammo(sim, n, cost);
    let flash = flash_state(sim, n, flash);
    set_psprite(sim, n, PS_FLASH, flash);
}

/// `A_BFGSpray`, the BFG ball's action on its body `ball` (routed here
/// from the body actions): forty tracers across 90 degrees from its
/// owner; each that finds a monster puts `spray` on it and does 15d8.
pub fn bfg_spray(sim: &mut Sim, ball: MobjId, spray: usize) {
    let Some(owner) = sim.mo(ball).target else { return };
    for i in 0..40u32 {
        let an = sim.mo(ball).angle - Angle(ANG90.0 / 2) + Angle((ANG90.0 / 40).wrapping_mul(i));
        collision::aim_line_attack(sim, owner, an, AIMRANGE);
        let Some(t) = sim.tm.linetarget else { continue };
        let m = sim.mo(t);
        sim.spawn_mobj(m.x, m.y, m.z + (m.height >> 2), spray);
        let mut damage = 0;
        for _ in 0..15 {
            damage += (sim.p_random() & 7) + 1;
        }
        interaction::damage_mobj(sim, t, Some(owner), Some(owner), damage);
    }
}

/// `P_SetupPsprites`: a new body's sprites are cleared and its weapon
/// comes up.
pub fn setup_psprites(sim: &mut Sim, player: usize) {
    let Some(p) = sim.players[player].as_mut() else { return };
    for psp in &mut p.psprites {
        psp.state = None;
    }
    p.pendingweapon = Some(p.readyweapon);
    bring_up_weapon(sim, player);
}

/// `P_MovePsprites`: each active sprite's tics count down (-1 stays) and
/// it moves on; the flash follows the weapon's place.
pub fn move_psprites(sim: &mut Sim, player: usize) {
    for position in 0..2 {
        let Some(p) = sim.players[player].as_mut() else { return };
        let psp = &mut p.psprites[position];
        let Some(state) = psp.state else { continue };
        if psp.tics == -1 {
            continue;
        }
        psp.tics -= 1;
        if psp.tics == 0 {
            let next = sim.info.state(state).next;
            set_psprite(sim, player, position, next);
        }
    }
    if let Some(p) = sim.players[player].as_mut() {
        p.psprites[PS_FLASH].sx = p.psprites[PS_WEAPON].sx;
        p.psprites[PS_FLASH].sy = p.psprites[PS_WEAPON].sy;
    }
}
