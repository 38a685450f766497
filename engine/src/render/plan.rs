//! The frame's plan: which effects the map and the view actually call for.
//! Everything not in the plan costs nothing: no masked pass without things
//! in view or see-through middles, no sky without a sky sector, no distance
//! arithmetic in a map that turns diminishing light off, no fog blend
//! without fog.

use crate::level::Level;

/// Effects a renderer may be told to leave out even when a map asks for them
/// (benchmarks measure with and without; players may prefer speed).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Disabled {
    pub sky: bool,
    pub sprites: bool,
    pub masked: bool,
    pub diminishing: bool,
    pub fog: bool,
}

/// What this frame will do.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plan {
    /// A sector of the map shows the sky.
    pub sky: bool,
    /// A thing is in view (in front of the eye, on screen).
    pub sprites: bool,
    /// A two-sided line has a see-through middle texture.
    pub masked: bool,
    /// Light falls off with distance.
    pub diminishing: bool,
    /// Surfaces fade into fog.
    pub fog: bool,
}

impl Plan {
    /// The plan for `level` seen with `sprites_in_view` things in view.
    pub fn new(level: &Level, sprites_in_view: usize, disabled: Disabled) -> Plan {
        let map = &level.map;
        Plan {
            sky: level.materials.sky.is_some() && !disabled.sky,
            sprites: sprites_in_view > 0 && !disabled.sprites,
            masked: level.materials.masked && !disabled.masked,
            diminishing: map.diminishing_light && !disabled.diminishing,
            fog: map.fog.is_some() && !disabled.fog,
        }
    }

    /// The effects in the plan, by name.
    pub fn effects(&self) -> Vec<&'static str> {
        [
            (self.sky, "sky"),
            (self.sprites, "sprites"),
            (self.masked, "masked"),
            (self.diminishing, "diminishing light"),
            (self.fog, "fog"),
        ]
        .into_iter()
        .filter_map(|(on, name)| on.then_some(name))
        .collect()
    }

    /// Whether the masked pass runs at all.
    pub fn masked_pass(&self) -> bool {
        self.sprites || self.masked
    }
}
