//! The autopilot as an expert for imitation learning: for an [`Episode`],
//! the action the autopilot would take now, as one value per the
//! scenario's available button (what [`Episode::step`] takes).
//!
//! The bot ([`Autopilot`] with [`Options::SCENARIO`]: fight what is in
//! sight, fetch the health and armour seen, explore, lead a moving enemy
//! with a rocket) answers a [`TickInput`]: forward and side moves, an
//! exact turn in degrees, fire, use. [`project`] turns that into the
//! scenario's buttons:
//!
//! - **Turns.** A delta turn button takes the bot's exact turn. Binary
//!   turn buttons turn by a fixed step (ZDoom's 320 of 65536 for the first
//!   five held tics, then 640, 1280 with SPEED: `run::command`); one is
//!   pressed when that step brings the body nearer the bot's facing than
//!   not turning, so the body settles within half a step of it.
//! - **Moves.** The way the bot wants the body to go (its forward and side
//!   moves about the facing it turns to) is matched by the available move
//!   buttons about the facing the body really has after this tic's turn:
//!   the combination whose way is nearest, if it is within 60 degrees;
//!   else none (health_gathering's body, with only MOVE_FORWARD, turns on
//!   the spot towards a medikit behind it before walking).
//! - **No turn buttons at all** (basic, rocket_basic: MOVE_LEFT,
//!   MOVE_RIGHT, ATTACK) while the bot aims at an enemy: the body strafes
//!   so that the enemy comes onto its line of fire, letting go early
//!   enough that friction's coasting (some ten tics' worth of its speed)
//!   does not carry it past.
//! - **Fire** only when the bot fires and the point it aims at (the enemy,
//!   or where a rocket will meet it) lies on the line of fire after this
//!   tic's turn, allowing for the drift of the body before the shot leaves:
//!   within the enemy's radius ([`FIRE_SHARE`]), or as near as a turn
//!   step allows (at 1,000 units half a slow step is 15 units aside). A
//!   launcher's trigger is let go for a tic when it is held at the ready
//!   ([`trigger_to_let_go`]). USE only when the body faces within 10
//!   degrees of where the bot does.
//! - **Weapons**: SELECT_WEAPONn for the slot the bot asks for (the
//!   scenario's command does not carry weapon changes yet: the value is
//!   what the bot would press). Other buttons stay 0.
//!
//! The expert only observes: the game is never written, and it is
//! deterministic (the bot has no generator of its own). It answers once per
//! tic: asked again on the same tic it gives the same answer without
//! ticking the bot again. Asked only every few tics (a frame skip), the bot
//! sees the game only then, as a player who looks up now and then.

use glam::DVec2;

use super::{Button, Episode, ScenarioConfig};
use crate::autopilot::observe::Observe;
use crate::autopilot::{Aim, Autopilot, Options};
use crate::play::{Player, TickInput};

/// A turn button's step in degrees, by the tic it is held on (`held`, from
/// 1) and whether SPEED is held (`run::command`'s rates, of 65536).
fn turn_step(held: u32, speed: bool) -> f64 {
    let units = if speed {
        1280.0
    } else if held <= super::run::SLOW_TURN_TICS {
        320.0
    } else {
        640.0
    };
    units * 360.0 / 65536.0
}

/// Friction keeps 0.90625 of a body's speed a tic (Doom's `FRICTION`,
/// 0xe800): let go, it coasts `speed / (1 - 0.90625)`, some ten tics' worth.
const COAST_TICS: f64 = 1.0 / (1.0 - 0.90625);
/// The drift of the body between the trigger and the shot, in tics of its
/// speed: a pistol fires 4 tics after the trigger (1 + 0.906 + 0.82 +
/// 0.74), a rocket leaves after 8 (the sum of 0.90625^k for k below 8).
const BULLET_DRIFT_TICS: f64 = 3.5;
const MISSILE_DRIFT_TICS: f64 = 5.8;
/// The share of the enemy's radius its aim point may be off the line of
/// fire for a shot. Over 50 seeds, basic paid 64 at 0.15, 69 at 0.3, 75 at
/// 0.6, 77 at 0.8 and 77.5 at 1 (every seed won at each), defend_the_center
/// 29.8 to 32.6 kills; rocket_basic 59 at 0.6, 62 at 1. (Before traces
/// met every body whose box they cross, a bullet missed a body whose
/// centre lay across a blockmap cell edge from its line, and 0.15 was
/// best: 55 against 37 at 0.6.)
const FIRE_SHARE: f64 = 1.0;
/// A move combination within this cosine of the wanted way is taken
/// (60 degrees).
const MOVE_COSINE: f64 = 0.5;

/// The autopilot playing along an episode.
pub struct Expert {
    bot: Autopilot,
    /// The tic of the last answer and the answer.
    last: Option<(u64, Vec<f64>)>,
    /// Each answer is printed to stderr (`SIGHTLINE_EXPERT_TRACE` set when
    /// the expert was made): what it saw, what the bot wanted, what it pressed.
    trace: bool,
}

impl Expert {
    /// An expert for `episode`, as it stands (its start, usually).
    pub fn new(episode: &Episode) -> Expert {
        let trace = std::env::var_os("SIGHTLINE_EXPERT_TRACE").is_some();
        Expert { bot: Autopilot::with_options(&episode.game, Options::SCENARIO), last: None, trace }
    }

    /// What the autopilot would press now in `episode` (the one this
    /// expert was made for): one value per available button. All zero
    /// once the episode is over.
    pub fn action(&mut self, episode: &Episode) -> Vec<f64> {
        let buttons = episode.config.available_buttons.len();
        if episode.end().is_some() {
            return vec![0.0; buttons];
        }
        let tic = Observe::ticks(&episode.game);
        if let Some((at, action)) = &self.last {
            if *at == tic {
                return action.clone();
            }
        }
        let mut input = self.bot.tick(&episode.game).sanitized();
        input.fire &= !trigger_to_let_go(&episode.game);
        let player = Observe::player(&episode.game);
        let action = project(&episode.config, episode.turn_held(), player, &input, self.bot.aim());
        if self.trace {
            eprintln!(
                "tic {tic}: at ({:.1}, {:.1}, {:.1}) facing {:.2}, moving ({:.2}, {:.2}), ammo {:?}; bot {input:?}, aim {:?} z {:?}; action {action:?}",
                player.pos.x,
                player.pos.y,
                player.z,
                player.angle,
                player.velocity.x,
                player.velocity.y,
                player.ammo,
                self.bot.aim(),
                self.bot.aim().and_then(|a| Observe::seen(&episode.game).get(a.thing).map(|s| (s.pos, s.z)))
            );
        }
        self.last = Some((tic, action.clone()));
        action
    }

    /// The bot itself (its route, its log).
    pub fn autopilot(&self) -> &Autopilot {
        &self.bot
    }
}

/// Must the trigger be let go this tic for the next press to fire? Doom's
/// rocket launcher and BFG fire from their ready state only on a fresh
/// press (`A_WeaponReady` ignores a trigger held since before, Doom's
/// `attackdown`); a player starts with it held, so a launcher that comes
/// up while the trigger is held never fires (rocket_basic, when the
/// cacodemon is in line from the first tic). Then the trigger is let go
/// for a tic while the weapon stands ready.
fn trigger_to_let_go(game: &dyn Observe) -> bool {
    let (player, table) = (game.player(), game.table());
    let Some(weapon) = player.ready_weapon else { return false };
    let fresh_only = table.actors[weapon].weapon.as_ref().is_some_and(|w| matches!(w.slot, 5 | 7));
    let ready = player.psprites[0]
        .state
        .and_then(|s| table.state(s).action.as_ref())
        .is_some_and(|a| crate::actors::actions::spec(a.action).name == "A_WeaponReady");
    player.fire_held && fresh_only && ready
}

/// The buttons of `config` that express `input`, the bot's wish for a body
/// in `player`'s state aiming at `aim`, with turn buttons held for
/// `turn_held` tics so far (see the module's notes).
pub fn project(
    config: &ScenarioConfig,
    turn_held: u32,
    player: &Player,
    input: &TickInput,
    aim: Option<Aim>,
) -> Vec<f64> {
    let buttons = &config.available_buttons;
    let mut out = vec![0.0; buttons.len()];
    let has = |b: Button| buttons.contains(&b);
    let mut set = |b: Button, v: f64| {
        if let Some(i) = buttons.iter().position(|&x| x == b) {
            out[i] = v;
        }
    };
    let limit = |b: Button, v: f64| match config.button_max_values.get(&b) {
        Some(&max) if max > 0 => v.clamp(-f64::from(max), f64::from(max)),
        _ => v,
    };
    let want = f64::from(input.turn);
    let moving = input.forward != 0 || input.strafe != 0;
    let mut speed = input.run && moving && has(Button::Speed);
    // Turns.
    let binary_turn = has(Button::TurnLeft) || has(Button::TurnRight);
    let turned = if has(Button::TurnLeftRightDelta) {
        // Degrees, positive to the right.
        let right = limit(Button::TurnLeftRightDelta, -want);
        set(Button::TurnLeftRightDelta, right);
        -right
    } else if binary_turn {
        if speed && want.abs() < turn_step(1, true) {
            // A fast step would overshoot a small turn.
            speed = false;
        }
        let step = turn_step(turn_held + 1, speed);
        if want > step / 2.0 && has(Button::TurnLeft) {
            set(Button::TurnLeft, 1.0);
            step
        } else if want < -step / 2.0 && has(Button::TurnRight) {
            set(Button::TurnRight, 1.0);
            -step
        } else {
            0.0
        }
    } else {
        0.0
    };
    let facing = player.angle + turned;
    let ahead = DVec2::from_angle(facing.to_radians());
    // Moves.
    let can_turn = binary_turn || has(Button::TurnLeftRightDelta);
    let (forward, side) = match aim.filter(|_| !can_turn) {
        Some(aim) => (f64::from(input.forward), line_up(player, ahead, aim)),
        None => nearest_move(config, player.angle + want, facing, input),
    };
    // A delta move carries the bot's speed itself, run or walk.
    let (walk, strafe) = if input.run { (50.0, 40.0) } else { (25.0, 24.0) };
    if has(Button::MoveForward) || has(Button::MoveBackward) {
        set(Button::MoveForward, f64::from(u8::from(forward > 0.0)));
        set(Button::MoveBackward, f64::from(u8::from(forward < 0.0)));
    } else {
        set(Button::MoveForwardBackwardDelta, limit(Button::MoveForwardBackwardDelta, forward * walk));
    }
    if has(Button::MoveRight) || has(Button::MoveLeft) {
        set(Button::MoveRight, f64::from(u8::from(side > 0.0)));
        set(Button::MoveLeft, f64::from(u8::from(side < 0.0)));
    } else {
        set(Button::MoveLeftRightDelta, limit(Button::MoveLeftRightDelta, side * strafe));
    }
    if speed && (forward != 0.0 || side != 0.0) {
        set(Button::Speed, 1.0);
    }
    // Fire and use.
    let off = want - turned;
    let lined_up = match aim {
        // A binary turn cannot come nearer than half its smallest step.
        Some(aim) => on_line_of_fire(player, ahead, aim, if binary_turn { turn_step(1, false) } else { 0.0 }),
        None => off.abs() < 2.0,
    };
    if input.fire && lined_up {
        set(Button::Attack, 1.0);
    }
    if input.use_line && off.abs() < 10.0 {
        set(Button::Use, 1.0);
    }
    if (1..=9).contains(&input.weapon) {
        set(Button::SelectWeapon(input.weapon), 1.0);
    }
    out
}

/// The side move (1 right, -1 left, 0 none) that brings `aim` onto the
/// line of fire of a body facing `ahead` that cannot turn: towards it while
/// coasting would not carry the body there by itself.
fn line_up(player: &Player, ahead: DVec2, aim: Aim) -> f64 {
    let to = aim.at - player.pos;
    // Positive: the aim point is to the left of the line of fire.
    let across = ahead.perp_dot(to);
    let drifting = player.velocity.dot(ahead.perp());
    let after = across - drifting * COAST_TICS;
    let tolerance = aim.radius * FIRE_SHARE / 2.0;
    if after > tolerance {
        -1.0
    } else if after < -tolerance {
        1.0
    } else {
        0.0
    }
}

/// Does `aim` lie on the line of fire of a body facing `ahead` once the
/// body has drifted as it will before the shot leaves: within
/// [`FIRE_SHARE`] of the enemy's radius, or within half a turn step
/// (`step`, degrees) where a step is coarser than that?
fn on_line_of_fire(player: &Player, ahead: DVec2, aim: Aim, step: f64) -> bool {
    let to = aim.at - player.pos;
    let along = to.dot(ahead);
    if along <= 0.0 {
        return false;
    }
    let drifting = player.velocity.dot(ahead.perp());
    let drift = if aim.missile { MISSILE_DRIFT_TICS } else { BULLET_DRIFT_TICS };
    let across = (ahead.perp_dot(to) - drifting * drift).abs();
    across <= aim.radius * FIRE_SHARE || across <= along * (step / 2.0).to_radians().tan()
}

/// The forward and side moves (each -1, 0 or 1; side 1 is right) that the
/// available buttons allow whose way, about `facing` (degrees), is nearest
/// the way `input` moves a body facing `wanted`; none when none is within
/// 60 degrees of it.
fn nearest_move(config: &ScenarioConfig, wanted: f64, facing: f64, input: &TickInput) -> (f64, f64) {
    let axes = |f: DVec2, fw: f64, side: f64| f * fw + f.perp() * -side;
    let way = axes(DVec2::from_angle(wanted.to_radians()), f64::from(input.forward), f64::from(input.strafe));
    if way == DVec2::ZERO {
        return (0.0, 0.0);
    }
    let has = |b: Button| config.available_buttons.contains(&b);
    let delta_forward = has(Button::MoveForwardBackwardDelta);
    let delta_side = has(Button::MoveLeftRightDelta);
    let forwards = [
        (0.0, true),
        (1.0, has(Button::MoveForward) || delta_forward),
        (-1.0, has(Button::MoveBackward) || delta_forward),
    ];
    let sides = [(0.0, true), (1.0, has(Button::MoveRight) || delta_side), (-1.0, has(Button::MoveLeft) || delta_side)];
    let ahead = DVec2::from_angle(facing.to_radians());
    let mut best = (MOVE_COSINE, (0.0, 0.0));
    for &(fw, ok) in &forwards {
        for &(side, ok2) in &sides {
            let moved = axes(ahead, fw, side);
            if !(ok && ok2) || moved == DVec2::ZERO {
                continue;
            }
            let cosine = moved.normalize().dot(way.normalize());
            if cosine > best.0 + 1e-9 {
                best = (cosine, (fw, side));
            }
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(buttons: &[Button]) -> ScenarioConfig {
        ScenarioConfig { available_buttons: buttons.to_vec(), ..ScenarioConfig::default() }
    }

    /// A body at the origin facing east (0 degrees), standing still.
    fn player() -> Player {
        Player::new(DVec2::ZERO, 0.0, 0, 0.0, 128.0)
    }

    fn aim(x: f64, y: f64) -> Option<Aim> {
        Some(Aim { at: DVec2::new(x, y), radius: 20.0, thing: 1, missile: false })
    }

    const BASIC: [Button; 3] = [Button::MoveLeft, Button::MoveRight, Button::Attack];

    /// basic: no turn buttons. An enemy 40 units to the left of the line
    /// of fire: strafe left, hold fire; on the line: fire, stand.
    #[test]
    fn without_turn_buttons_the_body_strafes_the_enemy_onto_its_line_of_fire() {
        let fire = TickInput { turn: 5.7, fire: true, ..TickInput::default() };
        assert_eq!(project(&config(&BASIC), 0, &player(), &fire, aim(400.0, 40.0)), [1.0, 0.0, 0.0]);
        assert_eq!(project(&config(&BASIC), 0, &player(), &fire, aim(400.0, -40.0)), [0.0, 1.0, 0.0]);
        assert_eq!(project(&config(&BASIC), 0, &player(), &fire, aim(400.0, 1.0)), [0.0, 0.0, 1.0]);
        // Drifting left at 6 units a tic, the body would coast some 64
        // units, past the enemy 40 to the left: it brakes (strafes right),
        // and fires, being 19 units off (within the radius) when the
        // pistol's shot leaves 4 tics later. At 3.75 a tic it coasts to the
        // enemy's line by itself, but would be 27 units off at the shot.
        let mut drifting = player();
        drifting.velocity = DVec2::new(0.0, 6.0);
        assert_eq!(project(&config(&BASIC), 0, &drifting, &fire, aim(400.0, 40.0)), [0.0, 1.0, 1.0]);
        drifting.velocity = DVec2::new(0.0, 3.75);
        assert_eq!(project(&config(&BASIC), 0, &drifting, &fire, aim(400.0, 40.0)), [0.0, 0.0, 0.0]);
    }

    /// Binary turns go by ZDoom's steps (1.76 degrees the first five held
    /// tics, 3.52 after): a turn is pressed when the step brings the body
    /// nearer the bot's facing; fire waits for the line of fire, or as near
    /// as a step can bring it (an enemy of radius 20 at 1,500 units is 0.76
    /// degrees wide, less than half a step).
    #[test]
    fn binary_turns_step_towards_the_bots_facing_and_fire_waits_for_the_line() {
        let c = config(&[Button::TurnLeft, Button::TurnRight, Button::Attack]);
        let at = |turn: f32, held| {
            let input = TickInput { turn, fire: true, ..TickInput::default() };
            let to = DVec2::from_angle(f64::from(turn).to_radians()) * 1500.0;
            project(&c, held, &player(), &input, aim(to.x, to.y))
        };
        assert_eq!(at(10.0, 0), [1.0, 0.0, 0.0]);
        assert_eq!(at(-10.0, 0), [0.0, 1.0, 0.0]);
        // Within half a slow step: no turn, and the shot goes.
        assert_eq!(at(0.8, 0), [0.0, 0.0, 1.0]);
        // 2 degrees after six held tics: a 3.52 step would overshoot to
        // 1.52 off, nearer than 2: turn; 1.7 off: stay.
        assert_eq!(at(2.0, 6), [1.0, 0.0, 0.0]);
        assert_eq!(at(1.7, 6), [0.0, 0.0, 0.0]);
    }

    /// A delta turn takes the bot's exact turn, in degrees to the right,
    /// within the button's maximum.
    #[test]
    fn a_delta_turn_takes_the_bots_exact_turn() {
        let mut c = config(&[Button::Attack, Button::TurnLeftRightDelta]);
        let input = TickInput { turn: 12.5, ..TickInput::default() };
        assert_eq!(project(&c, 0, &player(), &input, None), [0.0, -12.5]);
        c.button_max_values.insert(Button::TurnLeftRightDelta, 10);
        assert_eq!(project(&c, 0, &player(), &input, None), [0.0, -10.0]);
    }

    /// health_gathering: only MOVE_FORWARD and turns. A goal behind the
    /// body: turn on the spot; ahead and a little aside: walk and turn.
    #[test]
    fn with_only_forward_the_body_turns_before_it_walks() {
        let c = config(&[Button::TurnLeft, Button::TurnRight, Button::MoveForward]);
        let behind = TickInput { forward: 1, turn: 150.0, run: true, ..TickInput::default() };
        assert_eq!(project(&c, 0, &player(), &behind, None), [1.0, 0.0, 0.0]);
        let aside = TickInput { forward: 1, turn: -20.0, run: true, ..TickInput::default() };
        assert_eq!(project(&c, 0, &player(), &aside, None), [0.0, 1.0, 1.0]);
        // A strafe the buttons lack is walked as the nearest way: to the
        // right-forward, with forward alone 45 degrees off.
        let strafe = TickInput { forward: 1, strafe: 1, ..TickInput::default() };
        assert_eq!(project(&c, 0, &player(), &strafe, None), [0.0, 0.0, 1.0]);
    }

    /// Delta moves carry the bot's speed, and SPEED is held for a run on
    /// binary buttons; weapons by their slot's button.
    #[test]
    fn delta_moves_speed_and_weapons() {
        let c = config(&[Button::MoveForwardBackwardDelta, Button::MoveLeftRightDelta, Button::SelectWeapon(3)]);
        let run = TickInput { forward: 1, strafe: -1, run: true, weapon: 3, ..TickInput::default() };
        assert_eq!(project(&c, 0, &player(), &run, None), [50.0, -40.0, 1.0]);
        let c = config(&[Button::MoveForward, Button::Speed]);
        assert_eq!(project(&c, 0, &player(), &run, None), [1.0, 1.0]);
    }
}
