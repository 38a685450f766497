//! ViZDoom's scenarios from the command line: `sightline autoplay
//! SCENARIO.cfg` plays episodes with a policy and reports each one's
//! length and reward (`--json` as one object, which
//! `scripts/vizdoom-compare.py` reads).

use anyhow::{Context, Result};
use serde_json::json;
use sightline::scenario::{Episode, Expert, RandomPolicy, Scenario, ScenarioConfig};

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
    let scenario = Scenario::open(&config, args.iwad.as_deref())
        .with_context(|| format!("{}: cannot open the scenario", args.map))?;
    if !args.json {
        for line in &scenario.decorate_unread {
            println!("DECORATE, left out: {line}");
        }
    }
    let mut expert_us = Vec::new();
    for k in 0..u64::from(args.episodes) {
        let seed = args.seed.wrapping_add(k);
        let episode = play(&scenario, seed, args.policy, args.max_ticks, &mut expert_us)
            .with_context(|| format!("{}: cannot start the scenario", args.map))?;
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
            "expert_median_us": median(&mut expert_us),
        });
        println!("{out}");
    } else if let Some(us) = median(&mut expert_us) {
        println!("the expert's answer took {us:.1} µs a step (median of {})", expert_us.len());
    }
    Ok(())
}

/// Plays one episode of `scenario` seeded `seed` with `policy` for at most
/// `limit` actions; with the expert, each of its answers' time in µs is
/// added to `expert_us`. Episode `seed`'s random policy draws from a
/// generator seeded from it.
pub fn play(scenario: &Scenario, seed: u64, policy: Policy, limit: u64, expert_us: &mut Vec<f64>) -> Result<Episode> {
    let mut episode = scenario.episode(seed)?;
    let buttons = scenario.config.available_buttons.len();
    let mut random = RandomPolicy::new(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ 0x5eed);
    let mut expert = (policy == Policy::Expert).then(|| Expert::new(&episode));
    while episode.end().is_none() && u64::from(episode.actions) < limit {
        let action = match (policy, expert.as_mut()) {
            (Policy::Expert, Some(expert)) => {
                let started = std::time::Instant::now();
                let action = expert.action(&episode);
                expert_us.push(started.elapsed().as_secs_f64() * 1e6);
                action
            }
            (Policy::Random, _) => random.action(buttons),
            _ => vec![0.0; buttons],
        };
        episode.step(&action);
    }
    Ok(episode)
}

/// The median of `values` (sorted in place), if any.
pub fn median(values: &mut [f64]) -> Option<f64> {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied()
}
