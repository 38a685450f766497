//! `sightline bench expert SCENARIO.cfg...`: the autopilot as an expert
//! (`scenario::expert`). For each scenario, `--episodes` episodes followed
//! by the expert and as many by the random policy of `sightline autoplay`
//! (episode `k` seeded `k` for both), then one Markdown row: the mean
//! reward of each (with its standard deviation), the share of episodes
//! the expert finished by the exit, and what an answer costs: the median,
//! mean and 99th percentile of one step's answer, and the mean of making
//! the expert (its navigation grid and the level's mechanisms).

use std::time::Instant;

use anyhow::{Context, Result};
use sightline::scenario::{End, Expert, Scenario, ScenarioConfig};

use crate::cli::{BenchExpertArgs, Policy};
use crate::scenario::{median, play};

/// Actions at most per episode: defend_the_line and take_cover set no
/// timeout (5 minutes of play; none of their episodes came near it).
const LIMIT: u64 = 35 * 60 * 5;

pub fn run(args: &BenchExpertArgs) -> Result<()> {
    println!("| scenario | expert reward | random reward | expert's episodes ending by the exit | median µs | mean µs | p99 µs | setup ms |");
    println!("|---|---|---|---|---|---|---|---|");
    for cfg in &args.scenarios {
        let label = cfg.display();
        let config = ScenarioConfig::load(cfg)?;
        let scenario = Scenario::open(&config, args.iwad.as_deref())
            .with_context(|| format!("{label}: cannot open the scenario"))?;
        let (mut expert, mut random, mut exits, mut times) = (Vec::new(), Vec::new(), 0, Vec::new());
        for seed in 0..u64::from(args.episodes) {
            let episode = play(&scenario, seed, Policy::Expert, LIMIT, &mut times)?;
            exits += usize::from(episode.end() == Some(End::Exit));
            expert.push(episode.total_reward);
            random.push(play(&scenario, seed, Policy::Random, LIMIT, &mut Vec::new())?.total_reward);
        }
        let setup = setup_ms(&scenario, args.episodes)?;
        let name = cfg.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        let mean_us = times.iter().sum::<f64>() / times.len().max(1) as f64;
        let median_us = median(&mut times).unwrap_or(0.0);
        let p99 = times.get(times.len() * 99 / 100).copied().unwrap_or(0.0);
        println!(
            "| {name} | {} | {} | {exits} of {} | {median_us:.1} | {mean_us:.1} | {p99:.0} | {setup:.2} |",
            spread(&expert),
            spread(&random),
            args.episodes
        );
    }
    Ok(())
}

/// The mean of `values` and their standard deviation, as "m ± s".
fn spread(values: &[f64]) -> String {
    let n = values.len().max(1) as f64;
    let mean = values.iter().sum::<f64>() / n;
    let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    format!("{mean:.2} ± {sd:.2}")
}

/// The mean time of making an expert at an episode's start, ms.
fn setup_ms(scenario: &Scenario, episodes: u32) -> Result<f64> {
    let mut total = 0.0;
    let count = episodes.min(10);
    for seed in 0..u64::from(count) {
        let episode = scenario.episode(seed)?;
        let started = Instant::now();
        std::hint::black_box(Expert::new(&episode));
        total += started.elapsed().as_secs_f64() * 1e3;
    }
    Ok(total / f64::from(count.max(1)))
}
