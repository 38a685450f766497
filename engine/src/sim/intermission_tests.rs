use super::*;
use crate::play::lmp::Ticcmd;

const TICRATE_U: u32 = 35;

fn player() -> Player {
    let info = crate::sim::info::Info::new(crate::actors::ActorTable::active().clone(), false);
    let mut p = Player::reborn(&info, [0; MAXPLAYERS], (0, 0, 0));
    // Nothing held as the level ended.
    (p.attackdown, p.usedown) = (false, false);
    p
}

/// One player's game between levels, fed a command a tic.
struct Between {
    wi: Intermission,
    players: [Option<Player>; MAXPLAYERS],
}

impl Between {
    fn new(mode: GameMode, name: &str, secret: bool, tallies: Tallies) -> Between {
        let mut players: [Option<Player>; MAXPLAYERS] = Default::default();
        players[0] = Some(player());
        Between { wi: Intermission::start(mode, name, secret, tallies), players }
    }

    fn tic(&mut self, buttons: u8) {
        let cmd = Ticcmd { buttons, ..Ticcmd::default() };
        let mut cmds = [None; MAXPLAYERS];
        cmds[0] = Some(cmd);
        self.wi.tick(&mut self.players, &cmds);
    }

    /// Idle tics until `done` or `limit`; the tics run.
    fn idle_until(&mut self, limit: u32, done: impl Fn(&Intermission) -> bool) -> u32 {
        let mut n = 0;
        while !done(&self.wi) && n < limit {
            self.tic(0);
            n += 1;
        }
        n
    }
}

fn finished(wi: &Intermission) -> bool {
    matches!(wi.stage, Stage::Tallies { step: 10, .. })
}

#[test]
fn empty_tallies_count_through_five_pauses_and_wait_for_a_press() {
    // Every count is one tic (from -1 past 0), the five pauses 35 each.
    let mut b = Between::new(GameMode::Commercial, "MAP01", false, Tallies::default());
    assert_eq!(b.idle_until(1000, finished), 5 * TICRATE_U + 4);
    assert_eq!(b.wi.shown, Shown { kills: 0, items: 0, secrets: 0, time: 0, par: 0 });
    // Finished tallies wait as long as no one presses.
    b.idle_until(500, |_| false);
    assert!(finished(&b.wi));
    // Doom II: a press, then ten tics, then the next level.
    b.tic(buttons::USE);
    assert_eq!(b.wi.stage, Stage::Closing { left: NO_STATE });
    assert_eq!(b.wi.sounds, ["sgcock"]);
    assert_eq!(b.idle_until(100, Intermission::done), 10);
}

#[test]
fn the_counts_run_two_percent_and_three_seconds_a_tic() {
    // 50% kills: 26 tics (-1, 1, .., 49, 51 clamped to 50); 10% items: 6;
    // 0 of 0 secrets: 1; time 100 s against a par of 30 s: 34 tics (-1 + 3n >= 100).
    let tallies = Tallies {
        kills: 5,
        items: 1,
        secrets: 0,
        max_kills: 10,
        max_items: 10,
        max_secrets: 0,
        time: 100 * 35 + 20,
        par: 30 * 35,
    };
    let mut b = Between::new(GameMode::Commercial, "MAP01", false, tallies);
    assert_eq!(b.idle_until(1000, finished), 5 * TICRATE_U + 26 + 6 + 1 + 34);
    assert_eq!(b.wi.shown, Shown { kills: 50, items: 10, secrets: 0, time: 100, par: 30 });
}

#[test]
fn a_press_while_counting_shows_the_tallies_and_a_second_goes_on() {
    let tallies = Tallies { kills: 3, max_kills: 4, time: 35 * 60, par: 35 * 30, ..Tallies::default() };
    let mut b = Between::new(GameMode::Retail, "E1M1", false, tallies);
    b.idle_until(40, |_| false);
    b.tic(buttons::ATTACK);
    assert!(finished(&b.wi));
    assert_eq!(b.wi.shown, Shown { kills: 75, items: 0, secrets: 0, time: 60, par: 30 });
    assert_eq!(b.wi.sounds, ["barexp"]);
    // Fire still held is no press; let go and press again.
    b.tic(buttons::ATTACK);
    assert!(finished(&b.wi));
    b.tic(0);
    b.tic(buttons::ATTACK);
    // Doom 1: the episode map, 140 tics unless pressed, then ten tics.
    assert_eq!(b.wi.stage, Stage::NextLocation { left: SHOW_NEXT_LOC });
    assert_eq!(b.idle_until(1000, |wi| matches!(wi.stage, Stage::Closing { .. })), 140);
    assert_eq!(b.idle_until(100, Intermission::done), 10);
}

#[test]
fn use_held_from_the_exit_switch_does_not_skip_and_a_press_skips_the_map() {
    let mut b = Between::new(GameMode::Retail, "E1M2", false, Tallies::default());
    b.players[0].as_mut().unwrap().usedown = true;
    for _ in 0..20 {
        b.tic(buttons::USE);
    }
    assert!(matches!(b.wi.stage, Stage::Tallies { step: 1, .. }));
    b.idle_until(1000, finished);
    b.tic(buttons::USE);
    b.tic(0);
    b.tic(buttons::USE);
    assert_eq!(b.wi.stage, Stage::Closing { left: NO_STATE });
    // What the intermission left in the player goes on to the next level.
    assert!(b.players[0].as_ref().unwrap().usedown);
}

#[test]
fn doom_twos_text_screens_wait_fifty_tics_then_take_any_button() {
    for (name, secret, text) in
        [("MAP06", false, true), ("MAP15", false, false), ("MAP15", true, true), ("MAP07", false, false)]
    {
        let mut b = Between::new(GameMode::Commercial, name, secret, Tallies::default());
        b.idle_until(1000, finished);
        b.tic(buttons::USE);
        b.idle_until(10, |_| false);
        assert_eq!(b.wi.done(), !text, "{name}");
        if text {
            assert_eq!(b.wi.stage, Stage::Text { shown: 0 });
            // A weapon change counts: any button at all.
            for _ in 0..51 {
                b.tic(buttons::CHANGE);
            }
            assert_eq!(b.wi.stage, Stage::Text { shown: 51 });
            b.tic(buttons::CHANGE);
            assert!(b.wi.done());
        }
    }
}

/// Players 1 and 2 alone in the game.
fn two(a: Player, b: Player) -> [Option<Player>; MAXPLAYERS] {
    let mut players: [Option<Player>; MAXPLAYERS] = Default::default();
    (players[0], players[1]) = (Some(a), Some(b));
    players
}

/// Frags of the first players, none of the rest.
fn frags(first: &[i32]) -> [i32; MAXPLAYERS] {
    std::array::from_fn(|n| first.get(n).copied().unwrap_or(0))
}

#[test]
fn par_times_are_doom_exes() {
    assert_eq!(
        ["E1M1", "e1m7", "E3M9", "E4M1", "MAP01", "MAP32", "MAP33", "E5M1", "outpost"].map(par_seconds),
        [30, 180, 135, 90, 30, 30, 0, 90, 0]
    );
    assert!(ends_game(GameMode::Retail, "E2M8") && !ends_game(GameMode::Commercial, "MAP08"));
    assert!(!ends_game(GameMode::Retail, "E1M9"));
}

#[test]
fn deathmatch_counts_the_frags_table_one_a_tic_and_a_figure_past_99_never_ends() {
    let mut a = player();
    let mut b = player();
    a.frags = frags(&[0, 3]);
    b.frags = frags(&[-2, 0]);
    let players = two(a.clone(), b.clone());
    let start = || Intermission::start(GameMode::Commercial, "MAP01", false, Tallies::default());
    let mut between = Between { wi: start().for_netgame(&players, (0, 0, 0), true, false), players };
    // A pause, three tics of counting (the largest figure), a pause.
    let counted = |wi: &Intermission| matches!(wi.stage, Stage::Tallies { step: 4, .. });
    assert_eq!(between.idle_until(1000, counted), 35 + 3 + 1 + 35);
    // 120 frags: the table stops at 99 and counts on until a press.
    a.frags = frags(&[0, 120]);
    let players = two(a, b);
    let mut between = Between { wi: start().for_netgame(&players, (0, 0, 0), true, false), players };
    assert_eq!(between.idle_until(1000, counted), 1000);
    between.tic(buttons::ATTACK);
    assert!(counted(&between.wi));
}

#[test]
fn coop_counts_everyone_together_and_frags_only_when_someone_has_some() {
    let (mut a, mut b) = (player(), player());
    (a.killcount, b.killcount) = (10, 2);
    let players = two(a.clone(), b.clone());
    let start = || Intermission::start(GameMode::Commercial, "MAP01", false, Tallies::default());
    let done = |wi: &Intermission| matches!(wi.stage, Stage::Tallies { step: 10, .. });
    // Kills to 50% (25 tics, the slower player's), items and secrets one
    // tic each from 0, four pauses, no frags.
    let mut between = Between { wi: start().for_netgame(&players, (20, 0, 0), false, false), players: players.clone() };
    assert_eq!(between.idle_until(1000, done), 4 * 35 + 25 + 1 + 1);
    assert!(!between.wi.counted_frags());
    // A frag, or an earlier intermission's, counts the frags too.
    a.frags[1] = 2;
    let players = two(a, b);
    let mut between = Between { wi: start().for_netgame(&players, (20, 0, 0), false, false), players };
    assert_eq!(between.idle_until(1000, done), 5 * 35 + 25 + 1 + 1 + 2);
    assert!(between.wi.counted_frags());
}
