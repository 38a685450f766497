//! Debug aid (not committed): plays a map with monsters and prints what is
//! near whenever the player's health drops.
use sightline::autopilot;
use sightline::campaign::MapRef;
use sightline::play::playthrough::Playthrough;
use sightline::play::GameOptions;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let map = MapRef::parse(&args[1], None);
    let skill: u8 = args.get(2).map_or(2, |s| s.parse().unwrap());
    let seed: u64 = args.get(3).map_or(0, |s| s.parse().unwrap());
    let options = GameOptions { skill, seed, ..GameOptions::default() };
    let mut play = Playthrough::of(&map, options).unwrap();
    let mut last = play.game.player().health;
    let (outcome, bot) = autopilot::run(&mut play, 42000, |play, tick| {
        let p = play.game.player();
        let watch: Option<(u64, u64)> = std::env::var("DW_WATCH").ok().map(|w| {
            let (a, b) = w.split_once('-').unwrap();
            (a.parse().unwrap(), b.parse().unwrap())
        });
        if watch.is_some_and(|(a, b)| tick >= a && tick <= b) {
            let actors = play.game.actors();
            let w = p.ready_weapon.map(|w| actors.table.actors[w].name.clone());
            let mut ms = Vec::new();
            for a in &actors.list {
                let def = &actors.table.actors[a.kind];
                if !a.removed && def.has(sightline::actors::ActorFlag::Missile) && a.pos.distance(p.pos) < 400.0 {
                    ms.push(format!("{}@{:.0},{:.0} z{:.0}", def.name, a.pos.x, a.pos.y, a.z));
                }
            }
            println!(
                "  t{tick} pos ({:.0},{:.0}) z {:.0} ang {:.0} hp {} weapon {:?} pending {:?} missiles {}",
                p.pos.x,
                p.pos.y,
                p.z,
                p.angle,
                p.health,
                w,
                p.pending_weapon.is_some(),
                ms.join(" ")
            );
        }
        if p.health < last {
            let actors = play.game.actors();
            let mut near = Vec::new();
            for a in &actors.list {
                let def = &actors.table.actors[a.kind];
                if a.removed || a.health <= 0 && !def.has(sightline::actors::ActorFlag::Missile) {
                    continue;
                }
                let d = a.pos.distance(p.pos);
                let missile = def.has(sightline::actors::ActorFlag::Missile);
                if (missile && d < 200.0)
                    || (!missile && d < 900.0 && def.has(sightline::actors::ActorFlag::CountKill))
                    || def.name == "barrel" && d < 200.0
                {
                    near.push(format!("{}{}@{:.0}", def.name, if missile { "(m)" } else { "" }, d));
                }
            }
            println!(
                "tick {tick}: health {} -> {} at ({:.0},{:.0}) near: {}",
                last,
                p.health,
                p.pos.x,
                p.pos.y,
                near.join(" ")
            );
        }
        last = p.health;
        true
    })
    .unwrap();
    if let Ok(w) = std::env::var("DW_WATCH") {
        let (a, b) = w.split_once('-').unwrap();
        for t in a.parse::<usize>().unwrap()..b.parse::<usize>().unwrap().min(outcome.inputs.len() + 1) {
            println!("  input t{t}: {:?}", outcome.inputs[t - 1]);
        }
    }
    println!("outcome: exit {:?} died {} stuck {:?}", outcome.exit, outcome.died, outcome.stuck);
    for l in bot.log.iter().rev().take(5) {
        println!("{l}");
    }
}
