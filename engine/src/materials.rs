//! Materials: every texture name a map uses, resolved once when the level is
//! opened (a PNG beside the map or a built-in texture) into ids the renderer
//! indexes directly. A name that resolves to nothing is an error naming the
//! element that uses it.

use std::collections::{BTreeSet, HashMap};
use std::path::PathBuf;

mod standin;

pub use standin::MissingArt;

use crate::actors::{ActorDef, ActorTable, StateId};
use crate::map::{Map, Side, PLAYER_START, SKY};
use crate::texture::animdefs::AnimDefs;
use crate::texture::{Library, TextureError, TextureId, TextureKind, TextureSet};

/// The textures of one side of a line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct SideTextures {
    pub upper: Option<TextureId>,
    pub middle: Option<TextureId>,
    pub lower: Option<TextureId>,
}

/// A sector's plane textures; `None` for untextured or sky.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct SectorTextures {
    pub floor: Option<TextureId>,
    pub ceiling: Option<TextureId>,
}

#[derive(Clone, Default)]
pub struct Materials {
    pub textures: TextureSet,
    /// Per line: `[front, back]` (the back is empty on one-sided lines).
    pub sides: Vec<[SideTextures; 2]>,
    pub sectors: Vec<SectorTextures>,
    /// Per thing: its sprite (`None` for things that are not drawn, such as
    /// the player start).
    pub sprites: Vec<Option<TextureId>>,
    /// Per actor sprite and frame ([`Materials::view_index`]), the textures
    /// it shows from Doom's eight directions (index 0 is direction 1, the
    /// front), for every actor the map's things can bring into play; `None`
    /// where the art has no such frame. Mirrored views are textures of
    /// their own (see `wad::import::sprite_view`).
    pub sprite_views: Vec<Option<[TextureId; 8]>>,
    /// Per sprite frame (indexed as `sprite_views`), the screen picture of
    /// a weapon's frame (the weapons' states only).
    pub screen_views: Vec<Option<TextureId>>,
    /// The panorama shown by `"SKY"` ceilings and floors, if any sector has one.
    pub sky: Option<TextureId>,
    /// Some two-sided line has a see-through middle texture.
    pub masked: bool,
    /// Per texture id, the texture drawn in its place now: itself, or the
    /// current frame of its animation ([`Self::side`] and [`Self::plane`]
    /// apply it; `play::world::animation` advances it).
    pub translation: Vec<TextureId>,
    /// The animations whose textures the map uses, with every frame resolved.
    pub animations: Vec<Animated>,
    /// Switch textures the map uses: each with its partner and its place in
    /// the switch list (Doom swaps the first part of a side that matches,
    /// in list order).
    pub switches: HashMap<TextureId, (TextureId, usize)>,
    /// Per texture and player colour, the texture redrawn in that colour
    /// (or itself, where it has no green to redraw), made when a body in
    /// that colour is first drawn ([`Materials::in_colour`]).
    pub coloured: HashMap<(TextureId, u8), TextureId>,
    /// What an actor's frame that no art has becomes.
    pub missing: MissingArt,
    /// The sprite frames (`TROOA`) drawn as placeholders, each warned of once.
    pub placeholders: BTreeSet<String>,
    /// What a person should hear of: one line per frame drawn as a
    /// placeholder, naming the actor and the frame.
    pub warnings: Vec<String>,
}

/// Frames a sprite may have: `A` to `]` (Doom's 29).
const SPRITE_FRAMES: usize = 29;

/// An animation's frames, as texture ids.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Animated {
    pub frames: Vec<TextureId>,
    pub tics: u32,
}

#[derive(Debug, thiserror::Error)]
#[error("{path}: {element}: {error}")]
pub struct MaterialError {
    pub path: String,
    /// Which element uses the name, e.g. `line 6 front side upper texture`.
    pub element: String,
    pub error: TextureError,
}

impl Materials {
    /// Sets every animated texture's current frame for tick `time` (Doom's
    /// `P_UpdateSpecials`): a texture that is frame `k` of an animation of
    /// `n` shows frame `(k + time / tics) mod n`, so all run in step. The
    /// renderers apply [`Materials::translation`] where they look a
    /// texture up: only what is drawn pays for it.
    pub fn animate(&mut self, time: u64) {
        for anim in &self.animations {
            let n = anim.frames.len();
            let step = (time / u64::from(anim.tics)) as usize % n;
            for (k, &frame) in anim.frames.iter().enumerate() {
                if let Some(slot) = self.translation.get_mut(frame.0 as usize) {
                    *slot = anim.frames[(k + step) % n];
                }
            }
        }
    }

    /// Resolves every texture `map` names, looking for PNGs under each of `dirs`
    /// (`textures/` and `sprites/` inside them) before the built-in textures.
    /// `label` names the map in errors.
    pub fn resolve(map: &Map, dirs: &[PathBuf], label: &str) -> Result<Materials, MaterialError> {
        Materials::resolve_in(map, &Library::dirs(dirs), label)
    }

    /// [`Materials::resolve`] in a library: PNG folders, then a WAD, then
    /// the built-in set. An actor's frame none of them has is a stand-in
    /// figure when the library has no WAD, else a placeholder with a
    /// warning ([`MissingArt`]).
    pub fn resolve_in(map: &Map, library: &Library, label: &str) -> Result<Materials, MaterialError> {
        let missing = if library.wad.is_some() { MissingArt::Placeholder } else { MissingArt::StandIn };
        Materials::resolve_with(map, library, label, missing)
    }

    /// [`Materials::resolve_in`] with `missing` saying what an actor's
    /// frame no art has becomes; with [`MissingArt::Skip`] no sprite is
    /// looked up at all (walls and flats still are: their sizes matter to
    /// play, as Doom's raise-to-texture floors measure them).
    pub fn resolve_with(
        map: &Map,
        library: &Library,
        label: &str,
        missing: MissingArt,
    ) -> Result<Materials, MaterialError> {
        let mut m = Materials::default();
        // A name may be a texture of the other kind (a STONE floor): walls and
        // flats are both just images. Report the lookup of the expected kind.
        let mut get = |name: &str, kind: TextureKind, element: String| {
            let other = match kind {
                TextureKind::Wall => Some(TextureKind::Flat),
                TextureKind::Flat => Some(TextureKind::Wall),
                TextureKind::Sprite | TextureKind::Screen => None,
            };
            m.textures
                .resolve_in(name, kind, library)
                .or_else(|error| match other {
                    Some(o) if matches!(error, TextureError::Missing { .. }) => {
                        m.textures.resolve_in(name, o, library).map_err(|_| error)
                    }
                    _ => Err(error),
                })
                .map_err(|error| MaterialError { path: label.to_string(), element, error })
        };
        let mut sides = Vec::with_capacity(map.lines.len());
        for (i, line) in map.lines.iter().enumerate() {
            let mut pair = [SideTextures::default(); 2];
            for (k, (which, side)) in
                [("front", Some(&line.front)), ("back", line.back.as_ref())].into_iter().enumerate()
            {
                if let Some(side) = side {
                    pair[k] = side_textures(side, &mut |name, part| {
                        get(name, TextureKind::Wall, format!("line {i} {which} side {part} texture"))
                    })?;
                }
            }
            sides.push(pair);
        }
        let mut sectors = Vec::with_capacity(map.sectors.len());
        let mut uses_sky = false;
        for (i, s) in map.sectors.iter().enumerate() {
            let mut plane = |name: &Option<String>, which: &str| -> Result<Option<TextureId>, MaterialError> {
                match name.as_deref() {
                    None => Ok(None),
                    Some(n) if n.eq_ignore_ascii_case(SKY) => {
                        uses_sky = true;
                        Ok(None)
                    }
                    Some(n) => get(n, TextureKind::Flat, format!("sector {i} {which} texture")).map(Some),
                }
            };
            let floor = plane(&s.floor_texture, "floor")?;
            let ceiling = plane(&s.ceiling_texture, "ceiling")?;
            sectors.push(SectorTextures { floor, ceiling });
        }
        let sky = match (&map.sky, uses_sky) {
            (_, false) => None,
            (Some(name), true) => Some(get(name, TextureKind::Wall, format!("the sky ({name})"))?),
            (None, true) => Some(get(SKY, TextureKind::Wall, "the sky".into())?),
        };
        let masked =
            sides.iter().zip(&map.lines).any(|(s, l)| l.back.is_some() && s.iter().any(|s| s.middle.is_some()));
        let mut m = Materials { sides, sectors, sky, masked, missing, ..m };
        m.sprites = m.thing_sprites(map, library, label)?;
        let own = own_animations(map, library).map_err(|error| MaterialError {
            path: label.to_string(),
            element: "the animations file".into(),
            error,
        })?;
        m.add_animations(map, library, own.as_ref().unwrap_or(AnimDefs::doom()));
        if map.version >= 2 {
            m.add_sprite_views(map, library);
        }
        Ok(m)
    }

    /// Per thing, its sprite: `None` for things not drawn (the player
    /// start, markers) and, with [`MissingArt::Skip`], for all. A version-2
    /// thing's actor whose first frame no art has takes its stand-in or a
    /// placeholder; a version-1 thing names a picture, which must exist.
    fn thing_sprites(
        &mut self,
        map: &Map,
        library: &Library,
        label: &str,
    ) -> Result<Vec<Option<TextureId>>, MaterialError> {
        let table = ActorTable::active();
        let mut sprites = Vec::with_capacity(map.things.len());
        for (i, t) in map.things.iter().enumerate() {
            let error = |error| MaterialError {
                path: label.to_string(),
                element: format!("thing {i} (kind {:?}) sprite", t.kind),
                error,
            };
            if t.kind == PLAYER_START || self.missing == MissingArt::Skip {
                sprites.push(None);
                continue;
            }
            if map.version < 2 {
                let id = self
                    .textures
                    .resolve_in(&t.kind.to_ascii_uppercase(), TextureKind::Sprite, library)
                    .map_err(error)?;
                sprites.push(Some(id));
                continue;
            }
            // A thing type names its first frame; its front view is
            // rotation 0 (all sides alike) or 1 (facing the viewer).
            let Some(actor) = table.get(&t.kind).filter(|a| table.first_frame(a).is_some()) else {
                sprites.push(None);
                continue;
            };
            let Some(spawn) = actor.label("Spawn").map(|s| table.state(s)) else {
                sprites.push(None);
                continue;
            };
            let (sprite, frame) = (spawn.sprite, spawn.frame);
            let stem = format!("{}{}", table.sprites[usize::from(sprite)], char::from(b'A' + frame));
            let found = match self.textures.resolve_in(&format!("{stem}0"), TextureKind::Sprite, library) {
                Err(TextureError::Missing { .. }) => {
                    self.textures.resolve_in(&format!("{stem}1"), TextureKind::Sprite, library)
                }
                other => other,
            };
            sprites.push(match found {
                Ok(id) => Some(id),
                Err(TextureError::Missing { .. }) => self.unpainted(table, actor, sprite, frame).map(|views| views[0]),
                Err(e) => return Err(error(e)),
            });
        }
        Ok(sprites)
    }

    /// The views of `actor`'s frame that no art has, by [`Self::missing`]:
    /// its stand-in, or a placeholder and a warning (once a frame).
    fn unpainted(&mut self, table: &ActorTable, actor: &ActorDef, sprite: u16, frame: u8) -> Option<[TextureId; 8]> {
        let stem = format!("{}{}", table.sprites[usize::from(sprite)], char::from(b'A' + frame));
        match self.missing {
            MissingArt::Skip => None,
            MissingArt::StandIn => {
                let views = standin::views(table, actor, sprite, frame);
                let ids: Vec<TextureId> = if views.len() == 1 {
                    vec![self.textures.insert(&format!("{stem}0"), TextureKind::Sprite, views[0].clone())]
                } else {
                    let name = |k: usize| format!("{stem}{}", k + 1);
                    views
                        .iter()
                        .enumerate()
                        .map(|(k, v)| self.textures.insert(&name(k), TextureKind::Sprite, v.clone()))
                        .collect()
                };
                Some(std::array::from_fn(|k| ids[k % ids.len()]))
            }
            MissingArt::Placeholder => {
                let id =
                    self.textures.insert(&format!("{stem}0"), TextureKind::Sprite, standin::placeholder(Some(actor)));
                if self.placeholders.insert(stem.clone()) {
                    self.warnings.push(format!(
                        "no picture of {}'s frame {} (sprite {stem}): drawn as a placeholder",
                        actor.name,
                        char::from(b'A' + frame)
                    ));
                }
                Some([id; 8])
            }
        }
    }

    /// Texture `id` in player colour `colour` (Doom's translation bits: the
    /// player's number less one; 0 is the art's own green), made the first
    /// time it is asked for ([`crate::texture::colours`]).
    pub fn in_colour(&mut self, id: TextureId, colour: u8) -> TextureId {
        if colour == 0 {
            return id;
        }
        if let Some(&made) = self.coloured.get(&(id, colour)) {
            return made;
        }
        let made = match crate::texture::colours::in_colour(self.textures.get(id), usize::from(colour)) {
            Some(texture) => {
                let name = format!("{}@colour{colour}", self.textures.name(id));
                self.textures.add(name, texture)
            }
            None => id,
        };
        self.coloured.insert((id, colour), made);
        made
    }

    /// The index of sprite `sprite`'s frame `frame` in [`Self::sprite_views`].
    pub fn view_index(sprite: u16, frame: u8) -> usize {
        usize::from(sprite) * SPRITE_FRAMES + usize::from(frame)
    }

    /// Resolves every view of every frame of the actors the map's things
    /// can bring into play (the effects every game makes included). A view
    /// the art lacks takes the frame's first view; a frame with none stays
    /// `None`, and the actor keeps the last frame it could show.
    fn add_sprite_views(&mut self, map: &Map, library: &Library) {
        let table = ActorTable::active();
        let roots: Vec<usize> = map.things.iter().filter_map(|t| table.index(&t.kind)).collect();
        self.add_actor_views(table, roots, library);
    }

    /// Resolves the views of `actors` of `table` and of what they bring
    /// into play, with the effects every game makes and every weapon (a
    /// game whose scripts spawn actors by name, or whose table is a mod's
    /// with sprites of its own, adds its actors this way; the table's
    /// sprites must extend the active table's, as a layered table's do).
    pub fn add_actor_views(&mut self, table: &ActorTable, actors: Vec<usize>, library: &Library) {
        if self.missing == MissingArt::Skip {
            return;
        }
        let effects = ["bullet_puff", "blood", "teleport_fog", "item_fog"].into_iter().filter_map(|n| table.index(n));
        let weapons: Vec<usize> = (0..table.actors.len()).filter(|&i| table.actors[i].weapon.is_some()).collect();
        let slots = table.sprites.len() * SPRITE_FRAMES;
        if self.sprite_views.len() < slots {
            self.sprite_views.resize(slots, None);
            self.screen_views.resize(slots, None);
        }
        let roots = actors.into_iter();
        for &w in &weapons {
            for label in ["Ready", "Deselect", "Select", "Fire", "Flash"] {
                let Some(start) = table.actors[w].label(label) else { continue };
                // A label's sequence, up to the next label of the actor or a loop back.
                let mut at = Some(start);
                for _ in 0..64 {
                    let Some(id) = at else { break };
                    let state = table.state(id);
                    let slot = Materials::view_index(state.sprite, state.frame);
                    if self.screen_views[slot].is_none() {
                        let name =
                            format!("{}{}0", table.sprites[usize::from(state.sprite)], char::from(b'A' + state.frame));
                        self.screen_views[slot] = self.textures.resolve_in(&name, TextureKind::Screen, library).ok();
                    }
                    at = state.next.filter(|n| n.0 > id.0);
                }
            }
        }
        // What the map can bring into play is drawn whatever the art
        // lacks; the other weapons only where the art has them (their
        // screen pictures are what matters).
        let placed = table.closure(roots.chain(effects));
        for actor in table.closure(placed.iter().copied().chain(weapons.iter().copied())) {
            let def = &table.actors[actor];
            // A weapon's own states are on the screen (its screen views
            // above); in the world it shows its Spawn frames alone.
            let world: Option<Vec<StateId>> = def.weapon.as_ref().map(|_| {
                let mut run = Vec::new();
                let mut at = def.label("Spawn");
                while let Some(id) = at.filter(|id| !run.contains(id)) {
                    run.push(id);
                    at = table.state(id).next;
                }
                run
            });
            for id in table.states_of(def) {
                let state = table.state(id);
                let slot = Materials::view_index(state.sprite, state.frame);
                if self.sprite_views[slot].is_some() {
                    continue;
                }
                let stem = format!("{}{}", table.sprites[usize::from(state.sprite)], char::from(b'A' + state.frame));
                let mut find =
                    |view: char| self.textures.resolve_in(&format!("{stem}{view}"), TextureKind::Sprite, library).ok();
                let found = match find('0') {
                    Some(all) => Some([all; 8]),
                    None => {
                        let views: Vec<Option<TextureId>> = ('1'..='8').map(&mut find).collect();
                        views.iter().flatten().next().map(|&first| std::array::from_fn(|k| views[k].unwrap_or(first)))
                    }
                };
                let shown = placed.contains(&actor) && world.as_ref().is_none_or(|w| w.contains(&id));
                self.sprite_views[slot] =
                    found.or_else(|| if shown { self.unpainted(table, def, state.sprite, state.frame) } else { None });
            }
        }
    }

    /// Resolves the frames of every animation, and the partner of every
    /// switch, whose textures the map uses. An animation with a frame that
    /// resolves to nothing, or a switch without its partner, is left still
    /// (as Doom leaves out an animation whose textures a WAD lacks).
    fn add_animations(&mut self, map: &Map, library: &Library, defs: &AnimDefs) {
        let mut walls = BTreeSet::new();
        let mut flats = BTreeSet::new();
        for line in &map.lines {
            for side in std::iter::once(&line.front).chain(&line.back) {
                walls.extend(
                    [&side.upper, &side.middle, &side.lower].into_iter().flatten().map(|n| n.to_ascii_uppercase()),
                );
            }
        }
        for s in &map.sectors {
            flats.extend([&s.floor_texture, &s.ceiling_texture].into_iter().flatten().map(|n| n.to_ascii_uppercase()));
        }
        for (list, kind, used) in
            [(&defs.flats, TextureKind::Flat, &flats), (&defs.textures, TextureKind::Wall, &walls)]
        {
            for anim in list {
                if !anim.frames.iter().any(|f| used.contains(&f.to_ascii_uppercase())) {
                    continue;
                }
                let frames: Result<Vec<TextureId>, _> =
                    anim.frames.iter().map(|f| self.textures.resolve_in(f, kind, library)).collect();
                if let Ok(frames) = frames {
                    self.animations.push(Animated { frames, tics: anim.tics });
                }
            }
        }
        for (k, s) in defs.switches.iter().enumerate() {
            if !walls.contains(&s.off.to_ascii_uppercase()) && !walls.contains(&s.on.to_ascii_uppercase()) {
                continue;
            }
            let (Ok(off), Ok(on)) = (
                self.textures.resolve_in(&s.off, TextureKind::Wall, library),
                self.textures.resolve_in(&s.on, TextureKind::Wall, library),
            ) else {
                continue;
            };
            self.switches.insert(off, (on, k));
            self.switches.insert(on, (off, k));
        }
        self.translation = (0..self.textures.len() as u32).map(TextureId).collect();
    }

    /// What is drawn for `id` now (its animation's current frame).
    #[inline]
    pub fn current(&self, id: TextureId) -> TextureId {
        self.translation.get(id.0 as usize).copied().unwrap_or(id)
    }

    /// The textures side `k` (0 front, 1 back) of `line` shows now.
    #[inline]
    pub fn side(&self, line: usize, k: usize) -> SideTextures {
        let s = self.sides[line][k];
        let t = |id: Option<TextureId>| id.map(|id| self.current(id));
        SideTextures { upper: t(s.upper), middle: t(s.middle), lower: t(s.lower) }
    }

    /// The floor and ceiling textures `sector` shows now.
    #[inline]
    pub fn plane(&self, sector: usize) -> SectorTextures {
        let s = self.sectors[sector];
        SectorTextures { floor: s.floor.map(|id| self.current(id)), ceiling: s.ceiling.map(|id| self.current(id)) }
    }
}

/// The animations file a map names, read from its folder (the library's
/// first); `None` when it names none (the shipped list applies).
fn own_animations(map: &Map, library: &Library) -> Result<Option<AnimDefs>, TextureError> {
    let Some(name) = &map.animations else { return Ok(None) };
    let plain = !name.is_empty() && !name.starts_with('.') && !name.contains(['/', '\\', '\0', ':']);
    if !plain {
        return Err(TextureError::Animations(format!("{name:?} is not a plain file name beside the map")));
    }
    let path = library.dirs.first().map_or_else(|| PathBuf::from(name), |d| d.join(name));
    let text = std::fs::read_to_string(&path)
        .map_err(|e| TextureError::Animations(format!("{}: cannot read: {e}", path.display())))?;
    AnimDefs::parse(&text, &path.display().to_string()).map(Some).map_err(|e| TextureError::Animations(e.to_string()))
}

fn side_textures(
    side: &Side,
    get: &mut impl FnMut(&str, &str) -> Result<TextureId, MaterialError>,
) -> Result<SideTextures, MaterialError> {
    let mut one = |name: &Option<String>, part: &str| name.as_deref().map(|n| get(n, part)).transpose();
    Ok(SideTextures {
        upper: one(&side.upper, "upper")?,
        middle: one(&side.middle, "middle")?,
        lower: one(&side.lower, "lower")?,
    })
}
