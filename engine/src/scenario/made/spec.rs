//! A made scenario's reward specification ([`RewardSpec`]): what each
//! event pays, read from RON (`Rewards(kill: 1.0, reach: [...])`) or JSON
//! (what Python sends), then checked against the map it will pay on
//! ([`RewardSpec::check`]) so that a wrong sector or item kind is refused
//! by name before any game starts. The events themselves are counted in
//! `made::events`.
//!
//! Every number is a reward added when its event happens: a penalty is a
//! negative number (`death: -100.0`, `damage_taken: -0.1`), unlike ViZDoom's
//! `death_penalty`, which is subtracted. One sign rule for the whole
//! specification was thought less error-prone than ViZDoom's mix.

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{self, MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};

use super::MadeError;
use crate::actors::{ActorFlag, ActorTable};

/// What a made scenario pays, event by event (all 0 by default: an event
/// with no reward costs nothing per tic).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Rewards", deny_unknown_fields, default)]
pub struct RewardSpec {
    /// Per monster the player kills (Doom's kill count: in a one-player
    /// game every counted monster's death, as `KILLCOUNT`).
    pub kill: f64,
    /// Per item picked up.
    pub pickup: Pickup,
    /// Per point of health the player loses (after armour; `DAMAGE_TAKEN`).
    pub damage_taken: f64,
    /// Entering given sectors, once each.
    pub reach: Vec<Reach>,
    /// Per secret sector found.
    pub secret: f64,
    /// On leaving the level (an exit line); the episode ends on that tic.
    pub exit: f64,
    /// Per tic played (ViZDoom's `living_reward`).
    pub living: f64,
    /// On the player's death (which ends the episode).
    pub death: f64,
    /// The episode's length in tics; 0 is no limit. Read signed, so that a
    /// negative number is refused by name rather than as a type error.
    pub timeout: i64,
}

/// What picking items up pays: `each` for any item, or the amount given
/// for its kind (`kinds`, by the actor table's names: `"medikit"`,
/// `"clip"`). Written as a number (`pickup: 0.5`, every item alike) or in
/// full (`pickup: (each: 0.0, kinds: {"medikit": 1.0})`, JSON
/// `{"each": 0, "kinds": {"medikit": 1}}`).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Pickup {
    pub each: f64,
    pub kinds: BTreeMap<String, f64>,
}

/// A sector whose entry pays, once in an episode.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Reach {
    /// The sector's index in the map (signed, so that -1 is refused by name).
    pub sector: i64,
    #[serde(default)]
    pub reward: f64,
    /// Entering it ends the episode (as the exit does).
    #[serde(default)]
    pub end: bool,
}

impl Pickup {
    /// What picking up an item of `kind` pays.
    pub fn of(&self, kind: &str) -> f64 {
        self.kinds.get(kind).copied().unwrap_or(self.each)
    }

    /// Whether any pickup pays anything.
    pub fn pays(&self) -> bool {
        self.each != 0.0 || self.kinds.values().any(|&r| r != 0.0)
    }
}

impl<'de> Deserialize<'de> for Pickup {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Pickup, D::Error> {
        deserializer.deserialize_any(PickupVisitor)
    }
}

struct PickupVisitor;

impl<'de> Visitor<'de> for PickupVisitor {
    type Value = Pickup;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number (every item alike) or (each: N, kinds: {\"kind\": N})")
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Pickup, E> {
        Ok(Pickup { each: v, kinds: BTreeMap::new() })
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Pickup, E> {
        self.visit_f64(v as f64)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Pickup, E> {
        self.visit_f64(v as f64)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Pickup, A::Error> {
        let mut pickup = Pickup::default();
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                "each" => pickup.each = map.next_value()?,
                "kinds" => pickup.kinds = map.next_value()?,
                other => return Err(de::Error::unknown_field(other, &["each", "kinds"])),
            }
        }
        Ok(pickup)
    }
}

impl RewardSpec {
    /// Reads a specification written in RON (`Rewards(...)`; the name may
    /// be left out). Errors give RON's line and column.
    pub fn from_ron(text: &str) -> Result<RewardSpec, MadeError> {
        let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        options
            .from_str(text)
            .map_err(|e| MadeError::Syntax(format!("{}:{}: {}", e.span.start.line, e.span.start.col, e.code)))
    }

    /// Reads a specification written in JSON (an object of the fields).
    pub fn from_json(text: &str) -> Result<RewardSpec, MadeError> {
        serde_json::from_str(text).map_err(|e| MadeError::Syntax(e.to_string()))
    }

    /// RON if the text starts with `(` or a name, JSON if with `{`.
    pub fn parse(text: &str) -> Result<RewardSpec, MadeError> {
        if text.trim_start().starts_with('{') {
            RewardSpec::from_json(text)
        } else {
            RewardSpec::from_ron(text)
        }
    }

    /// The specification as RON text (what [`RewardSpec::from_ron`] reads).
    pub fn to_ron(&self) -> String {
        let config = ron::ser::PrettyConfig::default().struct_names(true);
        ron::ser::to_string_pretty(self, config).unwrap_or_else(|e| format!("/* {e} */"))
    }

    /// The timeout in tics, once [`RewardSpec::check`] has passed.
    pub fn timeout_tics(&self) -> u32 {
        u32::try_from(self.timeout).unwrap_or(0)
    }

    /// Refuses what cannot be paid on a map of `sectors` sectors with the
    /// actors of `table`: a number that is not finite, a negative timeout,
    /// a sector not in the map or named twice, an item kind that is not an
    /// item. The first problem found, by its element
    /// (`rewards.reach[1].sector`).
    pub fn check(&self, sectors: usize, table: &ActorTable) -> Result<(), MadeError> {
        let bad = |element: String, what: String| Err(MadeError::Rewards { element, what });
        let numbers = [
            ("kill", self.kill),
            ("damage_taken", self.damage_taken),
            ("secret", self.secret),
            ("exit", self.exit),
            ("living", self.living),
            ("death", self.death),
            ("pickup.each", self.pickup.each),
        ];
        let kinds = self.pickup.kinds.iter().map(|(k, &v)| (format!("pickup.kinds[{k:?}]"), v));
        let reaches = self.reach.iter().enumerate().map(|(i, r)| (format!("reach[{i}].reward"), r.reward));
        let all = numbers.iter().map(|&(k, v)| (k.to_string(), v)).chain(kinds).chain(reaches);
        for (element, value) in all {
            if !value.is_finite() {
                return bad(element, format!("{value} is not a finite number"));
            }
        }
        if self.timeout < 0 {
            let what = format!("{} tics is negative; give the episode's length in tics (0: no limit)", self.timeout);
            return bad("timeout".into(), what);
        }
        if self.timeout > i64::from(u32::MAX) {
            return bad("timeout".into(), format!("{} tics is more than {}", self.timeout, u32::MAX));
        }
        for (i, r) in self.reach.iter().enumerate() {
            if !(0..sectors as i64).contains(&r.sector) {
                let what = format!("sector {} is not in the map (its sectors are 0..{sectors})", r.sector);
                return bad(format!("reach[{i}].sector"), what);
            }
            if let Some(j) = self.reach[..i].iter().position(|q| q.sector == r.sector) {
                return bad(format!("reach[{i}].sector"), format!("sector {} is already reach[{j}]", r.sector));
            }
        }
        for kind in self.pickup.kinds.keys() {
            let item = table.get(kind).is_some_and(|a| a.has(ActorFlag::Special));
            if item {
                continue;
            }
            let items = table.actors.iter().filter(|a| a.has(ActorFlag::Special)).map(|a| a.name.as_str());
            let what = match (table.get(kind), crate::actors::nearest(kind, items)) {
                (Some(_), _) => format!("{kind:?} is not an item (nothing picks it up)"),
                (None, Some(n)) => format!("{kind:?} names no item; did you mean {n:?}?"),
                (None, None) => format!("{kind:?} names no item (the actors are in engine/data/actors.ron)"),
            };
            return bad(format!("pickup.kinds[{kind:?}]"), what);
        }
        Ok(())
    }
}
