//! `sightline check` for a made scenario, as data: the map's validation
//! problems, what the simulation cannot carry, then the autopilot's
//! reachability report (`autopilot::check::report`) as one [`Finding`]
//! each, and, given a reward specification, what in it can never pay (a
//! goal sector out of reach, a kill reward with no monster, an item kind
//! not in the map).

use glam::DVec2;

use super::{MapInput, RewardSpec};
use crate::actors::{ActorFlag, ActorTable};
use crate::campaign::{CampaignError, Opened};
use crate::level::{Level, LevelError};
use crate::map::MapError;

/// How much a finding matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The map cannot be played (it does not load), or the rewards name
    /// what is not there.
    Error,
    /// It plays, but something cannot be reached or can never pay.
    Warning,
    /// For information (the counts, a map without an exit).
    Note,
}

impl Severity {
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "note",
        }
    }
}

/// One thing `check` says of a map.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Finding {
    pub severity: Severity,
    pub message: String,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.severity.name(), self.message)
    }
}

fn finding(severity: Severity, message: String) -> Finding {
    Finding { severity, message }
}

/// Checks `map` as played at `skill` (1 to 5), with `rewards` if given:
/// errors first when it does not load (each validation problem its own),
/// else warnings and notes. An empty list has nothing to say.
pub fn check(map: &MapInput, rewards: Option<&RewardSpec>, skill: u8) -> Vec<Finding> {
    match map.load() {
        Ok(opened) => check_opened(&opened, rewards, skill),
        Err(e) => load_errors(&e),
    }
}

/// The errors of a map that does not load: each validation problem on
/// its own, with the map's name, as `sightline check` prints them.
fn load_errors(error: &CampaignError) -> Vec<Finding> {
    if let CampaignError::Level(LevelError::Map(MapError::Invalid { path, problems })) = error {
        return problems.iter().map(|p| finding(Severity::Error, format!("{path}: {p}"))).collect();
    }
    vec![finding(Severity::Error, error.to_string())]
}

/// [`check`] on a map already opened.
pub(super) fn check_opened(opened: &Opened, rewards: Option<&RewardSpec>, skill: u8) -> Vec<Finding> {
    let level = &opened.level;
    let table = ActorTable::active();
    let mut out = Vec::new();
    match crate::sim::from_map::level_and_report(&level.compiled, table) {
        Err(e) => return vec![finding(Severity::Error, e.to_string())],
        Ok(converted) => {
            for note in converted.report {
                out.push(finding(Severity::Warning, format!("in the simulation, {note}")));
            }
        }
    }
    if let Some(spec) = rewards {
        if let Err(e) = spec.check(level.compiled.map.sectors.len(), table) {
            out.push(finding(Severity::Error, e.to_string()));
            return out;
        }
    }
    let skill = skill.clamp(1, 5);
    let goals: Vec<usize> = rewards.map_or(Vec::new(), |r| r.reach.iter().map(|g| g.sector as usize).collect());
    let (report, reached) = reachability(level, skill, &goals);
    out.extend(report_findings(&report, rewards));
    if let Some(spec) = rewards {
        out.extend(reward_findings(level, spec, skill, &reached));
    }
    out.sort_by_key(|f| f.severity);
    out
}

/// The autopilot's report, and which of `goals` (sectors) the player can
/// stand in. The report already answers that for secret sectors (is a
/// cell of the sector reached?), so the goals are asked as secrets, on a
/// copy of the level; its secrets come in sector order.
fn reachability(level: &Level, skill: u8, goals: &[usize]) -> (crate::autopilot::check::Report, Vec<bool>) {
    let mut probe = level.clone();
    let sectors = &mut probe.compiled.map.sectors;
    let secret: Vec<bool> = sectors.iter().map(|s| s.special.secret).collect();
    for &g in goals {
        sectors[g].special.secret = true;
    }
    let asked: Vec<usize> = (0..sectors.len()).filter(|&s| sectors[s].special.secret).collect();
    let mut report = crate::autopilot::check::report(&probe, skill);
    // No secrets at all when the start has no standable cell near it.
    let reached_sector = |s: usize| asked.iter().position(|&a| a == s).and_then(|i| report.secrets.get(i));
    let reached = goals.iter().map(|&g| reached_sector(g).is_some_and(|p| p.reachable)).collect();
    let kept = asked.iter().zip(std::mem::take(&mut report.secrets)).filter(|(&s, _)| secret[s]);
    report.secrets = kept.map(|(_, place)| place).collect();
    (report, reached)
}

fn at(x: f64, y: f64) -> String {
    format!("({x:.0}, {y:.0})")
}

/// The reachability report, one finding per thing out of reach.
fn report_findings(report: &crate::autopilot::check::Report, rewards: Option<&RewardSpec>) -> Vec<Finding> {
    let mut out = Vec::new();
    let pays_exit = rewards.is_some_and(|r| r.exit != 0.0);
    if report.exits.is_empty() {
        let (severity, why) = if pays_exit {
            (Severity::Warning, ", so rewards.exit is never paid")
        } else {
            (Severity::Note, " (an episode ends by a goal sector, death or the timeout)")
        };
        out.push(finding(severity, format!("the map has no exit{why}")));
    } else if !report.exit_reachable {
        out.push(finding(Severity::Warning, "no exit can be reached".into()));
    }
    for e in report.exits.iter().filter(|e| !e.reachable) {
        out.push(finding(Severity::Warning, format!("the {} at {} cannot be reached", e.what, at(e.x, e.y))));
    }
    for k in report.keys.iter().filter(|k| !k.reachable) {
        let own = if k.behind_own_door { " (it is behind a door of its own colour)" } else { "" };
        out.push(finding(
            Severity::Warning,
            format!("the {} key at {} cannot be reached{own}", k.colour, at(k.x, k.y)),
        ));
    }
    for s in report.secrets.iter().filter(|s| !s.reachable) {
        out.push(finding(Severity::Warning, format!("{} at {} cannot be reached", s.what, at(s.x, s.y))));
    }
    for i in report.items.iter().filter(|i| !i.reachable) {
        out.push(finding(Severity::Warning, format!("the {} at {} cannot be reached", i.what, at(i.x, i.y))));
    }
    for s in &report.soft_locks {
        let what = format!(
            "soft lock: {} from sector {} into sector {} at {} leaves the exit unreachable",
            s.how,
            s.from_sector,
            s.to_sector,
            at(s.x, s.y)
        );
        out.push(finding(Severity::Warning, what));
    }
    let reached = report.items.iter().filter(|i| i.reachable).count();
    let cells = format!("{} of {} standable cells", report.reachable_cells, report.standable_cells);
    out.push(finding(Severity::Note, format!("{reached} of {} items and {cells} can be reached", report.items.len())));
    out
}

/// What in `spec` can never pay on this map at `skill`.
fn reward_findings(level: &Level, spec: &RewardSpec, skill: u8, reached: &[bool]) -> Vec<Finding> {
    let map = &level.compiled.map;
    let table = ActorTable::active();
    let mut out = Vec::new();
    let things: Vec<(&str, DVec2)> =
        map.things.iter().filter(|t| t.in_single_player(skill)).map(|t| (t.kind.as_str(), t.pos)).collect();
    let is = |kind: &str, flag| table.get(kind).is_some_and(|a| a.has(flag));
    let start = level.compiled.sector_at(map.player_start().pos);
    for (i, (goal, &ok)) in spec.reach.iter().zip(reached).enumerate() {
        let s = goal.sector;
        if !ok {
            out.push(finding(Severity::Warning, format!("rewards.reach[{i}]: sector {s} cannot be reached")));
        }
        if s as usize == start {
            let what =
                format!("rewards.reach[{i}]: the player starts in sector {s}, which pays only when entered again");
            out.push(finding(Severity::Warning, what));
        }
    }
    if spec.kill != 0.0 && !things.iter().any(|&(k, _)| is(k, ActorFlag::CountKill)) {
        let what = format!("rewards.kill: the map has no monster to kill at skill {skill}");
        out.push(finding(Severity::Warning, what));
    }
    if spec.secret != 0.0 && !map.sectors.iter().any(|s| s.special.secret) {
        out.push(finding(Severity::Warning, "rewards.secret: the map has no secret sector".into()));
    }
    if spec.pickup.pays() && !things.iter().any(|&(k, _)| is(k, ActorFlag::Special)) {
        let what = format!("rewards.pickup: the map has no item at skill {skill} (a monster may drop one)");
        out.push(finding(Severity::Note, what));
    }
    for kind in spec.pickup.kinds.keys() {
        if !things.iter().any(|&(k, _)| k == kind) {
            let what = format!("rewards.pickup.kinds[{kind:?}]: no {kind} in the map at skill {skill}");
            out.push(finding(Severity::Note, what));
        }
    }
    out
}
