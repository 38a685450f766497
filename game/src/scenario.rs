//! ViZDoom's scenarios from the command line: `sightline autoplay
//! SCENARIO.cfg` plays episodes with a policy and reports each one's
//! length and reward (`--json` as one object, which
//! `scripts/vizdoom-compare.py` reads).

use anyhow::{Context, Result};
use serde_json::json;
use sightline::scenario::{RandomPolicy, Scenario, ScenarioConfig};

use crate::cli::{AutoplayArgs, Policy};

/// Whether `map` names a scenario `.cfg` rather than a map.
pub fn is_cfg(map: &str) -> bool {
    std::path::Path::new(map).extension().is_some_and(|e| e.eq_ignore_ascii_case("cfg"))
}

/// `sightline autoplay SCENARIO.cfg`: `--episodes` episodes, episode `k`
/// with its game seeded `--seed` + `k` and the policy's generator
/// seeded from both.
pub fn autoplay(args: &AutoplayArgs) -> Result<()> {
    let config = ScenarioConfig::load(&args.map)?;
    let name = std::path::Path::new(&args.map).file_stem().map(|s| s.to_string_lossy().into_owned());
    let started = std::time::Instant::now();
    let mut episodes = Vec::new();
    let buttons = config.available_buttons.len();
    let scenario = Scenario::open(&config, args.iwad.as_deref())
        .with_context(|| format!("{}: cannot open the scenario", args.map))?;
    if !args.json {
        for line in &scenario.decorate_unread {
            println!("DECORATE, left out: {line}");
        }
    }
    for k in 0..u64::from(args.episodes) {
        let seed = args.seed.wrapping_add(k);
        let mut episode = scenario.episode(seed).with_context(|| format!("{}: cannot start the scenario", args.map))?;
        let mut policy = RandomPolicy::new(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ 0x5eed);
        let limit = args.max_ticks;
        while episode.end().is_none() && u64::from(episode.actions) < limit {
            let action = match args.policy {
                Policy::Random => policy.action(buttons),
                Policy::Idle => vec![0.0; buttons],
            };
            episode.step(&action);
        }
        let end = episode.end();
        let warnings: Vec<String> = episode.game.scripts().map(|s| s.warnings().cloned().collect()).unwrap_or_default();
        if !args.json {
            let how = end.map_or_else(|| "unfinished".to_string(), |e| format!("{e:?}").to_lowercase());
            println!("episode {k}: {} tics, reward {:.2}, {how}", episode.actions, episode.total_reward);
            for w in &warnings {
                println!("  script: {w}");
            }
        }
        episodes.push(json!({
            "tics": episode.actions,
            "reward": episode.total_reward,
            "dead": end == Some(sightline::scenario::End::Death),
            "end": end,
            "shaping": f64::from(episode.global(1)) / 65536.0,
            "kills": episode.game.stats().kills,
            "ammo": episode.game.player().ammo,
            "warnings": warnings,
        }));
    }
    if args.json {
        let out = json!({
            "scenario": name,
            "decorate_unread": scenario.decorate_unread,
            "episodes": episodes,
            "seconds": started.elapsed().as_secs_f64(),
        });
        println!("{out}");
    }
    Ok(())
}
