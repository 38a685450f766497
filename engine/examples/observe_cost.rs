//! Times the parts of one agent step on a ViZDoom scenario: the tic, the
//! frame, the screen's overlays and the format conversion (medians of
//! 2,000). `cargo run --release -p sightline-engine --example observe_cost -- CFG [WxH]`
use std::time::Instant;

use sightline::scenario::observe::{convert, Observer};
use sightline::scenario::{Scenario, ScenarioConfig, ScreenFormat, ScreenResolution};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mut config = ScenarioConfig::load(&args[1]).expect("cfg");
    if let Some(size) = args.get(2) {
        let (w, h) = size.split_once('x').expect("WxH");
        config.screen_resolution = ScreenResolution { width: w.parse().unwrap(), height: h.parse().unwrap() };
    }
    config.episode_timeout = 0;
    let scenario = Scenario::open(&config, None).expect("open");
    let mut starts = Vec::new();
    for seed in 0..20 {
        let t = Instant::now();
        let _ = scenario.episode(seed).expect("episode");
        starts.push(t.elapsed().as_secs_f64());
    }
    println!("new episode {:.0} us", median(starts) * 1e6);
    let mut episode = scenario.episode(1).expect("episode");
    let mut observer = Observer::new(&config, 1);
    let (mut step, mut render, mut conv) = (Vec::new(), Vec::new(), Vec::new());
    let mut out = Vec::new();
    let buttons = config.available_buttons.len();
    for i in 0..2000 {
        // A new episode where one ends (basic's monster dies to a shot),
        // so every tic timed is a tic played.
        if episode.end().is_some() {
            episode = scenario.episode(i as u64).expect("episode");
        }
        let mut action = vec![0.0; buttons];
        action[i % buttons] = 1.0;
        let t = Instant::now();
        episode.step(&action);
        step.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        observer.render(&episode.game);
        render.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        convert(observer.screen(), ScreenFormat::Rgb24, &mut out).unwrap();
        conv.push(t.elapsed().as_secs_f64());
    }
    println!(
        "tic {:.1} us, frame {:.1} us, RGB24 {:.1} us",
        median(step) * 1e6,
        median(render) * 1e6,
        median(conv) * 1e6
    );
}
